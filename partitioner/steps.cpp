#include "partitioner/steps.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace villa::partition {
namespace {

enum Side { kBottom, kRight, kTop, kLeft };

// The narrowest passage left beside the staircase, m (rooms beside it stay at least this wide).
constexpr double kStairPassage = 2.0;

// A notch box on `side` of the W x H rectangle: along that side from `offset` for `width`, `depth` deep.
IBox NotchBox(Side side, int64_t W, int64_t H, int64_t offset, int64_t width, int64_t depth) {
  switch (side) {
    case kBottom: return {offset, 0, offset + width, depth};
    case kTop: return {offset, H - depth, offset + width, H};
    case kLeft: return {0, offset, depth, offset + width};
    case kRight: return {W - depth, offset, W, offset + width};
  }
  return {};
}

int64_t Frac(int64_t value, double f) { return static_cast<int64_t>(std::llround(static_cast<double>(value) * f)); }

// rect minus the boxes; empty unless the result is one simple ring.
IRing Subtract(IRing ring, const std::vector<IBox>& boxes) {
  for (const IBox& box : boxes) {
    std::vector<IRing> out;
    if (!SubtractBox(ring, box, &out) || out.size() != 1) return {};
    ring = std::move(out[0]);
  }
  return ring;
}

bool AcceptCut(const IRing& before, const IRing& after) {
  return after.size() >= 3 && IsSimple(after) && TwiceArea(after) > 0 && TwiceArea(after) < TwiceArea(before);
}

// Chamfer the convex corner i: cut `a` units back along the incoming edge and `b` along the outgoing one.
IRing Chamfer(const IRing& ring, std::size_t i, int64_t a, int64_t b) {
  const std::size_t n = ring.size();
  const IPoint prev = ring[(i + n - 1) % n], v = ring[i], next = ring[(i + 1) % n];
  auto unit = [](IPoint from, IPoint to) {
    const int64_t g = Gcd(to.x - from.x, to.y - from.y);
    return IPoint{(to.x - from.x) / g, (to.y - from.y) / g};
  };
  const IPoint din = unit(v, prev), dout = unit(v, next);
  IRing out;
  for (std::size_t j = 0; j < n; ++j) {
    if (j == i) {
      out.push_back({v.x + din.x * a, v.y + din.y * a});
      out.push_back({v.x + dout.x * b, v.y + dout.y * b});
    } else {
      out.push_back(ring[j]);
    }
  }
  return Normalize(out);
}

int64_t AxisLength(IPoint a, IPoint b) { return std::llabs(b.x - a.x) + std::llabs(b.y - a.y); }
bool IsAxisAligned(IPoint a, IPoint b) { return a.x == b.x || a.y == b.y; }

// One angled cut of an irregular footprint: a chamfer, a long slanted edge or a triangular bite.
IRing AngledCut(const IRing& ring, const Scale& scale, Rng& rng) {
  const std::size_t n = ring.size();
  const int kind = static_cast<int>(rng.Int(0, 2));
  const std::size_t i = static_cast<std::size_t>(rng.Int(0, static_cast<int64_t>(n) - 1));
  const IPoint prev = ring[(i + n - 1) % n], v = ring[i], next = ring[(i + 1) % n];
  const int64_t one = scale.UnitsUp(1.0);
  if (kind <= 1) {
    if (Cross(prev, v, next) <= 0) return {};  // only convex corners
    if (!IsAxisAligned(prev, v) || !IsAxisAligned(v, next)) return {};
    const int64_t lin = AxisLength(prev, v), lout = AxisLength(v, next);
    int64_t a, b;
    if (kind == 0) {  // chamfer: both legs 1-4 m, independent (any slope)
      a = rng.Int(2 * one, std::min(4 * one, lin / 2));
      b = rng.Int(one + one / 2, std::min(4 * one, lout / 2));
    } else {  // slanted edge: a long leg along one side, a short one along the other
      a = rng.Int(Frac(lin, 0.4), Frac(lin, 0.75));
      b = rng.Int(one, std::min(3 * one, lout / 3));
    }
    if (a < one || b < one || a > lin - 2 * one || b > lout - 2 * one) return {};
    if (rng.Chance(0.5)) std::swap(a, b);
    if (a > lin - 2 * one || b > lout - 2 * one) return {};
    return Chamfer(ring, i, a, b);
  }
  // Triangular bite into the edge v -> next.
  if (!IsAxisAligned(v, next)) return {};
  const int64_t len = AxisLength(v, next);
  if (len < 7 * one) return {};
  const int64_t width = rng.Int(2 * one, std::min(4 * one, len - 4 * one));
  const int64_t start = rng.Int(2 * one, len - width - 2 * one);
  const int64_t depth = rng.Int(one, 2 * one + one / 2);
  const int64_t apex = start + rng.Int(std::max<int64_t>(1, width / 4), width - std::max<int64_t>(1, width / 4));
  const IPoint d{(next.x - v.x) / len, (next.y - v.y) / len};
  const IPoint inward{-d.y, d.x};  // left of the edge: inside a counter-clockwise ring
  IRing out;
  for (std::size_t j = 0; j < n; ++j) {
    out.push_back(ring[j]);
    if (j == i) {
      out.push_back({v.x + d.x * start, v.y + d.y * start});
      out.push_back({v.x + d.x * apex + inward.x * depth, v.y + d.y * apex + inward.y * depth});
      out.push_back({v.x + d.x * (start + width), v.y + d.y * (start + width)});
    }
  }
  return Normalize(out);
}

// `ring`, drawn in a w x h frame, mirrored and/or with its axes swapped (counter-clockwise kept).
IRing Oriented(const IRing& ring, int64_t w, int64_t h, bool mirror_x, bool mirror_y, bool swap) {
  IRing out;
  out.reserve(ring.size());
  for (IPoint p : ring) {
    if (mirror_x) p.x = w - p.x;
    if (mirror_y) p.y = h - p.y;
    if (swap) std::swap(p.x, p.y);
    out.push_back(p);
  }
  if (mirror_x != mirror_y ? !swap : swap) std::reverse(out.begin(), out.end());
  return Normalize(out);
}

}  // namespace

