// Scoring furnished .glb files (solver/glb_metrics.h): our own file scores as its report says (from the
// layout and from the .glb alone), and hand-made files in villa's glTF contract with a deliberate
// collision, a floating object, one out of bounds, and a turned object are scored as they are.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "building/glb_writer.h"
#include "solver/glb_metrics.h"
#include "util/atomic_file.h"
#include "test_files.h"
#include "villa_cli.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {

using testing::TempDir;
std::string Read(const fs::path& p) { return testing::ReadFile(p); }

// Plan (x, y, z), z up, in glTF's +Y-up file frame.
std::array<float, 3> File(double x, double y, double z) {
  return {static_cast<float>(x), static_cast<float>(z), static_cast<float>(-y)};
}

// A box from `lo` to `hi` (plan frame) as a glTF mesh, faces outward.
gltf::Mesh BoxMesh(const std::string& name, Vec3 lo, Vec3 hi) {
  gltf::Mesh mesh;
  mesh.name = name;
  gltf::Primitive p;
  p.material = 0;
  for (int k = 0; k < 8; ++k) {
    const auto v = File(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    p.positions.insert(p.positions.end(), v.begin(), v.end());
  }
  // Counter-clockwise seen from outside, in the plan frame (the file map keeps the handedness).
  const uint32_t faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& f : faces) p.indices.insert(p.indices.end(), {f[0], f[1], f[2]});
  mesh.primitives.push_back(std::move(p));
  return mesh;
}

gltf::Node MakeNode(const std::string& name, int mesh, std::vector<int> children = {}) {
  gltf::Node n;
  n.name = name;
  n.mesh = mesh;
  n.children = std::move(children);
  return n;
}

struct Box {
  std::string id;
  Vec3 at;           // plan position of the bottom centre
  double yaw = 0.0;  // rad
  int mesh = 1;      // 1: a 1 m cube; 2: a 2 x 0.5 x 0.8 bench; 3: a 0.2 m cube
  std::string parent = "floor";
  std::string relation = "ontop";
};

// The top of an L-shaped floor slab (0.175 thick): the 4 x 4 m square less its 2 x 2 m north-east quarter.
gltf::Mesh LFloorMesh() {
  gltf::Mesh mesh;
  mesh.name = "floor";
  gltf::Primitive p;
  p.material = 0;
  const double ring[6][2] = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  for (const auto& v : ring) {
    const auto f = File(v[0], v[1], 0.175);
    p.positions.insert(p.positions.end(), f.begin(), f.end());
  }
  // A fan from the south-west corner, counter-clockwise from above.
  for (uint32_t k = 1; k + 1 < 6; ++k) p.indices.insert(p.indices.end(), {0u, k, k + 1});
  mesh.primitives.push_back(std::move(p));
  return mesh;
}

// A one-room building in villa's contract: villa / level_0 / living-room_0/0 (a 4 x 4 m floor slab whose
// top is at 0.175) holding one node per box, extras as `villa furnish` writes them.
void WriteRoom(const fs::path& path, const std::vector<Box>& boxes, bool l_floor = false) {
  gltf::Document doc;
  doc.materials.push_back(gltf::Material{"grey"});
  doc.meshes.push_back(l_floor ? LFloorMesh() : BoxMesh("floor", {0, 0, 0}, {4, 4, 0.175}));
  doc.meshes.push_back(BoxMesh("cube", {-0.5, -0.5, 0}, {0.5, 0.5, 1.0}));
  doc.meshes.push_back(BoxMesh("bench", {-1.0, -0.25, 0}, {1.0, 0.25, 0.8}));
  doc.meshes.push_back(BoxMesh("small", {-0.1, -0.1, 0}, {0.1, 0.1, 0.2}));
  doc.nodes.push_back(MakeNode("villa", -1, {1}));
  doc.nodes.push_back(MakeNode("level_0", -1, {2}));
  gltf::Node room = MakeNode("living-room_0/0", 0);
  room.extras = {{"name", "living-room_0/0"}, {"category", "living-room"}, {"area_m2", 16.0}, {"level", 0}};
  doc.nodes.push_back(room);
  for (const Box& b : boxes) {
    gltf::Node n = MakeNode(b.id, b.mesh);
    const auto t = File(b.at.x, b.at.y, b.at.z);
    n.translation = std::array<double, 3>{t[0], t[1], t[2]};
    n.rotation = std::array<double, 4>{0.0, std::sin(b.yaw / 2), 0.0, std::cos(b.yaw / 2)};  // a turn about +Y: the yaw
    n.extras = {{"name", b.id}, {"id", b.id}, {"category", "box"}, {"asset", "hand-made"}, {"room", "living-room_0/0"},
                {"level", 0}, {"parent", b.parent}, {"relation", b.relation}};
    doc.nodes[2].children.push_back(static_cast<int>(doc.nodes.size()));
    doc.nodes.push_back(std::move(n));
  }
  doc.roots = {0};
  REQUIRE(WriteFileAtomic(path, gltf::WriteGlb(doc)));
}

