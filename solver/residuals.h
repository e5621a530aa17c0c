#pragma once
// The continuous solver's cost terms: one small templated functor each (Ceres autodiff), with a Create().
// Internal to villa_solver and its tests (it includes Ceres; public headers never do).
//
// Every object ("body") of a layer has two parameter blocks:
//   p[4] = {x, y, z, yaw}: footprint centre and bottom height in the layer frame (m), yaw (rad); the
//          solver bounds the yaw to a window around the body's 90-degree class, chosen outside Ceres;
//   s[1] = {scale}: uniform scale of the asset (1 = as modelled), held constant unless scaling is allowed.
// The layer frame is the world for the floor and wall layers, and the parent's frame (metric, origin at the
// parent's bottom centre, axes its asset axes) for objects on a surface or in a cavity.
// A BodyShape (solver/body_shape.h) says which box of the body a term sees. Residuals are hinge
// functions: exactly 0 when the condition holds, so a feasible arrangement costs 0 and the solver stops.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/jet.h>

#include "layout/layout.h"
#include "solver/body_shape.h"
#include "solver/problem.h"
#include "layout/geometry.h"

namespace villa::solver {

inline double Scalar(double v) { return v; }
template <typename T, int N>
double Scalar(const ceres::Jet<T, N>& v) {
  return v.a;
}

template <typename T>
T Hinge(const T& v) {
  return v > T(0.0) ? v : T(0.0);
}
template <typename T>
T Min(const T& a, const T& b) {
  return a < b ? a : b;
}
template <typename T>
T Max(const T& a, const T& b) {
  return a > b ? a : b;
}

// A placed box: centre, unit axis u (asset +x; v = asset +y = u turned +90 deg), half extents, z range.
template <typename T>
struct PlacedBox {
  T cx, cy, ux, uy, hx, hy, z0, z1;
  T vx() const { return -uy; }
  T vy() const { return ux; }
};

template <typename T>
PlacedBox<T> PlaceBox(const T* p, const T* s, const BodyShape& shape) {
  using std::cos;
  using std::sin;
  const T yaw = p[3];
  const T c = cos(yaw);
  const T n = sin(yaw);
  const T k = s[0];
  PlacedBox<T> b;
  b.cx = p[0] + (c * shape.cx - n * shape.cy) * k;
  b.cy = p[1] + (n * shape.cx + c * shape.cy) * k;
  b.ux = c;
  b.uy = n;
  b.hx = T(shape.hx) * k;
  b.hy = T(shape.hy) * k;
  b.z0 = p[2] + T(shape.z0) * k;
  b.z1 = p[2] + T(shape.z1) * k;
  return b;
}

// Half the box's extent along the unit direction (nx, ny).
template <typename T>
T ProjectedRadius(const PlacedBox<T>& b, const T& nx, const T& ny) {
  using std::abs;
  return b.hx * abs(nx * b.ux + ny * b.uy) + b.hy * abs(nx * b.vx() + ny * b.vy());
}

// Separating-axis depth of two upright boxes in plan: the smallest overlap over the four face normals
// (> 0: they overlap and must move this far apart; < 0: minus the widest gap along a face normal).
template <typename T>
T HorizontalDepth(const PlacedBox<T>& a, const PlacedBox<T>& b) {
  using std::abs;
  const T dx = b.cx - a.cx;
  const T dy = b.cy - a.cy;
  const T axes[4][2] = {{a.ux, a.uy}, {a.vx(), a.vy()}, {b.ux, b.uy}, {b.vx(), b.vy()}};
  T best = T(1e9);
  for (const auto& n : axes) {
    const T overlap = ProjectedRadius(a, n[0], n[1]) + ProjectedRadius(b, n[0], n[1]) - abs(n[0] * dx + n[1] * dy);
    best = Min(best, overlap);
  }
  return best;
}

// Penetration depth of two bodies' boxes, respecting heights: when neither height can move (floor
// objects), boxes whose z ranges are apart do not interact at all (a painting above a sofa); when one can
// (hung objects), the z overlap is a fifth separating axis, so the solver may lift the painting instead.
template <typename T>
T BoxPenetration(const PlacedBox<T>& a, const PlacedBox<T>& b, bool z_free, double margin, bool* apart) {
  const T z_overlap = Min(a.z1, b.z1) - Max(a.z0, b.z0);
  T depth = HorizontalDepth(a, b);
  *apart = false;
  if (z_free) {
    depth = Min(depth, z_overlap);
  } else if (z_overlap <= T(-margin)) {
    *apart = true;
  }
  return depth;
}

// Whether two shapes of two bodies are surely apart by more than `margin` (their bounding circles,
// around the bodies' reference points): the terms below are exactly zero there, so they skip the work.
template <typename T>
bool FarApart(const T* pa, const T* sa, const BodyShape& a, const T* pb, const T* sb, const BodyShape& b, double margin) {
  const double ax = std::abs(a.cx) + a.hx, ay = std::abs(a.cy) + a.hy, bx = std::abs(b.cx) + b.hx, by = std::abs(b.cy) + b.hy;
  const double ra = std::sqrt(ax * ax + ay * ay) * Scalar(sa[0]);
  const double rb = std::sqrt(bx * bx + by * by) * Scalar(sb[0]);
  const double dx = Scalar(pa[0]) - Scalar(pb[0]), dy = Scalar(pa[1]) - Scalar(pb[1]);
  const double reach = ra + rb + margin;
  return dx * dx + dy * dy > reach * reach;
}

// Two bodies' boxes must not overlap, with `margin` m of clearance (oriented-box proxy of E_col).
struct PenetrationResidual {
  BodyShape a, b;
  bool z_free = false;
  double margin = 0.02;
  double weight = 10.0;

