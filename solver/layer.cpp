#include "solver/layer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <set>

#include <ceres/ceres.h>

#include "mesh/geometry2d.h"
#include "solver/residuals.h"
#include "layout/geometry.h"

namespace villa::solver {
namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;

// x + B * delta for an orthonormal basis B of the directions a body may move in ({x, y, z, yaw} ambient):
// a wall-bound body slides exactly along its wall, a floor body keeps its height.
class AffineManifold final : public ceres::Manifold {
 public:
  explicit AffineManifold(std::vector<std::array<double, 4>> basis) : basis_(std::move(basis)) {}
  int AmbientSize() const override { return 4; }
  int TangentSize() const override { return static_cast<int>(basis_.size()); }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    for (int i = 0; i < 4; ++i) {
      x_plus_delta[i] = x[i];
      for (size_t k = 0; k < basis_.size(); ++k) x_plus_delta[i] += basis_[k][i] * delta[k];
    }
    return true;
  }
  bool PlusJacobian(const double* /*x*/, double* jacobian) const override {
    const size_t k_size = basis_.size();
    for (int i = 0; i < 4; ++i) {
      for (size_t k = 0; k < k_size; ++k) jacobian[i * k_size + k] = basis_[k][i];
    }
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    for (size_t k = 0; k < basis_.size(); ++k) {
      y_minus_x[k] = 0.0;
      for (int i = 0; i < 4; ++i) y_minus_x[k] += basis_[k][i] * (y[i] - x[i]);
    }
    return true;
  }
  bool MinusJacobian(const double* /*x*/, double* jacobian) const override {
    for (size_t k = 0; k < basis_.size(); ++k) {
      for (int i = 0; i < 4; ++i) jacobian[k * 4 + i] = basis_[k][i];
    }
    return true;
  }

 private:
  std::vector<std::array<double, 4>> basis_;
};

ceres::Manifold* ManifoldFor(const Body& b) {
  switch (b.motion) {
    case Motion::kAlongWall: return new AffineManifold({{b.wall_dir.x, b.wall_dir.y, 0.0, 0.0}});
    case Motion::kOnWall: return new AffineManifold({{b.wall_dir.x, b.wall_dir.y, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}});
    default: return new AffineManifold({{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0}});
  }
}

// Height of an object with the objects stacked on its surfaces, in its own unscaled units.
double StackTop(const RoomState& state, int i) {
  const ProblemObject& o = state.objects[i];
  double top = o.asset.size.z;
  for (int c : state.children[i]) {
    if (state.objects[c].relation != Relation::kOnTop || o.asset.support_surfaces.empty()) continue;
    const int k = std::clamp(state.placements[c].surface, 0, static_cast<int>(o.asset.support_surfaces.size()) - 1);
    const double child = StackTop(state, c) * state.objects[c].scale_max / state.placements[i].pose.scale;
    top = std::max(top, o.asset.support_surfaces[k].z + child);
  }
  return top;
}

Body MakeBody(const RoomState& state, int i) {
  Body b;
  b.object = i;
  const ProblemObject& o = state.objects[i];
  const ObjectPlacement& pl = state.placements[i];
  b.p[0] = pl.pose.x;
  b.p[1] = pl.pose.y;
  b.p[2] = pl.pose.z;
  b.p[3] = pl.pose.yaw;
  b.s[0] = pl.pose.scale;
  b.active = pl.placed;
  b.covering = state.IsFloorCovering(i);
  b.scalable = o.scale_max - o.scale_min > 1e-9;
  b.hx = 0.5 * o.asset.size.x;
  b.hy = 0.5 * o.asset.size.y;
  b.height = o.asset.size.z;
  b.top = StackTop(state, i);
  b.wall = pl.wall;
  if (b.wall >= 0 && b.wall < static_cast<int>(state.problem->walls.size())) {
    const WallEdge& w = state.problem->walls[b.wall];
    b.wall_dir = geo::Unit(geo::Sub(w.b, w.a));
  }
  return b;
}

