#include "physics/mjcf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "mesh/convex_parts.h"
#include "physics/glb_settle.h"
#include "util/atomic_file.h"

#include <LinearMath/btConvexHullComputer.h>

namespace villa::physics {
namespace {

namespace fs = std::filesystem;

// The triangles of each connected piece of `mesh` whose box is at least 0.1 mm thick every way (MuJoCo
// needs a volume).
std::vector<TriangleMesh> SolidPieces(const TriangleMesh& mesh) {
  std::vector<TriangleMesh> out;
  for (TriangleMesh& piece : SolidPiecesOf(mesh)) {
    const Box3 b = piece.Bounds();
    if (b.max.x - b.min.x < 1e-4 || b.max.y - b.min.y < 1e-4 || b.max.z - b.min.z < 1e-4) continue;
    out.push_back(std::move(piece));
  }
  return out;
}

// A piece that is a box (8 corners, three perpendicular edges): most of ours are, and boxes whose union
// fills their common box are merged into it (MergeBoxes).
struct BoxFit {
  Vec3 centre, x, y;  // centre, the box's x and y axes (unit; z = x cross y)
  Vec3 half;          // half sizes along x, y, z
};
std::optional<BoxFit> AsBox(const TriangleMesh& piece) {
  std::vector<Vec3> corners;
  for (const Vec3& v : piece.vertices) {
    bool seen = false;
    for (const Vec3& c : corners) seen = seen || Norm(v - c) < 1e-6;
    if (!seen) corners.push_back(v);
    if (corners.size() > 8) return std::nullopt;
  }
  if (corners.size() != 8) return std::nullopt;
  const Vec3 v0 = corners[0];
  std::vector<Vec3> rest(corners.begin() + 1, corners.end());
  std::sort(rest.begin(), rest.end(), [&](const Vec3& a, const Vec3& b) { return Norm(a - v0) < Norm(b - v0); });
  // The edges from v0: the nearest corners whose directions are perpendicular to those taken (a face's
  // diagonal can be nearer than the longest edge).
  std::vector<Vec3> e;
  for (const Vec3& c : rest) {
    const Vec3 d = c - v0;
    if (Norm(d) < 1e-5) return std::nullopt;
    bool perpendicular = true;
    for (const Vec3& f : e) perpendicular = perpendicular && std::abs(Dot(d, f)) <= 1e-3 * Norm(d) * Norm(f);
    if (perpendicular) e.push_back(d);
    if (e.size() == 3) break;
  }
  if (e.size() != 3) return std::nullopt;
  for (const Vec3& c : corners)
    for (int i = 0; i < 3; ++i) {
      const double t = Dot(c - v0, e[i]) / Dot(e[i], e[i]);
      if (std::abs(t) > 1e-3 && std::abs(t - 1.0) > 1e-3) return std::nullopt;
    }
  BoxFit fit;
  fit.centre = v0 + (e[0] + e[1] + e[2]) * 0.5;
  fit.x = Normalized(e[0]);
  fit.y = Normalized(e[1]);
  fit.half = {0.5 * Norm(e[0]), 0.5 * Norm(e[1]), 0.5 * Norm(e[2])};
  return fit;
}

// Boxes that together fill (nearly) their common box become that box: a book's pages, covers and spine
// are one book to a simulator, and MuJoCo makes up to eight contacts per pair of geoms, so four boxes a
// book on a shelf cost four times the contacts (and the constraint rows, whose memory MuJoCo 2.2 takes
// as their square). Merged when the boxes' axes are parallel and the common box is at most `slack` more
// than the volume they fill and none of it lies farther than `depth` from them (summed over a chain of
// merges).
struct MergedBox {
  BoxFit box;
  double solid = 0.0;  // the volume the merged parts fill (an estimate from below)
  double slop = 0.0;   // m: how far a point of the box may lie from the parts (0: the parts fill it)
};
std::vector<BoxFit> MergeBoxes(const std::vector<BoxFit>& boxes, double slack = 0.08, double depth = 0.005) {
  std::vector<MergedBox> groups;
  for (const BoxFit& b : boxes) groups.push_back({b, 8.0 * b.half.x * b.half.y * b.half.z, 0.0});
  auto axes = [](const BoxFit& b) { return std::array<Vec3, 3>{b.x, b.y, Cross(b.x, b.y)}; };
  // b's box in a's frame (lo, hi per axis), or nullopt when their axes are not parallel.
  auto in_frame = [&](const BoxFit& a, const BoxFit& b) -> std::optional<std::array<double, 6>> {
    const auto fa = axes(a), fb = axes(b);
    const double hb[3] = {b.half.x, b.half.y, b.half.z};
    std::array<double, 6> out{};
    for (int i = 0; i < 3; ++i) {
      double extent = 0.0;
      int parallel = 0;
      for (int k = 0; k < 3; ++k) {
        const double d = std::abs(Dot(fa[i], fb[k]));
        if (d > 1.0 - 1e-6) ++parallel;
        else if (d > 1e-6) return std::nullopt;
        extent += d * hb[k];
      }
      if (parallel != 1) return std::nullopt;
      const double c = Dot(b.centre - a.centre, fa[i]);
      out[2 * i] = c - extent;
      out[2 * i + 1] = c + extent;
    }
    return out;
  };
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < groups.size() && !merged; ++i)
      for (size_t j = i + 1; j < groups.size() && !merged; ++j) {
        const BoxFit& a = groups[i].box;
        const auto b = in_frame(a, groups[j].box);
        if (!b) continue;
        const double ha[3] = {a.half.x, a.half.y, a.half.z};
        double common = 1.0, overlap = 1.0, lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
          lo[k] = std::min(-ha[k], (*b)[2 * k]);
          hi[k] = std::max(ha[k], (*b)[2 * k + 1]);
          common *= hi[k] - lo[k];
          overlap *= std::max(0.0, std::min(ha[k], (*b)[2 * k + 1]) - std::max(-ha[k], (*b)[2 * k]));
        }
        const double solid = groups[i].solid + groups[j].solid - overlap;
        if (common > (1.0 + slack) * solid) continue;
        // Every point of the common box within `depth` of what the parts fill (sampled on a 9^3 grid, the
        // corners and faces' centres among it): pages 3 mm inside a book's covers merge; soil 2 cm below a
        // trough's rim does not (what stands on the soil would stand on air). Slop adds up over merges.
        const double alo[3] = {-ha[0], -ha[1], -ha[2]}, blo[3] = {(*b)[0], (*b)[2], (*b)[4]}, bhi[3] = {(*b)[1], (*b)[3], (*b)[5]};
        auto gap = [](const double* l, const double* h, const double p[3]) {
          double d2 = 0.0;
          for (int k = 0; k < 3; ++k) {
            const double d = std::max({l[k] - p[k], 0.0, p[k] - h[k]});
            d2 += d * d;
          }
          return std::sqrt(d2);
        };
        const double budget = depth - std::max(groups[i].slop, groups[j].slop);
        bool near = budget > 0.0;
        constexpr int kSamples = 9;
        for (int n = 0; n < kSamples * kSamples * kSamples && near; ++n) {
          const int idx[3] = {n % kSamples, (n / kSamples) % kSamples, n / (kSamples * kSamples)};
          double p[3];
          for (int k = 0; k < 3; ++k) p[k] = lo[k] + (hi[k] - lo[k]) * idx[k] / (kSamples - 1);
          near = std::min(gap(alo, ha, p), gap(blo, bhi, p)) <= budget;
        }
        if (!near) continue;
        double slop = 0.0;  // the merged box's own distance from the parts, for the next merge
        for (int n = 0; n < kSamples * kSamples * kSamples; ++n) {
          const int idx[3] = {n % kSamples, (n / kSamples) % kSamples, n / (kSamples * kSamples)};
          double p[3];
          for (int k = 0; k < 3; ++k) p[k] = lo[k] + (hi[k] - lo[k]) * idx[k] / (kSamples - 1);
          slop = std::max(slop, std::min(gap(alo, ha, p), gap(blo, bhi, p)));
        }
        slop += std::max(groups[i].slop, groups[j].slop);
        const auto fa = axes(a);
        BoxFit m = a;
        m.centre = a.centre + fa[0] * (0.5 * (lo[0] + hi[0])) + fa[1] * (0.5 * (lo[1] + hi[1])) + fa[2] * (0.5 * (lo[2] + hi[2]));
        m.half = {0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1]), 0.5 * (hi[2] - lo[2])};
        groups[i] = {m, solid, slop};
        groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(j));
        merged = true;
      }
  }
  std::vector<BoxFit> out;
  for (const MergedBox& g : groups) out.push_back(g.box);
  return out;
}