uint64_t MixSeed(uint64_t a, uint64_t b) {
  Rng rng(a ^ (b * 0xD1B54A32D192ED03ull + 0x8CB92BA72F3D8DD7ull));
  rng.Next();
  return rng.Next();
}

IRing ChamferCorners(IRing ring, const Scale& scale, Rng& rng) {
  const int64_t one = scale.UnitsUp(1.0);
  const int wanted = rng.Chance(0.6) ? 1 : 2;
  int made = 0;
  for (int attempt = 0; attempt < 8 && made < wanted; ++attempt) {
    const std::size_t n = ring.size();
    const std::size_t i = static_cast<std::size_t>(rng.Int(0, static_cast<int64_t>(n) - 1));
    const IPoint prev = ring[(i + n - 1) % n], v = ring[i], next = ring[(i + 1) % n];
    if (Cross(prev, v, next) <= 0 || !IsAxisAligned(prev, v) || !IsAxisAligned(v, next)) continue;
    const int64_t leg = rng.Int(one + one / 2, 2 * one);  // 1.5-2 m
    if (leg > AxisLength(prev, v) - 2 * one || leg > AxisLength(v, next) - 2 * one) continue;
    IRing cut = Chamfer(ring, i, leg, leg);
    if (!AcceptCut(ring, cut)) continue;
    ring = std::move(cut);
    ++made;
  }
  return ring;
}

int64_t Scale::Units(double metres) const { return static_cast<int64_t>(std::llround(metres / grid)); }
int64_t Scale::UnitsUp(double metres) const { return static_cast<int64_t>(std::ceil(metres / grid - 1e-9)); }

