#pragma once
// A furnished .glb read back by another reader (assimp) must hold every object of its scene.json where the
// scene puts it: a node named by its id under its room's node, extras naming it exactly, its transform the
// pose (origin and facing direction checked through the file's frame map), and objects of one asset
// sharing one mesh. Used by the tests of `villa furnish` and `villa generate`.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "building/export.h"
#include "scene/scene.h"

namespace villa::testing {

// A point of glTF's +Y-up file frame back in the building frame (z up).
inline Vec3 FromGltf(double x, double y, double z) { return {x, -z, y}; }

// The nodes by name, for further checks by the caller.
inline std::map<std::string, const SceneNodeInfo*> CheckGlbAgreesWithScene(const SceneInfo& glb, const scene::SceneFile& s) {
  std::map<std::string, const SceneNodeInfo*> nodes;
  for (const SceneNodeInfo& n : glb.nodes) nodes[n.name] = &n;
  for (const scene::SceneObject& o : s.objects) {
    INFO(o.id);
    REQUIRE(nodes.count(o.id));
    REQUIRE(o.pose);
    const SceneNodeInfo& n = *nodes[o.id];
    CHECK(n.path == "villa/level_" + std::to_string(o.level) + "/" + o.room + "/" + o.id);
    CHECK(n.metadata.at("id") == o.id);
    CHECK(n.metadata.at("name") == o.id);
    CHECK(n.metadata.at("asset") == o.asset);
    CHECK(n.metadata.at("category") == o.category);
    CHECK(n.metadata.at("parent") == o.parent);
    CHECK(n.metadata.at("relation") == std::string(scene::RelationName(o.relation)));
    const Vec3 origin = FromGltf(n.global[3], n.global[7], n.global[11]);
    CHECK(origin.x == Approx(o.pose->x).margin(1e-4));
    CHECK(origin.y == Approx(o.pose->y).margin(1e-4));
    CHECK(origin.z == Approx(o.pose->z).margin(1e-4));
    // The asset's front (-y in its frame; in glTF asset (0, -1, 0) is file (0, 0, 1)) faces f(yaw).
    const Vec3 front_file{n.global[2], n.global[6], n.global[10]};
    const Vec3 front = FromGltf(front_file.x, front_file.y, front_file.z) * (1.0 / o.scale[1]);
    CHECK(front.x == Approx(std::sin(o.pose->yaw)).margin(1e-4));
    CHECK(front.y == Approx(-std::cos(o.pose->yaw)).margin(1e-4));
  }
  // Instancing: objects with the same asset share one mesh.
  std::map<std::string, std::vector<int>> meshes_of;
  for (const scene::SceneObject& o : s.objects) {
    auto& m = meshes_of[o.asset];
    if (m.empty()) m = nodes[o.id]->meshes;
    else CHECK(nodes[o.id]->meshes == m);
  }
  CHECK(meshes_of.size() < s.objects.size());
  return nodes;
}

}  // namespace villa::testing
