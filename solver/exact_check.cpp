#include "solver/exact_check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include "mesh/geometry2d.h"
#include "solver/rng.h"
#include "solver/state.h"
#include "layout/geometry.h"

namespace villa::solver {
namespace {

using Model = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<Model> BuildModel(const TriangleMesh& mesh, double scale) {
  auto model = std::make_shared<Model>();
  std::vector<fcl::Vector3d> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) points.emplace_back(v.x * scale, v.y * scale, v.z * scale);
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
  model->addSubModel(points, triangles);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

// Area-weighted points on a mesh's surface (asset frame, scaled), from a fixed seed so the same mesh
// always gives the same points (SceneEval samples the surface uniformly, as here).
std::vector<Vec3> SurfaceSamples(const TriangleMesh& mesh, double scale, int count) {
  std::vector<Vec3> out;
  std::vector<double> cumulative;
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    total += 0.5 * Norm(Cross(b - a, c - a));
    cumulative.push_back(total);
  }
  Rng rng(0x0B5A11u + mesh.triangles.size());
  for (int k = 0; k < count && total > 0.0; ++k) {
    const double pick = rng.Unit() * total;
    const size_t i = std::min(cumulative.size() - 1,
                              static_cast<size_t>(std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()));
    const auto& t = mesh.triangles[i];
    double u = rng.Unit(), v = rng.Unit();
    if (u + v > 1.0) {
      u = 1.0 - u;
      v = 1.0 - v;
    }
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    out.push_back((a + (b - a) * u + (c - a) * v) * scale);
  }
  return out;
}

fcl::Transform3d TransformOf(const Pose& pose) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = fcl::AngleAxisd(pose.yaw, fcl::Vector3d::UnitZ()).toRotationMatrix();
  tf.translation() = fcl::Vector3d(pose.x, pose.y, pose.z);
  return tf;
}

bool AabbOverlap(const fcl::AABBd& a, const fcl::AABBd& b, double slack = 0.0) {
  for (int k = 0; k < 3; ++k) {
    if (a.min_[k] > b.max_[k] + slack || b.min_[k] > a.max_[k] + slack) return false;
  }
  return true;
}

bool InsideWithTolerance(Point p, const Ring& ring, double tolerance) {
  return PointInRing(p, ring, 0) || DistanceToBoundary(p, ring) <= tolerance;
}

}  // namespace

bool ExactCheckOptions::IsValid(std::string* message) const {
  auto fail = [&](const std::string& m) {
    if (message) *message = m;
    return false;
  };
  if (!(tau >= 0.0 && tau <= 0.1)) return fail("tau must be in [0, 0.1] m");
  if (!(nudge >= 0.0 && nudge <= 0.05)) return fail("nudge must be in [0, 0.05] m");
  if (!(in_bound_share > 0.0 && in_bound_share <= 1.0)) return fail("in_bound_share must be in (0, 1]");
  if (!(containment_tolerance >= 0.0 && containment_tolerance <= 0.05)) return fail("containment_tolerance must be in [0, 0.05] m");
  if (obr_samples < 16 || obr_samples > 100000) return fail("obr_samples must be in [16, 100000]");
  if (!(clearance_probe >= 0.0 && clearance_probe <= 1.0)) return fail("clearance_probe must be in [0, 1] m");
  return true;
}

struct ExactChecker::Impl {
  // One asset mesh at one scale: its FCL model (built on first use: most objects of a solved room never
  // come near another, and fitting OBBs to a 20,000-triangle mesh takes about 0.1 s), OBR samples, bounds.
  struct MeshEntry {
    TriangleMesh merged;  // asset frame, unscaled
    double scale = 1.0;
    std::shared_ptr<Model> model;
    std::vector<Vec3> samples;
    Box3 bounds;  // scaled
    const std::shared_ptr<Model>& Model_() {
      if (!model) model = BuildModel(merged, scale);
      return model;
    }
  };
  // A pair decision is kept while neither pose changes (the agent moves one object at a time).
  struct PairMemo {
    bool valid = false;
    Pose a, b;
    bool colliding = false;
  };
  const RoomProblem* problem;
  ExactCheckOptions options;
  std::vector<std::pair<std::string, std::shared_ptr<Model>>> building;
  std::vector<fcl::AABBd> building_boxes;
  std::map<std::pair<const AssetMesh*, double>, MeshEntry> meshes;
  std::map<std::pair<std::string, std::string>, PairMemo> pair_memo;

