// Small things that stand on surfaces or go inside cavities (books, dishes, clothes, decor, gadgets), and
// the floor and wall things with no structure of their own (rugs, plants, baskets, frames, mirrors).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/procedural/generator.h"

namespace villa::procedural {
namespace {

constexpr Vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

// Lengths that add up to `total`, each a random share (0.7-1.3 of the mean).
std::vector<double> Split(Rng& rng, double total, int n) {
  std::vector<double> weights(n);
  double sum = 0;
  for (double& w : weights) sum += (w = rng.Range(0.7, 1.3));
  for (double& w : weights) w *= total / sum;
  return weights;
}

// n random fractions in [lo, 1), one of them (at a random index) exactly 1: the item that sets the box.
std::vector<double> Fractions(Rng& rng, int n, double lo) {
  std::vector<double> f(n);
  for (double& v : f) v = rng.Range(lo, 1.0);
  f[rng.Int(0, n - 1)] = 1.0;
  return f;
}

int Around(double v, int lo, int hi) { return std::clamp(static_cast<int>(std::lround(v)), lo, hi); }

GeneratorDef Books() {
  return {.name = "books",
          .description =
              "books standing in a row, spines at -y (varied thickness, height, depth and colour); magazines lie in a "
              "stack",
          .categories = {"books", "magazine"},
          .extra = {CountParam("count", "books in the row, or magazines in the stack", 1, 12)},
          .resolve =
              [](ParamValues& p, const CategoryInfo& category, Rng& rng) {
                if (category.name == "magazine")
                  SetIfMissing(p, "count", [&] { return Around(p.Real("h") / 0.006, 1, 5); });
                else
                  SetIfMissing(p, "count", [&] { return Around(p.Real("w") / rng.Range(0.025, 0.045), 1, 12); });
              },
          .build =
              [](Gen& g) {
                const int n = g.params.Int("count");
                if (g.Is("magazine")) {
                  const std::vector<double> fw = Fractions(g.rng, n, 0.9), fd = Fractions(g.rng, n, 0.9);
                  for (int k = 0; k < n; ++k) {
                    const double hw = g.w * fw[k] / 2, hd = g.d * fd[k] / 2;
                    g.out.Box(g.out.Part(g.rng.Pick(g.palette.accent)), {-hw, -hd, g.h * k / n},
                              {hw, hd, g.h * (k + 1) / n});
                  }
                  return;
                }
                const std::vector<double> thick = Split(g.rng, g.w, n), fh = Fractions(g.rng, n, 0.78),
                                          fd = Fractions(g.rng, n, 0.8);
                const int paper = g.out.Part(Paper());
                double x = -g.w / 2;
                for (int k = 0; k < n; ++k) {
                  const double t = k + 1 == n ? g.w / 2 - x : thick[k];
                  const double bh = g.h * fh[k], y1 = -g.d / 2 + g.d * fd[k], c = std::min(0.003, t / 4);
                  const int cover = g.out.Part(g.rng.Pick(g.palette.accent));
                  g.out.Box(cover, {x, -g.d / 2, 0}, {x + c, y1, bh});
                  g.out.Box(cover, {x + t - c, -g.d / 2, 0}, {x + t, y1, bh});
                  g.out.Box(cover, {x + c, -g.d / 2, 0}, {x + t - c, -g.d / 2 + c, bh});
                  g.out.Box(paper, {x + c, -g.d / 2 + c, c}, {x + t - c, y1 - c, bh - c});
                  x += t;
                }
              }};
}

GeneratorDef Plate() {
  return {.name = "plate",
          .description = "plate: a foot, a shallow well and a rim",
          .categories = {"plate"},
          .build = [](Gen& g) {
            const int china = g.out.Part(
                g.style == "modern" || g.style == "scandinavian" ? Porcelain() : g.rng.Pick(g.palette.accent));
            const double h = g.h;
            g.out.VerticalLathe(china, {{0, 0}, {0.5, 0}, {1, h}, {0.93, h}, {0.55, 0.45 * h}, {0, 0.45 * h}}, 0, 0,
                                g.w / 2, g.d / 2, 24);
          }};
}

// An open vessel about (cx, 0): outer radii (rx, ry), height h, walls `wall` (relative), floor `floor` (m).
void Vessel(MeshBuilder& out, int part, double cx, double rx, double ry, double h, double foot, double wall,
            double floor) {
  out.VerticalLathe(part, {{0, 0}, {foot, 0}, {1, h}, {1 - wall, h}, {foot - wall / 2, floor}, {0, floor}}, cx, 0, rx,
                    ry, 24);
}

GeneratorDef Bowl() {
  return {.name = "bowl",
          .description = "bowl, fruit bowl (with fruit) or pan (straight sides, a handle at +x)",
          .categories = {"bowl", "fruit-bowl", "pan"},
          .build = [](Gen& g) {
            const int body = g.out.Part(g.Is("pan") ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.accent));
            if (g.Is("pan")) {
              const bool handle = g.w - g.d >= 0.05;
              const double rx = handle ? g.d / 2 : g.w / 2, cx = handle ? -(g.w - g.d) / 2 : 0.0;
              g.out.VerticalLathe(body, {{0, 0}, {1, 0}, {1, g.h}, {0.94, g.h}, {0.94, 0.01}, {0, 0.01}}, cx, 0, rx,
                                  g.d / 2, 24);
              if (handle)
                g.out.Tube(g.out.Part(ScreenBlack()), {cx + 0.95 * rx, 0, 0.8 * g.h}, {g.w / 2, 0, 0.8 * g.h}, 0.01);
              return;
            }
            const double floor = 0.15 * g.h;
            Vessel(g.out, body, 0, g.w / 2, g.d / 2, g.h, 0.5, 0.1, floor);
            if (!g.Is("fruit-bowl")) return;
            const double r = std::min({0.035, 0.2 * g.w, 0.4 * g.h});
            static const std::vector<MeshMaterial> fruit = {{"apple-red", 0.7, 0.1, 0.1, 1},
                                                            {"orange", 0.95, 0.55, 0.1, 1},
                                                            {"lemon", 0.95, 0.85, 0.25, 1},
                                                            {"green-apple", 0.5, 0.75, 0.25, 1}};
            const Point spots[4] = {{0, 0}, {0.3, 0.1}, {-0.25, 0.2}, {-0.05, -0.3}};
            for (Point s : spots)
              g.out.Ellipsoid(g.out.Part(g.rng.Pick(fruit)), s.x * g.w / 2, s.y * g.d / 2, r, r, floor, floor + 2 * r,
                              12);
          }};
}

GeneratorDef Cup() {
  return {.name = "cup",
          .description = "mug with a handle at +x, or a drinking glass (a wine glass in the classic style)",
          .categories = {"cup", "glass"},
          .build = [](Gen& g) {
            if (g.Is("glass")) {
              const int glass = g.out.Part(Glass());
              const double h = g.h;
              if (g.style == "classic")
                g.out.VerticalLathe(glass,
                                    {{0, 0},
                                     {0.75, 0},
                                     {0.75, 0.04 * h},
                                     {0.08, 0.06 * h},
                                     {0.08, 0.45 * h},
                                     {1, 0.75 * h},
                                     {0.86, h},
                                     {0.78, h},
                                     {0.86, 0.75 * h},
                                     {0, 0.52 * h}},
                                    0, 0, g.w / 2, g.d / 2, 24);
              else
                Vessel(g.out, glass, 0, g.w / 2, g.d / 2, h, 0.85, 0.07, 0.15 * h);
              return;
            }
            const int china = g.out.Part(g.rng.Pick(g.palette.accent));
            const bool handle = g.w - g.d >= 0.015;
            const double rx = handle ? g.d / 2 : g.w / 2, cx = handle ? -(g.w - g.d) / 2 : 0.0;
            g.out.VerticalLathe(china, {{0, 0}, {1, 0}, {1, g.h}, {0.88, g.h}, {0.88, 0.1 * g.h}, {0, 0.1 * g.h}}, cx,
                                0, rx, g.d / 2, 24);
            if (!handle) return;
            const double x0 = cx + rx - 0.005, x1 = g.w / 2, t = 0.008, z0 = 0.25 * g.h, z1 = 0.75 * g.h;
            g.out.Box(china, {x1 - t, -0.004, z0}, {x1, 0.004, z1});
            g.out.Box(china, {x0, -0.004, z0}, {x1 - t, 0.004, z0 + t});
            g.out.Box(china, {x0, -0.004, z1 - t}, {x1 - t, 0.004, z1});
          }};
}

GeneratorDef Bottle() {
  return {.name = "bottle",
          .description = "bottle: body, shoulder, neck and cap",
          .categories = {"bottle"},
          .build = [](Gen& g) {
            static const std::vector<MeshMaterial> glass = {{"green-glass", 0.15, 0.4, 0.2, 0.8},
                                                            {"brown-glass", 0.4, 0.22, 0.1, 0.8},
                                                            {"clear-glass", 0.8, 0.88, 0.9, 0.5},
                                                            {"white-plastic", 0.92, 0.92, 0.9, 1}};
            const double h = g.h;
            g.out.VerticalLathe(g.out.Part(g.rng.Pick(glass)),
                                {{0, 0}, {1, 0}, {1, 0.6 * h}, {0.33, 0.78 * h}, {0.33, 0.9 * h}, {0, 0.9 * h}}, 0, 0,
                                g.w / 2, g.d / 2, 16);
            g.out.Cylinder(g.out.Part(g.rng.Pick(g.palette.metal)), 0, 0, 0.4 * g.w / 2, 0.4 * g.d / 2, 0.88 * h, h,
                           16);
          }};
}

GeneratorDef Vase() {
  return {.name = "vase",
          .description = "vase: an open vessel with a belly, a neck and a flared lip",
          .categories = {"vase"},
          .build = [](Gen& g) {
            const double h = g.h;
            g.out.VerticalLathe(g.out.Part(g.rng.Pick(g.palette.accent)),
                                {{0, 0},
                                 {0.6, 0},
                                 {1, 0.35 * h},
                                 {0.55, 0.8 * h},
                                 {0.7, h},
                                 {0.62, h},
                                 {0.45, 0.8 * h},
                                 {0.8, 0.35 * h},
                                 {0.5, 0.08 * h},
                                 {0, 0.08 * h}},
                                0, 0, g.w / 2, g.d / 2, 24);
          }};
}

GeneratorDef Candle() {
  return {.name = "candle",
          .description = "pillar candle with a wick, or a candle in a candlestick (classic)",
          .categories = {"candle"},
          .build = [](Gen& g) {
            const int wax = g.out.Part(g.rng.Pick(g.palette.accent));
            const int black = g.out.Part(ScreenBlack());
            double top;
            if (g.style == "classic") {
              const int brass = g.out.Part(g.rng.Pick(g.palette.metal));
              g.out.Cylinder(brass, 0, 0, g.w / 2, g.d / 2, 0, 0.05 * g.h);
              g.out.Cylinder(brass, 0, 0, 0.25 * g.w / 2, 0.25 * g.d / 2, 0.05 * g.h, 0.4 * g.h);
              g.out.Cylinder(brass, 0, 0, 0.45 * g.w / 2, 0.45 * g.d / 2, 0.4 * g.h, 0.45 * g.h);
              g.out.Cylinder(wax, 0, 0, 0.3 * g.w / 2, 0.3 * g.d / 2, 0.45 * g.h, top = 0.96 * g.h);
            } else {
              g.out.Cylinder(wax, 0, 0, g.w / 2, g.d / 2, 0, top = 0.93 * g.h);
            }
            g.out.Cylinder(black, 0, 0, 0.002, 0.002, top, g.h, 4);
          }};
}

GeneratorDef Roll() {
  return {.name = "roll",
          .description = "toilet roll standing on end (a ring around its core)",
          .categories = {"toilet-paper"},
          .build = [](Gen& g) {
            g.out.VerticalLathe(g.out.Part(Paper()), {{0.35, 0}, {1, 0}, {1, g.h}, {0.35, g.h}}, 0, 0, g.w / 2, g.d / 2,
                                24);
          }};
}

GeneratorDef Dispenser() {
  return {.name = "dispenser",
          .description = "soap dispenser: a bottle with a pump head whose nozzle points to -y",
          .categories = {"soap"},
          .build = [](Gen& g) {
            const double h = g.h;
            g.out.VerticalLathe(g.out.Part(g.rng.Pick(g.palette.accent)),
                                {{0, 0}, {1, 0}, {1, 0.7 * h}, {0.5, 0.78 * h}, {0, 0.78 * h}}, 0, 0, g.w / 2, g.d / 2,
                                16);
            const int pump = g.out.Part(g.rng.Pick(g.palette.metal));
            g.out.Cylinder(pump, 0, 0, 0.15 * g.w, 0.15 * g.w, 0.78 * h, 0.92 * h, 8);
            g.out.Box(pump, {-0.012, -0.45 * g.d / 2, 0.9 * h}, {0.012, 0.012, h});
          }};
}

GeneratorDef Jar() {
  return {.name = "jar",
          .description = "cosmetics jar with a lid",
          .categories = {"cosmetics"},
          .build = [](Gen& g) {
            g.out.Cylinder(g.out.Part(g.rng.Pick(g.palette.accent)), 0, 0, g.w / 2, g.d / 2, 0, 0.75 * g.h);
            g.out.Cylinder(g.out.Part(g.rng.Pick(g.palette.metal)), 0, 0, g.w / 2, g.d / 2, 0.75 * g.h, g.h);
          }};
}

GeneratorDef FoldedClothes() {
  return {.name = "folded-clothes",
          .description = "a pile of folded clothes or towels",
          .categories = {"folded-clothes"},
          .extra = {CountParam("count", "items in the pile", 1, 6)},
          .resolve = [](ParamValues& p, const CategoryInfo&,
                        Rng&) { SetIfMissing(p, "count", [&] { return Around(p.Real("h") / 0.035, 1, 6); }); },
          .build =
              [](Gen& g) {
                const int n = g.params.Int("count");
                const std::vector<double> fw = Fractions(g.rng, n, 0.88), fd = Fractions(g.rng, n, 0.88);
                for (int k = 0; k < n; ++k) {
                  const double hw = g.w * fw[k] / 2, hd = g.d * fd[k] / 2, z0 = g.h * k / n, z1 = g.h * (k + 1) / n;
                  g.out.Cushion(g.out.Part(g.rng.Pick(g.palette.fabric)), {-hw, -hd, z0}, {hw, hd, z1},
                                std::min(0.01, 0.2 * (z1 - z0)));
                }
              }};
}

GeneratorDef HangingClothes() {
  return {.name = "hanging-clothes",
          .description = "garments on hangers, shoulders along x, one behind the other along y; each hanger's hook "
                         "curls over a rail along y at x = 0 whose top is kHookRise below h",
          .categories = {"hanging-clothes"},
          .extra = {CountParam("count", "garments", 1, 6)},
          .resolve = [](ParamValues& p, const CategoryInfo&,
                        Rng&) { SetIfMissing(p, "count", [&] { return Around(p.Real("d") / 0.06, 1, 6); }); },
          .build =
              [](Gen& g) {
                const int n = g.params.Int("count");
                const int wood = g.out.Part(g.rng.Pick(g.palette.wood));
                const int wire = g.out.Part(g.rng.Pick(g.palette.metal));
                // The hook: a bar across the rail (its underside on the rail's top), a shank down the +x side
                // to the hanger and a short lip on the -x side, both clear of a rail up to 13 mm thick even at
                // 0.8 scale; the hanger's bar below the rail.
                const double hook = 0.06, bar = 0.02, top = g.h - hook - bar, in = 0.017, wire_w = 0.004;
                const double gt = n == 1 ? g.d : std::min(0.05, 0.8 * g.d / n);
                const std::vector<double> length = Fractions(g.rng, n, 0.6);
                for (int k = 0; k < n; ++k) {
                  const double y = n == 1 ? 0.0 : -g.d / 2 + gt / 2 + k * (g.d - gt) / (n - 1);
                  const double ya = y - wire_w / 2, yb = y + wire_w / 2;
                  g.out.Box(wire, {-in - wire_w, ya, g.h - kHookRise}, {in + wire_w, yb, g.h});
                  g.out.Box(wire, {in, ya, g.h - hook}, {in + wire_w, yb, g.h - kHookRise});
                  g.out.Box(wire, {-in - wire_w, ya, g.h - 0.02}, {-in, yb, g.h - kHookRise});
                  g.out.Box(wood, {-g.w / 2, y - 0.005, top}, {g.w / 2, y + 0.005, g.h - hook});
                  const double zb = top - top * length[k], sw = 0.45 * g.w, bw = g.rng.Range(0.35, 0.5) * g.w;
                  const double y0 = y - gt / 2, y1 = y + gt / 2;
                  g.out.Hexahedron(g.out.Part(g.rng.Pick(g.palette.fabric)), {Vec3{-bw, y0, zb},
                                                                              {bw, y0, zb},
                                                                              {bw, y1, zb},
                                                                              {-bw, y1, zb},
                                                                              {-sw, y0, top},
                                                                              {sw, y0, top},
                                                                              {sw, y1, top},
                                                                              {-sw, y1, top}});
                }
              }};
}

GeneratorDef Pillow() {
  return {
      .name = "pillow", .description = "pillow or cushion lying flat", .categories = {"pillow"}, .build = [](Gen& g) {
        const int fabric = g.out.Part(g.rng.Chance(0.5) ? g.rng.Pick(g.palette.fabric) : g.rng.Pick(g.palette.accent));
        g.out.Cushion(fabric, {-g.w / 2, -g.d / 2, 0}, {g.w / 2, g.d / 2, g.h}, std::min(0.04, 0.3 * g.h));
      }};
}

GeneratorDef Rug() {
  return {.name = "rug",
          .description = "rug: a field inside a border, rectangular or elliptic; its top is a surface",
          .categories = {"rug"},
          .extra = {CountParam("round", "1: elliptic, 0: rectangular", 0, 1)},
          .resolve =
              [](ParamValues& p, const CategoryInfo&, Rng& rng) {
                SetIfMissing(p, "round",
                             [&] { return rng.Chance(p.Word("style") == "scandinavian" ? 0.4 : 0.15) ? 1 : 0; });
              },
          .build =
              [](Gen& g) {
                const int field = g.out.Part(g.rng.Pick(g.palette.fabric));
                const int border = g.out.Part(g.rng.Pick(g.palette.accent));
                if (g.params.Int("round") == 1) {
                  g.out.VerticalLathe(border, {{0.88, 0}, {1, 0}, {1, g.h}, {0.88, g.h}}, 0, 0, g.w / 2, g.d / 2, 32);
                  g.out.Cylinder(field, 0, 0, 0.88 * g.w / 2, 0.88 * g.d / 2, 0, g.h, 32);
                  g.out.Surface(g.h, Ellipse(0, 0, g.w / 2, g.d / 2, 32), g.OpenAbove(g.h));
                  return;
                }
                const double b = 0.08 * std::min(g.w, g.d), x = g.w / 2, y = g.d / 2;
                g.out.Box(field, {-x + b, -y + b, 0}, {x - b, y - b, g.h});
                g.out.Box(border, {-x, -y, 0}, {-x + b, y, g.h});
                g.out.Box(border, {x - b, -y, 0}, {x, y, g.h});
                g.out.Box(border, {-x + b, -y, 0}, {x - b, -y + b, g.h});
                g.out.Box(border, {-x + b, y - b, 0}, {x - b, y, g.h});
                g.TopSurface(g.h, -x, -y, x, y);
              }};
}

// A rectangular frame (four bars in the x-z plane from y0 to y1) around w x h, bars `bar` m wide.
void FrameBars(MeshBuilder& out, int part, double w, double h, double bar, double y0, double y1) {
  out.Box(part, {-w / 2, y0, 0}, {-w / 2 + bar, y1, h});
  out.Box(part, {w / 2 - bar, y0, 0}, {w / 2, y1, h});
  out.Box(part, {-w / 2 + bar, y0, 0}, {w / 2 - bar, y1, bar});
  out.Box(part, {-w / 2 + bar, y0, h - bar}, {w / 2 - bar, y1, h});
}

GeneratorDef Frame() {
  return {
      .name = "frame",
      .description =
          "framed picture (an abstract of coloured bands) or whiteboard with a marker tray (hung, back at +y)",
      .categories = {"painting", "whiteboard"},
      .build = [](Gen& g) {
        if (g.Is("whiteboard")) {
          const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
          const double bar = 0.02, y0 = -g.d / 2 + 0.3 * g.d;
          FrameBars(g.out, metal, g.w, g.h, bar, y0, g.d / 2);
          g.out.Box(g.out.Part(Porcelain()), {-g.w / 2 + bar, y0 + 0.003, bar}, {g.w / 2 - bar, g.d / 2, g.h - bar});
          g.out.Box(metal, {-0.3 * g.w, -g.d / 2, bar}, {0.3 * g.w, y0, bar + 0.02});
          return;
        }
        const double bar = std::min(0.05, 0.08 * std::min(g.w, g.h));
        FrameBars(g.out, g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.wood)),
                  g.w, g.h, bar, -g.d / 2, g.d / 2);
        // The canvas is recessed behind the frame's front, painted in bands.
        const double yc = -g.d / 2 + 0.4 * g.d, x0 = -g.w / 2 + bar, x1 = g.w / 2 - bar;
        const int bands = g.rng.Int(2, 4);
        const std::vector<double> heights = Split(g.rng, g.h - 2 * bar, bands);
        double z = bar;
        for (int k = 0; k < bands; ++k) {
          const double z1 = k + 1 == bands ? g.h - bar : z + heights[k];
          g.out.Box(g.out.Part(g.rng.Pick(g.palette.accent)), {x0, yc, z}, {x1, g.d / 2, z1});
          z = z1;
        }
      }};
}

