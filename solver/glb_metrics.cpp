#include "solver/glb_metrics.h"


#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "assets/mesh_affordances.h"
#include "assets/procedural.h"
#include "building/export.h"
#include "layout/geometry.h"
#include "layout/layout_io.h"
#include "scene/acquire.h"
#include "scene/file_digest.h"
#include "scene/room_context.h"
#include "scene/scene.h"
#include "solver/scene_problem.h"

namespace villa::solver {
namespace {

namespace fs = std::filesystem;
using Matrix = std::array<double, 16>;

// The plan frame (z up) and glTF's file frame (+Y up): plan (x, y, z) is file (x, z, -y).
Vec3 FromFile(const Vec3& v) { return {v.x, -v.z, v.y}; }
Vec3 ToFile(const Vec3& p) { return {p.x, p.z, -p.y}; }
Vec3 Apply(const Matrix& m, const Vec3& p) {
  return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
          m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
}
// A node's transform acting on plan-frame points.
Vec3 PlanApply(const Matrix& m, const Vec3& p) { return FromFile(Apply(m, ToFile(p))); }

std::optional<int> MetaInt(const SceneNodeInfo& n, const std::string& key) {
  const std::string v = n.Meta(key);
  if (v.empty()) return std::nullopt;
  try {
    size_t used = 0;
    const double d = std::stod(v, &used);
    if (used == 0 || d != std::floor(d)) return std::nullopt;
    return static_cast<int>(d);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}
// A node's exact name: extras.name (viewers rewrite names holding "/"), else its name.
std::string NameOf(const SceneNodeInfo& n) {
  const std::string name = n.Meta("name");
  return name.empty() ? n.name : name;
}

Category CategoryOfRoom(const std::string& room, const std::string& category_text) {
  if (auto c = ParseCategory(category_text)) return *c;
  if (auto name = ParseRoomName(room)) return name->category;
  if (auto c = ParseCategory(room.substr(0, room.find('_')))) return *c;
  return Category::kRoom;
}


// The top of a floor mesh: the largest boundary loop of its upward faces at its highest level (CCW),
// and that height.
std::pair<Ring, double> FloorTop(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return {{}, 0.0};
  const double top = mesh.Bounds().max.z;
  auto key = [](const Vec3& v) { return std::make_pair(std::llround(v.x * 1e5), std::llround(v.y * 1e5)); };
  using Key = std::pair<long long, long long>;
  std::map<std::pair<Key, Key>, int> directed;
  std::map<Key, Point> point_of;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    if (std::abs(a.z - top) > 1e-4 || std::abs(b.z - top) > 1e-4 || std::abs(c.z - top) > 1e-4) continue;
    const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (std::abs(cross) < 1e-12) continue;
    std::array<Vec3, 3> v{a, b, c};
    if (cross < 0) std::swap(v[1], v[2]);  // every face counter-clockwise seen from above
    for (int k = 0; k < 3; ++k) {
      const Key p = key(v[k]), q = key(v[(k + 1) % 3]);
      point_of[p] = {v[k].x, v[k].y};
      ++directed[{p, q}];
    }
  }
  // Boundary edges: those whose reverse is not there (interior edges come in opposite pairs).
  std::multimap<Key, Key> next;
  for (const auto& [edge, count] : directed)
    if (!directed.count({edge.second, edge.first})) next.emplace(edge.first, edge.second);
  Ring best;
  double best_area = 0.0;
  while (!next.empty()) {
    Ring loop;
    auto it = next.begin();
    const Key start = it->first;
    Key at = start;
    while (true) {
      auto step = next.find(at);
      if (step == next.end()) break;
      loop.push_back(point_of[at]);
      at = step->second;
      next.erase(step);
      if (at == start) break;
    }
    if (loop.size() >= 3 && std::abs(SignedArea(loop)) > best_area) {
      best_area = std::abs(SignedArea(loop));
      best = loop;
    }
  }
  if (SignedArea(best) < 0) std::reverse(best.begin(), best.end());
  return {best, top};
}

// The highest point of `mesh` (asset frame) straight under any of `points` and no higher than `ceiling`:
// where something standing there rests on it. None when the mesh is under none of them.
std::optional<double> ContactHeight(const AssetMesh& mesh, const std::vector<Point>& points, double ceiling) {
  std::optional<double> best;
  for (const AssetMeshPart& part : mesh.parts)
    for (const auto& t : part.mesh.triangles) {
      const Vec3 &a = part.mesh.vertices[t[0]], &b = part.mesh.vertices[t[1]], &c = part.mesh.vertices[t[2]];
      const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
      if (std::abs(det) < 1e-12) continue;  // vertical faces hold nothing up
      for (const Point& p : points) {
        const double u = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / det;
        const double v = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
        if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9) continue;
        const double z = a.z + u * (b.z - a.z) + v * (c.z - a.z);
        if (z <= ceiling && (!best || z > *best)) best = z;
      }
    }
  return best;
}

double SegmentDistance(const Point& p, const WallEdge& w) { return PointSegmentDistance(p, Segment{w.a, w.b}); }

// One object read from the file.
struct FileObject {
  const SceneNodeInfo* node = nullptr;
  std::string id, room, category, asset, parent = "floor";
  Relation relation = Relation::kOnTop;
  int level = 0;
  std::optional<int> surface, cavity, wall_edge;
};

// The asset record and the posed mesh of one object.
struct Posed {
  ProblemObject object;
  Pose pose;
  bool resolved = false;
};

class Measurer {
 public:
  Measurer(const SceneInfo& info, const GlbMetricsOptions& options, std::shared_ptr<const AssetLibrary> library,
           GlbMetricsSummary& summary)
      : info_(info), options_(options), library_(std::move(library)), summary_(summary) {}