// The one room of a file written by WriteRoom, measured from the .glb alone.
solver::GlbRoomMetrics MeasureRoom(const fs::path& glb, const std::vector<Box>& boxes, bool l_floor = false) {
  WriteRoom(glb, boxes, l_floor);
  auto s = solver::MeasureFurnishedGlb(glb);
  INFO((s.ok() ? s->frame : s.error()));
  REQUIRE(s.ok());
  CHECK(s->frame == "glb");
  REQUIRE(s->rooms.size() == 1);
  return s->rooms.front();
}

}  // namespace

TEST_CASE("A hand-made .glb: a deliberate collision, a floating object and one out of bounds are counted", "[solver][glb]") {
  TempDir dir("glbm_hand");
  const fs::path glb = dir.path / "room.glb";
  // cube-0 and cube-1 overlap by 0.3 m; cube-2 floats 0.2 m above the floor; cube-3 pokes 0.4 m out.
  const solver::GlbRoomMetrics room = MeasureRoom(glb, {{"living-room_0/0/cube-0", {1.0, 1.0, 0.175}},
                                                        {"living-room_0/0/cube-1", {1.7, 1.0, 0.175}},
                                                        {"living-room_0/0/cube-2", {1.0, 3.0, 0.375}},
                                                        {"living-room_0/0/cube-3", {3.9, 3.0, 0.175}}});
  CHECK(room.room == "living-room_0/0");
  CHECK(room.category == Category::kLivingRoom);
  const solver::ExactMetrics& m = room.metrics;
  CHECK(m.objects == 4);
  CHECK(m.colliding == 2);
  CHECK(m.cr == Approx(0.5));
  REQUIRE(m.pairs.size() == 1);
  CHECK(m.pairs[0].a == "living-room_0/0/cube-0");
  CHECK(m.pairs[0].b == "living-room_0/0/cube-1");
  CHECK(m.floating == 1);
  CHECK(m.per_object[2].floating);
  CHECK(m.per_object[2].support_gap == Approx(0.2).margin(1e-4));
  CHECK(m.out_of_bounds == 1);
  CHECK(m.per_object[3].out_of_bounds);
  CHECK(m.inside_edges == 0);
  CHECK(room.records_from_mesh == 4);  // "hand-made" is no asset villa knows: surfaces read off the meshes

  // Apart, on the floor, inside: clean.
  const solver::ExactMetrics clean =
      MeasureRoom(glb, {{"living-room_0/0/cube-0", {1.0, 1.0, 0.175}}, {"living-room_0/0/cube-1", {2.6, 1.0, 0.175}}}).metrics;
  CHECK(clean.objects == 2);
  CHECK(clean.Clean());
}

TEST_CASE("A turned object is read with its yaw: a bench turned 90 degrees misses the cube it would hit", "[solver][glb]") {
  TempDir dir("glbm_yaw");
  const fs::path glb = dir.path / "room.glb";
  // Unturned, the 2 m bench at x = 1.5 reaches x = 2.5 and hits the cube at x = 2.8 (its face at 2.3).
  const Box cube{"living-room_0/0/cube-0", {2.8, 2.0, 0.175}};
  CHECK(MeasureRoom(glb, {{"living-room_0/0/bench-0", {1.5, 2.0, 0.175}, 0.0, 2}, cube}).metrics.colliding == 2);
  CHECK(MeasureRoom(glb, {{"living-room_0/0/bench-0", {1.5, 2.0, 0.175}, std::numbers::pi / 2, 2}, cube}).metrics.Clean());
}

TEST_CASE("A child on a parent known only by its mesh rests on what is under it: on the top it is supported, above it floats",
          "[solver][glb]") {
  TempDir dir("glbm_contact");
  const fs::path glb = dir.path / "room.glb";
  const Box bench{"living-room_0/0/bench-0", {2.0, 2.0, 0.175}, 0.0, 2};
  // On the bench's top (0.175 + 0.8), near its end; then 5 cm above it.
  const solver::GlbRoomMetrics on =
      MeasureRoom(glb, {bench, {"living-room_0/0/cup-0", {2.8, 2.0, 0.975}, 0.0, 3, "living-room_0/0/bench-0"}});
  CHECK(on.metrics.objects == 2);
  CHECK(on.metrics.Clean());
  const solver::GlbRoomMetrics above =
      MeasureRoom(glb, {bench, {"living-room_0/0/cup-0", {2.8, 2.0, 1.025}, 0.0, 3, "living-room_0/0/bench-0"}});
  CHECK(above.metrics.floating == 1);
  CHECK(above.metrics.per_object[1].support_gap == Approx(0.05).margin(1e-4));
  CHECK(above.metrics.colliding == 0);
  // Half over the end of the bench: out of its bounds.
  const solver::GlbRoomMetrics over =
      MeasureRoom(glb, {bench, {"living-room_0/0/cup-0", {3.0, 2.0, 0.975}, 0.0, 3, "living-room_0/0/bench-0"}});
  CHECK(over.metrics.out_of_bounds == 1);
}

