#include "assets/asset_mesh.h"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "util/atomic_file.h"

namespace villa {
namespace {

constexpr char kMagic[8] = {'V', 'M', 'E', 'S', 'H', '1', '\0', '\0'};
// Sanity bounds on what a file may declare before anything is allocated.
constexpr std::uint32_t kMaxParts = 1u << 16;
constexpr std::uint32_t kMaxCount = 1u << 26;
constexpr double kMaxCoordinate = 1000.0;  // m from the asset's origin: no piece of furniture comes near

void PutU32(std::string* out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
void PutF32(std::string* out, double v) {
  float f = static_cast<float>(v);
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  PutU32(out, bits);
}

class Cursor {
 public:
  explicit Cursor(const std::string& data) : data_(data) {}
  bool U32(std::uint32_t* v) {
    if (pos_ + 4 > data_.size()) return false;
    *v = 0;
    for (int i = 0; i < 4; ++i) *v |= static_cast<std::uint32_t>(static_cast<unsigned char>(data_[pos_ + i])) << (8 * i);
    pos_ += 4;
    return true;
  }
  bool F32(double* v) {
    std::uint32_t bits;
    if (!U32(&bits)) return false;
    float f;
    std::memcpy(&f, &bits, 4);
    *v = f;
    return std::isfinite(f);
  }
  bool Bytes(size_t n, std::string* out) {
    if (pos_ + n > data_.size()) return false;
    *out = data_.substr(pos_, n);
    pos_ += n;
    return true;
  }
  size_t pos() const { return pos_; }
  size_t Left() const { return data_.size() - pos_; }
  bool AtEnd() const { return pos_ == data_.size(); }

 private:
  const std::string& data_;
  size_t pos_ = 0;
};

}  // namespace

Box3 AssetMesh::Bounds() const {
  Box3 box;
  for (const AssetMeshPart& p : parts) box.Add(p.mesh.Bounds());
  return box;
}

int AssetMesh::TriangleCount() const {
  int n = 0;
  for (const AssetMeshPart& p : parts) n += static_cast<int>(p.mesh.triangles.size());
  return n;
}

TriangleMesh AssetMesh::Merged() const {
  TriangleMesh out;
  for (const AssetMeshPart& p : parts) out.Append(p.mesh);
  return out;
}

Status WriteAssetMesh(const std::filesystem::path& path, const AssetMesh& mesh) {
  std::string out(kMagic, 8);
  PutU32(&out, static_cast<std::uint32_t>(mesh.parts.size()));
  for (const AssetMeshPart& p : mesh.parts) {
    PutU32(&out, static_cast<std::uint32_t>(p.material.name.size()));
    out += p.material.name;
    PutF32(&out, p.material.r);
    PutF32(&out, p.material.g);
    PutF32(&out, p.material.b);
    PutF32(&out, p.material.alpha);
    PutU32(&out, static_cast<std::uint32_t>(p.mesh.vertices.size()));
    for (const Vec3& v : p.mesh.vertices) {
      PutF32(&out, v.x);
      PutF32(&out, v.y);
      PutF32(&out, v.z);
    }
    PutU32(&out, static_cast<std::uint32_t>(p.mesh.triangles.size()));
    for (const auto& t : p.mesh.triangles)
      for (int i : t) PutU32(&out, static_cast<std::uint32_t>(i));
  }
  return WriteFileAtomic(path, out);
}

Result<AssetMesh> ReadAssetMesh(const std::filesystem::path& path) {
  auto data = ReadFile(path);
  if (!data) return Error{data.error()};
  const std::string where = path.string();
  if (data->size() < 8 || std::memcmp(data->data(), kMagic, 8) != 0)
    return Error{where + ": not a villa mesh file (expected the VMESH1 header)"};
  Cursor c(*data);
  std::string skip;
  c.Bytes(8, &skip);
  auto broken = [&](const std::string& what) {
    return Error{where + ": " + what + " at byte " + std::to_string(c.pos())};
  };
  std::uint32_t parts = 0;
  if (!c.U32(&parts) || parts > kMaxParts) return broken("bad part count");
  AssetMesh mesh;
  mesh.parts.resize(parts);
  for (AssetMeshPart& p : mesh.parts) {
    std::uint32_t name_size = 0, vertices = 0, triangles = 0;
    if (!c.U32(&name_size) || name_size > 4096 || !c.Bytes(name_size, &p.material.name)) return broken("bad material name");
    if (!c.F32(&p.material.r) || !c.F32(&p.material.g) || !c.F32(&p.material.b) || !c.F32(&p.material.alpha))
      return broken("bad material colour");
    // Counts are checked against the bytes there before anything is allocated (issue 33: a 36-byte file
    // declaring 2^26 vertices took 3 GB), and coordinates against a building's scale (3e38 crashed the ray tracer).
    if (!c.U32(&vertices) || vertices > kMaxCount) return broken("bad vertex count");
    if (std::uint64_t{vertices} * 12 > c.Left())
      return broken(std::to_string(vertices) + " vertices declared, " + std::to_string(c.Left()) + " bytes left (truncated)");
    p.mesh.vertices.resize(vertices);
    for (Vec3& v : p.mesh.vertices) {
      if (!c.F32(&v.x) || !c.F32(&v.y) || !c.F32(&v.z)) return broken("truncated or non-finite vertex");
      if (std::abs(v.x) > kMaxCoordinate || std::abs(v.y) > kMaxCoordinate || std::abs(v.z) > kMaxCoordinate)
        return broken("a vertex beyond 1000 m of the asset's origin");
    }
    if (!c.U32(&triangles) || triangles > kMaxCount) return broken("bad triangle count");
    if (std::uint64_t{triangles} * 12 > c.Left())
      return broken(std::to_string(triangles) + " triangles declared, " + std::to_string(c.Left()) + " bytes left (truncated)");
    p.mesh.triangles.resize(triangles);
    for (auto& t : p.mesh.triangles) {
      for (int& i : t) {
        std::uint32_t index = 0;
        if (!c.U32(&index)) return broken("truncated triangle");
        if (index >= vertices) return broken("triangle index " + std::to_string(index) + " past the vertex count");
        i = static_cast<int>(index);
      }
    }
  }
  if (!c.AtEnd()) return broken("trailing bytes");
  return mesh;
}

}  // namespace villa
