#include "solver/room_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "building/view_scene.h"

namespace villa::solver {
namespace {

constexpr double kCornerAzimuths[4] = {45.0, 135.0, 225.0, 315.0};
constexpr double kPictureAzimuth = 315.0;  // from the south-west, as the villa previews look
constexpr double kReach = 0.5;             // m around the room's box: building parts drawn with it

// The room's box: its polygon's plan bounds, floor to ceiling.
Box3 RoomBox(const RoomViewInput& room) {
  Box3 box;
  for (const Point& p : room.polygon) {
    box.Add(Vec3{p.x, p.y, room.floor_z});
    box.Add(Vec3{p.x, p.y, room.floor_z + room.clear_height});
  }
  return box;
}

// The objects' meshes in the world frame, one per asset part (kept alive while the scene is drawn).
struct PosedMeshes {
  std::vector<TriangleMesh> meshes;
  std::vector<MeshMaterial> materials;
};

PosedMeshes PoseObjects(const RoomViewInput& room) {
  PosedMeshes out;
  for (const RoomViewObject& o : room.objects) {
    const double c = std::cos(o.pose.yaw), s = std::sin(o.pose.yaw), k = o.pose.scale;
    for (const AssetMeshPart& part : o.mesh->parts) {
      TriangleMesh m;
      m.triangles = part.mesh.triangles;
      m.vertices.reserve(part.mesh.vertices.size());
      for (const Vec3& v : part.mesh.vertices)
        m.vertices.push_back(Vec3{o.pose.x + k * (c * v.x - s * v.y), o.pose.y + k * (s * v.x + c * v.y), o.pose.z + k * v.z});
      out.meshes.push_back(std::move(m));
      out.materials.push_back(part.material);
    }
  }
  return out;
}

// The building's meshes drawn with the room, and where each one stands relative to the room's centre
// (the centre of its bounds clipped to the room's box: a long wall shared with other rooms counts by the
// part that borders this one).
struct RoomParts {
  std::vector<ViewMesh> meshes;
  std::vector<Point> offsets;  // from the room's centre, plan m
};

RoomParts PartsAround(const RoomViewInput& room, const ViewScene& building_scene, const Box3& box) {
  RoomParts out;
  const Point centre{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y)};
  for (size_t k = 0; k < building_scene.meshes.size(); ++k) {
    const MeshPart& part = room.building->parts[k];
    const ViewMesh& view = building_scene.meshes[k];
    if (part.level != room.level) continue;
    if ((part.kind == PartKind::kFloor && part.name != room.room) || part.kind == PartKind::kTerrace) continue;
    const Box3 b = part.mesh.Bounds();
    const double x0 = std::max(b.min.x, box.min.x - kReach), x1 = std::min(b.max.x, box.max.x + kReach);
    const double y0 = std::max(b.min.y, box.min.y - kReach), y1 = std::min(b.max.y, box.max.y + kReach);
    if (x0 > x1 || y0 > y1) continue;
    out.meshes.push_back(view);
    out.offsets.push_back({0.5 * (x0 + x1) - centre.x, 0.5 * (y0 + y1) - centre.y});
  }
  return out;
}

// The scene seen from `azimuth_deg` (< 0: from above, nothing cut).
ViewScene SceneFor(const RoomParts& parts, const PosedMeshes& posed, const ViewScene& building_scene, int level,
                   double azimuth_deg) {
  ViewScene scene;
  scene.floor_z = building_scene.floor_z;
  const double az = azimuth_deg * std::numbers::pi / 180.0;
  const Point towards_camera{std::sin(az), -std::cos(az)};
  for (size_t k = 0; k < parts.meshes.size(); ++k) {
    ViewMesh m = parts.meshes[k];
    if (m.cut == CutAway::kCut) {
      const bool near = azimuth_deg >= 0.0 && parts.offsets[k].x * towards_camera.x + parts.offsets[k].y * towards_camera.y > 0.0;
      m.cut = near ? CutAway::kCut : CutAway::kKeep;
    }
    scene.meshes.push_back(m);
  }
  for (size_t k = 0; k < posed.meshes.size(); ++k) {
    ViewMesh m;
    m.mesh = &posed.meshes[k];
    m.color = Rgb{posed.materials[k].r, posed.materials[k].g, posed.materials[k].b};
    m.alpha = posed.materials[k].alpha;
    m.level = level;
    m.cut = CutAway::kKeep;
    scene.meshes.push_back(m);
  }
  return scene;
}

std::vector<ViewLabel> Labels(const RoomViewInput& room) {
  std::vector<ViewLabel> labels;
  for (const RoomViewObject& o : room.objects) {
    if (o.label.empty()) continue;
    const Box3 b = o.mesh->Bounds();
    labels.push_back({Vec3{o.pose.x, o.pose.y, o.pose.z + o.pose.scale * b.max.z + 0.02}, o.label});
  }
  return labels;
}

// What every picture of a room is drawn from: the box the cameras frame, the building's view scene, the
// parts of it around the room and the room's posed objects (members built in this order).
struct RoomStage {
  explicit RoomStage(const RoomViewInput& room)
      : room(room), box(RoomBox(room)), building(ViewSceneOf(*room.building)), parts(PartsAround(room, building, box)),
        posed(PoseObjects(room)) {}
  // The scene seen from `azimuth_deg` (-1: from above), walls on the camera's side cut.
  ViewScene SceneFrom(double azimuth_deg) const { return SceneFor(parts, posed, building, room.level, azimuth_deg); }
  // Cut-away at the room's level, `cut_height` m above its floor.
  RenderOptions Render(double cut_height) const {
    RenderOptions render;
    render.top_level = room.level;
    render.cut_height = cut_height;
    return render;
  }

