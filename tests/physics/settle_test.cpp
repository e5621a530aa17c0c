// Bullet settles (physics/settle.h): what falls is reported and what rests stays, welded things hold,
// bodies that start inside one another are named with how deep, and `villa physics` reads a .glb.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "mesh/solids.h"
#include "physics/glb_settle.h"
#include "physics/settle.h"
#include "villa_cli.h"

namespace villa::physics {
namespace {

// A closed box (12 triangles, outward) appended to `mesh` as its own piece.
void AddBox(TriangleMesh& mesh, Vec3 lo, Vec3 hi) {
  const int base = static_cast<int>(mesh.vertices.size());
  for (int k = 0; k < 8; ++k) mesh.vertices.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& f : faces) mesh.AddTriangle(base + f[0], base + f[1], base + f[2]);
}
TriangleMesh Box(Vec3 lo, Vec3 hi) {
  TriangleMesh m;
  AddBox(m, lo, hi);
  return m;
}
SettleBody Body(const std::string& id, TriangleMesh mesh, bool welded = false) { return {id, std::move(mesh), welded}; }

const std::vector<TriangleMesh> kFloor = {Box({-3, -3, -0.2}, {3, 3, 0})};

TEST_CASE("A cup floating above a table falls and is reported, the table and a cup resting on it stay", "[physics]") {
  TriangleMesh table;
  AddBox(table, {-0.4, -0.4, 0.71}, {0.4, 0.4, 0.75});  // top
  for (double x : {-0.35, 0.35})
    for (double y : {-0.35, 0.35}) AddBox(table, {x - 0.03, y - 0.03, 0}, {x + 0.03, y + 0.03, 0.71});
  const std::vector<SettleBody> bodies = {Body("table", table), Body("cup", Box({-0.2, -0.04, 0.75}, {-0.12, 0.04, 0.85})),
                                          Body("floating", Box({0.1, -0.04, 0.80}, {0.18, 0.04, 0.90}))};
  auto settled = Settle(kFloor, bodies);
  REQUIRE(settled.ok());
  const SettleResult& r = *settled;
  CHECK(r.free == 3);
  CHECK(r.bodies[0].parts == 5);
  CHECK(r.bodies[0].strict);
  CHECK(r.bodies[1].strict);
  CHECK(r.bodies[1].moved < 0.005);
  CHECK_FALSE(r.bodies[2].strict);
  CHECK(r.bodies[2].loose);
  CHECK(r.bodies[2].shift.z == Approx(-0.05).margin(0.005));
  CHECK(r.strict == 2);
  CHECK(r.starts_inside == 0);
}

TEST_CASE("A settle stops once every free body sleeps, and runs the whole time while one still falls", "[physics]") {
  const TriangleMesh crate = Box({-0.3, -0.3, 0}, {0.3, 0.3, 0.5}), lid = Box({-0.1, -0.1, 0.5}, {0.1, 0.1, 0.6});
  auto rest = Settle(kFloor, {Body("crate", crate), Body("lid", lid)});
  REQUIRE(rest.ok());
  CHECK(rest->steps < 240);  // asleep within the first second of the two
  CHECK(rest->strict == 2);
  CHECK(rest->bodies[1].moved < 0.001);
  // A box dropped from 30 m is still falling after 2 s (19.6 m): all 480 steps, and it fell that far.
  auto fall = Settle(kFloor, {Body("crate", crate), Body("dropped", Box({1.0, 1.0, 30.0}, {1.2, 1.2, 30.2}))});
  REQUIRE(fall.ok());
  CHECK(fall->steps == 480);
  CHECK(fall->bodies[1].shift.z == Approx(-0.5 * 9.81 * 4.0).epsilon(0.02));
}

TEST_CASE("A welded picture stays on its wall, the same picture unwelded falls to the floor", "[physics]") {
  const TriangleMesh picture = Box({-0.3, 0.97, 1.3}, {0.3, 1.0, 1.7});
  // A wall shelf with a cup on it: welded, it holds the cup; free, both fall.
  const TriangleMesh shelf = Box({-0.4, 0.8, 1.0}, {0.4, 1.0, 1.02}), cup = Box({-0.04, 0.86, 1.02}, {0.04, 0.94, 1.12});
  for (const bool welded : {true, false}) {
    auto settled = Settle(kFloor, {Body("picture", picture, welded), Body("shelf", shelf, welded), Body("cup", cup)});
    REQUIRE(settled.ok());
    const BodyMotion& m = settled->bodies[0];
    CHECK(m.welded == welded);
    CHECK(settled->free == (welded ? 1 : 3));
    if (welded) CHECK(m.moved == 0.0);
    else CHECK(m.moved > 1.0);
    CHECK(settled->bodies[2].strict == welded);  // the cup stays only on a welded shelf
    if (!welded) CHECK(settled->bodies[2].shift.z < -0.9);
  }
}

TEST_CASE("A book taller than its shelf starts inside the board above, named with how deep", "[physics]") {
  TriangleMesh shelf;
  AddBox(shelf, {-0.4, -0.15, 0.0}, {0.4, 0.15, 0.02});   // bottom board
  AddBox(shelf, {-0.4, -0.15, 0.24}, {0.4, 0.15, 0.26});  // the board above: 0.22 m clear
  AddBox(shelf, {-0.42, -0.15, 0.0}, {-0.4, 0.15, 0.26});
  AddBox(shelf, {0.4, -0.15, 0.0}, {0.42, 0.15, 0.26});
  for (const double h : {0.20, 0.25}) {
    auto settled = Settle(kFloor, {Body("shelf", shelf), Body("book", Box({-0.1, -0.1, 0.02}, {0.0, 0.1, 0.02 + h}))}, {.seconds = 0.1});
    REQUIRE(settled.ok());
    const BodyMotion& book = settled->bodies[1];
    if (h < 0.22) {
      CHECK(book.start_depth < 0.002);
      CHECK(settled->starts_inside == 0);
    } else {
      CHECK(book.start_depth == Approx(0.03).margin(0.004));
      CHECK(book.start_against == "shelf");
      CHECK(book.start_out.z < -0.7);  // out of the board above: down
      CHECK(settled->bodies[0].start_out.z > 0.7);
      CHECK(settled->starts_inside == 2);  // the book and the shelf
    }
  }
}

TEST_CASE("A mesh's convex parts are its connected pieces", "[physics]") {
  TriangleMesh m = Box({0, 0, 0}, {1, 1, 1});
  AddBox(m, {2, 0, 0}, {3, 1, 1});
  const auto pieces = ConnectedPieces(m);
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0].size() == 8);
  CHECK(pieces[1][0].x == 2.0);
  SettleOptions bad;
  bad.seconds = 0.0;
  CHECK(Settle({}, {}, bad).error() == "settle: seconds must be in (0, 60], got 0.000000");
}

