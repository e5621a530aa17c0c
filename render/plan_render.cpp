// Floor plans: the layout turned into a Scene (scene.h) of pixel-space paths and texts, then written as
// PNG (cairo) or SVG. Everything about how a plan looks lives here: scale and frame, walls, openings,
// stairs, labels, legend, title.
#include "render/plan_render.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include "layout/door_swing.h"
#include "layout/geometry.h"
#include "layout/topology.h"
#include "layout/walls.h"
#include "render/palette.h"
#include "render/plan_geometry.h"
#include "render/scene.h"
#include "util/atomic_file.h"
#include "util/excerpt.h"

namespace villa {
namespace {

// The turn (+pi or -pi) of a leaf opened flat from angle a0 (its leaf) back to its free jamb: the way that
// passes `side` (the leaf side, in the frame of a0) half way.
double FlatTurn(double a0, Point side) {
  return std::cos(a0 + M_PI / 2.0) * side.x + std::sin(a0 + M_PI / 2.0) * side.y >= 0.0 ? M_PI : -M_PI;
}

using plan::Fill;
using plan::LineCap;
using plan::LineJoin;
using plan::PathItem;
using plan::Px;
using plan::Scene;
using plan::Stroke;
using plan::SubPath;
using plan::TextAnchor;
using plan::TextItem;
using plan::TextMeasure;

// Wall thickness drawn, m (centred on the boundary line).
constexpr double kExteriorWall = 0.24;
constexpr double kInteriorWall = 0.12;
// The smallest label, as a share of PlanRenderOptions::font_size_px (8 px at the default 13 px).
constexpr double kMinLabelScale = 0.6;
// Stair tread depth drawn, m.
constexpr double kTread = 0.28;
// How close (m) an element must be to a wall line to count as lying on it (layout.h's policy).
constexpr double kOnWall = kOnWallTolerance;

const Rgb kWallInk{0.16, 0.18, 0.20};
const Rgb kText{0.11, 0.12, 0.14};
const Rgb kMuted{0.40, 0.43, 0.47};
const Rgb kHairline{0.50, 0.52, 0.55};
const Rgb kError = InvalidElementColor();
const Rgb kAccent{0.07, 0.36, 0.66};
const Rgb kWhite{1.0, 1.0, 1.0};
const Rgb kGlass{0.93, 0.97, 1.0};
const Rgb kPanoramicGlass{0.56, 0.80, 0.97};
const Rgb kPanoramicLine{0.05, 0.35, 0.70};
const Rgb kRule{0.85, 0.86, 0.88};
const Rgb kFurnitureLegend{0.62, 0.63, 0.66};

std::string Format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string AreaText(double m2) { return Format("%.1f", m2) + " m\u00b2"; }

std::string LevelTitle(int level) { return level == 0 ? "Ground floor" : "Floor " + std::to_string(level); }

std::string Plural(int n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

bool Finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

Point Add(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
Point Scale(Point a, double f) { return {a.x * f, a.y * f}; }
Point Sub(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }

// ----------------------------------------------------------------------------------------------------
// What each level holds, in plan coordinates.

struct PlacedElement {
  const Element* element = nullptr;
  bool on_wall = true;  // where FORMAT.md rule 3 puts it; drawn in red otherwise
  DoorSwing swing;      // doors and entrances (layout/door_swing.h: the rule the 3D building follows too)
  Point outward;        // entrances: unit direction pointing out of the building
};

struct LevelGeometry {
  int level = 0;
  std::vector<int> rooms;           // indices into Layout::rooms
  std::vector<Segment> exterior;    // footprint boundary: room edges no other room shares
  std::vector<Segment> shared;      // edges shared by two rooms (each stretch listed from both sides,
                                    // neighbours' collinear pieces along one edge merged into one stroke)
  std::vector<PlacedElement> entrances, doors, opens, windows, interiors;
  bool has_stairs = false;
  bool stairs_go_up = false;
};

// Whether an element lies where FORMAT.md rule 3 puts it, decided by the same query the validator uses
// (layout/topology.h): doors, opens and walls on the shared boundary of exactly two rooms; windows and
// the entrance on the boundary of exactly one room, which no other room touches there (the exterior).
std::vector<PlacedElement> Place(const Layout& layout, const std::vector<Element>& elements, int level) {
  std::vector<PlacedElement> placed;
  for (const Element& e : elements) {
    if (!e.OnLevel(level)) continue;
    const SegmentRooms rooms = RoomsAlongSegment(layout, level, e.shape, kOnWall);
    const bool exterior = e.kind == ElementKind::kWindow || e.kind == ElementKind::kEntrance;
    const bool in_place = exterior ? rooms.holding.size() == 1 && rooms.touching.size() == 1 : rooms.holding.size() == 2;
    placed.push_back({&e, in_place, {}, {}});
  }
  return placed;
}

LevelGeometry AnalyseLevel(const Layout& layout, int level, bool multi_story, int top_level) {
  LevelGeometry g;
  g.level = level;
  g.rooms = layout.RoomsOnLevel(level);
  // layout/walls.h's pieces, edge by edge: the shared ones of one edge merged into one stroke.
  const std::vector<WallPiece> pieces = LevelWallPieces(layout, level, kOnWall);
  for (std::size_t i = 0; i < pieces.size();) {
    const WallPiece& first = pieces[i];
    const Ring& ring = layout.rooms[first.room].polygon;
    const Segment edge{ring[first.edge], ring[(first.edge + 1) % ring.size()]};
    std::vector<Interval> shared;
    for (; i < pieces.size() && pieces[i].room == first.room && pieces[i].edge == first.edge; ++i) {
      if (pieces[i].exterior()) g.exterior.push_back(pieces[i].segment);
      else shared.push_back(pieces[i].along);
    }
    for (const Interval& stretch : MergeIntervals(shared, kOnWall)) g.shared.push_back(SubSegment(edge, stretch));
  }
  for (int r : g.rooms)
    if (multi_story && layout.rooms[r].category == Category::kUtilityRoom) g.has_stairs = true;
  g.stairs_go_up = level < top_level;
  g.entrances = Place(layout, layout.entrances, level);
  g.windows = Place(layout, layout.windows, level);
  g.doors = Place(layout, layout.doors, level);
  g.opens = Place(layout, layout.opens, level);
  g.interiors = Place(layout, layout.interiors, level);

  for (PlacedElement& door : g.doors) door.swing = SwingOfDoor(layout, *door.element, level);
  for (PlacedElement& entrance : g.entrances) {
    entrance.swing = SwingOfDoor(layout, *entrance.element, level);
    entrance.outward = {-entrance.swing.leaf_side.x, -entrance.swing.leaf_side.y};
  }
  return g;
}

// ----------------------------------------------------------------------------------------------------
// Sizes and places in the picture.

struct Fonts {
  double label, area, heading, title, legend, small;
};

Fonts MakeFonts(double base) {
  return {base, base * 0.9, base * 1.2, base * 1.5, base * 0.95, base * 0.85};
}

enum class Side { kLeft, kRight, kTop, kBottom };

// The entrance arrow, in pixel terms relative to the plan.
struct ArrowSpec {
  double length = 0.0;    // px
  double label_gap = 5.0; // px between arrow tail and the word
};

struct LegendEntry {
  enum Kind {
    kCategory, kExterior, kInterior, kDoor, kOpen, kWindow, kPanoramic, kEntrance, kStairs, kNoWall, kOffWall,
    kFurniture, kPath, kGroupTitle,
  } kind;
  Category category = Category::kRoom;
  std::string text;
  double width = 0.0;  // px, icon + text
};

struct LegendLayout {
  struct Placed {
    LegendEntry entry;
    double x = 0.0, y = 0.0;  // px, top-left of the entry's row cell (relative to the legend block)
  };
  std::vector<Placed> entries;
  double width = 0.0;
  double height = 0.0;
};

constexpr double kIconWidth = 30.0;
constexpr double kIconGap = 7.0;
constexpr double kEntryGap = 20.0;

LegendLayout PlaceLegend(const std::vector<std::vector<LegendEntry>>& groups, double max_width, double row_height) {
  LegendLayout out;
  double y = 0.0;
  for (const auto& group : groups) {
    if (group.empty()) continue;
    double x = 0.0;
    // Continuation rows start under the group's first entry, right of its title.
    double indent = 0.0;
    for (const LegendEntry& entry : group) {
      if (x > indent && x + entry.width > max_width) {
        x = indent;
        y += row_height;
      }
      if (entry.kind == LegendEntry::kGroupTitle && x == 0.0 && entry.width + kEntryGap < max_width / 3.0) {
        indent = entry.width + kEntryGap;
      }
      out.entries.push_back({entry, x, y});
      x += entry.width + kEntryGap;
      out.width = std::max(out.width, x - kEntryGap);
    }
    y += row_height;
  }
  out.height = y;
  return out;
}

// Everything about where things go, computed before any drawing.
struct Frame {
  PlanFrame pub;
  double s = 40.0;  // px per m
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;  // plan bounding box, m
  double pad[4] = {0, 0, 0, 0};  // px around the plan inside a panel, by Side
  double heading_height = 0.0;
  double panel_width = 0.0, panel_height = 0.0;
  double panels_left = 0.0, panels_top = 0.0;
  double title_baseline = 0.0;
  double rule_y = 0.0;
  double bottom_top = 0.0;  // top of the scale bar / legend band
  bool legend_beside_scale = true;
  double scale_bar_m = 1.0;
  int scale_bar_divisions = 2;
  double scale_block_width = 0.0;
  LegendLayout legend;
  double legend_left = 0.0, legend_top = 0.0;
  ArrowSpec arrow;
  std::string title_bold, title_rest;
  double title_bold_width = 0.0;
};

struct Content {
  const Layout* layout = nullptr;
  const PlanOverlay* overlay = nullptr;  // may be null
  std::vector<int> levels;
  std::vector<LevelGeometry> geometry;  // by position in `levels`
  std::string title_bold, title_rest;
  std::vector<std::vector<LegendEntry>> legend_groups;
};

// Every point finite and inside the building extent (layout.h): the reader refuses anything else, and a
// layout made in code gets the same answer here, before a scale or a label is computed from it.
Status CheckExtent(const Layout& layout) {
  for (const Room& room : layout.rooms) {
    for (const Point& p : room.polygon) {
      if (!Finite(p)) return Error{"rooms[\"" + room.name() + "\"].shape: a coordinate is not a finite number"};
      if (std::string problem = PointExtentProblem(p); !problem.empty()) return Error{"rooms[\"" + room.name() + "\"].shape: " + problem};
    }
  }
  for (ElementKind kind : kAllElementKinds) {
    for (const Element& e : layout.elements(kind)) {
      const std::string where = std::string(ElementKindKey(kind)) + "[\"" + Excerpt(e.name) + "\"].shape: ";
      if (!Finite(e.shape.a) || !Finite(e.shape.b)) return Error{where + "a coordinate is not a finite number"};
      if (std::string problem = SegmentExtentProblem(e.shape); !problem.empty()) return Error{where + problem};
    }
  }
  return Status::Ok();
}

Result<Content> Analyse(const Layout& layout, const PlanOverlay* overlay, const PlanRenderOptions& options,
                        const TextMeasure& measure) {
  if (Status extent = CheckExtent(layout); !extent.ok()) return Error{extent.error()};
  Content c;
  c.layout = &layout;
  c.overlay = overlay;
  int level_count = layout.LevelCount();
  for (ElementKind kind : kAllElementKinds) {
    for (const Element& e : layout.elements(kind)) level_count = std::max(level_count, e.level + 1);
  }
  level_count = std::max(level_count, 1);
  if (options.levels.empty()) {
    for (int l = 0; l < level_count; ++l) c.levels.push_back(l);
  } else {
    for (int l : options.levels) {
      if (l < 0 || l >= level_count) {
        return Error{"level " + std::to_string(l) + " is not in the layout (levels 0.." + std::to_string(level_count - 1) + ")"};
      }
      c.levels.push_back(l);
    }
  }
  const bool multi_story = layout.LevelCount() > 1;
  for (int l : c.levels) c.geometry.push_back(AnalyseLevel(layout, l, multi_story, layout.LevelCount() - 1));

  // Title.
  int rooms = 0;
  double area = 0.0;
  std::set<Category> categories;
  for (const LevelGeometry& g : c.geometry) {
    for (int r : g.rooms) {
      ++rooms;
      area += Area(layout.rooms[r].polygon);
      categories.insert(layout.rooms[r].category);
    }
  }
  const int floors = static_cast<int>(c.levels.size());
  std::string stats = Plural(floors, "floor", "floors") + "  \u00b7  " + Plural(rooms, "room", "rooms") + "  \u00b7  " +
                      AreaText(area);
  if (!options.title.empty()) {
    c.title_bold = options.title;
  } else {
    c.title_bold = options.source_name.empty() ? "Floor plan" : options.source_name;
    c.title_rest = stats;
  }

  // Legend: categories present, then the symbols drawn.
  const Fonts fonts = MakeFonts(options.font_size_px);
  auto entry = [&](LegendEntry::Kind kind, std::string text, Category category = Category::kRoom) {
    LegendEntry e{kind, category, std::move(text), 0.0};
    const bool title = kind == LegendEntry::kGroupTitle;
    e.width = (title ? 0.0 : kIconWidth + kIconGap) + measure.Width(e.text, fonts.legend, title);
    return e;
  };
  std::vector<LegendEntry> rooms_group{entry(LegendEntry::kGroupTitle, "Rooms")};
  auto add_category = [&](Category cat) {
    if (categories.count(cat)) rooms_group.push_back(entry(LegendEntry::kCategory, std::string(CategoryDisplayName(cat)), cat));
  };
  for (Category cat : LabelledCategories()) add_category(cat);
  add_category(Category::kRoom);

  bool any[LegendEntry::kGroupTitle] = {};
  for (const LevelGeometry& g : c.geometry) {
    if (!g.exterior.empty()) any[LegendEntry::kExterior] = true;
    if (!g.interiors.empty()) any[LegendEntry::kInterior] = true;
    if (!g.doors.empty()) any[LegendEntry::kDoor] = true;
    if (!g.opens.empty()) any[LegendEntry::kOpen] = true;
    if (!g.entrances.empty()) any[LegendEntry::kEntrance] = true;
    if (g.has_stairs) any[LegendEntry::kStairs] = true;
    for (const PlacedElement& w : g.windows) any[w.element->panoramic ? LegendEntry::kPanoramic : LegendEntry::kWindow] = true;
    for (const auto* list : {&g.entrances, &g.doors, &g.opens, &g.windows, &g.interiors}) {
      for (const PlacedElement& p : *list) {
        if (!p.on_wall) any[LegendEntry::kOffWall] = true;
      }
    }
  }
  std::vector<LegendEntry> symbols{entry(LegendEntry::kGroupTitle, "Symbols")};
  const std::pair<LegendEntry::Kind, const char*> symbol_texts[] = {
      {LegendEntry::kExterior, "Exterior wall"}, {LegendEntry::kInterior, "Interior wall"},
      {LegendEntry::kDoor, "Door"},              {LegendEntry::kOpen, "Open passage"},
      {LegendEntry::kWindow, "Window"},          {LegendEntry::kPanoramic, "Panoramic window"},
      {LegendEntry::kEntrance, "Entrance"},      {LegendEntry::kStairs, "Staircase"},
      {LegendEntry::kNoWall, "Shared edge without wall"},
      {LegendEntry::kOffWall, "Not on a wall (invalid)"},
      {LegendEntry::kFurniture, "Furniture"},    {LegendEntry::kPath, "Walking path"},
  };
  if (overlay) {
    any[LegendEntry::kFurniture] = !overlay->shapes.empty();
    any[LegendEntry::kPath] = !overlay->paths.empty();
  }
  // A shared edge without an interior wall (nor a door or open cut into it) gets a hairline.
  for (const LevelGeometry& g : c.geometry) {
    std::vector<Segment> walls;
    for (const auto* list : {&g.interiors, &g.doors, &g.opens}) {
      for (const PlacedElement& p : *list) walls.push_back(p.element->shape);
    }
    for (const Segment& s : g.shared) {
      if (!SegmentsCover(walls, s, kOnWall)) any[LegendEntry::kNoWall] = true;
    }
  }
  for (const auto& [kind, text] : symbol_texts) {
    if (any[kind]) symbols.push_back(entry(kind, text));
  }
  if (rooms_group.size() > 1) c.legend_groups.push_back(rooms_group);
  if (symbols.size() > 1) c.legend_groups.push_back(symbols);
  return c;
}

void ScaleBarFor(double s, double* metres, int* divisions) {
  const std::pair<double, int> choices[] = {{0.5, 1}, {1, 2}, {2, 2}, {5, 5}, {10, 5}, {20, 4}, {50, 5}, {100, 5}, {200, 4}, {500, 5}};
  *metres = choices[0].first;
  *divisions = choices[0].second;
  for (const auto& [m, d] : choices) {
    if (m * s <= 210.0) {
      *metres = m;
      *divisions = d;
    }
  }
}

Result<Frame> MakeFrame(const Content& c, const PlanRenderOptions& options, const TextMeasure& measure) {
  const Layout& layout = *c.layout;
  const Fonts fonts = MakeFonts(options.font_size_px);
  Frame f;
  // Bounding box of what is drawn on the chosen levels: rooms and every element.
  bool any = false;
  auto grow = [&](Point p) {
    if (!any) {
      f.min_x = f.max_x = p.x;
      f.min_y = f.max_y = p.y;
      any = true;
    }
    f.min_x = std::min(f.min_x, p.x);
    f.max_x = std::max(f.max_x, p.x);
    f.min_y = std::min(f.min_y, p.y);
    f.max_y = std::max(f.max_y, p.y);
  };
  for (const LevelGeometry& g : c.geometry) {
    for (int r : g.rooms) {
      for (const Point& p : layout.rooms[r].polygon) grow(p);
    }
    for (const auto* list : {&g.entrances, &g.doors, &g.opens, &g.windows, &g.interiors}) {
      for (const PlacedElement& p : *list) {
        grow(p.element->shape.a);
        grow(p.element->shape.b);
      }
    }
    // Door leaves and swing arcs (they stay inside rooms, except where a door hangs in the air).
    for (const auto* list : {&g.entrances, &g.doors}) {
      for (const PlacedElement& p : *list) {
        const DoorSwing& w = p.swing;
        const double radius = Distance(w.hinge, w.free_end);
        const Point bisector = Add(Sub(w.leaf_end, w.hinge), Sub(w.free_end, w.hinge));
        const double length = std::hypot(bisector.x, bisector.y);
        grow(w.leaf_end);
        if (length > 0.0) grow(Add(w.hinge, Scale(bisector, radius / length)));
        if (w.flat) grow(Add(w.hinge, Scale(w.leaf_side, radius)));  // the top of its half circle
      }
    }
  }
  if (!any) {
    f.max_x = f.max_y = 10.0;  // nothing to draw: an empty 10 x 10 m panel
  }
  if (f.max_x - f.min_x < 1.0) {
    f.min_x -= 0.5;
    f.max_x += 0.5;
  }
  if (f.max_y - f.min_y < 1.0) {
    f.min_y -= 0.5;
    f.max_y += 0.5;
  }
  const double plan_w = f.max_x - f.min_x;
  const double plan_h = f.max_y - f.min_y;
  const int n = static_cast<int>(c.levels.size());

  f.arrow.length = std::max(34.0, 3.0 * options.font_size_px);
  const double entrance_word = measure.Width("Entrance", fonts.small, true);
  const double small_cap = measure.CapHeight(fonts.small);

  // Padding around a plan: half an exterior wall, a little air, and room for the entrance arrow.
  auto compute_pads = [&](double s) {
    for (double& p : f.pad) p = kExteriorWall * s / 2.0 + 14.0;
    for (const LevelGeometry& g : c.geometry) {
      for (const PlacedElement& e : g.entrances) {
        const Point* out = &e.outward;
        const Point mid{(e.element->shape.a.x + e.element->shape.b.x) / 2.0, (e.element->shape.a.y + e.element->shape.b.y) / 2.0};
        const double wall = kExteriorWall * s / 2.0;
        const double reach = wall + f.arrow.length + f.arrow.label_gap + 6.0;
        // Pixel offsets of the tail from the plan's box edges.
        const double left = (mid.x - f.min_x) * s, right = (f.max_x - mid.x) * s;
        const double top = (f.max_y - mid.y) * s, bottom = (mid.y - f.min_y) * s;
        if (std::abs(out->x) >= std::abs(out->y)) {
          const Side side = out->x < 0 ? Side::kLeft : Side::kRight;
          const double need = reach + entrance_word - (side == Side::kLeft ? left : right);
          f.pad[int(side)] = std::max(f.pad[int(side)], need);
        } else {
          const Side side = out->y > 0 ? Side::kTop : Side::kBottom;
          const double need = reach + small_cap - (side == Side::kTop ? top : bottom);
          f.pad[int(side)] = std::max(f.pad[int(side)], need);
          // The word is centred on the tail: keep it inside the panel sideways.
          f.pad[int(Side::kLeft)] = std::max(f.pad[int(Side::kLeft)], entrance_word / 2.0 + 4.0 - left);
          f.pad[int(Side::kRight)] = std::max(f.pad[int(Side::kRight)], entrance_word / 2.0 + 4.0 - right);
        }
      }
    }
  };

  f.heading_height = fonts.heading * 2.1;
  const double title_gap = fonts.title * 1.1;
  f.title_bold = c.title_bold;
  f.title_rest = c.title_rest;
  f.title_bold_width = measure.Width(c.title_bold, fonts.title, true);
  const double title_width = f.title_bold_width + (c.title_rest.empty() ? 0.0 : fonts.title * 0.8 + measure.Width(c.title_rest, fonts.title * 0.8, false));
  const double row_height = std::max(20.0, fonts.legend * 1.9);

  double s = options.pixels_per_metre;
  if (options.target_width_px > 0) {
    // Solve for the scale that fills the width; the pads depend a little on the scale, so iterate.
    s = 40.0;
    for (int i = 0; i < 4; ++i) {
      compute_pads(s);
      const double fixed = 2.0 * options.margin_px + (n - 1) * options.panel_gap_px +
                           n * (f.pad[int(Side::kLeft)] + f.pad[int(Side::kRight)] - kExteriorWall * s);
      s = (options.target_width_px - fixed) / (n * (plan_w + kExteriorWall)) * 0.998;
      if (s < 1.0) s = 1.0;
    }
  }

  for (int attempt = 0; attempt < 8; ++attempt) {
    compute_pads(s);
    f.s = s;
    f.panel_width = plan_w * s + f.pad[int(Side::kLeft)] + f.pad[int(Side::kRight)];
    f.panel_height = f.heading_height + plan_h * s + f.pad[int(Side::kTop)] + f.pad[int(Side::kBottom)];
    const double panels_width = n * f.panel_width + (n - 1) * options.panel_gap_px;
    ScaleBarFor(s, &f.scale_bar_m, &f.scale_bar_divisions);
    f.scale_block_width = f.scale_bar_m * s + measure.Width(" m", fonts.small, false) + 24.0;

    double inner = std::max({panels_width, title_width, 480.0});
    if (options.target_width_px > 0) inner = std::max(inner, options.target_width_px - 2.0 * options.margin_px);
    double width = inner + 2.0 * options.margin_px;

    f.title_baseline = options.margin_px + measure.CapHeight(fonts.title);
    f.panels_top = f.title_baseline + title_gap;
    f.panels_left = options.margin_px;
    double bottom = f.panels_top + f.panel_height;
    if (options.legend) {
      f.rule_y = bottom + 8.0;
      f.bottom_top = f.rule_y + 16.0;
      const double beside = inner - f.scale_block_width - 28.0;
      f.legend_beside_scale = beside >= 360.0;
      const double legend_width = f.legend_beside_scale ? beside : inner;
      f.legend = PlaceLegend(c.legend_groups, legend_width, row_height);
      f.legend_left = options.margin_px + (f.legend_beside_scale ? f.scale_block_width + 28.0 : 0.0);
      f.legend_top = f.bottom_top + (f.legend_beside_scale ? 0.0 : 44.0);
      bottom = std::max(f.bottom_top + 40.0, f.legend_top + f.legend.height);
    }
    const double height = bottom + options.margin_px;

    const double largest = std::max(width, height);
    if (largest > options.max_side_px && attempt < 7) {
      s *= (options.max_side_px - 1.0) / largest * 0.97;
      continue;
    }
    if (largest > options.max_side_px) {
      return Error{"the plan does not fit in " + std::to_string(options.max_side_px) + " px at any usable scale (" +
                   Format("%.1f", plan_w) + " x " + Format("%.1f", plan_h) + " m)"};
    }
    f.pub.width_px = static_cast<int>(std::ceil(width));
    f.pub.height_px = static_cast<int>(std::ceil(height));
    break;
  }
  f.pub.pixels_per_metre = f.s;
  f.pub.min_x = f.min_x;
  f.pub.max_y = f.max_y;
  for (int i = 0; i < n; ++i) {
    PlanFrame::Panel panel;
    panel.level = c.levels[i];
    panel.plan_left_px = f.panels_left + i * (f.panel_width + options.panel_gap_px) + f.pad[int(Side::kLeft)];
    panel.plan_top_px = f.panels_top + f.heading_height + f.pad[int(Side::kTop)];
    f.pub.panels.push_back(panel);
  }
  return f;
}

// ----------------------------------------------------------------------------------------------------
// Drawing.

class Painter {
 public:
  Painter(Scene& scene) : scene_(scene) {}

  void Path(std::vector<SubPath> subpaths, std::optional<Fill> fill, std::optional<Stroke> stroke) {
    scene_.items.push_back(PathItem{std::move(subpaths), fill, std::move(stroke)});
  }
  void Line(Px a, Px b, Stroke stroke) { Path({SubPath{{a, b}, false}}, std::nullopt, std::move(stroke)); }
  void Polygon(std::vector<Px> points, std::optional<Fill> fill, std::optional<Stroke> stroke) {
    Path({SubPath{std::move(points), true}}, fill, std::move(stroke));
  }
  void Text(std::string text, Px at, double size, bool bold, Rgb color, TextAnchor anchor = TextAnchor::kStart,
            double angle = 0.0) {
    scene_.items.push_back(TextItem{std::move(text), at, size, bold, color, anchor, angle});
  }
  void Begin(std::string id, std::string title = {}) { scene_.items.push_back(plan::GroupBegin{std::move(id), std::move(title)}); }
  void End() { scene_.items.push_back(plan::GroupEnd{}); }

 private:
  Scene& scene_;
};

Stroke Pen(Rgb color, double width, LineCap cap = LineCap::kButt, std::vector<double> dash = {}) {
  Stroke s;
  s.color = color;
  s.width = width;
  s.cap = cap;
  s.dash = std::move(dash);
  return s;
}

// Points of a circular arc from angle a0 to a1 (radians, screen orientation), flattened.
std::vector<Px> Arc(Px centre, double radius, double a0, double a1) {
  const int steps = std::clamp(static_cast<int>(std::ceil(std::abs(a1 - a0) * radius / 2.0)), 6, 256);
  std::vector<Px> points;
  for (int i = 0; i <= steps; ++i) {
    const double a = a0 + (a1 - a0) * i / steps;
    points.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
  }
  return points;
}

std::vector<Px> RoundedRect(double x0, double y0, double x1, double y1, double radius) {
  std::vector<Px> points;
  radius = std::min({radius, (x1 - x0) / 2.0, (y1 - y0) / 2.0});
  auto corner = [&](double cx, double cy, double a0) {
    const auto arc = Arc({cx, cy}, radius, a0, a0 + M_PI / 2.0);
    points.insert(points.end(), arc.begin(), arc.end());
  };
  corner(x1 - radius, y1 - radius, 0.0);
  corner(x0 + radius, y1 - radius, M_PI / 2.0);
  corner(x0 + radius, y0 + radius, M_PI);
  corner(x1 - radius, y0 + radius, 3.0 * M_PI / 2.0);
  return points;
}

Px Offset(Px p, Px dir, double d) { return {p.x + dir.x * d, p.y + dir.y * d}; }
double Dist(Px a, Px b) { return std::hypot(a.x - b.x, a.y - b.y); }

void Arrowhead(Painter& paint, Px tip, Px dir, double length, double width, Rgb color) {
  const Px n{-dir.y, dir.x};
  const Px back = Offset(tip, dir, -length);
  paint.Polygon({tip, Offset(back, n, width / 2.0), Offset(back, n, -width / 2.0)}, Fill{color}, std::nullopt);
}

class PlanPainter {
 public:
  PlanPainter(const Content& content, const Frame& frame, const PlanRenderOptions& options, const TextMeasure& measure,
              Scene& scene)
      : c_(content), f_(frame), options_(options), measure_(measure), fonts_(MakeFonts(options.font_size_px)),
        paint_(scene) {}

  void Draw() {
    DrawTitle();
    for (size_t i = 0; i < c_.levels.size(); ++i) DrawLevel(i);
    if (options_.legend) DrawLegendBand();
  }

 private:
  double s() const { return f_.s; }
  double ExteriorPx() const { return std::max(3.0, kExteriorWall * s()); }
  double InteriorPx() const { return std::max(1.6, kInteriorWall * s()); }

  Px ToPx(Point p) const {
    return {panel_left_ + (p.x - f_.min_x) * s(), panel_top_ + (f_.max_y - p.y) * s()};
  }
  std::vector<Px> ToPx(const std::vector<Point>& points) const {
    std::vector<Px> out;
    out.reserve(points.size());
    for (const Point& p : points) out.push_back(ToPx(p));
    return out;
  }

  const Layout& layout() const { return *c_.layout; }

  void DrawTitle() {
    const double x = options_.margin_px;
    paint_.Text(f_.title_bold, {x, f_.title_baseline}, fonts_.title, true, kText);
    if (!f_.title_rest.empty()) {
      paint_.Text(f_.title_rest, {x + f_.title_bold_width + fonts_.title * 0.8, f_.title_baseline}, fonts_.title * 0.8,
                  false, kMuted);
    }
  }

  void DrawLevel(size_t index) {
    const LevelGeometry& g = c_.geometry[index];
    const PlanFrame::Panel& panel = f_.pub.panels[index];
    panel_left_ = panel.plan_left_px;
    panel_top_ = panel.plan_top_px;
    const double panel_x = f_.panels_left + index * (f_.panel_width + options_.panel_gap_px);

    paint_.Begin("level-" + std::to_string(g.level), LevelTitle(g.level));
    // Heading: "Ground floor   5 rooms · 112.0 m²".
    double area = 0.0;
    for (int r : g.rooms) area += Area(layout().rooms[r].polygon);
    const double heading_baseline = f_.panels_top + measure_.CapHeight(fonts_.heading);
    const std::string heading = LevelTitle(g.level);
    paint_.Text(heading, {panel_x, heading_baseline}, fonts_.heading, true, kText);
    paint_.Text(Plural(static_cast<int>(g.rooms.size()), "room", "rooms") + "  \u00b7  " + AreaText(area),
                {panel_x + measure_.Width(heading, fonts_.heading, true) + fonts_.heading * 0.7, heading_baseline},
                fonts_.small, false, kMuted);

    for (int r : g.rooms) DrawRoom(g, r);
    if (c_.overlay) DrawShapes(g.level);
    DrawWalls(g);
    for (const PlacedElement& e : g.opens) DrawOpen(e);
    for (const PlacedElement& e : g.windows) DrawWindow(g, e);
    for (const PlacedElement& e : g.doors) DrawDoor(e, false);
    for (const PlacedElement& e : g.entrances) DrawDoor(e, true);
    if (c_.overlay) DrawPaths(g.level);
    placed_.clear();
    for (int r : g.rooms) DrawLabel(g, r);
    paint_.End();
  }

  // -- overlay: furniture footprints and walking paths --------------------------------------------

  void DrawShapes(int level) {
    paint_.Begin("furniture-" + std::to_string(level), "Furniture");
    const double ink = std::clamp(0.02 * s(), 0.6, 1.4);
    for (const PlanOverlay::Shape& shape : c_.overlay->shapes) {
      if (shape.level != level || shape.outline.size() < 3) continue;
      Fill fill{shape.fill, shape.fill_alpha};
      paint_.Polygon(ToPx(shape.outline), fill, Pen(shape.ink, ink));
    }
    paint_.End();
  }

  void DrawPaths(int level) {
    paint_.Begin("paths-" + std::to_string(level), "Walking paths");
    for (const PlanOverlay::Path& path : c_.overlay->paths) {
      if (path.level != level || path.points.size() < 2) continue;
      Stroke pen = Pen(path.color, path.width_px, LineCap::kRound);
      pen.join = LineJoin::kRound;
      paint_.Path({SubPath{ToPx(path.points), false}}, std::nullopt, pen);
    }
    paint_.End();
  }

  // -- rooms -------------------------------------------------------------------------------------

  void DrawRoom(const LevelGeometry& g, int r) {
    const Room& room = layout().rooms[r];
    std::string id = "room-" + room.name();
    std::replace(id.begin(), id.end(), '/', '-');
    paint_.Begin(id, room.name());
    if (room.polygon.size() >= 3) paint_.Polygon(ToPx(room.polygon), Fill{CategoryColor(room.category)}, std::nullopt);
    if (g.has_stairs && room.category == Category::kUtilityRoom && room.polygon.size() >= 3) DrawStairs(g, room.polygon);
    paint_.End();
  }

  void DrawStairs(const LevelGeometry& g, const Ring& ring) {
    double min_x = ring[0].x, max_x = ring[0].x, min_y = ring[0].y, max_y = ring[0].y;
    for (const Point& p : ring) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
    const bool along_x = (max_x - min_x) > (max_y - min_y) + kTolerance;
    const double run_from = along_x ? min_x : min_y;
    const double run_to = along_x ? max_x : max_y;
    const Stroke tread = Pen({0.42, 0.43, 0.45}, std::max(0.8, 0.025 * s()));
    std::vector<SubPath> treads;
    // Real treads; a room far too large for a staircase (an invalid layout) gets at most 100 lines.
    const double step = std::max(kTread, (run_to - run_from) / 100.0);
    for (double t = run_from + step; t < run_to - step * 0.5; t += step) {
      const Point a = along_x ? Point{t, min_y - 1.0} : Point{min_x - 1.0, t};
      const Point b = along_x ? Point{t, max_y + 1.0} : Point{max_x + 1.0, t};
      for (const Segment& piece : plan::ClipSegmentToRing(a, b, ring)) {
        treads.push_back(SubPath{{ToPx(piece.a), ToPx(piece.b)}, false});
      }
    }
    if (!treads.empty()) paint_.Path(std::move(treads), std::nullopt, tread);
    if (!g.stairs_go_up) return;
    // The walking line: a dot where the flight starts, an arrow pointing up the flight.
    const double across = along_x ? (min_y + max_y) / 2.0 : (min_x + max_x) / 2.0;
    const double start = run_from + 0.35, end = run_to - 0.3;
    if (end - start < 0.5) return;
    const Point a = along_x ? Point{start, across} : Point{across, start};
    const Point b = along_x ? Point{end, across} : Point{across, end};
    const Px pa = ToPx(a), pb = ToPx(b);
    const double length = Dist(pa, pb);
    const Px dir{(pb.x - pa.x) / length, (pb.y - pa.y) / length};
    const double head = std::max(7.0, 0.22 * s());
    paint_.Line(pa, Offset(pb, dir, -head * 0.6), Pen(kWallInk, 1.3));
    paint_.Polygon(Arc(pa, std::max(2.2, 0.06 * s()), 0.0, 2.0 * M_PI), Fill{kWallInk}, std::nullopt);
    Arrowhead(paint_, pb, dir, head, head * 0.75, kWallInk);
  }

  // -- walls -------------------------------------------------------------------------------------

  std::vector<Segment> Openings(const LevelGeometry& g) const {
    std::vector<Segment> openings;
    for (const auto* list : {&g.entrances, &g.doors, &g.opens, &g.windows}) {
      for (const PlacedElement& p : *list) openings.push_back(p.element->shape);
    }
    return openings;
  }

  static std::vector<Segment> Minus(const std::vector<Segment>& segments, const std::vector<Segment>& cuts) {
    std::vector<Segment> out;
    for (const Segment& s : segments) {
      const auto covered = IntervalsOnSegments(s, cuts, kOnWall);
      for (const Interval& keep : ComplementIntervals(covered, Length(s), kOnWall)) out.push_back(SubSegment(s, keep));
    }
    return out;
  }

  // Strokes wall pieces joined into polylines (mitred corners). A chain end at an opening stops flush
  // (the opening's jamb); any other end is extended by half the wall so corners and T-junctions close.
  void StrokeWalls(const std::vector<Segment>& pieces, const std::vector<Segment>& openings, double width, Rgb color) {
    std::vector<SubPath> paths;
    for (plan::Polyline& chain : plan::ChainSegments(pieces, 1e-6)) {
      std::vector<Px> points = ToPx(chain.points);
      if (!chain.closed && points.size() >= 2) {
        auto at_opening = [&](const Point& p) {
          for (const Segment& o : openings) {
            if (Distance(p, o.a) < 1e-4 || Distance(p, o.b) < 1e-4) return true;
          }
          return false;
        };
        auto extend = [&](Px& end, const Px& inner) {
          const double length = Dist(end, inner);
          if (length <= 0.0) return;
          end = Offset(end, {(end.x - inner.x) / length, (end.y - inner.y) / length}, width / 2.0);
        };
        if (!at_opening(chain.points.front())) extend(points.front(), points[1]);
        if (!at_opening(chain.points.back())) extend(points.back(), points[points.size() - 2]);
      }
      paths.push_back(SubPath{std::move(points), chain.closed});
    }
    if (paths.empty()) return;
    Stroke pen = Pen(color, width);
    pen.join = LineJoin::kMiter;
    paint_.Path(std::move(paths), std::nullopt, pen);
  }

  void DrawWalls(const LevelGeometry& g) {
    const std::vector<Segment> openings = Openings(g);
    // Shared edges with no interior wall (nor a door or open in them): a hairline, so rooms stay apart.
    std::vector<Segment> walled;
    for (const auto* list : {&g.interiors, &g.doors, &g.opens}) {
      for (const PlacedElement& p : *list) walled.push_back(p.element->shape);
    }
    std::vector<SubPath> hairlines;
    for (const Segment& piece : Minus(g.shared, walled)) hairlines.push_back(SubPath{{ToPx(piece.a), ToPx(piece.b)}, false});
    if (!hairlines.empty()) paint_.Path(std::move(hairlines), std::nullopt, Pen(kHairline, 1.3, LineCap::kButt, {3.0, 2.5}));

    std::vector<Segment> good, bad;
    for (const PlacedElement& p : g.interiors) (p.on_wall ? good : bad).push_back(p.element->shape);
    StrokeWalls(Minus(good, openings), openings, InteriorPx(), kWallInk);
    StrokeWalls(Minus(bad, openings), openings, InteriorPx(), kError);
    StrokeWalls(Minus(g.exterior, openings), openings, ExteriorPx(), kWallInk);
  }

  // -- openings ----------------------------------------------------------------------------------

  // Wall thickness at an element, px: exterior where it lies on the footprint boundary.
  double WallAt(const LevelGeometry& g, const Segment& s) const {
    return SegmentsCover(g.exterior, s, kOnWall) ? ExteriorPx() : InteriorPx();
  }

  void DrawOpen(const PlacedElement& e) {
    const Px a = ToPx(e.element->shape.a), b = ToPx(e.element->shape.b);
    const Rgb color = e.on_wall ? kMuted : kError;
    paint_.Line(a, b, Pen(color, e.on_wall ? 1.4 : 2.2, LineCap::kButt, {5.0, 3.5}));
  }

  void DrawWindow(const LevelGeometry& g, const PlacedElement& e) {
    const Px a = ToPx(e.element->shape.a), b = ToPx(e.element->shape.b);
    const double length = Dist(a, b);
    if (length <= 0.0) return;
    const Px u{(b.x - a.x) / length, (b.y - a.y) / length};
    const Px n{-u.y, u.x};
    const double half = std::max(WallAt(g, e.element->shape), 4.0) / 2.0;
    const bool panoramic = e.element->panoramic;
    const Rgb ink = e.on_wall ? kWallInk : kError;
    paint_.Polygon({Offset(a, n, half), Offset(b, n, half), Offset(b, n, -half), Offset(a, n, -half)},
                   Fill{panoramic ? kPanoramicGlass : kGlass}, Pen(ink, 1.0));
    const double glass = half * (panoramic ? 0.55 : 0.38);
    paint_.Line(Offset(a, n, glass), Offset(b, n, glass), Pen(ink, 1.0));
    paint_.Line(Offset(a, n, -glass), Offset(b, n, -glass), Pen(ink, 1.0));
    if (panoramic) paint_.Line(a, b, Pen(e.on_wall ? kPanoramicLine : kError, 1.6));
  }

  // A door leaf standing open at 90 degrees with its quarter swing arc (180 degrees flat against the wall
  // with a half circle, where the rule opens it so); the entrance also gets the
  // arrow from outside. The leaf swings into the smaller room (a bedroom off a living room), never
  // onto a balcony, and into the building for the entrance.
  void DrawDoor(const PlacedElement& e, bool entrance) {
    const Segment& seg = e.element->shape;
    const double length = Length(seg);
    if (length <= 1e-9) return;
    const Point mid{(seg.a.x + seg.b.x) / 2.0, (seg.a.y + seg.b.y) / 2.0};
    const Point hinge = e.swing.hinge, free_end = e.swing.free_end, leaf_end = e.swing.leaf_end;
    const Rgb ink = e.on_wall ? kWallInk : kError;
    const Px h = ToPx(hinge), le = ToPx(leaf_end), fe = ToPx(free_end);
    if (!e.on_wall) paint_.Line(ToPx(seg.a), ToPx(seg.b), Pen(kError, 3.0));
    const double a0 = std::atan2(le.y - h.y, le.x - h.x);
    double a1 = std::atan2(fe.y - h.y, fe.x - h.x);
    while (a1 - a0 > M_PI) a1 -= 2.0 * M_PI;
    while (a0 - a1 > M_PI) a1 += 2.0 * M_PI;
    if (e.swing.flat) a1 = a0 + FlatTurn(a0, {e.swing.leaf_side.x, -e.swing.leaf_side.y});  // screen y is down
    const double radius = length * s();
    paint_.Path({SubPath{Arc(h, radius, a0, a1), false}}, std::nullopt, Pen(e.on_wall ? kMuted : kError, 1.0));
    paint_.Line(h, le, Pen(ink, std::max(2.0, 0.05 * s())));

    if (!entrance) return;
    const Point outward = e.outward;
    const Px pm = ToPx(mid);
    const Px dir{-outward.x, outward.y};  // pointing in, on screen (y flipped)
    const Px tip = Offset(pm, dir, -(ExteriorPx() / 2.0 + 4.0));
    const Px tail = Offset(tip, dir, -f_.arrow.length);
    const Rgb arrow_color = e.on_wall ? kAccent : kError;
    const double head = std::max(10.0, options_.font_size_px * 0.9);
    paint_.Line(tail, Offset(tip, dir, -head * 0.7), Pen(arrow_color, 2.6));
    Arrowhead(paint_, tip, dir, head, head * 0.85, arrow_color);
    const double cap = measure_.CapHeight(fonts_.small);
    const double gap = f_.arrow.label_gap;
    if (std::abs(dir.x) >= std::abs(dir.y)) {
      // Arrow comes in from the left (dir.x > 0) or the right.
      const bool from_left = dir.x > 0;
      paint_.Text("Entrance", {tail.x + (from_left ? -gap : gap), tail.y + cap / 2.0}, fonts_.small, true, arrow_color,
                  from_left ? TextAnchor::kEnd : TextAnchor::kStart);
    } else {
      const bool from_below = dir.y < 0;  // arrow points up the screen: tail below the plan
      paint_.Text("Entrance", {tail.x, from_below ? tail.y + gap + cap : tail.y - gap}, fonts_.small, true, arrow_color,
                  TextAnchor::kMiddle);
    }
  }

  // -- labels ------------------------------------------------------------------------------------

  struct LabelFit {
    Point centre;
    std::string name;        // the full display name, or the short one where that fits better
    double scale = 1.0;
    bool rotated = false;
    bool with_area = true;
    bool overflow = false;   // fits nowhere: drawn on a chip across the walls
  };

  // A label's rectangle in plan coordinates (m), as placed.
  struct Placed {
    Point lo, hi;
  };

  // The largest label that fits inside the room, wall thickness and a little air kept clear, away from
  // labels already placed on this floor and (where the room allows) from door swings. In order: name
  // over area, smaller, upright for tall narrow rooms; then the name alone; then the short name; and
  // when nothing fits, the short name on a chip where it overlaps no other label.
  LabelFit FitLabel(const LevelGeometry& g, const Ring& ring, const std::string& name, const std::string& short_name,
                    const std::string& area) const {
    // Door swings to keep clear of: the quarter discs, as polygons, with their boxes.
    std::vector<Ring> swings;
    std::vector<Placed> swing_boxes;
    for (const auto* list : {&g.doors, &g.entrances}) {
      for (const PlacedElement& e : *list) {
        const DoorSwing& w = e.swing;
        const double radius = Distance(w.hinge, w.free_end);
        const double a0 = std::atan2(w.leaf_end.y - w.hinge.y, w.leaf_end.x - w.hinge.x);
        double a1 = std::atan2(w.free_end.y - w.hinge.y, w.free_end.x - w.hinge.x);
        while (a1 - a0 > M_PI) a1 -= 2.0 * M_PI;
        while (a0 - a1 > M_PI) a1 += 2.0 * M_PI;
        if (w.flat) a1 = a0 + FlatTurn(a0, w.leaf_side);
        Ring sector{w.hinge};
        const int steps = w.flat ? 16 : 8;
        for (int i = 0; i <= steps; ++i) {
          const double a = a0 + (a1 - a0) * i / steps;
          sector.push_back({w.hinge.x + radius * std::cos(a), w.hinge.y + radius * std::sin(a)});
        }
        Placed box{sector[0], sector[0]};
        for (const Point& p : sector) {
          box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y)};
          box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y)};
        }
        swing_boxes.push_back(box);
        swings.push_back(std::move(sector));
      }
    }

