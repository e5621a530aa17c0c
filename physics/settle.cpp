#include "physics/settle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <tuple>

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

// A closed piece's triangles as a soup, for cutting: a triangle is its three corners.
using Soup = std::vector<std::array<Vec3, 3>>;

// What a cut leaves: how many of the probes (points inside what starts in the piece) its hulls hold more
// than 1 mm deep, and their volume.
struct CutCost {
  int held = 0;
  double volume = 0.0;
  bool operator<(const CutCost& o) const { return held != o.held ? held < o.held : volume < o.volume; }
};

CutCost HullCost(const std::vector<Vec3>& points, const std::vector<Vec3>& probes) {
  CutCost cost;
  if (points.size() < 4) return cost;
  btConvexHullComputer hc;
  hc.compute(&points[0].x, sizeof(Vec3), static_cast<int>(points.size()), 0.0, 0.0);
  if (hc.vertices.size() < 4) return cost;
  const btVector3 o = hc.vertices[0];
  btVector3 centre(0, 0, 0);
  for (int v = 0; v < hc.vertices.size(); ++v) centre += hc.vertices[v] / hc.vertices.size();
  std::vector<std::pair<btVector3, double>> planes;  // outward normal, offset
  for (int f = 0; f < hc.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hc.edges[hc.faces[f]];
    const int a = first->getSourceVertex();
    btVector3 normal(0, 0, 0);
    for (const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace(); e->getTargetVertex() != a; e = e->getNextEdgeOfFace()) {
      const btVector3 &pa = hc.vertices[a], &pb = hc.vertices[e->getSourceVertex()], &pc = hc.vertices[e->getTargetVertex()];
      cost.volume += (pa - o).dot((pb - o).cross(pc - o)) / 6.0;
      normal += (pb - pa).cross(pc - pa);
    }
    if (normal.length2() <= 0.0) continue;
    normal.normalize();
    if (normal.dot(centre - hc.vertices[a]) > 0.0) normal = -normal;
    planes.push_back({normal, normal.dot(hc.vertices[a])});
  }
  for (const Vec3& p : probes) {
    const btVector3 q = Bt(p);
    cost.held += std::all_of(planes.begin(), planes.end(), [&](const auto& pl) { return pl.first.dot(q) - pl.second < -0.001; });
  }
  return cost;
}

// The corners of `soup`: about `cap` of them (every k-th; repeats are harmless to a hull) where an
// estimate will do.
std::vector<Vec3> CornersOf(const Soup& soup, size_t cap = SIZE_MAX) {
  const size_t n = 3 * soup.size(), stride = n > cap ? (n + cap - 1) / cap : 1;
  std::vector<Vec3> out;
  out.reserve(n / stride + 1);
  for (size_t k = 0; k < n; k += stride) out.push_back(soup[k / 3][k % 3]);
  return out;
}

// The parts of `soup` on each side of the plane dot(axis, p) = at: each triangle cut (Sutherland and
// Hodgman for one plane) and fanned back into triangles. For a closed solid, each side's hull is the hull
// of the solid's part on that side (the cut face lies within the hull of the cut's edge points).
std::pair<Soup, Soup> CutSoup(const Soup& soup, Vec3 axis, double at) {
  std::pair<Soup, Soup> out;
  for (const auto& t : soup) {
    double d[3];
    for (int k = 0; k < 3; ++k) d[k] = Dot(axis, t[k]) - at;
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? -1.0 : 1.0;
      std::vector<Vec3> poly;
      for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        const bool in_k = sign * d[k] >= 0.0, in_j = sign * d[j] >= 0.0;
        if (in_k) poly.push_back(t[k]);
        if (in_k != in_j && d[k] != d[j]) {
          const double f = d[k] / (d[k] - d[j]);
          poly.push_back(t[k] + (t[j] - t[k]) * f);
        }
      }
      Soup& into = side == 0 ? out.first : out.second;
      for (size_t k = 2; k < poly.size(); ++k) into.push_back({poly[0], poly[k - 1], poly[k]});
    }
  }
  return out;
}

// Whether the piece is closed (every edge has a triangle each way) and fills its hull to `share`: a box, a
// cylinder, a cushion. Only the others are cut.
bool FillsItsHull(const TriangleMesh& piece, double share) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : piece.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : edges) {
    const auto back = edges.find({e.second, e.first});
    if (back == edges.end() || back->second != n) return false;
  }
  return piece.SignedVolume() >= share * HullCost(piece.vertices, {}).volume;
}

