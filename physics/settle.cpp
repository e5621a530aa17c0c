#include "physics/settle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>

#include <btBulletDynamicsCommon.h>
#include <BulletCollision/CollisionDispatch/btInternalEdgeUtility.h>
#include <LinearMath/btConvexHullComputer.h>

#include "mesh/convex_parts.h"

namespace villa::physics {
namespace {

btVector3 Bt(const Vec3& v) { return {v.x, v.y, v.z}; }

// A piece's hull: its volume and centroid (0 volume when flat or degenerate).
struct Hull {
  std::vector<btVector3> points;
  double volume = 0.0;
  btVector3 centroid{0, 0, 0};
};

// `margin`: the points kept are the hull shrunk by it (up to a quarter of its thickness), so that Bullet's
// collision margin round them gives back the piece's own surface: resting contacts start touching, not
// a margin deep (two margins between bodies), which kicked tall furniture into a sway.
Hull HullOf(const std::vector<btVector3>& points, double margin) {
  Hull h;
  btConvexHullComputer hc;
  hc.compute(&points[0].x(), sizeof(btVector3), static_cast<int>(points.size()), 0.0, 0.0);
  if (hc.vertices.size() < 4) return h;
  const btVector3 o = hc.vertices[0];
  btVector3 weighted(0, 0, 0);
  for (int f = 0; f < hc.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hc.edges[hc.faces[f]];
    const int a = first->getSourceVertex();
    for (const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace(); e->getTargetVertex() != a;
         e = e->getNextEdgeOfFace()) {
      const btVector3 &pa = hc.vertices[a], &pb = hc.vertices[e->getSourceVertex()], &pc = hc.vertices[e->getTargetVertex()];
      const double v = (pa - o).dot((pb - o).cross(pc - o)) / 6.0;
      h.volume += v;
      weighted += v * (o + pa + pb + pc) / 4.0;
    }
  }
  if (h.volume > 1e-12) h.centroid = weighted / h.volume;
  else h.volume = 0.0;
  btConvexHullComputer shrunk;
  const bool shrinks = margin > 0.0 && h.volume > 0.0 &&
                       shrunk.compute(&points[0].x(), sizeof(btVector3), static_cast<int>(points.size()), margin, 0.25) >= 0.0 &&
                       shrunk.vertices.size() >= 4;
  const btConvexHullComputer& kept = shrinks ? shrunk : hc;
  for (int v = 0; v < kept.vertices.size(); ++v) h.points.push_back(kept.vertices[v]);
  return h;
}

// Contacts with the building's triangles take the normals of the surface, not of the edges between its
// triangles (Bullet's internal-edge fix): a box standing across two floor triangles is not nudged sideways
// by the edge between them. Called for contacts of a body flagged CF_CUSTOM_MATERIAL_CALLBACK.
bool SmoothTriangleContact(btManifoldPoint& cp, const btCollisionObjectWrapper* a, int part_a, int index_a,
                           const btCollisionObjectWrapper* b, int part_b, int index_b) {
  btAdjustInternalEdgeContacts(cp, b, a, part_b, index_b);  // each returns at once unless its first is a triangle
  btAdjustInternalEdgeContacts(cp, a, b, part_a, index_a);
  return true;
}

}  // namespace

std::string SettleOptions::Check() const {
  if (!(seconds > 0.0 && seconds <= 60.0)) return "seconds must be in (0, 60], got " + std::to_string(seconds);
  if (!(step > 0.0 && step <= 0.05)) return "step must be in (0, 0.05], got " + std::to_string(step);
  if (!(density > 0.0 && density <= 20000.0)) return "density must be in (0, 20000], got " + std::to_string(density);
  if (!(friction > 0.0 && friction <= 2.0)) return "friction must be in (0, 2], got " + std::to_string(friction);
  if (!(margin >= 0.0 && margin <= 0.01)) return "margin must be in [0, 0.01], got " + std::to_string(margin);
  if (!(strict_move > 0 && strict_turn > 0 && loose_move >= strict_move && loose_turn >= strict_turn))
    return "the loose limits must be at least the strict ones, all > 0";
  return "";
}

std::vector<std::vector<Vec3>> ConnectedPieces(const TriangleMesh& mesh) {
  std::vector<std::vector<Vec3>> out;
  for (TriangleMesh& piece : SolidPiecesOf(mesh)) {
    if (piece.vertices.size() < 4) continue;
    // A piece that is a stack of prisms (a tray with its rim, a shelf unit modelled in one piece) in its
    // convex parts: its hull would fill the tray, and what lies in it would start inside.
    std::optional<std::vector<TriangleMesh>> parts = ConvexPrismParts(piece);
    if (!parts) parts = ConvexPrismParts(piece, kModelTolerance);
    if (parts && parts->size() > 1) {
      for (TriangleMesh& part : *parts) out.push_back(std::move(part.vertices));
      continue;
    }
    out.push_back(std::move(piece.vertices));
  }
  return out;
}

Result<SettleResult> Settle(const std::vector<TriangleMesh>& statics, const std::vector<SettleBody>& bodies,
                            const SettleOptions& options) {
  if (std::string bad = options.Check(); !bad.empty()) return Error{"settle: " + bad};
  const auto start = std::chrono::steady_clock::now();
  SettleResult result;
  result.bodies.resize(bodies.size());

  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity({0, 0, -9.81});
  gDeactivationTime = 0.2;

  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> rigid;
  std::vector<std::unique_ptr<btDefaultMotionState>> states;
  auto add_body = [&](btCollisionShape* shape, double mass, const btVector3& inertia, const btTransform& at) {
    states.push_back(std::make_unique<btDefaultMotionState>(at));
    btRigidBody::btRigidBodyConstructionInfo info(mass, states.back().get(), shape, inertia);
    info.m_friction = options.friction;
    info.m_restitution = 0.0;
    rigid.push_back(std::make_unique<btRigidBody>(info));
    world.addRigidBody(rigid.back().get());
    return rigid.back().get();
  };

  // The building: one static triangle mesh.
  auto triangles = std::make_unique<btTriangleMesh>(true, false);
  for (const TriangleMesh& m : statics)
    for (const auto& t : m.triangles) {
      const btVector3 a = Bt(m.vertices[t[0]]), b = Bt(m.vertices[t[1]]), c = Bt(m.vertices[t[2]]);
      // Downward faces (slab and stair undersides, wall bottoms) hold nothing up; a wall's bottom lies in the
      // floor's plane, and Bullet's contacts with it walked a heavy box standing 2 cm from the wall sideways
      // (a fridge drifted 3-5 cm).
      const btVector3 n = (b - a).cross(c - a);
      if (n.length2() > 0.0 && n.z() < -0.5 * n.length()) continue;
      triangles->addTriangle(a, b, c);
      ++result.static_triangles;
    }
  std::unique_ptr<btTriangleMesh> keep_triangles;
  std::unique_ptr<btTriangleInfoMap> edge_info;
  if (result.static_triangles > 0) {
    auto shape = std::make_unique<btBvhTriangleMeshShape>(triangles.get(), true);
    shape->setMargin(options.margin);
    edge_info = std::make_unique<btTriangleInfoMap>();
    btGenerateInternalEdgeInfo(shape.get(), edge_info.get());
    gContactAddedCallback = SmoothTriangleContact;
    btRigidBody* building = add_body(shape.get(), 0.0, {0, 0, 0}, btTransform::getIdentity());
    building->setCollisionFlags(building->getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
    shapes.push_back(std::move(shape));
    keep_triangles = std::move(triangles);
  }

  struct Tracked {
    btRigidBody* body = nullptr;
    btTransform start;
    std::vector<btVector3> corners;
  };
  std::vector<Tracked> tracked(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) {
    const SettleBody& b = bodies[i];
    BodyMotion& motion = result.bodies[i];
    motion.welded = b.welded;
    if (b.mesh.vertices.empty()) continue;
    const Box3 box = b.mesh.Bounds();
    const btVector3 origin = 0.5 * (Bt(box.min) + Bt(box.max));
    std::vector<Hull> hulls;
    for (const std::vector<Vec3>& piece : ConnectedPieces(b.mesh)) {
      std::vector<btVector3> local;
      for (const Vec3& v : piece) local.push_back(Bt(v) - origin);
      Hull h = HullOf(local, options.margin);
      if (h.volume > 0.0) hulls.push_back(std::move(h));
    }
    if (hulls.empty()) {  // only flat pieces (a picture's quad): the hull of the whole
      std::vector<btVector3> local;
      for (const Vec3& v : b.mesh.vertices) local.push_back(Bt(v) - origin);
      Hull h = HullOf(local, options.margin);
      if (h.points.size() < 4) continue;
      h.volume = std::max(h.volume, 1e-6);
      hulls.push_back(std::move(h));
    }
    auto compound = std::make_unique<btCompoundShape>(true, static_cast<int>(hulls.size()));
    std::vector<btScalar> masses;
    std::vector<std::unique_ptr<btConvexHullShape>> parts;
    for (const Hull& h : hulls) {
      auto part = std::make_unique<btConvexHullShape>(&h.points[0].x(), static_cast<int>(h.points.size()), sizeof(btVector3));
      part->setMargin(options.margin);
      compound->addChildShape(btTransform::getIdentity(), part.get());
      masses.push_back(h.volume * options.density);
      parts.push_back(std::move(part));
    }
    motion.parts = static_cast<int>(hulls.size());
    result.parts += motion.parts;
    double mass = 0.0;
    for (btScalar m : masses) mass += m;
    btTransform at(btQuaternion::getIdentity(), origin);
    btRigidBody* body = nullptr;
    if (b.welded) {
      body = add_body(compound.get(), 0.0, {0, 0, 0}, at);
    } else {
      // The body's frame at its centre of mass, along its principal axes.
      btTransform principal;
      btVector3 inertia;
      compound->calculatePrincipalAxisTransform(masses.data(), principal, inertia);
      auto centred = std::make_unique<btCompoundShape>(true, static_cast<int>(hulls.size()));
      for (int k = 0; k < compound->getNumChildShapes(); ++k)
        centred->addChildShape(principal.inverse() * compound->getChildTransform(k), compound->getChildShape(k));
      body = add_body(centred.get(), mass, inertia, at * principal);
      // A body that has come to rest (under 5 mm/s and 0.01 rad/s for 0.2 s) sleeps until something
      // touches it: most of a furnished villa stands still, and sleeping bodies cost nothing.
      body->setSleepingThresholds(0.005, 0.01);
      shapes.push_back(std::move(centred));
      ++result.free;
    }
    shapes.push_back(std::move(compound));
    for (auto& p : parts) shapes.push_back(std::move(p));
    Tracked& t = tracked[i];
    t.body = body;
    t.start = body->getWorldTransform();
    for (int k = 0; k < 8; ++k)
      t.corners.push_back({k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z});
  }

  // Where bodies start inside one another: the deepest contact of each, before anything moves.
  std::map<const btCollisionObject*, int> index_of;
  for (size_t i = 0; i < tracked.size(); ++i)
    if (tracked[i].body) index_of[tracked[i].body] = static_cast<int>(i);
  world.performDiscreteCollisionDetection();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    const auto a = index_of.find(manifold->getBody0()), b = index_of.find(manifold->getBody1());
    for (int c = 0; c < manifold->getNumContacts(); ++c) {
      const btManifoldPoint& point = manifold->getContactPoint(c);
      const double depth = -point.getDistance();
      const btVector3 n = point.m_normalWorldOnB;  // on body 1, toward body 0
      for (const auto& [self, other, sign] : {std::tuple{a, b, 1.0}, std::tuple{b, a, -1.0}}) {
        if (self == index_of.end()) continue;
        BodyMotion& motion = result.bodies[self->second];
        if (depth <= motion.start_depth) continue;
        motion.start_depth = depth;
        motion.start_against = other == index_of.end() ? "building" : bodies[other->second].id;
        motion.start_out = {sign * n.x(), sign * n.y(), sign * n.z()};
      }
    }
  }
  for (const BodyMotion& motion : result.bodies) result.starts_inside += motion.start_depth > kStartsInside;

  const int steps = static_cast<int>(std::ceil(options.seconds / options.step - 1e-9));
  // Once every free body sleeps nothing can wake it (a sleeping body moves only when an awake one touches
  // it), so the steps left would change nothing: stop there. Checked every 0.05 s of simulated time.
  std::vector<const btRigidBody*> free_bodies;
  for (size_t i = 0; i < tracked.size(); ++i)
    if (tracked[i].body && !bodies[i].welded) free_bodies.push_back(tracked[i].body);
  const int check_every = std::max(1, static_cast<int>(std::lround(0.05 / options.step)));
  for (int s = 0; s < steps; ++s) {
    world.stepSimulation(options.step, 0, options.step);
    ++result.steps;
    if ((s + 1) % check_every == 0 &&
        std::none_of(free_bodies.begin(), free_bodies.end(), [](const btRigidBody* b) { return b->isActive(); }))
      break;
  }

  for (size_t i = 0; i < bodies.size(); ++i) {
    BodyMotion& motion = result.bodies[i];
    const Tracked& t = tracked[i];
    if (t.body && !motion.welded) {
      const btTransform change = t.body->getWorldTransform() * t.start.inverse();
      for (const btVector3& c : t.corners) motion.moved = std::max<double>(motion.moved, (change * c - c).length());
      const btVector3 centre = 0.5 * (t.corners.front() + t.corners.back()), d = change * centre - centre;
      motion.shift = {d.x(), d.y(), d.z()};
      motion.turned = change.getRotation().getAngle();
      if (motion.turned > M_PI) motion.turned = 2.0 * M_PI - motion.turned;
      motion.strict = motion.moved <= options.strict_move && motion.turned <= options.strict_turn;
      motion.loose = motion.moved <= options.loose_move && motion.turned <= options.loose_turn;
      result.strict += motion.strict;
      result.loose += motion.loose;
    }
  }
  for (auto& b : rigid) world.removeRigidBody(b.get());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace villa::physics