IRing FootprintShape(ShapeClass shape, int64_t W, int64_t H, const Scale& scale, Rng& rng) {
  const IRing rect = BoxRing({0, 0, W, H});
  const int64_t arm = scale.UnitsUp(4.0);  // every wing at least 4 m deep (a staircase or a room fits)
  switch (shape) {
    case ShapeClass::kRectangle: return rect;
    case ShapeClass::kL: {
      const int64_t nw = rng.Int(Frac(W, 0.3), std::min(Frac(W, 0.55), W - arm));
      const int64_t nh = rng.Int(Frac(H, 0.3), std::min(Frac(H, 0.55), H - arm));
      if (nw < arm / 2 || nh < arm / 2) return {};
      const Side side = rng.Chance(0.5) ? kBottom : kTop;
      const bool at_start = rng.Chance(0.5);
      return Subtract(rect, {NotchBox(side, W, H, at_start ? 0 : W - nw, nw, nh)});
    }
    case ShapeClass::kU: {
      const Side side = static_cast<Side>(rng.Int(0, 3));
      const int64_t along = (side == kBottom || side == kTop) ? W : H;
      const int64_t across = (side == kBottom || side == kTop) ? H : W;
      const int64_t min_arm = std::max(arm, Frac(along, 0.2));
      const int64_t width = rng.Int(Frac(along, 0.25), std::min(Frac(along, 0.5), along - 2 * min_arm));
      const int64_t depth = rng.Int(Frac(across, 0.3), std::min(Frac(across, 0.55), across - arm));
      if (width < arm / 2 || depth < arm / 2 || along - width < 2 * min_arm) return {};
      const int64_t offset = rng.Int(min_arm, along - width - min_arm);
      return Subtract(rect, {NotchBox(side, W, H, offset, width, depth)});
    }
    case ShapeClass::kT: {
      const Side side = static_cast<Side>(rng.Int(0, 3));
      const int64_t along = (side == kBottom || side == kTop) ? W : H;
      const int64_t across = (side == kBottom || side == kTop) ? H : W;
      const int64_t stem = rng.Int(std::max(arm, Frac(along, 0.3)), Frac(along, 0.5));
      const int64_t a = rng.Int(Frac(along - stem, 0.4), Frac(along - stem, 0.6));
      const int64_t b = along - stem - a;
      const int64_t depth = rng.Int(Frac(across, 0.35), std::min(Frac(across, 0.6), across - arm));
      if (a < arm / 2 || b < arm / 2 || depth < arm / 2) return {};
      return Subtract(rect, {NotchBox(side, W, H, 0, a, depth), NotchBox(side, W, H, along - b, b, depth)});
    }
    case ShapeClass::kH: {
      const bool vertical_bar = rng.Chance(0.5);  // notches in bottom and top (else left and right)
      const Side s1 = vertical_bar ? kBottom : kLeft, s2 = vertical_bar ? kTop : kRight;
      const int64_t along = vertical_bar ? W : H;
      const int64_t across = vertical_bar ? H : W;
      const int64_t min_arm = std::max(arm, Frac(along, 0.22));
      std::vector<IBox> boxes;
      int64_t depth_total = 0;
      for (Side s : {s1, s2}) {
        const int64_t width = rng.Int(Frac(along, 0.25), std::min(Frac(along, 0.45), along - 2 * min_arm));
        const int64_t depth = rng.Int(Frac(across, 0.22), Frac(across, 0.32));
        if (width < arm / 2 || depth < arm / 2 || along - width < 2 * min_arm) return {};
        const int64_t slack = (along - width - 2 * min_arm) / 3;
        const int64_t centre_offset = (along - width) / 2;
        const int64_t offset = rng.Int(centre_offset - slack, centre_offset + slack);
        boxes.push_back(NotchBox(s, W, H, offset, width, depth));
        depth_total += depth;
      }
      if (across - depth_total < arm) return {};
      return Subtract(rect, boxes);
    }
    case ShapeClass::kHexagon: {
      // Pointed ends on the long axis, slopes of 2:1 (corners of 127 degrees at the points, 117 at the
      // others; a regular hexagon's 120 all round is 1.73:1, whose grid steps of 4 m hold no door, where 2:1
      // steps are 1.12 m).
      const bool swap = H > W;
      int64_t w = swap ? H : W;
      const int64_t q = (swap ? W : H) / 4, h = 2 * q;
      if (q < 1) return {};
      // The flat sides at least 8 m (a staircase 2 m from both ends): a frame too short for that grows.
      w = std::max(w, 2 * q + 2 * arm);
      const IRing hex{{q, 0}, {w - q, 0}, {w, h}, {w - q, 2 * h}, {q, 2 * h}, {0, h}};
      return Oriented(hex, w, 2 * h, false, false, swap);
    }
    case ShapeClass::kOctagon: {
      // A rectangle with four 45-degree corners of 22-32 % of the short side (29 % is regular).
      const int64_t c = Frac(std::min(W, H), 0.22 + 0.10 * rng.Unit());
      if (c < 2 || std::min(W, H) - 2 * c < arm) return {};
      return IRing{{c, 0}, {W - c, 0}, {W, c}, {W, H - c}, {W - c, H}, {c, H}, {0, H - c}, {0, c}};
    }
    case ShapeClass::kTrapezoid: {
      // The full base on one side, the opposite side shorter at one or both ends, the slanted sides rising
      // 2 or 3 to 1 (63 or 72 degrees; grid steps of 1.12 or 1.58 m, so doors fit on walls along them).
      const bool swap = rng.Chance(0.5);
      const int64_t w = swap ? H : W;
      const int64_t k = rng.Chance(0.5) ? 2 : 3;
      const int64_t h = (swap ? W : H) / k * k;
      // Both ends cut where the top keeps 40 % of the base, else one (a right trapezoid).
      int64_t a = h / k, b = rng.Chance(0.6) && 10 * 2 * a <= 6 * w ? h / k : 0;
      if (rng.Chance(0.5)) std::swap(a, b);
      if (a + b < 2 || w - a - b < arm || 10 * (a + b) > 6 * w) return {};
      const IRing trap = Normalize({{0, 0}, {w, 0}, {w - b, h}, {a, h}});
      return Oriented(trap, w, h, false, rng.Chance(0.5), swap);
    }
    case ShapeClass::kCross: {
      // Four wings round a central hall: a notch at each corner, 20-30 % of each side; wings at least 4 m.
      std::vector<IBox> boxes;
      for (int corner = 0; corner < 4; ++corner) {
        const int64_t nw = Frac(W, 0.2 + 0.1 * rng.Unit()), nh = Frac(H, 0.2 + 0.1 * rng.Unit());
        if (nw < 2 || nh < 2) return {};
        const int64_t x0 = corner & 1 ? W - nw : 0, y0 = corner & 2 ? H - nh : 0;
        boxes.push_back({x0, y0, x0 + nw, y0 + nh});
      }
      if (W - (boxes[0].width() + boxes[1].width()) < arm || H - (boxes[0].height() + boxes[2].height()) < arm ||
          W - (boxes[2].width() + boxes[3].width()) < arm || H - (boxes[1].height() + boxes[3].height()) < arm)
        return {};
      return Subtract(rect, boxes);
    }
    case ShapeClass::kBay: {
      // A bay 0.75-1.5 m deep out of one side, its base 35-50 % of the side, its two outer sides at 45
      // degrees, its front at least 1.5 m.
      const bool swap = rng.Chance(0.5);
      const int64_t w = swap ? H : W, h = swap ? W : H;
      const int64_t base = Frac(w, 0.35 + 0.15 * rng.Unit());
      const int64_t d = std::min(scale.UnitsUp(1.0 + 0.5 * rng.Unit()), (base - scale.UnitsUp(1.5)) / 2);
      const int64_t margin = scale.UnitsUp(2.0);
      if (d < scale.UnitsUp(0.75) || w - base < 2 * margin || h - d < arm) return {};
      const int64_t o = rng.Int(margin, w - base - margin);
      const IRing bay{{0, d}, {o, d}, {o + d, 0}, {o + base - d, 0}, {o + base, d}, {w, d}, {w, h}, {0, h}};
      return Oriented(bay, w, h, rng.Chance(0.5), rng.Chance(0.5), swap);
    }
    case ShapeClass::kAngledWing: {
      // A body with a wing turned 45 degrees off its side: the wing s * 1.41 wide (at least 4.2 m), its outer
      // side t * 1.41 long (its inner side at least 2.1 m).
      const bool swap = H > W;
      const int64_t w = swap ? H : W, h = swap ? W : H;
      const int64_t s_units = std::max(scale.UnitsUp(3.0), Frac(h, 0.3 + 0.1 * rng.Unit()));
      const int64_t t = std::min(s_units + scale.UnitsUp(2.0 + 2.0 * rng.Unit()), h - s_units);
      // The body at least as long as the wing reaches out (the frame grows for that), and 4 m.
      const int64_t body = std::max({w - t, t, arm});
      if (t < s_units + scale.UnitsUp(1.5)) return {};
      const IRing wing{{0, 0}, {body, 0}, {body + t, t}, {body + t - s_units, t + s_units}, {body, 2 * s_units},
                       {body, h}, {0, h}};
      return Oriented(wing, body + t, h, rng.Chance(0.5), rng.Chance(0.5), swap);
    }
    case ShapeClass::kIrregular: {
      IRing ring = rect;
      if (rng.Chance(0.4)) {
        const IRing l = FootprintShape(ShapeClass::kL, W, H, scale, rng);
        if (!l.empty()) ring = l;
      }
      const int cuts = static_cast<int>(rng.Int(1, 3));
      int made = 0;
      for (int attempt = 0; attempt < 12 && made < cuts; ++attempt) {
        IRing cut = AngledCut(ring, scale, rng);
        if (cut.empty() || !AcceptCut(ring, cut)) continue;
        ring = std::move(cut);
        ++made;
      }
      if (!HasAngledEdge(ring)) return {};
      return ring;
    }
  }
  return {};
}

