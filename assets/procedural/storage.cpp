// Storage furniture: carcasses of side, top, bottom and back panels split into columns and cells, each cell
// a cavity with its floor as a support surface; fronts open, behind doors or drawers (closed cavities).
#include <algorithm>
#include <cmath>

#include "assets/procedural/generator.h"

namespace villa::procedural {
namespace {

enum class Front { kOpen, kDoor, kGlass, kDrawer, kPanel };

struct Cell {
  double weight = 1.0;  // share of the column's inner height
  Front front = Front::kOpen;
  bool rail = false;  // a hanging rail under the cell's ceiling
};
struct Column {
  double weight = 1.0;      // share of the inner width
  std::vector<Cell> cells;  // bottom to top
};

// A carcass filling x0..x1 x y_front..y_back x z0..z1 (handles and fronts included in y_front).
struct Carcass {
  double x0 = 0, x1 = 0, y_front = 0, y_back = 0, z0 = 0, z1 = 0;
  double panel = 0.018;         // side, top, bottom, shelf and divider thickness, m
  double back = 0.008;          // back panel, m
  double base = 0.08;           // plinth or leg height, m (0: the bottom panel stands at z0)
  bool legs = false;            // legs instead of a plinth
  double plinth_recess = 0.03;  // plinth set back from the front, m
  bool top_panel = true;        // false: the caller lays a worktop on z1 and the cells reach z1
  std::vector<Column> columns;
};

constexpr double kHandleDepth = 0.02;  // m a handle stands proud of its front
constexpr double kFrontThickness = 0.018;
constexpr double kGap = 0.002;  // between neighbouring fronts

bool HasHandle(Front f) { return f == Front::kDoor || f == Front::kGlass || f == Front::kDrawer; }

// Builds the carcass with its surfaces (every cell's floor) and cavities (every cell); adds the top surface
// when it has a top panel.
void BuildCarcass(Gen& g, const Carcass& c) {
  const Palette& pal = g.palette;
  const int wood = g.out.Part(g.rng.Pick(pal.wood));
  const int front_part =
      g.out.Part(g.style == "modern" || g.style == "scandinavian" ? g.rng.Pick(pal.paint) : g.rng.Pick(pal.wood));
  const int handle = g.out.Part(g.rng.Pick(pal.metal));
  const int glass = g.out.Part(Glass());

  bool any_handle = false, any_front = false;
  for (const Column& col : c.columns)
    for (const Cell& cell : col.cells) {
      any_handle |= HasHandle(cell.front);
      any_front |= cell.front != Front::kOpen;
    }
  const double t = c.panel;
  const double yc = c.y_front + (any_handle ? kHandleDepth : 0.0) + (any_front ? kFrontThickness : 0.0);
  const double yb = c.y_back - c.back;  // inner face of the back panel
  const double zs = c.legs ? c.z0 + c.base : c.z0;
  const double z_side_top = c.top_panel ? c.z1 - t : c.z1;

  g.out.Box(wood, {c.x0, yc, zs}, {c.x0 + t, yb, z_side_top});
  g.out.Box(wood, {c.x1 - t, yc, zs}, {c.x1, yb, z_side_top});
  g.out.Box(wood, {c.x0, yb, zs}, {c.x1, c.y_back, c.z1});
  if (c.top_panel) g.out.Box(wood, {c.x0, yc, c.z1 - t}, {c.x1, yb, c.z1});
  const double zb = c.legs ? zs : c.z0 + c.base;  // bottom panel's underside
  g.out.Box(wood, {c.x0 + t, yc, zb}, {c.x1 - t, yb, zb + t});
  if (c.base > 0 && !c.legs) {
    g.out.Box(wood, {c.x0 + t, yc + c.plinth_recess, c.z0}, {c.x1 - t, yb, zb});
  } else if (c.base > 0) {
    const double half = std::min(0.025, 0.25 * std::min(c.x1 - c.x0, yb - yc));
    for (double x : {c.x0 + 0.01 + half, c.x1 - 0.01 - half})
      for (double y : {yc + 0.01 + half, yb - 0.01 - half}) g.Leg(wood, x, y, c.z0, zs, half);
  }

  const double xi0 = c.x0 + t, xi1 = c.x1 - t, zi0 = zb + t, zi1 = z_side_top;
  const int columns = static_cast<int>(c.columns.size());
  double width_weights = 0;
  for (const Column& col : c.columns) width_weights += col.weight;
  const double inner_width = xi1 - xi0 - (columns - 1) * t;
  double cx0 = xi0;
  for (int k = 0; k < columns; ++k) {
    const Column& col = c.columns[k];
    const double cx1 = k + 1 == columns ? xi1 : cx0 + inner_width * col.weight / width_weights;
    if (k + 1 < columns) g.out.Box(wood, {cx1, yc, zi0}, {cx1 + t, yb, zi1});
    const int rows = static_cast<int>(col.cells.size());
    double height_weights = 0;
    for (const Cell& cell : col.cells) height_weights += cell.weight;
    const double inner_height = zi1 - zi0 - (rows - 1) * t;
    double z = zi0;
    // Door leaves merge over consecutive door (or glass) cells of the column.
    double leaf_z0 = 0;
    for (int r = 0; r < rows; ++r) {
      const Cell& cell = col.cells[r];
      const double ztop = r + 1 == rows ? zi1 : z + inner_height * cell.weight / height_weights;
      if (r + 1 < rows) g.out.Box(wood, {cx0, yc, ztop}, {cx1, yb, ztop + t});
      double cavity_top = ztop, rail_top = 0.0;
      if (cell.rail) {
        const double rz = ztop - 0.06, rr = 0.012;
        g.out.Tube(handle, {cx0, (yc + yb) / 2, rz}, {cx1, (yc + yb) / 2, rz}, rr);
        cavity_top = rz - rr;
        rail_top = rz + rr;
      }
      const int floor = g.out.Surface(z, Rect(cx0, yc, cx1, yb), cavity_top - z);
      g.out.AddCavity({cx0, yc, z}, {cx1, yb, cavity_top}, cell.front == Front::kOpen ? "-y" : "closed", floor,
                      rail_top);

      // Fronts cover the opening and half the panels around it, clear of the carcass's outer edges.
      const double fx0 = std::max(c.x0 + kGap, cx0 - t / 2 + kGap), fx1 = std::min(c.x1 - kGap, cx1 + t / 2 - kGap);
      const double f_lo = std::max(zb + kGap, z - t / 2 + kGap);
      const double f_hi = std::min(c.z1 - kGap, ztop + t / 2 - kGap);
      const double fy0 = yc - kFrontThickness;
      const bool leaf = cell.front == Front::kDoor || cell.front == Front::kGlass;
      const bool leaf_starts = leaf && (r == 0 || col.cells[r - 1].front != cell.front);
      const bool leaf_ends = leaf && (r + 1 == rows || col.cells[r + 1].front != cell.front);
      if (leaf_starts) leaf_z0 = f_lo;
      if (cell.front == Front::kDrawer || cell.front == Front::kPanel) {
        g.out.Box(front_part, {fx0, fy0, f_lo}, {fx1, yc, f_hi});
        if (cell.front == Front::kDrawer) {
          const double hw = std::min(0.1, 0.25 * (fx1 - fx0)), zc = f_lo + 0.6 * (f_hi - f_lo);
          g.out.Box(handle, {-hw + (fx0 + fx1) / 2, c.y_front, zc - 0.006}, {hw + (fx0 + fx1) / 2, fy0, zc + 0.006});
        }
      } else if (leaf_ends) {
        g.out.Box(cell.front == Front::kGlass ? glass : front_part, {fx0, fy0, leaf_z0}, {fx1, yc, f_hi});
        // The handle sits on the leaf's edge nearer the carcass's middle (both edges meet there).
        const double mid = (c.x0 + c.x1) / 2;
        const bool right = columns == 1 || (fx0 + fx1) / 2 < mid;
        const double hx = right ? fx1 - 0.04 : fx0 + 0.04;
        const double hh = std::min(0.08, 0.3 * (f_hi - leaf_z0));
        const double hz = c.z1 - c.z0 > 1.2 ? std::min(leaf_z0 + 1.0, (leaf_z0 + f_hi) / 2) : (leaf_z0 + f_hi) / 2;
        g.out.Box(handle, {hx - 0.006, c.y_front, hz - hh}, {hx + 0.006, fy0, hz + hh});
      }
      z = ztop + t;
    }
    cx0 = cx1 + t;
  }
  if (c.top_panel) g.TopSurface(c.z1, c.x0, yc, c.x1, yb);
}

// The carcass of the whole box, with the style's thicknesses and base.
Carcass WholeBox(const Gen& g, double base, bool legs) {
  Carcass c;
  c.x0 = -g.w / 2;
  c.x1 = g.w / 2;
  c.y_front = -g.d / 2;
  c.y_back = g.d / 2;
  c.z1 = g.h;
  c.panel = g.style == "rustic" ? 0.028 : g.style == "classic" ? 0.024 : 0.018;
  c.base = base;
  c.legs = legs;
  return c;
}

bool LegStyle(const Gen& g) { return g.style == "scandinavian" || g.style == "modern"; }

std::vector<Column> Grid(int cols, int rows, Front front) {
  return std::vector<Column>(cols, Column{1.0, std::vector<Cell>(rows, Cell{1.0, front, false})});
}

int Around(double v, int lo, int hi) { return std::clamp(static_cast<int>(std::lround(v)), lo, hi); }

ProceduralParam DoorsParam() {
  return CountParam("doors", "1: doors in front (closed cavities), 0: open compartments", 0, 1, 1);
}

GeneratorDef Bookcase() {
  return {.name = "bookcase",
          .description = "shelving: rows x cols open compartments (cavities open at -y), a top surface",
          .categories = {"bookcase"},
          .extra = {CountParam("cols", "compartments side by side", 1, 4),
                    CountParam("rows", "compartments one above the other", 1, 8)},
          .resolve =
              [](ParamValues& p, const CategoryInfo&, Rng&) {
                SetIfMissing(p, "rows", [&] { return Around((p.Real("h") - 0.1) / 0.36, 1, 8); });
                SetIfMissing(p, "cols", [&] { return Around(p.Real("w") / 0.55, 1, 4); });
              },
          .build =
              [](Gen& g) {
                Carcass c = WholeBox(g, g.style == "scandinavian" ? 0.1 : 0.06, g.style == "scandinavian");
                c.columns = Grid(g.params.Int("cols"), g.params.Int("rows"), Front::kOpen);
                BuildCarcass(g, c);
              }};
}

GeneratorDef GlassCabinet() {
  return {.name = "glass-cabinet",
          .description = "display cabinet: shelves behind glass doors (closed cavities), a top surface",
          .categories = {"glass-cabinet"},
          .extra = {CountParam("cols", "doors side by side", 1, 3),
                    CountParam("rows", "shelves' compartments one above the other", 1, 6)},
          .resolve =
              [](ParamValues& p, const CategoryInfo&, Rng&) {
                SetIfMissing(p, "rows", [&] { return Around((p.Real("h") - 0.1) / 0.4, 1, 6); });
                SetIfMissing(p, "cols", [&] { return Around(p.Real("w") / 0.5, 1, 3); });
              },
          .build =
              [](Gen& g) {
                Carcass c = WholeBox(g, 0.1, LegStyle(g));
                c.columns = Grid(g.params.Int("cols"), g.params.Int("rows"), Front::kGlass);
                BuildCarcass(g, c);
              }};
}

GeneratorDef Cabinet() {
  return {.name = "cabinet",
          .description =
              "cupboard or sideboard: shelved compartments behind doors (a sideboard's top row drawers), a top surface",
          .categories = {"cabinet", "sideboard"},
          .extra = {DoorsParam(), CountParam("cols", "columns of compartments", 1, 4),
                    CountParam("rows", "compartments one above the other", 1, 6)},
          .resolve =
              [](ParamValues& p, const CategoryInfo&, Rng&) {
                SetIfMissing(p, "rows", [&] { return Around(p.Real("h") / 0.4, 1, 6); });
                SetIfMissing(p, "cols", [&] { return Around(p.Real("w") / 0.5, 1, 4); });
              },
          .build =
              [](Gen& g) {
                const bool doors = g.params.Int("doors") == 1;
                const bool sideboard = g.Is("sideboard");
                Carcass c = WholeBox(g, sideboard && LegStyle(g) ? 0.15 : 0.08, sideboard && LegStyle(g));
                c.columns = Grid(g.params.Int("cols"), g.params.Int("rows"), doors ? Front::kDoor : Front::kOpen);
                if (doors && sideboard && g.params.Int("rows") >= 2)
                  for (Column& col : c.columns) col.cells.back() = {0.5, Front::kDrawer, false};
                BuildCarcass(g, c);
              }};
}

GeneratorDef Chest() {
  return {.name = "chest",
          .description = "lidded chest: one closed cavity under the lid, a top surface",
          .categories = {"toy-chest"},
          .build = [](Gen& g) {
            Carcass c = WholeBox(g, 0.0, false);
            c.columns = Grid(1, 1, Front::kPanel);
            BuildCarcass(g, c);
          }};
}

GeneratorDef Counter() {
  return {.name = "counter",
          .description =
              "kitchen base units under a worktop (top surface); doors in front (closed cavities) or open shelves; an "
              "island overhangs at +y",
          .categories = {"counter", "island"},
          .extra = {DoorsParam(), CountParam("cols", "units side by side", 1, 4)},
          .resolve = [](ParamValues& p, const CategoryInfo&,
                        Rng&) { SetIfMissing(p, "cols", [&] { return Around(p.Real("w") / 0.6, 1, 4); }); },
          .build =
              [](Gen& g) {
                const double worktop = g.style == "rustic" ? 0.04 : 0.03;
                const double overhang_back = g.Is("island") ? std::clamp(g.d - 0.6, 0.02, 0.3) : 0.0;
                g.out.Box(g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.paint) : g.rng.Pick(g.palette.wood)),
                          {-g.w / 2, -g.d / 2, g.h - worktop}, {g.w / 2, g.d / 2, g.h});
                g.TopSurface(g.h, -g.w / 2, -g.d / 2, g.w / 2, g.d / 2);
                Carcass c = WholeBox(g, 0.1, false);
                c.y_front = -g.d / 2 + 0.02;
                c.y_back = g.d / 2 - overhang_back;
                c.z1 = g.h - worktop;
                c.top_panel = false;
                c.plinth_recess = 0.06;
                c.columns = Grid(g.params.Int("cols"), 2, g.params.Int("doors") == 1 ? Front::kDoor : Front::kOpen);
                BuildCarcass(g, c);
              }};
}

