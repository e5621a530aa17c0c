#pragma once
// The structural validator of a scene (SCENE.md "Rules"): what must hold of the graph before and after
// solving, independent of geometry. Each broken rule is a Finding naming the object (or room) and the rule;
// an empty list means the scene is structurally sound.
//
//   rule            what it checks
//   id              ids unique, of the form <room>/<category>-<k> with the object's own room and category
//   room            the object's room is a room of the layout, listed in `rooms`, on the object's level
//   rooms           `rooms` holds exactly the layout's rooms (a plan: only rooms of the layout)
//   physical-edge   every object but on_wall / hanging ones is V_con with its one parent + relation, and
//                   the relation fits the parent (ontop: floor or object; inside: object; against_wall:
//                   floor; on_wall: wall; hanging: ceiling)
//   forest          parents exist; following parents always ends at floor / wall / ceiling (no cycle)
//   level           a child's level equals its parent's
//   provider        a parent object is V_pro
//   surface         ontop an object names an existing support surface of the parent's asset
//   cavity          inside names an existing cavity of the parent's asset
//   wall            a posed against_wall / on_wall object names an edge of its room's polygon
//   asset           a named asset exists in the library (when a lookup is given); V_pro needs S or C
//   zone            interaction zones only on V_int objects; exempt ids exist
//   edge            semantic edges join two different objects of that room
//   hint            hints are known words
// Until an asset is chosen (asset ""), surface and cavity indices cannot be checked and may be absent; the
// solver chooses them, so an object without a pose (a plan with assets) may leave them unnamed too.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset.h"
#include "layout/layout.h"
#include "scene/scene.h"

namespace villa::scene {

struct Finding {
  std::string subject;  // object id, room name, or "scene"
  std::string rule;     // one of the rule names above
  std::string message;  // what is wrong, with the bad value
};

// An asset record by id; nullptr when the library has no such asset.
using AssetLookup = std::function<const AssetRecord*(std::string_view id)>;

struct ValidateOptions {
  // A plan lists only the rooms it planned; a solved scene lists every room of the layout.
  bool all_rooms = true;
};

// `lookup` may be empty: then asset-dependent rules (surface, cavity, asset) are skipped.
std::vector<Finding> ValidateScene(const SceneFile& scene, const Layout& layout, const AssetLookup& lookup,
                                   const ValidateOptions& options = {});

// "<subject>: <rule>: <message>" a line each.
std::string FormatFindings(const std::vector<Finding>& findings);

}  // namespace villa::scene
