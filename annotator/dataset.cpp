#include "annotator/dataset.h"

#include <unordered_map>

#include "layout/footprint.h"
#include "layout/layout_io.h"

namespace villa::annotator {

int Dataset::Find(const std::string& id) const {
  if (!index.empty()) {
    auto it = index.find(id);
    return it == index.end() ? -1 : it->second;
  }
  for (std::size_t i = 0; i < records.size(); ++i)
    if (records[i].id == id) return static_cast<int>(i);
  return -1;
}

std::filesystem::path LayoutsPath(const std::filesystem::path& dir) { return dir / "layouts.jsonl"; }
std::filesystem::path JournalPath(const std::filesystem::path& dir) { return dir / "annotations.journal.jsonl"; }

bool IsShapeClass(const std::string& shape) {
  const std::optional<ShapeClass> parsed = ParseShapeClass(shape);
  return parsed && ShapeClassName(*parsed) == shape;  // the exact name only, not the lower-case letters
}

Result<Dataset> LoadDataset(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return Error{dir.string() + ": no such dataset folder"};
  std::filesystem::path path = LayoutsPath(dir);
  if (!std::filesystem::exists(path, ec))
    return Error{path.string() + ": missing (a dataset folder holds the layouts.jsonl of `villa synth`)"};

  Dataset dataset;
  dataset.dir = dir;
  std::unordered_map<std::string, int> lines_by_id;
  std::string error;
  Status status = ReadJsonl(path, [&](const Json& record, int line) {
    std::string where = path.string() + ":" + std::to_string(line);
    if (!record.is_object()) {
      error = where + ": a record must be a JSON object";
      return false;
    }
    DatasetRecord out;
    out.line = line;
    auto id = record.find("id");
    if (id == record.end() || !id->is_string() || id->get<std::string>().empty()) {
      error = where + ": \"id\": missing or not a non-empty string";
      return false;
    }
    out.id = id->get<std::string>();
    if (auto [it, inserted] = lines_by_id.emplace(out.id, line); !inserted) {
      error = where + ": \"id\": \"" + out.id + "\" repeats line " + std::to_string(it->second);
      return false;
    }
    if (auto seed = record.find("seed"); seed != record.end()) {
      if (!seed->is_number_integer() && !seed->is_number_unsigned()) {
        error = where + ": \"seed\": " + seed->dump() + " is not an integer";
        return false;
      }
      out.seed = seed->is_number_unsigned() ? seed->get<std::uint64_t>()
                                            : static_cast<std::uint64_t>(seed->get<std::int64_t>());
    }
    if (auto shape = record.find("shape"); shape != record.end()) {
      if (!shape->is_string() || !IsShapeClass(shape->get<std::string>())) {
        error = where + ": \"shape\": " + shape->dump() + " is not a footprint class (rectangle, L, U, T, H, irregular, hexagon, octagon, trapezoid, cross, bay, angled-wing)";
        return false;
      }
      out.shape = shape->get<std::string>();
    } else {
      out.shape = "irregular";
    }
    auto layout = LayoutFromRecord(record, where);
    if (!layout) {
      error = layout.error();
      return false;
    }
    out.layout = std::move(layout).value();
    out.floors = out.layout.LevelCount();
    if (auto floors = record.find("floors"); floors != record.end()) {
      if (!floors->is_number_integer() || floors->get<int>() != out.floors) {
        error = where + ": \"floors\": " + floors->dump() + " does not match the layout's " +
                std::to_string(out.floors) + " levels";
        return false;
      }
    }
    dataset.index.emplace(out.id, static_cast<int>(dataset.records.size()));
    dataset.records.push_back(std::move(out));
    return true;
  });
  if (!status) return Error{status.error()};
  if (!error.empty()) return Error{error};
  if (dataset.records.empty()) return Error{path.string() + ": no records"};
  return dataset;
}

}  // namespace villa::annotator
