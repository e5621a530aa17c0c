#pragma once
// A dataset folder from `villa synth`: DIR/layouts.jsonl, one record a line:
//   {"id": "villa-000042", "seed": 123, "shape": "L", "floors": 2, "layout": {...FORMAT.md layout...}}
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "layout/layout.h"
#include "util/result.h"

namespace villa::annotator {

struct DatasetRecord {
  std::string id;         // unique within the dataset
  std::uint64_t seed = 0; // the partitioner's seed; also seeds the drafted descriptions
  std::string shape;      // footprint class: rectangle, L, U, T, H, irregular
  int floors = 0;
  Layout layout;
  int line = 0;           // line in layouts.jsonl (1-based), for messages
};

struct Dataset {
  std::filesystem::path dir;
  std::vector<DatasetRecord> records;
  std::unordered_map<std::string, int> index;  // id -> position in records (filled by LoadDataset)
  // Index of the record with this id, or -1.
  int Find(const std::string& id) const;
};

std::filesystem::path LayoutsPath(const std::filesystem::path& dir);
std::filesystem::path JournalPath(const std::filesystem::path& dir);

// Reads DIR/layouts.jsonl. Errors name the file, the line and the bad field or value
// ("d/layouts.jsonl:7: \"shape\": \"star\" is not a footprint class").
Result<Dataset> LoadDataset(const std::filesystem::path& dir);

// Footprint classes as the partitioner names them.
bool IsShapeClass(const std::string& shape);

}  // namespace villa::annotator