  template <typename T>
  bool operator()(const T* pa, const T* sa, const T* pb, const T* sb, T* r) const {
    if (FarApart(pa, sa, a, pb, sb, b, margin)) {
      r[0] = T(0.0);
      return true;
    }
    bool apart = false;
    const T depth = BoxPenetration(PlaceBox(pa, sa, a), PlaceBox(pb, sb, b), z_free, margin, &apart);
    r[0] = apart ? T(0.0) : T(weight) * Hinge(depth + T(margin));
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& a, const BodyShape& b, bool z_free, double margin, double weight) {
    return new ceres::AutoDiffCostFunction<PenetrationResidual, 1, 4, 1, 4, 1>(
        new PenetrationResidual{a, b, z_free, margin, weight});
  }
};

// A V_int body's interaction zone (shape `zone`, a box beside the owner) must hold no part of another body.
struct InteractionZoneResidual {
  BodyShape zone, other;
  double weight = 2.0;

  template <typename T>
  bool operator()(const T* p_owner, const T* s_owner, const T* p_other, const T* s_other, T* r) const {
    if (FarApart(p_owner, s_owner, zone, p_other, s_other, other, 0.0)) {
      r[0] = T(0.0);
      return true;
    }
    bool apart = false;
    const T depth = BoxPenetration(PlaceBox(p_owner, s_owner, zone), PlaceBox(p_other, s_other, other), false, 0.0, &apart);
    r[0] = apart ? T(0.0) : T(weight) * Hinge(depth);
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& zone, const BodyShape& other, double weight) {
    return new ceres::AutoDiffCostFunction<InteractionZoneResidual, 1, 4, 1, 4, 1>(
        new InteractionZoneResidual{zone, other, weight});
  }
};

// A body must stay out of a convex keep-out prism (door sweep, window zone, staircase) by `margin` m:
// separating-axis depth over the polygon's edge normals and the box's two axes, gated or extended by z
// as in BoxPenetration.
struct KeepOutResidual {
  BodyShape body;
  Ring polygon;  // convex, CCW, layer frame
  double z0 = 0.0, z1 = 0.0;
  bool z_free = false;
  double margin = 0.02;
  double weight = 10.0;
  // The polygon's outward edge normals and its extent along each, computed once by Create.
  std::vector<Point> normals;
  std::vector<std::pair<double, double>> extents;