void Index(Layer& layer, const RoomState& state) {
  layer.body_of.assign(state.objects.size(), -1);
  for (size_t k = 0; k < layer.bodies.size(); ++k) layer.body_of[layer.bodies[k].object] = static_cast<int>(k);
}

// Openings as thin prisms in front of the wall: floor bodies may not stand against them (exact heights),
// hung bodies keep 0.1 m from them all round (PRIORS.md wall decor).
void AddOpeningPrisms(const RoomProblem& problem, Layer& layer) {
  constexpr double kDepth = 0.15, kAround = 0.1;
  for (const WallEdge& w : problem.walls) {
    const Point d = geo::Unit(geo::Sub(w.b, w.a));
    const Point n = geo::Left(d);
    for (const WallOpening& o : w.openings) {
      auto rect = [&](double t0, double t1) {
        return Ring{geo::Add(w.a, geo::Scale(d, t0)), geo::Add(w.a, geo::Scale(d, t1)),
                    geo::Add(geo::Add(w.a, geo::Scale(d, t1)), geo::Scale(n, kDepth)),
                    geo::Add(geo::Add(w.a, geo::Scale(d, t0)), geo::Scale(n, kDepth))};
      };
      layer.prisms.push_back({rect(o.t0, o.t1), o.z0, o.z1, true, false});
      layer.prisms.push_back({rect(o.t0 - kAround, o.t1 + kAround), o.z0 - kAround, o.z1 + kAround, false, true});
    }
  }
}

}  // namespace

std::vector<double> RoomYawClasses(const RoomProblem& problem) {
  std::vector<double> bases;
  const Ring& f = problem.free_floor;
  for (size_t i = 0; i < f.size(); ++i) {
    const Point d = geo::Sub(f[(i + 1) % f.size()], f[i]);
    double a = std::fmod(std::atan2(d.y, d.x), kHalfPi);
    if (a < 0.0) a += kHalfPi;
    bool known = false;
    for (double b : bases) {
      double diff = std::abs(a - b);
      known |= std::min(diff, kHalfPi - diff) < 0.02;
    }
    if (!known) bases.push_back(a);
  }
  if (bases.empty()) bases.push_back(0.0);
  return bases;
}

double SnapYaw(double yaw, const std::vector<double>& bases) {
  double best = yaw, best_diff = 1e9;
  for (double b : bases) {
    double k = std::round((yaw - b) / kHalfPi);
    double snapped = b + k * kHalfPi;
    if (std::abs(yaw - snapped) < best_diff) {
      best_diff = std::abs(yaw - snapped);
      best = snapped;
    }
  }
  return best;
}

Term::Term() = default;
Term::Term(Term&&) noexcept = default;
Term& Term::operator=(Term&&) noexcept = default;
Term::~Term() = default;

int Layer::Movable() const {
  int n = 0;
  for (const Body& b : bodies) n += b.active && b.motion != Motion::kFixed;
  return n;
}

Layer RoomLayer(const RoomState& state, const std::vector<int>& movable, const std::vector<int>& fixed) {
  Layer layer;
  layer.kind = Layer::Kind::kRoom;
  const RoomProblem& problem = *state.problem;
  const std::vector<double> bases = RoomYawClasses(problem);
  for (int i : movable) {
    Body b = MakeBody(state, i);
    switch (state.objects[i].relation) {
      case Relation::kAgainstWall: b.motion = Motion::kAlongWall; break;
      case Relation::kOnWall: b.motion = Motion::kOnWall; break;
      default: b.motion = Motion::kFree; break;
    }
    b.yaw_class = SnapYaw(b.p[3], bases);
    layer.bodies.push_back(b);
  }
  for (int i : fixed) {
    Body b = MakeBody(state, i);
    b.motion = Motion::kFixed;
    layer.bodies.push_back(b);
  }
  Index(layer, state);
  layer.region = problem.free_floor;
  layer.reflex = ReflexVertices(problem.free_floor);
  for (const KeepOut& k : problem.keep_outs) {
    for (Ring& piece : ConvexPieces(k.polygon)) {
      const bool circulation = k.kind == KeepOutKind::kCirculation;
      const bool walked = k.kind == KeepOutKind::kWalkway || circulation;
      layer.prisms.push_back({std::move(piece), k.z_min, k.z_max, true, true, !walked, k.kind != KeepOutKind::kWalkway, circulation});
    }
  }
  AddOpeningPrisms(problem, layer);
  return layer;
}

