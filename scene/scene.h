#pragma once
// The scene file of shared/design/SCENE.md as types: every room's A-PSSG (objects with affordance roles,
// physical edges parent + relation, semantic edges) and, once solved, the poses, the solve outcome and the
// metrics. Our refinements of the contract (plans without poses, `hints`, the planner record, typed
// metrics) are in docs/SCENE.md.
//
// Units: metres; yaw in radians here, in degrees in files, always wrapped to (-pi, pi] / (-180, 180].
// Frames as SCENE.md: world = the layout's plan with z up; an object's pose is the bottom centre of its
// asset box; its front is -y of the asset frame, facing (sin yaw, -cos yaw) in the world.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "assets/asset.h"
#include "scene/strict_json.h"
#include "util/result.h"

namespace villa::scene {

inline constexpr std::string_view kSceneFormat = "villa-scene/1";

// Where an object rests (SCENE.md `relation`): the physical edge to its parent.
enum class Relation {
  kOnTop,        // on surface `surface` of the parent object, or on the floor
  kInside,       // in cavity `cavity` of the parent object
  kAgainstWall,  // on the floor, back face `wall.gap` from wall edge `wall.edge`
  kOnWall,       // hung on wall edge `wall.edge`, z free
  kHanging,      // from the ceiling
};
std::string_view RelationName(Relation relation);  // "ontop", "inside", "against_wall", "on_wall", "hanging"
std::optional<Relation> ParseRelation(std::string_view name);

// The ten semantic relations of SCENE.md; geometry is read in the target's frame for the four sides.
enum class SemanticRelation {
  kFaceTo,    // f(source) points at the target's centre within max_deg (default 30)
  kFrontOf,   // source lies in front of the target (target's -y side); optional gap range
  kBehind,
  kLeftOf,
  kRightOf,
  kNextTo,    // gap 0-0.5 m
  kNear,      // gap 0.5-1.5 m
  kFar,       // gap >= 1.5 m
  kAlign,     // yaw equal mod 90 within max_deg (default 5)
  kCentered,  // lateral offset in the target's frame <= max_offset (default 0.05 m)
};
inline constexpr int kSemanticRelationCount = 10;
std::string_view SemanticRelationName(SemanticRelation relation);  // "face_to", "front_of", ...
std::optional<SemanticRelation> ParseSemanticRelation(std::string_view name);

// Parameters of a semantic edge; only those the relation takes may be set (see ParamsAllowed).
struct EdgeParams {
  std::optional<double> max_deg;     // face_to, align: degrees
  std::optional<double> min_gap;     // sides and distance relations: m between the two boxes
  std::optional<double> max_gap;
  std::optional<double> max_offset;  // centered: m
  friend bool operator==(const EdgeParams&, const EdgeParams&) = default;
};
// The parameter names a relation accepts ("max_deg" for face_to and align, "min_gap"/"max_gap" for the
// four sides and next_to/near/far, "max_offset" for centered).
std::vector<std::string_view> ParamsAllowed(SemanticRelation relation);
// The parameters with SCENE.md's defaults filled in for those left unset.
EdgeParams EffectiveParams(SemanticRelation relation, const EdgeParams& params);

struct SemanticEdge {
  std::string source;  // object ids
  SemanticRelation relation = SemanticRelation::kNear;
  std::string target;
  EdgeParams params;
  friend bool operator==(const SemanticEdge&, const SemanticEdge&) = default;
};

struct Pose {
  double x = 0.0;    // m, world: the bottom centre of the object's box
  double y = 0.0;
  double z = 0.0;    // m, world height of the object's bottom
  double yaw = 0.0;  // radians, counter-clockwise seen from +z, in (-pi, pi]
  friend bool operator==(const Pose&, const Pose&) = default;
};
// Wraps an angle in radians to (-pi, pi].
double WrapYaw(double radians);

struct WallRef {
  int edge = 0;       // the room polygon's edge from vertex `edge` to `edge` + 1 (CCW, as parsed)
  double gap = 0.02;  // m between the object's back face and the wall's inner face
  friend bool operator==(const WallRef&, const WallRef&) = default;
};

struct InteractionZone {
  std::string side = "front";        // "front", "back", "left", "right", "sides" (both long sides)
  double depth = 0.0;                // m
  std::vector<std::string> exempt;   // object ids allowed inside it
  friend bool operator==(const InteractionZone&, const InteractionZone&) = default;
};

enum class Origin { kPrompt, kPrior, kCritic };
std::string_view OriginName(Origin origin);  // "prompt", "prior", "critic"
std::optional<Origin> ParseOrigin(std::string_view name);

// Placement wishes the solver reads besides the semantic edges (docs/SCENE.md): edges join objects,
// these name parts of the building.
inline constexpr std::string_view kHintFarFromDoor = "far_from_door";  // >= 1.5 m from every door sweep
inline constexpr std::string_view kHintNearWindow = "near_window";     // within 1.5 m of a window
inline constexpr std::string_view kHintMiddle = "middle";              // free-standing, >= 0.8 m from walls
inline constexpr std::string_view kHintCorner = "corner";              // in a corner of the free floor
// Issue 27: a further zone of a big room (a reading corner, a nook) goes where the floor is emptiest.
inline constexpr std::string_view kHintOpenFloor = "open_floor";
bool IsKnownHint(std::string_view hint);

inline constexpr std::string_view kParentFloor = "floor";
inline constexpr std::string_view kParentWall = "wall";
inline constexpr std::string_view kParentCeiling = "ceiling";
// True for "floor", "wall" and "ceiling" (the roots of the parent forest).
bool IsRootParent(std::string_view parent);

// One node of the A-PSSG.
struct SceneObject {
  std::string id;        // "<room>/<category>-<k>"
  std::string asset;     // asset record id; "" until an asset is chosen (plans)
  std::string category;
  std::string room;
  int level = 0;
  std::optional<Pose> pose;            // absent until solved
  std::array<double, 3> scale{1.0, 1.0, 1.0};
  Vec3 size;                           // m (asset axes): asset size x scale; in plans the target size
  unsigned affordances = kConsumer;    // assets/asset.h bits
  std::string parent;                  // "floor", "wall", "ceiling" or an object id
  Relation relation = Relation::kOnTop;
  std::optional<int> surface;          // ontop an object: index into the parent asset's support_surfaces
  std::optional<int> cavity;           // inside: index into the parent asset's cavities
  std::optional<WallRef> wall;         // against_wall / on_wall: chosen by the solver, absent in plans
  std::optional<InteractionZone> interaction_zone;
  Origin origin = Origin::kPrior;
  std::vector<std::string> hints;      // kHint* words
  friend bool operator==(const SceneObject&, const SceneObject&) = default;
};

// How the room's graph was made (docs/SCENE.md): the planner, its seed and the request text it read.
struct PlanRecord {
  std::string planner;               // "priors", later "mllm"
  uint64_t seed = 0;
  std::string text;                  // the request text given for this room ("" when none)
  std::vector<std::string> notes;    // what the planner could not do ("no room for a bathtub")
  friend bool operator==(const PlanRecord&, const PlanRecord&) = default;
};

enum class SolveOutcome { kConverged, kBudget, kInfeasible };
std::string_view SolveOutcomeName(SolveOutcome outcome);  // "converged", "budget", "infeasible"
std::optional<SolveOutcome> ParseSolveOutcome(std::string_view name);

struct RoomSolve {
  SolveOutcome outcome = SolveOutcome::kConverged;
  int iterations = 0;
  double energy = 0.0;
  std::vector<std::string> removed;  // object ids taken out
  Json actions = Json::array();      // the solver's action records (solver/ owns their shape)
  std::string note;                  // why, in words (a room left empty says so here)
  friend bool operator==(const RoomSolve&, const RoomSolve&) = default;
};

// SCENE.md's metrics by name: CR, FR, OBR, CSR, NO, NAV, ACC, OPC, RCH. Only these names are accepted.
struct Metrics {
  std::vector<std::pair<std::string, double>> values;  // in file order
  friend bool operator==(const Metrics&, const Metrics&) = default;
};
bool IsKnownMetric(std::string_view name);

struct RoomEntry {
  std::string name;                       // layout room name
  std::optional<PlanRecord> plan;         // stored under graph.planner / seed / text / notes
  std::vector<SemanticEdge> edges_sem;
  std::optional<RoomSolve> solve;
  std::optional<Metrics> metrics;
  friend bool operator==(const RoomEntry&, const RoomEntry&) = default;
};

struct FileRef {
  std::string file;    // as given (relative to the scene file's folder, or absolute)
  std::string sha256;  // 64 lowercase hex digits of the file's bytes
  friend bool operator==(const FileRef&, const FileRef&) = default;
};

// The wall and slab thicknesses the solver used (a subset of building/building.h BuildOptions).
struct BuildRecord {
  double slab_thickness = 0.175;
  double exterior_wall_thickness = 0.25;
  double interior_wall_thickness = 0.12;
  friend bool operator==(const BuildRecord&, const BuildRecord&) = default;
};

struct SceneFile {
  FileRef layout;
  std::optional<FileRef> library;   // absent while no asset library took part (plans)
  BuildRecord build;
  std::vector<RoomEntry> rooms;     // in file order
  std::vector<SceneObject> objects; // in file order
  std::optional<Metrics> metrics;   // the building's
  friend bool operator==(const SceneFile&, const SceneFile&) = default;

  const SceneObject* FindObject(std::string_view id) const;
  const RoomEntry* FindRoom(std::string_view name) const;
};

// JSON of SCENE.md: numbers rounded to 4 decimals, yaw in degrees.
Json SceneToJson(const SceneFile& scene);
std::string SceneToText(const SceneFile& scene);  // pretty, 2-space indent, trailing newline
// Strict: unknown keys, wrong types, bad names and out-of-range values are errors naming `source`, the
// JSON path and the value.
Result<SceneFile> SceneFromJson(const Json& json, const std::string& source);
Result<SceneFile> ParseSceneText(std::string_view text, const std::string& source);
Result<SceneFile> ReadScene(const std::filesystem::path& path);
Status WriteScene(const SceneFile& scene, const std::filesystem::path& path);  // atomic

// One object / one edge alone (the planner table, tests, critics).
Json ObjectToJson(const SceneObject& object);
Json EdgeToJson(const SemanticEdge& edge);

}  // namespace villa::scene
