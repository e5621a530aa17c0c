#pragma once
// A room to furnish, as plain types: the input of the pose solver (solver/solve.h).
//
// Frames and units (shared/design/SCENE.md "Frames and units"): world = the layout frame with z up, metres;
// angles are radians inside the code (degrees only in files). An object's pose (x, y) is the centre of its
// footprint, z the world height of its bottom, yaw counter-clockwise seen from above, the asset's front (-y)
// facing f(yaw) = (sin yaw, -cos yaw). Polygons are counter-clockwise rings without a repeated closing point.
//
// The problem is built from the scene graph, the room context and the asset library by the furnish
// pipeline, and directly by tests and benches. It holds no Ceres, FCL or Eigen types.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset.h"
#include "assets/asset_mesh.h"
#include "layout/layout.h"
#include "mesh/mesh.h"
#include "solver/box.h"
#include "solver/placement.h"
#include "util/result.h"

namespace villa::solver {

// What a keep-out zone protects: one kind per kind of the room context's zones (scene/room_context.h), so
// the furnish pipeline maps them one to one, and the walkway the reachability feedback keeps free for a
// person (solver/reach_feedback.h; floor coverings may lie on it). Names in messages depend on it.
enum class KeepOutKind {
  kDoorSweep, kDoorStrip, kOpenPassage, kWindowZone, kStaircase, kStairHole, kStairArrival, kOther, kWalkway,
  // Issue 27: the way through a room between its doors (a room others are reached through keeps a path
  // free, as a designer leaves circulation); floor coverings may lie on it.
  kCirculation
};
std::string_view KeepOutKindName(KeepOutKind kind);  // "door_sweep", "door_strip", "open_passage", ...

// A prism no object may enter: `polygon` (world x/y, CCW; convex or not) between heights z_min and z_max
// (world, m). A window zone starts at the sill, so a low sideboard may stand under the window.
struct KeepOut {
  Ring polygon;
  double z_min = 0.0;
  double z_max = 0.0;
  KeepOutKind kind = KeepOutKind::kOther;
  std::string name;  // for messages ("door kitchen_0/0 -> hall_0/0")
};

// A hole in a wall (door, open gap, window) as seen along the wall: from t0 to t1 m measured from the
// wall's `a` end, between world heights z0 and z1. Nothing stands against it or hangs over it.
struct WallOpening {
  double t0 = 0.0;
  double t1 = 0.0;
  double z0 = 0.0;
  double z1 = 0.0;
};

// The inner face of one wall: a segment of the free floor's boundary from `a` to `b` with the room on its
// left (the free floor is CCW). `edge` names the room polygon's edge i -> i+1 (SCENE.md `wall.edge`).
struct WallEdge {
  int edge = -1;
  Point a;
  Point b;
  bool hang_allowed = true;  // on_wall objects may hang here (false: glass, railings)
  std::vector<WallOpening> openings;
};

// A piece of the building the exact check treats as an obstacle (a wall piece, an open door leaf, a
// flight of stairs): a triangle mesh in the world frame.
struct BuildingPart {
  std::string name;
  TriangleMesh mesh;
};

// The physical edge of an object (SCENE.md `relation`): on a surface of its parent (or on the floor), in a
// cavity of its parent, on the floor with its back to a wall, hung on a wall, hung from the ceiling.
enum class Relation { kOnTop, kInside, kAgainstWall, kOnWall, kHanging };
std::string_view RelationName(Relation relation);  // "ontop", "inside", "against_wall", "on_wall", "hanging"
std::optional<Relation> ParseRelation(std::string_view name);

// Which object gives way when not everything fits: the lowest priority first (SCENE.md `origin`: the room
// type's essential pieces and what carries them (issue 27: a bedroom's bed, a kitchen's sink and the counter
// under it) > named in the request > room prior > decorative, e.g. added by a critic). Essential and named
// objects are protected: the agent, the critic and the reachability feedback move, turn or shrink them and
// remove other objects to make room for them; one is removed only when nothing else is left to try, and
// the report says so.
enum class Priority { kDecorative = 0, kPrior = 1, kNamed = 2, kEssential = 3 };
std::string_view PriorityName(Priority priority);  // "decorative", "prior", "named", "essential"
inline bool IsProtected(Priority priority) { return priority >= Priority::kNamed; }
std::optional<Priority> ParsePriority(std::string_view name);

// The box kept free in front of (or beside) a V_int object: `depth` m deep, the object's full width (or
// depth, for side zones) and height. `side`: "front", "back", "left", "right" or "sides" (both long sides,
// for beds); the object's left is asset +x (seen from the object, facing -y). Objects named in `exempt`
// may enter it (the coffee table in front of a sofa).
struct InteractionZone {
  std::string side = "front";
  double depth = 0.0;
  std::vector<std::string> exempt;
};

// One node of the room's A-PSSG with its physical edge. Object ids are unique within the problem.
struct ProblemObject {
  std::string id;        // "living-room_0/0/sofa-0"
  std::string category;  // "sofa"
  AssetRecord asset;     // size, support surfaces, cavities, placement (SCENE.md asset record)
  std::shared_ptr<const AssetMesh> mesh;  // the asset's geometry in the asset frame, for the exact check

