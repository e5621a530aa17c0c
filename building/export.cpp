#include "building/export.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/metadata.h>
#include <assimp/scene.h>

#include <cstring>
#include <fstream>
#include <functional>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <memory>

#include <nlohmann/json.hpp>

#include "building/glb_writer.h"
#include "building/materials.h"
#include "util/atomic_file.h"

namespace villa {
namespace {

aiVector3D ToGltf(const Vec3& p) {
  return aiVector3D(static_cast<float>(p.x), static_cast<float>(p.z), static_cast<float>(-p.y));
}

aiNode* NewNode(const std::string& name, aiNode* parent) {
  auto* node = new aiNode(name);
  node->mParent = parent;
  return node;
}

void SetChildren(aiNode* node, const std::vector<aiNode*>& children) {
  if (children.empty()) return;
  node->mNumChildren = static_cast<unsigned>(children.size());
  node->mChildren = new aiNode*[children.size()];
  for (size_t i = 0; i < children.size(); ++i) {
    node->mChildren[i] = children[i];
    children[i]->mParent = node;
  }
}

// The whole scene. aiScene's destructor frees everything allocated here.
std::unique_ptr<aiScene> MakeScene(const BuildingMesh& building) {
  auto scene = std::make_unique<aiScene>();
  // Materials, one per distinct look, in order of first use.
  std::vector<PartMaterial> materials;
  std::map<std::string, unsigned> material_index;
  std::vector<unsigned> part_material;
  for (const MeshPart& part : building.parts) {
    PartMaterial m = MaterialOf(part, building.style);
    auto [it, added] = material_index.emplace(m.name, static_cast<unsigned>(materials.size()));
    if (added) materials.push_back(m);
    part_material.push_back(it->second);
  }
  scene->mNumMaterials = static_cast<unsigned>(materials.size());
  scene->mMaterials = new aiMaterial*[materials.size()];
  for (size_t i = 0; i < materials.size(); ++i) {
    const PartMaterial& m = materials[i];
    auto* mat = new aiMaterial();
    aiString name(m.name);
    mat->AddProperty(&name, AI_MATKEY_NAME);
    aiColor4D color(static_cast<float>(m.color.r), static_cast<float>(m.color.g), static_cast<float>(m.color.b),
                    static_cast<float>(m.alpha));
    aiColor3D diffuse(color.r, color.g, color.b);
    mat->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
    mat->AddProperty(&color, 1, AI_MATKEY_BASE_COLOR);
    float metallic = static_cast<float>(m.metallic), roughness = static_cast<float>(m.roughness);
    mat->AddProperty(&metallic, 1, AI_MATKEY_METALLIC_FACTOR);
    mat->AddProperty(&roughness, 1, AI_MATKEY_ROUGHNESS_FACTOR);
    if (m.alpha < 1.0) {
      color.a = 1.0f;  // the exporter multiplies the base colour's alpha by the opacity
      mat->AddProperty(&color, 1, AI_MATKEY_BASE_COLOR);
      float opacity = static_cast<float>(m.alpha);
      mat->AddProperty(&opacity, 1, AI_MATKEY_OPACITY);
      aiString blend("BLEND");
      mat->AddProperty(&blend, AI_MATKEY_GLTF_ALPHAMODE);
      int two_sided = 1;
      mat->AddProperty(&two_sided, 1, AI_MATKEY_TWOSIDED);
    }
    scene->mMaterials[i] = mat;
  }
  // Meshes, one per part.
  scene->mNumMeshes = static_cast<unsigned>(building.parts.size());
  scene->mMeshes = new aiMesh*[building.parts.size()];
  for (size_t i = 0; i < building.parts.size(); ++i) {
    const TriangleMesh& src = building.parts[i].mesh;
    auto* mesh = new aiMesh();
    mesh->mName = aiString(building.parts[i].name);
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mMaterialIndex = part_material[i];
    mesh->mNumVertices = static_cast<unsigned>(src.vertices.size());
    mesh->mVertices = new aiVector3D[src.vertices.size()];
    for (size_t v = 0; v < src.vertices.size(); ++v) mesh->mVertices[v] = ToGltf(src.vertices[v]);
    mesh->mNumFaces = static_cast<unsigned>(src.triangles.size());
    mesh->mFaces = new aiFace[src.triangles.size()];
    for (size_t f = 0; f < src.triangles.size(); ++f) {
      aiFace& face = mesh->mFaces[f];
      face.mNumIndices = 3;
      face.mIndices = new unsigned[3];
      for (int k = 0; k < 3; ++k) face.mIndices[k] = static_cast<unsigned>(src.triangles[f][k]);
    }
    scene->mMeshes[i] = mesh;
  }
  // Nodes.
  std::map<std::string, double> room_area;
  for (const BuiltRoom& r : building.rooms) room_area[r.name] = r.area;
  auto* root = new aiNode("villa");
  scene->mRootNode = root;
  std::vector<aiNode*> level_nodes;
  for (int level = 0; level < building.levels; ++level) {
    aiNode* level_node = NewNode("level_" + std::to_string(level), root);
    std::vector<aiNode*> children;
    std::map<std::string, std::vector<aiNode*>> groups;
    const std::string suffix = "_" + std::to_string(level);
    for (size_t i = 0; i < building.parts.size(); ++i) {
      const MeshPart& part = building.parts[i];
      if (part.level != level) continue;
      aiNode* node = NewNode(part.name, nullptr);
      node->mNumMeshes = 1;
      node->mMeshes = new unsigned[1]{static_cast<unsigned>(i)};
      switch (part.kind) {
        case PartKind::kFloor: {
          node->mMetaData = aiMetadata::Alloc(4);
          node->mMetaData->Set(0, "category", aiString(std::string(CategoryName(part.category))));
          node->mMetaData->Set(1, "area_m2", room_area[part.name]);
          node->mMetaData->Set(2, "level", static_cast<int32_t>(level));
          node->mMetaData->Set(3, "part", aiString(std::string("floor")));
          children.push_back(node);
          break;
        }
        case PartKind::kRoof: children.push_back(node); break;
        case PartKind::kTerrace: groups["terraces" + suffix].push_back(node); break;
        case PartKind::kExteriorWall:
        case PartKind::kInteriorWall: groups["walls" + suffix].push_back(node); break;
        case PartKind::kDoorLeaf: groups["doors" + suffix].push_back(node); break;
        case PartKind::kWindowGlass:
        case PartKind::kWindowFrame: groups["windows" + suffix].push_back(node); break;
        case PartKind::kStair: groups["stairs" + suffix].push_back(node); break;
        case PartKind::kRailing: groups["railings" + suffix].push_back(node); break;
      }
    }
    for (const char* group : {"walls", "doors", "windows", "stairs", "railings", "terraces"}) {
      auto it = groups.find(group + suffix);
      if (it == groups.end()) continue;
      aiNode* g = NewNode(it->first, nullptr);
      SetChildren(g, it->second);
      children.push_back(g);
    }
    SetChildren(level_node, children);
    level_nodes.push_back(level_node);
  }
  SetChildren(root, level_nodes);
  return scene;
}

Vec3 ToGltfFrame(const Vec3& p) { return {p.x, p.z, -p.y}; }

// Furniture's normals where faces meet at this angle or less shade smooth (issue 31): a 12-sided lamp
// shade (30 degrees) is round, a box (90) keeps its edges. The building is all flat faces (a stair's soffit
// meets its landing at 35 degrees, a slab's edge turns 30 at an angled wall): only coplanar faces share.
constexpr double kFurnitureCreaseDeg = 40.0;
constexpr double kBuildingCreaseDeg = 0.5;

// A primitive of these triangles in the file's frame, with vertex normals (ShadeSmooth).
gltf::Primitive ShadedPrimitive(const TriangleMesh& mesh, double crease_deg) {
  const ShadedMesh shaded = ShadeSmooth(mesh, crease_deg);
  gltf::Primitive p;
  p.positions.reserve(3 * shaded.vertices.size());
  p.normals.reserve(3 * shaded.vertices.size());
  for (size_t v = 0; v < shaded.vertices.size(); ++v) {
    const Vec3 g = ToGltfFrame(shaded.vertices[v]), n = ToGltfFrame(shaded.normals[v]);
    p.positions.insert(p.positions.end(), {static_cast<float>(g.x), static_cast<float>(g.y), static_cast<float>(g.z)});
    p.normals.insert(p.normals.end(), {static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z)});
  }
  for (const auto& t : shaded.triangles)
    for (int k = 0; k < 3; ++k) p.indices.push_back(static_cast<std::uint32_t>(t[k]));
  return p;
}

// A building part's triangles split into its own material and, for floor slabs and terraces, the steep
// faces (|n_z| < 0.5: the slab's edges) in the exterior wall's material.
struct PartPrimitives {
  gltf::Primitive main;
  gltf::Primitive edges;
  gltf::Primitive below;   // a floor slab's underside: the ceiling of the room below
  gltf::Primitive treads;  // a stair's walking faces (up-facing), in the floor's wood
};
PartPrimitives SplitPart(const MeshPart& part) {
  const bool slab = part.kind == PartKind::kFloor || part.kind == PartKind::kTerrace;
  TriangleMesh main, edges, below, treads;
  std::vector<int> main_index(part.mesh.vertices.size(), -1), edge_index(part.mesh.vertices.size(), -1),
      below_index(part.mesh.vertices.size(), -1), tread_index(part.mesh.vertices.size(), -1);
  auto add = [&](TriangleMesh& m, std::vector<int>& index, int v) {
    if (index[v] < 0) {
      index[v] = static_cast<int>(m.vertices.size());
      m.vertices.push_back(part.mesh.vertices[v]);
    }
    return index[v];
  };
  for (const auto& t : part.mesh.triangles) {
    const Vec3 &a = part.mesh.vertices[t[0]], &b = part.mesh.vertices[t[1]], &c = part.mesh.vertices[t[2]];
    const Vec3 n = Cross(b - a, c - a);
    const double len = Norm(n);
    const bool steep = slab && len > 0.0 && std::abs(n.z) < 0.5 * len;
    const bool down = part.kind == PartKind::kFloor && !steep && n.z < 0.0;
    const bool tread = part.kind == PartKind::kStair && len > 0.0 && n.z > 0.9 * len;
    TriangleMesh& m = steep ? edges : down ? below : tread ? treads : main;
    std::vector<int>& index = steep ? edge_index : down ? below_index : tread ? tread_index : main_index;
    m.AddTriangle(add(m, index, t[0]), add(m, index, t[1]), add(m, index, t[2]));
  }
  PartPrimitives out;
  if (!main.triangles.empty()) out.main = ShadedPrimitive(main, kBuildingCreaseDeg);
  if (!edges.triangles.empty()) out.edges = ShadedPrimitive(edges, kBuildingCreaseDeg);
  if (!below.triangles.empty()) out.below = ShadedPrimitive(below, kBuildingCreaseDeg);
  if (!treads.triangles.empty()) out.treads = ShadedPrimitive(treads, kBuildingCreaseDeg);
  return out;
}

// One glTF material per distinct look, the sRGB colour written linear, metals as PbrByName reads their
// names; each name once (a second look under a name already taken is "glass-2").
class MaterialTable {
 public:
  // `open`: the part is a sheet, not a closed solid (a leaf, a curtain, a picture's face): its back faces
  // are drawn too, else it vanishes from behind (issue 31); closed solids keep back-face culling.
  int Of(const PartMaterial& given, bool open = false) {
    const PartMaterial m = PbrByName(given);
    const std::string key = m.name + "|" + std::to_string(m.color.r) + "," + std::to_string(m.color.g) + "," +
                            std::to_string(m.color.b) + "," + std::to_string(m.alpha) + "," + std::to_string(m.roughness) +
                            (open ? "|open" : "");
    auto [it, added] = index_.emplace(key, static_cast<int>(materials_.size()));
    if (added) {
      gltf::Material g;
      g.name = m.name;
      for (int n = 2; !names_.insert(g.name).second; ++n) g.name = m.name + "-" + std::to_string(n);
      g.base_color = {gltf::SrgbToLinear(m.color.r), gltf::SrgbToLinear(m.color.g), gltf::SrgbToLinear(m.color.b), m.alpha};
      g.roughness = m.roughness;
      g.metallic = m.metallic;
      g.blend = m.alpha < 1.0;
      g.double_sided = m.alpha < 1.0 || open;  // glass is seen from both sides
      materials_.push_back(g);
    }
    return it->second;
  }
  std::vector<gltf::Material> Take() { return std::move(materials_); }

