#include "solver/energy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "mesh/geometry2d.h"
#include "solver/free_space.h"
#include "solver/layer.h"
#include "solver/residuals.h"
#include "solver/state.h"
#include "layout/geometry.h"

namespace villa::solver {
namespace {

std::string Format(const char* format, const std::string& a, const std::string& b, double value) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format, a.c_str(), b.c_str(), value);
  return buffer;
}

// An object's pose as the cost functors read it.
struct Blocks {
  double p[4];
  double s[1];
};
Blocks BlocksOf(const ObjectPlacement& pl) {
  return {{pl.pose.x, pl.pose.y, pl.pose.z, pl.pose.yaw}, {pl.pose.scale}};
}

BodyShape ShapeOf(const ProblemObject& o) {
  return {0.0, 0.0, 0.5 * o.asset.size.x, 0.5 * o.asset.size.y, 0.0, o.asset.size.z};
}

// Volume of an object's box inside an upright prism (polygon x [z0, z1]).
double PrismOverlap(const OrientedBox& box, const Ring& polygon, double z0, double z1) {
  const double dz = std::min(box.z1, z1) - std::max(box.z0, z0);
  if (dz <= 0.0) return 0.0;
  return ClippedArea(polygon, box.Footprint()) * dz;
}

// The room as the shared clearance query sees it: the free floor as the region, every object's box but
// floor coverings (owner = its index) and the convex pieces of every building prism (owner = n + its index).
template <class Covering>
FreeSpace RoomFreeSpace(const Ring& free_floor, const std::vector<OrientedBox>& boxes,
                        const std::vector<std::pair<std::string, Prism>>& building, Covering covering) {
  const int n = static_cast<int>(boxes.size());
  std::vector<PlanObstacle> obstacles;
  for (int i = 0; i < n; ++i) {
    if (!covering(i)) obstacles.push_back({PlanShape::Polygon(boxes[i].Footprint()), boxes[i].z0, boxes[i].z1, i});
  }
  for (size_t p = 0; p < building.size(); ++p) {
    for (Ring& piece : ConvexPieces(building[p].second.polygon)) {
      obstacles.push_back({PlanShape::Polygon(std::move(piece)), building[p].second.z0, building[p].second.z1,
                           n + static_cast<int>(p)});
    }
  }
  return FreeSpace({free_floor}, std::move(obstacles));
}

}  // namespace

