#pragma once
// A small glTF 2.0 binary (.glb) writer: what villa's 3D files need and nothing more. Triangle meshes of
// one or more primitives (positions, unit normals where given (without, viewers shade flat), 32-bit
// indices), metallic-roughness materials by linear base colour factors, a node tree with names,
// TRS transforms, shared meshes (instancing: many chairs, one mesh) and `extras`, and the asset's extras
// (credits). The bytes depend only on the document, so equal documents give equal files.
//
// Frames: whatever the caller writes; villa writes glTF's +Y up (plan (x, y, z) -> (x, z, -y)).
// Colours: glTF's baseColorFactor is LINEAR; SrgbToLinear converts a palette's sRGB value.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace villa::gltf {

// One sRGB channel in [0, 1] to linear light (the sRGB transfer function inverted, IEC 61966-2-1).
double SrgbToLinear(double channel);
// And back (what a viewer's sRGB output does to a lit, linear colour).
double LinearToSrgb(double channel);

struct Material {
  std::string name;
  std::array<double, 4> base_color{0.8, 0.8, 0.8, 1.0};  // LINEAR r, g, b and alpha, [0, 1]
  double metallic = 0.0;
  double roughness = 0.9;
  bool blend = false;         // alphaMode BLEND (else OPAQUE)
  bool double_sided = false;
};

struct Primitive {
  std::vector<float> positions;     // x, y, z per vertex (file frame)
  std::vector<float> normals;       // empty, or a unit x, y, z per vertex (file frame): glTF's NORMAL
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise seen from outside
  int material = -1;                // index into Document::materials; -1: none
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;  // at least one, each with at least one triangle
};

struct Node {
  std::string name;
  int mesh = -1;                  // index into Document::meshes; -1: none
  std::vector<int> children;      // indices into Document::nodes
  std::optional<std::array<double, 3>> translation;
  std::optional<std::array<double, 4>> rotation;  // unit quaternion x, y, z, w
  std::optional<std::array<double, 3>> scale;
  nlohmann::ordered_json extras;  // written when not null
};

struct Document {
  std::string generator = "villa";
  nlohmann::ordered_json asset_extras;  // asset.extras, written when not null
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Node> nodes;
  std::vector<int> roots;  // the scene's root nodes
};

// The .glb bytes. Asserts on broken indices (a node naming a mesh that does not exist): the document is
// the program's, not outside input.
std::string WriteGlb(const Document& document);

}  // namespace villa::gltf