GeneratorDef WallCabinet() {
  return {.name = "wall-cabinet",
          .description = "hung kitchen cabinet (back at +y on the wall): shelves behind doors or open, a top surface",
          .categories = {"upper-cabinet"},
          .extra = {DoorsParam(), CountParam("cols", "columns", 1, 3),
                    CountParam("rows", "compartments one above the other", 1, 3)},
          .resolve =
              [](ParamValues& p, const CategoryInfo&, Rng&) {
                SetIfMissing(p, "rows", [&] { return Around(p.Real("h") / 0.32, 1, 3); });
                SetIfMissing(p, "cols", [&] { return Around(p.Real("w") / 0.5, 1, 3); });
              },
          .build =
              [](Gen& g) {
                Carcass c = WholeBox(g, 0.0, false);
                c.columns = Grid(g.params.Int("cols"), g.params.Int("rows"),
                                 g.params.Int("doors") == 1 ? Front::kDoor : Front::kOpen);
                BuildCarcass(g, c);
              }};
}

GeneratorDef WallShelf() {
  return {
      .name = "wall-shelf",
      .description = "hung shelf board on two brackets (back at +y on the wall), a top surface",
      .categories = {"wall-shelf"},
      .build = [](Gen& g) {
        const double board = g.h < 0.045 ? g.h : 0.035;
        g.out.Box(g.out.Part(g.rng.Pick(g.palette.wood)), {-g.w / 2, -g.d / 2, g.h - board}, {g.w / 2, g.d / 2, g.h});
        g.TopSurface(g.h, -g.w / 2, -g.d / 2, g.w / 2, g.d / 2);
        if (g.h - board < 0.01) return;
        const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
        for (double x : {-g.w / 2 + 0.1, g.w / 2 - 0.12}) {
          const double y0 = g.d / 2 - 0.02, y1 = g.d / 2, yt = g.d / 2 - 0.8 * g.d, z1 = g.h - board;
          g.out.Hexahedron(metal, {Vec3{x, y0, 0},
                                   {x + 0.02, y0, 0},
                                   {x + 0.02, y1, 0},
                                   {x, y1, 0},
                                   {x, yt, z1},
                                   {x + 0.02, yt, z1},
                                   {x + 0.02, y1, z1},
                                   {x, y1, z1}});
        }
      }};
}

