#include "assets/obj_model.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "mesh/triangulate.h"
#include "util/excerpt.h"

namespace villa {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Splits a line into blank-separated tokens (views into the line).
void Tokens(std::string_view line, std::vector<std::string_view>* out) {
  out->clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && IsSpace(line[i])) ++i;
    std::size_t start = i;
    while (i < line.size() && !IsSpace(line[i])) ++i;
    if (i > start) out->push_back(line.substr(start, i - start));
  }
}

bool Number(std::string_view token, double* out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), *out);
  return ec == std::errc() && end == token.data() + token.size() && std::isfinite(*out);
}

bool Integer(std::string_view token, long* out) {
  auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), *out);
  return ec == std::errc() && end == token.data() + token.size();
}

// The rest of a line after its keyword (a name that may hold blanks, e.g. a material or file name).
std::string_view Rest(std::string_view line, std::string_view keyword) {
  std::size_t at = line.find(keyword);
  std::string_view rest = line.substr(at + keyword.size());
  while (!rest.empty() && IsSpace(rest.front())) rest.remove_prefix(1);
  while (!rest.empty() && IsSpace(rest.back())) rest.remove_suffix(1);
  return rest;
}

// Calls `statement(line, tokens)` for each line that holds anything once its comment is cut off; the
// first message it returns ends the reading, as "<where>:<line>: <message>".
template <class Statement>
Status ForEachStatement(std::string_view text, const std::string& where, Statement&& statement) {
  std::vector<std::string_view> tokens;
  int line_number = 0;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    at = end + 1;
    ++line_number;
    line = line.substr(0, line.find('#'));
    Tokens(line, &tokens);
    if (tokens.empty()) continue;
    if (std::string problem = statement(line, tokens); !problem.empty())
      return Error{where + ":" + std::to_string(line_number) + ": " + problem};
  }
  return {};
}

// Triangulates one polygon (indices into `positions`), appending counter-clockwise triangles in the
// polygon's own winding. Convex polygons are fanned; others are ear-clipped in their best-fit plane.
void TriangulateFace(const std::vector<Vec3>& positions, std::vector<int> face,
                     std::vector<std::array<int, 3>>* out) {
  // Drop repeated consecutive corners (they make zero-area triangles).
  std::vector<int> clean;
  for (int v : face)
    if (clean.empty() || positions[clean.back()] != positions[v]) clean.push_back(v);
  while (clean.size() > 1 && positions[clean.front()] == positions[clean.back()]) clean.pop_back();
  if (clean.size() < 3) return;
  if (clean.size() == 3) {
    out->push_back({clean[0], clean[1], clean[2]});
    return;
  }
  // Newell's normal, then the plane's axes.
  Vec3 n{};
  for (std::size_t i = 0; i < clean.size(); ++i) {
    Vec3 a = positions[clean[i]], b = positions[clean[(i + 1) % clean.size()]];
    n = n + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  if (Norm(n) == 0.0) {
    for (std::size_t i = 1; i + 1 < clean.size(); ++i) out->push_back({clean[0], clean[i], clean[i + 1]});
    return;
  }
  n = Normalized(n);
  Vec3 u = std::abs(n.x) < 0.9 ? Normalized(Cross({1, 0, 0}, n)) : Normalized(Cross({0, 1, 0}, n));
  Vec3 v = Cross(n, u);
  Ring ring;
  for (int i : clean) ring.push_back({Dot(positions[i], u), Dot(positions[i], v)});
  // In (u, v) the polygon runs counter-clockwise (n is its Newell normal), as TriangulatePolygon wants.
  bool convex = true;
  for (std::size_t i = 0; i < ring.size() && convex; ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % ring.size()];
    const Point& c = ring[(i + 2) % ring.size()];
    convex = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) >= 0.0;
  }
  if (!convex) {
    std::vector<std::array<int, 3>> tris = TriangulatePolygon(ring);
    if (tris.size() == ring.size() - 2) {
      for (const auto& t : tris) out->push_back({clean[t[0]], clean[t[1]], clean[t[2]]});
      return;
    }
  }
  for (std::size_t i = 1; i + 1 < clean.size(); ++i) out->push_back({clean[0], clean[i], clean[i + 1]});
}

}  // namespace

int ObjModel::TriangleCount() const {
  int n = 0;
  for (const Group& g : groups) n += static_cast<int>(g.triangles.size());
  return n;
}