  // The record for an asset id whose mesh fits it, when the id resolves.
  std::optional<AssetRecord> Resolve(const std::string& id, const AssetMesh& mesh) {
    if (id.empty()) return std::nullopt;
    std::optional<AssetRecord> record;
    if (auto cached = records_.find(id); cached != records_.end()) {
      record = cached->second;
    } else {
      if (library_)
        if (const AssetRecord* r = library_->Find(id)) record = *r;
      if (!record && id.rfind("proc:", 0) == 0)
        if (auto made = MakeProceduralAsset(id); made.ok()) record = made->record;
      records_[id] = record;
    }
    if (record && !MeshOutsideAssetBox(*record, mesh).empty()) return std::nullopt;
    return record;
  }

  Posed Pose_(const FileObject& f) {
    Posed out;
    ProblemObject& o = out.object;
    o.id = f.id;
    o.category = f.category;
    o.parent = f.parent;
    o.relation = f.relation;
    const Matrix& g = f.node->global;
    const Vec3 origin = PlanApply(g, {0, 0, 0});
    const Vec3 c0 = PlanApply(g, {1, 0, 0}) - origin, c1 = PlanApply(g, {0, 1, 0}) - origin, c2 = PlanApply(g, {0, 0, 1}) - origin;
    const double sx = std::hypot(c0.x, c0.y), sy = std::hypot(c1.x, c1.y), sz = c2.z;
    const double eps = 1e-5 * std::max({sx, sy, std::abs(sz), 1e-9});
    const bool upright = std::abs(c0.z) < eps && std::abs(c1.z) < eps && std::abs(c2.x) < eps && std::abs(c2.y) < eps &&
                         sz > 0 && std::abs(c0.x * c1.x + c0.y * c1.y) < eps * std::max(sx, sy) &&
                         c0.x * c1.y - c0.y * c1.x > 0;
    const bool uniform = upright && std::abs(sx - sy) < eps && std::abs(sx - sz) < eps;
    auto mesh = std::make_shared<AssetMesh>();
    AssetMeshPart part;
    Pose pose;
    if (uniform) {  // the solver's own form: the asset frame and a pose
      part.mesh = PlanFrameMesh(info_, *f.node, false);
      pose = {origin.x, origin.y, origin.z, std::atan2(c0.y, c0.x), sx};
    } else if (upright) {  // scaled per axis: the scale goes into the mesh
      part.mesh = PlanFrameMesh(info_, *f.node, false);
      for (Vec3& v : part.mesh.vertices) v = {v.x * sx, v.y * sy, v.z * sz};
      pose = {origin.x, origin.y, origin.z, std::atan2(c0.y, c0.x), 1.0};
    } else {  // tilted or sheared: the moved mesh is the asset
      part.mesh = PlanFrameMesh(info_, *f.node, true);
      pose = {0, 0, 0, 0, 1.0};
    }
    mesh->parts.push_back(std::move(part));
    if (auto record = Resolve(f.asset, *mesh); record && uniform) {
      o.asset = *record;
      out.resolved = true;
    } else {
      // Bottom centre of the mesh's box to the origin, the pose moved to match.
      TriangleMesh& m = mesh->parts[0].mesh;
      const Box3 b = m.Bounds();
      const Vec3 shift{(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, b.min.z};
      for (Vec3& v : m.vertices) v = v - shift;
      const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
      pose.x += pose.scale * (c * shift.x - s * shift.y);
      pose.y += pose.scale * (s * shift.x + c * shift.y);
      pose.z += pose.scale * shift.z;
      const Box3 centred = m.Bounds();
      AssetRecord& r = o.asset;
      r.id = f.asset.empty() ? f.id : f.asset;
      r.category = f.category;
      r.size = centred.max - centred.min;
      MeshAffordances found = AffordancesFromMesh(m, r.size, std::nullopt);
      r.support_surfaces = std::move(found.surfaces);
      r.cavities = std::move(found.cavities);
    }
    o.mesh = mesh;
    out.pose = pose;
    return out;
  }

  // The room's problem with the file's objects and their placements, measured.
  GlbRoomMetrics Measure(RoomProblem problem, const std::vector<const FileObject*>& objects) {
    GlbRoomMetrics out;
    std::vector<Posed> posed;
    std::set<std::string> ids;
    for (const FileObject* f : objects) ids.insert(f->id);
    for (const FileObject* f : objects) {
      Posed p = Pose_(*f);
      if (!scene::IsRootParent(p.object.parent) && !ids.count(p.object.parent)) {
        summary_.notes.push_back(f->id + ": its parent " + p.object.parent + " is not in the room: read as on the floor");
        p.object.parent = "floor";
        if (p.object.relation == Relation::kInside) p.object.relation = Relation::kOnTop;
      }
      (p.resolved ? out.records_resolved : out.records_from_mesh)++;
      posed.push_back(std::move(p));
    }
    std::vector<ObjectPlacement> placements;
    for (size_t i = 0; i < posed.size(); ++i) {
      problem.objects.push_back(posed[i].object);
      ObjectPlacement pl;
      pl.pose = posed[i].pose;
      pl.placed = true;
      placements.push_back(pl);
    }
    // The discrete choices: the file's indices where the record is the one they index, else the surface
    // or cavity the object rests on, and the wall nearest the object.
    for (size_t i = 0; i < posed.size(); ++i) {
      ProblemObject& o = problem.objects[i];
      const FileObject& f = *objects[i];
      ObjectPlacement& pl = placements[i];
      const Point centre{pl.pose.x, pl.pose.y};
      if (o.relation == Relation::kAgainstWall || o.relation == Relation::kOnWall) {
        double best = 1e18;
        for (size_t w = 0; w < problem.walls.size(); ++w) {
          if (f.wall_edge && problem.walls[w].edge != *f.wall_edge && HasEdge(problem, *f.wall_edge)) continue;
          const double d = SegmentDistance(centre, problem.walls[w]);
          if (d < best) best = d, pl.wall = static_cast<int>(w);
        }
      }
      const int parent = problem.Find(o.parent);
      if (parent < 0) continue;
      ProblemObject& po = problem.objects[parent];
      const Pose& pp = placements[parent].pose;
      const bool exact = posed[i].resolved && posed[parent].resolved;
      const Box3 box = o.mesh->Bounds();
      const double bottom = pl.pose.z + pl.pose.scale * box.min.z;
      // The child's footprint centre and corners (shrunk a little) in the parent's unscaled frame.
      const double cy = std::cos(pl.pose.yaw), sy = std::sin(pl.pose.yaw), c = std::cos(pp.yaw), s = std::sin(pp.yaw);
      auto in_parent = [&](double x, double y) {
        const Point w{pl.pose.x + pl.pose.scale * (cy * x - sy * y), pl.pose.y + pl.pose.scale * (sy * x + cy * y)};
        return Point{(c * (w.x - pp.x) + s * (w.y - pp.y)) / pp.scale, (-s * (w.x - pp.x) + c * (w.y - pp.y)) / pp.scale};
      };
      const Point local = in_parent((box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2);
      std::vector<Point> footprint{local};
      for (const auto& [fx, fy] : {std::pair{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}})
        footprint.push_back(in_parent(box.min.x + fx * (box.max.x - box.min.x), box.min.y + fy * (box.max.y - box.min.y)));
      const double bottom_local = (bottom - pp.z) / pp.scale;
      if (o.relation == Relation::kInside) {
        if (exact && f.cavity && *f.cavity < static_cast<int>(po.asset.cavities.size())) {
          pl.cavity = *f.cavity;
        } else {
          pl.cavity = Nearest(po.asset.cavities.size(), [&](size_t k) {
            const Cavity& cv = po.asset.cavities[k];
            const bool over = local.x >= cv.min.x && local.x <= cv.max.x && local.y >= cv.min.y && local.y <= cv.max.y;
            return std::abs(cv.min.z - bottom_local) + (over ? 0.0 : 100.0);
          });
        }
        if (pl.cavity < 0) {
          // No cavity to check it against: measured as standing on what is under it, outside CSR.
          summary_.notes.push_back(o.id + ": its parent " + o.parent + " shows no cavity: CSR not measured for it");
          o.relation = Relation::kOnTop;
        }
      }
      if (o.relation != Relation::kOnTop) continue;
      if (exact && f.surface && *f.surface < static_cast<int>(po.asset.support_surfaces.size())) {
        pl.surface = *f.surface;
      } else if (exact) {
        pl.surface = Nearest(po.asset.support_surfaces.size(), [&](size_t k) {
          const SupportSurface& sf = po.asset.support_surfaces[k];
          return std::abs(sf.z - bottom_local) + (PointInRing(local, sf.polygon, 1e-6) ? 0.0 : 100.0);
        });
      } else if (auto top = ContactHeight(*po.mesh, footprint, bottom_local + options_.check.tau / pp.scale)) {
        // A parent known only by its mesh: the child rests on the highest part of it under its footprint
        // (SceneEval's downward rays); that height over the parent's footprint is its support.
        const Box3 pb = po.mesh->Bounds();
        po.asset.support_surfaces.push_back(
            {*top, {{pb.min.x, pb.min.y}, {pb.max.x, pb.min.y}, {pb.max.x, pb.max.y}, {pb.min.x, pb.max.y}}, pb.max.z - *top, "contact"});
        pl.surface = static_cast<int>(po.asset.support_surfaces.size()) - 1;
      }
      if (pl.surface < 0) {
        summary_.notes.push_back(o.id + ": nothing of its parent " + o.parent + " is under it: read as on the floor");
        o.parent = "floor";
      }
    }
    out.metrics = CheckArrangement(problem, placements, options_.check);
    return out;
  }

 private:
  static bool HasEdge(const RoomProblem& p, int edge) {
    return std::any_of(p.walls.begin(), p.walls.end(), [&](const WallEdge& w) { return w.edge == edge; });
  }
  template <typename Cost>
  static int Nearest(size_t n, Cost cost) {
    int best = -1;
    double best_cost = 1e18;
    for (size_t k = 0; k < n; ++k)
      if (const double c = cost(k); c < best_cost) best_cost = c, best = static_cast<int>(k);
    return best;
  }

  const SceneInfo& info_;
  const GlbMetricsOptions& options_;
  std::shared_ptr<const AssetLibrary> library_;
  GlbMetricsSummary& summary_;
  std::map<std::string, std::optional<AssetRecord>> records_;
};

std::vector<FileObject> ObjectsOf(const SceneInfo& info) {
  std::vector<FileObject> out;
  for (const SceneNodeInfo& n : info.nodes) {
    if (n.Meta("room").empty()) continue;
    FileObject f;
    f.node = &n;
    f.id = n.Meta("id").empty() ? NameOf(n) : n.Meta("id");
    f.room = n.Meta("room");
    f.category = n.Meta("category");
    f.asset = n.Meta("asset");
    f.level = MetaInt(n, "level").value_or(0);
    if (!n.Meta("parent").empty()) f.parent = n.Meta("parent");
    if (auto r = ParseRelation(n.Meta("relation"))) f.relation = *r;
    f.surface = MetaInt(n, "surface");
    f.cavity = MetaInt(n, "cavity");
    f.wall_edge = MetaInt(n, "wall");
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace

std::string GlbMetricsOptions::Check() const {
  std::string message;
  if (!check.IsValid(&message)) return "exact check: " + message;
  return "";
}

Result<GlbMetricsSummary> MeasureFurnishedGlb(const fs::path& glb, const GlbMetricsOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (std::string problem = options.Check(); !problem.empty()) return Error{problem};
  std::error_code ec;
  if (!fs::exists(glb, ec)) return Error{glb.string() + ": no such file"};
  auto info = ReadSceneInfo(glb);
  if (!info.ok()) return Error{info.error()};
  GlbMetricsSummary summary;

  // The scene names the layout, the wall thicknesses and the library.
  BuildOptions build;
  fs::path layout_path = options.layout, library_dir = options.library;
  std::string scene_layout_sha256;
  if (!options.scene.empty()) {
    auto s = scene::ReadScene(options.scene);
    if (!s.ok()) return Error{s.error()};
    scene_layout_sha256 = s->layout.sha256;
    build.slab_thickness = s->build.slab_thickness;
    build.exterior_wall_thickness = s->build.exterior_wall_thickness;
    build.interior_wall_thickness = s->build.interior_wall_thickness;
    const fs::path folder = options.scene.parent_path();
    if (layout_path.empty()) layout_path = fs::path(s->layout.file).is_absolute() ? fs::path(s->layout.file) : folder / s->layout.file;
    if (library_dir.empty() && s->library) {
      const fs::path jsonl = fs::path(s->library->file).is_absolute() ? fs::path(s->library->file) : folder / s->library->file;
      library_dir = jsonl.parent_path();
    }
  }
  auto opened = scene::OpenFurnishingLibrary(library_dir, false);
  if (!opened.ok()) return Error{opened.error()};
  std::shared_ptr<const AssetLibrary> library = opened->library;

  const std::vector<FileObject> objects = ObjectsOf(*info);
  summary.objects = static_cast<int>(objects.size());
  std::map<std::string, std::vector<const FileObject*>> by_room;
  for (const FileObject& f : objects) by_room[f.room].push_back(&f);
  Measurer measurer(*info, options, library, summary);

  if (!layout_path.empty()) {
    auto layout = LoadLayout(layout_path.string());
    if (!layout.ok()) return Error{layout.error()};
    // Issue 33: the layout must be the one the scene was made from (a mirrored layout scored OBR 32 %).
    if (!scene_layout_sha256.empty()) {
      auto digest = scene::FileSha256(layout_path);
      if (!digest.ok()) return Error{digest.error()};
      if (*digest != scene_layout_sha256)
        return Error{layout_path.string() + ": not the layout " + options.scene.string() + " was made from (its SHA-256 " + *digest +
                     " differs from the scene's " + scene_layout_sha256 + ")"};
    }
    for (const auto& [room, list] : by_room)
      if (layout->FindRoom(room) < 0)
        return Error{glb.string() + ": object " + list.front()->id + " is in room " + room + ", which " + layout_path.string() +
                     " does not have"};
    auto building = BuildBuilding(*layout, build);
    if (!building.ok()) return Error{layout_path.string() + ": " + building.error()};
    auto contexts = scene::RoomContexts(*layout, *building, build);
    if (!contexts.ok()) return Error{layout_path.string() + ": " + contexts.error()};
    const AssetResolver none = [](const std::string& id) -> Result<std::pair<AssetRecord, std::shared_ptr<const AssetMesh>>> {
      return Error{"no asset " + id};
    };
    summary.frame = "layout " + layout_path.string();
    for (const scene::RoomContext& context : *contexts) {
      auto frame = RoomProblemOf(context, *building, {}, {}, none);
      if (!frame.ok()) return Error{context.name + ": " + frame.error()};
      GlbRoomMetrics m = measurer.Measure(std::move(frame->problem), by_room[context.name]);
      m.room = context.name;
      m.category = context.category;
      m.level = context.level;
      summary.rooms.push_back(std::move(m));
    }
  } else {
    summary.frame = "glb";
    // Room nodes: ours carry area_m2; any node an object names as its room is one too.
    std::vector<const SceneNodeInfo*> rooms;
    std::set<std::string> seen;
    for (const SceneNodeInfo& n : info->nodes) {
      const std::string name = NameOf(n);
      if (n.Meta("room").empty() && (!n.Meta("area_m2").empty() || by_room.count(name)) && seen.insert(name).second)
        rooms.push_back(&n);
    }
    for (const auto& [room, list] : by_room)
      if (!seen.count(room)) return Error{glb.string() + ": object " + list.front()->id + " names room " + room + ", which has no node"};
    std::set<const SceneNodeInfo*> not_parts(rooms.begin(), rooms.end());
    for (const FileObject& f : objects) not_parts.insert(f.node);
    struct Part {
      const SceneNodeInfo* node;
      Box3 bounds;
    };
    std::vector<Part> parts;
    for (const SceneNodeInfo& n : info->nodes) {
      if (n.meshes.empty() || not_parts.count(&n)) continue;
      Box3 b;
      for (int m : n.meshes)
        for (const Vec3& v : info->meshes[m].mesh.vertices) b.Add(FromFile(Apply(n.global, v)));
      parts.push_back({&n, b});
    }
    for (const SceneNodeInfo* node : rooms) {
      RoomProblem p;
      p.room = NameOf(*node);
      auto [floor, top] = FloorTop(PlanFrameMesh(*info, *node, true));
      const std::vector<const FileObject*>& list = by_room[p.room];
      if (floor.size() < 3) {
        // No floor to measure against: a square around the objects keeps floor objects in bounds.
        if (!list.empty()) summary.notes.push_back(p.room + ": no floor mesh; floor objects counted in bounds");
        Box3 around;
        for (const FileObject* f : list) around.Add(FromFile(Apply(f->node->global, {0, 0, 0})));
        const double m = 100.0;
        floor = {{around.min.x - m, around.min.y - m}, {around.max.x + m, around.min.y - m},
                 {around.max.x + m, around.max.y + m}, {around.min.x - m, around.max.y + m}};
        top = list.empty() ? 0.0 : around.min.z;
      }
      p.free_floor = floor;
      p.floor_z = top;
      p.clear_height = 2.8 - build.slab_thickness;
      p.walls = WallsAlongFloor(p.free_floor);
      const Box2 near = BoundingBox(p.free_floor);
      for (const Part& part : parts) {
        const Box3& b = part.bounds;
        if (b.max.z <= p.floor_z + 1e-3 || b.min.z >= p.floor_z + p.clear_height) continue;
        if (!near.Touches({b.min.x, b.min.y, b.max.x, b.max.y}, 0.5)) continue;
        p.building.push_back({NameOf(*part.node), PlanFrameMesh(*info, *part.node, true)});
      }
      GlbRoomMetrics m = measurer.Measure(std::move(p), list);
      m.room = NameOf(*node);
      m.category = CategoryOfRoom(m.room, node->Meta("category"));
      m.level = MetaInt(*node, "level").value_or(list.empty() ? 0 : list.front()->level);
      summary.rooms.push_back(std::move(m));
    }
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace villa::solver