GeneratorDef Mirror() {
  return {.name = "mirror",
          .description = "wall mirror (hung, back at +y): a rectangular frame, or an oval one in the classic style",
          .categories = {"mirror"},
          .build = [](Gen& g) {
            const int frame =
                g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.wood));
            const int glass = g.out.Part(MirrorGlass());
            if (g.style == "classic") {
              const Vec3 origin{0, g.d / 2, g.h / 2};
              g.out.Lathe(frame, {{0.9, 0}, {1, 0}, {1, g.d}, {0.9, g.d}}, origin, kX * (g.w / 2), kZ * (g.h / 2),
                          kY * -1.0, 32);
              g.out.Lathe(glass, {{0, 0}, {0.9, 0}, {0.9, 0.6 * g.d}, {0, 0.6 * g.d}}, origin, kX * (g.w / 2),
                          kZ * (g.h / 2), kY * -1.0, 32);
              return;
            }
            const double bar = std::min(0.04, 0.08 * std::min(g.w, g.h));
            FrameBars(g.out, frame, g.w, g.h, bar, -g.d / 2, g.d / 2);
            g.out.Box(glass, {-g.w / 2 + bar, -g.d / 2 + 0.4 * g.d, bar}, {g.w / 2 - bar, g.d / 2, g.h - bar});
          }};
}