 private:
  std::map<std::string, int> index_;
  std::set<std::string> names_;
  std::vector<gltf::Material> materials_;
};

PartMaterial ExteriorWallMaterial(std::string_view style) {
  MeshPart wall;
  wall.kind = PartKind::kExteriorWall;
  return MaterialOf(wall, style);
}

}  // namespace

Result<std::string> BuildingToGlb(const BuildingMesh& building, const ExportFurniture* furniture) {
  gltf::Document doc;
  MaterialTable materials;
  const PartMaterial facade = ExteriorWallMaterial(building.style);
  auto named = [](const std::string& name) { return nlohmann::ordered_json{{"name", name}}; };
  auto add_node = [&](gltf::Node node) {
    doc.nodes.push_back(std::move(node));
    return static_cast<int>(doc.nodes.size()) - 1;
  };

  // One mesh per building part, in part order.
  std::vector<int> part_mesh(building.parts.size(), -1);
  for (size_t i = 0; i < building.parts.size(); ++i) {
    const MeshPart& part = building.parts[i];
    PartPrimitives split = SplitPart(part);
    gltf::Mesh mesh;
    mesh.name = part.name;
    if (!split.main.indices.empty()) {
      split.main.material = materials.Of(MaterialOf(part, building.style));
      mesh.primitives.push_back(std::move(split.main));
    }
    if (!split.edges.indices.empty()) {
      split.edges.material = materials.Of(facade);
      mesh.primitives.push_back(std::move(split.edges));
    }
    if (!split.below.indices.empty()) {
      split.below.material = materials.Of(CeilingMaterial());
      mesh.primitives.push_back(std::move(split.below));
    }
    if (!split.treads.indices.empty()) {
      split.treads.material = materials.Of(StairTreadMaterial(building.style));
      mesh.primitives.push_back(std::move(split.treads));
    }
    if (mesh.primitives.empty()) continue;
    part_mesh[i] = static_cast<int>(doc.meshes.size());
    doc.meshes.push_back(std::move(mesh));
  }

  // Furniture meshes: one per asset, in the asset frame turned to +Y up.
  std::vector<int> asset_mesh;
  if (furniture) {
    for (const ExportAssetMesh& asset : furniture->meshes) {
      gltf::Mesh mesh;
      mesh.name = asset.name;
      for (const ExportAssetMesh::Part& part : asset.parts) {
        if (!part.mesh || part.mesh->triangles.empty()) continue;
        gltf::Primitive p = ShadedPrimitive(*part.mesh, kFurnitureCreaseDeg);
        p.material = materials.Of(part.material, !CheckSolid(*part.mesh, 1e-6).closed);
        mesh.primitives.push_back(std::move(p));
      }
      asset_mesh.push_back(mesh.primitives.empty() ? -1 : static_cast<int>(doc.meshes.size()));
      if (!mesh.primitives.empty()) doc.meshes.push_back(std::move(mesh));
    }
  }

  std::map<std::string, const BuiltRoom*> rooms;
  for (const BuiltRoom& r : building.rooms) rooms[r.name] = &r;
  std::map<std::string, int> room_node;
  std::vector<int> level_nodes;
  for (int level = 0; level < building.levels; ++level) {
    std::vector<int> children;
    std::map<std::string, std::vector<int>> groups;
    const std::string suffix = "_" + std::to_string(level);
    for (size_t i = 0; i < building.parts.size(); ++i) {
      const MeshPart& part = building.parts[i];
      if (part.level != level || part_mesh[i] < 0) continue;
      gltf::Node node;
      node.name = part.name;
      node.mesh = part_mesh[i];
      node.extras = named(part.name);
      if (part.kind == PartKind::kFloor) {
        auto r = rooms.find(part.name);
        node.extras["category"] = std::string(CategoryName(part.category));
        if (r != rooms.end()) node.extras["area_m2"] = std::round(r->second->area * 100.0) / 100.0;
        node.extras["level"] = level;
      }
      if (part.hinge) {
        // The leaf's hinge for a simulator (BUILDING.md): a vertical axis (+Y) through (hinge_x, hinge_z) in
        // the file's frame, and the turns about it (degrees, right-handed about +Y) to closed and to open.
        const Vec3 at = ToGltfFrame({part.hinge->at.x, part.hinge->at.y, 0.0});
        node.extras["part"] = "door";
        node.extras["hinge_x"] = std::round(at.x * 1e4) / 1e4;
        node.extras["hinge_z"] = std::round(at.z * 1e4) / 1e4;
        node.extras["closed_deg"] = std::round(part.hinge->to_closed * 180.0 / std::numbers::pi * 100.0) / 100.0;
        node.extras["open_deg"] = std::round(part.hinge->to_open * 180.0 / std::numbers::pi * 100.0) / 100.0;
      }
      const int index = add_node(std::move(node));
      switch (part.kind) {
        case PartKind::kFloor:
          room_node[part.name] = index;
          children.push_back(index);
          break;
        case PartKind::kRoof: children.push_back(index); break;
        case PartKind::kTerrace: groups["terraces" + suffix].push_back(index); break;
        case PartKind::kExteriorWall:
        case PartKind::kInteriorWall: groups["walls" + suffix].push_back(index); break;
        case PartKind::kDoorLeaf: groups["doors" + suffix].push_back(index); break;
        case PartKind::kWindowGlass:
        case PartKind::kWindowFrame: groups["windows" + suffix].push_back(index); break;
        case PartKind::kStair: groups["stairs" + suffix].push_back(index); break;
        case PartKind::kRailing: groups["railings" + suffix].push_back(index); break;
      }
    }
    for (const char* group : {"walls", "doors", "windows", "stairs", "railings", "terraces"}) {
      auto it = groups.find(group + suffix);
      if (it == groups.end()) continue;
      gltf::Node g;
      g.name = it->first;
      g.children = it->second;
      g.extras = named(it->first);
      children.push_back(add_node(std::move(g)));
    }
    gltf::Node level_node;
    level_node.name = "level_" + std::to_string(level);
    level_node.children = children;
    level_node.extras = named(level_node.name);
    level_node.extras["level"] = level;
    level_nodes.push_back(add_node(std::move(level_node)));
  }

  // Objects under their rooms: the node maps the asset frame into the world, both written +Y up, so its
  // transform is the pose conjugated by the frame map: translation (x, z, -y), a turn about +Y by the
  // yaw, scale (sx, sz, sy).
  if (furniture) {
    for (const ExportObject& o : furniture->objects) {
      auto room = room_node.find(o.room);
      if (room == room_node.end()) return Error{"object " + o.name + ": room " + o.room + " is not in the building"};
      if (o.mesh < 0 || o.mesh >= static_cast<int>(asset_mesh.size()))
        return Error{"object " + o.name + ": mesh " + std::to_string(o.mesh) + " does not exist"};
      gltf::Node node;
      node.name = o.name;
      node.mesh = asset_mesh[o.mesh];
      node.translation = std::array<double, 3>{o.position.x, o.position.z, -o.position.y};
      if (o.yaw != 0.0) node.rotation = std::array<double, 4>{0.0, std::sin(o.yaw / 2.0), 0.0, std::cos(o.yaw / 2.0)};
      if (!(o.scale == Vec3{1.0, 1.0, 1.0})) node.scale = std::array<double, 3>{o.scale.x, o.scale.z, o.scale.y};
      node.extras = named(o.name);
      for (auto it = o.extras.begin(); it != o.extras.end(); ++it)
        if (it.key() != "name") node.extras[it.key()] = it.value();
      const int index = add_node(std::move(node));  // may grow doc.nodes: take the room's node after it
      doc.nodes[room->second].children.push_back(index);
    }
    doc.asset_extras = furniture->asset_extras;
  }

  gltf::Node root;
  root.name = "villa";
  root.children = level_nodes;
  root.extras = named("villa");
  doc.roots = {add_node(std::move(root))};
  doc.materials = materials.Take();
  return gltf::WriteGlb(doc);
}

