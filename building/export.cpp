#include "building/export.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/metadata.h>
#include <assimp/scene.h>

#include <cstring>
#include <functional>
#include <cmath>
#include <map>
#include <set>
#include <memory>

#include <nlohmann/json.hpp>

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
    PartMaterial m = MaterialOf(part);
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
    float metallic = 0.0f, roughness = static_cast<float>(m.roughness);
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
        case PartKind::kWindowGlass: groups["windows" + suffix].push_back(node); break;
        case PartKind::kStair: groups["stairs" + suffix].push_back(node); break;
      }
    }
    for (const char* group : {"walls", "doors", "windows", "stairs", "terraces"}) {
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

uint32_t ReadU32(const std::string& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}
void PutU32(std::string& b, uint32_t v) { b.append(reinterpret_cast<const char*>(&v), 4); }

// assimp's glTF exporter drops node metadata and declares extensions it does not use. This rewrites
// the JSON chunk of the .glb: room nodes get "extras" {category, area_m2, level}, and extensionsUsed
// keeps only extensions that occur. The binary chunk is kept byte for byte.
Result<std::string> PatchGlb(const std::string& glb, const BuildingMesh& building) {
  if (glb.size() < 20 || glb.compare(0, 4, "glTF") != 0) return Error{"exporter wrote no GLB header"};
  uint32_t json_len = ReadU32(glb, 12);
  if (glb.compare(16, 4, "JSON") != 0 || 20 + size_t{json_len} > glb.size()) return Error{"GLB without a JSON chunk"};
  auto json = nlohmann::ordered_json::parse(glb.substr(20, json_len), nullptr, false);
  if (json.is_discarded()) return Error{"GLB JSON chunk does not parse"};
  std::map<std::string, const BuiltRoom*> rooms;
  for (const BuiltRoom& r : building.rooms) rooms[r.name] = &r;
  if (json.contains("nodes"))
    for (auto& node : json["nodes"]) {
      auto it = node.contains("name") ? rooms.find(node["name"].get<std::string>()) : rooms.end();
      if (it == rooms.end() || !node.contains("mesh")) continue;
      node["extras"] = {{"category", std::string(CategoryName(it->second->category))},
                        {"area_m2", std::round(it->second->area * 100.0) / 100.0},
                        {"level", it->second->level}};
    }
  if (json.contains("extensionsUsed")) {
    std::set<std::string> present;
    std::function<void(const nlohmann::ordered_json&)> scan = [&](const nlohmann::ordered_json& j) {
      if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) {
          if (it.key() == "extensions" && it.value().is_object())
            for (auto e = it.value().begin(); e != it.value().end(); ++e) present.insert(e.key());
          scan(it.value());
        }
      } else if (j.is_array()) {
        for (const auto& v : j) scan(v);
      }
    };
    scan(json);
    nlohmann::ordered_json used = nlohmann::ordered_json::array();
    for (const auto& e : json["extensionsUsed"])
      if (present.count(e.get<std::string>())) used.push_back(e);
    if (used.empty())
      json.erase("extensionsUsed");
    else
      json["extensionsUsed"] = used;
  }
  std::string text = json.dump();
  while (text.size() % 4 != 0) text.push_back(' ');
  std::string rest = glb.substr(20 + json_len);  // the BIN chunk, header included
  std::string out = "glTF";
  PutU32(out, 2);
  PutU32(out, static_cast<uint32_t>(12 + 8 + text.size() + rest.size()));
  PutU32(out, static_cast<uint32_t>(text.size()));
  out += "JSON";
  out += text;
  out += rest;
  return out;
}

}  // namespace

std::optional<MeshFormat> ParseMeshFormat(std::string_view name) {
  if (name == "glb") return MeshFormat::kGlb;
  if (name == "obj") return MeshFormat::kObj;
  return std::nullopt;
}

Result<std::string> BuildingToGlb(const BuildingMesh& building) {
  auto scene = MakeScene(building);
  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), "glb2");
  if (!blob) return Error{std::string("glTF export failed: ") + exporter.GetErrorString()};
  return PatchGlb(std::string(static_cast<const char*>(blob->data), blob->size), building);
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

const SceneNodeInfo* SceneInfo::Find(std::string_view name) const {
  for (const SceneNodeInfo& n : nodes)
    if (n.name == name) return &n;
  return nullptr;
}

Result<SceneInfo> ReadSceneInfo(const std::filesystem::path& path) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode) return Error{path.string() + ": " + importer.GetErrorString()};
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
    for (unsigned v = 0; v < m->mNumVertices; ++v) mi.bounds.Add(Vec3{m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z});
    info.bounds.Add(mi.bounds);
    info.meshes.push_back(mi);
  }
  std::function<void(const aiNode*, const std::string&)> walk = [&](const aiNode* node, const std::string& parent) {
    SceneNodeInfo ni;
    ni.name = node->mName.C_Str();
    ni.path = parent.empty() ? ni.name : parent + "/" + ni.name;
    for (unsigned k = 0; k < node->mNumMeshes; ++k) ni.meshes.push_back(static_cast<int>(node->mMeshes[k]));
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
    for (unsigned c = 0; c < node->mNumChildren; ++c) walk(node->mChildren[c], path_here);
  };
  walk(scene->mRootNode, "");
  return info;
}

}  // namespace villa