  MeshEntry& Entry(const ProblemObject& o, double scale) {
    auto key = std::make_pair(o.mesh.get(), scale);
    auto it = meshes.find(key);
    if (it != meshes.end()) return it->second;
    MeshEntry e;
    e.merged = o.mesh->Merged();
    e.scale = scale;
    e.samples = SurfaceSamples(e.merged, scale, options.obr_samples);
    const Box3 b = e.merged.Bounds();
    e.bounds.min = b.min * scale;
    e.bounds.max = b.max * scale;
    return meshes.emplace(key, std::move(e)).first->second;
  }

  // Whether two placed objects collide in SceneEval's sense: an FCL collision that survives moving
  // `moved` by the nudge away from the mean contact point.
  bool Collide(fcl::CollisionObjectd& fixed, fcl::CollisionObjectd& moved) const {
    fcl::CollisionRequestd request(16, true);
    fcl::CollisionResultd result;
    fcl::collide(&fixed, &moved, request, result);
    if (!result.isCollision()) return false;
    if (options.nudge <= 0.0) return true;
    fcl::Vector3d mean = fcl::Vector3d::Zero();
    const size_t n = result.numContacts();
    for (size_t k = 0; k < n; ++k) mean += result.getContact(k).pos;
    if (n > 0) mean /= static_cast<double>(n);
    const fcl::AABBd& box = moved.getAABB();
    fcl::Vector3d away = 0.5 * (box.min_ + box.max_) - mean;
    away = away.norm() > 1e-9 ? away.normalized() : fcl::Vector3d::UnitZ();
    const fcl::Transform3d original = moved.getTransform();
    fcl::Transform3d shifted = original;
    shifted.translation() += options.nudge * away;
    moved.setTransform(shifted);
    moved.computeAABB();
    fcl::CollisionRequestd boolean_request;
    fcl::CollisionResultd again;
    fcl::collide(&fixed, &moved, boolean_request, again);
    moved.setTransform(original);
    moved.computeAABB();
    return again.isCollision();
  }

  // Whether a child enters its parent (issue 28: a book may touch its shelf, not stand into the shelf
  // above): an FCL collision that survives lifting the child `dz` m off its support (a hanger's hook rests
  // on its rail the same way).
  bool Enters(fcl::CollisionObjectd& parent, fcl::CollisionObjectd& child, double dz) const {
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    fcl::collide(&parent, &child, request, result);
    if (!result.isCollision()) return false;
    const fcl::Transform3d original = child.getTransform();
    fcl::Transform3d shifted = original;
    shifted.translation().z() += dz;
    child.setTransform(shifted);
    child.computeAABB();
    fcl::CollisionResultd again;
    fcl::collide(&parent, &child, request, again);
    child.setTransform(original);
    child.computeAABB();
    return again.isCollision();
  }
};

namespace {

bool SamePose(const Pose& a, const Pose& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z && a.yaw == b.yaw && a.scale == b.scale;
}

// World AABB of a box (local bounds) turned by yaw and moved to the pose.
fcl::AABBd WorldAabb(const Box3& local, const Pose& pose) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  fcl::AABBd box;
  bool first = true;
  for (int k = 0; k < 4; ++k) {
    const double x = k & 1 ? local.max.x : local.min.x, y = k & 2 ? local.max.y : local.min.y;
    const fcl::Vector3d p(pose.x + c * x - s * y, pose.y + s * x + c * y, pose.z + local.min.z);
    const fcl::Vector3d q(p.x(), p.y(), pose.z + local.max.z);
    if (first) {
      box = fcl::AABBd(p, q);
      first = false;
    } else {
      box += p;
      box += q;
    }
  }
  return box;
}

}  // namespace

ExactChecker::ExactChecker(const RoomProblem& problem, const ExactCheckOptions& options) : impl_(new Impl) {
  impl_->problem = &problem;
  impl_->options = options;
  for (const BuildingPart& part : problem.building) {
    if (part.mesh.triangles.empty()) continue;
    impl_->building.push_back({part.name, BuildModel(part.mesh, 1.0)});
    fcl::CollisionObjectd object(impl_->building.back().second, fcl::Transform3d::Identity());
    object.computeAABB();
    impl_->building_boxes.push_back(object.getAABB());
  }
}

ExactChecker::~ExactChecker() = default;