std::optional<MeshFormat> ParseMeshFormat(std::string_view name) {
  if (name == "glb") return MeshFormat::kGlb;
  if (name == "obj") return MeshFormat::kObj;
  return std::nullopt;
}

Status ExportBuilding(const BuildingMesh& building, const std::filesystem::path& out, MeshFormat format) {
  std::filesystem::path folder = out.parent_path().empty() ? std::filesystem::path(".") : out.parent_path();
  if (!std::filesystem::is_directory(folder)) return Error{out.string() + ": folder " + folder.string() + " does not exist"};
  if (format == MeshFormat::kGlb) {
    auto bytes = BuildingToGlb(building);
    if (!bytes) return Error{out.string() + ": " + bytes.error()};
    return WriteFileAtomic(out, *bytes);
  }
  // OBJ: the exporter gives the .obj and the .mtl it names as blobs; each is written atomically.
  auto scene = MakeScene(building);
  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), "obj");
  if (!blob) return Error{out.string() + ": OBJ export failed: " + exporter.GetErrorString()};
  std::string obj(static_cast<const char*>(blob->data), blob->size);
  std::filesystem::path mtl_path = out;
  mtl_path.replace_extension(".mtl");
  // The exporter refers to its material library by a placeholder name; point it at the real file.
  std::string mtl_line = "mtllib " + mtl_path.filename().string() + "\n";
  if (auto pos = obj.find("mtllib "); pos != std::string::npos) {
    auto end = obj.find('\n', pos);
    obj.replace(pos, end == std::string::npos ? std::string::npos : end - pos + 1, mtl_line);
  } else {
    obj = mtl_line + obj;
  }
  for (const aiExportDataBlob* b = blob->next; b; b = b->next) {
    std::string name = b->name.C_Str();
    if (name.find("mtl") == std::string::npos) continue;
    Status written = WriteFileAtomic(mtl_path, std::string_view(static_cast<const char*>(b->data), b->size));
    if (!written) return written;
  }
  return WriteFileAtomic(out, obj);
}

}  // namespace villa

