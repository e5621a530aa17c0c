// Seats and beds: sofas and armchairs (a seat surface per cushion), chairs, office chairs, stools, benches,
// loungers, beds (the mattress top is the surface; pillows are objects of their own). Front = -y: seats
// open to -y, backs and headboards stand at +y.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/procedural/generator.h"

namespace villa::procedural {
namespace {

// Sofa or armchair: legs, a base, two arms, a back, `seats` seat cushions (one surface each) and back
// cushions in front of the back.
void Upholstered(Gen& g, int seats) {
  const int fabric = g.out.Part(g.rng.Pick(g.palette.fabric));
  const int legs = g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.wood));
  const double leg_h = g.style == "rustic" ? 0.05 : g.style == "classic" ? 0.1 : 0.12;
  const double arm = std::min(0.2, (seats > 1 ? 0.1 : 0.15) * g.w);
  const double back = std::clamp(0.18 * g.d, 0.12, 0.2);
  const double back_cushion = 0.15;
  const double zs = std::min(0.45, 0.55 * g.h);  // seat height
  const double cushion = 0.12, zb = zs - cushion;
  const double arm_top = std::min(g.h, zs + 0.2);
  const double x0 = -g.w / 2 + arm, x1 = g.w / 2 - arm;
  g.out.Box(fabric, {x0, -g.d / 2 + 0.02, leg_h}, {x1, g.d / 2 - back, zb});
  g.out.Box(fabric, {-g.w / 2, -g.d / 2, leg_h}, {x0, g.d / 2, arm_top});
  g.out.Box(fabric, {x1, -g.d / 2, leg_h}, {g.w / 2, g.d / 2, arm_top});
  g.out.Box(fabric, {x0, g.d / 2 - back, leg_h}, {x1, g.d / 2, g.h});
  const double gap = 0.006, inset = 0.015;
  const double width = (x1 - x0 - (seats - 1) * gap) / seats;
  const double seat_back = g.d / 2 - back - back_cushion;
  for (int k = 0; k < seats; ++k) {
    const double a = x0 + k * (width + gap), b = a + width;
    g.out.Cushion(fabric, {a, -g.d / 2, zb}, {b, seat_back, zs}, inset, 0.6);
    g.out.Surface(zs, Rect(a + inset, -g.d / 2 + inset, b - inset, seat_back - inset), g.OpenAbove(zs));
    g.out.Cushion(fabric, {a, seat_back, zb}, {b, g.d / 2 - back, std::max(zs + 0.1, g.h - 0.06)}, inset);
  }
  const double half = 0.025;
  std::vector<double> xs = {-g.w / 2 + 0.03 + half, g.w / 2 - 0.03 - half};
  if (g.w > 2.0) xs.push_back(0.0);
  for (double x : xs)
    for (double y : {-g.d / 2 + 0.03 + half, g.d / 2 - 0.03 - half}) g.Leg(legs, x, y, 0, leg_h, half);
}

GeneratorDef Sofa() {
  return {.name = "sofa",
          .description = "sofa: arms, back, seat cushions (one seat surface each), back cushions, legs",
          .categories = {"sofa"},
          .extra = {CountParam("seats", "seat cushions side by side", 1, 4)},
          .resolve =
              [](ParamValues& p, const CategoryInfo&, Rng&) {
                SetIfMissing(p, "seats",
                             [&] { return std::clamp(static_cast<int>(std::lround(p.Real("w") / 0.65)), 2, 4); });
              },
          .build = [](Gen& g) { Upholstered(g, g.params.Int("seats")); }};
}

GeneratorDef Armchair() {
  return {.name = "armchair",
          .description = "armchair: arms, back, one seat cushion (a seat surface), legs",
          .categories = {"armchair"},
          .build = [](Gen& g) { Upholstered(g, 1); }};
}