TEST_CASE("Our own furnished.glb scores as its report says, from its layout and from the .glb alone", "[solver][glb]") {
  TempDir dir("glbm_own");
  const std::string house = std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json";
  const auto run = testing::RunVilla("furnish " + house + " --procedural --seed 4 -q -o " + dir.path.string());
  INFO(run.out);
  REQUIRE(run.status == 0);
  const auto report = nlohmann::json::parse(Read(dir.path / "report.json"));
  std::map<std::string, nlohmann::json> expected;
  for (const auto& r : report["rooms"]) expected[r["room"].get<std::string>()] = r["metrics"];

  solver::GlbMetricsOptions with_scene;
  with_scene.scene = dir.path / "scene.json";
  for (const solver::GlbMetricsOptions& options : {with_scene, solver::GlbMetricsOptions{}}) {
    auto s = solver::MeasureFurnishedGlb(dir.path / "furnished.glb", options);
    INFO((s.ok() ? s->frame : s.error()));
    REQUIRE(s.ok());
    CHECK(s->frame.rfind(options.scene.empty() ? "glb" : "layout", 0) == 0);
    REQUIRE(s->rooms.size() == expected.size());
    int objects = 0;
    for (const solver::GlbRoomMetrics& r : s->rooms) {
      INFO(r.room);
      REQUIRE(expected.count(r.room));
      const nlohmann::json& e = expected[r.room];
      const solver::ExactMetrics& m = r.metrics;
      CHECK(m.objects == e["NO"].get<int>());
      CHECK(m.cr == Approx(e["CR"].get<double>()).margin(1e-4));
      CHECK(m.fr == Approx(e["FR"].get<double>()).margin(1e-4));
      CHECK(m.obr == Approx(e["OBR"].get<double>()).margin(1e-4));
      if (e.contains("CSR")) CHECK(m.csr == Approx(e["CSR"].get<double>()).margin(1e-4));
      CHECK(r.records_from_mesh == 0);  // every asset is procedural: its record is rebuilt from its id
      CHECK(r.records_resolved == m.objects);
      objects += m.objects;
      for (const solver::CollisionPair& p : m.pairs) INFO(p.a << " x " << p.b);
    }
    CHECK(objects == report["totals"]["objects"].get<int>());
    CHECK(objects > 50);
  }
  // A bad scene path is an error naming it.
  solver::GlbMetricsOptions missing;
  missing.scene = dir.path / "nope.json";
  auto bad = solver::MeasureFurnishedGlb(dir.path / "furnished.glb", missing);
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().find("nope.json") != std::string::npos);
  // Issue 33: a layout other than the scene's (here the scene's own, one byte changed) is refused.
  const fs::path other = dir.path / "other.json";
  fs::copy_file(house, other);
  {
    std::ofstream append(other, std::ios::app);
    append << "\n";
  }
  solver::GlbMetricsOptions mismatched = with_scene;
  mismatched.layout = other;
  auto wrong = solver::MeasureFurnishedGlb(dir.path / "furnished.glb", mismatched);
  REQUIRE_FALSE(wrong.ok());
  CHECK(wrong.error().find("other.json: not the layout ") != std::string::npos);
  CHECK(wrong.error().find("differs from the scene's") != std::string::npos);
}

TEST_CASE("A .glb read alone: a wall-hung box reaching past its wall's end at an inner corner is in bounds, one through the wall is not",
          "[solver][glb]") {
  // The floor of a .glb runs to the walls' centre lines, so at an inner corner a wall's edge ends half a
  // wall short of the free floor's: make run's range hood was counted out of bounds (OBR 3 % in its kitchen).
  TempDir dir("glbm_corner");
  const fs::path glb = dir.path / "room.glb";
  Box past{"living-room_0/0/hood-0", {2.5, 1.75, 1.2}, 0.0, 2, "wall", "on_wall"};  // x 1.5-3.5 on the edge x 2-4
  const solver::GlbRoomMetrics in = MeasureRoom(glb, {past}, true);
  CHECK(in.metrics.objects == 1);
  CHECK(in.metrics.out_of_bounds == 0);
  Box through{"living-room_0/0/hood-0", {3.0, 1.9, 1.2}, 0.0, 2, "wall", "on_wall"};  // 0.15 m into the wall
  const solver::GlbRoomMetrics out = MeasureRoom(glb, {through}, true);
  CHECK(out.metrics.out_of_bounds == 1);
}
