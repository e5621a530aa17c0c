// villa assets import|list|show|search: the asset library (assets/asset_library.h).
#include <algorithm>
#include <iostream>
#include <mutex>
#include <memory>
#include <optional>
#include <string>

#include "assets/asset_library.h"
#include "assets/category.h"
#include "assets/sh3d_import.h"
#include "cli/command.h"
#include "util/progress.h"
#include "util/text_table.h"

namespace villa::cli {
namespace {

std::filesystem::path LibraryDir(const std::string& flag) { return flag.empty() ? DefaultLibraryDir() : std::filesystem::path(flag); }

// Opens the library or says why not (exit 1).
std::optional<AssetLibrary> OpenLibrary(const std::string& flag, const std::string& sub) {
  Result<AssetLibrary> library = AssetLibrary::Open(LibraryDir(flag));
  if (!library.ok()) {
    std::cerr << "villa assets " << sub << ": " << library.error() << "\n";
    SetExitCode(kExitFailure);
    return std::nullopt;
  }
  return std::move(*library);
}

std::string Size(const Vec3& s) { return FormatFixed(s.x, 2) + " x " + FormatFixed(s.y, 2) + " x " + FormatFixed(s.z, 2); }
// Width, depth, height spelled out (a table cell that starts with a letter stays left-aligned).
std::string Sides(const Vec3& s) { return "w " + FormatFixed(s.x, 2) + ", d " + FormatFixed(s.y, 2) + ", h " + FormatFixed(s.z, 2) + " m"; }

std::string Joined(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : separator) + s;
  return out;
}

// ---- import

struct ImportCommand {
  std::string from;
  std::string library;
  bool skip_over_budget = false;
  Sh3dImportOptions options;
};

void RunImport(ImportCommand& command) {
  if (std::string problem = command.options.Check(); !problem.empty()) throw UsageError("assets import: " + problem);
  command.options.decimate = !command.skip_over_budget;
  std::filesystem::path from = command.from.empty() ? DefaultSh3dFurnitureDir() : std::filesystem::path(command.from);
  if (!std::filesystem::exists(from)) {
    throw UsageError("assets import: " + from.string() +
                     ": no such folder (install Debian's sweethome3d-furniture, or pass --from DIR)");
  }
  std::unique_ptr<ProgressBar> bar;
  std::mutex bar_mutex;
  auto progress = [&](int, int total) {
    std::lock_guard<std::mutex> lock(bar_mutex);
    if (!bar) bar = std::make_unique<ProgressBar>("import", total);
    bar->Advance();
  };
  Result<Sh3dImportSummary> summary = ImportSh3dLibraries(from, LibraryDir(command.library), command.options, progress);
  if (bar) bar->Finish();
  if (!summary.ok()) {
    std::cerr << "villa assets import: " << summary.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  std::cout << summary->BriefReport();
  SetExitCode(kExitOk);
}

// ---- list

struct ListCommand {
  std::string library;
  std::string category;
  std::string room_type;
  bool json = false;
};

void RunList(const ListCommand& command) {
  std::optional<AssetLibrary> library = OpenLibrary(command.library, "list");
  if (!library) return;
  TextTable table({"id", "name", "category", "placement", "size (m)", "S", "C", "license"});
  int shown = 0;
  for (const AssetRecord& r : library->records()) {
    if (!command.category.empty() && r.category != command.category) continue;
    if (!command.room_type.empty() && !r.room_types.empty() &&
        std::find(r.room_types.begin(), r.room_types.end(), command.room_type) == r.room_types.end())
      continue;
    ++shown;
    if (command.json) {
      std::cout << AssetToJson(r).dump() << "\n";
      continue;
    }
    table.AddRow({r.id, r.name, r.category, std::string(PlacementName(r.placement)), Size(r.size),
                  std::to_string(r.support_surfaces.size()), std::to_string(r.cavities.size()), r.license});
  }
  if (!command.json) std::cout << table.Render() << shown << " of " << library->records().size() << " assets\n";
  SetExitCode(kExitOk);
}

// ---- show

struct ShowCommand {
  std::string library;
  std::string id;
};

void RunShow(const ShowCommand& command) {
  std::optional<AssetLibrary> library = OpenLibrary(command.library, "show");
  if (!library) return;
  const AssetRecord* r = library->Find(command.id);
  if (!r) {
    std::cerr << "villa assets show: " << command.id << ": no such asset in " << library->dir().string() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  TextTable table({"field", "value"});
  table.AddRow({"id", r->id});
  table.AddRow({"name", r->name});
  table.AddRow({"category", r->category + (FindCategory(r->category) ? "" : " (not in the vocabulary)")});
  table.AddRow({"source", r->source.kind + " " + r->source.library + " " + r->source.entry});
  if (!r->source.sh3d_category.empty()) table.AddRow({"sh3d category", r->source.sh3d_category});
  if (!r->source.tags.empty()) table.AddRow({"tags", Joined(r->source.tags)});
  table.AddRow({"license", r->license});
  table.AddRow({"creator", r->creator});
  if (std::string credit = r->Credit(); !credit.empty()) table.AddRow({"credit", credit});
  table.AddRow({"room types", r->room_types.empty() ? "any" : Joined(r->room_types)});
  table.AddRow({"size", Sides(r->size)});
  table.AddRow({"placement", std::string(PlacementName(r->placement))});
  table.AddRow({"affordances", Joined(AffordanceNames(r->affordances))});
  for (std::size_t i = 0; i < r->support_surfaces.size(); ++i) {
    const SupportSurface& s = r->support_surfaces[i];
    Box3 box;
    for (const Point& p : s.polygon) box.Add(Vec3{p.x, p.y, 0});
    table.AddRow({"surface " + std::to_string(i), "z " + FormatFixed(s.z, 3) + ", " + FormatFixed(box.max.x - box.min.x, 2) +
                                                      " x " + FormatFixed(box.max.y - box.min.y, 2) + " m, " +
                                                      std::to_string(s.polygon.size()) + " corners, clear " +
                                                      FormatFixed(s.clear_height, 2) + " m, from " + s.from});
  }
  for (std::size_t i = 0; i < r->cavities.size(); ++i) {
    const Cavity& c = r->cavities[i];
    table.AddRow({"cavity " + std::to_string(i), Sides(c.max - c.min) + ", at z " + FormatFixed(c.min.z, 3) + ", open " +
                                                     c.open + ", on surface " + std::to_string(c.floor_surface)});
  }
  if (r->interaction_zone) table.AddRow({"interaction zone", r->interaction_zone->side + " " + FormatFixed(r->interaction_zone->depth, 2) + " m"});
  table.AddRow({"mesh", r->mesh.file + ", " + std::to_string(r->mesh.triangles) + " triangles, " +
                            (r->mesh.watertight ? "watertight" : "not watertight") + ", manifold edges " +
                            FormatPercent(r->mesh.manifold_edges, 1.0)});
  std::cout << table.Render();
  SetExitCode(kExitOk);
}

Registration registration{70, [](CLI::App& app) {
  CLI::App* assets = app.add_subcommand(
      "assets",
      "The asset library: 3D models with their size, support surfaces, cavities, placement and licence\n"
      "(shared/design/SCENE.md). Folder: --library DIR, else $VILLA_ASSETS, else\n"
      "$XDG_DATA_HOME/villa/assets (~/.local/share/villa/assets).");
  assets->require_subcommand(1);

  auto import = std::make_shared<ImportCommand>();
  CLI::App* sub = assets->add_subcommand(
      "import",
      "Import Sweet Home 3D furniture libraries (*.sh3f) into the library: every piece but doors, windows\n"
      "and staircases, converted to the asset frame, with support surfaces and cavities found by ray casts.\n"
      "Replaces the library's Sweet Home 3D records only when the whole import succeeds. Exit status: 0\n"
      "imported, 1 failure (the old library is left as it was), 2 usage.");
  sub->add_option("--from", import->from, "folder of .sh3f files, or one file (default: " + DefaultSh3dFurnitureDir().string() + ")");
  sub->add_option("--library", import->library, "library folder to write");
  sub->add_option("--max-triangles", import->options.max_triangles,
                  "triangle budget per model (default 50000): larger meshes are decimated")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--skip-over-budget", import->skip_over_budget, "skip models over the budget instead of decimating them");
  sub->add_option("-j,--threads", import->options.threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  sub->callback([import] { RunImport(*import); });

  auto list = std::make_shared<ListCommand>();
  sub = assets->add_subcommand("list", "List the library's assets as a table (or JSONL records with --json).");
  sub->add_option("--library", list->library, "library folder");
  sub->add_option("--category", list->category, "only this category (e.g. sofa, bookcase)");
  sub->add_option("--room-type", list->room_type, "only assets suited to this room type (e.g. bedroom)");
  sub->add_flag("--json", list->json, "one asset record (SCENE.md) a line");
  sub->callback([list] { RunList(*list); });

  auto show = std::make_shared<ShowCommand>();
  sub = assets->add_subcommand("show", "Print one asset's record as a table.");
  sub->add_option("--library", show->library, "library folder");
  sub->add_option("id", show->id, "asset id, e.g. \"sh3d:BlendSwap-CC-0#bookcase\"")->required();
  sub->callback([show] { RunShow(*show); });
}};

}  // namespace
}  // namespace villa::cli
