#include "mesh/ray_caster.h"

#include <vector>

#include <embree3/rtcore.h>

namespace villa {

struct RayCaster::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  // Per mesh id, per triangle, from its winding (Embree's Ng follows its own convention).
  std::vector<std::vector<Vec3>> normals;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

RayCaster::RayCaster() : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice("threads=1");
  if (impl_->device) impl_->scene = rtcNewScene(impl_->device);
}

RayCaster::RayCaster(const TriangleMesh& mesh) : RayCaster() {
  Add(mesh);
  Commit();
}

RayCaster::~RayCaster() = default;

bool RayCaster::ok() const { return impl_->device && impl_->scene; }

int RayCaster::Add(const TriangleMesh& mesh) {
  if (!ok() || mesh.triangles.empty()) return -1;
  std::vector<Vec3> normals;
  normals.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    normals.push_back(Normalized(Cross(b - a, c - a)));
  }
  RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                       3 * sizeof(float), mesh.vertices.size()));
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    v[3 * k] = static_cast<float>(mesh.vertices[k].x);
    v[3 * k + 1] = static_cast<float>(mesh.vertices[k].y);
    v[3 * k + 2] = static_cast<float>(mesh.vertices[k].z);
  }
  auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), mesh.triangles.size()));
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int c = 0; c < 3; ++c) index[3 * k + c] = static_cast<unsigned>(mesh.triangles[k][c]);
  rtcCommitGeometry(geometry);
  // A fresh scene numbers its geometries 0, 1, 2... in the order attached: the id is the index of normals.
  const unsigned id = rtcAttachGeometry(impl_->scene, geometry);
  rtcReleaseGeometry(geometry);
  if (id >= impl_->normals.size()) impl_->normals.resize(id + 1);
  impl_->normals[id] = std::move(normals);
  return static_cast<int>(id);
}

void RayCaster::Commit() {
  if (ok()) rtcCommitScene(impl_->scene);
}

std::optional<RayCaster::Hit> RayCaster::Cast(Vec3 origin, Vec3 direction, double t_max, double t_min) const {
  if (!ok()) return std::nullopt;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(origin.x);
  rh.ray.org_y = static_cast<float>(origin.y);
  rh.ray.org_z = static_cast<float>(origin.z);
  rh.ray.dir_x = static_cast<float>(direction.x);
  rh.ray.dir_y = static_cast<float>(direction.y);
  rh.ray.dir_z = static_cast<float>(direction.z);
  rh.ray.tnear = static_cast<float>(t_min);
  rh.ray.tfar = static_cast<float>(t_max);
  rh.ray.mask = 0xFFFFFFFF;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  Hit hit;
  hit.t = rh.ray.tfar;
  hit.mesh = static_cast<int>(rh.hit.geomID);
  hit.triangle = static_cast<int>(rh.hit.primID);
  hit.normal = impl_->normals[rh.hit.geomID][rh.hit.primID];
  return hit;
}

std::vector<double> RayCaster::Crossings(Vec3 origin, Vec3 direction, double length) const {
  std::vector<double> out;
  double t = 0.0;
  // Past each hit by 0.1 mm: coplanar duplicates count once, panels thinner than that count once.
  constexpr double kStep = 1e-4;
  while (out.size() < 1000) {
    std::optional<Hit> hit = Cast(origin, direction, length, t);
    if (!hit) break;
    out.push_back(hit->t);
    t = hit->t + kStep;
  }
  return out;
}

}  // namespace villa
