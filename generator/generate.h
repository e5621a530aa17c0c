#pragma once
// Text to a furnished 3D villa in a folder, the library behind `villa generate`: plan a layout from the
// request (PlanLayout), build it (BuildBuilding) when it passes the geometric rules, furnish every room
// (solver/furnish.h: the request's furniture wishes go to the rooms they name), and write
//   layout.json    the layout
//   plan.png       the floor plans with every object's footprint (and the walking paths when reachability ran)
//   scene.json     every room's graph and the objects' poses (SCENE.md)
//   furnished.glb  the building and every object (glTF 2.0; extras per object)
//   CREDITS        the Creative Commons Attribution models placed
//   preview.png    the furnished villa from outside and a cut-away of each level
//   report.json    the plan's report, the building's figures, the macro metrics (FSR, RR, VCR), the micro
//                  ones (CR, FR, OBR, CSR, NO, RCH, ACC) and the furnish report per room, timings
// With `furnish` off it is the macro pipeline: layout.json, plan.png (bare), building.glb, preview.png
// (the empty building), report.json. What can be written is written even when a later step fails (a
// furnishing that fails leaves building.glb and the bare pictures).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "building/building.h"
#include "generator/text/plan.h"
#include "solver/furnish.h"
#include "util/result.h"

namespace villa {

struct GenerateOptions {
  PlanOptions plan;            // backend, seed, budget, model...
  BuildOptions build;          // wall thicknesses, door leaves...
  std::filesystem::path out;   // the folder (created when missing)
  bool force = false;          // replace files of an earlier run in the folder (never other files)
  bool furnish = true;         // false: the macro pipeline only (`--no-furnish`)
  // Rooms to furnish, jobs, library, solver settings, progress hooks, the reach hook. GenerateVilla sets
  // its `text` to the request, its `seed` to plan.seed and its `build` to `build`.
  solver::FurnishOptions furnishing;

  // False with the bad option named (BuildOptions::Check, PlanOptions::IsValid, FurnishOptions::Check).
  bool IsValid(std::string* message) const;
};

// The files a run writes, relative to the folder, for these options.
std::vector<std::string> GenerateOutputNames(const GenerateOptions& options);

// Why options.out cannot take the outputs ("OUT exists and is not a folder", "OUT/layout.json exists;
// pass --force to overwrite it"), or OK. A usage problem: nothing is written.
Status CheckGenerateOutput(const GenerateOptions& options);

struct GenerateSummary {
  PlanSummary plan;
  bool built = false;                      // a building came out
  bool furnished = false;                  // every room went through the furnish pipeline
  nlohmann::ordered_json building;         // report.json's "building" (levels, parts, VCR, warnings, ...)
  nlohmann::ordered_json report;           // report.json as written
  solver::FurnishSummary furnish;          // when furnished: rooms, outcomes, objects, CR/FR/OBR/CSR, times
  std::vector<std::string> files;          // written, relative to the folder, report.json last
  std::vector<std::string> problems;       // what went wrong, one line each
  double plan_s = 0.0, build_s = 0.0, furnish_s = 0.0, export_s = 0.0, preview_s = 0.0, seconds = 0.0;
  // A valid layout, built (and furnished when asked) and every file written.
  bool ok() const { return plan.valid() && problems.empty(); }
  // The lines `villa generate` prints: the plan's brief report, the building's figures, the furnishing's.
  std::string BriefReport() const;
};

// Runs the pipeline (options valid, the output checked by CheckGenerateOutput first). Errors: a folder
// that cannot be created, an asset library that cannot be opened (both before anything is written);
// everything later is reported in the summary.
Result<GenerateSummary> GenerateVilla(const std::string& text, const GenerateOptions& options);

}  // namespace villa
