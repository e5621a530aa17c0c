// villa assets import|list|show|search|front: the asset library (assets/asset_library.h), an asset's four
// views (assets/asset_views.h) and its front picked by a multimodal model (assets/asset_front.h).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <memory>
#include <optional>
#include <string>

#include "assets/asset_front.h"
#include "assets/asset_library.h"
#include "assets/asset_views.h"
#include "assets/category.h"
#include "assets/embedder.h"
#include "assets/procedural.h"
#include "assets/retrieval.h"
#include "assets/sh3d_import.h"
#include "cli/command.h"
#include "cli/flags.h"
#include "cli/embedding_flags.h"
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
  bool no_category_budgets = false;
  Sh3dImportOptions options;
};

void RunImport(ImportCommand& command) {
  if (std::string problem = command.options.Check(); !problem.empty()) throw UsageError("assets import: " + problem);
  command.options.decimate = !command.skip_over_budget;
  command.options.category_budgets = !command.no_category_budgets;
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
  std::string render;  // --render FILE.png
  int size = 480;
};

// The four views of the asset with its surfaces and cavities, two by two, into `path` (atomically).
bool RenderShown(const AssetRecord& record, const AssetMesh& mesh, const ShowCommand& command) {
  AssetViewOptions options;
  options.size_px = command.size;
  auto views = RenderAssetViews(record, mesh, options);
  if (!views.ok()) {
    std::cerr << "villa assets show: " << views.error() << "\n";
    return false;
  }
  auto sheet = AssetViewSheet(*views);
  Status written = sheet.ok() ? WritePng(*sheet, command.render) : Status(Error{sheet.error()});
  if (!written.ok()) {
    std::cerr << "villa assets show: " << command.render << ": " << written.error() << "\n";
    return false;
  }
  return true;
}

