// villa build LAYOUT -o building.glb [--format glb|obj] [--preview preview.png]: layout to 3D building.
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "cli/command.h"
#include "cli/flags.h"
#include "building/building.h"
#include "building/export.h"
#include "building/view_scene.h"
#include "layout/layout_io.h"
#include "layout/validate.h"

namespace villa::cli {
namespace {

struct BuildCommand {
  std::string input;
  std::string output;
  std::string format;  // "" = from the output's extension
  std::string preview;
  bool force = false;
  bool allow_invalid = false;
  bool quiet = false;
  BuildOptions options;
};

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void Fail(const std::string& message) {
  std::cerr << "villa build: " << message << "\n";
  SetExitCode(kExitFailure);
}

void Run(BuildCommand& command) {
  // Usage first: nothing is read or written when the command line is wrong.
  std::string format_name = command.format.empty() ? Lower(std::filesystem::path(command.output).extension().string())
                                                   : Lower(command.format);
  if (!format_name.empty() && format_name[0] == '.') format_name.erase(0, 1);
  if (command.format.empty() && format_name != "glb" && format_name != "obj") format_name = "glb";
  auto format = ParseMeshFormat(format_name);
  if (!format) throw UsageError("build: --format " + command.format + ": must be glb or obj");
  if (!std::filesystem::exists(command.input)) throw UsageError("build: " + command.input + ": no such file");
  std::vector<std::filesystem::path> outputs = {command.output};
  if (*format == MeshFormat::kObj) outputs.push_back(std::filesystem::path(command.output).replace_extension(".mtl"));
  if (!command.preview.empty()) {
    if (Lower(std::filesystem::path(command.preview).extension().string()) != ".png")
      throw UsageError("build: --preview " + command.preview + ": the preview is a PNG (.png)");
    outputs.push_back(command.preview);
  }
  for (const auto& out : outputs)
    if (std::filesystem::exists(out) && !command.force)
      throw UsageError("build: " + out.string() + " exists; pass --force to overwrite it");
  if (std::string problem = command.options.Check(); !problem.empty()) throw UsageError("build: " + problem);

  auto layout = LoadLayout(command.input);
  if (!layout) return Fail(layout.error());
  ValidateOptions vo;
  vo.check_architecture = false;
  ValidationReport report = ValidateLayout(*layout, vo);
  if (!report.geometric_ok()) {
    for (const Violation& v : report.violations)
      if (v.rule <= 5) std::cerr << "villa build: " << command.input << ": rule " << v.rule << ": " << v.message << "\n";
    if (!command.allow_invalid)
      return Fail(command.input + ": breaks the geometric rules 1-5; not built (--allow-invalid builds it anyway)");
  }

  auto start = std::chrono::steady_clock::now();
  auto building = BuildBuilding(*layout, command.options);
  if (!building) return Fail(command.input + ": " + building.error());
  double build_s = Seconds(start);
  start = std::chrono::steady_clock::now();
  if (Status s = ExportBuilding(*building, command.output, *format); !s) return Fail(s.error());
  double export_s = Seconds(start);
  double preview_s = 0.0;
  if (!command.preview.empty()) {
    start = std::chrono::steady_clock::now();
    auto image = RenderPreview(ViewSceneOf(*building));
    if (!image) return Fail(command.preview + ": " + image.error());
    if (Status s = WritePng(*image, command.preview); !s) return Fail(s.error());
    preview_s = Seconds(start);
  }
  if (!command.quiet) {
    size_t triangles = 0;
    for (const MeshPart& p : building->parts) triangles += p.mesh.triangles.size();
    VcrReport vcr = MeasureVcr(*building);
    Box3 box = building->Bounds();
    std::ostringstream out;
    out << std::fixed << std::setprecision(2);
    out << command.output << ": " << building->levels << " level(s), " << building->rooms.size() << " rooms, "
        << building->parts.size() << " parts, " << triangles << " triangles; " << box.max.x - box.min.x << " x "
        << box.max.y - box.min.y << " x " << box.max.z - box.min.z << " m\n";
    for (const VerticalConnection& pair : vcr.pairs)
      out << "  stairs level " << pair.lower_level << " -> " << pair.lower_level + 1 << ": "
          << (pair.connected() ? "connected" : "NOT connected") << " (overlap " << pair.overlap_area << " m2)\n";
    if (vcr.floor_pairs() > 0)
      out << "  VCR " << vcr.connected_pairs() << "/" << vcr.floor_pairs() << "\n";
    for (const std::string& w : building->warnings) out << "  warning: " << w << "\n";
    out << std::setprecision(3) << "  build " << build_s << " s, export " << export_s << " s";
    if (!command.preview.empty()) out << ", preview " << preview_s << " s (" << command.preview << ")";
    out << "\n";
    std::cout << out.str();
  }
  SetExitCode(kExitOk);
}

Registration registration{60, [](CLI::App& app) {
  auto command = std::make_shared<BuildCommand>();
  CLI::App* sub = app.add_subcommand(
      "build",
      "Turn a layout into a 3D building: floor slabs with stair holes, walls with door and window\n"
      "openings, door leaves, glass, staircases and a roof, written as glTF 2.0 binary (.glb, +Y up,\n"
      "metres) or OBJ (+ .mtl). The layout must pass the geometric rules 1-5 (see `villa validate`).\n"
      "Exit status: 0 built, 1 unreadable or unbuildable layout, 2 usage.");
  sub->add_option("layout", command->input, "layout file (.json)")->required();
  sub->add_option("-o,--output", command->output, "the 3D file to write (.glb or .obj)")->required()->check(PathName());
  sub->add_option("--format", command->format, "glb or obj (default: from the output's extension, else glb)");
  sub->add_option("--preview", command->preview,
                  "also write a PNG: the building from outside and a cut-away of each level, side by side");
  sub->add_flag("--force", command->force, "overwrite existing output files");
  sub->add_flag("--allow-invalid", command->allow_invalid,
                "build even when the layout breaks the geometric rules (the builder adapts and warns)");
  sub->add_flag("-q,--quiet", command->quiet, "print nothing on success");
  sub->add_option("--exterior-wall", command->options.exterior_wall_thickness, "exterior wall thickness, m")
      ->capture_default_str()
      ->check(NumberIn(0.0, 1.0, /*above_min=*/true));
  sub->add_option("--interior-wall", command->options.interior_wall_thickness, "interior wall thickness, m")
      ->capture_default_str()
      ->check(NumberIn(0.0, 0.5, /*above_min=*/true));
  sub->add_flag("!--closed-doors", command->options.door_leaves_open,
                "hang door leaves closed in their openings (default: swung open, 90 degrees or flat against the wall)");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
