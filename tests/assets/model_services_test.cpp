// What the asset library asks of model servers, against the local scripted OpenAI-compatible server:
// retrieval by an /v1/embeddings endpoint (the request, the cache answering a second run, an error named),
// an asset's front picked from four views and written into the library (turned mesh, size, surfaces,
// cavities, the note of who decided), and the four views themselves; and the commands that use them.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>

#include "assets/asset_front.h"
#include "assets/asset_library.h"
#include "assets/asset_views.h"
#include "assets/procedural.h"
#include "assets/remote_embedder.h"
#include "assets/retrieval.h"
#include "assets/sh3d_import.h"
#include "llm/scripted_server.h"
#include "sh3f_fixture.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
using testing::Completion;
using testing::Failure;
using testing::Json;
using testing::Reply;
using testing::ScriptedServer;

Reply Vectors(const std::vector<std::vector<double>>& vectors) {
  Json data = Json::array();
  for (size_t i = 0; i < vectors.size(); ++i) data.push_back({{"object", "embedding"}, {"index", i}, {"embedding", vectors[i]}});
  return testing::EmbeddingsReply(data);
}

LlmOptions EmbeddingModel(const ScriptedServer& server) { return testing::ScriptedOptions(server, "villa-embed"); }

AssetRecord Procedural(const std::string& category, Vec3 size) {
  auto id = ProceduralAssetId(category, size, "modern", 1);
  REQUIRE(id.ok());
  auto made = MakeProceduralAsset(*id);
  REQUIRE(made.ok());
  return made->record;
}

// A library imported from the test's Sweet Home 3D archive.
fs::path ImportedLibrary(const std::string& name) {
  const fs::path dir = test::FreshDir(name + "_" + std::to_string(::getpid()));
  test::WriteFixtureLibrary(dir / "from");
  Sh3dImportOptions options;
  options.threads = 1;
  REQUIRE(ImportSh3dLibraries(dir / "from", dir / "lib", options, {}).ok());
  return dir;
}

struct Run {
  int code = -1;
  std::string out;
};
Run Villa(const fs::path& dir, const std::string& args) {
  const std::string command = "env -u VILLA_ASSETS '" + std::string(VILLA_BINARY) + "' " + args + " >'" + (dir / "out").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  auto out = ReadFile(dir / "out");
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out.ok() ? *out : ""};
}

}  // namespace