GeneratorDef Chair() {
  return {.name = "chair",
          .description = "chair: four legs, a seat (surface) opening to -y, back posts and a back rail at +y",
          .categories = {"chair", "child-chair", "outdoor-chair"},
          .build = [](Gen& g) {
            const bool outdoor = g.Is("outdoor-chair");
            const int frame =
                g.out.Part(outdoor || g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.wood));
            const int seat_part =
                g.out.Part(g.style == "classic" ? g.rng.Pick(g.palette.fabric) : g.rng.Pick(g.palette.wood));
            const double zs = std::min(0.46, 0.55 * g.h), seat = 0.035;
            const double half = std::min(outdoor ? 0.014 : 0.02, 0.06 * g.w);
            const double post = 2 * half;
            g.out.Box(seat_part, {-g.w / 2, -g.d / 2, zs - seat}, {g.w / 2, g.d / 2, zs});
            for (double x : {-g.w / 2 + half, g.w / 2 - half})
              for (double y : {-g.d / 2 + half, g.d / 2 - half}) g.Leg(frame, x, y, 0, zs - seat, half);
            for (double x : {-g.w / 2, g.w / 2 - post})
              g.out.Box(frame, {x, g.d / 2 - post, zs}, {x + post, g.d / 2, g.h});
            // Back: one wide rail (modern, classic), or slats (rustic, scandinavian, outdoor).
            const double back_y0 = g.d / 2 - std::min(0.025, post);
            const double rail_top = g.h - 0.02, rail_bottom = std::max(zs + 0.08, g.h - 0.25);
            if (outdoor || g.style == "rustic" || g.style == "scandinavian") {
              for (int k = 0; k < 3; ++k) {
                const double z1 = rail_top - k * (rail_top - rail_bottom) / 3,
                             z0 = z1 - 0.6 * (rail_top - rail_bottom) / 3;
                g.out.Box(seat_part, {-g.w / 2 + post, back_y0, z0}, {g.w / 2 - post, g.d / 2, z1});
              }
            } else {
              g.out.Box(seat_part, {-g.w / 2 + post, back_y0, rail_bottom}, {g.w / 2 - post, g.d / 2, rail_top});
            }
            g.out.Surface(zs, Rect(-g.w / 2, -g.d / 2, g.w / 2, g.d / 2 - post), g.OpenAbove(zs));
          }};
}

GeneratorDef OfficeChair() {
  return {
      .name = "office-chair",
      .description = "swivel chair: five-star base on casters, gas column, seat (surface), armrests, back",
      .categories = {"office-chair"},
      .build = [](Gen& g) {
        const int black = g.out.Part(g.rng.Pick(g.palette.metal));
        const int fabric = g.out.Part(g.rng.Pick(g.palette.fabric));
        const double zs = std::min(0.5, 0.45 * g.h), seat = 0.08, arm = 0.05;
        const double reach = std::min(g.w, g.d) / 2 - 0.04;
        for (int k = 0; k < 5; ++k) {
          const double a = -std::numbers::pi / 2 + 2 * std::numbers::pi * k / 5;
          const Vec3 u{std::cos(a), std::sin(a), 0}, v{-u.y, u.x, 0};
          const double hw = 0.02;
          std::array<Vec3, 8> c;
          const Vec3 ring[4] = {v * -hw, u * reach + v * -hw, u * reach + v * hw, v * hw};
          for (int i = 0; i < 4; ++i) {
            c[i] = ring[i] + Vec3{0, 0, 0.05};
            c[i + 4] = ring[i] + Vec3{0, 0, 0.08};
          }
          g.out.Hexahedron(black, c);
          g.out.Cylinder(black, u.x * reach, u.y * reach, 0.025, 0.025, 0, 0.05, 8);
        }
        g.out.Cylinder(black, 0, 0, 0.03, 0.03, 0.08, zs - seat, 12);
        g.out.Cushion(fabric, {-g.w / 2 + arm, -g.d / 2, zs - seat}, {g.w / 2 - arm, g.d / 2 - 0.1, zs}, 0.015, 0.4);
        g.out.Surface(zs, Rect(-g.w / 2 + arm + 0.015, -g.d / 2 + 0.015, g.w / 2 - arm - 0.015, g.d / 2 - 0.115),
                      g.OpenAbove(zs));
        // Back on a bar from under the seat.
        g.out.Box(black, {-0.03, g.d / 2 - 0.1, zs - seat}, {0.03, g.d / 2 - 0.05, zs + 0.1});
        g.out.Cushion(fabric, {-0.42 * g.w, g.d / 2 - 0.06, zs + 0.08}, {0.42 * g.w, g.d / 2, g.h}, 0.01);
        for (double x : {-g.w / 2, g.w / 2 - arm}) {
          g.out.Box(black, {x + 0.01, -0.05, zs - seat}, {x + arm - 0.01, 0.0, zs + 0.18});
          g.out.Box(black, {x, -g.d / 2 + 0.1, zs + 0.18}, {x + arm, g.d / 2 - 0.15, zs + 0.21});
        }
      }};
}

