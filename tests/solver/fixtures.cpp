#include "fixtures.h"

#include <cmath>

#include "mesh/geometry2d.h"

namespace villa::solver::fixtures {
namespace {

void AddBox(TriangleMesh& mesh, Vec3 a, Vec3 b) { mesh.Append(BoxMesh(a, b)); }

std::shared_ptr<AssetMesh> Wrap(TriangleMesh mesh) {
  auto asset = std::make_shared<AssetMesh>();
  asset->parts.push_back({MeshMaterial{}, std::move(mesh)});
  return asset;
}

ProblemObject Make(const std::string& name, AssetRecord record, TriangleMesh mesh) {
  ProblemObject o;
  o.id = "r/" + name;
  o.category = record.category;
  o.asset = std::move(record);
  o.mesh = Wrap(std::move(mesh));
  return o;
}

// A wall slab outside the free floor along a -> b (room on the left), clear height tall.
TriangleMesh WallSlab(Point a, Point b, double z0, double height, double thickness) {
  const Point d = geo::Unit(geo::Sub(b, a));
  const Point out = {d.y, -d.x};
  const Point a2 = geo::Sub(a, geo::Scale(d, thickness)), b2 = geo::Add(b, geo::Scale(d, thickness));
  const Point q[4] = {a2, b2, geo::Add(b2, geo::Scale(out, thickness)), geo::Add(a2, geo::Scale(out, thickness))};
  TriangleMesh m;
  // Bottom ring q (clockwise seen from above when the room is on the left of a -> b), top ring above.
  for (int k = 0; k < 4; ++k) m.vertices.push_back({q[k].x, q[k].y, z0});
  for (int k = 0; k < 4; ++k) m.vertices.push_back({q[k].x, q[k].y, z0 + height});
  const int faces[12][3] = {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6}, {0, 4, 5}, {0, 5, 1},
                            {1, 5, 6}, {1, 6, 2}, {2, 6, 7}, {2, 7, 3}, {3, 7, 4}, {3, 4, 0}};
  for (const auto& f : faces) m.AddTriangle(f[0], f[1], f[2]);
  return m;
}

RoomProblem RoomOf(Ring floor) {
  RoomProblem room;
  room.room = "r";
  room.free_floor = std::move(floor);
  room.walls = WallsAlongFloor(room.free_floor);
  for (size_t i = 0; i < room.free_floor.size(); ++i) {
    room.building.push_back({"wall " + std::to_string(i),
                             WallSlab(room.free_floor[i], room.free_floor[(i + 1) % room.free_floor.size()], room.floor_z,
                                      room.clear_height, 0.12)});
  }
  return room;
}

}  // namespace

TriangleMesh BoxMesh(Vec3 a, Vec3 b) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) m.vertices.push_back({k & 1 ? b.x : a.x, k & 2 ? b.y : a.y, k & 4 ? b.z : a.z});
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& f : faces) m.AddTriangle(f[0], f[1], f[2]);
  return m;
}

AssetRecord BoxRecord(const std::string& category, double w, double d, double h, bool top, double top_clear) {
  AssetRecord r;
  r.id = "test:" + category;
  r.name = category;
  r.category = category;
  r.size = {w, d, h};
  r.affordances = kConsumer;
  if (top) {
    r.affordances |= kProvider;
    r.support_surfaces.push_back({h, {{-w / 2, -d / 2}, {w / 2, -d / 2}, {w / 2, d / 2}, {-w / 2, d / 2}}, top_clear, "procedural"});
  }
  return r;
}

ProblemObject BoxObject(const std::string& name, double w, double d, double h, bool top) {
  return Make(name, BoxRecord(name.substr(0, name.find('-')), w, d, h, top), BoxMesh({-w / 2, -d / 2, 0}, {w / 2, d / 2, h}));
}

ProblemObject TableObject(const std::string& name, double w, double d, double h) {
  TriangleMesh m;
  AddBox(m, {-w / 2, -d / 2, h - 0.04}, {w / 2, d / 2, h});
  for (int sx : {-1, 1}) {
    for (int sy : {-1, 1}) {
      const double x = sx * (w / 2 - 0.05), y = sy * (d / 2 - 0.05);
      AddBox(m, {x - 0.025, y - 0.025, 0}, {x + 0.025, y + 0.025, h - 0.04});
    }
  }
  return Make(name, BoxRecord(name.substr(0, name.find('-')), w, d, h, true, 1.0), std::move(m));
}

ProblemObject BookcaseObject(const std::string& name, double w, double d, double h, int rows) {
  constexpr double t = 0.02;
  TriangleMesh m;
  AddBox(m, {-w / 2, -d / 2, 0}, {-w / 2 + t, d / 2, h});     // left side
  AddBox(m, {w / 2 - t, -d / 2, 0}, {w / 2, d / 2, h});       // right side
  AddBox(m, {-w / 2 + t, d / 2 - t, 0}, {w / 2 - t, d / 2, h});  // back
  AssetRecord r = BoxRecord("bookcase", w, d, h);
  r.affordances |= kProvider | kInteractor;
  const double pitch = (h - t) / rows;
  for (int k = 0; k <= rows; ++k) {
    const double z = k * pitch;
    AddBox(m, {-w / 2 + t, -d / 2, z}, {w / 2 - t, d / 2 - t, z + t});  // board k
  }
  for (int k = 0; k < rows; ++k) {
    const double z = k * pitch + t;
    r.support_surfaces.push_back(
        {z, {{-w / 2 + t, -d / 2}, {w / 2 - t, -d / 2}, {w / 2 - t, d / 2 - t}, {-w / 2 + t, d / 2 - t}}, pitch - t, "procedural"});
    Cavity c;
    c.min = {-w / 2 + t, -d / 2, z};
    c.max = {w / 2 - t, d / 2 - t, (k + 1) * pitch};
    c.floor_surface = k;
    r.cavities.push_back(c);
  }
  r.support_surfaces.push_back({h, {{-w / 2, -d / 2}, {w / 2, -d / 2}, {w / 2, d / 2}, {-w / 2, d / 2}}, 0.5, "procedural"});
  r.interaction_zone = InteractionZoneSpec{"front", 0.5};
  return Make(name, std::move(r), std::move(m));
}

