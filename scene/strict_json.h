#pragma once
// Strict JSON for the scene files (SCENE.md): parsing that rejects what nlohmann accepts silently
// (duplicate keys, where the last one would win; numbers with an exponent or more decimals than the
// format allows), and a reader that walks a parsed document naming the JSON path of every value, so each
// error reads `scene.json: objects["living-room_0/0/sofa-0"].pose.yaw: expected a number, got "90"`.
//
// The reader throws JsonReadError internally; the public functions of scene/ catch it and return a
// Result, so bad input never escapes as an exception.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/result.h"

namespace villa::scene {

using Json = nlohmann::ordered_json;

// Parses `text`. Errors: "<source>: line L, column C: <parser message>" for malformed JSON, and
// "<source>: <path>: ..." for a duplicate key or a number with an exponent or more than `max_decimals`
// decimals (SCENE.md: at most 4 decimals, no exponent), and "<source>: line L, column C: nested deeper
// than 64 levels" for a document nested past util/json_read.h's limit.
Result<Json> ParseStrictJson(std::string_view text, const std::string& source, int max_decimals = 4);

// The path of a member below `path` ("pose" + "x" = "pose.x"; keys that are not identifiers are quoted:
// objects["living-room_0/0/sofa-0"]) and of an array element ("edges_sem[3]").
std::string MemberPath(const std::string& path, std::string_view key);
std::string ElementPath(const std::string& path, size_t index);

// What went wrong where; `message` already names the path and the bad value (cut to ~80 characters).
struct JsonReadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
[[noreturn]] void FailAt(const std::string& path, const std::string& what);
// A value as it appears in the file, cut to ~80 characters.
std::string Shown(const Json& value);

// Reads one JSON object: members are asked for by name; Finish() rejects any member never asked for.
class ObjectReader {
 public:
  // Throws when `value` is not an object.
  ObjectReader(const Json& value, std::string path);

  const std::string& path() const { return path_; }
  std::string PathOf(std::string_view key) const { return MemberPath(path_, key); }
  bool Has(std::string_view key) const { return value_.contains(key); }

  const Json* Optional(std::string_view key);
  const Json& Required(std::string_view key);

  std::string String(std::string_view key);
  std::optional<std::string> OptionalString(std::string_view key);
  double Number(std::string_view key);
  std::optional<double> OptionalNumber(std::string_view key);
  int Integer(std::string_view key);
  std::optional<int> OptionalInteger(std::string_view key);
  std::vector<std::string> Strings(std::string_view key);
  // A fixed-length array of numbers ([x, y, z]).
  std::vector<double> Numbers(std::string_view key, size_t count);

  // Throws on the first member that no call above asked for.
  void Finish() const;

 private:
  const Json& value_;
  std::string path_;
  std::vector<std::string> asked_;
};

// The value at `path` as a number / string, or a JsonReadError naming the path and what was found.
double NumberAt(const Json& value, const std::string& path);
std::string StringAt(const Json& value, const std::string& path);

// Files hold at most 4 decimals; -0 becomes 0.
double Round4(double value);

}  // namespace villa::scene