GeneratorDef Wardrobe() {
  return {.name = "wardrobe",
          .description =
              "wardrobe without doors: hanging compartments (rail, hat shelf) and shelf compartments, all open at -y",
          .categories = {"wardrobe"},
          .extra = {CountParam("cols", "columns (about half of them with a rail)", 1, 4)},
          .resolve = [](ParamValues& p, const CategoryInfo&,
                        Rng&) { SetIfMissing(p, "cols", [&] { return Around(p.Real("w") / 0.55, 1, 4); }); },
          .build =
              [](Gen& g) {
                Carcass c = WholeBox(g, g.style == "scandinavian" ? 0.12 : 0.08, g.style == "scandinavian");
                const int cols = g.params.Int("cols");
                const int hanging = std::max(1, cols / 2);
                const double inner = g.h - c.base - 2 * c.panel;
                for (int k = 0; k < cols; ++k) {
                  Column col;
                  if (k < hanging) {
                    col.weight = 1.3;
                    col.cells = {{inner - 0.35, Front::kOpen, true}, {0.33, Front::kOpen, false}};
                  } else {
                    col.cells.assign(Around(inner / 0.38, 2, 8), Cell{});
                  }
                  c.columns.push_back(col);
                }
                BuildCarcass(g, c);
              }};
}