    const Point pole = RoomLabelPoint(ring);
    if (ring.size() < 3) return {pole, short_name, kMinLabelScale, false, false, true};
    // Candidate centres: the pole, then a grid over the room in falling clearance.
    std::vector<std::pair<double, Point>> candidates{{plan::SignedDistanceToRing(pole, ring), pole}};
    double min_x = ring[0].x, max_x = ring[0].x, min_y = ring[0].y, max_y = ring[0].y;
    for (const Point& p : ring) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
    // About 12 samples across the room's narrow side, at most 60 along its long side.
    const double step = std::max({0.1, std::min(max_x - min_x, max_y - min_y) / 12.0, std::max(max_x - min_x, max_y - min_y) / 60.0});
    std::vector<std::pair<double, Point>> grid;
    for (double x = min_x + step / 2.0; x < max_x; x += step) {
      for (double y = min_y + step / 2.0; y < max_y; y += step) {
        const double d = plan::SignedDistanceToRing({x, y}, ring);
        if (d > 0.0) grid.push_back({d, {x, y}});
      }
    }
    std::stable_sort(grid.begin(), grid.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (size_t i = 0; i < grid.size() && i < 400; ++i) candidates.push_back(grid[i]);

    const double margin = (kExteriorWall / 2.0) + 5.0 / s();  // m kept clear around the text
    auto overlaps_label = [&](Point lo, Point hi) {
      for (const Placed& p : placed_) {
        if (lo.x < p.hi.x && p.lo.x < hi.x && lo.y < p.hi.y && p.lo.y < hi.y) return true;
      }
      return false;
    };
    auto fits = [&](Point c, double half_x, double half_y, bool avoid_swings) {
      const Point lo{c.x - half_x, c.y - half_y}, hi{c.x + half_x, c.y + half_y};
      if (overlaps_label(lo, hi)) return false;
      if (avoid_swings) {
        for (size_t i = 0; i < swings.size(); ++i) {
          const Placed& b = swing_boxes[i];
          if (lo.x >= b.hi.x || b.lo.x >= hi.x || lo.y >= b.hi.y || b.lo.y >= hi.y) continue;
          if (plan::RectOverlapsRing(lo, hi, swings[i])) return false;
        }
      }
      return plan::RectInsideRing(lo, hi, ring);
    };
    struct Try {
      const std::string* name;
      bool with_area;
      std::vector<std::pair<bool, double>> sizes;  // (upright, scale)
    };
    const std::vector<std::pair<bool, double>> large = {{false, 1.0}, {false, 0.9}, {false, 0.8},
                                                        {true, 1.0},  {true, 0.9},  {true, 0.8}};
    const std::vector<std::pair<bool, double>> small = {{false, 0.7}, {true, 0.7}, {false, kMinLabelScale}, {true, kMinLabelScale}};
    const std::vector<std::pair<bool, double>> smaller = {{false, 0.7}, {true, 0.7}};
    const Try tries[] = {{&name, true, large},        {&name, true, smaller}, {&name, false, large},
                         {&short_name, false, large}, {&name, false, small},  {&short_name, false, small}};
    for (const Try& t : tries) {
      for (bool avoid : {true, false}) {
        for (const auto& [rotated, scale] : t.sizes) {
          const LabelFit probe{pole, *t.name, scale, rotated, t.with_area, false};
          const auto [w, h] = LabelSize(probe, area);
          const double half_x = (rotated ? h : w) / 2.0 / s() + margin;
          const double half_y = (rotated ? w : h) / 2.0 / s() + margin;
          for (const auto& [clearance, c] : candidates) {
            // Candidates come in falling clearance; once a boundary point is nearer than the block's
            // half height it lies inside the block, here and at every later candidate.
            if (clearance < std::min(half_x, half_y)) break;
            if (fits(c, half_x, half_y, avoid)) return {c, *t.name, scale, rotated, t.with_area, false};
          }
        }
      }
    }
    // Nowhere inside: the short name on a chip, at the first candidate clear of other labels.
    LabelFit chip{pole, short_name, kMinLabelScale, false, false, true};
    const auto [w, h] = LabelSize(chip, area);
    for (const auto& [clearance, c] : candidates) {
      const Point lo{c.x - w / 2.0 / s(), c.y - h / 2.0 / s()}, hi{c.x + w / 2.0 / s(), c.y + h / 2.0 / s()};
      if (!overlaps_label(lo, hi)) {
        chip.centre = c;
        break;
      }
    }
    return chip;
  }