TEST_CASE("A tray modelled as one piece holds what lies in it: its convex parts, not its hull", "[physics]") {
  // A 0.6 x 0.4 m tray: a 2 cm base and a 3 cm rim round a recess, one closed piece (a stack of prisms).
  const Ring outer{{-0.3, -0.2}, {0.3, -0.2}, {0.3, 0.2}, {-0.3, 0.2}}, inner{{-0.27, -0.17}, {-0.27, 0.17}, {0.27, 0.17}, {0.27, -0.17}};
  const TriangleMesh tray = ExtrudePlan(outer, {}, 0.0, 0.02);
  const TriangleMesh rim = ExtrudePlan(outer, {inner}, 0.02, 0.05);
  // One piece: the rim's bottom and the base's top are glued where they meet (vertices shared).
  TriangleMesh piece;
  for (const TriangleMesh* m : std::initializer_list<const TriangleMesh*>{&tray, &rim})
    for (const auto& t : m->triangles) {
      int ids[3];
      for (int k = 0; k < 3; ++k) ids[k] = piece.AddVertex(m->vertices[t[k]], 1e-9);
      piece.AddTriangle(ids[0], ids[1], ids[2]);
    }
  // Faces back to back inside (the base's top under the rim, the rim's bottom) cancel in the cross-section.
  const auto parts = ConnectedPieces(piece);
  CHECK(parts.size() > 1);  // its hull would fill the recess
  const TriangleMesh cup = Box({-0.05, -0.05, 0.02}, {0.05, 0.05, 0.1});
  auto settled = Settle(kFloor, {Body("tray", piece), Body("cup", cup)});
  REQUIRE(settled.ok());
  CHECK(settled->bodies[1].start_depth < 0.002);
  CHECK(settled->bodies[1].strict);
  CHECK(settled->bodies[0].strict);
}