GeneratorDef Dresser() {
  return {.name = "dresser",
          .description = "chest of drawers or filing cabinet: drawers (closed cavities), a top surface",
          .categories = {"dresser", "filing-cabinet"},
          .extra = {CountParam("cols", "drawers side by side", 1, 3),
                    CountParam("rows", "drawers one above the other", 1, 6)},
          .resolve =
              [](ParamValues& p, const CategoryInfo& category, Rng&) {
                const bool filing = category.name == "filing-cabinet";
                SetIfMissing(p, "rows", [&] { return Around(p.Real("h") / (filing ? 0.32 : 0.22), 1, 6); });
                SetIfMissing(p, "cols", [&] { return filing || p.Real("w") < 1.0 ? 1 : 2; });
              },
          .build =
              [](Gen& g) {
                const bool legs = g.style == "scandinavian" || g.style == "classic";
                Carcass c = WholeBox(g, legs ? 0.12 : 0.06, legs);
                c.columns = Grid(g.params.Int("cols"), g.params.Int("rows"), Front::kDrawer);
                BuildCarcass(g, c);
              }};
}

GeneratorDef Nightstand() {
  return {.name = "nightstand",
          .description = "bedside table: two compartments, the upper or both behind drawers (closed), a top surface",
          .categories = {"nightstand"},
          .extra = {CountParam("drawers", "0: two open compartments, 1: a drawer above an open one, 2: two drawers", 0,
                               2, 1)},
          .build = [](Gen& g) {
            Carcass c = WholeBox(g, g.style == "rustic" ? 0.05 : 0.12, g.style != "rustic");
            const int drawers = g.params.Int("drawers");
            c.columns = {Column{1.0,
                                {{1.3, drawers == 2 ? Front::kDrawer : Front::kOpen, false},
                                 {1.0, drawers >= 1 ? Front::kDrawer : Front::kOpen, false}}}};
            BuildCarcass(g, c);
          }};
}