void RunShow(const ShowCommand& command) {
  if (!command.render.empty() && std::filesystem::path(command.render).extension() != ".png")
    throw UsageError("assets show: --render " + command.render + ": the picture's name must end in .png");
  // A procedural id is made from the id itself: no library needed.
  std::optional<ProceduralAsset> made;
  std::optional<AssetLibrary> library;
  const AssetRecord* r = nullptr;
  if (command.id.rfind("proc:", 0) == 0 && command.library.empty()) {
    auto asset = MakeProceduralAsset(command.id);
    if (!asset.ok()) {
      std::cerr << "villa assets show: " << asset.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    made = std::move(*asset);
    r = &made->record;
  } else {
    library = OpenLibrary(command.library, "show");
    if (!library) return;
    r = library->Find(command.id);
    if (!r) {
      std::cerr << "villa assets show: " << command.id << ": no such asset in " << library->dir().string() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
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
                                                     c.open + ", on surface " + std::to_string(c.floor_surface) +
                                                     (c.rail ? ", hanging rail at z " + FormatFixed(*c.rail, 3) : "")});
  }
  if (r->interaction_zone) table.AddRow({"interaction zone", r->interaction_zone->side + " " + FormatFixed(r->interaction_zone->depth, 2) + " m"});
  table.AddRow({"mesh", r->mesh.file + ", " + std::to_string(r->mesh.triangles) + " triangles, " +
                            (r->mesh.watertight ? "watertight" : "not watertight") + ", manifold edges " +
                            FormatPercent(r->mesh.manifold_edges, 1.0)});
  if (!r->mesh.full_file.empty())
    table.AddRow({"source mesh", r->mesh.full_file + ", " + std::to_string(r->mesh.full_triangles) + " triangles (the mesh above is it decimated)"});
  if (!r->front_decided_by.empty()) table.AddRow({"front decided by", r->front_decided_by});
  std::cout << table.Render();
  if (!command.render.empty()) {
    std::shared_ptr<const AssetMesh> mesh;
    if (made) {
      mesh = std::make_shared<const AssetMesh>(made->mesh);
    } else if (auto loaded = library->Mesh(r->id); loaded.ok()) {
      mesh = *loaded;
    } else {
      std::cerr << "villa assets show: " << loaded.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    if (!RenderShown(*r, *mesh, command)) {
      SetExitCode(kExitFailure);
      return;
    }
    std::cout << "wrote " << command.render << " (four views: -y, +x, +y, -x; surfaces S<i>, cavities C<k>)\n";
  }
  SetExitCode(kExitOk);
}

// ---- search

struct SearchCommand {
  std::string library;
  std::string text;
  int k = 10;
  std::vector<double> size;
  std::string placement;
  bool json = false;
  bool no_procedural = false;
  RetrievalQuery query;
  EmbeddingFlags embeddings;
};

void RunSearch(SearchCommand& command) {
  if (!command.size.empty()) {
    if (command.size.size() != 3 || !(command.size[0] > 0 && command.size[1] > 0 && command.size[2] > 0))
      throw UsageError("assets search: --size takes three lengths > 0 in m: W,D,H");
    command.query.size = Vec3{command.size[0], command.size[1], command.size[2]};
  }
  if (!command.placement.empty()) {
    command.query.placement = ParsePlacement(command.placement);
    if (!command.query.placement) throw UsageError("assets search: --placement: expected floor, wall, ceiling or surface, got " + command.placement);
  }
  if (!command.query.category.empty() && !FindCategory(command.query.category))
    std::cerr << "villa assets search: note: " << command.query.category << " is not in the vocabulary; matching it as a name\n";
  command.query.text = command.text;
  std::optional<AssetLibrary> library = OpenLibrary(command.library, "search");
  if (!library) return;
  // The offline lexical embedder, or an OpenAI-compatible endpoint's (cached on disk by text).
  std::shared_ptr<const Embedder> embedder = EmbedderFrom(command.embeddings, "assets search");
  if (!embedder) embedder = std::make_shared<LexicalEmbedder>();
  Result<AssetRetriever> retriever = AssetRetriever::Build(library->records(), embedder);
  if (!retriever.ok()) {
    std::cerr << "villa assets search: " << retriever.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  // Procedural generators offer an asset of the query's category at the wanted size, ranked with the rest.
  if (!command.no_procedural) retriever->SetOffer(ProceduralOffer);
  RetrievalOptions options;
  options.k = command.k;
  Result<RetrievalResult> result = retriever->Rank(command.query, options);
  if (!result.ok()) {
    std::cerr << "villa assets search: " << result.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  if (command.json) {
    for (const RankedAsset& r : result->ranked) {
      nlohmann::ordered_json j;
      j["id"] = r.asset->id;
      j["score"] = std::round(r.score * 1e4) / 1e4;
      j["similarity"] = std::round(r.similarity * 1e4) / 1e4;
      j["size_fit"] = std::round(r.size_fit * 1e4) / 1e4;
      j["name"] = r.asset->name;
      j["category"] = r.asset->category;
      std::cout << j.dump() << "\n";
    }
  } else {
    TextTable table({"#", "score", "text", "size", "id", "name", "category", "size (m)"});
    int rank = 0;
    for (const RankedAsset& r : result->ranked)
      table.AddRow({std::to_string(++rank), FormatFixed(r.score, 3), FormatFixed(r.similarity, 3), FormatFixed(r.size_fit, 2),
                    r.asset->id, r.asset->name, r.asset->category, Size(r.asset->size)});
    std::cout << "query: " << command.query.Text() << (result->category.empty() ? "" : " [category " + result->category + "]") << "\n";
    std::cout << table.Render();
  }
  if (result->category_missing) {
    std::cerr << "villa assets search: the library has no " << result->category << " that meets the query; "
              << (result->fallback_generator.empty() ? "no procedural generator makes one either"
                                                     : "the procedural generator '" + result->fallback_generator + "' makes one")
              << "\n";
  }
  SetExitCode(kExitOk);
}

// ---- front

struct FrontCommand {
  std::string library;
  std::string id;
  std::string api_key_env;
  std::string cache_dir;
  bool no_cache = false;
  bool dry_run = false;
  FrontPickOptions options;
};

void RunFront(FrontCommand& command) {
  FrontPickOptions& o = command.options;
  if (o.llm.url.empty()) throw UsageError("assets front: needs --mllm URL (an OpenAI-compatible vision endpoint)");
  if (o.llm.model.empty()) throw UsageError("assets front: needs --model NAME");
  if (!command.api_key_env.empty()) {
    const char* key = std::getenv(command.api_key_env.c_str());
    if (!key || !*key) throw UsageError("assets front: --api-key-env " + command.api_key_env + ": that environment variable is not set");
    o.llm.api_key = key;
  }
  std::string message;
  if (!o.llm.IsValid(&message)) throw UsageError("assets front: " + message);
  o.chat.cache_dir = command.no_cache ? std::filesystem::path()
                     : command.cache_dir.empty() ? DefaultLlmCacheDir() : std::filesystem::path(command.cache_dir);
  std::optional<AssetLibrary> library = OpenLibrary(command.library, "front");
  if (!library) return;
  const AssetRecord* record = library->Find(command.id);
  if (!record) {
    std::cerr << "villa assets front: " << command.id << ": no such asset in " << library->dir().string() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  if (record->source.kind == "procedural") {
    std::cerr << "villa assets front: " << command.id << ": a procedural asset's front is -y by construction\n";
    SetExitCode(kExitFailure);
    return;
  }
  auto mesh = library->Mesh(command.id);
  if (!mesh.ok()) {
    std::cerr << "villa assets front: " << mesh.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  auto pick = PickAssetFront(*record, **mesh, o);
  if (!pick.ok()) {
    std::cerr << "villa assets front: " << pick.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  const std::string decided = "model " + o.llm.model + " at " + ChatCompletionsUrl(o.llm.url) + ": the front is picture " +
                              std::to_string(pick->view + 1) + " of 4 (seen from " + std::string(pick->view == 0 ? "-y" : pick->view == 1 ? "+x" : pick->view == 2 ? "+y" : "-x") +
                              "), turned by " + std::to_string(pick->turn_deg) + " degrees, confidence " + FormatFixed(pick->confidence, 2) +
                              (pick->reason.empty() ? "" : ": " + pick->reason);
  std::cout << command.id << ": " << decided << " (" << pick->chat.requests << " request(s), " << pick->chat.cache_hits
            << " from the cache, " << pick->chat.prompt_tokens + pick->chat.completion_tokens << " tokens)\n";
  if (command.dry_run) {
    std::cout << "dry run: the library is unchanged\n";
    SetExitCode(kExitOk);
    return;
  }
  auto written = WriteAssetFront(library->dir(), command.id, pick->view, decided);
  if (!written.ok()) {
    std::cerr << "villa assets front: " << written.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  std::cout << "updated " << (library->dir() / kLibraryRecordsFile).string() << ": front_yaw_offset " << written->front_yaw_offset
            << ", size " << Size(written->size) << (written->mesh.file.empty() ? "" : ", mesh " + written->mesh.file) << "\n";
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
      ->transform(WholeIn(1, 100000000));
  sub->add_flag("--skip-over-budget", import->skip_over_budget, "skip models over the budget instead of decimating them");
  sub->add_flag("--no-category-budgets", import->no_category_budgets,
                "keep every model under --max-triangles as its source has it (default: decimate each to its category's budget, "
                "8,000 / 4,000 / 1,500 triangles by size, the source mesh kept beside it as the record's mesh.full; not tables, shelves, beds and the like)");
  sub->add_option("-j,--threads", import->options.threads, "worker threads (default: all cores)")->transform(WholeIn(0, 1024));
  sub->callback([import] { RunImport(*import); });

  auto list = std::make_shared<ListCommand>();
  sub = assets->add_subcommand("list", "List the library's assets as a table (or JSONL records with --json).");
  sub->add_option("--library", list->library, "library folder");
  sub->add_option("--category", list->category, "only this category (e.g. sofa, bookcase)");
  sub->add_option("--room-type", list->room_type, "only assets suited to this room type (e.g. bedroom)");
  sub->add_flag("--json", list->json, "one asset record (SCENE.md) a line");
  sub->callback([list] { RunList(*list); });

  auto show = std::make_shared<ShowCommand>();
  sub = assets->add_subcommand("show", "Print one asset's record as a table; --render draws it from four sides with its support\n"
                                         "surfaces (coloured slabs S<i>) and cavities (see-through boxes C<k>).");
  sub->add_option("--library", show->library, "library folder");
  sub->add_option("id", show->id, "asset id, e.g. \"sh3d:BlendSwap-CC-0#bookcase\"")->required();
  sub->add_option("--render", show->render, "also write the four views (two by two) to this PNG file");
  sub->add_option("--size", show->size, "pixels of each view (default 480)")->check(CLI::Range(64, 4096));
  sub->callback([show] { RunShow(*show); });

  auto search = std::make_shared<SearchCommand>();
  sub = assets->add_subcommand(
      "search",
      "Rank the library's assets for a query: cosine similarity of text embeddings (offline lexical\n"
      "embedding of names, categories, tags and synonyms) plus the fit of their size to --size (or to the\n"
      "category's usual sizes) plus a bonus for the query's category. The procedural generator of the\n"
      "query's category offers one asset at the wanted size (ids proc:...), ranked with the library's.");
  sub->add_option("text", search->text, "what to look for, e.g. \"dark leather couch\"")->required();
  sub->add_option("--library", search->library, "library folder");
  sub->add_option("-k", search->k, "answers to print (default 10)")->transform(WholeIn(1, 1000000));
  sub->add_option("--category", search->query.category, "vocabulary category (default: read from the text)");
  sub->add_option("--room-type", search->query.room_type, "room type the asset is for (e.g. bedroom)");
  sub->add_option("--size", search->size, "wanted size W,D,H in m (asset frame)")
      ->delimiter(',')
      ->check(NumberIn(0.0, 100.0, /*above_min=*/true));
  sub->add_flag("--needs-surface", search->query.needs_surface, "only assets with a support surface");
  sub->add_flag("--needs-cavity", search->query.needs_cavity, "only assets with a cavity");
  sub->add_option("--placement", search->placement, "only assets placed so: floor, wall, ceiling or surface");
  sub->add_flag("--no-procedural", search->no_procedural, "rank the library's records only (no procedural offer)");
  sub->add_flag("--json", search->json, "one JSON object a line: id, score, similarity, size_fit, name, category");
  sub->add_option("--embeddings", search->embeddings.url,
                  "rank by the embeddings of this OpenAI-compatible server (http://host:port, .../v1 or .../v1/embeddings) "
                  "instead of the offline lexical ones; every text is cached on disk by its hash");
  sub->add_option("--model", search->embeddings.model, "the embedding model's name (with --embeddings)");
  sub->add_option("--api-key-env", search->embeddings.api_key_env, "environment variable holding the API key (never printed)");
  sub->add_option("--embeddings-cache", search->embeddings.cache_dir,
                  "folder of cached embeddings (default: " + DefaultEmbeddingCacheDir().string() + ")");
  sub->callback([search] { RunSearch(*search); });

  auto front = std::make_shared<FrontCommand>();
  sub = assets->add_subcommand(
      "front",
      "Find an imported asset's front with a multimodal model: four views of it (from -y, the recorded front,\n"
      "then +x, +y and -x) go to an OpenAI-compatible vision endpoint, which answers which one shows the\n"
      "front. The record and its mesh are turned so that side faces -y (size, surfaces and cavities with it),\n"
      "front_yaw_offset adds the turn and front_decided_by says who decided; the library is rewritten\n"
      "atomically (a new mesh file beside the old one, then assets.jsonl). Answers are cached. Exit status: 0\n"
      "decided (and written unless --dry-run), 1 no such asset, no usable answer or a failed write, 2 usage.");
  sub->add_option("id", front->id, "asset id")->required();
  sub->add_option("--library", front->library, "library folder");
  sub->add_option("--mllm", front->options.llm.url, "the model's server: http://host:port, .../v1 or .../v1/chat/completions")->required();
  sub->add_option("--model", front->options.llm.model, "model name sent in the request")->required();
  sub->add_option("--api-key-env", front->api_key_env, "environment variable holding the API key (never printed)");
  sub->add_option("--timeout", front->options.llm.timeout_s, "seconds to wait for the answer")->capture_default_str();
  sub->add_option("--llm-cache", front->cache_dir, "folder of cached answers (default: " + DefaultLlmCacheDir().string() + ")");
  sub->add_flag("--no-cache", front->no_cache, "neither read nor write cached answers");
  sub->add_flag("--no-schema", [o = &front->options](std::int64_t) { o->json_schema = false; },
                "do not send response_format json_schema (servers without structured output)");
  sub->add_flag("--dry-run", front->dry_run, "ask and print the decision, change nothing");
  sub->callback([front] { RunFront(*front); });
}};

}  // namespace
}  // namespace villa::cli