  template <typename T>
  bool operator()(const T* p, const T* s, T* r) const {
    const PlacedBox<T> b = PlaceBox(p, s, body);
    const T z_overlap = Min(b.z1, T(z1)) - Max(b.z0, T(z0));
    if (!z_free && z_overlap <= T(-margin)) {
      r[0] = T(0.0);
      return true;
    }
    T depth = z_free ? z_overlap : T(1e9);
    for (size_t i = 0; i < normals.size(); ++i) {
      const T nx = T(normals[i].x), ny = T(normals[i].y);
      const T c = nx * b.cx + ny * b.cy, radius = ProjectedRadius(b, nx, ny);
      depth = Min(depth, Min(c + radius - T(extents[i].first), T(extents[i].second) - (c - radius)));
    }
    auto along_box_axis = [&](const T& nx, const T& ny, const T& radius) {
      const T c = nx * b.cx + ny * b.cy;
      T lo = T(1e18), hi = T(-1e18);
      for (const Point& q : polygon) {
        const T d = nx * q.x + ny * q.y;
        lo = Min(lo, d);
        hi = Max(hi, d);
      }
      depth = Min(depth, Min(c + radius - lo, hi - (c - radius)));
    };
    along_box_axis(b.ux, b.uy, b.hx);
    along_box_axis(b.vx(), b.vy(), b.hy);
    r[0] = T(weight) * Hinge(depth + T(margin));
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& body, const Ring& convex, double z0, double z1, bool z_free,
                                     double margin, double weight) {
    auto* f = new KeepOutResidual{body, convex, z0, z1, z_free, margin, weight, {}, {}};
    for (size_t i = 0; i < convex.size(); ++i) {
      const Point& q0 = convex[i];
      const Point& q1 = convex[(i + 1) % convex.size()];
      const double len = std::sqrt((q1.x - q0.x) * (q1.x - q0.x) + (q1.y - q0.y) * (q1.y - q0.y));
      const Point n{(q1.y - q0.y) / len, -(q1.x - q0.x) / len};
      double lo = 1e18, hi = -1e18;
      for (const Point& q : convex) {
        lo = std::min(lo, n.x * q.x + n.y * q.y);
        hi = std::max(hi, n.x * q.x + n.y * q.y);
      }
      f->normals.push_back(n);
      f->extents.push_back({lo, hi});
    }
    return new ceres::AutoDiffCostFunction<KeepOutResidual, 1, 4, 1>(f);
  }
};

// Signed distance from (px, py) to the boundary of a simple polygon, positive inside. The nearest feature
// (edge interior or vertex) is chosen on the values; the distance to it is differentiated.
template <typename T>
T SignedDistanceToRing(const Ring& ring, const T& px, const T& py) {
  using std::sqrt;
  const double x = Scalar(px), y = Scalar(py);
  const bool inside = PointInRing({x, y}, ring, 0);  // layout's point in polygon
  double best = 1e300;
  int best_edge = 0;
  double best_t = 0.0;
  const size_t n = ring.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = ring[j];
    const Point& b = ring[i];
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double l2 = ex * ex + ey * ey;
    const double t = l2 > 0.0 ? std::clamp(((x - a.x) * ex + (y - a.y) * ey) / l2, 0.0, 1.0) : 0.0;
    const double dx = x - (a.x + t * ex), dy = y - (a.y + t * ey);
    const double d = dx * dx + dy * dy;  // squared: only compared
    if (d < best) {
      best = d;
      best_edge = static_cast<int>(j);
      best_t = t;
    }
  }
  const Point& a = ring[best_edge];
  const Point& b = ring[(best_edge + 1) % n];
  if (best_t > 0.0 && best_t < 1.0) {
    const double len = std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    // Left of a CCW edge is inside: the cross product is the signed distance.
    return ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)) / len;
  }
  const Point& v = best_t <= 0.0 ? a : b;
  const T distance = sqrt((px - v.x) * (px - v.x) + (py - v.y) * (py - v.y) + T(1e-12));
  return inside ? distance : -distance;
}

// The four footprint corners of a body's box stay inside a polygon by `margin` m: the room's free floor
// (non-convex, any angle) in the floor layer, the parent's support surface in a surface layer (the support
// term: footprint inside S_parent, in the parent's frame).
struct FootprintInPolygonResidual {
  BodyShape body;
  Ring polygon;
  double margin = 0.01;
  double weight = 10.0;