GeneratorDef Stool() {
  return {
      .name = "stool",
      .description = "stool: an elliptic seat (surface) on four legs, a foot ring on tall ones",
      .categories = {"stool"},
      .build = [](Gen& g) {
        const int seat = g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.fabric) : g.rng.Pick(g.palette.wood));
        const int frame = g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.wood));
        const double top = 0.04, rx = g.w / 2, ry = g.d / 2;
        g.out.Cylinder(seat, 0, 0, rx, ry, g.h - top, g.h, 24);
        g.out.Surface(g.h, Ellipse(0, 0, rx, ry, 24), g.OpenAbove(g.h));
        const double half = 0.018, k = 0.45;
        const Point feet[4] = {{-k * rx, -k * ry}, {k * rx, -k * ry}, {k * rx, k * ry}, {-k * rx, k * ry}};
        for (Point p : feet) g.Leg(frame, p.x, p.y, 0, g.h - top, half);
        if (g.h > 0.6)
          for (int i = 0; i < 4; ++i) {
            Point a = feet[i], b = feet[(i + 1) % 4];
            g.out.Tube(frame, {a.x, a.y, 0.3 * g.h}, {b.x, b.y, 0.3 * g.h}, 0.008, 8);
          }
      }};
}

GeneratorDef Bench() {
  return {.name = "bench",
          .description = "backless bench: a board (top surface) on two panel legs or four legs",
          .categories = {"bench"},
          .build = [](Gen& g) {
            const int wood = g.out.Part(g.rng.Pick(g.palette.wood));
            const double top = 0.045, zt = g.h - top;
            g.out.Box(wood, {-g.w / 2, -g.d / 2, zt}, {g.w / 2, g.d / 2, g.h});
            g.TopSurface(g.h, -g.w / 2, -g.d / 2, g.w / 2, g.d / 2);
            if (g.style == "modern" || g.style == "scandinavian") {
              for (double x : {-g.w / 2 + 0.08, g.w / 2 - 0.11})
                g.out.Box(wood, {x, -g.d / 2 + 0.03, 0}, {x + 0.03, g.d / 2 - 0.03, zt});
            } else {
              const double half = 0.03;
              for (double x : {-g.w / 2 + 0.06 + half, g.w / 2 - 0.06 - half})
                for (double y : {-g.d / 2 + 0.03 + half, g.d / 2 - 0.03 - half}) g.Leg(wood, x, y, 0, zt, half);
            }
          }};
}

