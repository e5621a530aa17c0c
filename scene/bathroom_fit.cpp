#include "scene/bathroom_fit.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "layout/geometry.h"
#include "mesh/geometry2d.h"

namespace villa::scene {
namespace {

constexpr double kAreaSlack = 1e-4;  // m2: touching is not overlapping
constexpr double kEndGap = 0.02;     // m kept to a wall's ends (the solver keeps its body 2 cm from them)

// A wall as a frame: origin, unit direction, unit inward normal (the room is on the left of `inner`).
struct Frame {
  Point a, d, n;
};

Frame FrameOf(const FitWall& w) {
  Frame f;
  f.a = w.a;
  f.d = geo::Unit(geo::Sub(w.b, w.a));
  f.n = geo::Left(f.d);
  return f;
}

// The rectangle [t0, t1] along the wall x [s0, s1] out from it, CCW (d x n = +1).
Ring RectOf(const Frame& f, double t0, double t1, double s0, double s1) {
  auto at = [&](double t, double s) { return geo::Add(geo::Add(f.a, geo::Scale(f.d, t)), geo::Scale(f.n, s)); };
  return {at(t0, s0), at(t1, s0), at(t1, s1), at(t0, s1)};
}

struct Placed {
  int wall = -1;
  double t0 = 0.0, t1 = 0.0;
  Ring body, zone;  // zone empty when the fixture has none
  double z0 = 0.0, z1 = 0.0;
};

class Search {
 public:
  Search(const FitRoom& room, const std::vector<BathFixture>& fixtures, const BathFitOptions& options)
      : room_(room), fixtures_(fixtures), options_(options), placed_(fixtures.size()) {
    for (const FitWall& w : room_.walls) {
      frames_.push_back(FrameOf(w));
      lengths_.push_back(geo::Dist(w.a, w.b));
    }
    // The big ones first (they have the fewest places); companions after everything else, beside their
    // fixture.
    for (size_t i = 0; i < fixtures_.size(); ++i)
      if (fixtures_[i].companion_of < 0) order_.push_back(static_cast<int>(i));
    std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) {
      return fixtures_[a].width * (fixtures_[a].depth + fixtures_[a].zone) >
             fixtures_[b].width * (fixtures_[b].depth + fixtures_[b].zone);
    });
    for (size_t i = 0; i < fixtures_.size(); ++i)
      if (fixtures_[i].companion_of >= 0) order_.push_back(static_cast<int>(i));
  }

  BathFitResult Run() {
    BathFitResult r;
    r.fits = Place(0);
    r.exhausted = !r.fits && tried_ >= options_.budget;
    r.tried = tried_;
    if (r.fits)
      for (const Placed& p : placed_) r.places.push_back({p.wall, p.t0});
    return r;
  }

 private:
  bool OnFloor(const Ring& rect) const {
    double inside = 0.0;
    for (const Ring& ring : room_.free_floor) inside += IntersectionArea(ring, rect);
    return inside >= std::abs(SignedArea(rect)) - kAreaSlack;
  }

  // Whether fixture k fits at [t0, t0 + width] on wall w; fills `out`.
  bool Fits(int k, int w, double t0, Placed* out) {
    ++tried_;
    const BathFixture& f = fixtures_[k];
    const FitWall& wall = room_.walls[w];
    const Frame& fr = frames_[w];
    const double t1 = t0 + f.width;
    if (t0 < kEndGap - 1e-9 || t1 > lengths_[w] - kEndGap + 1e-9) return false;
    // On one free interval of the wall.
    if (std::none_of(wall.free.begin(), wall.free.end(),
                     [&](const Interval& i) { return t0 >= i.first - 1e-9 && t1 <= i.second + 1e-9; }))
      return false;
    if (f.mirror > 0.0) {
      const double c = 0.5 * (t0 + t1), h = 0.5 * std::max(f.mirror, f.width);
      for (const Interval& win : wall.windows)
        if (std::min(c + h, win.second) - std::max(c - h, win.first) > 0.01) return false;
    }
    Placed p;
    p.wall = w;
    p.t0 = t0;
    p.t1 = t1;
    const double s0 = options_.wall_gap, s1 = s0 + f.depth;
    p.body = RectOf(fr, t0, t1, s0, s1);
    if (f.zone > 0.0) p.zone = RectOf(fr, t0, t1, s1, s1 + f.zone);
    p.z0 = room_.floor_z;
    p.z1 = room_.floor_z + f.height;
    if (!OnFloor(p.body) || (!p.zone.empty() && !OnFloor(p.zone))) return false;
    for (const FitKeepOut& ko : room_.keep_outs)
      if (std::min(ko.z_max, p.z1) - std::max(ko.z_min, p.z0) > 0.0 && IntersectionArea(ko.polygon, p.body) > kAreaSlack)
        return false;
    for (size_t j = 0; j < placed_.size(); ++j) {
      const Placed& q = placed_[j];
      if (q.wall < 0) continue;
      if (IntersectionArea(q.body, p.body) > kAreaSlack) return false;
      if (!q.zone.empty() && IntersectionArea(q.zone, p.body) > kAreaSlack) return false;
      if (!p.zone.empty() && IntersectionArea(q.body, p.zone) > kAreaSlack) return false;
    }
    *out = std::move(p);
    return true;
  }