Layer ChildLayer(const RoomState& state, int parent, Layer::Kind kind, int group, const std::vector<int>& movable) {
  Layer layer;
  layer.kind = kind;
  layer.parent = parent;
  layer.group = group;
  layer.frame = state.FrameOf(parent);
  const double sp = layer.frame.scale;
  const AssetRecord& pa = state.objects[parent].asset;
  double z_rest = 0.0;
  if (kind == Layer::Kind::kSurface) {
    const SupportSurface& surface = pa.support_surfaces[group];
    for (Point v : surface.polygon) layer.region.push_back(geo::Scale(v, sp));
    layer.reflex = ReflexVertices(layer.region);
    layer.clear_height = surface.clear_height > 0.0 ? surface.clear_height * sp : layer.clear_height;
    z_rest = surface.z * sp;
  } else {
    const Cavity& c = pa.cavities[group];
    layer.cavity.min = c.min * sp;
    layer.cavity.max = c.max * sp;
    z_rest = c.min.z * sp;
  }
  auto local_body = [&](int i, Motion motion) {
    Body b = MakeBody(state, i);
    const Point q = layer.frame.ToLocal({b.p[0], b.p[1]});
    b.p[0] = q.x;
    b.p[1] = q.y;
    b.p[2] = motion == Motion::kFixed ? b.p[2] - layer.frame.z : z_rest;
    b.p[3] = WrapAngle(b.p[3] - layer.frame.yaw);
    b.motion = motion;
    b.yaw_class = std::round(b.p[3] / kHalfPi) * kHalfPi;
    // A garment on a hanger: its hook on the rail (which runs along x over the cavity's middle), turned
    // across it, sliding along it.
    // (A movable body's placement names this layer's cavity: the solver sets it before making the layer.)
    if (motion != Motion::kFixed && kind == Layer::Kind::kCavity && state.HangsOnRail(i)) {
      b.hangs = true;
      b.motion = Motion::kAlongWall;
      b.wall_dir = {1.0, 0.0};
      b.p[1] = 0.5 * (layer.cavity.min.y + layer.cavity.max.y);
      b.p[2] = *pa.cavities[group].rail * sp - (b.height - kHookRise) * b.s[0];
      b.p[3] = b.yaw_class = b.p[3] < 0.0 ? -kHalfPi : kHalfPi;
    }
    return b;
  };
  std::set<int> moving(movable.begin(), movable.end());
  std::set<int> skip = moving;  // movable bodies, their descendants, the parent and its ancestors
  for (int i : movable) {
    for (int d : state.Descendants(i)) skip.insert(d);
  }
  for (int a = parent; a >= 0; a = state.parent[a]) skip.insert(a);
  for (int i : movable) layer.bodies.push_back(local_body(i, Motion::kFree));
  const OrientedBox parent_box = state.WorldBox(parent);
  for (size_t i = 0; i < state.objects.size(); ++i) {
    if (skip.count(static_cast<int>(i)) || !state.placements[i].placed) continue;
    if (PlanDepth(parent_box, state.WorldBox(static_cast<int>(i))) < -0.3) continue;
    layer.bodies.push_back(local_body(static_cast<int>(i), Motion::kFixed));
  }
  Index(layer, state);
  // The room's keep-outs in the parent's frame: a TV on its stand stays out of the window zone.
  for (const KeepOut& k : state.problem->keep_outs) {
    // A walkway (or a circulation corridor) moves what stands on the floor; what stands on it goes with it.
    if (k.kind == KeepOutKind::kWalkway || k.kind == KeepOutKind::kCirculation) continue;
    Ring local;
    for (Point v : k.polygon) local.push_back(layer.frame.ToLocal(v));
    for (Ring& piece : ConvexPieces(local)) {
      layer.prisms.push_back({std::move(piece), k.z_min - layer.frame.z, k.z_max - layer.frame.z, true, true, true});
    }
  }
  return layer;
}

