#include "generator/generate.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "building/export.h"
#include "building/view_scene.h"
#include "layout/layout_io.h"
#include "render/plan_render.h"
#include "render/view3d.h"
#include "scene/acquire.h"
#include "scene/file_digest.h"
#include "scene/scene.h"
#include "util/atomic_file.h"
#include "util/staged_output.h"
#include "util/utf8.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

double Since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double Round3(double v) { return std::round(v * 1000.0) / 1000.0; }
double Round4(double v) { return std::round(v * 10000.0) / 10000.0; }

// report.json's "building": levels, parts, size, stairs and VCR measured on the built geometry.
Json BuildingJson(const BuildingMesh& building, const GenerateSummary& summary) {
  VcrReport vcr = MeasureVcr(building);
  size_t triangles = 0;
  for (const MeshPart& p : building.parts) triangles += p.mesh.triangles.size();
  Box3 box = building.Bounds();
  Json pairs = Json::array();
  for (const VerticalConnection& pair : vcr.pairs)
    pairs.push_back({{"levels", {pair.lower_level, pair.lower_level + 1}},
                     {"overlap_m2", Round3(pair.overlap_area)},
                     {"connected", pair.connected()}});
  return {{"levels", building.levels},
          {"rooms", building.rooms.size()},
          {"parts", building.parts.size()},
          {"triangles", triangles},
          {"size_m", {Round3(box.max.x - box.min.x), Round3(box.max.y - box.min.y), Round3(box.max.z - box.min.z)}},
          {"stairs", building.stairs.size()},
          {"vcr", {{"floor_pairs", vcr.floor_pairs()},
                   {"connected", vcr.connected_pairs()},
                   {"value", vcr.floor_pairs() > 0 ? Json(vcr.vcr()) : Json(nullptr)},
                   {"pairs", pairs}}},
          {"warnings", building.warnings},
          {"seconds", {{"build", Round3(summary.build_s)}, {"export", Round3(summary.export_s)}, {"preview", Round3(summary.preview_s)}}}};
}

// report.json's "micro": the paper's micro metrics over the furnished rooms; RCH and ACC only when the
// reach hook measured them (null otherwise: not measured, never guessed).
Json MicroJson(const solver::FurnishedVilla& villa) {
  const solver::FurnishSummary& s = villa.summary;
  Json j{{"rooms", s.furnished},
         {"objects", s.objects},
         {"CR", Round4(s.cr())},
         {"FR", Round4(s.fr())},
         {"OBR", Round4(s.obr())},
         {"CSR", s.inside_edges ? Json(Round4(s.csr())) : Json(nullptr)},
         {"NO", Round4(s.furnished ? double(s.objects) / s.furnished : 0.0)}};
  // The mean of a figure over the rooms (objects) the reach hook measured.
  auto mean = [](const std::map<std::string, double>& values) {
    double sum = 0.0;
    for (const auto& [name, value] : values) sum += value;
    return values.empty() ? Json(nullptr) : Json(Round4(sum / values.size()));
  };
  j["RCH"] = villa.reach ? mean(villa.reach->rch) : Json(nullptr);
  j["ACC"] = villa.reach ? mean(villa.reach->acc) : Json(nullptr);
  if (!villa.reach) j["note"] = "RCH and ACC not measured: no reachability check is plugged in";
  return j;
}

}  // namespace

bool GenerateOptions::IsValid(std::string* message) const {
  if (std::string problem = build.Check(); !problem.empty()) {
    if (message) *message = problem;
    return false;
  }
  if (furnish)
    if (std::string problem = furnishing.Check(); !problem.empty()) {
      if (message) *message = problem;
      return false;
    }
  return plan.IsValid(message);
}

std::vector<std::string> GenerateOutputNames(const GenerateOptions& options) {
  if (!options.furnish) return {"layout.json", "building.glb", "plan.png", "preview.png", "report.json"};
  return {"layout.json", "plan.png", "scene.json", "furnished.glb", "CREDITS", "preview.png", "building.glb", "report.json"};
}

Status CheckGenerateOutput(const GenerateOptions& options) {
  const fs::path& dir = options.out;
  if (fs::exists(dir) && !fs::is_directory(dir)) return Error{dir.string() + " exists and is not a folder"};
  for (const std::string& name : GenerateOutputNames(options))
    if (fs::exists(dir / name) && !options.force)
      return Error{(dir / name).string() + " exists; pass --force to overwrite it"};
  return Status{};
}