EnergyTerms StateEnergy(const RoomState& st) {
  const RoomProblem& problem = *st.problem;
  const int n = static_cast<int>(st.objects.size());
  EnergyTerms e;
  e.object_collision.assign(n, 0.0);
  e.object_support.assign(n, 0.0);
  e.object_semantic.assign(n, 0.0);
  std::vector<OrientedBox> boxes;
  for (int i = 0; i < n; ++i) boxes.push_back(st.WorldBox(i));

  // The building: walls (outside the free floor), keep-outs, and the thin prisms in front of openings.
  std::vector<std::pair<std::string, Prism>> building;
  for (const KeepOut& k : problem.keep_outs) {
    if (k.kind == KeepOutKind::kCirculation) continue;  // a preference of the placement, not a constraint
    building.push_back({std::string(KeepOutKindName(k.kind)) + " " + k.name,
                        {k.polygon, k.z_min, k.z_max, true, true, k.kind != KeepOutKind::kWalkway, k.kind != KeepOutKind::kWalkway}});
  }
  const Layer openings = RoomLayer(st, {}, {});
  for (const Prism& p : openings.prisms) {
    if (p.binds_floor && p.binds_hung) continue;  // keep-outs, counted above
    if (p.binds_floor) building.push_back({"wall opening", p});
  }
  // What overlaps what is asked of the shared clearance query (solver/free_space.h), the one the
  // reachability check asks too; the volumes are then measured on the boxes and prisms themselves.
  const FreeSpace space = RoomFreeSpace(problem.free_floor, boxes, building, [&](int i) { return st.IsFloorCovering(i); });

  for (int i = 0; i < n; ++i) {
    if (st.IsFloorCovering(i)) continue;
    for (int k : space.Overlapping(PlanShape::Polygon(boxes[i].Footprint()), boxes[i].z0, boxes[i].z1)) {
      const int j = space.obstacles()[k].owner;
      if (j <= i || j >= n || st.ParentChild(i, j)) continue;
      const double v = OverlapVolume(boxes[i], boxes[j]);
      if (v <= 1e-12) continue;
      e.collision += v;
      e.object_collision[i] += v;
      e.object_collision[j] += v;
      e.overlaps.push_back({st.objects[i].id, st.objects[j].id});
      e.findings.push_back(Format("collision %s x %s: %.6f m3", st.objects[i].id, st.objects[j].id, v));
    }
  }
  for (int i = 0; i < n; ++i) {
    const OrientedBox& b = boxes[i];
    const PlanShape footprint_shape = PlanShape::Polygon(b.Footprint());
    double v = 0.0;
    if (space.RegionClearance(footprint_shape, 0.0).clearance < 0.0) {
      const double footprint = 4.0 * b.hx * b.hy;
      const double outside = std::max(0.0, footprint - ClippedArea(problem.free_floor, b.Footprint()));
      v = outside > 1e-9 ? outside * (b.z1 - b.z0) : 0.0;
    }
    if (v > 0.0) {
      e.overlaps.push_back({st.objects[i].id, "walls"});
      e.findings.push_back(Format("collision %s x %s: %.6f m3", st.objects[i].id, "walls", v));
    }
    std::vector<int> prisms;
    for (int k : space.Overlapping(footprint_shape, b.z0, b.z1)) {
      if (space.obstacles()[k].owner >= n) prisms.push_back(space.obstacles()[k].owner - n);
    }
    std::sort(prisms.begin(), prisms.end());
    prisms.erase(std::unique(prisms.begin(), prisms.end()), prisms.end());
    for (int p : prisms) {
      const auto& [name, prism] = building[p];
      if (st.IsFloorCovering(i) && !prism.binds_coverings) continue;
      // Walkways move what stands on the floor (what stands on it goes with it).
      if (!prism.binds_protected && st.parent[i] >= 0) continue;
      const double w = PrismOverlap(b, prism.polygon, prism.z0, prism.z1);
      if (w <= 1e-12) continue;
      v += w;
      e.overlaps.push_back({st.objects[i].id, name});
      e.findings.push_back(Format("collision %s x %s: %.6f m3", st.objects[i].id, name, w));
    }
    e.collision += v;
    e.object_collision[i] += v;
  }

  for (int i = 0; i < n; ++i) {
    if (st.Hung(i)) continue;
    const double dz = std::abs(st.placements[i].pose.z - st.SupportHeight(i));
    const bool outside = !PointInRing(boxes[i].c, st.SupportRegion(i), 0);
    const double s = dz + (outside ? 1.0 : 0.0);
    if (s <= 0.0) continue;
    e.support += s;
    e.object_support[i] += s;
    e.findings.push_back(Format("support %s%s: %.4f", st.objects[i].id, outside ? " (centre off its support)" : "", s));
  }

  for (const SemanticEdge& edge : st.edges) {
    const int a = st.Find(edge.source), b = st.Find(edge.target);
    double v = 0.0;
    if (a >= 0 && b >= 0) {
      v = EdgeViolation(edge, st.objects[a], st.placements[a], st.objects[b], st.placements[b]);
      if (v > 1e-9) {
        e.object_semantic[a] += v;
        e.findings.push_back(Format("relation %s -> %s: %.4f", edge.source + " " + std::string(SemanticRelationName(edge.relation)),
                                    edge.target, v));
      }
    }
    e.edge_violation.push_back(v);
    e.semantic += v;
  }
  for (int i = 0; i < n; ++i) {
    for (const BodyShape& zone : ZoneShapes(st, i)) {
      Blocks po = BlocksOf(st.placements[i]);
      for (int j = 0; j < n; ++j) {
        if (j == i || st.IsFloorCovering(j) || ZoneExempt(st, i, j)) continue;
        Blocks pj = BlocksOf(st.placements[j]);
        InteractionZoneResidual intrusion{zone, ShapeOf(st.objects[j]), 1.0};
        double depth = 0.0;
        intrusion(po.p, po.s, pj.p, pj.s, &depth);
        if (depth <= 1e-9) continue;
        e.semantic += depth;
        e.object_semantic[j] += depth;
        e.findings.push_back(Format("zone of %s entered by %s: %.4f m", st.objects[i].id, st.objects[j].id, depth));
      }
    }
  }
  e.total = kWeightCollision * e.collision + kWeightSupport * e.support + kWeightSemantic * e.semantic;
  return e;
}

double EdgeViolation(const SemanticEdge& edge, const ProblemObject& source, const ObjectPlacement& at_source, const ProblemObject& target,
                     const ObjectPlacement& at_target) {
  Blocks pa = BlocksOf(at_source), pb = BlocksOf(at_target);
  bool pose_only = false;
  std::unique_ptr<ceres::CostFunction> cost(SemanticCost(edge, ShapeOf(source), ShapeOf(target), 1.0, &pose_only));
  std::vector<double*> blocks = pose_only ? std::vector<double*>{pa.p, pb.p} : std::vector<double*>{pa.p, pa.s, pb.p, pb.s};
  double v = 0.0;
  cost->Evaluate(blocks.data(), &v, nullptr);
  return std::abs(v);
}

EnergyTerms ArrangementEnergy(const RoomProblem& problem, const std::vector<ObjectPlacement>& placements) {
  RoomState state = RoomState::From(problem);
  state.placements = placements;
  state.placements.resize(problem.objects.size());
  return StateEnergy(state);
}

}  // namespace villa::solver