GeneratorDef TvStand() {
  return {
      .name = "tv-stand",
      .description = "low media unit: open compartments (the outer ones behind doors when 3 or more), a top surface",
      .categories = {"tv-stand"},
      .extra = {CountParam("cols", "compartments side by side", 1, 4)},
      .resolve = [](ParamValues& p, const CategoryInfo&,
                    Rng&) { SetIfMissing(p, "cols", [&] { return Around(p.Real("w") / 0.5, 1, 4); }); },
      .build =
          [](Gen& g) {
            Carcass c = WholeBox(g, LegStyle(g) ? 0.12 : 0.05, LegStyle(g));
            const int cols = g.params.Int("cols");
            c.columns = Grid(cols, 1, Front::kOpen);
            if (cols >= 3) c.columns.front().cells[0].front = c.columns.back().cells[0].front = Front::kDoor;
            BuildCarcass(g, c);
          }};
}

GeneratorDef Piano() {
  return {.name = "piano",
          .description = "upright piano: a tall case at the back, cheeks at both ends carrying the keybed, white keys "
                         "and black keys in octaves, a pedal bar; its lid a top surface",
          .categories = {"piano"},
          .build =
              [](Gen& g) {
                const int body = g.out.Part(g.style == "modern" ? ScreenBlack() : g.rng.Pick(g.palette.wood));
                const int ivory = g.out.Part(Porcelain()), ebony = g.out.Part(ScreenBlack());
                const int brass = g.out.Part(g.rng.Pick(g.palette.metal));
                const double x0 = -g.w / 2, x1 = g.w / 2, y0 = -g.d / 2, y1 = g.d / 2;
                const double case_front = y1 - std::clamp(0.55 * g.d, 0.25, 0.4), cheek = std::min(0.06, g.w / 20);
                const double keys = std::min(0.72, g.h * 0.6), reach = std::min(0.16, case_front - y0 - 0.02);
                g.out.Box(body, {x0, case_front, 0}, {x1, y1, g.h});  // the case with the strings
                g.out.Box(body, {x0, y0, 0}, {x0 + cheek, case_front, keys + 0.04});  // cheeks to the floor
                g.out.Box(body, {x1 - cheek, y0, 0}, {x1, case_front, keys + 0.04});
                g.out.Box(body, {x0 + cheek, y0 + 0.02, keys - 0.1}, {x1 - cheek, case_front, keys - 0.02});  // keybed
                g.out.Box(ivory, {x0 + cheek, y0 + 0.02, keys - 0.02}, {x1 - cheek, y0 + 0.02 + reach, keys});
                g.out.Box(body, {x0 + cheek, y0 + 0.02 + reach, keys - 0.02}, {x1 - cheek, case_front, keys + 0.06});  // fallboard
                // Black keys: 2 then 3 in each octave of 7 white keys (a white key 23.5 mm of the keyboard).
                const double white = (x1 - x0 - 2 * cheek) / std::max(1.0, std::floor((x1 - x0 - 2 * cheek) / 0.0235));
                int k = 0;
                for (double x = x0 + cheek + white; x + white / 3 < x1 - cheek; x += white, ++k) {
                  const int in_octave = k % 7;
                  if (in_octave == 2 || in_octave == 6) continue;  // no black key between E-F and B-C
                  g.out.Box(ebony, {x - white * 0.3, y0 + 0.02 + reach * 0.4, keys}, {x + white * 0.3, y0 + 0.02 + reach, keys + 0.012});
                }
                g.out.Box(brass, {-0.12, case_front - 0.08, 0.04}, {0.12, case_front, 0.07});  // pedals
                g.TopSurface(g.h, x0, case_front, x1, y1);
              }};
}