namespace villa {

std::string SceneNodeInfo::Meta(const std::string& key) const {
  auto it = metadata.find(key);
  return it == metadata.end() ? std::string() : it->second;
}

TriangleMesh PlanFrameMesh(const SceneInfo& info, const SceneNodeInfo& node, bool world) {
  TriangleMesh out;
  const auto& m = node.global;
  for (int k : node.meshes) {
    const TriangleMesh& src = info.meshes[k].mesh;
    const int base = static_cast<int>(out.vertices.size());
    for (const Vec3& v : src.vertices) {
      const Vec3 f = world ? Vec3{m[0] * v.x + m[1] * v.y + m[2] * v.z + m[3], m[4] * v.x + m[5] * v.y + m[6] * v.z + m[7],
                                  m[8] * v.x + m[9] * v.y + m[10] * v.z + m[11]}
                           : v;
      out.vertices.push_back({f.x, -f.z, f.y});
    }
    for (const auto& t : src.triangles) out.AddTriangle(base + t[0], base + t[1], base + t[2]);
  }
  return out;
}

const SceneNodeInfo* SceneInfo::Find(std::string_view name) const {
  for (const SceneNodeInfo& n : nodes)
    if (n.name == name) return &n;
  return nullptr;
}

namespace {
SceneInfo SceneInfoOf(const aiScene* scene);
}  // namespace

namespace {
Status CheckGlbStructureUnsafe(std::string_view bytes, const std::string& name);
}  // namespace

Status CheckGlbStructure(std::string_view bytes, const std::string& name) {
  try {
    return CheckGlbStructureUnsafe(bytes, name);
  } catch (const nlohmann::json::exception& e) {  // a member of the wrong type ("meshes": [1])
    return Error{name + ": malformed glTF JSON: " + std::string(e.what())};
  }
}

namespace {
Status CheckGlbStructureUnsafe(std::string_view bytes, const std::string& name) {
  auto u32 = [&](std::size_t at) {
    uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
    return v;
  };
  if (bytes.size() < 20 || bytes.substr(0, 4) != "glTF") return Error{name + ": not a binary glTF (.glb): no \"glTF\" header"};
  if (u32(4) != 2) return Error{name + ": glTF version " + std::to_string(u32(4)) + ", expected 2"};
  if (u32(8) != bytes.size())
    return Error{name + ": the header says " + std::to_string(u32(8)) + " bytes, the file has " + std::to_string(bytes.size()) + " (torn?)"};
  const uint32_t json_length = u32(12);
  if (u32(16) != 0x4E4F534Au || json_length > bytes.size() - 20) return Error{name + ": the first chunk is not a whole JSON chunk"};
  if (json_length > (64u << 20))
    return Error{name + ": a JSON chunk of " + std::to_string(json_length >> 20) + " MB, more than the 64 MB a scene's may be"};
  const nlohmann::json j = nlohmann::json::parse(bytes.substr(20, json_length), nullptr, false);
  if (j.is_discarded() || !j.is_object()) return Error{name + ": its JSON chunk does not parse"};
  auto bounded = [](const nlohmann::json& a, std::size_t at_least) {
    if (!a.is_array() || a.size() < at_least) return false;
    for (const auto& v : a)
      if (!v.is_number() || !std::isfinite(v.get<double>()) || std::abs(v.get<double>()) > kMaxGlbCoordinate) return false;
    return true;
  };
  const nlohmann::json nodes = j.value("nodes", nlohmann::json::array());
  if (!nodes.is_array()) return Error{name + ": \"nodes\" is not an array"};
  if (nodes.size() > kMaxGlbNodes)
    return Error{name + ": " + std::to_string(nodes.size()) + " nodes, more than the " + std::to_string(kMaxGlbNodes) + " a scene may have"};
  std::vector<int> parent(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const nlohmann::json& n = nodes[i];
    const std::string where = name + ": node " + std::to_string(i);
    if (!n.is_object()) return Error{where + ": not an object"};
    for (const char* key : {"translation", "scale", "matrix"})
      if (n.contains(key) && !bounded(n[key], std::string(key) == "matrix" ? 16 : 3))
        return Error{where + ": \"" + key + "\" " + n[key].dump().substr(0, 80) + " is not finite numbers within " +
                     std::to_string(static_cast<long>(kMaxGlbCoordinate)) + " m"};
    if (!n.contains("children")) continue;
    if (!n["children"].is_array()) return Error{where + ": \"children\" is not an array"};
    for (const auto& c : n["children"]) {
      if (!c.is_number_unsigned() || c.get<std::size_t>() >= nodes.size()) return Error{where + ": child " + c.dump() + " is no node"};
      const std::size_t k = c.get<std::size_t>();
      if (parent[k] >= 0)
        return Error{name + ": node " + std::to_string(k) + " has two parents (" + std::to_string(parent[k]) + " and " + std::to_string(i) + ")"};
      parent[k] = static_cast<int>(i);
    }
  }
  // Depth (and cycles) without recursion: walk up from each node, remembering depths found.
  std::vector<int> depth(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    std::vector<std::size_t> chain;
    std::size_t k = i;
    while (depth[k] < 0 && parent[k] >= 0) {
      chain.push_back(k);
      if (chain.size() > nodes.size()) return Error{name + ": node " + std::to_string(i) + " is its own ancestor (a cycle)"};
      k = static_cast<std::size_t>(parent[k]);
    }
    int d = depth[k] < 0 ? (depth[k] = 0) : depth[k];
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) depth[*it] = ++d;
    if (d > kMaxGlbDepth)
      return Error{name + ": nodes nested " + std::to_string(d) + " deep, more than the " + std::to_string(kMaxGlbDepth) + " a scene may be"};
  }
  for (const auto& b : j.value("buffers", nlohmann::json::array()))
    if (b.is_object() && b.contains("uri") && !(b["uri"].is_string() && b["uri"].get<std::string>().rfind("data:", 0) == 0))
      return Error{name + ": a buffer refers to an outside file (" + b["uri"].dump().substr(0, 80) + "); only embedded buffers are read"};
  for (const auto& b : j.value("images", nlohmann::json::array()))
    if (b.is_object() && b.contains("uri") && !(b["uri"].is_string() && b["uri"].get<std::string>().rfind("data:", 0) == 0))
      return Error{name + ": an image refers to an outside file (" + b["uri"].dump().substr(0, 80) + "); only embedded images are read"};
  const nlohmann::json accessors = j.value("accessors", nlohmann::json::array());
  for (const auto& m : j.value("meshes", nlohmann::json::array()))
    for (const auto& p : m.value("primitives", nlohmann::json::array())) {
      if (!p.is_object() || !p.contains("attributes") || !p["attributes"].contains("POSITION")) continue;
      const auto& a = p["attributes"]["POSITION"];
      if (!a.is_number_unsigned() || a.get<std::size_t>() >= accessors.size())
        return Error{name + ": a POSITION accessor " + a.dump() + " that does not exist"};
      const auto& acc = accessors[a.get<std::size_t>()];
      if (!bounded(acc.value("min", nlohmann::json()), 3) || !bounded(acc.value("max", nlohmann::json()), 3))
        return Error{name + ": accessor " + a.dump() + " (POSITION): min/max missing, not finite or beyond " +
                     std::to_string(static_cast<long>(kMaxGlbCoordinate)) + " m"};
    }
  return Status{};
}
}  // namespace