void WriteBack(const Layer& layer, int body, RoomState& state) {
  const Body& b = layer.bodies[body];
  Pose pose;
  if (layer.kind == Layer::Kind::kRoom) {
    pose = {b.p[0], b.p[1], b.p[2], WrapAngle(b.p[3]), b.s[0]};
  } else {
    const Point w = layer.frame.ToWorld({b.p[0], b.p[1]});
    pose = {w.x, w.y, layer.frame.z + b.p[2], WrapAngle(layer.frame.yaw + b.p[3]), b.s[0]};
  }
  ObjectPlacement& pl = state.placements[b.object];
  state.SetPose(b.object, pose);
  pl.placed = true;
  if (b.motion == Motion::kAlongWall || b.motion == Motion::kOnWall) pl.wall = b.wall;
  if (layer.kind == Layer::Kind::kSurface) pl.surface = layer.group;
  if (layer.kind == Layer::Kind::kCavity) pl.cavity = layer.group;
}

bool ZoneExempt(const RoomState& state, int owner, int other) {
  const ProblemObject& o = state.objects[owner];
  // The exempt object and what stands on it or in it (the remote on the coffee table).
  for (int a = other; a >= 0; a = state.parent[a]) {
    if (a == owner) return true;
    const std::string& id = state.objects[a].id;
    if (o.zone && std::find(o.zone->exempt.begin(), o.zone->exempt.end(), id) != o.zone->exempt.end()) return true;
  }
  return false;
}

// Bounding-circle radius of a body's box (m).
double Radius(const Body& b) { return std::sqrt(b.hx * b.hx + b.hy * b.hy) * b.s[0]; }

// Whether two bodies may interact at all (both placed, one movable, neither a rug, not parent and child).
bool PairEligible(const Layer& layer, const RoomState& state, int a, int b) {
  const Body& A = layer.bodies[a];
  const Body& B = layer.bodies[b];
  const bool any_moves = A.motion != Motion::kFixed || B.motion != Motion::kFixed;
  return A.active && B.active && any_moves && !A.covering && !B.covering && !state.ParentChild(A.object, B.object);
}

// A pair left out at the start of a solve (circles more than `slack` apart) whose circles now come
// within the pair clearance.
bool MissedPair(const Layer& layer, const RoomState& state, const std::vector<Point>& start_xy, double slack,
                const SolveOptions& o) {
  const double margin = layer.kind == Layer::Kind::kRoom ? o.object_gap : o.child_gap;
  for (size_t a = 0; a < layer.bodies.size(); ++a) {
    for (size_t b = a + 1; b < layer.bodies.size(); ++b) {
      if (!PairEligible(layer, state, static_cast<int>(a), static_cast<int>(b))) continue;
      const Body& A = layer.bodies[a];
      const Body& B = layer.bodies[b];
      const double reach = Radius(A) + Radius(B);
      if (geo::Dist(start_xy[a], start_xy[b]) <= reach + slack) continue;
      if (std::hypot(A.p[0] - B.p[0], A.p[1] - B.p[1]) < reach + margin) return true;
    }
  }
  return false;
}

BodyShape BodyBox(const Body& body) { return {0.0, 0.0, body.hx, body.hy, 0.0, body.top}; }

