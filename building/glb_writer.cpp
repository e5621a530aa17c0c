#include "building/glb_writer.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace villa::gltf {
namespace {

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// Six decimals: 1 µm in metres, 1e-6 in colour; keeps the JSON short and the same on every machine.
double Round6(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0.0 ? 0.0 : r;  // no "-0.0"
}

void PutU32(std::string& out, std::uint32_t v) {
  char b[4];
  std::memcpy(b, &v, 4);  // glTF is little-endian, as every machine villa builds on
  out.append(b, 4);
}

template <class T>
void Append(std::string& bin, const std::vector<T>& values) {
  bin.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

nlohmann::ordered_json Array(const std::array<double, 3>& a) { return {Round6(a[0]), Round6(a[1]), Round6(a[2])}; }

}  // namespace

double SrgbToLinear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double LinearToSrgb(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

std::string WriteGlb(const Document& doc) {
  using Json = nlohmann::ordered_json;
  Json root;
  root["asset"] = {{"version", "2.0"}, {"generator", doc.generator}};
  if (!doc.asset_extras.is_null()) root["asset"]["extras"] = doc.asset_extras;
  root["scene"] = 0;
  root["scenes"] = Json::array({Json{{"nodes", doc.roots}}});

  Json nodes = Json::array();
  for (const Node& n : doc.nodes) {
    Json j;
    if (!n.name.empty()) j["name"] = n.name;
    if (n.mesh >= 0) {
      assert(n.mesh < static_cast<int>(doc.meshes.size()) && "node names a mesh that does not exist");
      j["mesh"] = n.mesh;
    }
    if (!n.children.empty()) j["children"] = n.children;
    if (n.translation) j["translation"] = Array(*n.translation);
    if (n.rotation) {
      const auto& q = *n.rotation;
      const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      j["rotation"] = {Round6(q[0] / norm), Round6(q[1] / norm), Round6(q[2] / norm), Round6(q[3] / norm)};
    }
    if (n.scale) j["scale"] = Array(*n.scale);
    if (!n.extras.is_null()) j["extras"] = n.extras;
    nodes.push_back(std::move(j));
  }
  root["nodes"] = std::move(nodes);

  if (!doc.materials.empty()) {
    Json materials = Json::array();
    for (const Material& m : doc.materials) {
      Json j;
      j["name"] = m.name;
      j["pbrMetallicRoughness"] = {{"baseColorFactor",
                                    {Round6(m.base_color[0]), Round6(m.base_color[1]), Round6(m.base_color[2]),
                                     Round6(m.base_color[3])}},
                                   {"metallicFactor", Round6(m.metallic)},
                                   {"roughnessFactor", Round6(m.roughness)}};
      if (m.blend) j["alphaMode"] = "BLEND";
      if (m.double_sided) j["doubleSided"] = true;
      materials.push_back(std::move(j));
    }
    root["materials"] = std::move(materials);
  }

  // The binary chunk: per primitive its positions, then its indices (both 4-byte aligned by size).
  std::string bin;
  Json meshes = Json::array(), accessors = Json::array(), views = Json::array();
  for (const Mesh& mesh : doc.meshes) {
    Json primitives = Json::array();
    for (const Primitive& p : mesh.primitives) {
      assert(p.positions.size() % 3 == 0 && !p.indices.empty() && p.indices.size() % 3 == 0);
      assert(p.material < static_cast<int>(doc.materials.size()));
      const size_t vertices = p.positions.size() / 3;
      std::array<float, 3> lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
      std::array<float, 3> hi{-lo[0], -lo[1], -lo[2]};
      for (size_t v = 0; v < vertices; ++v)
        for (int k = 0; k < 3; ++k) {
          lo[k] = std::min(lo[k], p.positions[3 * v + k]);
          hi[k] = std::max(hi[k], p.positions[3 * v + k]);
        }
      views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", p.positions.size() * 4}, {"target", kArrayBuffer}});
      Append(bin, p.positions);
      // min and max are the floats' own values, so the validator finds them exact.
      accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", kFloat}, {"count", vertices}, {"type", "VEC3"},
                           {"min", {double(lo[0]), double(lo[1]), double(lo[2])}},
                           {"max", {double(hi[0]), double(hi[1]), double(hi[2])}}});
      const size_t position_accessor = accessors.size() - 1;
      assert((p.normals.empty() || p.normals.size() == p.positions.size()) && "one normal per vertex");
      std::optional<size_t> normal_accessor;
      if (!p.normals.empty()) {
        views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", p.normals.size() * 4}, {"target", kArrayBuffer}});
        Append(bin, p.normals);
        accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", kFloat}, {"count", vertices}, {"type", "VEC3"}});
        normal_accessor = accessors.size() - 1;
      }
      assert(std::all_of(p.indices.begin(), p.indices.end(), [&](std::uint32_t i) { return i < vertices; }) &&
             "index beyond the primitive's vertices");
      views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", p.indices.size() * 4}, {"target", kElementArrayBuffer}});
      Append(bin, p.indices);
      accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", kUnsignedInt}, {"count", p.indices.size()}, {"type", "SCALAR"}});
      Json prim{{"attributes", {{"POSITION", position_accessor}}}, {"indices", accessors.size() - 1}};
      if (normal_accessor) prim["attributes"]["NORMAL"] = *normal_accessor;
      if (p.material >= 0) prim["material"] = p.material;
      primitives.push_back(std::move(prim));
    }
    Json m;
    if (!mesh.name.empty()) m["name"] = mesh.name;
    m["primitives"] = std::move(primitives);
    meshes.push_back(std::move(m));
  }
  if (!meshes.empty()) {
    root["meshes"] = std::move(meshes);
    root["accessors"] = std::move(accessors);
    root["bufferViews"] = std::move(views);
    root["buffers"] = Json::array({Json{{"byteLength", bin.size()}}});
  }

  std::string json = root.dump();
  while (json.size() % 4 != 0) json.push_back(' ');
  while (bin.size() % 4 != 0) bin.push_back('\0');
  const bool has_bin = !bin.empty();
  std::string out = "glTF";
  PutU32(out, 2);
  PutU32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + (has_bin ? 8 + bin.size() : 0)));
  PutU32(out, static_cast<std::uint32_t>(json.size()));
  out += "JSON";
  out += json;
  if (has_bin) {
    PutU32(out, static_cast<std::uint32_t>(bin.size()));
    out += std::string("BIN\0", 4);
    out += bin;
  }
  return out;
}

}  // namespace villa::gltf
