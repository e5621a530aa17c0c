#include "mesh/solids.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "mesh/geometry2d.h"
#include "mesh/triangulate.h"

namespace villa {
namespace {

constexpr double kWeld = 1e-7;  // m: vertices this close are one (faces built from the same corner)

// Adds a planar polygon (2D ring + holes mapped to 3D by `map`) triangulated, facing `normal`.
void AddFace(TriangleMesh& mesh, const Ring& outer, const std::vector<Ring>& holes,
             const std::function<Vec3(Point)>& map, Vec3 normal) {
  std::vector<Vec3> points;
  for (Point p : outer) points.push_back(map(p));
  for (const Ring& h : holes)
    for (Point p : h) points.push_back(map(p));
  auto triangles = TriangulatePolygon(outer, holes);
  if (triangles.empty()) return;
  // The triangles are CCW in the 2D frame; the map decides which way that faces in 3D.
  bool flip = false;
  for (const auto& t : triangles) {
    Vec3 n = Cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
    if (Norm(n) > 1e-12) {
      flip = Dot(n, normal) < 0.0;
      break;
    }
  }
  std::vector<int> index(points.size());
  for (size_t i = 0; i < points.size(); ++i) index[i] = mesh.AddVertex(points[i], kWeld);
  for (const auto& t : triangles) {
    if (flip)
      mesh.AddTriangle(index[t[0]], index[t[2]], index[t[1]]);
    else
      mesh.AddTriangle(index[t[0]], index[t[1]], index[t[2]]);
  }
}

// A planar quad a-b-c-d (in order around it), facing `normal`.
void AddQuad(TriangleMesh& mesh, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 normal) {
  int ia = mesh.AddVertex(a, kWeld), ib = mesh.AddVertex(b, kWeld), ic = mesh.AddVertex(c, kWeld),
      id = mesh.AddVertex(d, kWeld);
  Vec3 n = Cross(b - a, c - a) + Cross(c - a, d - a);
  if (Dot(n, normal) < 0.0) {
    std::swap(ib, id);
  }
  mesh.AddTriangle(ia, ib, ic);
  mesh.AddTriangle(ia, ic, id);
}

Vec3 At(Point p, double z) { return {p.x, p.y, z}; }

// Vertical quads along every edge of a ring (CCW: outward; a hole given CW faces into the hole).
void AddSides(TriangleMesh& mesh, const Ring& ring, double z0, double z1, bool ring_is_hole) {
  Ring r = ring;
  if ((SignedArea(r) > 0.0) == ring_is_hole) std::reverse(r.begin(), r.end());
  for (size_t i = 0; i < r.size(); ++i) {
    Point a = r[i];
    Point b = r[(i + 1) % r.size()];
    Point out = {b.y - a.y, a.x - b.x};  // right of a->b: outward for a CCW ring, into the hole for a CW one
    AddQuad(mesh, At(a, z0), At(b, z0), At(b, z1), At(a, z1), {out.x, out.y, 0.0});
  }
}

}  // namespace

TriangleMesh ExtrudePlan(const Ring& outer, const std::vector<Ring>& holes, double z0, double z1) {
  TriangleMesh mesh;
  AddFace(mesh, outer, holes, [z1](Point p) { return At(p, z1); }, {0, 0, 1});
  AddFace(mesh, outer, holes, [z0](Point p) { return At(p, z0); }, {0, 0, -1});
  AddSides(mesh, outer, z0, z1, false);
  for (const Ring& h : holes) AddSides(mesh, h, z0, z1, true);
  return mesh;
}

TriangleMesh ExtrudeProfile(const Ring& profile, Point origin, Point along, Point across, double w0, double w1) {
  TriangleMesh mesh;
  auto map = [&](Point p, double w) {
    Point plan = geo::Add(origin, geo::Add(geo::Scale(along, p.x), geo::Scale(across, w)));
    return Vec3{plan.x, plan.y, p.y};
  };
  Vec3 out_w{across.x, across.y, 0.0};
  AddFace(mesh, profile, {}, [&](Point p) { return map(p, w1); }, out_w);
  AddFace(mesh, profile, {}, [&](Point p) { return map(p, w0); }, out_w * -1.0);
  Ring r = profile;
  if (SignedArea(r) < 0.0) std::reverse(r.begin(), r.end());
  for (size_t i = 0; i < r.size(); ++i) {
    Point a = r[i];
    Point b = r[(i + 1) % r.size()];
    Point out2 = {b.y - a.y, a.x - b.x};  // outward in the profile plane (a, z)
    Vec3 normal = Vec3{along.x, along.y, 0.0} * out2.x + Vec3{0, 0, 1} * out2.y;
    AddQuad(mesh, map(a, w0), map(b, w0), map(b, w1), map(a, w1), normal);
  }
  return mesh;
}

SRange FullSection(const Ring& plan, const WallFrame& frame) {
  const double half = frame.thickness / 2.0;
  const double eps = 1e-6;
  int plus_edges = 0, minus_edges = 0;
  double plus_lo = 0, plus_hi = 0, minus_lo = 0, minus_hi = 0;
  for (size_t i = 0; i < plan.size(); ++i) {
    Point a = plan[i];
    Point b = plan[(i + 1) % plan.size()];
    double qa = frame.Q(a), qb = frame.Q(b);
    double sa = frame.S(a), sb = frame.S(b);
    if (std::abs(qa - half) < eps && std::abs(qb - half) < eps) {
      ++plus_edges;
      plus_lo = std::min(sa, sb);
      plus_hi = std::max(sa, sb);
    } else if (std::abs(qa + half) < eps && std::abs(qb + half) < eps) {
      ++minus_edges;
      minus_lo = std::min(sa, sb);
      minus_hi = std::max(sa, sb);
    }
  }
  if (plus_edges != 1 || minus_edges != 1) return {0.0, 0.0};
  return {std::max(plus_lo, minus_lo), std::min(plus_hi, minus_hi)};
}

TriangleMesh WallSolid(const Ring& plan, const WallFrame& frame, double zb, double zt,
                       const std::vector<WallOpening>& openings) {
  if (openings.empty()) return ExtrudePlan(plan, {}, zb, zt);
  const double half = frame.thickness / 2.0;
  const double eps = 1e-6;
  TriangleMesh mesh;
  // Top cap, and the end chains: every plan edge not on a face.
  AddFace(mesh, plan, {}, [zt](Point p) { return At(p, zt); }, {0, 0, 1});
  double face_lo[2] = {0, 0}, face_hi[2] = {0, 0};  // [0]: q = -half, [1]: q = +half
  for (size_t i = 0; i < plan.size(); ++i) {
    Point a = plan[i];
    Point b = plan[(i + 1) % plan.size()];
    double qa = frame.Q(a), qb = frame.Q(b);
    for (int side = 0; side < 2; ++side) {
      double q = side ? half : -half;
      if (std::abs(qa - q) < eps && std::abs(qb - q) < eps) {
        face_lo[side] = std::min(frame.S(a), frame.S(b));
        face_hi[side] = std::max(frame.S(a), frame.S(b));
        goto next_edge;
      }
    }
    {
      Point out = {b.y - a.y, a.x - b.x};
      AddQuad(mesh, At(a, zb), At(b, zb), At(b, zt), At(a, zt), {out.x, out.y, 0.0});
    }
  next_edge:;
  }
  // The two faces: elevation (s, z) with doors as notches in the bottom edge and windows as holes.
  for (int side = 0; side < 2; ++side) {
    double q = side ? half : -half;
    Ring outer;
    std::vector<Ring> holes;
    outer.push_back({face_lo[side], zb});
    for (const WallOpening& o : openings) {
      if (o.z0 <= zb + eps) {
        outer.push_back({o.s0, zb});
        outer.push_back({o.s0, o.z1});
        outer.push_back({o.s1, o.z1});
        outer.push_back({o.s1, zb});
      } else {
        holes.push_back({{o.s0, o.z0}, {o.s1, o.z0}, {o.s1, o.z1}, {o.s0, o.z1}});
      }
    }
    outer.push_back({face_hi[side], zb});
    outer.push_back({face_hi[side], zt});
    outer.push_back({face_lo[side], zt});
    Point n = frame.normal;
    AddFace(mesh, outer, holes, [&](Point p) { return At(frame.ToPlan(p.x, q), p.y); },
            Vec3{n.x, n.y, 0.0} * (side ? 1.0 : -1.0));
  }
  // Reveals: jambs, heads and sills through the thickness.
  Vec3 d{frame.direction.x, frame.direction.y, 0.0};
  for (const WallOpening& o : openings) {
    auto corner = [&](double s, double q, double z) { return At(frame.ToPlan(s, q), z); };
    AddQuad(mesh, corner(o.s0, -half, o.z0), corner(o.s0, half, o.z0), corner(o.s0, half, o.z1),
            corner(o.s0, -half, o.z1), d);
    AddQuad(mesh, corner(o.s1, -half, o.z0), corner(o.s1, half, o.z0), corner(o.s1, half, o.z1),
            corner(o.s1, -half, o.z1), d * -1.0);
    AddQuad(mesh, corner(o.s0, -half, o.z1), corner(o.s1, -half, o.z1), corner(o.s1, half, o.z1),
            corner(o.s0, half, o.z1), {0, 0, -1});
    if (o.z0 > zb + eps)
      AddQuad(mesh, corner(o.s0, -half, o.z0), corner(o.s1, -half, o.z0), corner(o.s1, half, o.z0),
              corner(o.s0, half, o.z0), {0, 0, 1});
  }
  // Bottom: the plan between the door slots.
  std::vector<double> cuts;  // s0, s1 of each door, in order
  for (const WallOpening& o : openings)
    if (o.z0 <= zb + eps) {
      cuts.push_back(o.s0);
      cuts.push_back(o.s1);
    }
  Point d2 = frame.direction;
  for (size_t k = 0; k <= cuts.size(); k += 2) {
    Ring part = plan;
    if (k > 0) part = geo::ClipHalfPlane(part, frame.ToPlan(cuts[k - 1], 0.0), d2);
    if (k < cuts.size()) part = geo::ClipHalfPlane(part, frame.ToPlan(cuts[k], 0.0), geo::Scale(d2, -1.0));
    part = geo::CleanRing(part, 1e-9);
    if (!part.empty()) AddFace(mesh, part, {}, [zb](Point p) { return At(p, zb); }, {0, 0, -1});
  }
  return mesh;
}

}  // namespace villa