  template <typename T>
  bool operator()(const T* p, const T* s, T* r) const {
    const PlacedBox<T> b = PlaceBox(p, s, body);
    const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
      const T x = b.cx + signs[k][0] * b.hx * b.ux + signs[k][1] * b.hy * b.vx();
      const T y = b.cy + signs[k][0] * b.hx * b.uy + signs[k][1] * b.hy * b.vy();
      r[k] = T(weight) * Hinge(T(margin) - SignedDistanceToRing(polygon, x, y));
    }
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& body, const Ring& polygon, double margin, double weight) {
    return new ceres::AutoDiffCostFunction<FootprintInPolygonResidual, 4, 4, 1>(
        new FootprintInPolygonResidual{body, polygon, margin, weight});
  }
};

// No reflex vertex of a non-convex floor may lie inside a body's footprint (with corners inside the
// floor, this is what keeps a box from bridging the inner corner of an L room): one residual per vertex,
// the depth of the vertex inside the box.
struct ReflexVertexResidual {
  BodyShape body;
  std::vector<Point> vertices;
  double margin = 0.01;
  double weight = 10.0;

  template <typename T>
  bool operator()(const T* p, const T* s, T* r) const {
    using std::abs;
    const PlacedBox<T> b = PlaceBox(p, s, body);
    for (size_t k = 0; k < vertices.size(); ++k) {
      const T dx = T(vertices[k].x) - b.cx;
      const T dy = T(vertices[k].y) - b.cy;
      const T qx = dx * b.ux + dy * b.uy;
      const T qy = dx * b.vx() + dy * b.vy();
      r[k] = T(weight) * Hinge(Min(b.hx - abs(qx), b.hy - abs(qy)) + T(margin));
    }
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& body, const std::vector<Point>& vertices, double margin,
                                     double weight) {
    auto* cost = new ceres::AutoDiffCostFunction<ReflexVertexResidual, ceres::DYNAMIC, 4, 1>(
        new ReflexVertexResidual{body, vertices, margin, weight}, static_cast<int>(vertices.size()));
    return cost;
  }
};

// A child inside its parent's cavity (parent frame, cavity box already scaled by the parent): footprint
// corners within the box's x/y range and the top below its ceiling, `margin` m inside the walls.
struct ContainmentResidual {
  BodyShape body;
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0, max_z = 0;
  double margin = 0.005;
  double weight = 10.0;

  template <typename T>
  bool operator()(const T* p, const T* s, T* r) const {
    const PlacedBox<T> b = PlaceBox(p, s, body);
    const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
      const T x = b.cx + signs[k][0] * b.hx * b.ux + signs[k][1] * b.hy * b.vx();
      const T y = b.cy + signs[k][0] * b.hx * b.uy + signs[k][1] * b.hy * b.vy();
      r[2 * k] = T(weight) * (Hinge(T(min_x + margin) - x) + Hinge(x - T(max_x - margin)));
      r[2 * k + 1] = T(weight) * (Hinge(T(min_y + margin) - y) + Hinge(y - T(max_y - margin)));
    }
    r[8] = T(weight) * Hinge(b.z1 - T(max_z - margin));
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& body, double min_x, double min_y, double max_x, double max_y,
                                     double max_z, double margin, double weight) {
    return new ceres::AutoDiffCostFunction<ContainmentResidual, 9, 4, 1>(
        new ContainmentResidual{body, min_x, min_y, max_x, max_y, max_z, margin, weight});
  }
};

// face_to: the angle between the source's facing f = (sin yaw, -cos yaw) and the direction to the
// target's centre stays within max_angle (rad); the residual is the excess in rad.
struct FaceToResidual {
  BodyShape source, target;
  double max_angle = 0.5236;
  double weight = 1.0;

  template <typename T>
  bool operator()(const T* ps, const T* ss, const T* pt, const T* st, T* r) const {
    using std::abs;
    using std::atan2;
    using std::cos;
    using std::sin;
    const PlacedBox<T> a = PlaceBox(ps, ss, source);
    const PlacedBox<T> b = PlaceBox(pt, st, target);
    const T yaw = ps[3];
    const T fx = sin(yaw), fy = -cos(yaw);
    const T dx = b.cx - a.cx, dy = b.cy - a.cy;
    const T angle = atan2(fx * dy - fy * dx, fx * dx + fy * dy + T(1e-12));
    r[0] = T(weight) * Hinge(abs(angle) - T(max_angle));
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& source, const BodyShape& target, double max_angle, double weight) {
    return new ceres::AutoDiffCostFunction<FaceToResidual, 1, 4, 1, 4, 1>(
        new FaceToResidual{source, target, max_angle, weight});
  }
};