// Levels along `axis` at which to try cutting `soup`: the faces of what starts inside it (`guides`), and
// `most` of its own corners' levels (a headboard's inner face, not a point in the middle of the rails),
// 5 mm apart and 5 mm in from its ends.
std::vector<double> CutLevels(const Soup& soup, Vec3 axis, const std::vector<Box3>& guides, size_t most) {
  std::vector<double> levels;
  levels.reserve(3 * soup.size());
  for (const auto& t : soup)
    for (const Vec3& c : t) levels.push_back(Dot(axis, c));
  if (levels.empty()) return {};
  std::sort(levels.begin(), levels.end());
  const double low = levels.front() + 0.005, high = levels.back() - 0.005;
  std::vector<double> distinct;
  for (double l : levels)
    if (l > low && l < high && (distinct.empty() || l > distinct.back() + 0.005)) distinct.push_back(l);
  std::vector<double> out;
  for (size_t k = 0; k < std::min(most, distinct.size()); ++k) out.push_back(distinct[k * distinct.size() / std::min(most, distinct.size())]);
  for (const Box3& g : guides) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < 8; ++k) {
      const double l = Dot(axis, Vec3{k & 1 ? g.max.x : g.min.x, k & 2 ? g.max.y : g.min.y, k & 4 ? g.max.z : g.min.z});
      lo = std::min(lo, l), hi = std::max(hi, l);
    }
    for (double l : {lo, hi})
      if (l > low && l < high) out.push_back(l);
  }
  return out;
}

// Approximate convex parts of a piece whose hull would fill its hollows (an imported bed in one piece: the
// hull of its headboard, rails and footboard is a wedge over the mattress, and the pillows at the head start
// 40 cm inside it). The piece is cut by the plane, across one of its three axes (the way its horizontal
// edges run, the one across it, and up) at one of CutLevels, that leaves the fewest `probes` (points
// spread through what starts inside the piece) inside the two sides' hulls, then the least hull volume
// (estimated on 300 corners a side); a cut is made when it frees probes or saves `enough` volume. Then each
// side the same, to `depth` cuts deep.
void CutIntoHulls(const Soup& soup, const std::array<Vec3, 3>& axes, const std::vector<Box3>& guides, const std::vector<Vec3>& probes,
                  int depth, double enough, std::vector<std::vector<Vec3>>& out) {
  const CutCost whole = HullCost(CornersOf(soup, 300), probes);
  CutCost best = whole;
  std::pair<Soup, Soup> best_sides;  // the best cut's two sides, kept
  if (depth > 0 && whole.volume > enough) {
    for (const Vec3& axis : axes)
      for (double at : CutLevels(soup, axis, guides, 8)) {
        std::pair<Soup, Soup> sides = CutSoup(soup, axis, at);
        const CutCost a = HullCost(CornersOf(sides.first, 300), probes), b = HullCost(CornersOf(sides.second, 300), probes);
        const CutCost sum{a.held + b.held, a.volume + b.volume};
        if (sum < best) best = sum, best_sides = std::move(sides);
      }
  }
  if (best.held == whole.held && whole.volume - best.volume < enough) {
    out.push_back(CornersOf(soup));
    return;
  }
  CutIntoHulls(best_sides.first, axes, guides, probes, depth - 1, enough, out);
  CutIntoHulls(best_sides.second, axes, guides, probes, depth - 1, enough, out);
}

std::vector<std::vector<Vec3>> HullParts(const TriangleMesh& piece, const std::vector<Box3>& guides) {
  if (FillsItsHull(piece, 0.9)) return {piece.vertices};
  // The piece's axes: the direction (modulo quarter turns) its horizontal edges run, by length, to a degree
  // (a model's frame is turned with it; a face's diagonal is one edge against its four sides), across
  // it, and up.
  std::array<double, 90> run{};
  for (const auto& t : piece.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = piece.vertices[t[(k + 1) % 3]] - piece.vertices[t[k]];
      const double length = std::hypot(e.x, e.y);
      if (length <= 0.0 || std::abs(e.z) > 1e-3 * length) continue;
      double degrees = std::atan2(e.y, e.x) * 180.0 / M_PI;
      degrees -= 90.0 * std::floor(degrees / 90.0);
      run[static_cast<size_t>(std::lround(degrees)) % 90] += length;
    }
  const double turn = static_cast<double>(std::max_element(run.begin(), run.end()) - run.begin()) * M_PI / 180.0;
  const Vec3 along{std::cos(turn), std::sin(turn), 0.0};
  Soup soup;
  for (const auto& t : piece.triangles) soup.push_back({piece.vertices[t[0]], piece.vertices[t[1]], piece.vertices[t[2]]});
  std::vector<Box3> near;  // what starts inside this piece's box
  const Box3 box = piece.Bounds();
  for (const Box3& g : guides)
    if (g.min.x < box.max.x && g.max.x > box.min.x && g.min.y < box.max.y && g.max.y > box.min.y && g.min.z < box.max.z && g.max.z > box.min.z)
      near.push_back(g);
  std::vector<Vec3> probes;  // 5 x 5 x 3 through each, 2 mm in from its faces (touching is no harm)
  for (const Box3& g : near)
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j)
        for (int k = 0; k < 3; ++k) {
          const Vec3 lo = g.min + Vec3{0.002, 0.002, 0.002}, span = g.max - g.min - Vec3{0.004, 0.004, 0.004};
          probes.push_back(lo + Vec3{span.x * i / 4.0, span.y * j / 4.0, span.z * k / 2.0});
        }
  std::vector<std::vector<Vec3>> out;
  CutIntoHulls(soup, {along, Vec3{-along.y, along.x, 0.0}, Vec3{0, 0, 1}}, near, probes, 5, 0.002, out);
  return out;
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