GeneratorDef Desk() {
  return {.name = "desk",
          .description =
              "desk: top (surface) on a side panel or legs, a drawer pedestal at +x (closed cavities) when drawers > 0",
          .categories = {"desk"},
          .extra = {CountParam("drawers", "drawers in the pedestal, 0: none", 0, 4)},
          .resolve =
              [](ParamValues& p, const CategoryInfo&, Rng& rng) {
                const std::string& style = p.Word("style");
                SetIfMissing(p, "drawers", [&] {
                  return style == "classic" ? 3 : style == "scandinavian" ? 1 : rng.Chance(0.5) ? 3 : 0;
                });
              },
          .build =
              [](Gen& g) {
                const double top = g.style == "rustic" ? 0.045 : 0.03, zt = g.h - top;
                const int wood = g.out.Part(g.rng.Pick(g.palette.wood));
                g.out.Box(wood, {-g.w / 2, -g.d / 2, zt}, {g.w / 2, g.d / 2, g.h});
                g.TopSurface(g.h, -g.w / 2, -g.d / 2, g.w / 2, g.d / 2);
                const int drawers = g.params.Int("drawers");
                const bool panels = g.style == "modern" || g.style == "scandinavian";
                const double pedestal = drawers > 0 ? std::min(0.42, 0.4 * g.w) : 0.0;
                // One support at each end: a side panel or two legs; the pedestal stands for the one at +x.
                for (double side : {-1.0, 1.0}) {
                  if (side > 0 && drawers > 0) continue;
                  if (panels) {
                    const double x = side * g.w / 2;
                    g.out.Box(wood, {std::min(x, x - side * 0.025), -g.d / 2 + 0.03, 0},
                              {std::max(x, x - side * 0.025), g.d / 2 - 0.03, zt});
                  } else {
                    const double half = g.style == "rustic" ? 0.035 : 0.025;
                    for (double y : {-g.d / 2 + 0.04 + half, g.d / 2 - 0.04 - half})
                      g.Leg(wood, side * (g.w / 2 - 0.04 - half), y, 0, zt, half);
                  }
                }
                const double modesty = std::min(0.35, zt - 0.15);
                if (modesty > 0.1) {
                  const double x1 = g.w / 2 - (drawers > 0 ? pedestal : 0.1);
                  g.out.Box(wood, {-g.w / 2 + 0.1, g.d / 2 - 0.05, zt - modesty}, {x1, g.d / 2 - 0.03, zt});
                }
                if (drawers > 0) {
                  Carcass c = WholeBox(g, 0.05, false);
                  c.x0 = g.w / 2 - pedestal;
                  c.y_back = g.d / 2 - 0.02;
                  c.z1 = zt;
                  c.top_panel = false;
                  c.columns = Grid(1, drawers, Front::kDrawer);
                  BuildCarcass(g, c);
                }
              }};
}

}  // namespace

std::vector<GeneratorDef> StorageGenerators() {
  return {Bookcase(),  GlassCabinet(), Cabinet(), Chest(),      Counter(), WallCabinet(),
          WallShelf(), Wardrobe(),     Dresser(), Nightstand(), TvStand(), Desk(), Piano()};
}

}  // namespace villa::procedural