bool PieceUsable(const IRing& piece, const BspLimits& limits) {
  if (piece.size() < 4 || TwiceArea(piece) < limits.min_area2 || HasSharpCorner(piece)) return false;
  const IBox box = BoundingBox(piece);
  if (box.width() < limits.min_side || box.height() < limits.min_side) return false;
  return !NarrowerThan(piece, limits.min_width);
}

std::optional<IBox> PlaceStaircase(const IRing& footprint, int64_t size, const Scale& scale, Rng& rng) {
  const std::size_t n = footprint.size();
  const int64_t margin = scale.UnitsUp(2.0);
  // What is left may narrow to a passage beside the staircase (a hall arm), no less.
  const double min_width = kStairPassage / scale.grid - 1e-9;
  double fx, fy;
  Centroid(footprint, &fx, &fy);
  const int64_t expected = TwiceArea(footprint) - 2 * size * size;
  // Candidate squares: on an axis-aligned edge, flush with either end or at a random offset.
  std::vector<IBox> candidates;
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint a = footprint[i], b = footprint[(i + 1) % n];
    if (!IsAxisAligned(a, b)) continue;
    const int64_t len = AxisLength(a, b);
    if (len < size) continue;
    const IPoint d{(b.x - a.x) / len, (b.y - a.y) / len};
    const IPoint inward{-d.y, d.x};
    // Flush with either end, or any whole-metre offset leaving at least 2 m to both ends.
    std::vector<int64_t> offsets{0, len - size};
    const int64_t metre = std::max<int64_t>(1, scale.Units(1.0));
    for (int64_t off = margin; off <= len - size - margin; off += metre) offsets.push_back(off);
    for (int64_t off : offsets) {
      const IPoint p0{a.x + d.x * off, a.y + d.y * off};
      const IPoint p1{p0.x + d.x * size + inward.x * size, p0.y + d.y * size + inward.y * size};
      candidates.push_back({std::min(p0.x, p1.x), std::min(p0.y, p1.y), std::max(p0.x, p1.x), std::max(p0.y, p1.y)});
    }
  }
  // Random order, first that fits.
  for (std::size_t i = candidates.size(); i > 1; --i)
    std::swap(candidates[i - 1], candidates[static_cast<std::size_t>(rng.Int(0, static_cast<int64_t>(i) - 1))]);
  for (const IBox& box : candidates) {
    const double sx = (box.min_x + box.max_x) / 2.0, sy = (box.min_y + box.max_y) / 2.0;
    if (std::abs(sx - fx) < 1e-6 && std::abs(sy - fy) < 1e-6) continue;
    std::vector<IRing> rest;
    if (!SubtractInside(footprint, BoxRing(box), &rest) || rest.size() != 1 || TwiceArea(rest[0]) != expected)
      continue;
    if (NarrowerThan(rest[0], min_width) || HasSharpCorner(rest[0])) continue;
    return box;
  }
  return std::nullopt;
}

