// Tables: a top (the support surface, rectangular or elliptic) on legs or a pedestal; a lower shelf on
// some coffee tables (a second surface).
#include <algorithm>
#include <cmath>

#include "assets/procedural/generator.h"

namespace villa::procedural {
namespace {

constexpr int kRoundSegments = 32;

GeneratorDef Table() {
  return {
      .name = "table",
      .description = "table: a rectangular or elliptic top (support surface) on legs or a pedestal",
      .categories = {"dining-table", "coffee-table", "side-table", "conference-table", "play-table", "outdoor-table"},
      .extra = {CountParam("round", "1: elliptic top, 0: rectangular", 0, 1)},
      .resolve =
          [](ParamValues& p, const CategoryInfo& category, Rng& rng) {
            const double chance = category.name == "side-table"         ? 0.5
                                  : category.name == "outdoor-table"    ? 0.4
                                  : category.name == "conference-table" ? 0.1
                                                                        : 0.25;
            SetIfMissing(p, "round", [&] { return rng.Chance(chance) ? 1 : 0; });
          },
      .build =
          [](Gen& g) {
            const bool round = g.params.Int("round") == 1;
            const double top = std::min(g.style == "rustic"    ? 0.05
                                        : g.style == "classic" ? 0.035
                                        : g.style == "modern"  ? 0.025
                                                               : 0.03,
                                        0.25 * g.h);
            const double zt = g.h - top;
            const int wood = g.out.Part(g.rng.Pick(g.palette.wood));
            const int legs = g.style == "modern" ? g.out.Part(g.rng.Pick(g.palette.metal)) : wood;
            if (round) {
              g.out.Cylinder(wood, 0, 0, g.w / 2, g.d / 2, zt, g.h, kRoundSegments);
              g.out.Surface(g.h, Ellipse(0, 0, g.w / 2, g.d / 2, kRoundSegments), g.OpenAbove(g.h));
            } else {
              g.out.Box(wood, {-g.w / 2, -g.d / 2, zt}, {g.w / 2, g.d / 2, g.h});
              g.TopSurface(g.h, -g.w / 2, -g.d / 2, g.w / 2, g.d / 2);
            }
            const double small = std::min(g.w, g.d);
            const double half = std::min(g.style == "rustic"    ? 0.04
                                         : g.style == "classic" ? 0.03
                                                                : 0.022,
                                         0.08 * small);
            if (round && small < 0.9) {
              // Pedestal: a column on a foot.
              const double foot = 0.03, column = std::min(0.05, 0.15 * small);
              g.out.Cylinder(legs, 0, 0, 0.35 * g.w, 0.35 * g.d, 0, foot, 24);
              g.out.Cylinder(legs, 0, 0, column, column, foot, zt, 12);
              return;
            }
            // Legs inside the top's outline (an ellipse holds its inscribed rectangle at 1/sqrt 2 of the radii).
            const double lx = round ? 0.6 * g.w / 2 : g.w / 2 - 0.04 - half;
            const double ly = round ? 0.6 * g.d / 2 : g.d / 2 - 0.04 - half;
            std::vector<double> xs = {-lx, lx};
            if (g.w > 2.4) xs.push_back(0.0);
            for (double x : xs)
              for (double y : {-ly, ly}) g.Leg(legs, x, y, 0, zt, half);
            const bool apron = !round && (g.style == "classic" || g.style == "rustic") && zt > 0.3;
            const double apron_h = 0.07;
            if (apron) {
              g.out.Box(wood, {-lx + half, -ly - 0.01, zt - apron_h}, {lx - half, -ly + 0.01, zt});
              g.out.Box(wood, {-lx + half, ly - 0.01, zt - apron_h}, {lx - half, ly + 0.01, zt});
              g.out.Box(wood, {-lx - 0.01, -ly + half, zt - apron_h}, {-lx + 0.01, ly - half, zt});
              g.out.Box(wood, {lx - 0.01, -ly + half, zt - apron_h}, {lx + 0.01, ly - half, zt});
            }
            if (!round && g.Is("coffee-table") && (g.style == "rustic" || g.style == "scandinavian")) {
              const double z0 = 0.1, z1 = 0.12, ceiling = apron ? zt - apron_h : zt;
              g.out.Box(wood, {-lx + half, -ly + half, z0}, {lx - half, ly - half, z1});
              g.out.Surface(z1, Rect(-lx + half, -ly + half, lx - half, ly - half), ceiling - z1);
            }
          }};
}

}  // namespace

std::vector<GeneratorDef> TableGenerators() { return {Table()}; }

}  // namespace villa::procedural