GeneratorDef Box() {
  return {
      .name = "box",
      .description = "storage box with a lid, or an open crate (rustic)",
      .categories = {"box"},
      .build = [](Gen& g) {
        const int body = g.out.Part(g.style == "rustic" ? g.rng.Pick(g.palette.wood) : g.rng.Pick(g.palette.paint));
        if (g.style == "rustic") {
          g.out.Tray(body, {-g.w / 2, -g.d / 2, 0}, {g.w / 2, g.d / 2, g.h}, 0.015, 0.015);
          return;
        }
        const double lid = std::min(0.025, 0.2 * g.h);
        g.out.Box(body, {-g.w / 2 + 0.004, -g.d / 2 + 0.004, 0}, {g.w / 2 - 0.004, g.d / 2 - 0.004, g.h - lid + 0.005});
        g.out.Box(g.out.Part(g.rng.Pick(g.palette.accent)), {-g.w / 2, -g.d / 2, g.h - lid}, {g.w / 2, g.d / 2, g.h});
      }};
}

GeneratorDef Decor() {
  return {.name = "decor",
          .description = "ornament: a sphere on a plinth, two stacked pebbles or a turned figurine (by seed)",
          .categories = {"decor"},
          .build = [](Gen& g) {
            const int a = g.out.Part(g.rng.Pick(g.palette.accent)), b = g.out.Part(g.rng.Pick(g.palette.accent));
            const double rx = g.w / 2, ry = g.d / 2, h = g.h;
            switch (g.rng.Int(0, 2)) {
              case 0:
                g.out.Cylinder(a, 0, 0, rx, ry, 0, 0.3 * h);
                g.out.Ellipsoid(b, 0, 0, 0.6 * rx, 0.6 * ry, 0.3 * h, h);
                break;
              case 1:
                g.out.RestingEllipsoid(a, 0, 0, rx, ry, 0, 0.55 * h);
                g.out.Ellipsoid(b, 0, 0, 0.6 * rx, 0.6 * ry, 0.45 * h, h);
                break;
              default:
                g.out.VerticalLathe(a,
                                    {{0, 0},
                                     {1, 0},
                                     {1, 0.08 * h},
                                     {0.4, 0.15 * h},
                                     {0.7, 0.5 * h},
                                     {0.3, 0.8 * h},
                                     {0.5, 0.9 * h},
                                     {0, h}},
                                    0, 0, rx, ry, 16);
            }
          }};
}

