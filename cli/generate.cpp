// villa generate "TEXT" -o OUTDIR: the whole pipeline. Plan a layout from the text, then build it:
// OUTDIR/layout.json, building.glb, plan.png (floor plans), preview.png (3D cut-aways), report.json.
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>

#include "cli/backend_flags.h"
#include "cli/command.h"
#include "building/building.h"
#include "building/export.h"
#include "building/view_scene.h"
#include "generator/text/plan.h"
#include "layout/layout_io.h"
#include "render/plan_render.h"
#include "util/atomic_file.h"

namespace villa::cli {


namespace {

namespace fs = std::filesystem;

struct GenerateCommand {
  std::string text;
  std::string out;
  std::string backend = "procedural";
  std::string api_key_env;
  bool force = false;
  bool quiet = false;
  PlanOptions options;
  BuildOptions build;
};

double Since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double Round3(double v) { return std::round(v * 1000.0) / 1000.0; }

void Run(GenerateCommand& command) {
  if (command.text == "-") command.text.assign(std::istreambuf_iterator<char>(std::cin), {});
  if (command.text.find_first_not_of(" \t\r\n") == std::string::npos) throw UsageError("generate: the request text is empty");
  ApplyBackendFlags(command.backend, command.api_key_env, command.options);
  if (std::string problem = command.build.Check(); !problem.empty()) throw UsageError("generate: " + problem);
  const fs::path dir = command.out;
  const fs::path layout_path = dir / "layout.json", glb_path = dir / "building.glb", plan_png = dir / "plan.png",
                 preview_png = dir / "preview.png", report_path = dir / "report.json";
  if (fs::exists(dir) && !fs::is_directory(dir)) throw UsageError("generate: " + command.out + " exists and is not a folder");
  for (const fs::path& p : {layout_path, glb_path, plan_png, preview_png, report_path})
    if (fs::exists(p) && !command.force)
      throw UsageError("generate: " + p.string() + " exists; pass --force to overwrite it");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    std::cerr << "villa generate: " << command.out << ": " << ec.message() << "\n";
    SetExitCode(kExitFailure);
    return;
  }

  auto start = std::chrono::steady_clock::now();
  PlanSummary plan = PlanLayout(command.text, command.options);
  double plan_s = Since(start);
  Json report = PlanReportJson(plan);
  Json files = Json::array();
  Json building_json = Json::object();
  std::vector<std::string> problems;
  auto fail = [&](const std::string& m) { problems.push_back(m); };

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
    auto building = BuildBuilding(*plan.layout, command.build);
    double build_s = Since(start);
    if (!building) {
      fail("layout.json: " + building.error());
    } else {
      start = std::chrono::steady_clock::now();
      Status exported = ExportBuilding(*building, glb_path, MeshFormat::kGlb);
      double export_s = Since(start);
      if (exported) files.push_back("building.glb");
      else fail(exported.error());
      start = std::chrono::steady_clock::now();
      auto image = RenderPreview(ViewSceneOf(*building));
      Status written = image ? WritePng(*image, preview_png) : Status(Error{preview_png.string() + ": " + image.error()});
      double preview_s = Since(start);
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
                       {"seconds", {{"build", Round3(build_s)}, {"export", Round3(export_s)}, {"preview", Round3(preview_s)}}}};
    }
  } else if (plan.layout) {
    fail("the layout breaks the geometric rules 1-5; no building (see violations)");
  }
  report["building"] = building_json;
  report["seconds_plan"] = Round3(plan_s);
  report["files"] = files;
  report["problems"] = problems;
  files.push_back("report.json");
  if (Status s = WriteFileAtomic(report_path, report.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"); !s) problems.push_back(s.error());

  const bool ok = plan.valid() && problems.empty();
  if (!command.quiet || !ok) {
    std::ostream& out = ok ? std::cout : std::cerr;
    out << plan.BriefReport();
    if (!building_json.empty()) {
      out << "building: " << building_json["levels"] << " level(s), " << building_json["parts"] << " parts, "
          << building_json["triangles"] << " triangles; VCR " << building_json["vcr"]["connected"] << "/"
          << building_json["vcr"]["floor_pairs"] << "\n";
    }
    for (const std::string& p : problems) std::cerr << "villa generate: " << p << "\n";
    for (const auto& f : files) out << (dir / f.get<std::string>()).string() << "\n";
  }
  SetExitCode(ok ? kExitOk : kExitFailure);
}

Registration registration{65, [](CLI::App& app) {
  auto command = std::make_shared<GenerateCommand>();
  CLI::App* sub = app.add_subcommand(
      "generate",
      "Text to a 3D villa: plan a layout from the request (like `villa plan`), then build it (like\n"
      "`villa build`). Writes into OUTDIR: layout.json, plan.png (floor plans), building.glb (glTF 2.0),\n"
      "preview.png (the building and a cut-away of each level) and report.json (brief, checks, metrics,\n"
      "VCR on the built geometry, timings). Exit status: 0 a valid layout built, 1 the plan or the build\n"
      "failed (what could be written is written, report.json says why), 2 usage.");
  sub->add_option("text", command->text, "the request, in English (\"-\" reads it from stdin)")->required();
  sub->add_option("-o,--out", command->out, "output folder (created if missing)")->required();
  AddBackendFlags(sub, command->backend, command->api_key_env, command->options);
  sub->add_flag("--force", command->force, "overwrite existing output files in OUTDIR");
  sub->add_flag("-q,--quiet", command->quiet, "print nothing on success");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
