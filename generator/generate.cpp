#include "generator/generate.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "building/export.h"
#include "building/view_scene.h"
#include "layout/layout_io.h"
#include "render/plan_render.h"
#include "render/view3d.h"
#include "util/atomic_file.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

double Since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double Round3(double v) { return std::round(v * 1000.0) / 1000.0; }

const char* const kOutputs[] = {"layout.json", "building.glb", "plan.png", "preview.png", "report.json"};

}  // namespace

bool GenerateOptions::IsValid(std::string* message) const {
  if (std::string problem = build.Check(); !problem.empty()) {
    if (message) *message = problem;
    return false;
  }
  return plan.IsValid(message);
}

Status CheckGenerateOutput(const GenerateOptions& options) {
  const fs::path& dir = options.out;
  if (fs::exists(dir) && !fs::is_directory(dir)) return Error{dir.string() + " exists and is not a folder"};
  for (const char* name : kOutputs)
    if (fs::exists(dir / name) && !options.force)
      return Error{(dir / name).string() + " exists; pass --force to overwrite it"};
  return Status{};
}

Result<GenerateSummary> GenerateVilla(const std::string& text, const GenerateOptions& options) {
  const fs::path& dir = options.out;
  const fs::path layout_path = dir / "layout.json", glb_path = dir / "building.glb", plan_png = dir / "plan.png",
                 preview_png = dir / "preview.png", report_path = dir / "report.json";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return Error{dir.string() + ": " + ec.message()};

  GenerateSummary summary;
  PlanSummary& plan = summary.plan;
  std::vector<std::string>& problems = summary.problems;
  auto fail = [&](const std::string& m) { problems.push_back(m); };
  auto start = std::chrono::steady_clock::now();
  plan = PlanLayout(text, options.plan);
  summary.plan_s = Since(start);
  Json report = PlanReportJson(plan);
  Json files = Json::array();
  Json building_json = Json::object();

  if (plan.layout) {
    if (Status s = SaveLayout(*plan.layout, layout_path); s) files.push_back("layout.json");
    else fail(s.error());
    PlanRenderOptions plan_options;
    plan_options.source_name = "layout.json";
    if (Status s = RenderPlan(*plan.layout, plan_png, plan_options); s) files.push_back("plan.png");
    else fail(s.error());
  } else {
    fail("no layout came out of the plan: " + plan.error);
  }

  if (plan.layout && plan.metrics.format_success) {
    start = std::chrono::steady_clock::now();
    auto building = BuildBuilding(*plan.layout, options.build);
    summary.build_s = Since(start);
    if (!building) {
      fail("layout.json: " + building.error());
    } else {
      start = std::chrono::steady_clock::now();
      Status exported = ExportBuilding(*building, glb_path, MeshFormat::kGlb);
      summary.export_s = Since(start);
      if (exported) files.push_back("building.glb");
      else fail(exported.error());
      start = std::chrono::steady_clock::now();
      auto image = RenderPreview(ViewSceneOf(*building));
      Status written = image ? WritePng(*image, preview_png) : Status(Error{preview_png.string() + ": " + image.error()});
      summary.preview_s = Since(start);
      if (written) files.push_back("preview.png");
      else fail(written.error());
      VcrReport vcr = MeasureVcr(*building);
      size_t triangles = 0;
      for (const MeshPart& p : building->parts) triangles += p.mesh.triangles.size();
      Box3 box = building->Bounds();
      Json pairs = Json::array();
      for (const VerticalConnection& pair : vcr.pairs)
        pairs.push_back({{"levels", {pair.lower_level, pair.lower_level + 1}},
                         {"overlap_m2", Round3(pair.overlap_area)},
                         {"connected", pair.connected()}});
      building_json = {{"levels", building->levels},
                       {"rooms", building->rooms.size()},
                       {"parts", building->parts.size()},
                       {"triangles", triangles},
                       {"size_m", {Round3(box.max.x - box.min.x), Round3(box.max.y - box.min.y), Round3(box.max.z - box.min.z)}},
                       {"stairs", building->stairs.size()},
                       {"vcr", {{"floor_pairs", vcr.floor_pairs()},
                                {"connected", vcr.connected_pairs()},
                                {"value", vcr.floor_pairs() > 0 ? Json(vcr.vcr()) : Json(nullptr)},
                                {"pairs", pairs}}},
                       {"warnings", building->warnings},
                       {"seconds", {{"build", Round3(summary.build_s)}, {"export", Round3(summary.export_s)}, {"preview", Round3(summary.preview_s)}}}};
      summary.built = true;
    }
  } else if (plan.layout) {
    fail("the layout breaks the geometric rules 1-5; no building (see violations)");
  }
  report["building"] = building_json;
  report["seconds_plan"] = Round3(summary.plan_s);
  report["files"] = files;
  report["problems"] = problems;
  files.push_back("report.json");
  if (Status s = WriteFileAtomic(report_path, report.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"); !s) problems.push_back(s.error());

  summary.building = building_json;
  summary.report = report;
  for (const auto& f : files) summary.files.push_back(f.get<std::string>());
  return summary;
}

std::string GenerateSummary::BriefReport() const {
  std::ostringstream out;
  out << plan.BriefReport();
  if (!building.empty()) {
    out << "building: " << building["levels"] << " level(s), " << building["parts"] << " parts, " << building["triangles"]
        << " triangles; VCR " << building["vcr"]["connected"] << "/" << building["vcr"]["floor_pairs"] << "\n";
  }
  return out.str();
}

}  // namespace villa
