#pragma once
// Text to a 3D villa in a folder, the library behind `villa generate`: plan a layout from the request
// (PlanLayout), build it (BuildBuilding) when it passes the geometric rules, and write OUT/layout.json,
// plan.png (the floor plans), building.glb (glTF 2.0), preview.png (the building and a cut-away of each
// level) and report.json (the plan's report, the building's figures and VCR on the built geometry, the
// files written, the problems met, timings). What can be written is written even when a later step fails.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "building/building.h"
#include "generator/text/plan.h"
#include "util/result.h"

namespace villa {

struct GenerateOptions {
  PlanOptions plan;            // backend, seed, budget, model...
  BuildOptions build;          // wall thicknesses, door leaves...
  std::filesystem::path out;   // the folder (created when missing)
  bool force = false;          // replace files of an earlier run in the folder

  // False with the bad build or plan option named (BuildOptions::Check, PlanOptions::IsValid).
  bool IsValid(std::string* message) const;
};

// Why options.out cannot take the outputs ("OUT exists and is not a folder", "OUT/layout.json exists;
// pass --force to overwrite it"), or OK. A usage problem: nothing is written.
Status CheckGenerateOutput(const GenerateOptions& options);

struct GenerateSummary {
  PlanSummary plan;
  bool built = false;                      // a building came out
  nlohmann::ordered_json building;         // report.json's "building" (levels, parts, VCR, warnings, ...)
  nlohmann::ordered_json report;           // report.json as written
  std::vector<std::string> files;          // written, relative to the folder, report.json last
  std::vector<std::string> problems;       // what went wrong, one line each
  double plan_s = 0.0, build_s = 0.0, export_s = 0.0, preview_s = 0.0;
  // A valid layout, built and every file written.
  bool ok() const { return plan.valid() && problems.empty(); }
  // The lines `villa generate` prints: the plan's brief report and the building's figures.
  std::string BriefReport() const;
};

// Runs the pipeline (options valid, the output checked by CheckGenerateOutput first). A folder that cannot be created is
// the only error; everything later is reported in the summary.
Result<GenerateSummary> GenerateVilla(const std::string& text, const GenerateOptions& options);

}  // namespace villa
