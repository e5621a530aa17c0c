#pragma once
// Reading and writing whole layouts (FORMAT.md), and JSONL streams of dataset records.
// Errors name the source (file, or file:line for JSONL), the JSON path and the bad value:
//   layout.json: rooms["kitchen_0/0"].shape: expected ')' at column 19: shapely.box(0, 0, 4
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "layout/layout.h"
#include "util/result.h"

namespace villa {

using Json = nlohmann::ordered_json;

// Strict: exactly the six keys, known categories, well-formed names, shapes and levels.
// `source` prefixes every message (a file name, or "file.jsonl:12").
Result<Layout> LayoutFromJson(const Json& json, std::string_view source);
Result<Layout> ParseLayoutText(std::string_view text, std::string_view source);
Result<Layout> LoadLayout(const std::filesystem::path& path);

// Canonical JSON of FORMAT.md: six keys in fixed order, shapes in canonical shapely strings,
// "level" always set, "is_panoramic" on windows.
Json LayoutToJson(const Layout& layout);
// indent < 0: compact one line (for JSONL and LLM answers); otherwise pretty with that indent.
std::string LayoutToString(const Layout& layout, int indent = 2);
Status SaveLayout(const Layout& layout, const std::filesystem::path& path);  // atomic

// Calls `on_record(json, line_number)` for each non-empty line of a JSONL file. A line that is not
// JSON gives an error "file:line: ..." and stops, unless `on_bad_line` is set, which is then called
// with the message and reading goes on. `on_record` returns false to stop early.
Status ReadJsonl(const std::filesystem::path& path,
                 const std::function<bool(const Json& record, int line)>& on_record,
                 const std::function<void(const std::string& message)>& on_bad_line = nullptr);

// A layout from a JSONL record: the record itself when it has the six layout keys, else its "layout".
Result<Layout> LayoutFromRecord(const Json& record, std::string_view source);

}  // namespace villa