GeneratorDef Toy() {
  return {.name = "toy",
          .description = "toy: a teddy bear, building blocks, a toy car (along x) or a ball (by seed)",
          .categories = {"toy"},
          .build = [](Gen& g) {
            auto colour = [&] { return g.out.Part(g.rng.Pick(g.palette.accent)); };
            const double w = g.w, d = g.d, h = g.h;
            switch (g.rng.Int(0, 3)) {
              case 0: {  // teddy: body, head, arms
                const int fur = g.out.Part({"fur", 0.6, 0.42, 0.25, 1});
                g.out.RestingEllipsoid(fur, 0, 0, 0.35 * w, d / 2, 0, 0.6 * h);  // sitting
                g.out.Ellipsoid(fur, 0, 0, 0.25 * w, 0.4 * d, 0.55 * h, h);
                for (double s : {-1.0, 1.0})
                  g.out.Ellipsoid(fur, s * 0.375 * w, 0, 0.125 * w, 0.15 * d, 0.25 * h, 0.5 * h);
                break;
              }
              case 1:  // blocks: two side by side, one on top
                g.out.Box(colour(), {-w / 2, -d / 2, 0}, {-0.01, d / 2, h / 2});
                g.out.Box(colour(), {0.01, -0.4 * d, 0}, {w / 2, 0.4 * d, 0.45 * h});
                g.out.Box(colour(), {-0.25 * w, -0.35 * d, h / 2}, {0.25 * w, 0.35 * d, h});
                break;
              case 2: {  // car: body, cabin, four wheels of radius r
                const int body = colour();
                const double r = std::min(0.2 * h, 0.15 * w);
                g.out.Box(body, {-w / 2, -0.35 * d, r}, {w / 2, 0.35 * d, r + 0.45 * (h - r)});
                g.out.Box(body, {-0.25 * w, -0.3 * d, r + 0.45 * (h - r)}, {0.2 * w, 0.3 * d, h});
                const int tyre = g.out.Part(ScreenBlack());
                for (double x : {-0.3 * w, 0.3 * w}) {
                  g.out.Tube(tyre, {x, -d / 2, r}, {x, -0.3 * d, r}, r, 12);
                  g.out.Tube(tyre, {x, 0.3 * d, r}, {x, d / 2, r}, r, 12);
                }
                break;
              }
              default:  // a soft ball, flattened where it rests
                g.out.RestingEllipsoid(colour(), 0, 0, w / 2, d / 2, 0, h, 16);
            }
          }};
}