IRing UpperFootprint(const IRing& lower, const std::optional<IBox>& stair, int64_t min_area2, const Scale& scale,
                     Rng& rng) {
  if (rng.Chance(0.3)) return lower;
  const IBox bb = BoundingBox(lower);
  const int64_t W = bb.width(), H = bb.height();
  const double min_width = static_cast<double>(scale.UnitsUp(2.5));
  IRing ring = lower;
  const int cuts = rng.Chance(0.7) ? 1 : 2;
  int made = 0;
  for (int attempt = 0; attempt < 10 && made < cuts; ++attempt) {
    // A corner block, a notch in a side, or a setback strip along a whole side.
    const int kind = static_cast<int>(rng.Int(0, 2));
    const Side side = static_cast<Side>(rng.Int(0, 3));
    const int64_t along = (side == kBottom || side == kTop) ? W : H;
    const int64_t across = (side == kBottom || side == kTop) ? H : W;
    int64_t width, offset;
    int64_t depth = rng.Int(Frac(across, 0.15), Frac(across, 0.4));
    if (kind == 0) {
      width = rng.Int(Frac(along, 0.2), Frac(along, 0.5));
      offset = rng.Chance(0.5) ? 0 : along - width;
    } else if (kind == 1) {
      width = rng.Int(Frac(along, 0.2), Frac(along, 0.45));
      offset = rng.Int(Frac(along, 0.15), along - width - Frac(along, 0.15));
    } else {
      width = along;
      offset = 0;
      depth = rng.Int(Frac(across, 0.1), Frac(across, 0.3));
    }
    if (width <= 0 || depth <= 0) continue;
    IBox box = NotchBox(side, W, H, offset, width, depth);
    box.min_x += bb.min_x;
    box.max_x += bb.min_x;
    box.min_y += bb.min_y;
    box.max_y += bb.min_y;
    // Reach past the bounding box on the outer side so the cut is clean.
    if (stair && box.min_x < stair->max_x && stair->min_x < box.max_x && box.min_y < stair->max_y &&
        stair->min_y < box.max_y)
      continue;
    std::vector<IRing> out;
    if (!SubtractBox(ring, box, &out) || out.size() != 1) continue;
    if (TwiceArea(out[0]) >= TwiceArea(ring) || TwiceArea(out[0]) < min_area2) continue;
    if (NarrowerThan(out[0], min_width)) continue;
    if (stair) {
      // What stays beside the staircase must still hold rooms.
      std::vector<IRing> rest;
      if (!SubtractInside(out[0], BoxRing(*stair), &rest)) continue;
      bool wide = true;
      for (const IRing& r : rest) wide = wide && !NarrowerThan(r, kStairPassage / scale.grid - 1e-9);
      if (!wide) continue;
    }
    ring = std::move(out[0]);
    ++made;
  }
  return ring;
}