TEST_CASE("A bed modelled in one piece holds a pillow at its head: its hollows cut out where the pillow lies", "[physics]") {
  // A 2 x 1.5 m bed in one closed piece, as imported models are: its profile (a 1 m headboard, a 0.3 m base
  // and a 0.6 m footboard) extruded across its width, the headboard's top rising 0.2 m toward one side and
  // bevelled 3 cm toward the bed (no stack of prisms). Its hull is a wedge over the base; the pillow at the head starts 0.4 m inside it.
  const Ring profile{{0, 0}, {2, 0}, {2, 0.6}, {1.95, 0.6}, {1.95, 0.3}, {0.05, 0.3}, {0.05, 1.0}, {0, 1.0}};
  const TriangleMesh flat = ExtrudePlan(profile, {}, 0.0, 1.5);
  TriangleMesh bed;
  for (const Vec3& v : flat.vertices) bed.vertices.push_back({v.x, v.z, v.y + (v.y > 0.9 ? 0.2 * v.z / 1.5 - (v.x > 0.01 ? 0.03 : 0.0) : 0.0)});
  for (const auto& t : flat.triangles) bed.AddTriangle(t[0], t[2], t[1]);  // (x, y, z) -> (x, z, y) mirrors
  REQUIRE(bed.SignedVolume() == Approx(1.5 * (2 * 0.3 + 0.05 * 0.7 + 0.05 * 0.3) + 0.05 * 0.1 * 1.5 - 0.5 * 0.05 * 0.03 * 1.5).epsilon(1e-6));
  REQUIRE(ConnectedPieces(bed).size() == 1);  // uncut: its hull
  const TriangleMesh pillow = Box({0.1, 0.5, 0.3}, {0.6, 1.0, 0.45});
  const std::vector<Box3> guides{pillow.Bounds()};
  const auto parts = ConnectedPieces(bed, &guides);
  CHECK(parts.size() >= 3);  // headboard, base, footboard at least
  CHECK(parts.size() <= 32);
  auto settled = Settle(kFloor, {Body("bed", bed), Body("pillow", pillow)});
  REQUIRE(settled.ok());
  const SettleResult& r = *settled;
  CHECK(r.bodies[0].parts == static_cast<int>(parts.size()));  // the settle cut the bed the pillow starts in
  CHECK(r.bodies[1].start_depth < 0.002);
  CHECK(r.starts_inside == 0);
  CHECK(r.bodies[0].strict);
  CHECK(r.bodies[1].strict);
}