// A piece's convex hull as a closed mesh (MuJoCo collides a mesh as its hull anyway, but takes its mass
// and inertia from the mesh as written: an imported piece that is open or folded gave inertia no body can
// have, and the file did not load). Nullopt for a sheet: under 1 cm3, or under 2 mm thick.
std::optional<TriangleMesh> HullMesh(const TriangleMesh& piece) {
  std::vector<btVector3> points;
  for (const Vec3& v : piece.vertices) points.emplace_back(v.x, v.y, v.z);
  if (points.size() < 4) return std::nullopt;
  btConvexHullComputer hc;
  hc.compute(&points[0].x(), sizeof(btVector3), static_cast<int>(points.size()), 0.0, 0.0);
  TriangleMesh hull;
  for (int v = 0; v < hc.vertices.size(); ++v) hull.vertices.push_back({hc.vertices[v].x(), hc.vertices[v].y(), hc.vertices[v].z()});
  for (int f = 0; f < hc.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hc.edges[hc.faces[f]];
    const int a = first->getSourceVertex();
    for (const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace(); e->getTargetVertex() != a; e = e->getNextEdgeOfFace())
      hull.AddTriangle(a, e->getSourceVertex(), e->getTargetVertex());
  }
  if (hull.triangles.size() < 4 || hull.SignedVolume() < 1e-6) return std::nullopt;
  // Thinner than 2 mm across one of its faces (a polytope is narrowest across a face or between two
  // edges; a face's is an upper bound): MuJoCo's inertia of a sheet fails its own triangle inequality.
  for (const auto& t : hull.triangles) {
    const Vec3 n = Normalized(Cross(hull.vertices[t[1]] - hull.vertices[t[0]], hull.vertices[t[2]] - hull.vertices[t[0]]));
    double lo = 1e300, hi = -1e300;
    for (const Vec3& v : hull.vertices) {
      lo = std::min(lo, Dot(v, n));
      hi = std::max(hi, Dot(v, n));
    }
    if (hi - lo < 0.002) return std::nullopt;
  }
  return hull;
}