std::vector<BodyShape> ZoneShapes(const RoomState& state, int object) {
  const ProblemObject& o = state.objects[object];
  std::optional<InteractionZone> zone = o.zone;
  if (!zone && o.asset.interaction_zone && o.asset.Has(kInteractor)) {
    zone = InteractionZone{o.asset.interaction_zone->side, o.asset.interaction_zone->depth, {}};
  }
  if (state.Hung(object)) return {};
  const double hx = 0.5 * o.asset.size.x, hy = 0.5 * o.asset.size.y, h = o.asset.size.z;
  std::vector<BodyShape> out;
  if (zone && zone->depth > 0.0) {
    const double d = zone->depth;
    const BodyShape front{0.0, -(hy + 0.5 * d), hx, 0.5 * d, 0.0, h};
    const BodyShape back{0.0, hy + 0.5 * d, hx, 0.5 * d, 0.0, h};
    const BodyShape left{hx + 0.5 * d, 0.0, 0.5 * d, hy, 0.0, h};
    const BodyShape right{-(hx + 0.5 * d), 0.0, 0.5 * d, hy, 0.0, h};
    if (zone->side == "front") out = {front};
    else if (zone->side == "back") out = {back};
    else if (zone->side == "left") out = {left};
    else if (zone->side == "right") out = {right};
    else out = {left, right};
  }
  // Room to pull a dining chair out, behind it (its back is +y).
  if (o.pull_out > 0.0) out.push_back({0.0, hy + 0.5 * o.pull_out, hx, 0.5 * o.pull_out, 0.0, h});
  return out;
}

std::vector<Term> MakeTerms(Layer& layer, const RoomState& state, const SolveOptions& o, int only, double slack) {
  std::vector<Term> terms;
  enum Blocks { kPoseAndScale, kPoseOnly, kScaleOnly };
  auto add = [&](ceres::CostFunction* cost, std::vector<int> bodies, bool hard, Blocks blocks = kPoseAndScale) {
    Term t;
    t.cost.reset(cost);
    for (int b : bodies) {
      if (blocks != kScaleOnly) t.blocks.push_back(layer.bodies[b].p);
      if (blocks != kPoseOnly) t.blocks.push_back(layer.bodies[b].s);
    }
    t.bodies = std::move(bodies);
    t.hard = hard;
    terms.push_back(std::move(t));
  };
  const int n = static_cast<int>(layer.bodies.size());
  auto movable = [&](int b) { return layer.bodies[b].active && layer.bodies[b].motion != Motion::kFixed; };
  auto wanted = [&](int a, int b) { return only < 0 || a == only || b == only; };
  const bool room = layer.kind == Layer::Kind::kRoom;
  const double pair_margin = room ? o.object_gap : o.child_gap;

  for (int b = 0; b < n; ++b) {
    const Body& body = layer.bodies[b];
    if (!movable(b) || !wanted(b, b)) continue;
    const BodyShape shape = BodyBox(body);
    if (body.scalable && o.optimise_scale) add(ScalePriorResidual::Create(0.5), {b}, false, kScaleOnly);
    if (body.motion == Motion::kFree) add(YawPriorResidual::Create(body.yaw_class, 0.2), {b}, false, kPoseOnly);
    if (layer.kind == Layer::Kind::kCavity) {
      const Box3& c = layer.cavity;
      // A hanging garment's hook reaches over the rail, above the box.
      const double top = body.hangs ? c.max.z + 0.1 : c.max.z;
      add(ContainmentResidual::Create(shape, c.min.x, c.min.y, c.max.x, c.max.y, top, o.child_gap,
                                      o.weight_containment),
          {b}, true);
      continue;
    }
    const double margin = room ? o.bounds_margin : o.child_gap;
    add(FootprintInPolygonResidual::Create(shape, layer.region, margin, o.weight_bounds), {b}, true);
    if (!layer.reflex.empty()) add(ReflexVertexResidual::Create(shape, layer.reflex, margin, o.weight_bounds), {b}, true);
    if (room && body.wall >= 0 && (body.motion == Motion::kAlongWall || body.motion == Motion::kOnWall)) {
      const WallEdge& w = state.problem->walls[body.wall];
      add(WallSpanResidual::Create(shape, w.a, body.wall_dir, geo::Dist(w.a, w.b), o.bounds_margin, o.weight_bounds), {b}, true);
    }
    for (const Prism& prism : layer.prisms) {
      if (!(body.ZFree() ? prism.binds_hung : prism.binds_floor)) continue;
      if (body.covering && !prism.binds_coverings) continue;
      if (!prism.binds_protected && !layer.walkways_bind_all && IsProtected(state.objects[body.object].priority)) continue;
      if (prism.soft && !o.functional_groups) continue;  // circulation: issue 27's, with the groups
      if (slack >= 0.0 && !PointInRing({body.p[0], body.p[1]}, prism.polygon, 0) &&
          DistanceToBoundary({body.p[0], body.p[1]}, prism.polygon) > Radius(body) + slack)
        continue;
      add(KeepOutResidual::Create(shape, prism.polygon, prism.z0, prism.z1, body.ZFree(), prism.soft ? 0.0 : o.object_gap,
                                  prism.soft ? o.weight_zone : o.weight_keep_out),
          {b}, !prism.soft);
    }
  }

  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      if (!PairEligible(layer, state, a, b) || !wanted(a, b)) continue;
      const Body& A = layer.bodies[a];
      const Body& B = layer.bodies[b];
      if (slack >= 0.0 && std::hypot(A.p[0] - B.p[0], A.p[1] - B.p[1]) > Radius(A) + Radius(B) + slack) continue;
      add(PenetrationResidual::Create(BodyBox(A), BodyBox(B), A.ZFree() || B.ZFree(), pair_margin, o.weight_collision),
          {a, b}, true);
    }
  }

  if (room) {
    for (int a = 0; a < n; ++a) {
      const Body& owner = layer.bodies[a];
      if (!owner.active) continue;
      const std::vector<BodyShape> zones = ZoneShapes(state, owner.object);
      if (zones.empty()) continue;
      for (const BodyShape& zone : zones) {
        if (movable(a) && wanted(a, a)) {
          add(FootprintInPolygonResidual::Create(zone, layer.region, 0.0, o.weight_zone), {a}, false);
        }
        for (int b = 0; b < n; ++b) {
          const Body& other = layer.bodies[b];
          if (b == a || !other.active || other.covering || !(movable(a) || movable(b)) || !wanted(a, b)) continue;
          if (ZoneExempt(state, owner.object, other.object)) continue;
          if (slack >= 0.0 && std::hypot(owner.p[0] - other.p[0], owner.p[1] - other.p[1]) >
                                  Radius(owner) + 2.0 * zone.hx + 2.0 * zone.hy + Radius(other) + slack)
            continue;
          add(InteractionZoneResidual::Create(zone, BodyBox(other), o.weight_zone), {a, b}, false);
        }
      }
    }
  }

  for (const SemanticEdge& e : state.edges) {
    const int si = state.Find(e.source), ti = state.Find(e.target);
    if (si < 0 || ti < 0) continue;
    const int a = layer.body_of[si], b = layer.body_of[ti];
    if (a < 0 || b < 0 || !layer.bodies[a].active || !layer.bodies[b].active) continue;
    if (!(movable(a) || movable(b)) || !wanted(a, b)) continue;
    bool pose_only = false;
    ceres::CostFunction* cost =
        SemanticCost(e, BodyBox(layer.bodies[a]), BodyBox(layer.bodies[b]), o.weight_semantic, &pose_only);
    add(cost, {a, b}, false, pose_only ? kPoseOnly : kPoseAndScale);
  }
  return terms;
}

