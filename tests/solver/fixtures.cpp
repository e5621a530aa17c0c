#include "fixtures.h"

#include <cmath>
#include <numbers>
#include <map>

#include "mesh/geometry2d.h"
#include "solver/rng.h"

namespace villa::solver::fixtures {
namespace {

void AddBox(TriangleMesh& mesh, Vec3 a, Vec3 b) { mesh.Append(BoxMesh(a, b)); }

std::shared_ptr<AssetMesh> Wrap(TriangleMesh mesh) {
  auto asset = std::make_shared<AssetMesh>();
  asset->parts.push_back({MeshMaterial{}, std::move(mesh)});
  return asset;
}

}  // namespace

ProblemObject Make(const std::string& name, AssetRecord record, TriangleMesh mesh) {
  ProblemObject o;
  o.id = "r/" + name;
  o.category = record.category;
  o.asset = std::move(record);
  o.mesh = Wrap(std::move(mesh));
  return o;
}

namespace {

// A wall slab outside the free floor along a -> b (room on the left), clear height tall, reaching round
// the convex corners at its ends (so the slabs close the room) but not past an inner corner.
TriangleMesh WallSlab(Point a, Point b, bool extend_a, bool extend_b, double z0, double height, double thickness) {
  const Point d = geo::Unit(geo::Sub(b, a));
  const Point out = {d.y, -d.x};
  const Point a2 = geo::Sub(a, geo::Scale(d, extend_a ? thickness : 0.0));
  const Point b2 = geo::Add(b, geo::Scale(d, extend_b ? thickness : 0.0));
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
  const Ring& f = room.free_floor;
  const size_t n = f.size();
  auto convex = [&](size_t i) {
    return geo::Cross(geo::Sub(f[i], f[(i + n - 1) % n]), geo::Sub(f[(i + 1) % n], f[i])) > 0.0;
  };
  for (size_t i = 0; i < n; ++i) {
    room.building.push_back({"wall " + std::to_string(i), WallSlab(f[i], f[(i + 1) % n], convex(i), convex((i + 1) % n),
                                                                   room.floor_z, room.clear_height, 0.12)});
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

// "coffee-table-0" -> "coffee-table".
std::string CategoryOf(const std::string& name) { return name.substr(0, name.rfind('-')); }

ProblemObject BoxObject(const std::string& name, double w, double d, double h, bool top) {
  return Make(name, BoxRecord(CategoryOf(name), w, d, h, top), BoxMesh({-w / 2, -d / 2, 0}, {w / 2, d / 2, h}));
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
  return Make(name, BoxRecord(CategoryOf(name), w, d, h, true, 1.0), std::move(m));
}

ProblemObject BookcaseObject(const std::string& name, double w, double d, double h, int rows) {
  constexpr double t = 0.02;
  TriangleMesh m;
  AddBox(m, {-w / 2, -d / 2, 0}, {-w / 2 + t, d / 2, h});     // left side
  AddBox(m, {w / 2 - t, -d / 2, 0}, {w / 2, d / 2, h});       // right side
  AddBox(m, {-w / 2 + t, d / 2 - t, 0}, {w / 2 - t, d / 2, h});  // back
  AssetRecord r = BoxRecord(CategoryOf(name), w, d, h);
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

RoomProblem WithFloor(Ring free_floor) { return RoomOf(std::move(free_floor)); }
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
  room.objects.back().scale_min = 0.8;
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

namespace {

const char* const kTypeNames[] = {"living-room", "bedroom", "kitchen", "bathroom", "dining-room",
                                  "children-room", "office", "meeting-room", "balcony", "utility-room"};

// The free floor of a W x D room of the given shape, with about the rectangle's area.
Ring ShapeFloor(RoomShape shape, double w, double d) {
  if (shape == RoomShape::kL) {
    const double k = 1.0 / std::sqrt(1.0 - 0.16);  // the cut corner takes 16 % of the rectangle
    w *= k;
    d *= k;
    return {{0, 0}, {w, 0}, {w, 0.6 * d}, {0.6 * w, 0.6 * d}, {0.6 * w, d}, {0, d}};
  }
  if (shape == RoomShape::kAngled) {
    const double c = 0.35 * std::min(w, d);
    return {{0, 0}, {w, 0}, {w, d - c}, {w - c, d}, {0, d}};
  }
  return {{0, 0}, {w, 0}, {w, d}, {0, d}};
}

// Builds a room's objects with ids "r/<category>-<k>" and its door and window.
class Builder {
 public:
  enum Kind { kBox, kTop, kTable, kShelf };
  Builder(RoomProblem& room, uint64_t seed) : room_(room), rng_(seed) {}

  // +-8 % of a nominal size.
  double Jit(double v) { return v * (0.92 + 0.16 * rng_.Unit()); }
  bool Chance(double p) { return rng_.Unit() < p; }

  std::string Object(const std::string& category, double w, double d, double h, Kind kind, int rows = 0) {
    const std::string name = category + "-" + std::to_string(counts_[category]++);
    ProblemObject o;
    switch (kind) {
      case kBox: o = BoxObject(name, w, d, h); break;
      case kTop: o = BoxObject(name, w, d, h, true); break;
      case kTable: o = TableObject(name, w, d, h); break;
      case kShelf: o = BookcaseObject(name, w, d, h, rows); break;
    }
    o.asset.interaction_zone.reset();
    room_.objects.push_back(std::move(o));
    return room_.objects.back().id;
  }
  ProblemObject& Last() { return room_.objects.back(); }
  ProblemObject& Get(const std::string& id) { return room_.objects[room_.Find(id)]; }

  std::string Anchor(const std::string& category, double w, double d, double h, Kind kind = kTop, int rows = 0,
                     double zone = 0.0) {
    const std::string id = Object(category, Jit(w), d, h, kind, rows);
    Last().relation = Relation::kAgainstWall;
    if (zone > 0) Last().zone = InteractionZone{"front", zone, {}};
    return id;
  }
  std::string Free(const std::string& category, double w, double d, double h, Kind kind = kBox, double zone = 0.0) {
    const std::string id = Object(category, Jit(w), Jit(d), h, kind);
    if (zone > 0) Last().zone = InteractionZone{"front", zone, {}};
    return id;
  }
  std::string Hung(const std::string& category, double w, double d, double h, Kind kind = kBox, int rows = 0) {
    const std::string id = Object(category, w, d, h, kind, rows);
    Last().parent = "wall";
    Last().relation = Relation::kOnWall;
    Last().priority = Priority::kDecorative;
    return id;
  }
  std::string Ceiling(const std::string& category, double w, double d, double h) {
    const std::string id = Object(category, w, d, h, kBox);
    Last().parent = "ceiling";
    Last().relation = Relation::kHanging;
    return id;
  }
  std::string Small(const std::string& category, double w, double d, double h, const std::string& parent,
                    Relation relation = Relation::kOnTop, int surface = -1) {
    const std::string id = Object(category, Jit(w), Jit(d), Jit(h), kBox);
    Last().parent = parent;
    Last().relation = relation;
    Last().surface = relation == Relation::kOnTop ? surface : -1;
    Last().priority = Priority::kDecorative;
    Last().scale_min = 0.8;
    return id;
  }
  // `n` books of 3-6 cm inside a shelf's cavities.
  void Books(const std::string& shelf, int n, const std::string& category = "books") {
    for (int k = 0; k < n; ++k) Small(category, 0.03 + 0.03 * rng_.Unit(), 0.2, 0.22, shelf, Relation::kInside);
  }
  void Edge(const std::string& a, SemanticRelation relation, const std::string& b) { room_.edges.push_back(DefaultEdge(a, relation, b)); }
  void Exempt(const std::string& owner, const std::string& other) {
    ProblemObject& o = Get(owner);
    if (o.zone) o.zone->exempt.push_back(other);
  }
  // Chairs around a table: facing it (the side they sit at: within 75 degrees of its centre, as the priors'
  // seats), next to it, in its zone's exemption list when it has one.
  void ChairsAround(const std::string& table, int n, const std::string& category, double w, double d, double h) {
    for (int k = 0; k < n; ++k) {
      const std::string chair = Free(category, w, d, h);
      Edge(chair, SemanticRelation::kFaceTo, table);
      room_.edges.back().max_angle = 75.0 * std::numbers::pi / 180.0;
      Edge(chair, SemanticRelation::kNextTo, table);
    }
  }

 private:
  RoomProblem& room_;
  Rng rng_;
  std::map<std::string, int> counts_;
};

void Compose(RoomType type, Builder& b) {
  using R = SemanticRelation;
  switch (type) {
    case RoomType::kLiving: {
      const std::string sofa = b.Anchor("sofa", 2.1, 0.9, 0.85, Builder::kTop, 0, 0.45);
      b.Get(sofa).priority = Priority::kNamed;
      const std::string table = b.Free("coffee-table", 1.1, 0.6, 0.42, Builder::kTable);
      b.Exempt(sofa, table);
      b.Edge(table, R::kFrontOf, sofa);
      b.Edge(table, R::kNextTo, sofa);
      b.Edge(table, R::kCentered, sofa);
      const std::string stand = b.Anchor("tv-stand", 1.6, 0.42, 0.5);
      b.Small("tv", 1.2, 0.08, 0.7, stand);
      b.Edge(sofa, R::kFaceTo, stand);
      for (int k = 0; k < 2; ++k) {
        const std::string arm = b.Free("armchair", 0.85, 0.85, 0.9, Builder::kBox, 0.45);
        b.Edge(arm, R::kFaceTo, table);
        b.Edge(arm, R::kNear, table);
      }
      for (int k = 0; k < 2; ++k) {
        const std::string side = b.Free("side-table", 0.5, 0.5, 0.55, Builder::kTable);
        b.Edge(side, R::kNextTo, sofa);
        b.Small("table-lamp", 0.25, 0.25, 0.45, side);
      }
      for (int k = 0; k < 2; ++k) {
        const std::string shelf = b.Anchor("bookcase", 0.9, 0.32, 1.9, Builder::kShelf, 5, 0.5);
        b.Books(shelf, 6);
        b.Small("vase", 0.15, 0.15, 0.3, shelf, Relation::kOnTop, 5);
      }
      b.Free("plant", 0.5, 0.5, 1.3);
      const std::string lamp = b.Free("floor-lamp", 0.4, 0.4, 1.6);
      b.Edge(lamp, R::kNextTo, sofa);
      const std::string rug = b.Free("rug", 2.2, 1.6, 0.01);
      b.Edge(rug, R::kCentered, table);
      const std::string painting = b.Hung("painting", 1.0, 0.04, 0.7);
      b.Edge(painting, R::kCentered, sofa);
      b.Hung("painting", 0.6, 0.04, 0.5);
      b.Ceiling("ceiling-lamp", 0.5, 0.5, 0.35);
      b.Small("remote", 0.05, 0.18, 0.03, table);
      b.Small("bowl", 0.25, 0.25, 0.1, table);
      b.Small("magazine", 0.22, 0.3, 0.01, table);
      break;
    }
    case RoomType::kBedroom: {
      const std::string bed = b.Anchor("bed", 1.6, 2.05, 0.55, Builder::kTop);
      b.Get(bed).priority = Priority::kNamed;
      b.Get(bed).zone = InteractionZone{"sides", 0.6, {}};
      b.Small("pillow", 0.5, 0.35, 0.15, bed);
      b.Small("pillow", 0.5, 0.35, 0.15, bed);
      for (R side : {R::kLeftOf, R::kRightOf}) {
        const std::string ns = b.Anchor("nightstand", 0.5, 0.4, 0.55);
        b.Edge(ns, R::kNextTo, bed);
        b.Edge(ns, side, bed);
        b.Exempt(bed, ns);
        b.Small("table-lamp", 0.22, 0.22, 0.4, ns);
        if (side == R::kLeftOf) b.Small("alarm-clock", 0.12, 0.08, 0.1, ns);
      }
      const std::string wardrobe = b.Anchor("wardrobe", 1.6, 0.6, 2.1, Builder::kShelf, 4, 0.8);
      for (int k = 0; k < 4; ++k) b.Small("folded-clothes", 0.35, 0.3, 0.15, wardrobe, Relation::kInside);
      const std::string dresser = b.Anchor("dresser", 1.0, 0.5, 0.85, Builder::kTop, 0, 0.5);
      b.Small("jewelry-box", 0.2, 0.15, 0.1, dresser);
      b.Small("vase", 0.15, 0.15, 0.3, dresser);
      const std::string desk = b.Anchor("desk", 1.2, 0.6, 0.75, Builder::kTable, 0, 0.6);
      const std::string chair = b.Free("chair", 0.45, 0.5, 0.9);
      b.Edge(chair, R::kFrontOf, desk);
      b.Edge(chair, R::kNextTo, desk);
      b.Exempt(desk, chair);
      b.Small("laptop", 0.34, 0.24, 0.03, desk);
      b.Free("rug", 1.8, 1.2, 0.01);
      const std::string painting = b.Hung("painting", 0.9, 0.04, 0.6);
      b.Edge(painting, R::kCentered, bed);
      b.Hung("mirror", 0.5, 0.03, 0.9);
      b.Ceiling("ceiling-lamp", 0.5, 0.5, 0.3);
      b.Free("slippers", 0.3, 0.25, 0.08);
      break;
    }
    case RoomType::kKitchen: {
      for (int k = 0; k < 3; ++k) {
        const std::string counter = b.Anchor("counter", 1.2, 0.6, 0.9, Builder::kTop, 0, 1.0);
        if (k == 0) {
          b.Small("microwave", 0.5, 0.38, 0.3, counter);
          b.Small("kettle", 0.2, 0.15, 0.25, counter);
        } else if (k == 1) {
          b.Small("coffee-machine", 0.25, 0.35, 0.4, counter);
          b.Small("toaster", 0.28, 0.18, 0.2, counter);
          b.Small("knife-stand", 0.12, 0.12, 0.25, counter);
        } else {
          b.Small("bottle", 0.08, 0.08, 0.3, counter);
          b.Small("bottle", 0.08, 0.08, 0.3, counter);
        }
      }
      b.Anchor("fridge", 0.7, 0.7, 1.85, Builder::kBox, 0, 1.0);
      const std::string oven = b.Anchor("oven", 0.6, 0.6, 0.9, Builder::kTop, 0, 1.0);
      b.Small("pan", 0.3, 0.3, 0.1, oven);
      for (int k = 0; k < 2; ++k) {
        const std::string upper = b.Hung("upper-cabinet", 0.8, 0.35, 0.7, Builder::kShelf, 2);
        for (int p = 0; p < 3; ++p) b.Small("plate", 0.22, 0.22, 0.05, upper, Relation::kInside);
      }
      const std::string table = b.Free("dining-table", 1.2, 0.8, 0.75, Builder::kTable);
      b.ChairsAround(table, 4, "chair", 0.45, 0.5, 0.9);
      b.Small("fruit-bowl", 0.28, 0.28, 0.12, table);
      break;
    }
    case RoomType::kBathroom: {
      b.Anchor("toilet", 0.4, 0.7, 0.8, Builder::kBox, 0, 0.6);
      b.Get(b.Anchor("shower", 0.9, 0.9, 2.0, Builder::kBox)).priority = Priority::kNamed;
      const std::string vanity = b.Anchor("vanity", 0.8, 0.5, 0.85, Builder::kTop, 0, 0.7);
      b.Small("soap", 0.08, 0.06, 0.1, vanity);
      b.Small("cosmetics", 0.06, 0.06, 0.15, vanity);
      b.Small("cosmetics", 0.06, 0.06, 0.15, vanity);
      const std::string mirror = b.Hung("mirror", 0.7, 0.03, 0.8);
      b.Edge(mirror, R::kCentered, vanity);
      b.Hung("towel-rack", 0.6, 0.1, 0.1);
      const std::string cabinet = b.Anchor("cabinet", 0.4, 0.3, 1.6, Builder::kShelf, 4, 0.5);
      b.Small("towel", 0.3, 0.25, 0.12, cabinet, Relation::kInside);
      b.Small("towel", 0.3, 0.25, 0.12, cabinet, Relation::kInside);
      b.Free("bin", 0.25, 0.25, 0.3);
      b.Free("laundry-basket", 0.4, 0.35, 0.5);
      b.Ceiling("ceiling-lamp", 0.3, 0.3, 0.15);
      break;
    }
    case RoomType::kDining: {
      const std::string table = b.Free("dining-table", 1.8, 0.95, 0.75, Builder::kTable);
      b.Get(table).priority = Priority::kNamed;
      b.ChairsAround(table, 6, "chair", 0.45, 0.5, 0.9);
      for (int k = 0; k < 6; ++k) b.Small("plate", 0.26, 0.26, 0.03, table);
      b.Small("fruit-bowl", 0.3, 0.3, 0.12, table);
      b.Small("vase", 0.15, 0.15, 0.35, table);
      const std::string sideboard = b.Anchor("sideboard", 1.6, 0.45, 0.85, Builder::kShelf, 2, 0.8);
      for (int k = 0; k < 3; ++k) b.Small("dish", 0.25, 0.25, 0.08, sideboard, Relation::kInside);
      b.Small("table-lamp", 0.25, 0.25, 0.45, sideboard, Relation::kOnTop, 2);
      const std::string cabinet = b.Anchor("glass-cabinet", 1.0, 0.4, 1.9, Builder::kShelf, 4, 0.8);
      for (int k = 0; k < 4; ++k) b.Small("plate", 0.24, 0.24, 0.03, cabinet, Relation::kInside);
      const std::string pendant = b.Ceiling("pendant-lamp", 0.6, 0.6, 0.5);
      b.Edge(pendant, R::kCentered, table);
      b.Free("plant", 0.5, 0.5, 1.2);
      b.Hung("painting", 0.9, 0.04, 0.6);
      b.Hung("painting", 0.9, 0.04, 0.6);
      const std::string rug = b.Free("rug", 2.6, 2.0, 0.01);
      b.Edge(rug, R::kCentered, table);
      break;
    }
    case RoomType::kChildren: {
      const std::string bed = b.Anchor("child-bed", 0.9, 1.9, 0.5, Builder::kTop);
      b.Get(bed).priority = Priority::kNamed;
      b.Small("teddy", 0.25, 0.2, 0.3, bed);
      b.Small("pillow", 0.45, 0.3, 0.12, bed);
      const std::string ns = b.Anchor("nightstand", 0.45, 0.4, 0.5);
      b.Edge(ns, R::kNextTo, bed);
      b.Small("table-lamp", 0.2, 0.2, 0.35, ns);
      const std::string desk = b.Anchor("desk", 1.0, 0.55, 0.72, Builder::kTable, 0, 0.6);
      const std::string chair = b.Free("child-chair", 0.4, 0.4, 0.6);
      b.Edge(chair, R::kFrontOf, desk);
      b.Exempt(desk, chair);
      b.Small("books", 0.2, 0.28, 0.05, desk);
      const std::string shelf = b.Anchor("bookcase", 0.8, 0.3, 1.5, Builder::kShelf, 4, 0.5);
      b.Books(shelf, 4);
      for (int k = 0; k < 2; ++k) b.Small("toy", 0.15, 0.15, 0.15, shelf, Relation::kInside);
      const std::string wardrobe = b.Anchor("wardrobe", 1.0, 0.55, 1.8, Builder::kShelf, 3, 0.8);
      b.Small("folded-clothes", 0.3, 0.28, 0.15, wardrobe, Relation::kInside);
      b.Small("folded-clothes", 0.3, 0.28, 0.15, wardrobe, Relation::kInside);
      const std::string chest = b.Anchor("toy-chest", 0.8, 0.45, 0.5);
      b.Small("toy", 0.2, 0.2, 0.2, chest);
      b.Free("rug", 1.6, 1.2, 0.01);
      const std::string play = b.Free("play-table", 0.7, 0.6, 0.5, Builder::kTable);
      b.ChairsAround(play, 2, "child-chair", 0.35, 0.35, 0.55);
      b.Hung("painting", 0.6, 0.03, 0.5);
      b.Ceiling("ceiling-lamp", 0.4, 0.4, 0.25);
      break;
    }
    case RoomType::kOffice: {
      const std::string desk = b.Anchor("desk", 1.4, 0.7, 0.75, Builder::kTable, 0, 0.6);
      b.Get(desk).priority = Priority::kNamed;
      const std::string chair = b.Free("office-chair", 0.6, 0.6, 1.0);
      b.Edge(chair, R::kFrontOf, desk);
      b.Edge(chair, R::kNextTo, desk);
      b.Exempt(desk, chair);
      b.Small("monitor", 0.55, 0.2, 0.45, desk);
      b.Small("desk-lamp", 0.15, 0.15, 0.4, desk);
      b.Small("phone", 0.15, 0.2, 0.08, desk);
      b.Small("pen-holder", 0.08, 0.08, 0.1, desk);
      for (int k = 0; k < 2; ++k) {
        const std::string shelf = b.Anchor("bookcase", 0.8, 0.35, 1.9, Builder::kShelf, 5, 0.5);
        b.Books(shelf, 5);
      }
      const std::string files = b.Anchor("filing-cabinet", 0.45, 0.6, 1.0, Builder::kTop, 0, 0.7);
      b.Small("printer", 0.42, 0.4, 0.25, files);
      for (int k = 0; k < 2; ++k) {
        const std::string visitor = b.Free("chair", 0.5, 0.5, 0.85);
        b.Edge(visitor, R::kFaceTo, desk);
        b.Edge(visitor, R::kNear, desk);
      }
      b.Free("plant", 0.45, 0.45, 1.1);
      b.Free("floor-lamp", 0.35, 0.35, 1.6);
      b.Hung("whiteboard", 1.2, 0.03, 0.9);
      break;
    }
    case RoomType::kMeeting: {
      const std::string table = b.Free("conference-table", 2.8, 1.2, 0.75, Builder::kTable);
      b.Get(table).priority = Priority::kNamed;
      b.ChairsAround(table, 8, "chair", 0.5, 0.5, 0.9);
      for (int k = 0; k < 3; ++k) b.Small("laptop", 0.34, 0.24, 0.03, table);
      for (int k = 0; k < 4; ++k) b.Small("cup", 0.09, 0.09, 0.1, table);
      b.Hung("whiteboard", 1.8, 0.03, 1.0);
      const std::string credenza = b.Anchor("sideboard", 1.6, 0.45, 0.8, Builder::kTop, 0, 0.8);
      b.Small("water-jug", 0.15, 0.15, 0.3, credenza);
      b.Free("plant", 0.5, 0.5, 1.3);
      b.Free("plant", 0.5, 0.5, 1.3);
      break;
    }
    case RoomType::kBalcony: {
      const std::string table = b.Free("outdoor-table", 0.8, 0.8, 0.72, Builder::kTable);
      b.ChairsAround(table, 2, "outdoor-chair", 0.5, 0.55, 0.85);
      b.Small("teapot", 0.2, 0.15, 0.2, table);
      b.Small("cup", 0.09, 0.09, 0.1, table);
      b.Small("cup", 0.09, 0.09, 0.1, table);
      for (int k = 0; k < 3; ++k) b.Free("plant", 0.4, 0.4, 0.9);
      b.Anchor("flower-box", 1.0, 0.3, 0.3);
      break;
    }
    case RoomType::kUtility: {
      const std::string washer = b.Anchor("washing-machine", 0.6, 0.6, 0.85, Builder::kTop, 0, 1.0);
      b.Small("detergent", 0.2, 0.12, 0.3, washer);
      const std::string dryer = b.Anchor("dryer", 0.6, 0.6, 0.85, Builder::kTop, 0, 1.0);
      b.Edge(dryer, R::kNextTo, washer);
      for (int k = 0; k < 2; ++k) {
        const std::string shelf = b.Anchor("shelves", 0.9, 0.4, 1.8, Builder::kShelf, 4, 0.5);
        b.Small("box", 0.3, 0.3, 0.25, shelf, Relation::kInside);
        b.Small("box", 0.3, 0.3, 0.25, shelf, Relation::kInside);
      }
      b.Free("laundry-basket", 0.45, 0.35, 0.5);
      b.Hung("water-heater", 0.5, 0.45, 0.8);
      b.Free("broom", 0.3, 0.1, 1.3);
      break;
    }
  }
}

}  // namespace

const char* RoomTypeName(RoomType type) { return kTypeNames[static_cast<int>(type)]; }
const char* RoomShapeName(RoomShape shape) {
  return shape == RoomShape::kRectangle ? "rectangle" : shape == RoomShape::kL ? "L" : "angled";
}

RoomProblem SyntheticRoom(RoomType type, RoomShape shape, uint64_t seed, double scale) {
  static const double kSizes[][2] = {{5.6, 4.6}, {4.6, 4.0}, {4.4, 3.6}, {2.8, 2.4}, {5.0, 4.2},
                                     {4.2, 3.8}, {4.0, 3.4}, {6.0, 4.6}, {4.0, 1.8}, {4.0, 4.0}};
  const double k = std::sqrt(scale);
  RoomProblem room = RoomOf(ShapeFloor(shape, kSizes[static_cast<int>(type)][0] * k, kSizes[static_cast<int>(type)][1] * k));
  room.room = std::string(RoomTypeName(type)) + "_0/0";
  const double z = room.floor_z;
  // The door: in the bottom wall near its start, swinging in (PRIORS.md: a w x w square on the leaf side).
  room.walls[0].openings.push_back({0.3, 1.2, z, z + 2.1});
  room.keep_outs.push_back({{{0.3, 0.0}, {1.2, 0.0}, {1.2, 0.9}, {0.3, 0.9}}, z, z + 2.1, KeepOutKind::kDoorSweep, "door"});
  // A window in the middle of the longest other wall: sill 0.9, the 0.5 m zone in front of it.
  size_t longest = 1;
  for (size_t i = 1; i < room.walls.size(); ++i) {
    if (geo::Dist(room.walls[i].a, room.walls[i].b) > geo::Dist(room.walls[longest].a, room.walls[longest].b)) longest = i;
  }
  WallEdge& wall = room.walls[longest];
  const double len = geo::Dist(wall.a, wall.b), ww = std::min(1.5, 0.5 * len);
  const double t0 = 0.5 * (len - ww), t1 = t0 + ww;
  wall.openings.push_back({t0, t1, z + 0.9, z + 2.1});
  const Point dir = geo::Unit(geo::Sub(wall.b, wall.a)), in = geo::Left(dir);
  const Point p0 = geo::Add(wall.a, geo::Scale(dir, t0)), p1 = geo::Add(wall.a, geo::Scale(dir, t1));
  room.keep_outs.push_back({{p0, p1, geo::Add(p1, geo::Scale(in, 0.5)), geo::Add(p0, geo::Scale(in, 0.5))}, z + 0.9, z + 2.1,
                            KeepOutKind::kWindowZone, "window"});
  if (type == RoomType::kUtility) {
    // The staircase and its landing along the right wall (x = the floor's largest x).
    double x1 = 0.0, y1 = 0.0;
    for (Point p : room.free_floor) {
      x1 = std::max(x1, p.x);
      y1 = std::max(y1, p.y);
    }
    room.keep_outs.push_back({{{x1 - 1.1, 0.2}, {x1, 0.2}, {x1, y1 - 0.2}, {x1 - 1.1, y1 - 0.2}}, z, z + room.clear_height,
                              KeepOutKind::kStaircase, "staircase"});
  }
  Builder b(room, seed);
  const int repeats = std::max(1, static_cast<int>(std::lround(scale)));
  for (int r = 0; r < repeats; ++r) Compose(type, b);
  return room;
}

}  // namespace villa::solver::fixtures