TEST_CASE("A washbasin against a wall is welded (plumbed and bolted), the toilet beside it is free", "[physics][cli]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("villa_physics_weld_" + std::to_string(::getpid()));
  const testing::CliRun furnished =
      testing::RunVilla("furnish " + std::string(VILLA_FIXTURE_DIR) + "/layouts/living_angled_tv.json -o " + dir.string() +
                        " --room bathroom_1/0 --seed 2027 --no-reach --critic none --no-physics --force");
  REQUIRE(furnished.status == 0);
  auto bodies = ReadGlbBodies(dir / "furnished.glb");
  REQUIRE(bodies.ok());
  int basins = 0, toilets = 0;
  for (size_t i = 0; i < bodies->bodies.size(); ++i) {
    const GlbObjectMotion& o = bodies->objects[i];
    INFO(o.id);
    if (o.category == "washbasin") {
      CHECK(bodies->bodies[i].welded);
      ++basins;
    }
    if (o.category == "toilet") {
      CHECK_FALSE(bodies->bodies[i].welded);
      ++toilets;
    }
  }
  CHECK(basins >= 1);
  CHECK(toilets >= 1);
  std::filesystem::remove_all(dir);
}

TEST_CASE("The physics summary lists each object that starts more than 2 mm inside another, with how deep", "[physics]") {
  GlbSettleSummary s;
  s.objects.resize(3);
  s.objects[0].id = "bedroom_0/0/books-0";
  s.objects[0].motion.start_depth = 0.0061;
  s.objects[0].motion.start_against = "bedroom_0/0/nightstand-0";
  s.objects[1].id = "bedroom_0/0/pillow-0";
  s.objects[1].motion.start_depth = 0.0019;  // within the 2 mm tolerance: not listed
  s.objects[2].id = "utility-room_0/0/washing-machine-0";
  s.objects[2].motion.start_depth = 0.0028;
  s.objects[2].motion.start_against = "building";
  s.starts_inside = 2;
  const auto j = SettleSummaryJson(s, SettleOptions{}, 10);
  REQUIRE(j["inside"].size() == 2);
  CHECK(j["inside"][0]["id"] == "bedroom_0/0/books-0");
  CHECK(j["inside"][0]["depth_m"].get<double>() == Approx(0.0061));
  CHECK(j["inside"][0]["against"] == "bedroom_0/0/nightstand-0");
  CHECK(j["inside"][1]["id"] == "utility-room_0/0/washing-machine-0");
  CHECK(j["inside"][1]["against"] == "building");
}

TEST_CASE("villa physics names a missing file and exits 2", "[physics][cli]") {
  const testing::CliRun missing = testing::RunVilla("physics /nonexistent/x.glb");
  CHECK(missing.status == 2);
  CHECK(missing.out.find("/nonexistent/x.glb: no such file") != std::string::npos);
}

TEST_CASE("villa physics settles a furnished room's .glb: everything stays within the loose rule", "[physics][cli]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("villa_physics_" + std::to_string(::getpid()));
  const testing::CliRun furnished =
      testing::RunVilla("furnish " + std::string(VILLA_FIXTURE_DIR) + "/layouts/living_angled_tv.json -o " + dir.string() +
                        " --room living-room_0/0 --seed 2027 --no-reach --critic none --force");
  REQUIRE(furnished.status == 0);
  const testing::CliRun run = testing::RunVilla("physics " + (dir / "furnished.glb").string() + " --json");
  INFO(run.out);
  REQUIRE(run.status == 0);
  const auto j = nlohmann::json::parse(run.out.substr(run.out.find('{')));
  CHECK(j["format"] == "villa-physics/1");
  CHECK(j["all"]["free"].get<int>() >= 15);
  CHECK(j["all"]["loose_share"] == 1.0);
  CHECK(j["all"]["strict_share"].get<double>() >= 0.9);
  CHECK(j["by_room_type"].contains("living-room"));
  CHECK(j["decals"].get<int>() >= 1);  // the living room's rug
  CHECK(j["inside"].size() == j["starts_inside"].get<size_t>());
  // The furnish report's physics is the same settle of the same bytes.
  std::ifstream in(dir / "report.json");
  const auto report = nlohmann::json::parse(in);
  CHECK(report["physics"]["all"] == j["all"]);
  CHECK(report["physics"]["by_room_type"] == j["by_room_type"]);
  CHECK(furnished.out.find("physics: ") != std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace villa::physics
