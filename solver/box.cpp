#include "solver/box.h"

#include <algorithm>
#include <cmath>

#include "mesh/geometry2d.h"
#include "solver/residuals.h"

namespace villa::solver {
namespace {

PlacedBox<double> AsPlaced(const OrientedBox& b) {
  PlacedBox<double> p;
  p.cx = b.c.x;
  p.cy = b.c.y;
  p.ux = std::cos(b.yaw);
  p.uy = std::sin(b.yaw);
  p.hx = b.hx;
  p.hy = b.hy;
  p.z0 = b.z0;
  p.z1 = b.z1;
  return p;
}

}  // namespace

Point OrientedBox::U() const { return {std::cos(yaw), std::sin(yaw)}; }
Point OrientedBox::V() const { return {-std::sin(yaw), std::cos(yaw)}; }
Point OrientedBox::Front() const { return {std::sin(yaw), -std::cos(yaw)}; }
Point OrientedBox::Local(Point p) const {
  const Point d = geo::Sub(p, c);
  return {geo::Dot(d, U()), geo::Dot(d, V())};
}

double DistanceToBox(const OrientedBox& box, Point p) {
  const Point d = geo::Sub(p, box.c);
  const double lx = std::abs(geo::Dot(d, box.U())) - box.hx, ly = std::abs(geo::Dot(d, box.V())) - box.hy;
  return std::hypot(std::max(lx, 0.0), std::max(ly, 0.0));
}

Ring OrientedBox::Footprint() const {
  const Point u = geo::Scale(U(), hx);
  const Point v = geo::Scale(V(), hy);
  return {geo::Sub(geo::Sub(c, u), v), geo::Sub(geo::Add(c, u), v), geo::Add(geo::Add(c, u), v),
          geo::Add(geo::Sub(c, u), v)};
}

bool OrientedBox::ContainsPlan(Point p, double tolerance) const {
  const Point d = geo::Sub(p, c);
  return std::abs(geo::Dot(d, U())) <= hx + tolerance && std::abs(geo::Dot(d, V())) <= hy + tolerance;
}

double PlanDepth(const OrientedBox& a, const OrientedBox& b) { return HorizontalDepth(AsPlaced(a), AsPlaced(b)); }

double HeightOverlap(const OrientedBox& a, const OrientedBox& b) {
  return std::min(a.z1, b.z1) - std::max(a.z0, b.z0);
}

double OverlapVolume(const OrientedBox& a, const OrientedBox& b) {
  const double dz = HeightOverlap(a, b);
  if (dz <= 0.0 || PlanDepth(a, b) <= 0.0) return 0.0;
  return ClippedArea(a.Footprint(), b.Footprint()) * dz;
}

double ClippedArea(const Ring& subject, const Ring& clip) {
  // Sutherland-Hodgman against a convex window: for a non-convex subject the result may hold zero-width
  // bridges, which add no area, so the shoelace area is still exact.
  const Ring part = geo::ClipConvex(subject, clip);
  return part.size() < 3 ? 0.0 : std::abs(SignedArea(part));
}

std::vector<Point> ReflexVertices(const Ring& ring) {
  std::vector<Point> out;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Point& p = ring[(i + n - 1) % n];
    const Point& c = ring[i];
    const Point& q = ring[(i + 1) % n];
    if (geo::Cross(geo::Sub(c, p), geo::Sub(q, c)) < -1e-9) out.push_back(c);
  }
  return out;
}

}  // namespace villa::solver
