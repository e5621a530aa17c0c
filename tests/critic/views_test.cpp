// What the critic looks at: the room's pictures (solver/room_view.h through critic/observation.h) and its
// text state.
#include <catch2/catch.hpp>

#include "critic/observation.h"
#include "room_fixture.h"
#include "solver/room_view.h"
#include "solver/solve.h"

namespace villa {
namespace {

int Differing(const Image& a, const Image& b) {
  int n = 0;
  for (size_t i = 0; i < a.rgb.size(); i += 3) n += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
  return n;
}

}  // namespace

TEST_CASE("A room is seen from above and from its four corners, labels where asked, the same pixels whatever the threads", "[critic][views]") {
  auto room = testing::MakeCriticRoom("living-room_0/0");
  solver::RoomSolver session(room->mapped.problem, room->input.solve, room->input.check);
  REQUIRE(session.Initialise().ok());
  session.RunAgent();
  const solver::RoomSolution s = session.Solution();
  solver::RoomViewOptions options;
  options.size_px = 160;
  auto plain = critic::RoomViews(room->input, s, options);
  REQUIRE(plain.ok());
  REQUIRE(plain->size() == 5);
  const std::vector<std::string> names{"top", "corner-45", "corner-135", "corner-225", "corner-315"};
  for (size_t k = 0; k < 5; ++k) {
    CHECK((*plain)[k].name == names[k]);
    CHECK((*plain)[k].image.width == 160);
    CHECK((*plain)[k].image.height == 160);
  }
  // Five different pictures, none blank.
  for (size_t k = 0; k < 5; ++k) {
    int lit = 0;
    const Image& img = (*plain)[k].image;
    for (size_t i = 0; i < img.rgb.size(); i += 3) lit += img.rgb[i] != 255 || img.rgb[i + 1] != 255 || img.rgb[i + 2] != 255;
    CHECK(lit > 160 * 160 / 4);
    for (size_t j = k + 1; j < 5; ++j) CHECK(Differing((*plain)[k].image, (*plain)[j].image) > 1000);
  }
  options.labels = true;
  auto labelled = critic::RoomViews(room->input, s, options);
  REQUIRE(labelled.ok());
  CHECK(Differing((*plain)[0].image, (*labelled)[0].image) > 100);
  options.threads = 2;
  auto threaded = critic::RoomViews(room->input, s, options);
  REQUIRE(threaded.ok());
  for (size_t k = 0; k < 5; ++k) CHECK((*threaded)[k].image.rgb == (*labelled)[k].image.rgb);
  // Furniture shows: without it the pictures differ.
  solver::RoomSolution empty = s;
  empty.objects.clear();
  empty.placements.clear();
  auto bare = critic::RoomViews(room->input, empty, {});
  REQUIRE(bare.ok());
  CHECK(Differing((*bare)[0].image, (*critic::RoomViews(room->input, s, {}))[0].image) > 5000);
  options.size_px = 20;
  CHECK_FALSE(critic::RoomViews(room->input, s, options).ok());
}

TEST_CASE("The text state names every object with its physical edge, the relations with their measures, and the last actions", "[critic][views]") {
  auto room = testing::MakeCriticRoom("bedroom_0/0");
  solver::RoomSolver session(room->mapped.problem, room->input.solve, room->input.check);
  REQUIRE(session.Initialise().ok());
  session.RunAgent();
  const solver::RoomSolution s = session.Solution();
  const critic::RoomRelations relations = critic::MeasureRelations(s.objects, s.placements, room->plan.edges);
  solver::ActionResult refused;
  refused.action.kind = solver::ActionKind::kUpdatePose;
  refused.action.id = "bedroom_0/0/bed-0";
  refused.status = solver::ActionStatus::kRefused;
  refused.message = "no free pose";
  const std::string state = critic::RoomStateText(room->input, s, relations, {refused});
  for (const solver::ProblemObject& o : s.objects) CHECK(state.find("  " + critic::ShortId("bedroom_0/0", o.id) + ": " + o.category + ";") != std::string::npos);
  CHECK(state.find("walls (index") != std::string::npos);
  CHECK(state.find("bed-0: bed; against_wall wall ") != std::string::npos);
  CHECK(state.find("pillow-0: pillow; ontop bed-0 surface") != std::string::npos);
  CHECK(state.find("nightstand-0 next_to bed-0: gap") != std::string::npos);
  CHECK(state.find("exact check: clean") != std::string::npos);
  CHECK(state.find("update_pose bed-0: refused (no free pose)") != std::string::npos);
  CHECK(critic::ShortId("bedroom_0/0", "bedroom_0/0/bed-0") == "bed-0");
  CHECK(critic::FullId("bedroom_0/0", "bed-0") == "bedroom_0/0/bed-0");
  CHECK(critic::FullId("bedroom_0/0", "bedroom_0/0/bed-0") == "bedroom_0/0/bed-0");
}

}  // namespace villa