GeneratorDef Lounger() {
  return {
      .name = "lounger",
      .description = "deck chair: a flat seat (surface) with the foot at -y and a raised back rising to +y, on legs",
      .categories = {"deck-chair"},
      .build = [](Gen& g) {
        const int frame = g.out.Part(g.style == "modern" ? g.rng.Pick(g.palette.metal) : g.rng.Pick(g.palette.wood));
        const int fabric = g.out.Part(g.rng.Pick(g.palette.fabric));
        const double zs = std::min(0.35, 0.5 * g.h), t = 0.05;
        const double yb = g.d / 2 - std::min(0.6, 0.4 * g.d);  // where the back starts to rise
        g.out.Box(fabric, {-g.w / 2, -g.d / 2, zs - t}, {g.w / 2, yb, zs});
        g.out.Surface(zs, Rect(-g.w / 2, -g.d / 2, g.w / 2, yb), g.OpenAbove(zs));
        const double w2 = g.w / 2, y1 = g.d / 2;
        g.out.Hexahedron(fabric, {Vec3{-w2, yb, zs - t},
                                  {w2, yb, zs - t},
                                  {w2, y1, g.h - t},
                                  {-w2, y1, g.h - t},
                                  {-w2, yb, zs},
                                  {w2, yb, zs},
                                  {w2, y1, g.h},
                                  {-w2, y1, g.h}});
        const double half = 0.02;
        // The back's underside at the rear legs (it rises linearly from yb to the rear edge).
        const double y_rear = y1 - 2 * half;
        const double z_rear = zs - t + (g.h - zs) * (y_rear - yb) / (y1 - yb);
        for (double x : {-w2 + half, w2 - half}) {
          g.Leg(frame, x, -g.d / 2 + half, 0, zs - t, half);
          g.Leg(frame, x, yb - half, 0, zs - t, half);
          g.Leg(frame, x, y1 - half, 0, z_rear, half);
        }
      }};
}

GeneratorDef Bed() {
  return {.name = "bed",
          .description =
              "bed: legs, frame, mattress (its top the surface), headboard at +y, footboard at -y (classic, rustic)",
          .categories = {"bed", "child-bed"},
          .build = [](Gen& g) {
            const int wood = g.out.Part(g.rng.Pick(g.palette.wood));
            const int linen = g.out.Part(g.rng.Pick(g.palette.fabric));
            const bool child = g.Is("child-bed");
            const double zm = std::min(child ? 0.45 : 0.55, g.h - 0.1);  // mattress top
            const double mattress = std::min(0.2, zm - 0.15), zf = zm - mattress;
            const double rail = std::min(0.12, zf - 0.02);
            const double head = 0.06, foot = 0.05;
            const bool footboard = g.style == "classic" || g.style == "rustic";
            g.out.Box(wood, {-g.w / 2, g.d / 2 - head, 0}, {g.w / 2, g.d / 2, g.h});
            g.out.Box(wood, {-g.w / 2, -g.d / 2, zf - rail}, {g.w / 2, g.d / 2 - head, zf});
            const double half = 0.03;
            for (double x : {-g.w / 2 + half, g.w / 2 - half})
              for (double y : {-g.d / 2 + half, g.d / 2 - head - half}) g.Leg(wood, x, y, 0, zf - rail, half);
            const double my0 = footboard ? -g.d / 2 + foot + 0.005 : -g.d / 2 + 0.02;
            const double mx = g.w / 2 - 0.03, my1 = g.d / 2 - head - 0.005, inset = 0.02;
            if (footboard) g.out.Box(wood, {-g.w / 2, -g.d / 2, zf - rail}, {g.w / 2, -g.d / 2 + foot, zm + 0.1});
            if (child && g.h >= 0.8)  // guard rail along the +x side, near the head
              g.out.Box(wood, {mx + 0.005, g.d / 2 - head - 0.6 * g.d, zf}, {g.w / 2, g.d / 2 - head, zm + 0.2});
            g.out.Cushion(linen, {-mx, my0, zf}, {mx, my1, zm}, inset, 0.5);
            g.out.Surface(zm, Rect(-mx + inset, my0 + inset, mx - inset, my1 - inset), g.OpenAbove(zm));
          }};
}

}  // namespace

std::vector<GeneratorDef> SeatingGenerators() {
  return {Sofa(), Armchair(), Chair(), OfficeChair(), Stool(), Bench(), Lounger(), Bed()};
}

}  // namespace villa::procedural
