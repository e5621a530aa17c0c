// villa_bench_build: layout -> 3D building speed. Builds a three-floor villa many times, exports it as
// .glb, renders one view and the preview; prints median times. `make bench` runs it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "building/building.h"
#include "building/export.h"
#include "building/view_scene.h"
#include "layout/layout_io.h"
#include "tests/building/test_layouts.h"

using namespace villa;

namespace {

double MedianMs(int runs, const std::function<void()>& f) {
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

int main() {
  auto layout = ParseLayoutText(testing::kThreeFloorVilla, "three-floor fixture");
  if (!layout) {
    std::fprintf(stderr, "%s\n", layout.error().c_str());
    return 1;
  }
  auto building = BuildBuilding(*layout);
  if (!building) {
    std::fprintf(stderr, "%s\n", building.error().c_str());
    return 1;
  }
  size_t triangles = 0;
  for (const MeshPart& p : building->parts) triangles += p.mesh.triangles.size();
  std::printf("three-floor villa: %zu rooms, %zu parts, %zu triangles\n", building->rooms.size(),
              building->parts.size(), triangles);
  double build = MedianMs(50, [&] { (void)BuildBuilding(*layout); });
  double vcr = MedianMs(50, [&] { (void)MeasureVcr(*building); });
  size_t glb_bytes = 0;
  double glb = MedianMs(20, [&] { glb_bytes = BuildingToGlb(*building)->size(); });
  const ViewScene scene = ViewSceneOf(*building);
  Camera cam = FramingCamera(scene.Bounds(), -35, 38, 800, 600);
  RenderOptions one;
  double view = MedianMs(3, [&] { (void)RenderView(scene, cam, one); });
  double preview = MedianMs(3, [&] { (void)RenderPreview(scene); });
  std::printf("build (layout -> meshes)      median %8.2f ms  (50 runs)\n", build);
  std::printf("VCR on the built geometry     median %8.3f ms  (50 runs)\n", vcr);
  std::printf("glb export (assimp, in memory) median %7.2f ms  (20 runs, %zu bytes)\n", glb, glb_bytes);
  std::printf("render 800x600, 1 spp, shadows median %7.1f ms  (3 runs)\n", view);
  std::printf("preview 4 panels 560x460, 4 spp median %6.1f ms  (3 runs)\n", preview);
  return 0;
}
