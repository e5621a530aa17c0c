// The floor plan as terminal cells: the whole outline on the canvas at every size (the west wall was
// lost when a plan filled the width exactly), and stair treads in a glyph windows do not use.
#include <catch2/catch.hpp>

#include "annotator/floorplan_canvas.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;

namespace {

Layout WideLayout() {
  auto dataset = LoadDataset(test::TempDataset("wide.jsonl").dir());
  REQUIRE(dataset.ok());
  return dataset->records[0].layout;
}

// The columns holding anything, and whether a glyph is in a column.
struct Extent {
  int left = -1, right = -1;
};
Extent Columns(const Canvas& c) {
  Extent e;
  for (int x = 0; x < c.width; ++x)
    for (int y = 0; y < c.height; ++y)
      if (c.at(x, y).kind != CellKind::kEmpty) {
        if (e.left < 0) e.left = x;
        e.right = x;
      }
  return e;
}
bool ColumnHas(const Canvas& c, int x, const std::string& glyph) {
  for (int y = 0; y < c.height; ++y)
    if (c.at(x, y).glyph == glyph) return true;
  return false;
}

}  // namespace

TEST_CASE("the plan's outline stays on the canvas at every size, the west wall included", "[canvas]") {
  std::vector<Layout> layouts = {WideLayout(), test::FixtureLayout("villa-000000"), test::FixtureLayout("villa-000001")};
  for (const Layout& layout : layouts) {
    for (int width = 20; width <= 120; ++width) {
      for (int height : {10, 13, 20, 21, 37, 44}) {
        CanvasOptions o;
        o.width = width;
        o.height = height;
        Canvas c = DrawFloorPlan(layout, 0, o);
        Extent e = Columns(c);
        INFO("canvas " << width << "x" << height);
        REQUIRE(e.left >= 0);
        // The building's west side runs the full depth: its corners are both in the leftmost column.
        CHECK(ColumnHas(c, e.left, "┌"));
        CHECK(ColumnHas(c, e.left, "└"));
        CHECK(ColumnHas(c, e.right, "┘"));
      }
    }
  }
  // The 80x24 case of issue 16: the plan is 43 x 20 cells; the living room's west window is drawn.
  CanvasOptions o;
  o.width = 43;
  o.height = 20;
  Canvas c = DrawFloorPlan(WideLayout(), 0, o);
  CHECK(Columns(c).left == 0);
  CHECK(Columns(c).right == 42);
  CHECK(ColumnHas(c, 0, "║"));
}

TEST_CASE("stair treads are drawn in their own glyph, not the window's", "[canvas]") {
  Layout layout = test::FixtureLayout("villa-000001");
  for (bool unicode : {true, false}) {
    CanvasOptions o;
    o.width = 60;
    o.height = 24;
    o.unicode = unicode;
    Canvas c = DrawFloorPlan(layout, 0, o);
    int treads = 0;
    for (const CanvasCell& cell : c.cells) {
      if (cell.kind == CellKind::kStair && cell.glyph != " ") {
        CHECK(cell.glyph == (unicode ? "≡" : "_"));
        ++treads;
      }
      if (cell.kind == CellKind::kWindow) CHECK(cell.glyph != (unicode ? "≡" : "_"));
    }
    CHECK(treads > 0);
  }
}