  // Width (along the text) and height (across) of the label block, px.
  std::pair<double, double> LabelSize(const LabelFit& fit, const std::string& area) const {
    const double name_size = fonts_.label * fit.scale, area_size = fonts_.area * fit.scale;
    double width = measure_.Width(fit.name, name_size, true);
    double height = measure_.CapHeight(name_size);
    if (fit.with_area) {
      width = std::max(width, measure_.Width(area, area_size, false));
      height += name_size * 0.55 + measure_.CapHeight(area_size);
    }
    return {width, height};
  }

  void DrawLabel(const LevelGeometry& g, int r) {
    const Room& room = layout().rooms[r];
    std::string index = " ";  // appended: GCC 12 warns (-Wrestrict, a false alarm) on " " + std::string
    index += std::to_string(room.index);
    const std::string name = std::string(CategoryDisplayName(room.category)) + index;
    const std::string short_name = std::string(CategoryShortName(room.category)) + index;
    const std::string area = AreaText(Area(room.polygon));
    const LabelFit fit = FitLabel(g, room.polygon, name, short_name, area);
    const auto [w, h] = LabelSize(fit, area);
    const double box_w = fit.rotated ? h : w, box_h = fit.rotated ? w : h;
    placed_.push_back({{fit.centre.x - box_w / 2.0 / s(), fit.centre.y - box_h / 2.0 / s()},
                       {fit.centre.x + box_w / 2.0 / s(), fit.centre.y + box_h / 2.0 / s()}});
    const Px c = ToPx(fit.centre);
    const double name_size = fonts_.label * fit.scale, area_size = fonts_.area * fit.scale;
    const double name_cap = measure_.CapHeight(name_size);
    std::string id = "label-" + room.name();
    std::replace(id.begin(), id.end(), '/', '-');
    paint_.Begin(id);
    if (fit.overflow || (g.has_stairs && room.category == Category::kUtilityRoom)) {
      // A chip under the text so it reads over stair treads and walls.
      const double bw = box_w / 2.0 + 4.0, bh = box_h / 2.0 + 3.0;
      paint_.Polygon(RoundedRect(c.x - bw, c.y - bh, c.x + bw, c.y + bh, 3.0), Fill{kWhite, 0.88},
                     fit.overflow ? std::optional<Stroke>(Pen(CategoryInk(room.category), 1.0)) : std::nullopt);
    }
    if (!fit.rotated) {
      const double top = c.y - h / 2.0;
      paint_.Text(fit.name, {c.x, top + name_cap}, name_size, true, kText, TextAnchor::kMiddle);
      if (fit.with_area) paint_.Text(area, {c.x, c.y + h / 2.0}, area_size, false, kMuted, TextAnchor::kMiddle);
    } else {
      // Reads bottom to top; the block's "top" is on the left.
      const double left = c.x - h / 2.0;
      paint_.Text(fit.name, {left + name_cap, c.y}, name_size, true, kText, TextAnchor::kMiddle, -90.0);
      if (fit.with_area) paint_.Text(area, {c.x + h / 2.0, c.y}, area_size, false, kMuted, TextAnchor::kMiddle, -90.0);
    }
    paint_.End();
  }