TEST_CASE("Retrieval by a remote embedding model: the request, the ranking, the cache answering a second run", "[assets][embeddings]") {
  const fs::path cache = test::FreshDir("embed_cache_" + std::to_string(::getpid()));
  const std::vector<AssetRecord> records{Procedural("sofa", {2.0, 0.9, 0.85}), Procedural("bookcase", {0.9, 0.35, 1.8}),
                                         Procedural("dining-table", {1.6, 0.9, 0.75})};
  // The model puts the query next to the bookcase.
  ScriptedServer server({Vectors({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), Vectors({{0.1, 0.9, 0.0}})});
  auto remote = std::make_shared<RemoteEmbedder>(EmbeddingModel(server));
  auto cached = std::make_shared<CachedEmbedder>(remote, cache);
  auto retriever = AssetRetriever::Build(records, cached);
  REQUIRE(retriever.ok());
  RetrievalQuery query;
  query.text = "something to keep my novels in";
  RetrievalOptions options;
  options.k = 3;
  options.category_weight = 0.0;
  options.range_weight = 0.0;
  auto ranked = retriever->Rank(query, options);
  REQUIRE(ranked.ok());
  REQUIRE(ranked->ranked.size() == 3);
  CHECK(ranked->ranked[0].asset->category == "bookcase");
  const auto bodies = server.bodies();
  REQUIRE(bodies.size() == 2);
  CHECK(server.paths()[0] == "/v1/embeddings");
  CHECK(bodies[0]["model"] == "villa-embed");
  REQUIRE(bodies[0]["input"].size() == 3);
  CHECK(bodies[0]["input"][1] == AssetText(records[1]));
  CHECK(bodies[1]["input"].size() == 1);
  CHECK(remote->Name() == "remote:villa-embed@" + server.url() + "/v1/embeddings");

  // The same texts again (a second run): from the disk cache, no request.
  auto again_cached = std::make_shared<CachedEmbedder>(std::make_shared<RemoteEmbedder>(EmbeddingModel(server)), cache);
  auto again = AssetRetriever::Build(records, again_cached);
  REQUIRE(again.ok());
  auto ranked_again = again->Rank(query, options);
  REQUIRE(ranked_again.ok());
  CHECK(ranked_again->ranked[0].asset->id == ranked->ranked[0].asset->id);
  CHECK(server.bodies().size() == 2);
  CHECK(again_cached->hits() == 4);
  CHECK(again_cached->misses() == 0);

  // A server that fails says so, with its words and where.
  ScriptedServer failing({Failure(400, "model villa-embed does not exist")});
  auto broken = AssetRetriever::Build(records, std::make_shared<RemoteEmbedder>(EmbeddingModel(failing)));
  REQUIRE_FALSE(broken.ok());
  CHECK(broken.error().find("/v1/embeddings") != std::string::npos);
  CHECK(broken.error().find("model villa-embed does not exist") != std::string::npos);
  fs::remove_all(cache);
}

TEST_CASE("Turning an asset to its picked front turns its mesh, size, surfaces and cavities together", "[assets][front]") {
  AssetRecord r;
  r.id = "sh3d:Test#thing";
  r.size = {1.0, 0.5, 0.8};
  r.support_surfaces = {{0.4, {{-0.5, -0.25}, {0.5, -0.25}, {0.5, 0.25}, {-0.5, 0.25}}, 0.4, "mesh"}};
  r.cavities = {{{-0.4, -0.2, 0.1}, {0.0, 0.2, 0.4}, "-y", 0, std::nullopt}};
  AssetMesh mesh;
  mesh.parts.push_back({{}, {}});
  mesh.parts[0].mesh.vertices = {{0.5, -0.25, 0.0}, {-0.5, 0.25, 0.8}};
  // The front is the side seen from +x (picture 2): a quarter turn clockwise brings it to -y.
  const TurnedAsset t = TurnAsset(r, mesh, 1);
  CHECK(t.record.size.x == 0.5);
  CHECK(t.record.size.y == 1.0);
  CHECK(t.mesh.parts[0].mesh.vertices[0].x == -0.25);
  CHECK(t.mesh.parts[0].mesh.vertices[0].y == -0.5);
  CHECK(t.record.front_yaw_offset == 270);
  CHECK(t.record.cavities[0].open == "-x");  // the old front is now the left-hand side seen from the new front
  CHECK(t.record.cavities[0].min.x == -0.2);
  CHECK(t.record.cavities[0].max.y == 0.4);
  CHECK(t.record.to_asset[0][1] == 1.0);   // x' = y of the source frame
  CHECK(t.record.to_asset[1][0] == -1.0);  // y' = -x
  // Four quarter turns (any view four times) come back to the start.
  TurnedAsset back{r, mesh};
  for (int k = 0; k < 4; ++k) back = TurnAsset(back.record, back.mesh, 1);
  CHECK(back.record.size.x == 1.0);
  CHECK(back.mesh.parts[0].mesh.vertices[0].x == 0.5);
  CHECK(back.record.front_yaw_offset == 0);
  CHECK(back.record.cavities[0].open == "-y");
}

TEST_CASE("The model picks the front from four views, the library is rewritten with the turned asset and who decided", "[assets][front]") {
  const fs::path dir = ImportedLibrary("front");
  auto library = AssetLibrary::Open(dir / "lib");
  REQUIRE(library.ok());
  const std::string id = "sh3d:TestLib#chest";
  const AssetRecord* record = library->Find(id);
  REQUIRE(record);
  auto mesh = library->Mesh(id);
  REQUIRE(mesh.ok());
  ScriptedServer server({Completion("the front is picture two"),
                         Completion(Json{{"front", 2}, {"confidence", 0.8}, {"reason", "the lid opens that way"}}.dump())});
  FrontPickOptions options;
  options.llm.url = server.url();
  options.llm.model = "villa-vision";
  options.llm.max_retries = 0;
  options.views.size_px = 128;
  auto pick = PickAssetFront(*record, **mesh, options);
  REQUIRE(pick.ok());
  CHECK(pick->view == 1);
  CHECK(pick->turn_deg == -90);
  CHECK(pick->reason == "the lid opens that way");
  const auto bodies = server.bodies();
  REQUIRE(bodies.size() == 2);  // the prose answer was asked again
  int images = 0;
  for (const Json& part : bodies[0]["messages"][1]["content"])
    if (part["type"] == "image_url") {
      ++images;
      CHECK(part["image_url"]["url"].get<std::string>().rfind("data:image/png;base64,", 0) == 0);
    }
  CHECK(images == 4);
  CHECK(bodies[0]["response_format"]["json_schema"]["name"] == "asset_front");

  const std::string old_mesh = record->mesh.file;
  const Vec3 old_size = record->size;
  auto written = WriteAssetFront(dir / "lib", id, pick->view, "a test decided");
  REQUIRE(written.ok());
  auto reread = AssetLibrary::Open(dir / "lib");
  REQUIRE(reread.ok());
  const AssetRecord* turned = reread->Find(id);
  REQUIRE(turned);
  CHECK(turned->front_yaw_offset == 270);
  CHECK(turned->front_decided_by == "a test decided");
  CHECK(turned->size.x == Approx(old_size.y));
  CHECK(turned->size.y == Approx(old_size.x));
  CHECK(turned->mesh.file != old_mesh);
  CHECK(fs::exists(dir / "lib" / old_mesh));  // the old mesh stays: the library was whole at every step
  auto turned_mesh = reread->Mesh(id);
  REQUIRE(turned_mesh.ok());
  const Box3 b = (*turned_mesh)->Bounds();
  CHECK(b.max.x - b.min.x == Approx(turned->size.x).margin(0.01));
  CHECK(b.max.y - b.min.y == Approx(turned->size.y).margin(0.01));
  CHECK(reread->records().size() == library->records().size());
  // A second decision turns from the turned asset, and names one mesh file per offset.
  REQUIRE(WriteAssetFront(dir / "lib", id, 1, "again").ok());
  auto third = AssetLibrary::Open(dir / "lib");
  REQUIRE(third.ok());
  CHECK(third->Find(id)->front_yaw_offset == 180);
  CHECK(third->Find(id)->mesh.file.find("@front180") != std::string::npos);
  // Confirming the recorded front changes only the note; procedural assets are refused.
  REQUIRE(WriteAssetFront(dir / "lib", "sh3d:TestLib#bookcase", 0, "confirmed").ok());
  CHECK(AssetLibrary::Open(dir / "lib")->Find("sh3d:TestLib#bookcase")->front_yaw_offset == 0);
  CHECK_FALSE(WriteAssetFront(dir / "lib", "sh3d:TestLib#nothing", 1, "x").ok());
  fs::remove_all(dir);
}

TEST_CASE("An asset is drawn from four sides with its surfaces and cavities", "[assets][views]") {
  const AssetRecord bookcase = Procedural("bookcase", {0.9, 0.35, 1.8});
  auto made = MakeProceduralAsset(bookcase.id);
  REQUIRE(made.ok());
  REQUIRE_FALSE(bookcase.cavities.empty());
  AssetViewOptions options;
  options.size_px = 128;
  auto with = RenderAssetViews(bookcase, made->mesh, options);
  REQUIRE(with.ok());
  REQUIRE(with->size() == 4);
  CHECK((*with)[0].side == "-y");
  CHECK((*with)[1].side == "+x");
  options.overlays = false;
  auto without = RenderAssetViews(bookcase, made->mesh, options);
  REQUIRE(without.ok());
  int differing = 0;
  for (size_t i = 0; i < (*with)[0].image.rgb.size(); ++i) differing += (*with)[0].image.rgb[i] != (*without)[0].image.rgb[i];
  CHECK(differing > 500);
  auto sheet = AssetViewSheet(*with);
  REQUIRE(sheet.ok());
  CHECK(sheet->width == 2 * 128 + 6);
  CHECK(sheet->height == 2 * 128 + 6);
}

TEST_CASE("villa assets show --render, search --embeddings and front --mllm", "[assets][cli]") {
  const fs::path dir = ImportedLibrary("cli_models");
  const std::string lib = " --library '" + (dir / "lib").string() + "'";
  Run show = Villa(dir, "assets show sh3d:TestLib#bookcase --size 96 --render '" + (dir / "bookcase.png").string() + "'" + lib);
  INFO(show.out);
  REQUIRE(show.code == 0);
  auto png = ReadFile(dir / "bookcase.png");
  REQUIRE(png.ok());
  CHECK(png->compare(0, 8, std::string("\x89PNG\r\n\x1a\n", 8)) == 0);
  CHECK(Villa(dir, "assets show sh3d:TestLib#bookcase --render '" + (dir / "bookcase.jpg").string() + "'" + lib).code == 2);

  auto records = AssetLibrary::Open(dir / "lib");
  REQUIRE(records.ok());
  const size_t n = records->records().size();
  std::vector<std::vector<double>> vectors(n, {0.0, 1.0});
  for (size_t i = 0; i < n; ++i)
    if (records->records()[i].id == "sh3d:TestLib#bookcase") vectors[i] = {1.0, 0.0};
  ScriptedServer server({Vectors(vectors), Vectors({{1.0, 0.0}}), Completion(Json{{"front", 1}, {"confidence", 1}, {"reason", "shelves"}}.dump())});
  Run search = Villa(dir, "assets search 'a place for my novels' --no-procedural --json -k 1 --embeddings " + server.url() +
                              " --model villa-embed --embeddings-cache '" + (dir / "cache").string() + "'" + lib);
  INFO(search.out);
  REQUIRE(search.code == 0);
  CHECK(search.out.find("sh3d:TestLib#bookcase") != std::string::npos);
  CHECK(server.bodies()[0]["input"].size() == n);
  Run no_model = Villa(dir, "assets search shelf --embeddings " + server.url() + lib);
  CHECK(no_model.code == 2);
  CHECK(no_model.out.find("--model") != std::string::npos);

  Run front = Villa(dir, "assets front sh3d:TestLib#bookcase --mllm " + server.url() + " --model villa-vision --no-cache" + lib);
  INFO(front.out);
  REQUIRE(front.code == 0);
  CHECK(front.out.find("the front is picture 1 of 4") != std::string::npos);
  auto after = AssetLibrary::Open(dir / "lib");
  REQUIRE(after.ok());
  CHECK(after->Find("sh3d:TestLib#bookcase")->front_decided_by.find("model villa-vision") != std::string::npos);
  CHECK(Villa(dir, "assets front sh3d:TestLib#bookcase --model m" + lib).code == 2);
  fs::remove_all(dir);
}

}  // namespace villa
