// Issue 28's physics in the furnish pipeline (solver/furnish.h): the finished villa settles in Bullet; an
// optional piece that moved is taken out by its room's solver and the villa settles again; protected
// pieces (a room's essentials) stay, and the room's solve record says why each piece went.
#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <string>

#include "layout/layout_io.h"
#include "physics/glb_settle.h"
#include "scene/acquire.h"
#include "solver/furnish.h"

using namespace villa;

namespace {

solver::FurnishedVilla FurnishedWith(const solver::FurnishOptions& options) {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json");
  REQUIRE(layout.ok());
  auto library = scene::OpenFurnishingLibrary("", true);
  REQUIRE(library.ok());
  auto villa = solver::FurnishLayout(*layout, {"house_one_floor.json", std::string(64, '0')}, library->library, std::nullopt, options);
  INFO((villa.ok() ? "" : villa.error()));
  REQUIRE(villa.ok());
  return std::move(*villa);
}

}  // namespace

TEST_CASE("Optional pieces that move in the settle are taken out and the villa settled again, essentials stay", "[solver][physics]") {
  solver::FurnishOptions options;
  options.seed = 2;
  options.jobs = 2;
  options.check_reach = false;
  // Any motion at all counts: every free piece that stirs is a mover.
  options.settle.strict_move = options.settle.loose_move = 1e-9;
  options.settle.strict_turn = options.settle.loose_turn = 1e-9;
  options.physics_rounds = 0;
  const solver::FurnishedVilla kept = FurnishedWith(options);
  REQUIRE(kept.summary.physics_checked);
  CHECK(kept.summary.physics_removed == 0);
  const int movers = kept.summary.stability.free - kept.summary.stability.strict;
  REQUIRE(movers > 0);

  options.physics_rounds = 1;
  const solver::FurnishedVilla fixed = FurnishedWith(options);
  const solver::FurnishSummary& s = fixed.summary;
  CHECK(s.physics_removed > 0);
  CHECK(s.objects == kept.summary.objects - s.physics_removed);
  CHECK(s.functional.rooms_essential == s.functional.with_essentials);  // nothing essential went
  int physics_actions = 0;
  for (const scene::RoomEntry& room : fixed.scene.rooms) {
    if (!room.solve) continue;
    for (const auto& a : room.solve->actions)
      if (a.value("reason", "").rfind("physics: moved ", 0) == 0) {
        ++physics_actions;
        CHECK(a["action"] == "remove_entity");
      }
  }
  CHECK(physics_actions > 0);
  CHECK(physics_actions <= movers);
  REQUIRE(fixed.physics);
  CHECK(fixed.physics->all.free == s.stability.free);
  // The second settle ran only the rooms that changed, the others kept from the first: the same as settling
  // the written villa whole, object by object.
  auto whole = physics::SettleGlbBytes(fixed.glb, options.settle);
  REQUIRE(whole.ok());
  CHECK(whole->all.free == fixed.physics->all.free);
  CHECK(whole->all.strict == fixed.physics->all.strict);
  CHECK(whole->all.loose == fixed.physics->all.loose);
  CHECK(whole->starts_inside == fixed.physics->starts_inside);
  CHECK(whole->decals == fixed.physics->decals);
  CHECK(whole->parts == fixed.physics->parts);
  std::map<std::string, bool> strict;
  for (const auto& o : whole->objects) strict[o.id] = o.motion.strict;
  CHECK(strict.size() == fixed.physics->objects.size());
  for (const auto& o : fixed.physics->objects) {
    INFO(o.id);
    REQUIRE(strict.count(o.id));
    CHECK(strict[o.id] == o.motion.strict);
  }
}
