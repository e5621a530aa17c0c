#include "scene/strict_json.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "util/excerpt.h"
#include "util/json_read.h"

namespace villa::scene {
namespace {

bool IsIdentifier(std::string_view key) {
  if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
  return std::all_of(key.begin(), key.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Line and column (1-based) of a byte offset.
std::string LineColumn(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t line = 1, column = 1;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// SAX events building the document, watching keys and number spellings on the way and keeping the path of
// the value being read. The document is built here, not by nlohmann's DOM builder: its ordered objects look
// every key up before inserting it, which made a scene of 100,000 objects (one object keyed by id) take
// half a minute to read (issue 33); keys are checked for duplicates in a set, so members are appended.
class StrictSax : public nlohmann::json_sax<Json> {
 public:
  StrictSax(Json& root, std::string_view text, std::string source, int max_decimals)
      : root_(root), text_(text), source_(std::move(source)), max_decimals_(max_decimals) {}

  const std::string& error() const { return error_; }

  bool null() override { return Put(Json(nullptr)); }
  bool boolean(bool v) override { return Put(Json(v)); }
  bool number_integer(number_integer_t v) override { return Put(Json(v)); }
  bool number_unsigned(number_unsigned_t v) override { return Put(Json(v)); }
  bool number_float(number_float_t v, const string_t& spelling) override {
    if (spelling.find_first_of("eE") != std::string::npos)
      return Fail(ValuePath(), spelling + ": numbers are written without an exponent");
    size_t dot = spelling.find('.');
    if (dot != std::string::npos && static_cast<int>(spelling.size() - dot - 1) > max_decimals_)
      return Fail(ValuePath(), spelling + ": numbers have at most " + std::to_string(max_decimals_) + " decimals");
    return Put(Json(v));
  }
  bool string(string_t& v) override { return Put(Json(std::move(v))); }
  bool binary(binary_t& v) override { return Put(Json(std::move(v))); }
  bool start_object(std::size_t) override {
    frames_.push_back({true, ValuePath(), 0, {}, {}, Json::object()});
    return true;
  }
  bool key(string_t& k) override {
    Frame& f = frames_.back();
    if (!f.keys.insert(k).second) return Fail(MemberPath(Path(), k), "duplicate key");
    f.key = k;
    return true;
  }
  bool end_object() override { return Close(); }
  bool start_array(std::size_t) override {
    frames_.push_back({false, ValuePath(), 0, {}, {}, Json::array()});
    return true;
  }
  bool end_array() override { return Close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    if (error_.empty()) {
      std::string what = e.what();
      // nlohmann's message repeats its own position; keep the part after "parse error ...: ".
      size_t colon = what.find(": ", what.find("parse error"));
      if (colon != std::string::npos) what = what.substr(colon + 2);
      error_ = source_ + ": " + LineColumn(text_, position > 0 ? position - 1 : 0) + ": " + what;
    }
    return false;
  }

 private:
  struct Frame {
    bool object = false;
    std::string path;  // path of this container
    size_t index = 0;  // arrays: index of the next element
    std::set<std::string> keys;
    std::string key;   // objects: the member being read
    Json value;        // the container being built
  };
  // A finished value into the innermost container (appended: its key is known to be new), or the root.
  bool Put(Json value) {
    if (frames_.empty()) {
      root_ = std::move(value);
      return true;
    }
    Frame& f = frames_.back();
    if (f.object) {
      auto& members = static_cast<std::vector<std::pair<const std::string, Json>>&>(f.value.get_ref<Json::object_t&>());
      members.emplace_back(f.key, std::move(value));
    } else {
      f.value.get_ref<Json::array_t&>().push_back(std::move(value));
    }
    Done();
    return true;
  }
  bool Close() {
    Json done = std::move(frames_.back().value);
    frames_.pop_back();
    return Put(std::move(done));
  }

  std::string Path() const { return frames_.empty() ? std::string() : frames_.back().path; }
  // The path of the value about to be read (a member or an element of the innermost container).
  std::string ValuePath() const {
    if (frames_.empty()) return "";
    const Frame& f = frames_.back();
    return f.object ? MemberPath(f.path, f.key) : ElementPath(f.path, f.index);
  }
  void Done() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
  }
  bool Fail(const std::string& path, const std::string& what) {
    if (error_.empty()) error_ = source_ + ": " + (path.empty() ? "(document)" : path) + ": " + Excerpt(what);
    return false;
  }

  Json& root_;
  std::string_view text_;
  std::string source_;
  int max_decimals_;
  std::vector<Frame> frames_;
  std::string error_;
};

}  // namespace

Result<Json> ParseStrictJson(std::string_view text, const std::string& source, int max_decimals) {
  // The nesting limit first (util/json_read.h): a value nested 100,000 deep would overflow any recursive
  // walk over the document; duplicate keys are this reader's own to name, with their JSON path.
  if (std::string deep = JsonStructureProblem(text, kMaxJsonDepth, /*duplicate_keys=*/false); !deep.empty())
    return Error{source + ": " + deep};
  Json root;
  StrictSax sax(root, text, source, max_decimals);
  bool ok = Json::sax_parse(text.begin(), text.end(), &sax, nlohmann::detail::input_format_t::json, true, false);
  if (!ok || !sax.error().empty())
    return Error{sax.error().empty() ? source + ": not valid JSON" : sax.error()};
  return root;
}

std::string MemberPath(const std::string& path, std::string_view key) {
  if (IsIdentifier(key)) return path.empty() ? std::string(key) : path + "." + std::string(key);
  return path + "[" + Json(std::string(key)).dump() + "]";
}

std::string ElementPath(const std::string& path, size_t index) { return path + "[" + std::to_string(index) + "]"; }

void FailAt(const std::string& path, const std::string& what) {
  throw JsonReadError((path.empty() ? std::string("(document)") : path) + ": " + what);
}

std::string Shown(const Json& value) { return Excerpt(value.dump()); }

ObjectReader::ObjectReader(const Json& value, std::string path) : value_(value), path_(std::move(path)) {
  if (!value_.is_object()) FailAt(path_, "expected an object, got " + Shown(value_));
}

const Json* ObjectReader::Optional(std::string_view key) {
  asked_.emplace_back(key);
  auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

const Json& ObjectReader::Required(std::string_view key) {
  const Json* v = Optional(key);
  if (!v) FailAt(PathOf(key), "missing");
  return *v;
}

std::string ObjectReader::String(std::string_view key) { return StringAt(Required(key), PathOf(key)); }

std::optional<std::string> ObjectReader::OptionalString(std::string_view key) {
  const Json* v = Optional(key);
  if (!v) return std::nullopt;
  return StringAt(*v, PathOf(key));
}

double ObjectReader::Number(std::string_view key) { return NumberAt(Required(key), PathOf(key)); }

std::optional<double> ObjectReader::OptionalNumber(std::string_view key) {
  const Json* v = Optional(key);
  if (!v) return std::nullopt;
  return NumberAt(*v, PathOf(key));
}

int ObjectReader::Integer(std::string_view key) {
  auto v = OptionalInteger(key);
  if (!v) FailAt(PathOf(key), "missing");
  return *v;
}

std::optional<int> ObjectReader::OptionalInteger(std::string_view key) {
  const Json* v = Optional(key);
  if (!v) return std::nullopt;
  if (!v->is_number_integer() || v->get<long long>() < -1000000000LL || v->get<long long>() > 1000000000LL)
    FailAt(PathOf(key), "expected an integer, got " + Shown(*v));
  return static_cast<int>(v->get<long long>());
}

std::vector<std::string> ObjectReader::Strings(std::string_view key) {
  const Json& v = Required(key);
  std::string path = PathOf(key);
  if (!v.is_array()) FailAt(path, "expected an array of strings, got " + Shown(v));
  std::vector<std::string> out;
  for (size_t i = 0; i < v.size(); ++i) out.push_back(StringAt(v[i], ElementPath(path, i)));
  return out;
}

std::vector<double> ObjectReader::Numbers(std::string_view key, size_t count) {
  const Json& v = Required(key);
  std::string path = PathOf(key);
  if (!v.is_array() || v.size() != count)
    FailAt(path, "expected " + std::to_string(count) + " numbers, got " + Shown(v));
  std::vector<double> out;
  for (size_t i = 0; i < count; ++i) out.push_back(NumberAt(v[i], ElementPath(path, i)));
  return out;
}

void ObjectReader::Finish() const {
  for (auto it = value_.begin(); it != value_.end(); ++it)
    if (std::find(asked_.begin(), asked_.end(), it.key()) == asked_.end()) FailAt(PathOf(it.key()), "unknown key");
}

double NumberAt(const Json& value, const std::string& path) {
  if (!value.is_number() || !std::isfinite(value.get<double>()))
    FailAt(path, "expected a number, got " + Shown(value));
  return value.get<double>();
}

std::string StringAt(const Json& value, const std::string& path) {
  if (!value.is_string()) FailAt(path, "expected a string, got " + Shown(value));
  return value.get<std::string>();
}

double Round4(double value) {
  double r = std::round(value * 1e4) / 1e4;
  return r == 0.0 ? 0.0 : r;
}

}  // namespace villa::scene