Result<SceneInfo> ReadSceneInfo(const std::filesystem::path& path) {
  if (Status s = CheckReadable(path); !s) return Error{s.error()};
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  char magic[4] = {};
  {
    std::ifstream head(path, std::ios::binary);
    head.read(magic, 4);
  }
  // A .glb by name or by its first bytes (a renamed one) is checked before the importer sees it.
  if (extension == ".glb" || std::string_view(magic, 4) == "glTF") {
    auto bytes = ReadFile(path);
    if (!bytes.ok()) return Error{bytes.error()};
    return ReadSceneInfoFromMemory(*bytes, "glb", path.string());
  }
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode) return Error{path.string() + ": " + importer.GetErrorString()};
  return SceneInfoOf(scene);
}

Result<SceneInfo> ReadSceneInfoFromMemory(const std::string& bytes, const std::string& extension, const std::string& name) {
  if (extension == "glb")
    if (Status s = CheckGlbStructure(bytes, name.empty() ? "in-memory .glb" : name); !s) return Error{s.error()};
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_ValidateDataStructure,
                                                     extension.c_str());
  if (!scene || !scene->mRootNode)
    return Error{(name.empty() ? std::string("in-memory .") + extension : name) + ": " + importer.GetErrorString()};
  return SceneInfoOf(scene);
}

