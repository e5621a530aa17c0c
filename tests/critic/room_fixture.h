#pragma once
// One room of a fixture layout made ready for the critic, as the furnish pipeline makes it: the layout
// built, the room's context, the priors' graph, procedural assets, the solver's problem, and the
// RoomCriticInput that points at all of them.
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "assets/asset_library.h"
#include "building/building.h"
#include "layout/layout.h"
#include "layout/layout_io.h"
#include "scene/acquire.h"
#include "scene/planner.h"
#include "scene/room_context.h"
#include "solver/furnish.h"
#include "solver/scene_problem.h"

namespace villa::testing {

struct CriticRoom {
  Layout layout;
  BuildingMesh building;
  std::vector<scene::RoomContext> contexts;
  const scene::RoomContext* context = nullptr;
  std::shared_ptr<AssetLibrary> library;
  std::shared_ptr<scene::AssetAcquirer> acquirer;
  scene::RoomPlan plan;
  solver::SceneRoomProblem mapped;
  solver::RoomCriticInput input;
};

// A folder of its own under the system's temporary folder, removed afterwards.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("villa_critic_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

inline const std::string kHouse = std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json";

// Heap-allocated: the input points into the fixture.
inline std::unique_ptr<CriticRoom> MakeCriticRoom(const std::string& room, uint64_t seed = 3, const std::string& layout = kHouse) {
  auto r = std::make_unique<CriticRoom>();
  auto loaded = LoadLayout(layout);
  REQUIRE(loaded.ok());
  r->layout = *loaded;
  auto building = BuildBuilding(r->layout);
  REQUIRE(building.ok());
  r->building = std::move(*building);
  auto contexts = scene::RoomContexts(r->layout, r->building, BuildOptions{});
  REQUIRE(contexts.ok());
  r->contexts = std::move(*contexts);
  for (const scene::RoomContext& c : r->contexts)
    if (c.name == room) r->context = &c;
  REQUIRE(r->context);
  auto library = scene::OpenFurnishingLibrary("", true);
  REQUIRE(library.ok());
  r->library = library->library;
  auto acquirer = scene::AssetAcquirer::Make(*r->library, {}, seed, "");
  REQUIRE(acquirer.ok());
  r->acquirer = *acquirer;
  auto plan = scene::PriorsPlanner().Plan({r->context, "", seed, &r->layout});
  REQUIRE(plan.ok());
  r->plan = std::move(*plan);
  REQUIRE(r->acquirer->Acquire(*r->context, r->plan.objects).ok());
  const solver::AssetResolver resolve = [lib = r->library, acq = r->acquirer](const std::string& id)
      -> Result<std::pair<AssetRecord, std::shared_ptr<const AssetMesh>>> {
    const AssetRecord* record = acq->Find(id);
    if (!record) return Error{"asset " + id + " is not in the library"};
    auto mesh = lib->Mesh(id);
    if (!mesh.ok()) return Error{mesh.error()};
    return std::make_pair(*record, *mesh);
  };
  auto mapped = solver::RoomProblemOf(*r->context, r->building, r->plan.objects, r->plan.edges, resolve);
  REQUIRE(mapped.ok());
  r->mapped = std::move(*mapped);
  solver::SolveOptions solve;
  solve.seed = seed;
  r->input = {r->context, &r->building, &r->mapped.problem, &r->plan.objects, &r->plan.edges, "", solve, {}, resolve};
  return r;
}

}  // namespace villa::testing
