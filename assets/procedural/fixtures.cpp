// Appliances, bathroom fixtures, lamps, screens and clocks: recognisable simple shapes, with the top
// surfaces the priors put things on (a cooker's hob, a washer's top, a washbasin's counter).
#include <algorithm>
#include <cmath>

#include "assets/procedural/generator.h"

namespace villa::procedural {
namespace {

constexpr Vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

// A disc or ring facing -y: lathe about the axis through (cx, y_back, cz) pointing to -y, radii (rx, rz)
// along x and z; `profile` in (r, distance towards -y).
void FrontLathe(MeshBuilder& out, int part, const std::vector<Point>& profile, double cx, double y_back, double cz,
                double rx, double rz, int segments = 24) {
  out.Lathe(part, profile, {cx, y_back, cz}, kX * rx, kZ * rz, kY * -1.0, segments);
}

GeneratorDef Fridge() {
  return {.name = "fridge",
          .description = "fridge-freezer: body, freezer door below, fridge door above, bar handles at -y",
          .categories = {"fridge"},
          .build = [](Gen& g) {
            const int body = g.out.Part(Appliance(g.style));
            const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
            const double y_doors = -g.d / 2 + 0.025, y_body = y_doors + 0.04, split = 0.35 * g.h;
            g.out.Box(body, {-g.w / 2, y_body, 0}, {g.w / 2, g.d / 2, g.h});
            g.out.Box(body, {-g.w / 2 + 0.004, y_doors, 0.01}, {g.w / 2 - 0.004, y_body, split});
            g.out.Box(body, {-g.w / 2 + 0.004, y_doors, split + 0.006}, {g.w / 2 - 0.004, y_body, g.h - 0.01});
            const double hx = g.w / 2 - 0.06;
            g.out.Box(metal, {hx, -g.d / 2, split - 0.25 * split}, {hx + 0.015, y_doors, split - 0.04});
            g.out.Box(metal, {hx, -g.d / 2, split + 0.05}, {hx + 0.015, y_doors, split + 0.05 + 0.3 * (g.h - split)});
          }};
}

GeneratorDef Cooker() {
  return {
      .name = "cooker",
      .description = "free-standing cooker: oven door with window, knobs, a glass hob (top surface), backguard at +y",
      .categories = {"cooker"},
      .build = [](Gen& g) {
        const int body = g.out.Part(Appliance(g.style));
        const int black = g.out.Part(ScreenBlack());
        const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
        const double guard = 0.08, hob = 0.006, zb = g.h - guard - hob;  // top of the body
        const double y_front = -g.d / 2 + 0.03;
        g.out.Box(body, {-g.w / 2, y_front, 0}, {g.w / 2, g.d / 2, zb});
        g.out.Box(body, {-g.w / 2, g.d / 2 - 0.04, zb}, {g.w / 2, g.d / 2, g.h});
        g.out.Box(black, {-g.w / 2 + 0.01, y_front + 0.01, zb}, {g.w / 2 - 0.01, g.d / 2 - 0.05, zb + hob});
        g.out.Surface(zb + hob, Rect(-g.w / 2 + 0.01, y_front + 0.01, g.w / 2 - 0.01, g.d / 2 - 0.05),
                      g.OpenAbove(zb + hob));
        const double door_top = zb - 0.12;
        g.out.Box(body, {-g.w / 2 + 0.02, y_front - 0.012, 0.08}, {g.w / 2 - 0.02, y_front, door_top});
        g.out.Box(black, {-g.w / 2 + 0.08, y_front - 0.016, 0.2}, {g.w / 2 - 0.08, y_front - 0.012, door_top - 0.1});
        g.out.Tube(metal, {-0.35 * g.w, -g.d / 2 + 0.008, door_top - 0.04},
                   {0.35 * g.w, -g.d / 2 + 0.008, door_top - 0.04}, 0.008);
        for (int k = 0; k < 4; ++k) {
          const double x = -g.w / 2 + g.w * (k + 0.5) / 4;
          FrontLathe(g.out, metal, {{0, 0}, {1, 0}, {1, 0.018}, {0, 0.018}}, x, y_front, zb - 0.06, 0.016, 0.016, 12);
        }
      }};
}

GeneratorDef Dishwasher() {
  return {
      .name = "dishwasher",
      .description = "dishwasher: body, full-height door with a bar handle and a control strip",
      .categories = {"dishwasher"},
      .build = [](Gen& g) {
        const int body = g.out.Part(Appliance(g.style));
        const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
        const int black = g.out.Part(ScreenBlack());
        const double y_door = -g.d / 2 + 0.016, y_body = y_door + 0.02;
        g.out.Box(body, {-g.w / 2, y_body, 0}, {g.w / 2, g.d / 2, g.h});
        g.out.Box(body, {-g.w / 2 + 0.003, y_door, 0.08}, {g.w / 2 - 0.003, y_body, g.h - 0.003});
        g.out.Box(black, {-g.w / 2 + 0.02, y_door - 0.002, g.h - 0.07}, {g.w / 2 - 0.02, y_door, g.h - 0.02});
        g.out.Tube(metal, {-0.3 * g.w, -g.d / 2 + 0.008, g.h - 0.12}, {0.3 * g.w, -g.d / 2 + 0.008, g.h - 0.12}, 0.008);
      }};
}

GeneratorDef Washer() {
  return {.name = "washer",
          .description = "front-loading washing machine or dryer: round door at -y, control panel, a top surface",
          .categories = {"washing-machine", "dryer"},
          .build = [](Gen& g) {
            const int body = g.out.Part(Appliance(g.style));
            const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
            const int glass = g.out.Part(g.Is("dryer") ? ScreenBlack() : Glass());
            const double y_body = -g.d / 2 + 0.04;
            g.out.Box(body, {-g.w / 2, y_body, 0}, {g.w / 2, g.d / 2, g.h});
            g.TopSurface(g.h, -g.w / 2, y_body, g.w / 2, g.d / 2);
            const double r = 0.3 * g.w, zc = 0.45 * g.h;
            FrontLathe(g.out, metal, {{0.78, 0}, {1, 0}, {1, 0.04}, {0.78, 0.04}}, 0, y_body, zc, r, r);
            FrontLathe(g.out, glass, {{0, 0}, {0.8, 0}, {0.8, 0.025}, {0, 0.025}}, 0, y_body, zc, r, r);
            g.out.Box(metal, {-g.w / 2 + 0.03, y_body - 0.01, g.h - 0.1}, {-0.1 * g.w, y_body, g.h - 0.03});
            FrontLathe(g.out, metal, {{0, 0}, {1, 0}, {1, 0.02}, {0, 0.02}}, 0.3 * g.w, y_body, g.h - 0.065, 0.025,
                       0.025, 12);
          }};
}

GeneratorDef RangeHood() {
  return {.name = "range-hood",
          .description = "chimney hood (hung, back at +y): a canopy tapering up into a chimney",
          .categories = {"range-hood"},
          .build = [](Gen& g) {
            const int body = g.out.Part(Appliance(g.style));
            const double canopy = std::min(0.25, 0.5 * g.h), cw = 0.15 * g.w + 0.05, cd = std::min(0.25, 0.6 * g.d);
            g.out.Box(body, {-g.w / 2, -g.d / 2, 0}, {g.w / 2, g.d / 2, 0.05});
            const double yt = g.d / 2 - cd - 0.03;
            g.out.Hexahedron(body, {Vec3{-g.w / 2, -g.d / 2, 0.05},
                                    {g.w / 2, -g.d / 2, 0.05},
                                    {g.w / 2, g.d / 2, 0.05},
                                    {-g.w / 2, g.d / 2, 0.05},
                                    {-cw - 0.03, yt, canopy},
                                    {cw + 0.03, yt, canopy},
                                    {cw + 0.03, g.d / 2, canopy},
                                    {-cw - 0.03, g.d / 2, canopy}});
            g.out.Box(body, {-cw, g.d / 2 - cd, canopy}, {cw, g.d / 2, g.h});
          }};
}

GeneratorDef WaterHeater() {
  return {.name = "water-heater",
          .description = "wall boiler (hung, back at +y): a domed cylinder with a control box at -y",
          .categories = {"water-heater"},
          .build = [](Gen& g) {
            const int body = g.out.Part(Porcelain());
            const int black = g.out.Part(ScreenBlack());
            const double ry = (g.d - 0.03) / 2, h = g.h;
            g.out.VerticalLathe(body, {{0, 0}, {0.8, 0}, {1, 0.08 * h}, {1, 0.92 * h}, {0.8, h}, {0, h}}, 0, 0.015,
                                g.w / 2, ry, 24);
            g.out.Box(black, {-0.06, -g.d / 2, 0.2 * h}, {0.06, -g.d / 2 + 0.04, 0.2 * h + 0.08});
          }};
}

GeneratorDef WaterCooler() {
  return {
      .name = "water-cooler",
      .description = "water dispenser: a cabinet with taps at -y and an upturned bottle on top",
      .categories = {"water-cooler"},
      .build = [](Gen& g) {
        const int body = g.out.Part(Appliance(g.style));
        const int water = g.out.Part(Glass());
        const int black = g.out.Part(ScreenBlack());
        const double zc = 0.62 * g.h;
        g.out.Box(body, {-g.w / 2, -g.d / 2 + 0.03, 0}, {g.w / 2, g.d / 2, zc});
        const double r = 0.4 * std::min(g.w, g.d), bh = g.h - zc;
        g.out.VerticalLathe(
            water,
            {{0, zc}, {0.3, zc}, {0.3, zc + 0.1 * bh}, {1, zc + 0.3 * bh}, {1, zc + 0.9 * bh}, {0.8, g.h}, {0, g.h}}, 0,
            0.015, r, r, 16);
        for (double x : {-0.06, 0.04})
          g.out.Box(black, {x, -g.d / 2, 0.5 * g.h}, {x + 0.02, -g.d / 2 + 0.03, 0.5 * g.h + 0.05});
      }};
}

GeneratorDef Toilet() {
  return {.name = "toilet",
          .description = "toilet: pedestal bowl opening up, seat ring, cistern at +y against the wall",
          .categories = {"toilet"},
          .build = [](Gen& g) {
            const int china = g.out.Part(Porcelain());
            const int seat =
                g.out.Part(g.style == "classic" || g.style == "rustic" ? g.rng.Pick(g.palette.wood) : Porcelain());
            const double tank = 0.18, zt = 0.4;
            g.out.Box(china, {-g.w / 2, g.d / 2 - tank, zt}, {g.w / 2, g.d / 2, g.h});
            const double rx = 0.45 * g.w, ry = (g.d - 0.16) / 2, yc = -g.d / 2 + ry;
            g.out.VerticalLathe(
                china, {{0, 0}, {0.55, 0}, {0.5, 0.15}, {0.85, 0.3}, {1, zt}, {0.88, zt}, {0.55, 0.25}, {0, 0.25}}, 0,
                yc, rx, ry, 24);
            g.out.VerticalLathe(seat, {{0.7, zt}, {1, zt}, {1, zt + 0.02}, {0.7, zt + 0.02}}, 0, yc, rx, ry, 24);
            // The foot runs back under the cistern (the trapway), as a real one does: the cistern's weight
            // over the floor, not behind the bowl's round foot (dropped in a simulator, it tipped back).
            // Behind the bowl's opening (not up through it), under the cistern.
            g.out.Box(china, {-0.2 * g.w, yc + 0.9 * ry, 0}, {0.2 * g.w, g.d / 2 - 0.06, zt});
          }};
}

GeneratorDef Washbasin() {
  return {
      .name = "washbasin",
      .description =
          "vanity: a cabinet with a door, a counter (surfaces left and right of the basin), a vessel basin and a tap",
      .categories = {"washbasin"},
      .build = [](Gen& g) {
        const int wood = g.out.Part(g.style == "modern" || g.style == "scandinavian" ? g.rng.Pick(g.palette.paint)
                                                                                     : g.rng.Pick(g.palette.wood));
        const int china = g.out.Part(Porcelain());
        const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
        const double zt = g.h - 0.16, slab = 0.03;
        g.out.Box(wood, {-g.w / 2 + 0.01, -g.d / 2 + 0.03, 0}, {g.w / 2 - 0.01, g.d / 2, zt - slab});
        g.out.Box(wood, {-g.w / 2 + 0.015, -g.d / 2 + 0.01, 0.1},
                  {g.w / 2 - 0.015, -g.d / 2 + 0.03, zt - slab - 0.005});
        g.out.Box(metal, {-0.1 * g.w, -g.d / 2, zt - slab - 0.05}, {0.1 * g.w, -g.d / 2 + 0.01, zt - slab - 0.04});
        g.out.Box(china, {-g.w / 2, -g.d / 2, zt - slab}, {g.w / 2, g.d / 2, zt});
        const double rb = std::min(0.2, 0.3 * g.w), rby = std::min(0.2, 0.3 * g.d), yb = -g.d / 2 + 0.04 + rby;
        g.out.VerticalLathe(china,
                            {{0, zt}, {0.5, zt}, {1, zt + 0.13}, {0.9, zt + 0.13}, {0.42, zt + 0.02}, {0, zt + 0.02}},
                            0, yb, rb, rby, 24);
        const double ty = g.d / 2 - 0.05;
        g.out.Cylinder(metal, 0, ty, 0.018, 0.018, zt, g.h, 12);
        g.out.Tube(metal, {0, ty, g.h - 0.02}, {0, ty - 0.12, g.h - 0.02}, 0.01);
        for (double side : {-1.0, 1.0}) {
          const double a = side * (rb + 0.01), b = side * g.w / 2;
          g.out.Surface(zt, Rect(std::min(a, b), -g.d / 2, std::max(a, b), g.d / 2), g.OpenAbove(zt));
        }
      }};
}

GeneratorDef Bathtub() {
  return {.name = "bathtub",
          .description = "bathtub: a tub open at the top, on four feet in the classic style",
          .categories = {"bathtub"},
          .build = [](Gen& g) {
            const int china = g.out.Part(Porcelain());
            const bool feet = g.style == "classic";
            const double z0 = feet ? 0.1 : 0.0;
            g.out.Tray(china, {-g.w / 2, -g.d / 2, z0}, {g.w / 2, g.d / 2, g.h}, 0.06, 0.05);
            if (feet) {
              const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
              for (double x : {-g.w / 2 + 0.15, g.w / 2 - 0.15})
                for (double y : {-g.d / 2 + 0.1, g.d / 2 - 0.1}) g.Leg(metal, x, y, 0, z0, 0.035);
            }
          }};
}

GeneratorDef Shower() {
  return {.name = "shower",
          .description = "shower: a tray, glass screens at -y (with an opening) and +x, a riser with a head at +y",
          .categories = {"shower"},
          .build = [](Gen& g) {
            const int china = g.out.Part(Porcelain());
            const int glass = g.out.Part(Glass());
            const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
            const double tray = 0.06;
            g.out.Box(china, {-g.w / 2, -g.d / 2, 0}, {g.w / 2, g.d / 2, tray});
            g.out.Box(glass, {-g.w / 2, -g.d / 2, tray}, {0.1 * g.w, -g.d / 2 + 0.008, g.h});
            g.out.Box(glass, {g.w / 2 - 0.008, -g.d / 2 + 0.01, tray}, {g.w / 2, g.d / 2, g.h});
            const double x = -g.w / 2 + 0.1, y = g.d / 2 - 0.03, top = g.h - 0.1;
            g.out.Cylinder(metal, x, y, 0.012, 0.012, tray, top, 8);
            g.out.Tube(metal, {x, y, top - 0.01}, {x, y - 0.25, top - 0.01}, 0.01);
            g.out.Cylinder(metal, x, y - 0.25, 0.08, 0.08, top - 0.05, top - 0.02, 16);
          }};
}

GeneratorDef TowelRack() {
  return {.name = "towel-rack",
          .description = "towel rail (hung, back at +y): two side tubes on wall brackets with bars across",
          .categories = {"towel-rack"},
          .build = [](Gen& g) {
            const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
            const double r = std::min(0.0125, g.d / 4), y = -g.d / 2 + r;
            for (double side : {-1.0, 1.0}) {
              const double x = side * (g.w / 2 - r);
              g.out.Cylinder(metal, x, y, r, r, 0, g.h, 8);
              g.out.Box(metal, {x - 0.008, y + r - 0.002, 0.3 * g.h}, {x + 0.008, g.d / 2, 0.3 * g.h + 0.03});
            }
            const int bars = std::clamp(static_cast<int>(std::lround(g.h / 0.12)), 1, 8);
            for (int k = 0; k < bars; ++k) {
              const double z = g.h * (k + 0.5) / bars;
              g.out.Tube(metal, {-g.w / 2 + r, y, z}, {g.w / 2 - r, y, z}, 0.6 * r);
            }
          }};
}

GeneratorDef Sink() {
  return {.name = "sink",
          .description = "kitchen sink unit standing on a counter: a basin, a rear deck and a tap at +y",
          .categories = {"sink"},
          .build = [](Gen& g) {
            const int steel =
                g.out.Part(g.style == "classic" || g.style == "rustic" ? Porcelain() : g.rng.Pick(g.palette.metal));
            const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
            const double hb = std::min(0.18, g.h - 0.05), deck = 0.07;
            g.out.Tray(steel, {-g.w / 2, -g.d / 2, 0}, {g.w / 2, g.d / 2 - deck, hb}, 0.02, 0.015);
            g.out.Box(steel, {-g.w / 2, g.d / 2 - deck, 0}, {g.w / 2, g.d / 2, hb});
            const double ty = g.d / 2 - deck / 2;
            g.out.Cylinder(metal, 0, ty, 0.02, 0.02, hb, g.h, 12);
            g.out.Tube(metal, {0, ty, g.h - 0.03}, {0, ty - 0.2, g.h - 0.03}, 0.011);
          }};
}

GeneratorDef Screen() {
  return {
      .name = "screen",
      .description = "flat screen facing -y: a TV on two feet or a monitor on a stand",
      .categories = {"tv", "monitor"},
      .build = [](Gen& g) {
        const int body = g.out.Part(g.rng.Pick(g.palette.metal));
        const int black = g.out.Part(ScreenBlack());
        if (g.Is("tv")) {
          const double pd = std::min(0.05, 0.5 * g.d), feet = 0.025;
          for (double x : {-0.35 * g.w, 0.35 * g.w})
            g.out.Box(body, {x - 0.03, -g.d / 2, 0}, {x + 0.03, g.d / 2, feet});
          g.out.Box(body, {-g.w / 2, -pd / 2 + 0.002, feet}, {g.w / 2, pd / 2, g.h});
          g.out.Box(black, {-g.w / 2 + 0.012, -pd / 2, feet + 0.03}, {g.w / 2 - 0.012, -pd / 2 + 0.002, g.h - 0.012});
          return;
        }
        const double pd = std::min(0.03, 0.4 * g.d), ph = std::min(g.h - 0.08, 0.62 * g.w);
        g.out.Box(body, {-std::min(0.12, 0.3 * g.w), -g.d / 2, 0}, {std::min(0.12, 0.3 * g.w), g.d / 2, 0.015});
        g.out.Box(body, {-0.025, pd / 2, 0.015}, {0.025, std::min(g.d / 2, pd / 2 + 0.025), g.h - ph / 2});
        g.out.Box(body, {-g.w / 2, -pd / 2 + 0.002, g.h - ph}, {g.w / 2, pd / 2, g.h});
        g.out.Box(black, {-g.w / 2 + 0.01, -pd / 2, g.h - ph + 0.02}, {g.w / 2 - 0.01, -pd / 2 + 0.002, g.h - 0.01});
      }};
}

GeneratorDef Laptop() {
  return {.name = "laptop",
          .description = "closed laptop: a base and a lid",
          .categories = {"laptop"},
          .build = [](Gen& g) {
            const int base = g.out.Part(g.rng.Pick(g.palette.metal));
            const int lid = g.out.Part(ScreenBlack());
            g.out.Box(base, {-g.w / 2, -g.d / 2, 0}, {g.w / 2, g.d / 2, 0.55 * g.h});
            g.out.Box(lid, {-g.w / 2 + 0.001, -g.d / 2 + 0.001, 0.55 * g.h}, {g.w / 2 - 0.001, g.d / 2 - 0.001, g.h});
          }};
}

// A lamp shade about (0, cy): a thin frustum open at both ends, bottom radii (rx, ry), the top `top` times
// smaller.
void Shade(Gen& g, int part, double cy, double rx, double ry, double z0, double z1, double top) {
  g.out.VerticalLathe(part, {{0.95, z0}, {1.0, z0}, {top, z1}, {top - 0.05, z1}}, 0, cy, rx, ry, 24);
}

GeneratorDef Lamp() {
  return {.name = "lamp",
          .description =
              "floor lamp (base, pole, shade), table lamp (turned body, shade), wall lamp (back plate at +y, arm, "
              "shade) or ceiling pendant (canopy at the top, cord, dome)",
          .categories = {"floor-lamp", "table-lamp", "wall-lamp", "ceiling-lamp"},
          .build = [](Gen& g) {
            const int metal = g.out.Part(g.rng.Pick(g.palette.metal));
            const int shade =
                g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.fabric));
            if (g.Is("ceiling-lamp")) {
              const double sh = std::min(g.h - 0.04, std::max(0.1, 0.5 * g.h)), canopy = std::min(0.06, 0.2 * g.w);
              g.out.VerticalLathe(shade, {{0, sh - 0.015}, {0.95, 0}, {1, 0}, {0.35, sh}, {0, sh}}, 0, 0, g.w / 2,
                                  g.d / 2, 24);
              g.out.Cylinder(metal, 0, 0, 0.005, 0.005, sh, g.h - 0.03, 8);
              g.out.Cylinder(metal, 0, 0, canopy, canopy, g.h - 0.03, g.h, 16);
              return;
            }
            if (g.Is("wall-lamp")) {
              const double plate = std::min(0.015, 0.2 * g.d), ry = std::min(g.w / 2, 0.4 * g.d), cy = -g.d / 2 + ry;
              const double sh = 0.5 * g.h, arm_z = g.h - 0.6 * sh;
              g.out.Box(metal, {-std::min(0.04, 0.4 * g.w), g.d / 2 - plate, 0},
                        {std::min(0.04, 0.4 * g.w), g.d / 2, 0.75 * g.h});
              Shade(g, shade, cy, g.w / 2, ry, g.h - sh, g.h, 0.7);
              if (g.d / 2 - plate - cy > 0.005)
                g.out.Tube(metal, {0, g.d / 2 - plate, arm_z}, {0, cy, arm_z}, std::min(0.006, 0.1 * g.h));
              return;
            }
            const bool floor = g.Is("floor-lamp");
            const double sh = floor ? std::min(0.35, 0.3 * g.h) : 0.45 * g.h;
            Shade(g, shade, 0, g.w / 2, g.d / 2, g.h - sh, g.h, 0.7);
            if (floor) {
              g.out.Cylinder(metal, 0, 0, 0.6 * g.w / 2, 0.6 * g.d / 2, 0, 0.03, 24);
              g.out.Cylinder(metal, 0, 0, 0.012, 0.012, 0.03, g.h - 0.4 * sh, 8);
            } else {
              const int body = g.out.Part(g.rng.Pick(g.palette.accent));
              const double l = 0.55 * g.h;
              g.out.VerticalLathe(body,
                                  {{0, 0}, {0.5, 0}, {0.8, 0.2 * l}, {0.85, 0.5 * l}, {0.4, 0.9 * l}, {0.2, l}, {0, l}},
                                  0, 0, 0.5 * g.w / 2, 0.5 * g.d / 2, 16);
              g.out.Cylinder(metal, 0, 0, 0.006, 0.006, l, g.h - 0.4 * sh, 8);
            }
          }};
}