// front_of / behind / left_of / right_of, in the target's frame (front = -y, left = +x): the source's
// centre lies in the target's band on that side, i.e. on that side of the target's centre line and
// within the target's extent across it (a painting on the wall behind a sofa, a nightstand beside the
// bed's length). The residual is how far short of the centre line plus how far outside the band (m).
// Distance is the gap edges' business; floor objects cannot overlap anyway, hung ones may (the painting).
struct RelativeSideResidual {
  enum Side { kFront, kBehind, kLeft, kRight };
  BodyShape source, target;
  Side side = kFront;
  double weight = 1.0;

  template <typename T>
  bool operator()(const T* ps, const T* ss, const T* pt, const T* st, T* r) const {
    using std::abs;
    const PlacedBox<T> a = PlaceBox(ps, ss, source);
    const PlacedBox<T> b = PlaceBox(pt, st, target);
    const T dx = a.cx - b.cx, dy = a.cy - b.cy;
    const T qx = dx * b.ux + dy * b.uy;
    const T qy = dx * b.vx() + dy * b.vy();
    T short_by, outside;
    switch (side) {
      case kFront: short_by = qy, outside = abs(qx) - b.hx; break;
      case kBehind: short_by = -qy, outside = abs(qx) - b.hx; break;
      case kLeft: short_by = -qx, outside = abs(qy) - b.hy; break;
      default: short_by = qx, outside = abs(qy) - b.hy; break;
    }
    r[0] = T(weight) * (Hinge(short_by) + Hinge(outside));
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& source, const BodyShape& target, Side side, double weight) {
    return new ceres::AutoDiffCostFunction<RelativeSideResidual, 1, 4, 1, 4, 1>(
        new RelativeSideResidual{source, target, side, weight});
  }
};

// next_to / near / far: the plan gap between the two boxes (the widest separation along a face normal;
// negative when they overlap) stays within [min_gap, max_gap] m.
struct GapResidual {
  BodyShape source, target;
  double min_gap = 0.0, max_gap = 0.5;
  double weight = 1.0;

  template <typename T>
  bool operator()(const T* ps, const T* ss, const T* pt, const T* st, T* r) const {
    const T gap = -HorizontalDepth(PlaceBox(ps, ss, source), PlaceBox(pt, st, target));
    r[0] = T(weight) * (Hinge(T(min_gap) - gap) + Hinge(gap - T(max_gap)));
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& source, const BodyShape& target, double min_gap, double max_gap,
                                     double weight) {
    return new ceres::AutoDiffCostFunction<GapResidual, 1, 4, 1, 4, 1>(
        new GapResidual{source, target, min_gap, max_gap, weight});
  }
};

// align: the yaws agree modulo 90 degrees within `tolerance` rad.
struct AlignResidual {
  double tolerance = 0.0873;
  double weight = 1.0;

  template <typename T>
  bool operator()(const T* ps, const T* pt, T* r) const {
    using std::abs;
    using std::atan2;
    using std::cos;
    using std::sin;
    const T d = T(4.0) * (ps[3] - pt[3]);
    const T deviation = atan2(sin(d), cos(d)) / T(4.0);
    r[0] = T(weight) * Hinge(abs(deviation) - T(tolerance));
    return true;
  }
  static ceres::CostFunction* Create(double tolerance, double weight) {
    return new ceres::AutoDiffCostFunction<AlignResidual, 1, 4, 4>(new AlignResidual{tolerance, weight});
  }
};

// centered: the source's centre lies on the target's front-back axis (lateral offset along the target's
// x within `tolerance` m): the coffee table centred on the sofa, the rug under the table.
struct CenteredResidual {
  BodyShape source, target;
  double tolerance = 0.05;
  double weight = 1.0;