  std::string parent = "floor";  // "floor", "wall", "ceiling" or another object's id
  Relation relation = Relation::kOnTop;
  int surface = -1;  // kOnTop on an object: index into the parent's support_surfaces; -1: the solver picks
  int cavity = -1;   // kInside: index into the parent's cavities; -1: the solver picks
  int wall = -1;     // kAgainstWall / kOnWall: index into RoomProblem::walls; -1: the solver picks
  double wall_gap = 0.02;  // m between the back face and the wall, [0, 0.2]

  // Uniform scale the solver may apply, [0.5, 2] with scale_min <= 1 <= scale_max (SCENE.md: [0.8, 1.25]).
  double scale_min = 1.0;
  double scale_max = 1.0;
  Priority priority = Priority::kPrior;
  std::optional<InteractionZone> zone;  // V_int only; nullopt: none kept free
  // m kept free behind it, across its width (a dining or meeting table's chair: room to pull it out, issue
  // 27); a second zone of the solver's, as soft as V_int's. 0: none.
  double pull_out = 0.0;
  // Placement wishes of the planner (scene/scene.h kHint*: far_from_door, near_window, middle, corner,
  // open_floor), read as preferences by the constructive start (solver/place.cpp).
  std::vector<std::string> hints;
};

// SCENE.md's semantic relations; params as SceneEval's (face_to within max_deg; next_to gap 0-0.5,
// near 0.5-1.5, far >= 1.5 m; align yaw equal mod 90 +- 5 deg; centred lateral offset <= 0.05 m).
enum class SemanticRelation { kFaceTo, kFrontOf, kBehind, kLeftOf, kRightOf, kNextTo, kNear, kFar, kAlign, kCentered };
std::string_view SemanticRelationName(SemanticRelation relation);  // "face_to", "front_of", ..., "centered"
std::optional<SemanticRelation> ParseSemanticRelation(std::string_view name);

struct SemanticEdge {
  std::string source;  // object id
  SemanticRelation relation = SemanticRelation::kNear;
  std::string target;  // object id
  // face_to: largest angle (rad) between f(source) and the direction to the target's centre.
  // align: largest yaw difference mod 90 degrees (rad). centered: largest lateral offset (m).
  // next_to / near / far: the gap range between the two boxes (m). Defaults per relation: DefaultEdge().
  double max_angle = 0.0;
  double min_gap = 0.0;
  double max_gap = 0.0;
  double tolerance = 0.0;
};
// An edge with SceneEval's default parameters for its relation.
SemanticEdge DefaultEdge(std::string source, SemanticRelation relation, std::string target);

struct RoomProblem {
  std::string room;          // "living-room_0/0"
  Ring free_floor;           // CCW, may be non-convex, edges at any angle: the room inset by its walls
  double floor_z = 0.175;    // world height of the floor surface (m)
  double clear_height = 2.625;  // m from the floor to the ceiling
  std::vector<WallEdge> walls;
  std::vector<KeepOut> keep_outs;
  std::vector<BuildingPart> building;  // obstacles for the exact check (walls, door leaves, stairs)
  std::vector<ProblemObject> objects;
  std::vector<SemanticEdge> edges;

  // Index of the object with this id, or -1.
  int Find(std::string_view id) const;
  // Checks what the solver relies on; the message names the room, the object id or the field, and the bad
  // value: unique ids, known parents (no cycles), surfaces and cavities that exist, scale ranges, meshes.
  Status Check() const;
};

// The object's box where it stands (world: footprint centre, yaw, half sizes and heights, all scaled).
OrientedBox StandingBox(const ProblemObject& object, const Pose& pose);
// A flat floor object (a rug, <= 3 cm high, on the floor): part of the floor, walked on, no collisions.
bool IsFloorCovering(const ProblemObject& object);
// Empty when `mesh` lies within the box of `asset`'s size (origin at the bottom centre; 1 cm or 1 % of a side
// of slack), else which side it leaves and by how much. The optimiser's boxes are the record's size: a mesh
// reaching outside them would collide where the optimiser sees nothing, so RoomProblem::Check refuses it.
std::string MeshOutsideAssetBox(const AssetRecord& asset, const AssetMesh& mesh);

// One wall along every edge of the free floor (edge i = vertex i -> i+1), no openings: for tests, benches
// and rooms whose context has no wall list.
std::vector<WallEdge> WallsAlongFloor(const Ring& free_floor);

}  // namespace villa::solver
