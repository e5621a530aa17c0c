#include "solver/reach_scene.h"

#include "building/building.h"
#include "layout/layout_io.h"
#include "scene/file_digest.h"
#include "solver/free_space.h"

namespace villa::solver {

std::vector<ReachObject> ReachObjectsOfScene(const scene::SceneFile& file) {
  std::vector<ReachObject> out;
  auto box_of = [](const scene::SceneObject& o) {
    OrientedBox b;
    b.c = {o.pose->x, o.pose->y};
    b.yaw = o.pose->yaw;
    b.hx = 0.5 * o.size.x;
    b.hy = 0.5 * o.size.y;
    b.z0 = o.pose->z;
    b.z1 = o.pose->z + o.size.z;
    return b;
  };
  for (const scene::SceneObject& o : file.objects) {
    if (!o.pose) continue;
    ReachObject r;
    r.id = o.id;
    r.room = o.room;
    r.level = o.level;
    r.box = box_of(o);
    r.covering = o.parent == scene::kParentFloor && o.relation == scene::Relation::kOnTop && o.size.z <= 0.03;
    const bool hung = o.relation == scene::Relation::kOnWall || o.relation == scene::Relation::kHanging;
    if (o.interaction_zone && (o.affordances & kInteractor) && !hung) {
      r.zone = ZoneFootprints(r.box, o.interaction_zone->side, o.interaction_zone->depth);
      for (const std::string& id : o.interaction_zone->exempt) {
        const scene::SceneObject* other = file.FindObject(id);
        if (!other || !other->pose) continue;
        const PlanShape shape = PlanShape::Polygon(box_of(*other).Footprint());
        for (const Ring& z : r.zone) r.zone_shared |= PlanClearance(PlanShape::Polygon(z), shape) < 0.0;
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

Result<SceneReach> ReachOfScene(const std::filesystem::path& scene_file, const ReachOptions& options) {
  std::string message;
  if (!options.IsValid(&message)) return Error{"reach options: " + message};
  auto file = scene::ReadScene(scene_file);
  if (!file.ok()) return Error{file.error()};
  SceneReach out;
  out.layout = std::filesystem::path(file->layout.file);
  if (out.layout.is_relative()) out.layout = scene_file.parent_path() / out.layout;
  auto layout = LoadLayout(out.layout);
  if (!layout.ok()) return Error{scene_file.string() + ": layout: " + layout.error()};
  if (auto digest = scene::FileSha256(out.layout); digest.ok() && *digest != file->layout.sha256) {
    out.warnings.push_back(out.layout.string() + " is not the file the scene was made from (its sha256 differs)");
  }
  BuildOptions build;
  build.slab_thickness = file->build.slab_thickness;
  build.exterior_wall_thickness = file->build.exterior_wall_thickness;
  build.interior_wall_thickness = file->build.interior_wall_thickness;
  auto building = BuildBuilding(*layout, build);
  if (!building.ok()) return Error{out.layout.string() + ": " + building.error()};
  auto input = BuildingReachInput(*layout, *building, build, options);
  if (!input.ok()) return Error{out.layout.string() + ": " + input.error()};
  AddObjects(*input, ReachObjectsOfScene(*file), options);
  auto report = CheckReach(*input, options);
  if (!report.ok()) return Error{scene_file.string() + ": " + report.error()};
  out.report = std::move(*report);
  return out;
}

}  // namespace villa::solver