ProblemObject SmallObject(const std::string& name, double w, double d, double h, const std::string& parent,
                          Relation relation) {
  ProblemObject o = BoxObject(name, w, d, h);
  o.parent = "r/" + parent;
  o.relation = relation;
  o.priority = Priority::kDecorative;
  return o;
}

RoomProblem Rectangle(double w, double d) { return RoomOf({{0, 0}, {w, 0}, {w, d}, {0, d}}); }
RoomProblem LShape() { return RoomOf({{0, 0}, {6, 0}, {6, 2.5}, {3, 2.5}, {3, 5}, {0, 5}}); }
RoomProblem Angled() { return RoomOf({{0, 0}, {5, 0}, {5, 3}, {3, 5}, {0, 5}}); }

void FurnishLivingRoom(RoomProblem& room) {
  auto add = [&](ProblemObject o) { room.objects.push_back(std::move(o)); };
  auto edge = [&](const std::string& a, SemanticRelation rel, const std::string& b) {
    room.edges.push_back(DefaultEdge("r/" + a, rel, "r/" + b));
  };
  ProblemObject sofa = BoxObject("sofa-0", 2.0, 0.9, 0.85, true);
  sofa.relation = Relation::kAgainstWall;
  sofa.priority = Priority::kNamed;
  sofa.zone = InteractionZone{"front", 0.45, {"r/coffee-table-0"}};
  add(sofa);
  add(TableObject("coffee-table-0", 1.0, 0.55, 0.42));
  ProblemObject stand = BoxObject("tv-stand-0", 1.5, 0.42, 0.5, true);
  stand.relation = Relation::kAgainstWall;
  add(stand);
  ProblemObject bookcase = BookcaseObject("bookcase-0", 0.9, 0.32, 1.8, 5);
  bookcase.relation = Relation::kAgainstWall;
  add(bookcase);
  ProblemObject armchair = BoxObject("armchair-0", 0.8, 0.8, 0.9);
  armchair.zone = InteractionZone{"front", 0.45, {}};
  add(armchair);
  ProblemObject side = TableObject("side-table-0", 0.45, 0.45, 0.55);
  add(side);
  add(BoxObject("plant-0", 0.45, 0.45, 1.2));
  ProblemObject rug = BoxObject("rug-0", 2.0, 1.4, 0.01);
  rug.priority = Priority::kDecorative;
  add(rug);
  ProblemObject painting = BoxObject("painting-0", 0.9, 0.04, 0.6);
  painting.parent = "wall";
  painting.relation = Relation::kOnWall;
  add(painting);
  ProblemObject lamp = BoxObject("ceiling-lamp-0", 0.5, 0.5, 0.3);
  lamp.parent = "ceiling";
  lamp.relation = Relation::kHanging;
  add(lamp);
  ProblemObject tv = SmallObject("tv-0", 1.1, 0.08, 0.65, "tv-stand-0", Relation::kOnTop);
  tv.priority = Priority::kPrior;
  add(tv);
  add(SmallObject("table-lamp-0", 0.25, 0.25, 0.45, "side-table-0", Relation::kOnTop));
  add(SmallObject("vase-0", 0.15, 0.15, 0.3, "bookcase-0", Relation::kOnTop));
  room.objects.back().surface = 5;
  add(SmallObject("remote-0", 0.05, 0.18, 0.03, "coffee-table-0", Relation::kOnTop));
  add(SmallObject("bowl-0", 0.22, 0.22, 0.1, "coffee-table-0", Relation::kOnTop));
  for (int k = 0; k < 8; ++k) add(SmallObject("books-" + std::to_string(k), 0.04 + 0.01 * (k % 3), 0.22, 0.24, "bookcase-0", Relation::kInside));
  edge("coffee-table-0", SemanticRelation::kFrontOf, "sofa-0");
  edge("coffee-table-0", SemanticRelation::kNextTo, "sofa-0");
  edge("coffee-table-0", SemanticRelation::kCentered, "sofa-0");
  edge("sofa-0", SemanticRelation::kFaceTo, "tv-stand-0");
  edge("armchair-0", SemanticRelation::kFaceTo, "coffee-table-0");
  edge("armchair-0", SemanticRelation::kNear, "coffee-table-0");
  edge("side-table-0", SemanticRelation::kNextTo, "sofa-0");
  edge("rug-0", SemanticRelation::kCentered, "coffee-table-0");
  edge("painting-0", SemanticRelation::kCentered, "sofa-0");
}

}  // namespace villa::solver::fixtures