std::vector<std::vector<Vec3>> ConnectedPieces(const TriangleMesh& mesh, const std::vector<Box3>* guides) {
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
    if (!guides) {
      out.push_back(std::move(piece.vertices));
      continue;
    }
    for (std::vector<Vec3>& part : HullParts(piece, *guides)) out.push_back(std::move(part));
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
  // Body i as a rigid body of its pieces' hulls (`guides`: a piece's hollows cut out, ConnectedPieces).
  auto build = [&](size_t i, const std::vector<Box3>* guides) {
    const SettleBody& b = bodies[i];
    BodyMotion& motion = result.bodies[i];
    motion.welded = b.welded;
    if (b.mesh.vertices.empty()) return;
    const Box3 box = b.mesh.Bounds();
    const btVector3 origin = 0.5 * (Bt(box.min) + Bt(box.max));
    std::vector<Hull> hulls;
    for (const std::vector<Vec3>& piece : ConnectedPieces(b.mesh, guides)) {
      std::vector<btVector3> local;
      for (const Vec3& v : piece) local.push_back(Bt(v) - origin);
      Hull h = HullOf(local, options.margin);
      if (h.volume > 0.0) hulls.push_back(std::move(h));
    }
    if (hulls.empty()) {  // only flat pieces (a picture's quad): the hull of the whole
      std::vector<btVector3> local;
      for (const Vec3& v : b.mesh.vertices) local.push_back(Bt(v) - origin);
      Hull h = HullOf(local, options.margin);
      if (h.points.size() < 4) return;
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
    Tracked& t = tracked[i];
    if (t.body) {  // built before, uncut: this one takes its place
      world.removeRigidBody(t.body);
      result.parts -= motion.parts;
      result.free -= !b.welded;
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
    t.body = body;
    t.start = body->getWorldTransform();
    t.corners.clear();
    for (int k = 0; k < 8; ++k)
      t.corners.push_back({k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z});
  };
  for (size_t i = 0; i < bodies.size(); ++i) build(i, nullptr);

  // Where bodies start inside one another: the deepest contact of each, before anything moves.
  std::map<const btCollisionObject*, int> index_of;
  auto start_contacts = [&] {
    index_of.clear();
    for (size_t i = 0; i < tracked.size(); ++i)
      if (tracked[i].body) index_of[tracked[i].body] = static_cast<int>(i);
    for (BodyMotion& motion : result.bodies) motion.start_depth = 0.0, motion.start_against.clear(), motion.start_out = {};
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
  };
  start_contacts();
  // What another body starts inside is built again with its hollows cut out (an imported bed's hull over
  // its mattress, an armchair's over its seat), the cuts tried at the faces of what is inside: only those
  // bodies, for cutting costs up to a tenth of a second a model.
  std::map<std::string, size_t> by_id;
  for (size_t i = 0; i < bodies.size(); ++i) by_id.emplace(bodies[i].id, i);
  std::map<size_t, std::vector<Box3>> hosts;
  for (size_t i = 0; i < bodies.size(); ++i)
    if (result.bodies[i].start_depth > kStartsInside)
      if (auto it = by_id.find(result.bodies[i].start_against); it != by_id.end()) hosts[it->second].push_back(bodies[i].mesh.Bounds());
  for (const auto& [i, guides] : hosts) build(i, &guides);
  if (!hosts.empty()) start_contacts();
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
