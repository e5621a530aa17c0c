#pragma once
// Can a person walk everywhere in the furnished building (issue 13)? A person is a disc (radius 0.2 m by
// default) on each level's floor: the union of the level's rooms, minus the building's walls (their door
// and open gaps stay passable), door leaves, window panes, the staircase rising from the level, the hole
// of the one arriving from below, and every placed object whose bottom is below head height (2.0 m above
// the floor; floor coverings are walked on). Levels are joined by their staircases: from the strip in front
// of the first flight's foot to the strip in front of the second flight's top on the level above.
//
// An open door leaf is an obstacle where it stands (it may close a narrow way); a leaf shut in its opening is
// not (the person opens it). When something is unreachable, objects and open leaves are told apart.
//
// Deciding: a raster flood fill (2 cm cells) of the floor eroded by the radius, across levels through the
// stairs, from the entrance. A cell is free when the shared clearance query (solver/free_space.h) says the
// disc at its centre touches nothing, so "free" means what it means to the pose solver. Sampling planners
// cannot prove that a place is unreachable; the raster can.
// Drawing: OMPL paths for everything reachable (RealVectorStateSpace(2), a StateValidityChecker and a
// MotionValidator on the same query; a PRM roadmap built once per level and queried for every target;
// RRTConnect when the roadmap has no answer), simplified, with their lengths. OMPL stays in reach_paths.cpp.
// Blocking: for what is unreachable, a raster shortest path on which cells taken only by objects cost more
// instead of being forbidden; the objects it crosses are the blockers (solver/reach_feedback.h moves them).
//
// Frame: world plan x, y and height z in metres (SCENE.md); rings CCW. Everything here is plain types.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "layout/layout.h"
#include "mesh/mesh.h"
#include "solver/box.h"
#include "util/result.h"

namespace villa {
struct BuildingMesh;
struct BuildOptions;
}  // namespace villa

namespace villa::solver {

struct ReachOptions {
  double radius = 0.2;         // m, the person's disc (SCENE.md agent radius), [0.05, 1]
  double cell = 0.02;          // m, side of a raster cell (SCENE.md raster), [0.005, 0.1]
  double head_height = 2.0;    // m above the floor: objects whose bottom is lower are obstacles, (0.5, 2.6]
  // A zone that holds objects allowed in it (the table at a chair, the chair at a desk) is also reached by
  // standing within this much of its owner (m, beyond touching), [0, 1]: one pulls the chair out.
  double arm_reach = 0.3;
  double entrance_snap = 0.6;  // m: the walk starts at the free cell nearest the entrance, at most this far, (0, 3]
  // Looking for blockers: a cell taken only by objects costs this many free cells, [2, 1e5]. Higher finds
  // the way through the fewest object cells; lower the shortest way.
  double block_cost = 30.0;
  bool paths = true;           // draw OMPL paths (false: the raster's verdict and lengths only)
  int roadmap_density = 12;    // PRM milestones per m2 of reachable floor, [1, 200]
  int roadmap_min = 150;       // milestones per level at least, [10, 1e6]
  int roadmap_max = 3000;      // and at most, [roadmap_min, 1e6]
  int rrt_iterations = 20000;  // RRTConnect iterations for a target the roadmap does not join, [0, 1e7]
  uint64_t seed = 1;           // the roadmap's samples (SplitMix64): same seed, same paths