  // -- legend and scale bar ----------------------------------------------------------------------

  void DrawLegendBand() {
    const double left = options_.margin_px;
    const double right = f_.pub.width_px - options_.margin_px;
    paint_.Line({left, f_.rule_y}, {right, f_.rule_y}, Pen(kRule, 1.0));
    DrawScaleBar(left, f_.bottom_top);
    paint_.Begin("legend");
    const double row = std::max(20.0, fonts_.legend * 1.9);
    for (const LegendLayout::Placed& placed : f_.legend.entries) {
      const double x = f_.legend_left + placed.x;
      const double y = f_.legend_top + placed.y;
      const double mid_y = y + row / 2.0;
      const double baseline = mid_y + measure_.CapHeight(fonts_.legend) / 2.0;
      if (placed.entry.kind == LegendEntry::kGroupTitle) {
        paint_.Text(placed.entry.text, {x, baseline}, fonts_.legend, true, kMuted);
        continue;
      }
      DrawIcon(placed.entry, x, mid_y);
      paint_.Text(placed.entry.text, {x + kIconWidth + kIconGap, baseline}, fonts_.legend, false, kText);
    }
    paint_.End();
  }

  void DrawScaleBar(double x, double top) {
    paint_.Begin("scale-bar");
    const double bar = f_.scale_bar_m * s();
    const double y = top + 8.0, height = 6.0;
    const int d = f_.scale_bar_divisions;
    for (int i = 0; i < d; ++i) {
      const double x0 = x + bar * i / d, x1 = x + bar * (i + 1) / d;
      paint_.Polygon({{x0, y}, {x1, y}, {x1, y + height}, {x0, y + height}}, Fill{i % 2 == 0 ? kWallInk : kWhite},
                     Pen(kWallInk, 1.0));
    }
    const double baseline = y + height + 6.0 + measure_.CapHeight(fonts_.small);
    auto label = [&](double metres) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, metres == std::floor(metres) ? "%.0f" : "%.1f", metres);
      return std::string(buffer);
    };
    // Numbers under the ticks, as many as fit without touching: 0, every k-th tick, and the end in metres.
    const std::string end_text = label(f_.scale_bar_m) + " m";
    const double end_half = measure_.Width(end_text, fonts_.small, false) / 2.0;
    double widest = 0.0;
    for (int i = 0; i < d; ++i) widest = std::max(widest, measure_.Width(label(f_.scale_bar_m * i / d), fonts_.small, false));
    const double air = fonts_.small * 0.6;
    int k = 1;
    while (k < d && bar * k / d < widest + air) ++k;
    for (int i = 0; i < d; i += k) {
      const double px = x + bar * i / d;
      if (x + bar - end_half - (px + widest / 2.0) < air) break;  // would touch the end label
      paint_.Text(label(f_.scale_bar_m * i / d), {px, baseline}, fonts_.small, false, kText, TextAnchor::kMiddle);
    }
    paint_.Text(end_text, {x + bar, baseline}, fonts_.small, false, kText, TextAnchor::kMiddle);
    paint_.Text("Scale", {x, top + 1.0}, fonts_.small * 0.9, true, kMuted);
    paint_.End();
  }

  void DrawIcon(const LegendEntry& entry, double x, double mid) {
    const double w = kIconWidth, x1 = x + w;
    const double wall = std::clamp(ExteriorPx(), 4.0, 9.0), thin = std::clamp(InteriorPx(), 2.0, 5.0);
    switch (entry.kind) {
      case LegendEntry::kCategory:
        paint_.Polygon(RoundedRect(x + 2, mid - 7, x1 - 2, mid + 7, 2.5), Fill{CategoryColor(entry.category)},
                       Pen(CategoryInk(entry.category), 1.0));
        break;
      case LegendEntry::kExterior:
        paint_.Line({x, mid}, {x1, mid}, Pen(kWallInk, wall));
        break;
      case LegendEntry::kInterior:
        paint_.Line({x, mid}, {x1, mid}, Pen(kWallInk, thin));
        break;
      case LegendEntry::kNoWall:
        paint_.Line({x, mid}, {x1, mid}, Pen(kHairline, 1.3, LineCap::kButt, {3.0, 2.5}));
        break;
      case LegendEntry::kDoor: {
        const double y = mid + 5.0, r = 14.0, g0 = x + 8.0;
        paint_.Line({x, y}, {g0, y}, Pen(kWallInk, thin));
        paint_.Line({g0 + r, y}, {x1, y}, Pen(kWallInk, thin));
        paint_.Path({SubPath{Arc({g0, y}, r, -M_PI / 2.0, 0.0), false}}, std::nullopt, Pen(kMuted, 1.0));
        paint_.Line({g0, y}, {g0, y - r}, Pen(kWallInk, 2.0));
        break;
      }
      case LegendEntry::kOpen:
        paint_.Line({x, mid}, {x + 7, mid}, Pen(kWallInk, thin));
        paint_.Line({x1 - 7, mid}, {x1, mid}, Pen(kWallInk, thin));
        paint_.Line({x + 7, mid}, {x1 - 7, mid}, Pen(kMuted, 1.4, LineCap::kButt, {4.0, 3.0}));
        break;
      case LegendEntry::kWindow:
      case LegendEntry::kPanoramic: {
        const bool pano = entry.kind == LegendEntry::kPanoramic;
        const double half = wall / 2.0 + 0.5;
        paint_.Line({x, mid}, {x + 5, mid}, Pen(kWallInk, wall));
        paint_.Line({x1 - 5, mid}, {x1, mid}, Pen(kWallInk, wall));
        paint_.Polygon({{x + 5, mid - half}, {x1 - 5, mid - half}, {x1 - 5, mid + half}, {x + 5, mid + half}},
                       Fill{pano ? kPanoramicGlass : kGlass}, Pen(kWallInk, 1.0));
        const double glass = half * (pano ? 0.55 : 0.38);
        paint_.Line({x + 5, mid - glass}, {x1 - 5, mid - glass}, Pen(kWallInk, 1.0));
        paint_.Line({x + 5, mid + glass}, {x1 - 5, mid + glass}, Pen(kWallInk, 1.0));
        if (pano) paint_.Line({x + 5, mid}, {x1 - 5, mid}, Pen(kPanoramicLine, 1.6));
        break;
      }
      case LegendEntry::kEntrance:
        paint_.Line({x, mid}, {x1 - 8, mid}, Pen(kAccent, 2.6));
        Arrowhead(paint_, {x1, mid}, {1, 0}, 10.0, 8.5, kAccent);
        break;
      case LegendEntry::kStairs: {
        paint_.Polygon({{x + 2, mid - 7}, {x1 - 2, mid - 7}, {x1 - 2, mid + 7}, {x + 2, mid + 7}},
                       Fill{CategoryColor(Category::kUtilityRoom)}, Pen(kWallInk, 1.0));
        std::vector<SubPath> treads;
        for (double tx = x + 6; tx < x1 - 3; tx += 4.0) treads.push_back(SubPath{{{tx, mid - 7}, {tx, mid + 7}}, false});
        paint_.Path(std::move(treads), std::nullopt, Pen({0.42, 0.43, 0.45}, 0.8));
        paint_.Line({x + 5, mid}, {x1 - 8, mid}, Pen(kWallInk, 1.2));
        Arrowhead(paint_, {x1 - 4, mid}, {1, 0}, 6.0, 5.0, kWallInk);
        break;
      }
      case LegendEntry::kOffWall:
        paint_.Line({x, mid}, {x1, mid}, Pen(kError, 3.0));
        break;
      case LegendEntry::kFurniture:
        paint_.Polygon({{x + 6, mid - 6}, {x1 - 6, mid - 6}, {x1 - 6, mid + 6}, {x + 6, mid + 6}}, Fill{kFurnitureLegend},
                       Pen(kWallInk, 1.0));
        break;
      case LegendEntry::kPath: {
        Stroke pen = Pen(kAccent, 1.6, LineCap::kRound);
        paint_.Path({SubPath{{{x + 2, mid + 4}, {x + 12, mid - 3}, {x1 - 10, mid + 3}, {x1 - 2, mid - 4}}, false}},
                    std::nullopt, pen);
        break;
      }
      case LegendEntry::kGroupTitle:
        break;
    }
  }

  const Content& c_;
  const Frame& f_;
  const PlanRenderOptions& options_;
  const TextMeasure& measure_;
  Fonts fonts_;
  Painter paint_;
  double panel_left_ = 0.0, panel_top_ = 0.0;
  std::vector<Placed> placed_;  // labels placed on the current floor
};