  template <typename T>
  bool operator()(const T* ps, const T* ss, const T* pt, const T* st, T* r) const {
    using std::abs;
    const PlacedBox<T> a = PlaceBox(ps, ss, source);
    const PlacedBox<T> b = PlaceBox(pt, st, target);
    const T lateral = (a.cx - b.cx) * b.ux + (a.cy - b.cy) * b.uy;
    r[0] = T(weight) * Hinge(abs(lateral) - T(tolerance));
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& source, const BodyShape& target, double tolerance, double weight) {
    return new ceres::AutoDiffCostFunction<CenteredResidual, 1, 4, 1, 4, 1>(
        new CenteredResidual{source, target, tolerance, weight});
  }
};

// A wall-bound body (against_wall, on_wall) keeps its whole width on its wall piece, `margin` m from
// either end: past the end of a wall that stops at an inner corner there is nothing behind it.
struct WallSpanResidual {
  BodyShape body;
  Point a;            // the wall's start
  Point d;            // unit direction along the wall
  double length = 0;  // m
  double margin = 0.0;
  double weight = 10.0;

  template <typename T>
  bool operator()(const T* p, const T* s, T* r) const {
    const PlacedBox<T> b = PlaceBox(p, s, body);
    const T t = (b.cx - a.x) * d.x + (b.cy - a.y) * d.y;
    const T half = ProjectedRadius(b, T(d.x), T(d.y));
    r[0] = T(weight) * Hinge(half + T(margin) - t);
    r[1] = T(weight) * Hinge(t + half + T(margin) - T(length));
    return true;
  }
  static ceres::CostFunction* Create(const BodyShape& body, Point a, Point d, double length, double margin, double weight) {
    return new ceres::AutoDiffCostFunction<WallSpanResidual, 2, 4, 1>(new WallSpanResidual{body, a, d, length, margin, weight});
  }
};

// A weak pull of a free body's yaw back to its 90-degree class: without it a relation tilts a table by a
// few degrees for a marginal gain; a relation that needs the turn still gets it.
struct YawPriorResidual {
  double yaw_class = 0.0;  // rad
  double weight = 0.2;     // per rad

  template <typename T>
  bool operator()(const T* p, T* r) const {
    r[0] = T(weight) * (p[3] - T(yaw_class));
    return true;
  }
  static ceres::CostFunction* Create(double yaw_class, double weight) {
    return new ceres::AutoDiffCostFunction<YawPriorResidual, 1, 4>(new YawPriorResidual{yaw_class, weight});
  }
};

// A weak pull of a scalable body's scale back to 1, so the solver shrinks only what must shrink.
struct ScalePriorResidual {
  double weight = 0.5;
  template <typename T>
  bool operator()(const T* s, T* r) const {
    r[0] = T(weight) * (s[0] - T(1.0));
    return true;
  }
  static ceres::CostFunction* Create(double weight) {
    return new ceres::AutoDiffCostFunction<ScalePriorResidual, 1, 1>(new ScalePriorResidual{weight});
  }
};

// The cost term of a semantic edge between two bodies: distances weighted `weight` per m, angles `weight`
// per 30 degrees (SCENE.md's E_sem units). Sets *pose_only when the term reads only the two pose blocks
// (align), not the scales.
inline ceres::CostFunction* SemanticCost(const SemanticEdge& e, const BodyShape& source, const BodyShape& target,
                                         double weight, bool* pose_only) {
  const double per_rad = weight * 6.0 / 3.14159265358979323846;
  *pose_only = false;
  using Side = RelativeSideResidual::Side;
  switch (e.relation) {
    case SemanticRelation::kFaceTo: return FaceToResidual::Create(source, target, e.max_angle, per_rad);
    case SemanticRelation::kFrontOf: return RelativeSideResidual::Create(source, target, Side::kFront, weight);
    case SemanticRelation::kBehind: return RelativeSideResidual::Create(source, target, Side::kBehind, weight);
    case SemanticRelation::kLeftOf: return RelativeSideResidual::Create(source, target, Side::kLeft, weight);
    case SemanticRelation::kRightOf: return RelativeSideResidual::Create(source, target, Side::kRight, weight);
    case SemanticRelation::kAlign: *pose_only = true; return AlignResidual::Create(e.tolerance, per_rad);
    case SemanticRelation::kCentered: return CenteredResidual::Create(source, target, e.tolerance, weight);
    default: return GapResidual::Create(source, target, e.min_gap, e.max_gap, weight);
  }
}

}  // namespace villa::solver
