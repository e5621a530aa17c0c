// Floor-plan rendering speed: milliseconds per picture of the bundled examples, single thread.
// A dataset build renders a preview per layout, so the three-floor villa should take well under 100 ms.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "layout/layout_io.h"
#include "render/plan_render.h"

namespace {

template <class F>
double MillisecondsPerCall(F&& f, double min_seconds = 1.0) {
  using Clock = std::chrono::steady_clock;
  long calls = 0;
  const auto start = Clock::now();
  double elapsed = 0;
  do {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < min_seconds || calls < 3);
  return elapsed * 1e3 / calls;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? std::filesystem::path(argv[1])
                                             : std::filesystem::path(__FILE__).parent_path().parent_path() / "examples";
  const std::vector<std::string> names = {"three-floor-villa.json", "two-floor-house.json", "l-shaped-house.json"};
  std::printf("%-24s %6s %6s %11s %9s %11s %9s %13s\n", "example", "floors", "rooms", "size px", "PNG ms", "PNG bytes",
              "SVG ms", "PNG 800px ms");
  volatile std::size_t sink = 0;
  for (const auto& name : names) {
    const auto layout = villa::LoadLayout(dir / name);
    if (!layout) {
      std::fprintf(stderr, "%s\n", layout.error().c_str());
      return 1;
    }
    const villa::PlanRenderOptions options;
    villa::PlanRenderOptions small;
    small.target_width_px = 800;
    const auto frame = villa::ComputePlanFrame(*layout, options);
    const auto png = villa::RenderPlanPng(*layout, options);
    if (!frame || !png) {
      std::fprintf(stderr, "%s: cannot render\n", name.c_str());
      return 1;
    }
    const double png_ms = MillisecondsPerCall([&] { sink = sink + villa::RenderPlanPng(*layout, options)->size(); });
    const double svg_ms = MillisecondsPerCall([&] { sink = sink + villa::RenderPlanSvg(*layout, options)->size(); });
    const double small_ms = MillisecondsPerCall([&] { sink = sink + villa::RenderPlanPng(*layout, small)->size(); });
    const std::string size = std::to_string(frame->width_px) + "x" + std::to_string(frame->height_px);
    std::printf("%-24s %6d %6zu %11s %9.1f %11zu %9.1f %13.1f\n", name.c_str(), layout->LevelCount(),
                layout->rooms.size(), size.c_str(), png_ms, png->size(), svg_ms, small_ms);
  }
  return 0;
}