Result<Scene> BuildScene(const Layout& layout, const PlanOverlay* overlay, const PlanRenderOptions& options) {
  if (std::string problem = options.Check(); !problem.empty()) return Error{problem};
  TextMeasure measure(options.font_family);
  Result<Content> content = Analyse(layout, overlay, options, measure);
  if (!content.ok()) return Error{content.error()};
  Result<Frame> frame = MakeFrame(*content, options, measure);
  if (!frame.ok()) return Error{frame.error()};
  Scene scene;
  scene.width = frame->pub.width_px;
  scene.height = frame->pub.height_px;
  scene.font_family = options.font_family;
  scene.title = content->title_bold + (content->title_rest.empty() ? "" : " - " + content->title_rest);
  PlanPainter(*content, *frame, options, measure, scene).Draw();
  return scene;
}

}  // namespace

std::string PlanRenderOptions::Check() const {
  auto bad = [](const char* field, double value, const char* why) {
    return std::string(field) + " = " + Format("%g", value) + ": " + why;
  };
  if (!(pixels_per_metre >= 5.0 && pixels_per_metre <= 400.0)) return bad("pixels_per_metre", pixels_per_metre, "must be in 5..400");
  if (target_width_px < 0 || target_width_px > 30000) return bad("target_width_px", target_width_px, "must be 0 (off) or up to 30000");
  if (!(margin_px >= 0.0 && margin_px <= 1000.0)) return bad("margin_px", margin_px, "must be in 0..1000");
  if (!(panel_gap_px >= 0.0 && panel_gap_px <= 1000.0)) return bad("panel_gap_px", panel_gap_px, "must be in 0..1000");
  if (!(font_size_px >= 6.0 && font_size_px <= 48.0)) return bad("font_size_px", font_size_px, "must be in 6..48");
  if (max_side_px < 64 || max_side_px > 32767) return bad("max_side_px", max_side_px, "must be in 64..32767");
  if (png_compression < 1 || png_compression > 9) return bad("png_compression", png_compression, "must be in 1..9");
  if (font_family.empty()) return "font_family is empty";
  return {};
}