  // False, with the reason in *message, when a field is out of its range.
  bool IsValid(std::string* message) const;
};

// ---- input

// Where the person may stand on one level (before obstacles): the union of the level's rooms.
struct ReachLevel {
  int level = 0;
  double floor_z = 0.175;    // m, world height of the floor surface
  std::vector<Ring> floor;   // rings, even-odd (a ring inside another is a hole)
};

enum class ObstacleKind { kWall, kDoorLeaf, kWindow, kStair, kStairHole, kObject };
std::string_view ObstacleKindName(ObstacleKind kind);  // "wall", "door_leaf", "window", "stair", "stair_hole", "object"

// Something a person walks around, on one level: convex plan pieces between two world heights.
struct ReachObstacle {
  std::string name;     // object id, or the building part's name ("exterior_0_3", "living0_kitchen0")
  ObstacleKind kind = ObstacleKind::kObject;
  int level = 0;
  std::string room;     // objects: the room whose solver may move them
  std::vector<Ring> pieces;  // convex, CCW (ConvexPieces)
  double z0 = 0.0, z1 = 0.0;
};

// A stretch of a staircase's outline where a person steps on or off it, and the unit direction out of
// the staircase there.
struct StairStep {
  Segment along;
  Point out;
};

// A staircase from `level` to level + 1, read from its mesh. The person steps on where the treads just
// inside its outline are within two risers of the floor (across the first flight's foot, or sideways onto
// its first treads from a door beside them), and off where they are within two risers of the floor above
// (the second flight's top, or its last treads' side). `walk` is the way along the flights (world points,
// from the middle of the first flight's foot to the middle of the second flight's top), `length` its 3D
// length (m). Standing on the stairs counts as being in `room` (level) and in `upper_room` (level + 1,
// the room its hole opens in): a staircase hall the flights fill is reached when its stairs are.
struct StairLink {
  std::string room;
  std::string upper_room;  // "" when no room above holds the hole
  int level = 0;
  std::vector<StairStep> entries;  // on `level`
  std::vector<StairStep> exits;    // on level + 1
  std::vector<Vec3> walk;
  double length = 0.0;
};

// Somewhere to reach: a point inside a room, or the interaction zone of a V_int object.
enum class TargetKind { kRoom, kZone };
std::string_view TargetKindName(TargetKind kind);  // "room", "zone"

// A part of a target: the person is there when its centre lies inside `polygon` (kInside), or when its
// disc comes within `reach` m of it (kTouch; 0: the disc touches the polygon).
struct TargetArea {
  enum class Mode { kInside, kTouch };
  Ring polygon;
  Mode mode = Mode::kInside;
  double reach = 0.0;
};

struct ReachTarget {
  TargetKind kind = TargetKind::kRoom;
  std::string name;    // the room's name, or the object's id
  std::string room;
  int level = 0;
  std::vector<TargetArea> areas;  // any one will do
};

struct ReachInput {
  std::vector<ReachLevel> levels;  // one per level, ascending
  std::vector<ReachObstacle> obstacles;
  std::vector<StairLink> stairs;
  // The entrance (ground floor): the person comes in across `entrance`, from the outside; `inside` is the
  // unit normal pointing into the building, `depth` how far in the walk starts (the wall's thickness).
  Segment entrance;
  Point inside;
  double depth = 0.25;
  std::vector<ReachTarget> targets;
  // Points worth a roadmap milestone whatever the samples do (level, point): the middle of every door and
  // open, where a sampled roadmap is thinnest.
  std::vector<std::pair<int, Point>> anchors;
};

// A placed object as reachability sees it.
struct ReachObject {
  std::string id;
  std::string room;
  int level = 0;
  OrientedBox box;           // world: footprint and heights (m)
  bool covering = false;     // a floor covering (rug): walked on, no obstacle
  // V_int: the zone boxes beside it (world footprints), and whether objects allowed in it stand there.
  std::vector<Ring> zone;
  bool zone_shared = false;
};

// The building's part of the input (levels, walls, leaves, panes, stairs, holes, entrance) and a room
// target for every room, from the layout and its built building (BuildBuilding with the same options).
// Building parts count where they stand between the floor and head height (reach.head_height): the wall
// over a door is higher, so a door is a gap; the wall under a window is not.
Result<ReachInput> BuildingReachInput(const Layout& layout, const BuildingMesh& building, const BuildOptions& options,
                                      const ReachOptions& reach = {});
// Adds the objects: obstacles (bottom below head height, not coverings) and a zone target for every V_int
// object with a zone.
void AddObjects(ReachInput& input, const std::vector<ReachObject>& objects, const ReachOptions& options);
// The zone boxes of an object (SCENE.md interaction_zone: `side` front/back/left/right/sides, `depth` m,
// the object's full width or depth) as world footprints.
std::vector<Ring> ZoneFootprints(const OrientedBox& box, const std::string& side, double depth);

// ---- output

struct ReachPath {
  std::vector<Vec3> points;   // world: plan points at their floor's height, the stairs' way in between
  std::vector<int> level;     // per point: the level walked on, -1 on a stair's way
  double length = 0.0;        // m, 3D
  std::string planner;        // "prm", "rrt_connect", "straight" (start and goal in sight of each other)
};

struct TargetResult {
  TargetKind kind = TargetKind::kRoom;
  std::string name;
  std::string room;
  int level = 0;
  bool reachable = false;
  Point goal;                      // where the person stands (reachable targets)
  double raster_length = -1.0;     // m, the raster's geodesic from the entrance (stairs included); -1: none
  std::optional<ReachPath> path;   // the drawn OMPL path (reachable targets, when options.paths)
  std::string note;                // why no path was drawn, or why it is unreachable
  // Zones: SCENE.md's ACC, the share of the zone's area a person standing on reached floor covers (their
  // disc; the disc never covers an obstacle, so that part is on free floor); 1 for a zone that holds the
  // objects allowed in it (the table at a chair) reached within arm's reach of its owner. Rooms: 1 or 0.
  double share = 0.0;
  // Unreachable: the objects on the cheapest way through objects and open door leaves (in the order
  // met), the leaves on it (the building's: nothing the solver moves), and that way's raster cells as world
  // points per level (the walkway the feedback keeps free).
  std::vector<std::string> blockers;
  // Open door leaves on the blocked way: none since the leaves count as fixed (2026-11-24, the blocked way
  // goes round them); kept for the report's format.
  std::vector<std::string> door_leaves;
  std::vector<std::pair<int, std::vector<Point>>> blocked_way;
  bool structural = false;         // unreachable even without objects: walls, stairs, holes, open door leaves
};

struct LevelStats {
  int level = 0;
  long cells = 0;               // raster cells
  double free_area = 0.0;       // m2 of cells where the disc is free
  double reached_area = 0.0;    // m2 of them reached from the entrance
  int milestones = 0, roadmap_edges = 0;
  double seconds_raster = 0.0;   // occupancy, distance transform, exact classification
  double seconds_roadmap = 0.0;  // PRM construction
  double seconds_queries = 0.0;  // path queries and simplification on this level
};

// The raster cells of one level a person reached from the entrance (with everything in place), for the
// feedback's last resort: a zone moved where a reached cell's disc touches it is reachable, as long as the
// move itself does not cut the way to that cell.
struct ReachedCells {
  int level = 0;
  double x0 = 0.0, y0 = 0.0;  // world corner of cell (0, 0), m
  double cell = 0.02;         // m
  int nx = 0, ny = 0;
  std::vector<uint8_t> reached;  // row-major, nx * ny: 1 reached
  // Whether the cell holding p was reached (false outside the grid).
  bool At(Point p) const;
};

struct ReachReport {
  bool entrance_free = false;   // a free cell near the entrance
  std::vector<TargetResult> targets;  // in input order
  std::vector<ReachedCells> reached;  // per level, ascending (not in ToJson)
  int rooms = 0, rooms_reachable = 0;
  int zones = 0, zones_reachable = 0;
  int paths_drawn = 0;
  std::vector<LevelStats> levels;
  double seconds = 0.0;
  double seconds_blockers = 0.0;

  double Rch() const { return rooms ? static_cast<double>(rooms_reachable) / rooms : 1.0; }
  double zone_share = 0.0;  // the sum of the zones' shares
  // RCH: the share of rooms reachable. ACC: the mean over the zones of the share of each zone reachable.
  double Acc() const { return zones ? zone_share / zones : 1.0; }
  const TargetResult* Find(std::string_view name) const;
  std::string BriefReport() const;
  // {"rch", "acc", "rooms": [...], "zones": [...], "levels": [...]}; numbers at 4 decimals, paths as
  // [x, y, z] lists.
  nlohmann::ordered_json ToJson() const;
};

// Checks every target. An invalid input or options is an error naming the field; unreachable targets are
// results, not errors.
Result<ReachReport> CheckReach(const ReachInput& input, const ReachOptions& options);

}  // namespace villa::solver
