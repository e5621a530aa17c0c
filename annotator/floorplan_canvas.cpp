#include "annotator/floorplan_canvas.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "annotator/utf8.h"
#include "layout/geometry.h"

namespace villa::annotator {
namespace {

// Wall neighbour mask bits.
constexpr int kUp = 1, kDown = 2, kLeft = 4, kRight = 8;

const char* BoxGlyph(int mask, bool unicode) {
  if (!unicode) {
    if (mask == (kLeft | kRight) || mask == kLeft || mask == kRight) return "-";
    if (mask == (kUp | kDown) || mask == kUp || mask == kDown) return "|";
    if (mask == 0) return "+";
    return "+";
  }
  switch (mask) {
    case 0: return "·";
    case kLeft: case kRight: case kLeft | kRight: return "─";
    case kUp: case kDown: case kUp | kDown: return "│";
    case kDown | kRight: return "┌";
    case kDown | kLeft: return "┐";
    case kUp | kRight: return "└";
    case kUp | kLeft: return "┘";
    case kUp | kDown | kRight: return "├";
    case kUp | kDown | kLeft: return "┤";
    case kLeft | kRight | kDown: return "┬";
    case kLeft | kRight | kUp: return "┴";
    default: return "┼";
  }
}

}  // namespace

std::string Canvas::Row(int y) const {
  std::string out;
  for (int x = 0; x < width; ++x) out += at(x, y).glyph;
  return out;
}

Canvas DrawFloorPlan(const Layout& layout, int level, const CanvasOptions& o) {
  Canvas canvas;
  canvas.width = std::max(o.width, 1);
  canvas.height = std::max(o.height, 1);
  canvas.cells.assign(static_cast<std::size_t>(canvas.width) * canvas.height, CanvasCell{});
  Box2 b = LayoutBounds(layout);
  if (b.width() <= 0 || b.height() <= 0) return canvas;

  // Scale: rows per metre sy, columns per metre sx = aspect * sy; the plan's corners land on cells.
  double sy = std::min((canvas.height - 1) / b.height(), (canvas.width - 1) / (o.aspect * b.width()));
  double sx = o.aspect * sy;
  // The margins, floored with a little slack: when the plan fills the width exactly, b.width() * sx can
  // come out a hair above width - 1, and a plain floor would push the west wall off the canvas.
  double ox = std::max(0.0, std::floor((canvas.width - 1 - b.width() * sx) / 2 + 1e-6));
  double oy = std::max(0.0, std::floor((canvas.height - 1 - b.height() * sy) / 2 + 1e-6));
  auto col = [&](double x) { return ox + (x - b.min_x) * sx; };
  auto row = [&](double y) { return oy + (b.max_y - y) * sy; };
  auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < canvas.width && y < canvas.height; };

  std::vector<int> rooms = layout.RoomsOnLevel(level);
  bool multi = layout.LevelCount() > 1;

  // Floors: the room under each cell's centre.
  for (int y = 0; y < canvas.height; ++y) {
    for (int x = 0; x < canvas.width; ++x) {
      Point p{b.min_x + (x - ox) / sx, b.max_y - (y - oy) / sy};
      for (int r : rooms) {
        if (!PointInRing(p, layout.rooms[r].polygon, 1e-9)) continue;
        CanvasCell& cell = canvas.at(x, y);
        cell.room = r;
        bool stair = o.show_stairs && multi && layout.rooms[r].category == Category::kUtilityRoom;
        cell.kind = stair ? CellKind::kStair : CellKind::kFloor;
        // Treads on every other row, in a glyph of their own (windows are drawn with ═ and =).
        cell.glyph = stair && y % 2 == 0 ? (o.unicode ? "≡" : "_") : " ";
        break;
      }
    }
  }