GeneratorDef Gadget() {
  return {.name = "gadget",
          .description =
              "small appliances and desk things, each a body with the detail that names it (door window, lens, slots, "
              "screen, handle...)",
          .categories = {"microwave", "printer", "projector", "phone", "speaker", "remote", "coffee-machine", "toaster",
                         "knife-stand", "stationery", "tools"},
          .build = [](Gen& g) {
            const double w = g.w, d = g.d, h = g.h;
            const int body = g.out.Part(g.Is("tools") ? g.rng.Pick(g.palette.accent) : Appliance(g.style));
            const int dark = g.out.Part(ScreenBlack());
            if (g.Is("microwave")) {
              g.out.Box(body, {-w / 2, -d / 2 + 0.01, 0}, {w / 2, d / 2, h});
              g.out.Box(dark, {-w / 2 + 0.03, -d / 2 + 0.003, 0.15 * h}, {0.2 * w, -d / 2 + 0.01, 0.85 * h});
              g.out.Box(dark, {0.25 * w, -d / 2, 0.1 * h}, {w / 2 - 0.02, -d / 2 + 0.01, 0.9 * h});
            } else if (g.Is("printer")) {
              g.out.Box(body, {-w / 2, -d / 2 + 0.02, 0}, {w / 2, d / 2, 0.8 * h});
              g.out.Box(body, {-0.45 * w, -d / 2 + 0.04, 0.8 * h}, {0.45 * w, d / 2 - 0.04, 0.86 * h});
              g.out.Box(g.out.Part(Paper()), {-0.35 * w, d / 2 - 0.03, 0.8 * h}, {0.35 * w, d / 2, h});
              g.out.Box(dark, {-0.35 * w, -d / 2, 0.3 * h}, {0.35 * w, -d / 2 + 0.02, 0.34 * h});
            } else if (g.Is("projector")) {
              g.out.Box(body, {-w / 2, -d / 2 + 0.02, 0}, {w / 2, d / 2, h});
              const double r = std::min(0.03, 0.35 * h);
              g.out.Tube(dark, {0.25 * w, -d / 2 + 0.02, h / 2}, {0.25 * w, -d / 2, h / 2}, r, 12);
            } else if (g.Is("phone") || g.Is("remote")) {
              const double top = g.Is("phone") ? std::min(0.001, 0.2 * h) : 0.2 * h;
              g.out.Box(body, {-w / 2, -d / 2, 0}, {w / 2, d / 2, h - top});
              g.out.Box(dark, {-w / 2 + 0.2 * w, -d / 2 + 0.1 * d, h - top}, {w / 2 - 0.2 * w, d / 2 - 0.1 * d, h});
            } else if (g.Is("speaker")) {
              g.out.Box(body, {-w / 2, -d / 2 + 0.005, 0}, {w / 2, d / 2, h});
              const double r = 0.35 * std::min(w, h);
              g.out.Lathe(dark, {{0, 0}, {1, 0}, {1, 0.005}, {0, 0.005}}, {0, -d / 2 + 0.005, 0.45 * h}, kX * r, kZ * r,
                          kY * -1.0, 16);
            } else if (g.Is("coffee-machine")) {
              g.out.Box(body, {-w / 2, 0, 0}, {w / 2, d / 2, h});
              g.out.Box(body, {-w / 2, -d / 2, 0}, {w / 2, 0, 0.12 * h});
              g.out.Box(dark, {-0.03, -0.3 * d, 0.6 * h}, {0.03, 0, 0.7 * h});
            } else if (g.Is("toaster")) {
              g.out.Box(body, {-w / 2, -d / 2, 0}, {w / 2 - 0.015, d / 2, h - 0.004});
              for (double y : {-0.3 * d, 0.05 * d})
                g.out.Box(dark, {-0.35 * w, y, h - 0.004}, {0.3 * w, y + 0.25 * d, h});
              g.out.Box(dark, {w / 2 - 0.015, -0.01, 0.5 * h}, {w / 2, 0.01, 0.6 * h});
            } else if (g.Is("knife-stand")) {
              const int wood = g.out.Part(g.rng.Pick(g.palette.wood));
              g.out.Hexahedron(wood, {Vec3{-w / 2, -d / 2, 0},
                                      {w / 2, -d / 2, 0},
                                      {w / 2, d / 2, 0},
                                      {-w / 2, d / 2, 0},
                                      {-w / 2, -d / 2, 0.6 * h},
                                      {w / 2, -d / 2, 0.6 * h},
                                      {w / 2, d / 2, 0.8 * h},
                                      {-w / 2, d / 2, 0.8 * h}});
              for (double x : {-0.25 * w, 0.0, 0.25 * w})
                g.out.Box(dark, {x - 0.008, -0.008, 0.65 * h}, {x + 0.008, 0.008, h});
            } else if (g.Is("stationery")) {
              if (std::max(w, d) > 2 * std::min(w, d) || h < 0.06) {  // a letter tray
                g.out.Tray(body, {-w / 2, -d / 2, 0}, {w / 2, d / 2, h}, 0.006, 0.006);
              } else {  // a pen pot with pens
                g.out.VerticalLathe(body,
                                    {{0, 0}, {1, 0}, {1, 0.75 * h}, {0.9, 0.75 * h}, {0.9, 0.1 * h}, {0, 0.1 * h}}, 0,
                                    0, w / 2, d / 2, 16);
                const int pen = g.out.Part(g.rng.Pick(g.palette.accent));
                for (Point p : {Point{-0.3, 0.1}, Point{0.25, -0.2}, Point{0.1, 0.35}})
                  g.out.Cylinder(pen, p.x * w / 2, p.y * d / 2, 0.004, 0.004, 0.1 * h, h, 8);
              }
            } else {  // tools: a toolbox with a handle
              g.out.Box(body, {-w / 2, -d / 2, 0}, {w / 2, d / 2, 0.75 * h});
              for (double x : {-0.3 * w, 0.3 * w - 0.015}) g.out.Box(dark, {x, -0.01, 0.75 * h}, {x + 0.015, 0.01, h});
              g.out.Box(dark, {-0.3 * w, -0.01, 0.92 * h}, {0.3 * w, 0.01, h});
            }
          }};
}