Point PlanFrame::ToPixel(int level, Point p) const {
  for (const Panel& panel : panels) {
    if (panel.level == level) {
      return {panel.plan_left_px + (p.x - min_x) * pixels_per_metre, panel.plan_top_px + (max_y - p.y) * pixels_per_metre};
    }
  }
  return {-1.0, -1.0};
}

Result<PlanFrame> ComputePlanFrame(const Layout& layout, const PlanRenderOptions& options) {
  if (std::string problem = options.Check(); !problem.empty()) return Error{problem};
  TextMeasure measure(options.font_family);
  Result<Content> content = Analyse(layout, nullptr, options, measure);
  if (!content.ok()) return Error{content.error()};
  Result<Frame> frame = MakeFrame(*content, options, measure);
  if (!frame.ok()) return Error{frame.error()};
  return frame->pub;
}

Point RoomLabelPoint(const Ring& polygon, double precision) { return plan::PoleOfInaccessibility(polygon, precision); }

namespace {

Result<std::string> PngOf(const Layout& layout, const PlanOverlay* overlay, const PlanRenderOptions& options) {
  Result<Scene> scene = BuildScene(layout, overlay, options);
  if (!scene.ok()) return Error{scene.error()};
  std::string error;
  std::optional<std::string> png = plan::SceneToPng(*scene, options.png_compression, &error);
  if (!png) return Error{error};
  return std::move(*png);
}

Result<std::string> SvgOf(const Layout& layout, const PlanOverlay* overlay, const PlanRenderOptions& options) {
  Result<Scene> scene = BuildScene(layout, overlay, options);
  if (!scene.ok()) return Error{scene.error()};
  return plan::SceneToSvg(*scene);
}

}  // namespace