namespace {
// ShapePenalty in the frame of direction (dx, dy): the piece's extents along it and across it.
double PenaltyInFrame(const IRing& piece, double dx, double dy) {
  const double len = std::sqrt(dx * dx + dy * dy);
  dx /= len, dy /= len;
  double u0 = 1e18, u1 = -1e18, v0 = 1e18, v1 = -1e18;
  for (const IPoint& p : piece) {
    const double u = static_cast<double>(p.x) * dx + static_cast<double>(p.y) * dy;
    const double v = -static_cast<double>(p.x) * dy + static_cast<double>(p.y) * dx;
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  const double w = u1 - u0, h = v1 - v0;
  if (w <= 0.0 || h <= 0.0) return 1e9;
  const double aspect = std::max(w, h) / std::min(w, h);
  const double fill = static_cast<double>(TwiceArea(piece)) / (2.0 * w * h);
  double penalty = 0.0;
  if (aspect > 2.0) penalty += 4.0 * (aspect - 2.0) * (aspect - 2.0);  // 2.5: 1, 3: 4, 4: 16
  if (fill < 0.75) penalty += 16.0 * (0.75 - fill);                    // a thin L round a corner
  return penalty;
}
}  // namespace

double PartsPenalty(const std::vector<IRing>& parts, const BspLimits& limits, double* worst) {
  double sum = 0.0;
  for (const IRing& part : parts) {
    const double penalty = ShapePenalty(part);
    if (worst) *worst = std::max(*worst, penalty);
    sum += penalty;
    if (limits.comfortable_width > 0.0 && NarrowerThan(part, limits.comfortable_width)) sum += kNarrowPenalty;
  }
  return sum;
}

double ShapePenalty(const IRing& piece) {
  // The axis frame, or the frame of one of its slanted edges where the piece is better proportioned in it
  // (a room in an angled wing is a rectangle in the wing's frame).
  double best = PenaltyInFrame(piece, 1.0, 0.0);
  for (std::size_t i = 0; i < piece.size() && best > 0.0; ++i) {
    const IPoint a = piece[i], b = piece[(i + 1) % piece.size()];
    if (a.x != b.x && a.y != b.y)
      best = std::min(best, PenaltyInFrame(piece, static_cast<double>(b.x - a.x), static_cast<double>(b.y - a.y)));
  }
  return best;
}

std::vector<IRing> SplitRoomBsp(std::vector<IRing> pieces, int target, const BspLimits& limits, Rng& rng,
                                std::vector<int64_t> wanted_area2, const std::vector<ILine>& follow) {
  std::sort(wanted_area2.begin(), wanted_area2.end());
  int failures = 0;
  auto oversized = [&] {
    if (limits.max_area2 <= 0 || static_cast<int>(pieces.size()) >= limits.max_pieces) return false;
    for (const IRing& p : pieces)
      if (TwiceArea(p) > limits.max_area2) return true;
    return false;
  };
  constexpr int kCandidates = 4;
  constexpr double kAngledBonus = 1.0;
  constexpr double kAngledWorst = 1.6;  // fill >= 65 % of the bounding box in the part's own frame, aspect <= 2.6
  while ((static_cast<int>(pieces.size()) < target || oversized()) && failures < 40) {
    const bool extra = static_cast<int>(pieces.size()) >= target;
    // A piece big enough to halve, chosen with weight area^3 (big rooms get split first, not always),
    // elongated or L-shaped pieces more often; past the target only the oversized ones.
    std::vector<double> weights(pieces.size(), 0.0);
    bool any = false;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const double a = static_cast<double>(TwiceArea(pieces[i]));
      if (extra && TwiceArea(pieces[i]) <= limits.max_area2) continue;
      if (a >= 2.0 * static_cast<double>(limits.min_area2)) {
        weights[i] = a * a * a * (1.0 + ShapePenalty(pieces[i]));
        any = true;
      }
    }
    if (!any) break;
    const std::size_t index = static_cast<std::size_t>(rng.Weighted(weights.data(), static_cast<int>(weights.size())));
    const IRing& piece = pieces[index];
    const IBox box = BoundingBox(piece);
    const double ratio = static_cast<double>(box.width()) / static_cast<double>(std::max<int64_t>(1, box.height()));
    // Cut across the longer side (rooms stay compact); a squarish piece either way.
    const double p_vertical = ratio > 1.2 ? 0.92 : (ratio < 1.0 / 1.2 ? 0.08 : 0.5);
    const int cap = std::max(target, extra ? limits.max_pieces : target);
    // Reflex corners of a non-convex piece (beside the staircase, in a notch): a line through one squares
    // off the L instead of leaving it to a room.
    std::vector<IPoint> reflex;
    for (std::size_t v = 0; v < piece.size() && piece.size() > 4; ++v) {
      const IPoint a = piece[(v + piece.size() - 1) % piece.size()], b = piece[v], c = piece[(v + 1) % piece.size()];
      if (Cross(a, b, c) < 0) reflex.push_back(b);
    }
    // A few candidate lines; the one whose parts are best proportioned wins (the first of equals).
    std::vector<IRing> best_parts;
    double best_score = 1e18;
    int64_t best_aimed = -1;
    // Directions of walls that follow the building: the slanted edges of the piece and of the floor's
    // outline (`follow`), as line normals (a, b) with a > 0 or a == 0 < b, each once.
    std::vector<std::pair<int64_t, int64_t>> normals;
    auto add_normal = [&](int64_t a, int64_t b) {
      if (a < 0 || (a == 0 && b < 0)) a = -a, b = -b;
      if (std::find(normals.begin(), normals.end(), std::make_pair(a, b)) == normals.end()) normals.push_back({a, b});
    };
    for (const ILine& l : SlantedLines(piece)) add_normal(l.a, l.b);
    for (const ILine& l : follow) add_normal(l.a, l.b);
    // Only slopes whose grid steps hold a door (1:1, 1:2, 2:1: steps of 0.71-1.12 m on the 0.5 m grid).
    normals.erase(std::remove_if(normals.begin(), normals.end(),
                                 [](const auto& n) { return std::llabs(n.first) + std::llabs(n.second) > 3; }),
                  normals.end());
    // The parts of `piece` cut by `line`, when the cut is on the grid and every part is a usable room.
    auto split_by = [&](const ILine& line) -> std::optional<std::vector<IRing>> {
      std::vector<IRing> low, high;
      if (!SplitIsOnGrid(piece, line) || !SplitRing(piece, line, &low, &high)) return std::nullopt;
      for (auto& r : high) low.push_back(std::move(r));
      bool ok = low.size() >= 2 && static_cast<int>(pieces.size() - 1 + low.size()) <= cap;
      for (const IRing& part : low) ok = ok && PieceUsable(part, limits);
      if (!ok) return std::nullopt;
      return low;
    };
    auto keep = [&](std::vector<IRing>& parts, double score, int64_t aimed) {
      if (score >= best_score) return;
      best_score = score;
      best_parts = std::move(parts);
      best_aimed = aimed;
    };
    const int angled_candidates = normals.empty() ? 0 : 2;
    for (int c = 0; c < kCandidates + angled_candidates && best_score > (angled_candidates ? -kAngledBonus : 0.0); ++c) {
      if (!normals.empty() && rng.Chance(0.75)) {
        const auto [na, nb] = normals[static_cast<std::size_t>(rng.Int(0, static_cast<int64_t>(normals.size()) - 1))];
        int64_t lo = std::numeric_limits<int64_t>::max(), hi = std::numeric_limits<int64_t>::min();
        for (const IPoint& p : piece) {
          lo = std::min(lo, na * p.x + nb * p.y);
          hi = std::max(hi, na * p.x + nb * p.y);
        }
        const double norm = std::sqrt(static_cast<double>(na * na + nb * nb));
        const int64_t margin = static_cast<int64_t>(std::ceil(static_cast<double>(limits.min_side) * norm - 1e-9));
        if (hi - lo < 2 * margin) continue;
        // Through a vertex of the piece in range (no jog beside the wall), else near the middle; the first
        // of a few whose line crosses every edge at a grid point.
        std::vector<int64_t> ks;
        for (const IPoint& p : piece) {
          const int64_t k = na * p.x + nb * p.y;
          if (k >= lo + margin && k <= hi - margin && rng.Chance(0.6)) ks.push_back(k);
        }
        for (int draw = 0; draw < 3; ++draw)
          ks.push_back((rng.Int(lo + margin, hi - margin) + rng.Int(lo + margin, hi - margin)) / 2);
        const auto k = std::find_if(ks.begin(), ks.end(), [&](int64_t v) { return SplitIsOnGrid(piece, ILine{na, nb, v}); });
        if (k == ks.end()) continue;
        std::optional<std::vector<IRing>> parts = split_by(ILine{na, nb, *k});
        if (!parts) continue;
        // Only where every part stays well proportioned (no wedge or sliver of a room for the angle's sake).
        // A wall that follows the building is worth a little proportion (kAngledBonus): rooms along a slanted
        // side keep its angle instead of a jagged axis-parallel wall beside it.
        double worst = 0.0;
        const double score = (wanted_area2.empty() ? 0.0 : 0.75) - kAngledBonus + PartsPenalty(*parts, limits, &worst);
        if (worst <= kAngledWorst) keep(*parts, score, -1);
        continue;
      }
      const Axis axis = rng.Chance(p_vertical) ? Axis::kX : Axis::kY;
      const int64_t min_end = axis == Axis::kX ? box.min_x : box.min_y;
      const int64_t max_end = axis == Axis::kX ? box.max_x : box.max_y;
      const int64_t lo = min_end + limits.min_side, hi = max_end - limits.min_side;
      if (hi < lo) continue;
      // Near the middle more often than at the ends (average of two uniform draws), or, while rooms of a
      // wanted size are missing, at the offset that cuts one of the two smallest off one end.
      int64_t k = (rng.Int(lo, hi) + rng.Int(lo, hi) + static_cast<int64_t>(rng.Int(0, 1))) / 2;
      int64_t aimed = -1;
      if (!reflex.empty() && rng.Chance(0.5)) {
        const IPoint p = reflex[static_cast<std::size_t>(rng.Int(0, static_cast<int64_t>(reflex.size()) - 1))];
        const int64_t at = axis == Axis::kX ? p.x : p.y;
        if (at >= lo && at <= hi) k = at;
      } else if (!wanted_area2.empty() && rng.Chance(0.75)) {
        const int64_t want =
            wanted_area2[static_cast<std::size_t>(rng.Int(0, std::min<int64_t>(1, static_cast<int64_t>(wanted_area2.size()) - 1)))];
        const int64_t across = axis == Axis::kX ? box.height() : box.width();
        const int64_t offset = std::max<int64_t>(1, (want / 2 + across / 2) / std::max<int64_t>(1, across));
        k = rng.Chance(0.5) ? min_end + offset : max_end - offset;
        k = std::clamp(k, lo, hi);
        aimed = want;
      }
      std::optional<std::vector<IRing>> parts = split_by(AxisLine(axis, k));
      if (!parts) continue;
      double score = PartsPenalty(*parts, limits);
      bool matched = false;
      if (aimed >= 0) {
        // The wanted size is served when some part came within -40 % / +30 % of it.
        for (const IRing& part : *parts) {
          const int64_t a = TwiceArea(part);
          matched |= a * 10 >= aimed * 6 && a * 10 <= aimed * 13;
        }
        if (!matched) score += 1.5;
      } else if (!wanted_area2.empty()) {
        score += 0.75;  // a middle cut while small rooms are still wanted
      }
      keep(*parts, score, matched ? aimed : -1);
    }
    // A small wanted room (a bathroom) carved out of one corner of the piece, the rest an L (a single line
    // would cut a strip as deep as the piece).
    if (!wanted_area2.empty() && best_aimed != wanted_area2.front() && static_cast<int>(pieces.size()) + 1 <= cap) {
      const int64_t want = wanted_area2.front();
      const double side = std::sqrt(static_cast<double>(want) / 2.0) * (0.85 + 0.3 * rng.Unit());
      const int64_t d1 = std::max<int64_t>(limits.min_side, std::llround(side));
      const int64_t d2 = std::max<int64_t>(limits.min_side, (want / 2 + d1 - 1) / d1);
      const bool swap = rng.Chance(0.5);
      const int64_t dx = swap ? d2 : d1, dy = swap ? d1 : d2;
      if (dx <= box.width() - limits.min_side && dy <= box.height() - limits.min_side) {
        // At a corner of the bounding box that is a corner of the piece; the areas adding up below
        // proves the carved box lies inside the piece.
        const int corner = static_cast<int>(rng.Int(0, 3));
        const int64_t x0 = corner & 1 ? box.max_x - dx : box.min_x;
        const int64_t y0 = corner & 2 ? box.max_y - dy : box.min_y;
        const IPoint tip{corner & 1 ? box.max_x : box.min_x, corner & 2 ? box.max_y : box.min_y};
        const IBox cut{x0, y0, x0 + dx, y0 + dy};
        std::vector<IRing> rest;
        if (std::find(piece.begin(), piece.end(), tip) != piece.end() && SubtractBox(piece, cut, &rest) &&
            rest.size() == 1) {
          std::vector<IRing> parts{std::move(rest[0]), BoxRing(cut)};
          if (PieceUsable(parts[0], limits) && PieceUsable(parts[1], limits) &&
              TwiceArea(parts[0]) + TwiceArea(parts[1]) == TwiceArea(piece)) {
            const int64_t a = TwiceArea(parts[1]);
            const bool matched = a * 10 >= want * 6 && a * 10 <= want * 13;
            keep(parts, PartsPenalty(parts, limits) + (matched ? 0.0 : 1.5), matched ? want : -1);
          }
        }
      }
    }
    if (best_parts.empty()) {
      ++failures;
      continue;
    }
    if (best_aimed >= 0) wanted_area2.erase(std::find(wanted_area2.begin(), wanted_area2.end(), best_aimed));
    pieces.erase(pieces.begin() + static_cast<long>(index));
    for (auto& r : best_parts) pieces.push_back(std::move(r));
  }
  return pieces;
}

std::optional<ISegment> PlaceDoor(const ISegment& wall, int64_t width, int64_t clearance, Rng& rng) {
  const int64_t len = Gcd(wall.b.x - wall.a.x, wall.b.y - wall.a.y);  // grid steps along the wall
  if (len == 0 || len < width + 2 * clearance) return std::nullopt;
  const IPoint d{(wall.b.x - wall.a.x) / len, (wall.b.y - wall.a.y) / len};
  const int64_t off = rng.Int(clearance, len - width - clearance);
  const IPoint a{wall.a.x + d.x * off, wall.a.y + d.y * off};
  return ISegment{a, {a.x + d.x * width, a.y + d.y * width}};
}

}  // namespace villa::partition
