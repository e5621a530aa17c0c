#pragma once
// A furnished .glb dropped into Bullet as an outside reader would (issue 28): object nodes are those whose
// extras name a `room` (SCENE.md "The furnished glTF"); every other node with a mesh is the building,
// static. Objects hung on a wall (`on_wall`), from the ceiling (`hanging`) or on a rail (hanging clothes)
// are welded; rugs (`rug`, or floor things at most 3 mm high) are decals and left out. The rest fall for
// `seconds` and are judged by the strict and loose rules of physics/settle.h, per room type.
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "physics/settle.h"
#include "util/result.h"

namespace villa::physics {

struct GlbObjectMotion {
  std::string id, room, category;
  std::string room_type;  // the room's category ("bedroom"), from its name
  BodyMotion motion;
};

struct StabilityCount {
  int free = 0, strict = 0, loose = 0;
  StabilityCount& operator+=(const StabilityCount& o) {
    free += o.free, strict += o.strict, loose += o.loose;
    return *this;
  }
};

struct GlbSettleSummary {
  std::vector<GlbObjectMotion> objects;  // every simulated object (free and welded), in the file's order
  std::map<std::string, StabilityCount> by_room_type;
  StabilityCount all;
  int decals = 0;  // rugs left out
  int starts_inside = 0;  // objects starting more than 2 mm inside another or the building
  int parts = 0, static_triangles = 0;
  double seconds = 0.0;
};

// `only`: when not empty, only these objects (ids) are free; the others are welded where they stand (to
// see what one object does among the rest).
// What a .glb holds for a simulator: the building's meshes (static), the objects as bodies (welded or free,
// rugs left out as decals), each object's names, all in the plan frame (z up).
// A door leaf with its hinge (the building's node extras, BUILDING.md): the vertical axis through `hinge`
// (hinge_x, hinge_y: plan frame) and the turns (radians, counter-clockwise from above) to closed and to 90 degrees open.
struct GlbDoor {
  std::string name;
  int static_index = -1;  // its mesh in GlbBodies::statics (a settle keeps leaves where they hang)
  double hinge_x = 0.0, hinge_y = 0.0;
  double to_closed = 0.0, to_open = 0.0;
};
struct GlbBodies {
  std::vector<TriangleMesh> statics;
  std::vector<GlbDoor> doors;
  std::vector<SettleBody> bodies;
  std::vector<GlbObjectMotion> objects;  // parallel to bodies (no motion yet)
  int decals = 0;
};
Result<GlbBodies> ReadGlbBodies(const std::filesystem::path& glb);

Result<GlbSettleSummary> SettleGlb(const std::filesystem::path& glb, const SettleOptions& options = {},
                                   const std::vector<std::string>& only = {});
// The same for a .glb's bytes (a furnished villa before it is written).
Result<GlbSettleSummary> SettleGlbBytes(const std::string& glb, const SettleOptions& options = {});

// The villa settled again where only `rooms` changed since `before` (the settle of the same villa): only
// their objects are simulated (the building whole; objects of different rooms never touch) and the other
// rooms keep what `before` found for them. `seconds` is this settle's.
Result<GlbSettleSummary> ResettleRooms(const std::string& glb, const GlbSettleSummary& before, const std::set<std::string>& rooms,
                                       const SettleOptions& options = {});

// {"free", "strict", "loose", "strict_share", "loose_share"}.
nlohmann::ordered_json StabilityJson(const StabilityCount& count);
// report.json's "physics": {"seconds_simulated", "all", "by_room_type", "movers" (up to `movers`, the
// largest first: id, moved_m, turned_rad), "starts_inside", "decals", "seconds"}.
nlohmann::ordered_json SettleSummaryJson(const GlbSettleSummary& summary, const SettleOptions& options, int movers = 10);

}  // namespace villa::physics