Result<GenerateSummary> GenerateVilla(const std::string& text, const GenerateOptions& options) {
  const auto run_start = std::chrono::steady_clock::now();
  if (std::string p = RequestTextProblem(text); !p.empty()) return Error{"usage: the request: " + p};
  // The library first: a bad --library is the user's to fix before anything runs.
  scene::FurnishingLibrary library;
  if (options.furnish) {
    auto opened = scene::OpenFurnishingLibrary(options.furnishing.library, options.furnishing.procedural_only);
    if (!opened.ok()) return Error{opened.error()};
    library = std::move(*opened);
  }
  std::error_code ec;
  // Issue 33: everything is written into a staging folder and moved into `dir` together at the end, under
  // the folder's lock: a killed run leaves the folder as it was, a second run into it is refused meanwhile.
  auto stage = StagedOutput::Open(options.out);
  if (!stage.ok()) return Error{stage.error().rfind("busy: ", 0) == 0 ? "usage: " + stage.error().substr(6) : stage.error()};
  const fs::path& dir = (*stage)->path();
  const fs::path layout_path = dir / "layout.json", report_path = dir / "report.json";

  GenerateSummary summary;
  PlanSummary& plan = summary.plan;
  std::vector<std::string>& problems = summary.problems;
  auto fail = [&](const std::string& m) { problems.push_back(m); };
  Json files = Json::array();
  auto write = [&](const std::string& name, const Result<std::string>& bytes) {
    if (!bytes.ok()) return fail((dir / name).string() + ": " + bytes.error());
    if (Status s = WriteFileAtomic(dir / name, *bytes); !s) return fail(s.error());
    files.push_back(name);
  };
  auto write_picture = [&](const std::string& name, const Result<Image>& image) {
    write(name, image.ok() ? EncodePng(*image) : Result<std::string>(Error{image.error()}));
  };

  auto start = std::chrono::steady_clock::now();
  plan = PlanLayout(text, options.plan);
  summary.plan_s = Since(start);
  Json report = PlanReportJson(plan);
  Json building_json = Json::object();
  bool layout_written = false;
  if (plan.layout) {
    if (Status s = SaveLayout(*plan.layout, layout_path); s) {
      files.push_back("layout.json");
      layout_written = true;
    } else {
      fail(s.error());
    }
  } else {
    fail("no layout came out of the plan: " + plan.error);
  }

  std::optional<BuildingMesh> building;
  if (plan.layout && plan.metrics.format_success) {
    start = std::chrono::steady_clock::now();
    auto built = BuildBuilding(*plan.layout, options.build);
    summary.build_s = Since(start);
    if (built) building = std::move(*built);
    else fail("layout.json: " + built.error());
  } else if (plan.layout) {
    fail("the layout breaks the geometric rules 1-5; no building (see violations)");
  }

  // Furnishing, on the layout as written (the scene names it by path and SHA-256).
  std::optional<solver::FurnishedVilla> villa;
  solver::FurnishOptions furnishing = options.furnishing;
  furnishing.text = text;
  furnishing.seed = options.plan.seed;
  furnishing.build = options.build;
  if (options.furnish && building && layout_written) {
    start = std::chrono::steady_clock::now();
    auto digest = scene::FileSha256(layout_path);
    Result<solver::FurnishedVilla> furnished = digest.ok()
        ? solver::FurnishLayout(*plan.layout, {"layout.json", *digest}, library.library, library.file, furnishing)
        : Result<solver::FurnishedVilla>(Error{digest.error()});
    summary.furnish_s = Since(start);
    if (furnished.ok()) {
      villa = std::move(*furnished);
      villa->library_note = library.note;
    } else {
      fail("furnishing: " + furnished.error());
    }
  }

  if (villa) {
    summary.furnished = true;
    summary.furnish = villa->summary;
    write("plan.png", solver::FurnishedPlanPng(*villa));
    write("scene.json", scene::SceneToText(villa->scene));
    start = std::chrono::steady_clock::now();
    write("furnished.glb", solver::FurnishedGlb(*villa));
    summary.export_s = Since(start);
    write("CREDITS", solver::FurnishCredits(*villa));
    if (furnishing.pictures) {
      fs::create_directories(dir / "rooms", ec);
      if (ec) fail((dir / "rooms").string() + ": " + ec.message());
      for (const scene::RoomContext& context : villa->contexts)
        write(solver::RoomPictureName(context.name), solver::RoomPicturePng(*villa, context));
    }
    start = std::chrono::steady_clock::now();
    write_picture("preview.png", solver::RenderFurnishedPreview(*villa));
    summary.preview_s = Since(start);
  } else {
    if (plan.layout) {
      PlanRenderOptions plan_options;
      plan_options.source_name = "layout.json";
      write("plan.png", RenderPlanPng(*plan.layout, plan_options));
    }
    if (building) {
      start = std::chrono::steady_clock::now();
      write("building.glb", BuildingToGlb(*building));
      summary.export_s = Since(start);
      start = std::chrono::steady_clock::now();
      write_picture("preview.png", RenderPreview(ViewSceneOf(*building)));
      summary.preview_s = Since(start);
    }
  }
  if (building) {
    building_json = BuildingJson(*building, summary);
    summary.built = true;
  }
  report["building"] = building_json;
  if (villa) {
    report["micro"] = MicroJson(*villa);
    Json furnish = solver::FurnishReportJson(*villa, furnishing);
    furnish.erase("text");  // the request is the report's "text" already
    report["furnish"] = std::move(furnish);
  } else {
    report["micro"] = nullptr;
    report["furnish"] = nullptr;
  }
  summary.seconds = Since(run_start);
  report["seconds_plan"] = Round3(summary.plan_s);
  report["timings"] = {{"plan", Round3(summary.plan_s)}, {"build", Round3(summary.build_s)},
                       {"furnish", Round3(summary.furnish_s)}, {"export", Round3(summary.export_s)},
                       {"preview", Round3(summary.preview_s)}, {"total", Round3(summary.seconds)}};
  report["files"] = files;
  report["problems"] = problems;
  files.push_back("report.json");
  if (Status s = WriteFileAtomic(report_path, report.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"); !s)
    problems.push_back(s.error());

  summary.building = building_json;
  summary.report = report;
  for (const auto& f : files) summary.files.push_back(f.get<std::string>());
  if (Status s = (*stage)->Commit(summary.files); !s) return Error{s.error()};
  return summary;
}

std::string GenerateSummary::BriefReport() const {
  std::ostringstream out;
  out << plan.BriefReport();
  if (!building.empty()) {
    out << "building: " << building["levels"] << " level(s), " << building["parts"] << " parts, " << building["triangles"]
        << " triangles; VCR " << building["vcr"]["connected"] << "/" << building["vcr"]["floor_pairs"] << "\n";
  }
  if (furnished) out << furnish.BriefReport();
  return out.str();
}

}  // namespace villa