// Binary STL of `mesh` moved by -origin.
std::string Stl(const TriangleMesh& mesh, const Vec3& origin) {
  std::string out(80, '\0');
  auto put32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  auto putf = [&](double v) {
    const float f = static_cast<float>(v);
    out.append(reinterpret_cast<const char*>(&f), 4);
  };
  put32(static_cast<uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - origin, b = mesh.vertices[t[1]] - origin, c = mesh.vertices[t[2]] - origin;
    const Vec3 n = Normalized(Cross(b - a, c - a));
    for (double v : {n.x, n.y, n.z, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z}) putf(v);
    out.append(2, '\0');
  }
  return out;
}

std::string Xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string Num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

}  // namespace

Result<MjcfSummary> WriteMjcf(const fs::path& glb, const fs::path& dir, const SettleOptions& options) {
  if (std::string bad = options.Check(); !bad.empty()) return Error{"mjcf: " + bad};
  auto scene = ReadGlbBodies(glb);
  if (!scene.ok()) return Error{scene.error()};
  std::error_code ec;
  fs::create_directories(dir / "meshes", ec);
  if (ec) return Error{(dir / "meshes").string() + ": cannot create the folder: " + ec.message()};
  MjcfSummary summary;
  std::ostringstream assets, world;
  auto add_mesh = [&](const TriangleMesh& piece, const Vec3& origin) -> Result<std::string> {
    const std::string name = "m" + std::to_string(summary.meshes++);
    if (Status s = WriteFileAtomic(dir / "meshes" / (name + ".stl"), Stl(piece, origin)); !s) return Error{s.error()};
    assets << "    <mesh name=\"" << name << "\" file=\"" << name << ".stl\"/>\n";
    return name;
  };
  // A box piece is written as an 8-corner mesh in its own frame (one asset per size), placed by the geom's
  // pos and axes. Not a box geom: MuJoCo's box-box collider (2.2, and still in 3.x: its issue #3476) can
  // return a phantom contact as deep as a box is wide for two boxes resting flush, face to face (a counter's
  // 8 mm side panel on the floor slab came out 1.44 m deep and the counter was thrown with what stood on
  // it); box-mesh and mesh-mesh pairs go through its general convex collider, multi-point with multiccd.
  std::map<std::string, std::string> box_meshes;
  auto add_box = [&](std::ostringstream& out, const BoxFit& box, const Vec3& origin, const std::string& indent,
                     const char* kind) -> Status {
    const std::string size = Num(box.half.x) + " " + Num(box.half.y) + " " + Num(box.half.z);
    auto [it, fresh] = box_meshes.emplace(size, "");
    if (fresh) {
      TriangleMesh corners;
      for (int k = 0; k < 8; ++k)
        corners.vertices.push_back({(k & 1 ? 1 : -1) * box.half.x, (k & 2 ? 1 : -1) * box.half.y, (k & 4 ? 1 : -1) * box.half.z});
      // Outward faces: -x, +x, -y, +y, -z, +z, two triangles each.
      for (const auto& t : std::vector<std::array<int, 3>>{{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                                                           {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}})
        corners.AddTriangle(t[0], t[1], t[2]);
      auto name = add_mesh(corners, {0, 0, 0});
      if (!name.ok()) return Error{name.error()};
      it->second = *name;
    }
    const Vec3 c = box.centre - origin;
    out << indent << "<geom type=\"mesh\" mesh=\"" << it->second << "\" pos=\"" << Num(c.x) << " " << Num(c.y) << " "
        << Num(c.z) << "\" xyaxes=\"" << Num(box.x.x) << " " << Num(box.x.y) << " " << Num(box.x.z) << " " << Num(box.y.x)
        << " " << Num(box.y.y) << " " << Num(box.y.z) << "\" class=\"" << kind << "\"/>\n";
    ++summary.boxes;
    return {};
  };
  // A body's (or the building's) pieces: boxes (merged where they fill their common box) as box meshes,
  // the rest as mesh geoms; `origin` is the body's. Returns the number of geoms written.
  auto add_geoms = [&](std::ostringstream& out, const std::vector<TriangleMesh>& pieces, const Vec3& origin,
                       const std::string& indent, const char* kind, bool merge) -> Result<int> {
    std::vector<BoxFit> boxes;
    int geoms = 0;
    std::vector<TriangleMesh> convex;
    for (const TriangleMesh& piece : pieces) {
      std::optional<std::vector<TriangleMesh>> parts;
      if (!AsBox(piece)) parts = ConvexPrismParts(piece);  // a tray, not its hull (as the settle reads it)
      if (!AsBox(piece) && !parts) parts = ConvexPrismParts(piece, kModelTolerance);
      if (parts && parts->size() > 1) convex.insert(convex.end(), parts->begin(), parts->end());
      else convex.push_back(piece);
    }
    for (const TriangleMesh& piece : convex) {
      if (const std::optional<BoxFit> box = AsBox(piece)) {
        boxes.push_back(*box);
        continue;
      }
      const std::optional<TriangleMesh> hull = HullMesh(piece);
      if (!hull) {
        ++summary.sheets;
        continue;
      }
      auto name = add_mesh(*hull, origin);
      if (!name.ok()) return Error{name.error()};
      out << indent << "<geom type=\"mesh\" mesh=\"" << *name << "\" class=\"" << kind << "\"/>\n";
      ++geoms;
    }
    if (merge) {
      const size_t before = boxes.size();
      boxes = MergeBoxes(boxes);
      summary.merged += static_cast<int>(before - boxes.size());
    }
    for (const BoxFit& box : boxes)
      if (Status s = add_box(out, box, origin, indent, kind); !s) return Error{s.error()};
    return geoms + static_cast<int>(boxes.size());
  };
  std::vector<bool> is_door(scene->statics.size(), false);
  for (const GlbDoor& door : scene->doors) is_door[door.static_index] = true;
  for (size_t i = 0; i < scene->statics.size(); ++i) {
    if (is_door[i]) continue;
    // The building's pieces cut into convex prisms (a wall's hull would fill its doorways).
    std::vector<TriangleMesh> convex;
    // Welded first: a file may repeat a corner for each face (a slab's hole is lined by faces of their own).
    for (TriangleMesh& piece : SolidPieces(WeldedByPosition(scene->statics[i]))) {
      if (std::optional<std::vector<TriangleMesh>> parts = ConvexPrismParts(piece)) {
        for (TriangleMesh& part : *parts) convex.push_back(std::move(part));
        ++summary.prisms;
      } else {
        convex.push_back(std::move(piece));
        ++summary.hulls;
      }
    }
    auto geoms = add_geoms(world, convex, {0, 0, 0}, "    ", "building", false);
    if (!geoms.ok()) return Error{geoms.error()};
    summary.static_geoms += *geoms;
  }
  // Door leaves: bodies on a vertical hinge at the jamb, free to turn between closed and 90 degrees open
  // (or as far as they hang, flat against the wall), damped like a real door's hinges.
  for (const GlbDoor& door : scene->doors) {
    const TriangleMesh& leaf = scene->statics[door.static_index];
    const Box3 box = leaf.Bounds();
    const Vec3 origin{door.hinge_x, door.hinge_y, 0.5 * (box.min.z + box.max.z)};
    const double lo = std::min({0.0, door.to_closed, door.to_open}), hi = std::max({0.0, door.to_closed, door.to_open});
    world << "    <body name=\"" << Xml(door.name) << "\" pos=\"" << Num(origin.x) << " " << Num(origin.y) << " " << Num(origin.z)
          << "\">\n      <joint name=\"" << Xml(door.name) << "\" type=\"hinge\" axis=\"0 0 1\" limited=\"true\" range=\""
          << Num(lo) << " " << Num(hi) << "\" class=\"hinge\"/>\n";
    auto geoms = add_geoms(world, SolidPieces(leaf), origin, "      ", "door", false);
    if (!geoms.ok()) return Error{geoms.error()};
    world << "    </body>\n";
    ++summary.doors;
  }
  for (const SettleBody& b : scene->bodies) {
    const std::vector<TriangleMesh> pieces = SolidPieces(b.mesh);
    if (pieces.empty()) continue;
    const Box3 box = b.mesh.Bounds();
    const Vec3 origin = (box.min + box.max) * 0.5;
    world << "    <body name=\"" << Xml(b.id) << "\" pos=\"" << Num(origin.x) << " " << Num(origin.y) << " " << Num(origin.z) << "\">\n";
    if (!b.welded) {
      world << "      <freejoint/>\n";
      ++summary.free;
    }
    auto geoms = add_geoms(world, pieces, origin, "      ", "object", true);
    if (!geoms.ok()) return Error{geoms.error()};
    if (*geoms == 0 && !b.welded) {
      // Nothing but sheets: its box, so that it has a mass (a free body without one does not load).
      add_box(world, BoxFit{origin, {1, 0, 0}, {0, 1, 0}, (box.max - box.min) * 0.5}, origin, "      ", "object");
      *geoms = 1;
    }
    summary.geoms += *geoms;
    world << "    </body>\n";
    ++summary.bodies;
  }
  // Contacts: multi-point convex collision (a box on a mesh floor otherwise touches at one point and
  // creeps); the buffers first guessed from the geoms: two contacts for each, three constraint rows for
  // each contact (elliptic cones).
  const int geoms = summary.geoms + summary.static_geoms + summary.doors;
  summary.nconmax = std::clamp(2 * geoms, 500, kMjcfMaxRows / 3);
  summary.njmax = 3 * summary.nconmax;
  std::ostringstream xml;
  xml << "<mujoco model=\"" << Xml(glb.stem().string()) << "\">\n"
      << "  <!-- Written by villa physics --mjcf from " << Xml(glb.filename().string()) << ": the building static, its door\n"
      << "       leaves on hinges, every object a body named by its scene id (a free joint unless hung or on a rail),\n"
      << "       one geom a convex part. -->\n"
      << "  <compiler meshdir=\"meshes\" angle=\"radian\"/>\n"
      << "  <!-- Elliptic friction cones, stiffer contacts than MuJoCo's defaults and multi-point convex contacts:\n"
      << "       with MuJoCo's defaults things held between two geoms were squeezed out and boxes on meshes crept. -->\n"
      << "  <option timestep=\"0.002\" gravity=\"0 0 -9.81\" cone=\"elliptic\" impratio=\"10\">\n"
      << "    <flag multiccd=\"enable\"/>\n"
      << "  </option>\n"
      << "  <size nconmax=\"" << summary.nconmax << "\" njmax=\"" << summary.njmax << "\"/>\n"
      << "  <default>\n"
      << "    <default class=\"building\"><geom contype=\"1\" conaffinity=\"1\" friction=\"" << Num(options.friction)
      << " 0.005 0.0001\" rgba=\"0.8 0.8 0.78 1\" solimp=\"0.95 0.99 0.001\" solref=\"0.005 1\"/></default>\n"
      << "    <default class=\"object\"><geom contype=\"1\" conaffinity=\"1\" density=\"" << Num(options.density)
      << "\" friction=\"" << Num(options.friction) << " 0.005 0.0001\" rgba=\"0.6 0.5 0.4 1\" solimp=\"0.95 0.99 0.001\" "
      << "solref=\"0.005 1\"/></default>\n"
      << "    <!-- A door leaf: 40 mm of wood and air (about 450 kg/m3, some 30 kg), hinges that damp its swing. -->\n"
      << "    <default class=\"door\"><geom contype=\"1\" conaffinity=\"1\" density=\"450\" friction=\"" << Num(options.friction)
      << " 0.005 0.0001\" rgba=\"0.55 0.38 0.22 1\" solimp=\"0.95 0.99 0.001\" solref=\"0.005 1\"/></default>\n"
      << "    <default class=\"hinge\"><joint damping=\"4\" armature=\"0.05\" frictionloss=\"0.2\"/></default>\n"
      << "  </default>\n"
      << "  <asset>\n" << assets.str() << "  </asset>\n"
      << "  <worldbody>\n"
      << "    <light pos=\"0 0 20\" dir=\"0 0 -1\" directional=\"true\"/>\n"
      << world.str() << "  </worldbody>\n"
      << "</mujoco>\n";
  if (Status s = WriteFileAtomic(dir / "villa.xml", xml.str()); !s) return Error{s.error()};
  return summary;
}

Status SetMjcfBuffers(const fs::path& xml, int nconmax, int njmax) {
  auto text = ReadFile(xml);
  if (!text.ok()) return Error{text.error()};
  const size_t at = text->find("  <size nconmax=\"");
  const size_t end = at == std::string::npos ? at : text->find("/>\n", at);
  if (end == std::string::npos) return Error{xml.string() + ": no <size nconmax=... njmax=.../> line (not written by villa?)"};
  text->replace(at, end + 3 - at,
                "  <size nconmax=\"" + std::to_string(nconmax) + "\" njmax=\"" + std::to_string(njmax) + "\"/>\n");
  return WriteFileAtomic(xml, *text);
}

}  // namespace villa::physics
