// Plans of layouts written to break the renderer (issue 17): coordinates far outside any building, rooms
// 1e-320 m wide, JSON nested 100,000 deep. Each is refused or drawn with work bounded by the picture.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "render/plan_render.h"
#include "render_test_support.h"

using namespace villa;
using namespace villa::test;

TEST_CASE("a room 1e12 m long is refused before a scale or a label is computed", "[render][hostile]") {
  Layout layout;
  layout.rooms.push_back({Category::kBedroom, 0, 0, {{0, 0}, {1e12, 0}, {1e12, 4}, {0, 4}}});
  const Result<std::string> png = RenderPlanPng(layout);
  REQUIRE_FALSE(png.ok());
  CHECK(png.error() == "rooms[\"bedroom_0/0\"].shape: x = 1e+12 is outside the building extent (|x| and |y| at most 10000 m)");
  layout.rooms[0].polygon = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  layout.doors.push_back({"d", ElementKind::kDoor, {{0, 0}, {-1e12, 0}}, 0, false});
  const Result<PlanFrame> frame = ComputePlanFrame(layout);
  REQUIRE_FALSE(frame.ok());
  CHECK(frame.error() == "doors[\"d\"].shape: x = -1e+12 is outside the building extent (|x| and |y| at most 10000 m)");
}

TEST_CASE("a room 1e-320 m wide is drawn, its label point found with bounded work", "[render][hostile]") {
  const Ring sliver{{0, 0}, {1e-320, 0}, {1e-320, 4}, {0, 4}};
  const Point label = RoomLabelPoint(sliver);
  CHECK(label.x >= 0);
  CHECK(label.x <= 1e-320);
  CHECK(label.y == Approx(2.0).margin(0.01));
  // A 10 km by 1 cm room: at most 4,096 starting cells, not a million.
  const Point long_label = RoomLabelPoint({{0, 0}, {10000, 0}, {10000, 0.01}, {0, 0.01}});
  CHECK(long_label.y == Approx(0.005).margin(0.001));
  Layout layout;
  layout.rooms.push_back({Category::kBedroom, 0, 0, {{0, 0}, {4, 0}, {4, 4}, {0, 4}}});
  layout.rooms.push_back({Category::kKitchen, 0, 0, {{4, 0}, {4 + 1e-320, 0}, {4 + 1e-320, 4}, {4, 4}}});
  const Result<std::string> png = RenderPlanPng(layout);
  REQUIRE(png.ok());
  CHECK(DecodePng(*png).width > 100);
}

namespace {

int RunVilla(const std::string& args, std::string* err) {
  const auto log = std::filesystem::temp_directory_path() / ("villa-hostile-render-" + std::to_string(::getpid()) + ".err");
  const std::string command = std::string("'") + VILLA_BINARY + "' " + args + " >/dev/null 2>'" + log.string() + "'";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::ostringstream text;
  text << in.rdbuf();
  *err = text.str();
  std::filesystem::remove(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("villa render refuses extreme coordinates and deep nesting with exit 1, writing nothing", "[render][cli][hostile]") {
  const auto dir = std::filesystem::temp_directory_path() / ("villa-hostile-render-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "far.json") << R"J({"rooms": {"bedroom_0/0": {"shape": "shapely.box(0, 0, 1e12, 4)"}},
    "entrance": {}, "doors": {}, "opens": {}, "windows": {}, "interiors": {}})J";
  // The issue's 200 KB file: 100,000 nested arrays.
  std::ofstream(dir / "deep.json") << std::string(100000, '[') << std::string(100000, ']');
  std::string err;
  CHECK(RunVilla("render '" + (dir / "far.json").string() + "' -o '" + (dir / "far.png").string() + "'", &err) == 1);
  CHECK(err == "villa render: " + (dir / "far.json").string() +
                   ": rooms[\"bedroom_0/0\"].shape: x = 1e+12 is outside the building extent (|x| and |y| at most 10000 m)\n");
  CHECK_FALSE(std::filesystem::exists(dir / "far.png"));
  CHECK(RunVilla("render '" + (dir / "deep.json").string() + "' -o '" + (dir / "deep.png").string() + "'", &err) == 1);
  CHECK(err == "villa render: " + (dir / "deep.json").string() + ": line 1, column 65: nested deeper than 64 levels\n");
  CHECK_FALSE(std::filesystem::exists(dir / "deep.png"));
  std::filesystem::remove_all(dir);
}
