#pragma once
// One layer of the continuous problem (internal to villa_solver): the bodies that move together in one
// frame and the fixed ones around them, the region they must stay in, and the cost terms between them.
// Layers: the floor (floor objects), then the walls and the ceiling (hung objects, floor objects fixed),
// then each support surface and each cavity in its parent's frame (the parent and its neighbours fixed).
// Ceres appears only in layer.cpp.
#include <limits>
#include <memory>
#include <vector>

#include "solver/body_shape.h"
#include "solver/free_space.h"
#include "solver/options.h"
#include "solver/state.h"

namespace ceres {
class CostFunction;
}

namespace villa::solver {

// How a body may move in its layer (a Ceres manifold on its {x, y, z, yaw} block).
enum class Motion {
  kFixed,      // an obstacle: not optimised
  kFree,       // x, y and yaw (z follows from the support)
  kAlongWall,  // slides along its wall: back at the gap, yaw from the wall (held exactly, not penalised)
  kOnWall,     // hung: slides along its wall and up or down
};

struct Body {
  int object = -1;             // index into RoomState::objects
  Motion motion = Motion::kFixed;
  double p[4] = {0, 0, 0, 0};  // x, y, z (bottom), yaw: layer frame
  double s[1] = {1.0};         // uniform scale
  double yaw_class = 0.0;      // rad: the 90-degree class, centre of the yaw window (kFree)
  int wall = -1;               // kAlongWall / kOnWall: index into RoomProblem::walls
  Point wall_dir{1.0, 0.0};    // unit direction of that wall
  bool active = true;          // false: not placed yet (ignored by every term)
  bool covering = false;       // a floor covering (rug): no pair terms
  bool scalable = false;       // its scale range is not just 1
  bool hangs = false;          // hangs from its cavity's rail: slides along it, turned across it (kAlongWall)
  double hx = 0.0, hy = 0.0, height = 0.0;  // asset half width, half depth, height (unscaled, m)
  // Top of the body with what stands on its surfaces (a TV on its stand), unscaled m: the box other
  // layers' terms see, so a stand whose TV would reach into a window zone keeps away from the window.
  double top = 0.0;
  bool ZFree() const { return motion == Motion::kOnWall; }
};

// A convex keep-out prism in the layer frame; which bodies it binds.
struct Prism {
  Ring polygon;
  double z0 = 0.0, z1 = 0.0;
  bool binds_floor = true;  // floor and ceiling bodies
  bool binds_hung = true;   // on_wall bodies
  bool binds_coverings = true;  // floor coverings (a rug may lie on a walkway)
  // Protected objects (essential or named, problem.h): a walkway the reachability feedback lays does not
  // push a bedroom's bed through its walls in a polish; the agent moves it out of the way where a free slot
  // is (Layer::walkways_bind_all), else the way goes round it or the zone is reported unreachable.
  bool binds_protected = true;
  // A preference, not a constraint (issue 27's circulation through a room): a soft term of the zones'
  // weight, so furniture keeps off the way through a room where it can.
  bool soft = false;
};

struct Layer {
  enum class Kind { kRoom, kSurface, kCavity };
  Kind kind = Kind::kRoom;
  int parent = -1;  // surface / cavity layers: the parent object
  int group = -1;   // the surface or cavity index
  Frame frame;      // the layer frame in the world (identity for the room)
  std::vector<Body> bodies;
  std::vector<int> body_of;  // object index -> body index, -1 when not in the layer

  Ring region;                 // free floor (room) or the scaled surface polygon (surface)
  std::vector<Point> reflex;   // reflex vertices of a non-convex region
  std::vector<Prism> prisms;   // keep-outs and wall openings (room)
  Box3 cavity;                 // scaled cavity box (cavity layer), parent frame
  // Walkways bind protected bodies too: true where the agent looks for a slot out of the way (FindSlot),
  // false in the polishes (a walkway must not push a bed through its wall).
  bool walkways_bind_all = false;
  double clear_height = std::numeric_limits<double>::infinity();  // room above a surface (m)

  int Movable() const;  // active bodies that are not fixed
};

// The room's yaw classes: every wall direction modulo 90 degrees (one family for a rectilinear room, two
// or more with angled walls), in [0, pi/2). SnapYaw gives the nearest yaw of any class.
std::vector<double> RoomYawClasses(const RoomProblem& problem);
double SnapYaw(double yaw, const std::vector<double>& classes);

// The room layer: `movable` objects optimised (their placements as start values), `fixed` as obstacles.
Layer RoomLayer(const RoomState& state, const std::vector<int>& movable, const std::vector<int>& fixed);
// A surface or cavity layer of `parent` holding `movable` children; placed neighbours (objects near the
// parent, the parent's other children) become fixed obstacles.
Layer ChildLayer(const RoomState& state, int parent, Layer::Kind kind, int group, const std::vector<int>& movable);
// Puts a body's pose, in the layer frame, into its world placement (descendants follow).
void WriteBack(const Layer& layer, int body, RoomState& state);
// The body's box shape (asset frame, unscaled).
BodyShape BodyBox(const Body& body);
// The interaction zone boxes of a V_int object (asset frame, unscaled; none for hung objects). Its zone,
// or when the problem gives none, the asset record's (no exemptions).
std::vector<BodyShape> ZoneShapes(const RoomState& state, int object);
// Whether `other` may enter `owner`'s zone (SCENE.md): named in the zone's `exempt`, or a descendant of
// the owner. The graph planner lists the objects meant to be inside (the coffee table, the desk chair).
bool ZoneExempt(const RoomState& state, int owner, int other);

// One cost term: a Ceres cost function and the parameter blocks it reads.
struct Term {
  Term();
  Term(Term&&) noexcept;
  Term& operator=(Term&&) noexcept;
  ~Term();
  std::unique_ptr<ceres::CostFunction> cost;
  std::vector<double*> blocks;
  std::vector<int> bodies;
  bool hard = true;  // collision, bounds, keep-out, support, containment (soft: relations, zones, scale)
};

// The terms of a layer among its active bodies. `only` >= 0: just those involving that body. `slack` >= 0:
// pairs whose bounding circles are more than `slack` m apart are left out.
std::vector<Term> MakeTerms(Layer& layer, const RoomState& state, const SolveOptions& options, int only,
                            double slack);

struct LayerCost {
  double hard = 0.0;         // sum of squared hard residuals
  double soft = 0.0;         // sum of squared soft residuals
  double soft_linear = 0.0;  // sum of the soft terms' residual norms (weighted m or rad: E_sem's units)
};
// `hard_limit`: stop as soon as the hard cost exceeds it (the caller only needs to know that it does).
LayerCost Evaluate(const std::vector<Term>& terms, double hard_limit = 1e300);

struct PolishStats {
  int solves = 0;
  int iterations = 0;
  double seconds = 0.0;
  bool sparse = false;
  LayerCost cost;  // at the end
};
// Ceres polish of the layer's movable bodies from their current values.
PolishStats Polish(Layer& layer, const RoomState& state, const SolveOptions& options);

}  // namespace villa::solver
