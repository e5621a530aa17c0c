#include "scene/door_swing.h"

#include <algorithm>
#include <cmath>

#include "layout/geometry.h"
#include "mesh/geometry2d.h"

namespace villa::scene {
namespace {

using namespace villa::geo;

constexpr double kStripDepth = 0.6;  // m beyond the wall face (PRIORS.md door clearance)

// The rectangle from s0 to s1 along the door segment (m from door.a) and from offset q0 to q1 along its
// left normal, CCW.
Ring Band(const Segment& door, double s0, double s1, double q0, double q1) {
  Point u = Unit(Sub(door.b, door.a));
  Point n = Left(u);
  if (q0 > q1) std::swap(q0, q1);
  const Point a = Add(door.a, Scale(u, s0)), b = Add(door.a, Scale(u, s1));
  return CleanRing({Add(a, Scale(n, q0)), Add(b, Scale(n, q0)), Add(b, Scale(n, q1)), Add(a, Scale(n, q1))}, 1e-9);
}
Ring Band(const Segment& door, double q0, double q1) { return Band(door, 0.0, Length(door), q0, q1); }

bool OnExterior(const Segment& s, const std::vector<Segment>& exterior) {
  for (const Segment& e : exterior) {
    Interval overlap;
    if (CollinearOverlapInterval(s, e, kTolerance, &overlap) && overlap.second - overlap.first > 0.5 * Length(s))
      return true;
  }
  return false;
}

}  // namespace

std::vector<DoorSwing> DoorSwings(const Layout& layout, const BuildingMesh& building, const BuildOptions& options,
                                  int level) {
  std::vector<Ring> rings;
  for (int i : layout.RoomsOnLevel(level)) rings.push_back(layout.rooms[i].polygon);
  const std::vector<Segment> exterior = ExteriorBoundaryOf(rings, kTolerance).pieces;

  std::vector<DoorSwing> out;
  auto add = [&](const Element& e, ElementKind kind) {
    DoorSwing swing;
    swing.element = e.name;
    swing.kind = kind;
    swing.door = e.shape;
    const double width = Length(e.shape);
    if (width < 1e-6) return;
    // Depth of the wall face from the element's line on each side: exterior walls stand inward of the
    // footprint edge (the element's line is their outer face), interior walls are centred on it.
    const bool outer = kind == ElementKind::kEntrance || OnExterior(e.shape, exterior);
    const double half = options.interior_wall_thickness / 2.0;

    const Point u = Unit(Sub(e.shape.b, e.shape.a));
    const Point n = Left(u);
    double q_min = 1e300, q_max = -1e300, s_sum = 0.0;
    int count = 0;
    for (const MeshPart& part : building.parts) {
      if (part.kind != PartKind::kDoorLeaf || part.level != level || part.element != e.name) continue;
      for (const Vec3& v : part.mesh.vertices) {
        Point p{v.x, v.y};
        double q = Dot(Sub(p, e.shape.a), n);
        q_min = std::min(q_min, q);
        q_max = std::max(q_max, q);
        s_sum += Dot(Sub(p, e.shape.a), u);
        ++count;
      }
    }
    // An open leaf stands perpendicular to the wall, reaching about one door width beyond it.
    const double reach = std::max(std::abs(q_min), std::abs(q_max));
    const bool open = count > 0 && reach > 0.5 * width && (q_min > 0.0 || q_max < 0.0);
    // A leaf opened 180 degrees (layout/door_swing.h: where no leaf can stand at 90 degrees) lies flat
    // against the wall beside its opening, on one side of it; its sweep is the half disc over the opening
    // and that wall (two squares), kept clear like a quarter disc's square.
    const double s_mean = count > 0 ? s_sum / count : 0.0;
    const bool flat = count > 0 && !open && (q_min > 0.0 || q_max < 0.0) && (s_mean < 0.0 || s_mean > width);
    if (flat) {
      swing.side = q_min > 0.0 ? 1 : -1;
      swing.hinge = s_mean < 0.0 ? 0 : 1;
      // Its half disc: the square over the opening and the one over the wall it folds onto.
      swing.sweep = swing.hinge == 0 ? Band(e.shape, -width, width, 0.0, swing.side * width)
                                     : Band(e.shape, 0.0, 2.0 * width, 0.0, swing.side * width);
      const double face = outer ? 0.0 : half;
      swing.strips.push_back(Band(e.shape, 0.0, -swing.side * (face + kStripDepth)));
    } else if (open) {
      swing.side = q_min > 0.0 ? 1 : -1;
      swing.hinge = s_sum / count < width / 2.0 ? 0 : 1;
      swing.sweep = Band(e.shape, 0.0, swing.side * reach);
      // The other side: outward of an exterior wall is outdoors (kept; no room overlaps it).
      double face = outer ? 0.0 : half;
      swing.strips.push_back(Band(e.shape, 0.0, -swing.side * (face + kStripDepth)));
    } else {
      double inner_face = outer ? options.exterior_wall_thickness : half;
      // Which side is inside for an exterior door: the footprint lies to the left of its CCW edges; the
      // element may run either way, so give both sides and let the room filter keep the inner one.
      swing.strips.push_back(Band(e.shape, 0.0, inner_face + kStripDepth));
      swing.strips.push_back(Band(e.shape, 0.0, -(outer ? inner_face : half) - kStripDepth));
    }
    out.push_back(std::move(swing));
  };
  if (level == 0)
    for (const Element& e : layout.entrances) add(e, ElementKind::kEntrance);
  for (const Element& e : layout.doors)
    if (e.OnLevel(level)) add(e, ElementKind::kDoor);
  return out;
}

}  // namespace villa::scene
