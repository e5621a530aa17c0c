#include "solver/state.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "mesh/geometry2d.h"

namespace villa::solver {

Point Frame::ToLocal(Point world) const {
  const Point d = geo::Sub(world, origin);
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {c * d.x + s * d.y, -s * d.x + c * d.y};
}

Point Frame::ToWorld(Point local) const {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {origin.x + c * local.x - s * local.y, origin.y + s * local.x + c * local.y};
}

RoomState RoomState::From(const RoomProblem& problem) {
  RoomState state;
  state.problem = &problem;
  state.objects = problem.objects;
  state.placements.resize(problem.objects.size());
  state.edges = problem.edges;
  for (size_t i = 0; i < state.objects.size(); ++i) {
    ObjectPlacement& p = state.placements[i];
    p.surface = state.objects[i].surface;
    p.cavity = state.objects[i].cavity;
    p.wall = state.objects[i].wall;
  }
  state.Reindex();
  return state;
}

void RoomState::Reindex() {
  const int n = static_cast<int>(objects.size());
  parent.assign(n, -1);
  children.assign(n, {});
  for (int i = 0; i < n; ++i) {
    parent[i] = Find(objects[i].parent);
    if (parent[i] >= 0) children[parent[i]].push_back(i);
  }
}

int RoomState::Find(std::string_view id) const {
  for (size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

bool RoomState::IsFloorCovering(int i) const { return parent[i] < 0 && solver::IsFloorCovering(objects[i]); }

bool RoomState::ParentChild(int i, int j) const { return parent[i] == j || parent[j] == i; }

bool RoomState::Hung(int i) const {
  return objects[i].relation == Relation::kOnWall || objects[i].relation == Relation::kHanging;
}

bool RoomState::HangsOnRail(int i) const {
  const int p = parent[i];
  if (p < 0 || objects[i].relation != Relation::kInside || !HangsFromRail(objects[i].category)) return false;
  const std::vector<Cavity>& cavities = objects[p].asset.cavities;
  const int k = std::max(0, placements[i].cavity);
  return k < static_cast<int>(cavities.size()) && cavities[k].rail.has_value();
}

std::vector<int> RoomState::Descendants(int i) const {
  std::vector<int> out;
  std::vector<int> stack = children[i];
  while (!stack.empty()) {
    int k = stack.back();
    stack.pop_back();
    out.push_back(k);
    stack.insert(stack.end(), children[k].begin(), children[k].end());
  }
  return out;
}

OrientedBox RoomState::WorldBox(int i) const { return StandingBox(objects[i], placements[i].pose); }

Frame RoomState::FrameOf(int i) const {
  const Pose& p = placements[i].pose;
  return {{p.x, p.y}, p.z, p.yaw, p.scale};
}

double RoomState::SupportHeight(int i) const {
  const int q = parent[i];
  if (q < 0) return problem->floor_z;
  const Pose& pp = placements[q].pose;
  const AssetRecord& pa = objects[q].asset;
  if (objects[i].relation == Relation::kInside) {
    const Cavity& c = pa.cavities[std::max(0, placements[i].cavity)];
    // A hanging garment: its hook on the rail.
    if (HangsOnRail(i)) return pp.z + pp.scale * *c.rail - (objects[i].asset.size.z - kHookRise) * placements[i].pose.scale;
    return pp.z + pp.scale * c.min.z;
  }
  const int k = std::max(0, placements[i].surface);
  return pp.z + pp.scale * pa.support_surfaces[k].z + placements[i].lift;
}

Ring RoomState::LocalSupportPolygon(int i) const {
  const int q = parent[i];
  const double s = placements[q].pose.scale;
  const AssetRecord& pa = objects[q].asset;
  Ring local;
  if (objects[i].relation == Relation::kInside) {
    const Cavity& c = pa.cavities[std::max(0, placements[i].cavity)];
    local = {{c.min.x, c.min.y}, {c.max.x, c.min.y}, {c.max.x, c.max.y}, {c.min.x, c.max.y}};
  } else {
    local = pa.support_surfaces[std::max(0, placements[i].surface)].polygon;
  }
  for (Point& v : local) v = geo::Scale(v, s);
  return local;
}

Ring RoomState::SupportRegion(int i) const {
  if (parent[i] < 0) return problem->free_floor;
  const Frame f = FrameOf(parent[i]);
  Ring world;
  for (Point v : LocalSupportPolygon(i)) world.push_back(f.ToWorld(v));
  return world;
}

void RoomState::SetPose(int i, const Pose& pose) {
  const Frame before = FrameOf(i);
  placements[i].pose = pose;
  const Frame after = FrameOf(i);
  // A rescaled parent carries its children's offsets (surfaces and cavities scale with it); each child
  // then carries its own children at their own scale.
  const double ratio = after.scale / before.scale;
  for (int k : children[i]) {
    Pose d = placements[k].pose;
    const Point world = after.ToWorld(geo::Scale(before.ToLocal({d.x, d.y}), ratio));
    d.x = world.x;
    d.y = world.y;
    d.z = after.z + (d.z - before.z) * ratio;
    d.yaw = WrapAngle(d.yaw + after.yaw - before.yaw);
    SetPose(k, d);
  }
}

std::vector<std::string> RoomState::Remove(int i) {
  std::vector<int> gone = Descendants(i);
  gone.push_back(i);
  std::set<std::string> ids;
  for (int k : gone) ids.insert(objects[k].id);
  std::vector<std::string> removed;
  std::vector<ProblemObject> kept_objects;
  std::vector<ObjectPlacement> kept_placements;
  for (size_t k = 0; k < objects.size(); ++k) {
    if (ids.count(objects[k].id)) {
      removed.push_back(objects[k].id);
    } else {
      kept_objects.push_back(objects[k]);
      kept_placements.push_back(placements[k]);
    }
  }
  objects = std::move(kept_objects);
  placements = std::move(kept_placements);
  std::erase_if(edges, [&](const SemanticEdge& e) { return ids.count(e.source) || ids.count(e.target); });
  Reindex();
  return removed;
}

}  // namespace villa::solver
