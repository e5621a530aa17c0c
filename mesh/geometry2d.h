#pragma once
// Small plane-vector helpers for building solids (x, y in metres, rings CCW): arithmetic, half-plane and
// convex clipping, ring cleaning. Questions about the plan (point in polygon, distances, footprints) are
// layout/geometry.h's.
#include <algorithm>
#include <cmath>
#include <vector>

#include "layout/layout.h"

namespace villa::geo {

inline Point Add(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
inline Point Sub(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
inline Point Scale(Point a, double s) { return {a.x * s, a.y * s}; }
inline double Dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
inline double Cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
inline double Len(Point a) { return std::hypot(a.x, a.y); }
inline double Dist(Point a, Point b) { return Len(Sub(a, b)); }
inline Point Unit(Point a) {
  double l = Len(a);
  return l > 0.0 ? Scale(a, 1.0 / l) : a;
}
inline Point Left(Point d) { return {-d.y, d.x}; }  // d rotated +90 degrees
inline Point Lerp(Point a, Point b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; }

// Keeps the part of `ring` where Dot(x - origin, normal) >= 0 (Sutherland-Hodgman, one plane).
inline Ring ClipHalfPlane(const Ring& ring, Point origin, Point normal) {
  Ring out;
  size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    Point a = ring[i];
    Point b = ring[(i + 1) % n];
    double da = Dot(Sub(a, origin), normal);
    double db = Dot(Sub(b, origin), normal);
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) out.push_back(Lerp(a, b, da / (da - db)));
  }
  return out;
}

// Clips `subject` (any simple ring) by the convex ring `clip` (CCW).
inline Ring ClipConvex(Ring subject, const Ring& clip) {
  for (size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    Point a = clip[i];
    Point b = clip[(i + 1) % clip.size()];
    subject = ClipHalfPlane(subject, a, Left(Sub(b, a)));
  }
  return subject;
}

// Drops repeated points (closer than `eps`) and vertices within `eps` of the line through their
// neighbours; returns a CCW ring (reversed if it was clockwise), empty when fewer than 3 points remain.
inline Ring CleanRing(Ring ring, double eps = 1e-7) {
  bool changed = true;
  while (changed && ring.size() >= 3) {
    changed = false;
    for (size_t i = 0; i < ring.size() && ring.size() >= 3; ++i) {
      size_t n = ring.size();
      Point p = ring[(i + n - 1) % n];
      Point c = ring[i];
      Point q = ring[(i + 1) % n];
      double base = Dist(p, q);
      bool repeated = Dist(p, c) < eps;
      // Collinear with its neighbours: a vertex on a straight stretch, or the tip of a zero-width spike
      // (what clipping a non-convex ring leaves where the result touches the clip line).
      bool collinear = base > eps && std::abs(Cross(Sub(q, p), Sub(c, p))) / base < eps;
      bool spike = base < eps;  // p == q: c is the tip of a zero-width spike
      if (repeated || collinear || spike) {
        ring.erase(ring.begin() + static_cast<long>(i));
        changed = true;
      }
    }
  }
  if (ring.size() < 3) return {};
  if (SignedArea(ring) < 0.0) std::reverse(ring.begin(), ring.end());
  return ring;
}

inline Ring Translate(const Ring& ring, Point by) {
  Ring out;
  for (Point p : ring) out.push_back(Add(p, by));
  return out;
}

}  // namespace villa::geo