Result<ObjModel> ParseObj(std::string_view text, const std::string& where) {
  ObjModel model;
  std::map<std::string, int> group_of;
  int current = -1;
  std::vector<int> face;
  Status read = ForEachStatement(text, where, [&](std::string_view line, const std::vector<std::string_view>& tokens) -> std::string {
    std::string_view key = tokens[0];
    if (key == "v") {
      if (tokens.size() < 4) return "vertex needs 3 coordinates: " + Excerpt(line);
      Vec3 p;
      if (!Number(tokens[1], &p.x) || !Number(tokens[2], &p.y) || !Number(tokens[3], &p.z))
        return "vertex coordinates must be finite numbers: " + Excerpt(line);
      model.positions.push_back(p);
    } else if (key == "f") {
      face.clear();
      for (std::size_t i = 1; i < tokens.size(); ++i) {
        std::string_view corner = tokens[i].substr(0, tokens[i].find('/'));
        long index = 0;
        if (!Integer(corner, &index) || index == 0) return "bad face corner '" + Excerpt(tokens[i]) + "'";
        long count = static_cast<long>(model.positions.size());
        long resolved = index > 0 ? index - 1 : count + index;  // negative: relative to the latest vertex
        if (resolved < 0 || resolved >= count)
          return "face index " + std::to_string(index) + " out of range (" + std::to_string(count) + " vertices)";
        face.push_back(static_cast<int>(resolved));
      }
      if (face.size() < 3) {  // a "face" of one or two corners is a point or a line: nothing to draw
        ++model.degenerate_faces;
        return "";
      }
      if (current < 0) {
        group_of[""] = 0;
        model.groups.push_back({"", {}});
        current = 0;
      }
      ++model.faces;
      TriangulateFace(model.positions, face, &model.groups[current].triangles);
    } else if (key == "usemtl") {
      std::string name(Rest(line, "usemtl"));
      auto [it, inserted] = group_of.try_emplace(name, static_cast<int>(model.groups.size()));
      if (inserted) model.groups.push_back({name, {}});
      current = it->second;
    } else if (key == "mtllib") {
      for (std::size_t i = 1; i < tokens.size(); ++i) model.material_libraries.emplace_back(tokens[i]);
    }
    return "";
  });
  if (!read.ok()) return Error{read.error()};
  std::erase_if(model.groups, [](const ObjModel::Group& g) { return g.triangles.empty(); });
  return model;
}

Result<std::vector<ObjMaterial>> ParseMtl(std::string_view text, const std::string& where) {
  std::vector<ObjMaterial> materials;
  Status read = ForEachStatement(text, where, [&](std::string_view line, const std::vector<std::string_view>& tokens) -> std::string {
    std::string_view key = tokens[0];
    if (key == "newmtl") {
      materials.push_back({});
      materials.back().name = std::string(Rest(line, "newmtl"));
      return "";
    }
    if (materials.empty()) {
      if (key == "Kd" || key == "d" || key == "Tr" || key == "map_Kd") return std::string(key) + " before any newmtl";
      return "";
    }
    ObjMaterial& m = materials.back();
    if (key == "Kd") {
      if (tokens.size() < 2) return "Kd needs a colour: " + Excerpt(line);
      if (tokens[1] == "spectral" || tokens[1] == "xyz") return "";  // rare forms: keep the default colour
      for (int i = 0; i < 3; ++i) {
        std::string_view t = tokens.size() > static_cast<std::size_t>(i + 1) ? tokens[i + 1] : tokens[1];  // "Kd r" = grey
        if (!Number(t, &m.diffuse[i])) return "Kd must be numbers: " + Excerpt(line);
        m.diffuse[i] = std::clamp(m.diffuse[i], 0.0, 1.0);
      }
    } else if (key == "d" || key == "Tr") {
      double value = 1.0;
      std::string_view t = tokens.size() > 1 ? tokens.back() : std::string_view{};
      if (!Number(t, &value)) return std::string(key) + " must be a number: " + Excerpt(line);
      value = std::clamp(value, 0.0, 1.0);
      m.alpha = key == "d" ? value : 1.0 - value;
    } else if (key == "map_Kd") {
      // Options (-s 1 1 1, -clamp on, ...) come first; the file name is the last token.
      if (tokens.size() < 2) return "map_Kd needs a file name";
      m.diffuse_texture = std::string(tokens.back());
    }
    return "";
  });
  if (!read.ok()) return Error{read.error()};
  return materials;
}

}  // namespace villa
