#include "physics/mjcf.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "physics/glb_settle.h"
#include "util/atomic_file.h"

namespace villa::physics {
namespace {

namespace fs = std::filesystem;

// The triangles of each connected piece of `mesh` whose box is at least 0.1 mm thick every way (MuJoCo
// needs a volume).
std::vector<TriangleMesh> SolidPieces(const TriangleMesh& mesh) {
  const std::vector<int> root = PieceRoots(mesh);
  std::map<int, TriangleMesh> pieces;
  for (const auto& t : mesh.triangles) {
    TriangleMesh& piece = pieces[root[t[0]]];
    const int base = static_cast<int>(piece.vertices.size());
    for (int k = 0; k < 3; ++k) piece.vertices.push_back(mesh.vertices[t[k]]);
    piece.AddTriangle(base, base + 1, base + 2);
  }
  std::vector<TriangleMesh> out;
  for (auto& [r, piece] : pieces) {
    const Box3 b = piece.Bounds();
    if (b.max.x - b.min.x < 1e-4 || b.max.y - b.min.y < 1e-4 || b.max.z - b.min.z < 1e-4) continue;
    out.push_back(std::move(piece));
  }
  return out;
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
  for (const TriangleMesh& m : scene->statics)
    for (const TriangleMesh& piece : SolidPieces(m)) {
      auto name = add_mesh(piece, {0, 0, 0});
      if (!name.ok()) return Error{name.error()};
      world << "    <geom type=\"mesh\" mesh=\"" << *name << "\" class=\"building\"/>\n";
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
      auto name = add_mesh(piece, origin);
      if (!name.ok()) return Error{name.error()};
      world << "      <geom type=\"mesh\" mesh=\"" << *name << "\" class=\"object\"/>\n";
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
      << "  <option timestep=\"0.002\" gravity=\"0 0 -9.81\"/>\n"
      << "  <size nconmax=\"" << std::max(2000, 2 * (summary.geoms + summary.static_geoms)) << "\" njmax=\""
      << std::max(4000, 4 * (summary.geoms + summary.static_geoms)) << "\"/>\n"
      << "  <default>\n"
      << "    <default class=\"building\"><geom contype=\"1\" conaffinity=\"1\" friction=\"" << Num(options.friction)
      << " 0.005 0.0001\" rgba=\"0.8 0.8 0.78 1\"/></default>\n"
      << "    <default class=\"object\"><geom contype=\"1\" conaffinity=\"1\" density=\"" << Num(options.density)
      << "\" friction=\"" << Num(options.friction) << " 0.005 0.0001\" rgba=\"0.6 0.5 0.4 1\"/></default>\n"
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