namespace {
SceneInfo SceneInfoOf(const aiScene* scene) {
  SceneInfo info;
  for (unsigned i = 0; i < scene->mNumMaterials; ++i) {
    const aiMaterial* m = scene->mMaterials[i];
    SceneMaterialInfo mi;
    aiString name;
    if (m->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) mi.name = name.C_Str();
    aiColor4D base;
    aiColor3D diffuse;
    if (m->Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) {
      mi.color = {base.r, base.g, base.b};
      mi.alpha = base.a;
    } else if (m->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) {
      mi.color = {diffuse.r, diffuse.g, diffuse.b};
    }
    float opacity = 1.0f;
    if (m->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < mi.alpha) mi.alpha = opacity;
    aiString mode;
    if (m->Get(AI_MATKEY_GLTF_ALPHAMODE, mode) == AI_SUCCESS) mi.alpha_mode = mode.C_Str();
    info.materials.push_back(mi);
  }
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* m = scene->mMeshes[i];
    SceneMeshInfo mi;
    mi.name = m->mName.C_Str();
    mi.material = static_cast<int>(m->mMaterialIndex);
    mi.vertices = static_cast<int>(m->mNumVertices);
    mi.triangles = static_cast<int>(m->mNumFaces);
    for (unsigned v = 0; v < m->mNumVertices; ++v) {
      const Vec3 p{m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z};
      mi.bounds.Add(p);
      mi.mesh.vertices.push_back(p);
      if (m->HasNormals()) mi.normals.push_back({m->mNormals[v].x, m->mNormals[v].y, m->mNormals[v].z});
    }
    for (unsigned f = 0; f < m->mNumFaces; ++f)
      if (m->mFaces[f].mNumIndices == 3)
        mi.mesh.AddTriangle(static_cast<int>(m->mFaces[f].mIndices[0]), static_cast<int>(m->mFaces[f].mIndices[1]),
                            static_cast<int>(m->mFaces[f].mIndices[2]));
    info.meshes.push_back(std::move(mi));
  }
  auto to_array = [](const aiMatrix4x4& t) {
    return std::array<double, 16>{t.a1, t.a2, t.a3, t.a4, t.b1, t.b2, t.b3, t.b4, t.c1, t.c2, t.c3, t.c4, t.d1, t.d2, t.d3, t.d4};
  };
  std::function<void(const aiNode*, const std::string&, const aiMatrix4x4&)> walk = [&](const aiNode* node, const std::string& parent,
                                                                                         const aiMatrix4x4& above) {
    SceneNodeInfo ni;
    ni.name = node->mName.C_Str();
    ni.path = parent.empty() ? ni.name : parent + "/" + ni.name;
    const aiMatrix4x4 global = above * node->mTransformation;
    ni.local = to_array(node->mTransformation);
    ni.global = to_array(global);
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      ni.meshes.push_back(static_cast<int>(node->mMeshes[k]));
      for (const Vec3& v : info.meshes[node->mMeshes[k]].mesh.vertices) {
        const aiVector3D w = global * aiVector3D(static_cast<ai_real>(v.x), static_cast<ai_real>(v.y), static_cast<ai_real>(v.z));
        info.bounds.Add(Vec3{w.x, w.y, w.z});
      }
    }
    if (const aiMetadata* md = node->mMetaData) {
      for (unsigned k = 0; k < md->mNumProperties; ++k) {
        const aiMetadataEntry& e = md->mValues[k];
        std::string value;
        switch (e.mType) {
          case AI_BOOL: value = *static_cast<bool*>(e.mData) ? "true" : "false"; break;
          case AI_INT32: value = std::to_string(*static_cast<int32_t*>(e.mData)); break;
          case AI_UINT64: value = std::to_string(*static_cast<uint64_t*>(e.mData)); break;
          case AI_FLOAT: value = std::to_string(*static_cast<float*>(e.mData)); break;
          case AI_DOUBLE: value = std::to_string(*static_cast<double*>(e.mData)); break;
          case AI_AISTRING: value = static_cast<aiString*>(e.mData)->C_Str(); break;
          default: continue;
        }
        ni.metadata[md->mKeys[k].C_Str()] = value;
      }
    }
    info.nodes.push_back(ni);
    std::string path_here = info.nodes.back().path;
    for (unsigned c = 0; c < node->mNumChildren; ++c) walk(node->mChildren[c], path_here, global);
  };
  walk(scene->mRootNode, "", aiMatrix4x4());
  return info;
}
}  // namespace

}  // namespace villa
