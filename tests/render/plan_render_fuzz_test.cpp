// Garbage in, a picture out: random rooms (overlapping, self-intersecting, degenerate, far apart) and
// random elements never crash the renderer, and the picture has the frame's size.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>

#include "render/plan_render.h"
#include "render_test_support.h"

using namespace villa;

namespace {

// Uniform double in [lo, hi) from the raw 64-bit generator (no std::*_distribution: same on every
// standard library).
double Uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);
}
int Below(std::mt19937_64& rng, int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); }

Layout RandomLayout(std::mt19937_64& rng) {
  Layout layout;
  const int levels = 1 + Below(rng, 3);
  const double span = Uniform(rng, 2.0, 40.0);
  for (int level = 0; level < levels; ++level) {
    const int rooms = Below(rng, 8);
    for (int i = 0; i < rooms; ++i) {
      Room room;
      room.category = static_cast<Category>(Below(rng, kCategoryCount));
      room.level = level;
      room.index = i;
      const int corners = Below(rng, 7);  // 0..6: degenerate rings too
      if (Below(rng, 2) == 0 && corners >= 3) {
        const double x = Uniform(rng, 0, span), y = Uniform(rng, 0, span);
        const double w = Uniform(rng, 0.2, span / 2), h = Uniform(rng, 0.2, span / 2);
        room.polygon = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
      } else {
        for (int c = 0; c < corners; ++c) room.polygon.push_back({Uniform(rng, 0, span), Uniform(rng, 0, span)});
      }
      layout.rooms.push_back(room);
    }
  }
  const ElementKind kinds[] = {ElementKind::kEntrance, ElementKind::kDoor, ElementKind::kOpen, ElementKind::kWindow,
                               ElementKind::kInterior};
  const int elements = Below(rng, 25);
  for (int i = 0; i < elements; ++i) {
    Element e;
    e.kind = kinds[Below(rng, 5)];
    e.name = "e" + std::to_string(i);
    e.level = Below(rng, 5) == 0 ? kAllLevels : Below(rng, levels);
    e.panoramic = Below(rng, 2) == 0;
    // Often on a room edge (so some elements are "on a wall"), sometimes anywhere, sometimes a point.
    if (!layout.rooms.empty() && Below(rng, 2) == 0) {
      const Room& room = layout.rooms[Below(rng, static_cast<int>(layout.rooms.size()))];
      if (room.polygon.size() >= 2) {
        const size_t k = Below(rng, static_cast<int>(room.polygon.size()));
        const Point a = room.polygon[k], b = room.polygon[(k + 1) % room.polygon.size()];
        const double t0 = Uniform(rng, 0, 0.5), t1 = Uniform(rng, 0.5, 1.0);
        e.shape = {{a.x + (b.x - a.x) * t0, a.y + (b.y - a.y) * t0}, {a.x + (b.x - a.x) * t1, a.y + (b.y - a.y) * t1}};
      }
    } else if (Below(rng, 6) == 0) {
      const Point p{Uniform(rng, 0, span), Uniform(rng, 0, span)};
      e.shape = {p, p};
    } else {
      e.shape = {{Uniform(rng, 0, span), Uniform(rng, 0, span)}, {Uniform(rng, 0, span), Uniform(rng, 0, span)}};
    }
    layout.elements(e.kind).push_back(e);
  }
  return layout;
}

}  // namespace

TEST_CASE("random and broken layouts always render", "[render][fuzz]") {
  std::mt19937_64 rng(20261122);
  PlanRenderOptions small;
  small.pixels_per_metre = 8;
  for (int i = 0; i < 150; ++i) {
    const Layout layout = RandomLayout(rng);
    INFO("layout " << i << ": " << layout.rooms.size() << " rooms");
    const Result<PlanFrame> frame = ComputePlanFrame(layout, small);
    REQUIRE(frame.ok());
    const Result<std::string> svg = RenderPlanSvg(layout, small);
    REQUIRE(svg.ok());
    CHECK(svg->find("</svg>") != std::string::npos);
    if (i % 10 == 0) {
      const Result<std::string> png = RenderPlanPng(layout, small);
      REQUIRE(png.ok());
      const test::Picture picture = test::DecodePng(*png);
      CHECK(picture.width == frame->width_px);
      CHECK(picture.height == frame->height_px);
    }
  }
}