  // Positions along wall w for fixture k: a comb over each free interval, its ends, and the slots right
  // beside what is placed (its body's and its zone's ends seen along this wall), so tight packings are found.
  std::vector<double> Stops(int k, int w) const {
    const double width = fixtures_[k].width;
    std::vector<double> ts;
    for (const Interval& i : room_.walls[w].free) {
      const double lo = std::max(i.first, kEndGap), hi = std::min(i.second, lengths_[w] - kEndGap) - width;
      if (hi < lo - 1e-9) continue;
      for (double t = lo; t < hi; t += options_.step) ts.push_back(t);
      ts.push_back(hi);
    }
    const Frame& fr = frames_[w];
    for (const Placed& q : placed_) {
      if (q.wall < 0) continue;
      for (const Ring* r : {&q.body, &q.zone}) {
        if (r->empty()) continue;
        double lo = 1e9, hi = -1e9;
        for (Point c : *r) {
          const double t = geo::Dot(geo::Sub(c, fr.a), fr.d);
          lo = std::min(lo, t);
          hi = std::max(hi, t);
        }
        ts.push_back(hi + 0.01);
        ts.push_back(lo - 0.01 - width);
      }
    }
    return ts;
  }

  bool Place(size_t depth) {
    if (depth == order_.size()) return true;
    if (tried_ >= options_.budget) return false;
    const int k = order_[depth];
    const BathFixture& f = fixtures_[k];
    if (f.companion_of >= 0) {
      const Placed& owner = placed_[f.companion_of];
      if (owner.wall < 0) return false;
      for (double t0 : {owner.t1 + options_.companion_gap, owner.t0 - options_.companion_gap - f.width}) {
        Placed p;
        if (!Fits(k, owner.wall, t0, &p)) continue;
        placed_[k] = std::move(p);
        if (Place(depth + 1)) return true;
        placed_[k] = Placed{};
      }
      return false;
    }
    std::vector<std::pair<int, double>> stops;
    for (int w = 0; w < static_cast<int>(room_.walls.size()); ++w)
      for (double t0 : Stops(k, w)) stops.push_back({w, t0});
    for (const auto& [w, t0] : stops) {
      Placed p;
      if (!Fits(k, w, t0, &p)) continue;
      placed_[k] = std::move(p);
      if (Place(depth + 1)) return true;
      placed_[k] = Placed{};
      if (tried_ >= options_.budget) return false;
    }
    return false;
  }

  const FitRoom& room_;
  const std::vector<BathFixture>& fixtures_;
  const BathFitOptions& options_;
  std::vector<Frame> frames_;
  std::vector<double> lengths_;
  std::vector<int> order_;
  std::vector<Placed> placed_;
  long tried_ = 0;
};

}  // namespace

std::string BathFitOptions::Check() const {
  if (!(step > 0.01 && step <= 1.0)) return "step = " + std::to_string(step) + ": must be in (0.01, 1]";
  if (!(wall_gap >= 0.0 && wall_gap <= 0.2)) return "wall_gap = " + std::to_string(wall_gap) + ": must be in [0, 0.2]";
  if (!(companion_gap >= 0.0 && companion_gap <= 0.5))
    return "companion_gap = " + std::to_string(companion_gap) + ": must be in [0, 0.5]";
  if (budget < 1) return "budget = " + std::to_string(budget) + ": must be >= 1";
  return "";
}

FitRoom FitRoomOf(const RoomContext& room) {
  FitRoom out;
  out.free_floor = room.free_floor;
  out.floor_z = room.floor_z;
  for (const WallEdge& w : room.walls) {
    FitWall f{w.inner.a, w.inner.b, w.free, {}};
    for (const WallWindow& win : w.windows) f.windows.push_back(win.span);
    out.walls.push_back(std::move(f));
  }
  for (const KeepOut& k : room.keep_outs) out.keep_outs.push_back({k.polygon, k.z_min, k.z_max});
  return out;
}

BathFitResult FitBathFixtures(const RoomContext& room, const std::vector<BathFixture>& fixtures,
                              const BathFitOptions& options) {
  return FitBathFixtures(FitRoomOf(room), fixtures, options);
}

BathFitResult FitBathFixtures(const FitRoom& room, const std::vector<BathFixture>& fixtures,
                              const BathFitOptions& options) {
  for (const BathFixture& f : fixtures)
    if (f.companion_of >= static_cast<int>(fixtures.size()) || f.companion_of == &f - fixtures.data()) return {};
  return Search(room, fixtures, options).Run();
}

}  // namespace villa::scene