Result<std::string> RenderPlanPng(const Layout& layout, const PlanRenderOptions& options) { return PngOf(layout, nullptr, options); }
Result<std::string> RenderPlanSvg(const Layout& layout, const PlanRenderOptions& options) { return SvgOf(layout, nullptr, options); }
Result<std::string> RenderPlanPng(const Layout& layout, const PlanOverlay& overlay, const PlanRenderOptions& options) {
  return PngOf(layout, &overlay, options);
}
Result<std::string> RenderPlanSvg(const Layout& layout, const PlanOverlay& overlay, const PlanRenderOptions& options) {
  return SvgOf(layout, &overlay, options);
}

Status RenderPlan(const Layout& layout, const std::filesystem::path& out, const PlanRenderOptions& options) {
  std::string extension = out.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  Result<std::string> bytes = Error{""};
  if (extension == ".png") {
    bytes = RenderPlanPng(layout, options);
  } else if (extension == ".svg") {
    bytes = RenderPlanSvg(layout, options);
  } else {
    return Error{out.string() + ": unknown picture type '" + out.extension().string() +
                 "' (the extension must be .png or .svg)"};
  }
  if (!bytes.ok()) return Error{out.string() + ": " + bytes.error()};
  return WriteFileAtomic(out, *bytes);
}

}  // namespace villa
