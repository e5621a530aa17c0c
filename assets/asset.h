#pragma once
// The asset record of shared/design/SCENE.md: everything the furnishing stage knows about one 3D model
// (size, support surfaces S, containment cavities C, front, placement, licence), as types and strict JSON.
// The asset library is a JSONL file of these records; a scene refers to assets by id and never repeats them.
//
// Asset frame: metres, z up, origin at the bottom centre of the asset's axis-aligned box, front = -y,
// width along x, depth along y, height along z (SCENE.md "Frames and units").
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "layout/layout.h"
#include "mesh/mesh.h"
#include "util/result.h"

namespace villa {

// Where an asset should stand: on the floor, hung on a wall, from the ceiling, or on another object.
enum class Placement { kFloor, kWall, kCeiling, kSurface };
std::string_view PlacementName(Placement placement);  // "floor", "wall", "ceiling", "surface"
std::optional<Placement> ParsePlacement(std::string_view name);

// The paper's affordance roles (A-PSSG node attributes), as a bit set.
enum Affordance : unsigned {
  kProvider = 1u << 0,     // V_pro: exposes support surfaces or containment cavities
  kConsumer = 1u << 1,     // V_con: must rest on a surface or inside a cavity (or hang)
  kInteractor = 1u << 2,   // V_int: keeps an interaction zone free
};
// ["V_con", "V_pro", "V_int"] in that fixed order (the order SCENE.md writes them).
std::vector<std::string> AffordanceNames(unsigned affordances);
std::optional<unsigned> ParseAffordances(const std::vector<std::string>& names);

// A horizontal upward surface in the asset frame: `polygon` (CCW, x/y in m) at height `z`, with
// `clear_height` m of free space above it (up to the geometry above, or +inf for a top surface: written
// as the asset's height allowance, see docs/SCENE.md).
struct SupportSurface {
  double z = 0.0;
  Ring polygon;
  double clear_height = 0.0;
  std::string from;  // "drop_on_top", "mesh" or "procedural"
};

// A box of free space inside the asset (a shelf compartment, a cabinet's inside), asset frame.
struct Cavity {
  Vec3 min;
  Vec3 max;
  std::string open = "-y";   // the open side ("-y" = the front) or "closed" (behind a door)
  int floor_surface = -1;    // index into support_surfaces of the cavity's floor, -1 when none
  // The top of a hanging rail across the cavity along x (asset frame z), when it has one; the box ends
  // under the rail. Hangers hook over it (issue 28: clothes hang, they do not stand on a hem).
  std::optional<double> rail;
};

// Garments on hangers: they hang from a cavity's rail, never stand on its floor.
bool HangsFromRail(std::string_view category);
// A hanger's hook lies on the rail: the garment's top is this far (unscaled m) above the rail's top.
inline constexpr double kHookRise = 0.004;
// Whether things of `category` may go into cavity `c` (hanging ones need a rail).
bool CavitySuits(const Cavity& c, std::string_view category);
// The height (unscaled, asset units) a thing of `category` may have there: the box's height, or for a
// hanging one the drop from its hook to the cavity's floor.
double CavityClearHeight(const Cavity& c, std::string_view category);

struct InteractionZoneSpec {
  std::string side = "front";  // "front", "left", "right", "back", "sides" (both long sides, beds)
  double depth = 0.0;          // m
};

struct AssetSource {
  std::string kind;           // "sh3d", "procedural", "gltf", ...
  std::string package;        // "sweethome3d-furniture 1.8-1"
  std::string library;        // "BlendSwap-CC-0.sh3f"
  std::string entry;          // the model's path inside the library
  std::string sh3d_category;  // "Living room"
  std::vector<std::string> tags;
};

struct AssetMeshInfo {
  std::string file;           // relative to the library directory ("" for procedural: rebuilt from the id)
  int triangles = 0;
  bool watertight = false;
  double manifold_edges = 0.0;  // share of edges used by exactly two triangles, [0, 1]
  // The model as its source had it, when `file` holds it decimated to its category's triangle budget
  // (issue 31; "" when `file` is the source's own).
  std::string full_file;
  int full_triangles = 0;
};

struct AssetRecord {
  std::string id;             // "sh3d:BlendSwap-CC-0#couch", "proc:bookcase?cols=2&rows=5&seed=3"
  std::string name;           // human name ("Couch")
  std::string category;       // priors vocabulary: lowercase, '-' separated ("sofa", "bookcase")
  AssetSource source;
  std::string license;        // SPDX id ("CC0-1.0", "CC-BY-3.0")
  std::string creator;
  std::vector<std::string> room_types;  // layout category names this asset suits
  Vec3 size;                  // m: width (x), depth (y), height (z) of the asset frame box
  // 3x4 row-major: source-file coordinates -> asset frame (identity for procedural assets).
  std::array<std::array<double, 4>, 3> to_asset{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
  int front_yaw_offset = 0;   // degrees, a multiple of 90
  // Who found the front on another side (or confirmed it) and how, when someone did ("model NAME at URL:
  // picture 2 of 4, turned by -90 degrees ..."); written only when set (docs/ASSETS.md).
  std::string front_decided_by;
  Placement placement = Placement::kFloor;
  unsigned affordances = kConsumer;
  std::vector<SupportSurface> support_surfaces;
  std::vector<Cavity> cavities;
  std::optional<InteractionZoneSpec> interaction_zone;
  AssetMeshInfo mesh;

  bool Has(Affordance a) const { return (affordances & a) != 0; }
  // Whether support surface `surface` is the floor of a closed cavity (a cell behind a door or a drawer
  // front): a place to store things inside, not a top to stand things on (issue 27: no kettle 'ontop' a
  // counter's inner shelf).
  bool ClosedCellFloor(int surface) const;
  // Credit line for CC-BY assets ("Couch by Jane Doe (CC-BY-3.0)"); empty when none is needed.
  std::string Credit() const;
};

// SCENE.md's JSON. Reading is strict: unknown keys, wrong types and out-of-range values are errors naming
// `where` (e.g. "assets.jsonl:12") and the JSON path ("support_surfaces[1].polygon: ...").
nlohmann::ordered_json AssetToJson(const AssetRecord& asset);
Result<AssetRecord> AssetFromJson(const nlohmann::json& json, const std::string& where);

// The whole library file, one record a line. Reading checks ids are unique (the error names both lines).
Result<std::vector<AssetRecord>> ReadAssetRecords(const std::string& path);
Status WriteAssetRecords(const std::string& path, const std::vector<AssetRecord>& assets);  // atomic

}  // namespace villa