GeneratorDef Slippers() {
  return {.name = "slippers",
          .description = "a pair of slippers side by side, toes at -y",
          .categories = {"slippers"},
          .build = [](Gen& g) {
            const int sole = g.out.Part(ScreenBlack()), upper = g.out.Part(g.rng.Pick(g.palette.fabric));
            for (auto [x0, x1] : {std::pair{-g.w / 2, -0.01}, std::pair{0.01, g.w / 2}}) {
              g.out.Box(sole, {x0, -g.d / 2, 0}, {x1, g.d / 2, 0.3 * g.h});
              g.out.Cushion(upper, {x0, -g.d / 2, 0.3 * g.h}, {x1, 0.05 * g.d, g.h}, std::min(0.01, 0.2 * g.h), 0.0);
            }
          }};
}

GeneratorDef Plant() {
  return {.name = "plant",
          .description = "potted plant: a pot with soil, a stem and rounded foliage",
          .categories = {"plant", "small-plant"},
          .build = [](Gen& g) {
            const int pot = g.out.Part(g.style == "rustic" ? MeshMaterial{"terracotta-pot", 0.7, 0.38, 0.25, 1}
                                                           : g.rng.Pick(g.palette.accent));
            const int leaf = g.out.Part(Foliage(g.rng));
            const double rp = 0.55 * std::min(g.w, g.d) / 2, hp = (g.Is("small-plant") ? 0.4 : 0.3) * g.h;
            g.out.VerticalLathe(pot, {{0, 0}, {0.75, 0}, {1, hp}, {0, hp}}, 0, 0, rp, rp, 16);
            g.out.Cylinder(g.out.Part(Soil()), 0, 0, 0.9 * rp, 0.9 * rp, hp, hp + 0.005, 16);
            const double fh = 0.6 * (g.h - hp);
            g.out.Cylinder(g.out.Part({"stem", 0.35, 0.28, 0.18, 1}), 0, 0, 0.012, 0.012, hp, g.h - fh / 2, 8);
            g.out.Ellipsoid(leaf, 0, 0, g.w / 2, g.d / 2, g.h - fh, g.h, 12);
            for (int k = 0; k < 3; ++k) {
              const double x = g.rng.Range(-0.4, 0.4) * g.w / 2, y = g.rng.Range(-0.4, 0.4) * g.d / 2;
              const double z1 = g.h - fh * g.rng.Range(0.2, 0.5);
              g.out.Ellipsoid(leaf, x, y, 0.5 * g.w / 2, 0.5 * g.d / 2, std::max(hp, z1 - 0.8 * fh), z1, 12);
            }
          }};
}

