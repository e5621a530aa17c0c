#include "physics/mjcf.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "physics/glb_settle.h"
#include "util/atomic_file.h"

namespace villa::physics {
namespace {

namespace fs = std::filesystem;

// The triangles of each connected piece of `mesh` whose box is at least 0.1 mm thick every way (MuJoCo
// needs a volume).
std::vector<TriangleMesh> SolidPieces(const TriangleMesh& mesh) {
  std::vector<TriangleMesh> out;
  for (TriangleMesh& piece : SplitPieces(mesh)) {
    const Box3 b = piece.Bounds();
    if (b.max.x - b.min.x < 1e-4 || b.max.y - b.min.y < 1e-4 || b.max.z - b.min.z < 1e-4) continue;
    out.push_back(std::move(piece));
  }
  return out;
}

// A piece that is a box (8 corners, three perpendicular edges): MuJoCo collides box geoms at several
// points (two meshes touch at one, and rock), so box pieces (most of ours) are written as boxes.
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
  // A piece as a box geom when it is one, else as a mesh geom; `indent` and `origin` (the body's).
  auto add_geom = [&](std::ostringstream& out, const TriangleMesh& piece, const Vec3& origin, const std::string& indent,
                      const char* kind) -> Status {
    if (const std::optional<BoxFit> box = AsBox(piece)) {
      const Vec3 c = box->centre - origin;
      out << indent << "<geom type=\"box\" size=\"" << Num(box->half.x) << " " << Num(box->half.y) << " " << Num(box->half.z)
          << "\" pos=\"" << Num(c.x) << " " << Num(c.y) << " " << Num(c.z) << "\" xyaxes=\"" << Num(box->x.x) << " "
          << Num(box->x.y) << " " << Num(box->x.z) << " " << Num(box->y.x) << " " << Num(box->y.y) << " " << Num(box->y.z)
          << "\" class=\"" << kind << "\"/>\n";
      ++summary.boxes;
      return Status::Ok();
    }
    auto name = add_mesh(piece, origin);
    if (!name.ok()) return Error{name.error()};
    out << indent << "<geom type=\"mesh\" mesh=\"" << *name << "\" class=\"" << kind << "\"/>\n";
    return Status::Ok();
  };
  for (const TriangleMesh& m : scene->statics)
    for (const TriangleMesh& piece : SolidPieces(m)) {
      if (Status s = add_geom(world, piece, {0, 0, 0}, "    ", "building"); !s) return Error{s.error()};
      ++summary.static_geoms;
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
    for (const TriangleMesh& piece : pieces) {
      if (Status s = add_geom(world, piece, origin, "      ", "object"); !s) return Error{s.error()};
      ++summary.geoms;
    }
    world << "    </body>\n";
    ++summary.bodies;
  }
  std::ostringstream xml;
  xml << "<mujoco model=\"" << Xml(glb.stem().string()) << "\">\n"
      << "  <!-- Written by villa physics --mjcf from " << Xml(glb.filename().string()) << ": the building static, every\n"
      << "       object a body named by its scene id (a free joint unless hung or on a rail), one geom a convex part. -->\n"
      << "  <compiler meshdir=\"meshes\" angle=\"radian\"/>\n"
      << "  <!-- Elliptic friction cones and stiffer contacts than MuJoCo's defaults: with those, things held between\n"
      << "       two geoms (clothes between shelves) were squeezed out; here 96.5 % of a villa's objects stay. -->\n"
      << "  <option timestep=\"0.002\" gravity=\"0 0 -9.81\" cone=\"elliptic\" impratio=\"10\"/>\n"
      << "  <size nconmax=\"" << std::max(2000, 2 * (summary.geoms + summary.static_geoms)) << "\" njmax=\""
      << std::max(4000, 4 * (summary.geoms + summary.static_geoms)) << "\"/>\n"
      << "  <default>\n"
      << "    <default class=\"building\"><geom contype=\"1\" conaffinity=\"1\" friction=\"" << Num(options.friction)
      << " 0.005 0.0001\" rgba=\"0.8 0.8 0.78 1\" solimp=\"0.95 0.99 0.001\" solref=\"0.005 1\"/></default>\n"
      << "    <default class=\"object\"><geom contype=\"1\" conaffinity=\"1\" density=\"" << Num(options.density)
      << "\" friction=\"" << Num(options.friction) << " 0.005 0.0001\" rgba=\"0.6 0.5 0.4 1\" solimp=\"0.95 0.99 0.001\" "
      << "solref=\"0.005 1\"/></default>\n"
      << "  </default>\n"
      << "  <asset>\n" << assets.str() << "  </asset>\n"
      << "  <worldbody>\n"
      << "    <light pos=\"0 0 20\" dir=\"0 0 -1\" directional=\"true\"/>\n"
      << world.str() << "  </worldbody>\n"
      << "</mujoco>\n";
  if (Status s = WriteFileAtomic(dir / "villa.xml", xml.str()); !s) return Error{s.error()};
  return summary;
}

}  // namespace villa::physics