LayerCost Evaluate(const std::vector<Term>& terms, double hard_limit) {
  LayerCost cost;
  double residuals[64];
  for (const Term& t : terms) {
    if (cost.hard > hard_limit) break;
    const int m = t.cost->num_residuals();
    if (!t.cost->Evaluate(t.blocks.data(), residuals, nullptr)) continue;
    double sum = 0.0;
    for (int k = 0; k < m && k < 64; ++k) sum += residuals[k] * residuals[k];
    (t.hard ? cost.hard : cost.soft) += sum;
    if (!t.hard) cost.soft_linear += std::sqrt(sum);
  }
  return cost;
}

PolishStats Polish(Layer& layer, const RoomState& state, const SolveOptions& o) {
  PolishStats stats;
  const auto start = std::chrono::steady_clock::now();
  const int movable = layer.Movable();
  if (movable == 0) return stats;
  stats.sparse = o.linear_solver == LinearSolverChoice::kSparseNormalCholesky ||
                 (o.linear_solver == LinearSolverChoice::kAuto && movable >= o.sparse_from_objects);
  // The yaw window must hold the start (a candidate facing an angled target may lie off the classes).
  for (Body& b : layer.bodies) {
    if (b.motion == Motion::kFree && std::abs(b.p[3] - b.yaw_class) > o.max_yaw_offset) b.yaw_class = b.p[3];
  }
  double slack = o.pair_slack;
  std::vector<Point> start_xy;
  for (const Body& b : layer.bodies) start_xy.push_back({b.p[0], b.p[1]});
  // The start, to fall back on: a relation may pull a body through an obstacle into a pocket where the
  // penetration's gradient points where the body cannot move (a painting slid behind a wardrobe).
  std::vector<std::array<double, 5>> start_params;
  for (const Body& b : layer.bodies) start_params.push_back({b.p[0], b.p[1], b.p[2], b.p[3], b.s[0]});
  const LayerCost start_cost = Evaluate(MakeTerms(layer, state, o, -1, -1.0));
  for (int round = 0; round < 2; ++round) {
    std::vector<Term> terms = MakeTerms(layer, state, o, -1, slack);
    ceres::Problem::Options po;
    po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    po.manifold_ownership = ceres::TAKE_OWNERSHIP;
    ceres::Problem problem(po);
    for (Body& b : layer.bodies) {
      if (!b.active || b.motion == Motion::kFixed) continue;
      problem.AddParameterBlock(b.p, 4, ManifoldFor(b));
      problem.AddParameterBlock(b.s, 1);
      if (b.motion == Motion::kFree) {
        problem.SetParameterLowerBound(b.p, 3, b.yaw_class - o.max_yaw_offset);
        problem.SetParameterUpperBound(b.p, 3, b.yaw_class + o.max_yaw_offset);
      }
      const ProblemObject& obj = state.objects[b.object];
      if (b.scalable && o.optimise_scale && b.motion != Motion::kAlongWall && b.motion != Motion::kOnWall &&
          !state.Hung(b.object)) {
        problem.SetParameterLowerBound(b.s, 0, obj.scale_min);
        problem.SetParameterUpperBound(b.s, 0, obj.scale_max);
      } else {
        problem.SetParameterBlockConstant(b.s);
      }
    }
    for (Term& t : terms) problem.AddResidualBlock(t.cost.get(), nullptr, t.blocks);
    for (Body& b : layer.bodies) {
      if (b.motion != Motion::kFixed || !problem.HasParameterBlock(b.p)) continue;
      problem.SetParameterBlockConstant(b.p);
      problem.SetParameterBlockConstant(b.s);
    }
    ceres::Solver::Options so;
    so.linear_solver_type = stats.sparse ? ceres::SPARSE_NORMAL_CHOLESKY : ceres::DENSE_QR;
    so.max_num_iterations = o.ceres_max_iterations;
    so.num_threads = 1;
    so.logging_type = ceres::SILENT;
    so.minimizer_progress_to_stdout = false;
    so.function_tolerance = 1e-7;
    so.gradient_tolerance = 1e-10;
    so.parameter_tolerance = 1e-8;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    ++stats.solves;
    stats.iterations += static_cast<int>(summary.iterations.size());
    if (slack < 0.0 || !MissedPair(layer, state, start_xy, slack, o)) break;
    slack = -1.0;  // a pair left out at the start met during the solve: solve again with every pair
  }
  stats.cost = Evaluate(MakeTerms(layer, state, o, -1, -1.0));
  // Tolerated: hard terms eaten into their margins by about a centimetre (a compromise with a relation);
  // more means a body was pushed into something: keep the start.
  const double tolerated = std::pow(o.weight_collision * 0.01, 2);
  if (stats.cost.hard > start_cost.hard + tolerated) {
    for (size_t k = 0; k < layer.bodies.size(); ++k) {
      Body& b = layer.bodies[k];
      std::copy(start_params[k].begin(), start_params[k].begin() + 4, b.p);
      b.s[0] = start_params[k][4];
    }
    stats.cost = start_cost;
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace villa::solver