GeneratorDef Planter() {
  return {.name = "planter",
          .description = "flower box filled with soil (its top the surface small plants stand on)",
          .categories = {"flower-box"},
          .build = [](Gen& g) {
            const int box = g.out.Part(g.style == "rustic" ? g.rng.Pick(g.palette.wood) : g.rng.Pick(g.palette.paint));
            const double wall = 0.02, rim = 0.02;
            g.out.Tray(box, {-g.w / 2, -g.d / 2, 0}, {g.w / 2, g.d / 2, g.h}, wall, wall);
            g.out.Box(g.out.Part(Soil()), {-g.w / 2 + wall, -g.d / 2 + wall, wall},
                      {g.w / 2 - wall, g.d / 2 - wall, g.h - rim});
            g.out.Surface(g.h - rim, Rect(-g.w / 2 + wall, -g.d / 2 + wall, g.w / 2 - wall, g.d / 2 - wall),
                          g.OpenAbove(g.h - rim));
          }};
}

GeneratorDef Basket() {
  return {.name = "basket",
          .description = "open basket: a rectangular laundry basket or a round bin",
          .categories = {"laundry-basket", "bin"},
          .build = [](Gen& g) {
            const int body = g.out.Part(g.style == "rustic" || g.style == "classic" ? g.rng.Pick(g.palette.wood)
                                                                                    : g.rng.Pick(g.palette.paint));
            if (g.Is("laundry-basket")) {
              g.out.Tray(body, {-g.w / 2, -g.d / 2, 0}, {g.w / 2, g.d / 2, g.h}, 0.012, 0.012);
              return;
            }
            g.out.VerticalLathe(body, {{0, 0}, {0.85, 0}, {1, g.h}, {0.95, g.h}, {0.8, 0.015}, {0, 0.015}}, 0, 0,
                                g.w / 2, g.d / 2, 24);
          }};
}

