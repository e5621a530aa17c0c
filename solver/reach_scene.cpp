#include "solver/reach_scene.h"

#include <algorithm>
#include <cmath>

#include "building/building.h"
#include "layout/layout_io.h"
#include "scene/file_digest.h"
#include "scene/validate.h"
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
  // Issue 33: a scene that breaks its own contract (a parent cycle, a missing parent, an object in a room
  // the layout does not have) is refused, naming what is wrong, rather than walked through.
  if (const std::vector<scene::Finding> findings = scene::ValidateScene(*file, *layout, nullptr); !findings.empty()) {
    std::string what = scene::FormatFindings(findings);
    const size_t lines = static_cast<size_t>(std::count(what.begin(), what.end(), '\n'));
    if (lines > 10) {
      size_t cut = 0;
      for (int k = 0; k < 10; ++k) cut = what.find('\n', cut) + 1;
      what = what.substr(0, cut) + "... and " + std::to_string(lines - 10) + " more\n";
    }
    return Error{scene_file.string() + ": not a valid scene (" + std::to_string(findings.size()) + " finding(s)):\n" + what};
  }
  // Poses within the 10 km a layout's coordinates may span (an object at x = 3e10 once took 2.8 GB of raster).
  for (const scene::SceneObject& o : file->objects) {
    if (!o.pose) continue;
    const scene::Pose& p = *o.pose;
    for (double v : {p.x, p.y, p.z})
      if (!std::isfinite(v) || std::abs(v) > 1.0e4)
        return Error{scene_file.string() + ": object " + o.id + " stands at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                     std::to_string(p.z) + "), beyond the 10 km a layout spans"};
    for (double v : {o.size.x, o.size.y, o.size.z})
      if (!std::isfinite(v) || v < 0.0 || v > 1.0e3)
        return Error{scene_file.string() + ": object " + o.id + " has a size of " + std::to_string(v) + " m (expected 0 to 1000)"};
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
