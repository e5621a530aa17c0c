// `villa reach` on a scene file: a bedroom whose door a wardrobe closes is reported with the wardrobe named,
// as text and as JSON; a bad radius is a usage error.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "scene/file_digest.h"
#include "scene/scene.h"

namespace villa::solver {
namespace {

namespace fs = std::filesystem;

// Runs the villa binary; its exit status and everything it printed.
std::pair<int, std::string> Villa(const std::string& args, const fs::path& dir) {
  const fs::path log = dir / "villa.log";
  const int status = std::system((std::string(VILLA_BINARY) + " " + args + " > " + log.string() + " 2>&1").c_str());
  std::ifstream in(log);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, std::string((std::istreambuf_iterator<char>(in)), {})};
}

TEST_CASE("villa reach names the wardrobe that seals a bedroom, as text and as JSON", "[reach][cli]") {
  const fs::path dir = fs::temp_directory_path() / ("villa_reach_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json", dir / "layout.json");
  scene::SceneFile file;
  file.layout = {"layout.json", *scene::FileSha256(dir / "layout.json")};
  for (const char* room : {"living-room_0/0", "kitchen_0/0", "dining-room_0/0", "bedroom_0/0", "bathroom_0/0", "office_0/0"}) {
    file.rooms.push_back({room, {}, {}, {}, {}});
  }
  scene::SceneObject wardrobe;
  wardrobe.id = "bedroom_0/0/wardrobe-0";
  wardrobe.asset = "test:wardrobe";
  wardrobe.category = "wardrobe";
  wardrobe.room = "bedroom_0/0";
  wardrobe.pose = scene::Pose{2.0, 5.38, 0.175, std::numbers::pi};  // against the south wall, across the door
  wardrobe.size = {2.0, 0.6, 2.0};
  wardrobe.affordances = kConsumer | kProvider | kInteractor;
  wardrobe.parent = "floor";
  wardrobe.relation = scene::Relation::kAgainstWall;
  wardrobe.wall = scene::WallRef{0, 0.02};
  wardrobe.interaction_zone = scene::InteractionZone{"front", 0.8, {}};
  file.objects.push_back(wardrobe);
  REQUIRE(scene::WriteScene(file, dir / "scene.json").ok());

  const auto [status, out] = Villa("reach " + (dir / "scene.json").string(), dir);
  INFO(out);
  CHECK(status == 0);
  CHECK(out.find("rooms 5/6 reachable") != std::string::npos);
  CHECK(out.find("bedroom_0/0/wardrobe-0") != std::string::npos);

  const auto [json_status, json_out] = Villa("reach --json " + (dir / "scene.json").string(), dir);
  REQUIRE(json_status == 0);
  const auto report = nlohmann::json::parse(json_out);
  CHECK(report["rch"].get<double>() == Approx(5.0 / 6.0).margin(1e-4));
  bool named = false;
  for (const auto& room : report["rooms"]) {
    if (room["room"] == "bedroom_0/0") {
      CHECK(room["reachable"] == false);
      named = room["blockers"] == nlohmann::json::array({"bedroom_0/0/wardrobe-0"});
    } else {
      CHECK(room["reachable"] == true);
      CHECK(room["path"].size() >= 2);
    }
  }
  CHECK(named);
  CHECK(report["zones"].size() == 1);

  const auto [bad, bad_out] = Villa("reach --radius 0 " + (dir / "scene.json").string(), dir);
  CHECK(bad == 2);
  CHECK(bad_out.find("radius") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("villa reach refuses a scene that breaks its contract: a parent cycle, an object in no room of the layout", "[reach][cli][issue33]") {
  const fs::path dir = fs::temp_directory_path() / ("villa_reach_bad_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json", dir / "layout.json");
  scene::SceneFile file;
  file.layout = {"layout.json", *scene::FileSha256(dir / "layout.json")};
  for (const char* room : {"living-room_0/0", "kitchen_0/0", "dining-room_0/0", "bedroom_0/0", "bathroom_0/0", "office_0/0"})
    file.rooms.push_back({room, {}, {}, {}, {}});
  auto object = [](const std::string& id, const std::string& room, const std::string& parent) {
    scene::SceneObject o;
    o.id = id;
    o.asset = "test:box";
    o.category = "decor";
    o.room = room;
    o.pose = scene::Pose{2.0, 2.0, 0.9, 0.0};
    o.size = {0.2, 0.2, 0.2};
    o.affordances = kConsumer;
    o.parent = parent;
    o.relation = scene::Relation::kOnTop;
    return o;
  };
  file.objects.push_back(object("kitchen_0/0/decor-0", "kitchen_0/0", "kitchen_0/0/decor-1"));
  file.objects.push_back(object("kitchen_0/0/decor-1", "kitchen_0/0", "kitchen_0/0/decor-0"));
  file.objects.push_back(object("attic_9/0/decor-2", "attic_9/0", "floor"));
  REQUIRE(scene::WriteScene(file, dir / "scene.json").ok());
  const auto [status, out] = Villa("reach " + (dir / "scene.json").string(), dir);
  INFO(out);
  CHECK(status == 1);
  CHECK(out.find("scene.json: not a valid scene (") != std::string::npos);
  CHECK(out.find("attic_9/0") != std::string::npos);
  CHECK(out.find("kitchen_0/0/decor-0") != std::string::npos);
  // An object 3e10 m away: refused at once, not rastered (it once took 2.8 GB).
  file.objects = {object("kitchen_0/0/decor-0", "kitchen_0/0", "floor")};
  file.objects[0].pose->x = 3e10;
  REQUIRE(scene::WriteScene(file, dir / "far.json").ok());
  const auto [far_status, far_out] = Villa("reach " + (dir / "far.json").string(), dir);
  INFO(far_out);
  CHECK(far_status == 1);
  CHECK(far_out.find("object kitchen_0/0/decor-0 stands at (30000000000.000000,") != std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace villa::solver