GeneratorDef Kettle() {
  return {
      .name = "kettle",
      .description = "kettle or teapot: a body with a lid knob, a spout to -x and a handle at +x",
      .categories = {"kettle"},
      .build = [](Gen& g) {
        const int body = g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.accent));
        const int dark = g.out.Part(ScreenBlack());
        const double rb = std::min(g.d / 2, 0.35 * g.w), h = g.h;
        g.out.VerticalLathe(body, {{0, 0}, {1, 0}, {1, 0.7 * h}, {0.7, 0.9 * h}, {0, 0.9 * h}}, 0, 0, rb, g.d / 2, 16);
        g.out.Cylinder(dark, 0, 0, 0.2 * rb, 0.2 * rb, 0.9 * h, h, 8);
        g.out.Tube(body, {-0.9 * rb, 0, 0.55 * h}, {-g.w / 2, 0, 0.55 * h}, 0.012, 8);
        const double x1 = g.w / 2 - 0.02;
        g.out.Box(dark, {x1, -0.012, 0.2 * h}, {g.w / 2, 0.012, 0.85 * h});
        g.out.Box(dark, {0.9 * rb, -0.012, 0.75 * h}, {x1, 0.012, 0.85 * h});
        g.out.Box(dark, {0.9 * rb, -0.012, 0.2 * h}, {x1, 0.012, 0.28 * h});
      }};
}

GeneratorDef ClothesHorse() {
  return {.name = "clothes-horse",
          .description = "drying rack: four legs, rails along x at the top and bars across the middle",
          .categories = {"clothes-horse"},
          .build = [](Gen& g) {
            const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
            const double r = 0.01, x = g.w / 2 - r, y = g.d / 2 - r;
            for (double sx : {-x, x})
              for (double sy : {-y, y}) g.out.Cylinder(metal, sx, sy, r, r, 0, g.h, 8);
            for (double sy : {-y, y}) g.out.Tube(metal, {-g.w / 2, sy, g.h - r}, {g.w / 2, sy, g.h - r}, 0.7 * r);
            for (double sx : {-x, x}) g.out.Tube(metal, {sx, -y, g.h - 2.5 * r}, {sx, y, g.h - 2.5 * r}, 0.7 * r);
            for (int k = 1; k <= 3; ++k) {
              const double sy = -y + 2 * y * k / 4;
              g.out.Tube(metal, {-x, sy, 0.75 * g.h}, {x, sy, 0.75 * g.h}, 0.5 * r);
            }
          }};
}

GeneratorDef Broom() {
  return {.name = "broom",
          .description = "broom standing upright: a bristle head on the floor and a handle",
          .categories = {"broom"},
          .build = [](Gen& g) {
            const int wood = g.out.Part(g.rng.Pick(g.palette.wood));
            const int bristle = g.out.Part(ScreenBlack());
            const double head = std::min(0.04, g.d / 2);
            g.out.Box(bristle, {-g.w / 2 + 0.01, -g.d / 2, 0}, {g.w / 2 - 0.01, g.d / 2, 0.06});
            g.out.Box(wood, {-g.w / 2, -head, 0.06}, {g.w / 2, head, 0.1});
            g.out.Cylinder(wood, 0, 0, 0.012, 0.012, 0.1, g.h, 8);
          }};
}

}  // namespace

std::vector<GeneratorDef> SmallGenerators() {
  return {
      Books(), Plate(),         Bowl(),           Cup(),    Bottle(),  Vase(),   Candle(), Roll(),         Dispenser(),
      Jar(),   FoldedClothes(), HangingClothes(), Pillow(), Rug(),     Frame(),  Mirror(), Box(),          Decor(),
      Toy(),   Gadget(),        Slippers(),       Plant(),  Planter(), Basket(), Kettle(), ClothesHorse(), Broom()};
}

}  // namespace villa::procedural