GeneratorDef Clock() {
  return {
      .name = "clock",
      .description = "wall clock (round face, or a case with a pendulum when tall; hung, back at +y) or alarm clock",
      .categories = {"clock", "alarm-clock"},
      .build = [](Gen& g) {
        const int body = g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.wood));
        const int face = g.out.Part(Paper());
        const int black = g.out.Part(ScreenBlack());
        // Front to back: hands from y0 to y1, the face from y1 to y2, the body behind y2.
        const double y0 = -g.d / 2, y1 = y0 + 0.002, y2 = y1 + 0.004;
        const std::vector<Point> disc = {{0, 0}, {1, 0}, {1, y2 - y1}, {0, y2 - y1}};
        double cz, r;
        if (g.Is("alarm-clock")) {
          g.out.Box(body, {-g.w / 2, y2, 0}, {g.w / 2, g.d / 2, g.h});
          cz = g.h / 2;
          r = 0.4 * std::min(g.w, g.h);
          FrontLathe(g.out, face, disc, 0, y2, cz, r, r);
        } else if (g.h > 1.25 * g.w) {
          g.out.Box(body, {-g.w / 2, y2, 0}, {g.w / 2, g.d / 2, g.h});
          r = 0.4 * g.w;
          cz = g.h - 0.5 * g.w;
          FrontLathe(g.out, face, disc, 0, y2, cz, r, r);
          g.out.Box(black, {-0.004, y1 + 0.001, 0.15 * g.h}, {0.004, y2, cz - r - 0.01});
          FrontLathe(g.out, body, disc, 0, y2, 0.15 * g.h, 0.08 * g.w, 0.08 * g.w, 16);
        } else {
          cz = g.h / 2;
          FrontLathe(g.out, body, {{0, 0}, {1, 0}, {1, g.d / 2 - y2}, {0, g.d / 2 - y2}}, 0, g.d / 2, cz, g.w / 2,
                     g.h / 2, 32);
          FrontLathe(g.out, face, {{0, 0}, {0.88, 0}, {0.88, y2 - y1}, {0, y2 - y1}}, 0, y2, cz, g.w / 2, g.h / 2, 32);
          r = 0.8 * std::min(g.w, g.h) / 2;
        }
        g.out.Box(black, {-0.004, y0, cz - 0.01}, {0.004, y1, cz + 0.6 * r});
        g.out.Box(black, {-0.01, y0, cz - 0.004}, {0.8 * r, y1, cz + 0.004});
      }};
}

}  // namespace

std::vector<GeneratorDef> FixtureGenerators() {
  return {Fridge(),  Cooker(), Dishwasher(), Washer(), RangeHood(), WaterHeater(), WaterCooler(), Toilet(), Washbasin(),
          Bathtub(), Shower(), TowelRack(),  Sink(),   Screen(),    Laptop(),      Lamp(),        Clock()};
}

}  // namespace villa::procedural
