#pragma once
// Reading JSON that came from outside (layout files and JSONL lines, asset records, journals, fine-tune
// samples, LLM answers) with the guards nlohmann's own parse lacks:
//  - a nesting limit: a value nested 100,000 deep parses, but every recursive walk over it afterwards
//    (dump, copy, compare, destroy in older versions) overflows the stack. Nothing villa reads nests
//    deeper than a few levels, so kMaxJsonDepth is far above need and far below the stack's limit.
//  - duplicate object keys are errors naming the key and both places (nlohmann keeps the last silently,
//    so a layout with two "kitchen_0/0" lost a room without a word).
//  - objects with many members build in linear time (nlohmann's ordered_json looks every key up in a
//    list while parsing, so 50,000 doors took seconds); member order is kept as written.
// Errors: "<source>: line 1, column 65: nested deeper than 64 levels",
//         "<source>: rooms: duplicate key "kitchen_0/0" on lines 3 and 7",
//         "<source>: not valid JSON: [json.exception.parse_error.101] parse error at line 1, ...".
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/result.h"

namespace villa {

// Containers (objects and arrays) nested inside one another, the outermost counting 1.
inline constexpr int kMaxJsonDepth = 64;

// Empty when `text` nests at most `max_depth` containers deep and (with `duplicate_keys`) no object repeats
// a key; otherwise the first such problem, with its place ("line L, column C: nested deeper than N
// levels", "<path>: duplicate key "K" on lines A and B"). Text that is not JSON is not judged here: the
// parser names that. Readers with their own duplicate-key message (scene/strict_json.h) pass false.
std::string JsonStructureProblem(std::string_view text, int max_depth = kMaxJsonDepth, bool duplicate_keys = true);

namespace json_read_detail {

// nlohmann's SAX events into a DOM, appending object members without looking them up (the structure
// check has already ruled out duplicates) and refusing to nest deeper than the limit.
template <class J>
class DomBuilder : public nlohmann::json_sax<J> {
 public:
  using typename nlohmann::json_sax<J>::number_integer_t;
  using typename nlohmann::json_sax<J>::number_unsigned_t;
  using typename nlohmann::json_sax<J>::number_float_t;
  using typename nlohmann::json_sax<J>::string_t;
  using typename nlohmann::json_sax<J>::binary_t;

  DomBuilder(J& root, int max_depth) : root_(root), max_depth_(max_depth) {}
  const std::string& error() const { return error_; }

  bool null() override { return Put(J(nullptr)) != nullptr; }
  bool boolean(bool v) override { return Put(J(v)) != nullptr; }
  bool number_integer(number_integer_t v) override { return Put(J(v)) != nullptr; }
  bool number_unsigned(number_unsigned_t v) override { return Put(J(v)) != nullptr; }
  bool number_float(number_float_t v, const string_t&) override { return Put(J(v)) != nullptr; }
  bool string(string_t& v) override { return Put(J(std::move(v))) != nullptr; }
  bool binary(binary_t& v) override { return Put(J::binary(std::move(v))) != nullptr; }
  bool start_object(std::size_t) override { return Open(J::value_t::object); }
  bool start_array(std::size_t) override { return Open(J::value_t::array); }
  bool end_object() override { return Close(); }
  bool end_array() override { return Close(); }
  bool key(string_t& k) override {
    auto& object = stack_.back()->template get_ref<typename J::object_t&>();
    // ordered_json's object is a std::vector of pairs underneath (nlohmann::ordered_map derives from it).
    using Object = typename J::object_t;
    using Members = std::vector<std::pair<const typename J::string_t, J>, typename Object::allocator_type>;
    if constexpr (std::is_base_of_v<Members, Object>) {
      object.emplace_back(std::move(k), J());  // the list's own append: no search
      member_ = &object.back().second;
    } else {
      member_ = &object.emplace(std::move(k), J()).first->second;
    }
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    if (error_.empty()) error_ = std::string("not valid JSON: ") + e.what();
    return false;
  }

 private:
  // Places a finished value where the parser is: the root, the next array element or the member just keyed.
  J* Put(J&& value) {
    if (stack_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    J& top = *stack_.back();
    if (top.is_array()) {
      auto& array = top.template get_ref<typename J::array_t&>();
      array.push_back(std::move(value));
      return &array.back();
    }
    *member_ = std::move(value);
    return member_;
  }
  bool Open(typename J::value_t type) {
    if (static_cast<int>(stack_.size()) >= max_depth_) {
      if (error_.empty()) error_ = "nested deeper than " + std::to_string(max_depth_) + " levels";
      return false;
    }
    stack_.push_back(Put(J(type)));
    return true;
  }
  bool Close() {
    stack_.pop_back();
    return true;
  }

  J& root_;
  int max_depth_;
  std::vector<J*> stack_;  // the open containers, outermost first
  J* member_ = nullptr;    // the member of the innermost object whose value comes next
  std::string error_;
};

}  // namespace json_read_detail

// Parses `text` as one JSON value of type J (nlohmann::json or nlohmann::ordered_json) under the guards
// above. `source` prefixes every error ("layout.json", "data.jsonl:12"); empty: no prefix.
template <class J>
Result<J> ParseJson(std::string_view text, std::string_view source, int max_depth = kMaxJsonDepth) {
  const std::string prefix = source.empty() ? std::string() : std::string(source) + ": ";
  if (std::string problem = JsonStructureProblem(text, max_depth); !problem.empty()) return Error{prefix + problem};
  J root;
  json_read_detail::DomBuilder<J> builder(root, max_depth);
  const bool ok = J::sax_parse(text.begin(), text.end(), &builder, nlohmann::detail::input_format_t::json, true, false);
  if (!ok || !builder.error().empty())
    return Error{prefix + (builder.error().empty() ? std::string("not valid JSON") : builder.error())};
  return root;
}

}  // namespace villa