ExactMetrics ExactChecker::Check(const RoomState& st, bool measure_clearance) {
  const auto start = std::chrono::steady_clock::now();
  Impl& im = *impl_;
  const ExactCheckOptions& opt = im.options;
  const RoomProblem& problem = *st.problem;
  const int n = static_cast<int>(st.objects.size());
  ExactMetrics m;
  m.objects = n;
  m.per_object.resize(n);

  std::vector<Impl::MeshEntry*> entries;
  std::vector<fcl::AABBd> boxes;
  for (int i = 0; i < n; ++i) {
    const Pose& pose = st.placements[i].pose;
    entries.push_back(&im.Entry(st.objects[i], pose.scale));
    boxes.push_back(WorldAabb(entries[i]->bounds, pose));
    m.per_object[i].id = st.objects[i].id;
  }
  // FCL objects only for the objects that need an exact test.
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects(n);
  auto object = [&](int i) -> fcl::CollisionObjectd& {
    if (!objects[i]) {
      objects[i] = std::make_unique<fcl::CollisionObjectd>(entries[i]->Model_(), TransformOf(st.placements[i].pose));
      objects[i]->computeAABB();
    }
    return *objects[i];
  };
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> parts;
  for (const auto& [name, model] : im.building) {
    parts.push_back(std::make_unique<fcl::CollisionObjectd>(model, fcl::Transform3d::Identity()));
    parts.back()->computeAABB();
  }
  // A pair's decision, from the memo while both poses are unchanged.
  auto decide = [&](const std::string& a_id, const Pose& a_pose, const std::string& b_id, const Pose& b_pose,
                    const std::function<bool()>& test) {
    Impl::PairMemo& memo = im.pair_memo[{a_id, b_id}];
    if (!(memo.valid && SamePose(memo.a, a_pose) && SamePose(memo.b, b_pose))) {
      memo.valid = true;
      memo.a = a_pose;
      memo.b = b_pose;
      memo.colliding = test();
    }
    return memo.colliding;
  };

  // CR.
  for (int i = 0; i < n; ++i) {
    const Pose& pi = st.placements[i].pose;
    for (int j = i + 1; j < n; ++j) {
      if (st.IsFloorCovering(i) || st.IsFloorCovering(j)) continue;
      if (st.ParentChild(i, j)) {
        if (!AabbOverlap(boxes[i], boxes[j])) continue;
        const int p = st.parent[j] == i ? i : j, c = p == i ? j : i;
        const bool hit = decide(st.objects[p].id, st.placements[p].pose, st.objects[c].id, st.placements[c].pose,
                                [&] { return im.Enters(object(p), object(c), opt.nudge); });
        if (hit) {
          m.per_object[i].colliding = m.per_object[j].colliding = true;
          m.pairs.push_back({st.objects[i].id, st.objects[j].id, false});
        }
        continue;
      }
      if (!AabbOverlap(boxes[i], boxes[j], opt.clearance_probe)) continue;
      if (!AabbOverlap(boxes[i], boxes[j])) {
        if (!measure_clearance) continue;
        // Close but apart boxes: how close do the meshes come?
        fcl::DistanceRequestd request;
        fcl::DistanceResultd result;
        fcl::distance(&object(i), &object(j), request, result);
        if (result.min_distance >= 0.0 && (m.min_clearance < 0.0 || result.min_distance < m.min_clearance)) {
          m.min_clearance = result.min_distance;
        }
        continue;
      }
      const bool hit = decide(st.objects[i].id, pi, st.objects[j].id, st.placements[j].pose,
                              [&] { return im.Collide(object(i), object(j)); });
      if (hit) {
        m.per_object[i].colliding = m.per_object[j].colliding = true;
        m.pairs.push_back({st.objects[i].id, st.objects[j].id, false});
      }
    }
    for (size_t k = 0; k < parts.size(); ++k) {
      if (!AabbOverlap(boxes[i], im.building_boxes[k])) continue;
      const bool hit = decide(st.objects[i].id, pi, "\n" + im.building[k].first, Pose{0, 0, 0, 0, 1},
                              [&] { return im.Collide(*parts[k], object(i)); });
      if (hit) {
        m.per_object[i].colliding = true;
        m.pairs.push_back({st.objects[i].id, im.building[k].first, true});
      }
    }
  }

  for (int i = 0; i < n; ++i) {
    ObjectCheck& c = m.per_object[i];
    const ProblemObject& o = st.objects[i];
    const Pose& pose = st.placements[i].pose;
    // FR.
    if (!st.Hung(i)) {
      ++m.consumers;
      c.support_gap = std::abs(pose.z + entries[i]->bounds.min.z - st.SupportHeight(i));
      c.floating = c.support_gap > opt.tau;
    }
    // OBR.
    const double cs = std::cos(pose.yaw), sn = std::sin(pose.yaw);
    int inside = 0, total = 0;
    const bool on_wall = o.relation == Relation::kOnWall && st.placements[i].wall >= 0;
    const Ring region = on_wall || o.relation == Relation::kHanging ? problem.free_floor : st.SupportRegion(i);
    WallEdge wall;
    if (on_wall) wall = problem.walls[st.placements[i].wall];
    const Point wd = geo::Unit(geo::Sub(wall.b, wall.a));
    const double wall_length = geo::Dist(wall.a, wall.b);
    for (const Vec3& v : entries[i]->samples) {
      const Point w{pose.x + cs * v.x - sn * v.y, pose.y + sn * v.x + cs * v.y};
      bool in;
      if (on_wall) {
        const Point r = geo::Sub(w, wall.a);
        const double t = geo::Dot(r, wd), depth = geo::Dot(r, geo::Left(wd)), z = pose.z + v.z;
        // Along its wall, or anywhere over the free floor: a hood at a reflex corner reaches past the end of
        // its wall's edge where the region is still the room's (a .glb read alone gives the floor to the
        // walls' centre lines, whose edges end half a wall short of the free floor's there).
        in = ((t >= -1e-4 && t <= wall_length + 1e-4 && depth >= -1e-4) || InsideWithTolerance(w, region, 1e-4)) &&
             z >= problem.floor_z - 1e-4 && z <= problem.floor_z + problem.clear_height + 1e-4;
      } else {
        in = InsideWithTolerance(w, region, 1e-4);
      }
      inside += in;
      ++total;
    }
    c.in_bound_share = total > 0 ? static_cast<double>(inside) / total : 1.0;
    c.out_of_bounds = c.in_bound_share < opt.in_bound_share;
    // CSR.
    if (o.relation == Relation::kInside && st.parent[i] >= 0) {
      c.inside_edge = true;
      ++m.inside_edges;
      const int p = st.parent[i];
      const Frame f = st.FrameOf(p);
      const Cavity& cav = st.objects[p].asset.cavities[std::max(0, st.placements[i].cavity)];
      const double t = opt.containment_tolerance;
      const OrientedBox box = st.WorldBox(i);
      // A hanging garment's hook reaches over the rail, above the box.
      const double top = st.HangsOnRail(i) ? *cav.rail + 2.0 * kHookRise : cav.max.z;
      bool within = box.z0 - f.z >= cav.min.z * f.scale - t && box.z1 - f.z <= top * f.scale + t;
      for (Point corner : box.Footprint()) {
        const Point q = f.ToLocal(corner);
        within = within && q.x >= cav.min.x * f.scale - t && q.x <= cav.max.x * f.scale + t &&
                 q.y >= cav.min.y * f.scale - t && q.y <= cav.max.y * f.scale + t;
      }
      // A hanger's hook rests on the rail as a book on its shelf: lifted, it is free.
      const bool touches = AabbOverlap(boxes[p], boxes[i]) &&
                           (st.HangsOnRail(i) ? im.Enters(object(p), object(i), opt.nudge)
                                               : decide(st.objects[p].id, st.placements[p].pose, st.objects[i].id, pose,
                                                        [&] { return im.Collide(object(p), object(i)); }));
      c.contained = within && !touches && c.support_gap <= opt.tau;
      m.contained += c.contained;
    }
    m.colliding += c.colliding;
    m.floating += c.floating;
    m.out_of_bounds += c.out_of_bounds;
  }
  if (n > 0) {
    m.cr = static_cast<double>(m.colliding) / n;
    m.obr = static_cast<double>(m.out_of_bounds) / n;
  }
  if (m.consumers > 0) m.fr = static_cast<double>(m.floating) / m.consumers;
  if (m.inside_edges > 0) m.csr = static_cast<double>(m.contained) / m.inside_edges;
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}

ExactMetrics CheckArrangement(const RoomProblem& problem, const std::vector<ObjectPlacement>& placements,
                              const ExactCheckOptions& options) {
  RoomState state = RoomState::From(problem);
  state.placements = placements;
  state.placements.resize(problem.objects.size());
  ExactChecker checker(problem, options);
  return checker.Check(state);
}

}  // namespace villa::solver
