// Issue 27 in the solver: a room type's essential pieces and what carries a protected piece are protected
// (MarkEssentials), so the room gives up its optional pieces for them; table chairs are placed from their
// group's template (at the table's sides, facing it) whatever the room's shape.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "fixtures.h"
#include "solver/group_rules.h"
#include "solver/scene_problem.h"
#include "solver/solve.h"

namespace villa::solver {
namespace {

using namespace fixtures;

int Index(const RoomSolution& s, const std::string& id) {
  for (size_t k = 0; k < s.objects.size(); ++k)
    if (s.objects[k].id == id && s.placements[k].placed) return static_cast<int>(k);
  return -1;
}

OrientedBox Plan(const RoomSolution& s, int k) { return StandingBox(s.objects[k], s.placements[k].pose); }

TEST_CASE("A bathroom too small for its toilet and a cabinet keeps the toilet, essential, and loses the cabinet",
          "[solver][groups]") {
  // 1.3 x 1.6 m: the cabinet (1.2 x 1.4) leaves no 0.4 x 0.65 spot for the toilet. Without the essentials
  // both would be priors and the smaller, the toilet, would go.
  RoomProblem room = Rectangle(1.3, 1.6);
  room.objects.push_back(BoxObject("cabinet-0", 1.2, 1.4, 0.9));
  room.objects.push_back(BoxObject("toilet-0", 0.4, 0.65, 0.8));
  MarkEssentials(Category::kBathroom, room);
  CHECK(room.objects[0].priority == Priority::kPrior);
  CHECK(room.objects[1].priority == Priority::kEssential);
  auto solved = SolveRoom(room, {});
  REQUIRE(solved.ok());
  INFO(solved->summary.BriefReport());
  CHECK(solved->summary.metrics.Clean());
  CHECK(Index(*solved, "r/toilet-0") >= 0);
  CHECK(Index(*solved, "r/cabinet-0") < 0);
}

TEST_CASE("What carries a protected piece is protected: the TV stand under a requested TV, the counter under the sink",
          "[solver][groups]") {
  RoomProblem room = Rectangle(4, 3);
  room.objects.push_back(BoxObject("tv-stand-0", 1.2, 0.4, 0.5, true));
  ProblemObject tv = SmallObject("tv-0", 1.0, 0.1, 0.6, "tv-stand-0", Relation::kOnTop);
  tv.priority = Priority::kNamed;  // the request asked for it
  room.objects.push_back(tv);
  room.objects.push_back(BoxObject("counter-0", 1.2, 0.6, 0.9, true));
  room.objects.push_back(SmallObject("sink-0", 0.5, 0.4, 0.2, "counter-0", Relation::kOnTop));
  room.objects.push_back(BoxObject("sideboard-0", 1.2, 0.45, 0.8, true));
  MarkEssentials(Category::kKitchen, room);
  CHECK(room.objects[0].priority == Priority::kNamed);      // carries the named TV
  CHECK(room.objects[2].priority == Priority::kEssential);  // carries the essential sink
  CHECK(room.objects[3].priority == Priority::kEssential);
  CHECK(room.objects[4].priority == Priority::kPrior);
}

TEST_CASE("Dining chairs are seated from their table's template: at its sides, facing it, in any room shape",
          "[solver][groups]") {
  for (const char* shape : {"rectangle", "L"}) {
    DYNAMIC_SECTION(shape) {
      RoomProblem room = std::string(shape) == "L" ? LShape() : Rectangle(5.0, 4.4);
      room.objects.push_back(TableObject("dining-table-0", 1.6, 0.9, 0.75));
      for (int k = 0; k < 4; ++k) {
        const std::string chair = "chair-" + std::to_string(k);
        room.objects.push_back(BoxObject(chair, 0.45, 0.5, 0.85));
        room.edges.push_back(DefaultEdge("r/" + chair, SemanticRelation::kFaceTo, "r/dining-table-0"));
        SemanticEdge next = DefaultEdge("r/" + chair, SemanticRelation::kNextTo, "r/dining-table-0");
        next.max_gap = 0.3;
        room.edges.push_back(next);
      }
      MarkEssentials(Category::kDiningRoom, room);
      auto solved = SolveRoom(room, {});
      REQUIRE(solved.ok());
      INFO(solved->summary.BriefReport());
      CHECK(solved->summary.metrics.Clean());
      const int t = Index(*solved, "r/dining-table-0");
      REQUIRE(t >= 0);
      int seated = 0;
      for (int k = 0; k < 4; ++k) {
        const int c = Index(*solved, "r/chair-" + std::to_string(k));
        REQUIRE(c >= 0);  // essential: two of them; the others fit in a room this size
        const std::string problem = TableSeatProblem(Plan(*solved, c), Plan(*solved, t));
        INFO("chair-" << k << ": " << problem);
        seated += problem.empty();
      }
      CHECK(seated == 4);
    }
  }
}

}  // namespace
}  // namespace villa::solver