  // Walls: every room outline of the level, rasterised onto cells.
  std::vector<int> wall_mask(canvas.cells.size(), -1);  // -1: not a wall
  std::vector<int> slant(canvas.cells.size(), 0);       // +1 '/', -1 '\'
  auto mark = [&](const Segment& s, const std::function<void(int, int, double)>& visit, bool ends) {
    double x0 = col(s.a.x), y0 = row(s.a.y), x1 = col(s.b.x), y1 = row(s.b.y);
    double steps = std::max({std::abs(x1 - x0), std::abs(y1 - y0), 1.0}) * 4;
    for (int k = 0; k <= steps; ++k) {
      double t = k / steps;
      int x = static_cast<int>(std::lround(x0 + (x1 - x0) * t));
      int y = static_cast<int>(std::lround(y0 + (y1 - y0) * t));
      if (!ends) {
        // Keep the wall cells at the element's two ends (the jambs) as walls.
        int xa = static_cast<int>(std::lround(x0)), ya = static_cast<int>(std::lround(y0));
        int xb = static_cast<int>(std::lround(x1)), yb = static_cast<int>(std::lround(y1));
        bool long_enough = std::abs(xb - xa) + std::abs(yb - ya) >= 2;
        if (long_enough && ((x == xa && y == ya) || (x == xb && y == yb))) continue;
      }
      if (inside(x, y)) visit(x, y, t);
    }
  };
  for (int r : rooms) {
    const Ring& ring = layout.rooms[r].polygon;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Segment s{ring[i], ring[(i + 1) % ring.size()]};
      bool axis = std::abs(s.a.x - s.b.x) < 1e-9 || std::abs(s.a.y - s.b.y) < 1e-9;
      // Screen slope: y grows down on screen.
      int dir = 0;
      if (!axis) dir = ((s.b.x - s.a.x) * (s.b.y - s.a.y) > 0) ? 1 : -1;
      mark(s, [&](int x, int y, double) {
        std::size_t at = static_cast<std::size_t>(y) * canvas.width + x;
        wall_mask[at] = 0;
        if (!axis && slant[at] == 0) slant[at] = dir;
        if (axis) slant[at] = 2;  // axis walls win over slants
      }, true);
    }
  }
  for (int y = 0; y < canvas.height; ++y) {
    for (int x = 0; x < canvas.width; ++x) {
      std::size_t at = static_cast<std::size_t>(y) * canvas.width + x;
      if (wall_mask[at] < 0) continue;
      auto wall = [&](int xx, int yy) {
        return inside(xx, yy) && wall_mask[static_cast<std::size_t>(yy) * canvas.width + xx] >= 0;
      };
      int mask = (wall(x, y - 1) ? kUp : 0) | (wall(x, y + 1) ? kDown : 0) | (wall(x - 1, y) ? kLeft : 0) |
                 (wall(x + 1, y) ? kRight : 0);
      CanvasCell& cell = canvas.at(x, y);
      cell.kind = CellKind::kWall;
      cell.room = -1;
      if (slant[at] == 1 || slant[at] == -1)
        cell.glyph = slant[at] == 1 ? (o.unicode ? "╱" : "/") : (o.unicode ? "╲" : "\\");
      else
        cell.glyph = BoxGlyph(mask, o.unicode);
    }
  }

  // Openings over the walls.
  auto overlay = [&](const std::vector<Element>& elements, CellKind kind) {
    for (const Element& e : elements) {
      if (!e.OnLevel(level)) continue;
      bool horizontal = std::abs(col(e.shape.b.x) - col(e.shape.a.x)) >= std::abs(row(e.shape.b.y) - row(e.shape.a.y));
      const char* glyph = " ";
      switch (kind) {
        case CellKind::kDoor: glyph = o.unicode ? "▒" : "#"; break;
        case CellKind::kOpen: glyph = " "; break;
        case CellKind::kWindow: glyph = o.unicode ? (horizontal ? "═" : "║") : (horizontal ? "=" : "H"); break;
        case CellKind::kPanoramic: glyph = o.unicode ? "█" : "%"; break;
        case CellKind::kEntrance: glyph = o.unicode ? "▓" : "E"; break;
        default: break;
      }
      CellKind cell_kind = kind == CellKind::kWindow && e.panoramic ? CellKind::kPanoramic : kind;
      if (cell_kind == CellKind::kPanoramic) glyph = o.unicode ? "█" : "%";
      mark(e.shape, [&](int x, int y, double) {
        CanvasCell& cell = canvas.at(x, y);
        if (cell.kind != CellKind::kWall && cell.kind != CellKind::kWindow && cell.kind != CellKind::kDoor &&
            cell.kind != CellKind::kOpen && cell.kind != CellKind::kPanoramic)
          return;
        cell.kind = cell_kind;
        cell.glyph = glyph;
      }, false);
    }
  };
  overlay(layout.windows, CellKind::kWindow);
  overlay(layout.doors, CellKind::kDoor);
  overlay(layout.opens, CellKind::kOpen);
  if (level == 0) overlay(layout.entrances, CellKind::kEntrance);

  // Labels: centred on the room's cells nearest its centroid, on cells of that room only.
  for (int r : rooms) {
    if (r >= static_cast<int>(o.labels.size())) continue;
    Point c = Centroid(layout.rooms[r].polygon);
    double cx = col(c.x), cy = row(c.y);
    int best_x = -1, best_y = -1;
    double best = std::numeric_limits<double>::max();
    for (int y = 0; y < canvas.height; ++y)
      for (int x = 0; x < canvas.width; ++x) {
        const CanvasCell& cell = canvas.at(x, y);
        if (cell.room != r) continue;
        double d = std::hypot((x - cx) / o.aspect, y - cy);
        if (d < best) {
          best = d;
          best_x = x;
          best_y = y;
        }
      }
    if (best_x < 0) continue;
    for (const std::string& label : o.labels[r]) {
      auto glyphs = Utf8Glyphs(label);
      int n = static_cast<int>(glyphs.size());
      // Try start columns so the label covers best_x, centred first.
      bool placed = false;
      for (int shift = 0; shift < n && !placed; ++shift) {
        for (int sign : {-1, 1}) {
          int start = best_x - n / 2 + sign * shift;
          bool fits = start >= 0 && start + n <= canvas.width;
          for (int k = 0; fits && k < n; ++k) fits = canvas.at(start + k, best_y).room == r;
          if (!fits) continue;
          for (int k = 0; k < n; ++k) {
            canvas.at(start + k, best_y).glyph = glyphs[k];
            canvas.at(start + k, best_y).kind = CellKind::kLabel;
          }
          placed = true;
          break;
        }
      }
      if (placed) break;
    }
  }
  return canvas;
}

}  // namespace villa::annotator