  const RoomViewInput& room;
  const Box3 box;
  const ViewScene building;
  const RoomParts parts;
  const PosedMeshes posed;
};

Status CheckInput(const RoomViewInput& room) {
  if (!room.building) return Error{"room view of " + room.room + ": no building given"};
  if (room.polygon.size() < 3) return Error{"room view of " + room.room + ": the room polygon has fewer than 3 corners"};
  for (const RoomViewObject& o : room.objects)
    if (!o.mesh) return Error{"room view of " + room.room + ": object " + o.label + " has no mesh"};
  return Status::Ok();
}

}  // namespace

std::string RoomViewOptions::Check() const {
  if (size_px < 64 || size_px > 4096) return "view size " + std::to_string(size_px) + " px: must be in [64, 4096]";
  if (!(elevation_deg >= 10.0 && elevation_deg <= 80.0)) return "view elevation: must be in [10, 80] degrees";
  if (!(cut_height >= 0.0 && cut_height <= 2.5)) return "cut height: must be in [0, 2.5] m";
  if (!(label_px >= 6.0 && label_px <= 48.0)) return "label size: must be in [6, 48] px";
  if (samples < 1 || samples > 4) return "samples " + std::to_string(samples) + ": must be in [1, 4]";
  if (threads < 0) return "threads " + std::to_string(threads) + ": must be >= 0";
  return "";
}

Result<std::vector<RoomViewImage>> RenderRoomViews(const RoomViewInput& room, const RoomViewOptions& options) {
  if (std::string problem = options.Check(); !problem.empty()) return Error{"room views: " + problem};
  if (Status s = CheckInput(room); !s.ok()) return Error{s.error()};
  const RoomStage stage(room);
  const std::vector<ViewLabel> labels = options.labels ? Labels(room) : std::vector<ViewLabel>{};
  RenderOptions render = stage.Render(options.cut_height);
  render.samples = options.samples;
  render.threads = options.threads;
  LabelStyle style;
  style.font_px = options.label_px;

  std::vector<Camera> cameras = RoomCameras(stage.box, options.size_px, options.elevation_deg);
  std::vector<RoomViewImage> out;
  for (size_t v = 0; v < cameras.size(); ++v) {
    const double azimuth = v == 0 ? -1.0 : kCornerAzimuths[v - 1];
    auto image = RenderView(stage.SceneFrom(azimuth), cameras[v], render);
    if (!image.ok()) return Error{"room views of " + room.room + ": " + image.error()};
    if (!labels.empty())
      if (Status s = DrawLabels(*image, cameras[v], labels, style); !s.ok()) return Error{s.error()};
    out.push_back({v == 0 ? "top" : "corner-" + std::to_string(static_cast<int>(azimuth)), cameras[v], std::move(*image)});
  }
  return out;
}

Result<Image> RoomPicture(const RoomViewInput& room, int panel_px) {
  RoomViewOptions options;
  options.size_px = panel_px;
  if (std::string problem = options.Check(); !problem.empty()) return Error{"room picture: " + problem};
  if (Status s = CheckInput(room); !s.ok()) return Error{s.error()};
  const RoomStage stage(room);
  RenderOptions render = stage.Render(options.cut_height);
  render.samples = 1;
  render.threads = 0;
  const Camera cameras[2] = {FramingCamera(stage.box, 0.0, 90.0, panel_px, panel_px),
                             FramingCamera(stage.box, kPictureAzimuth, options.elevation_deg, panel_px, panel_px)};
  const double azimuths[2] = {-1.0, kPictureAzimuth};
  // The top view is lit flat: no shadows, so the walls' shadows do not lie on the floor as dark patches;
  // every level surface then gets the same light, the floor and the tops in the tones the corner view
  // gives them where the sun reaches. The corner view keeps its shadows: they give the room its depth.
  RenderOptions flat = render;
  flat.shadows = false;
  const RenderOptions* lighting[2] = {&flat, &render};
  constexpr int kGap = 8;
  Image out{2 * panel_px + kGap, panel_px, {}};
  out.rgb.assign(size_t{3} * out.width * out.height, 255);
  for (int k = 0; k < 2; ++k) {
    auto image = RenderView(stage.SceneFrom(azimuths[k]), cameras[k], *lighting[k]);
    if (!image.ok()) return Error{"room picture of " + room.room + ": " + image.error()};
    for (int y = 0; y < panel_px; ++y)
      std::copy_n(image->rgb.begin() + size_t{3} * y * panel_px, size_t{3} * panel_px,
                  out.rgb.begin() + size_t{3} * (size_t(y) * out.width + size_t(k) * (panel_px + kGap)));
  }
  return out;
}

}  // namespace villa::solver
