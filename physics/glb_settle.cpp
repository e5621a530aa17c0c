#include "physics/glb_settle.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>

#include "building/export.h"
#include "layout/layout.h"

namespace villa::physics {
namespace {

std::string RoomType(const std::string& room) {
  if (auto name = ParseRoomName(room)) return std::string(CategoryName(name->category));
  return room.substr(0, room.find('_'));
}

// A node's numeric extra as the scene reader gives it (text); nullopt unless all of it is a finite number.
std::optional<double> ParseNumber(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

// `rooms`: when given, only the objects of these rooms become bodies (the rest are left out; their rugs are
// still counted as decals).
static Result<GlbBodies> ReadGlbBodies(const SceneInfo& info, const std::string& glb, const std::vector<std::string>& only,
                                       const std::set<std::string>* rooms = nullptr) {
  GlbBodies out;
  for (const SceneNodeInfo& n : info.nodes) {
    if (n.meshes.empty()) continue;
    TriangleMesh mesh = PlanFrameMesh(info, n, true);
    for (const Vec3& v : mesh.vertices)
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        return Error{glb + ": node " + n.name + ": a vertex is not finite"};
    const std::string room = n.Meta("room");
    if (room.empty()) {
      if (n.Meta("part") == "door" && !n.Meta("hinge_x").empty()) {
        GlbDoor door;
        door.name = n.name;
        door.static_index = static_cast<int>(out.statics.size());
        const double deg = std::numbers::pi / 180.0;
        const std::optional<double> x = ParseNumber(n.Meta("hinge_x")), z = ParseNumber(n.Meta("hinge_z")),
                                    closed = ParseNumber(n.Meta("closed_deg")), open = ParseNumber(n.Meta("open_deg"));
        if (!x || !z || !closed || !open || std::abs(*closed) > 180.0 || std::abs(*open) > 180.0)
          return Error{glb + ": door " + n.name + ": its hinge extras (hinge_x, hinge_z, closed_deg, open_deg) are not numbers of a hinge"};
        door.hinge_x = *x;
        door.hinge_y = -*z;
        door.to_closed = *closed * deg;
        door.to_open = *open * deg;
        out.doors.push_back(std::move(door));
      }
      out.statics.push_back(std::move(mesh));
      continue;
    }
    const std::string category = n.Meta("category"), relation = n.Meta("relation");
    const Box3 box = mesh.Bounds();
    if (category == "rug" || (n.Meta("parent") == "floor" && box.max.z - box.min.z <= 0.003)) {
      ++out.decals;
      continue;
    }
    if (rooms && !rooms->count(room)) continue;
    SettleBody b;
    b.id = n.Meta("id").empty() ? n.name : n.Meta("id");
    // Welded: what hangs on a wall, from the ceiling or on a rail, and a washbasin against a wall (plumbed
    // and bolted to it: an imported pedestal basin's bowl overhangs its foot and tipped over).
    b.welded = relation == "on_wall" || relation == "hanging" || category == "hanging-clothes" ||
               (category == "washbasin" && relation == "against_wall") ||
               (!only.empty() && std::find(only.begin(), only.end(), b.id) == only.end());
    b.mesh = std::move(mesh);
    GlbObjectMotion o;
    o.id = b.id;
    o.room = room;
    o.category = category;
    o.room_type = RoomType(room);
    out.objects.push_back(std::move(o));
    out.bodies.push_back(std::move(b));
  }
  return out;
}

Result<GlbBodies> ReadGlbBodies(const std::filesystem::path& glb) {
  auto info = ReadSceneInfo(glb);
  if (!info.ok()) return Error{info.error()};
  return ReadGlbBodies(*info, glb.string(), {});
}

namespace {

// The stability counts (all, by room type) of a summary's free objects.
void CountStable(GlbSettleSummary& s) {
  for (const GlbObjectMotion& o : s.objects) {
    if (o.motion.welded) continue;
    const StabilityCount one{1, o.motion.strict, o.motion.loose};
    s.all += one;
    s.by_room_type[o.room_type] += one;
  }
}

Result<GlbSettleSummary> SettleScene(const Result<SceneInfo>& info, const std::string& glb, const SettleOptions& options,
                                     const std::vector<std::string>& only, const std::set<std::string>* rooms = nullptr) {
  if (!info.ok()) return Error{info.error()};
  auto scene = ReadGlbBodies(*info, glb, only, rooms);
  if (!scene.ok()) return Error{scene.error()};
  GlbSettleSummary summary;
  summary.objects = std::move(scene->objects);
  summary.decals = scene->decals;
  const std::vector<TriangleMesh>& statics = scene->statics;
  const std::vector<SettleBody>& bodies = scene->bodies;
  auto settled = Settle(statics, bodies, options);
  if (!settled.ok()) return Error{glb + ": " + settled.error()};
  for (size_t i = 0; i < bodies.size(); ++i) summary.objects[i].motion = settled->bodies[i];
  CountStable(summary);
  summary.parts = settled->parts;
  summary.starts_inside = settled->starts_inside;
  summary.static_triangles = settled->static_triangles;
  summary.seconds = settled->seconds;
  return summary;
}

}  // namespace

Result<GlbSettleSummary> SettleGlb(const std::filesystem::path& glb, const SettleOptions& options,
                                   const std::vector<std::string>& only) {
  return SettleScene(ReadSceneInfo(glb), glb.string(), options, only);
}

Result<GlbSettleSummary> SettleGlbBytes(const std::string& glb, const SettleOptions& options) {
  return SettleScene(ReadSceneInfoFromMemory(glb, "glb"), "furnished.glb", options, {});
}

Result<GlbSettleSummary> ResettleRooms(const std::string& glb, const GlbSettleSummary& before, const std::set<std::string>& rooms,
                                       const SettleOptions& options) {
  auto part = SettleScene(ReadSceneInfoFromMemory(glb, "glb"), "furnished.glb", options, {}, &rooms);
  if (!part.ok()) return Error{part.error()};
  GlbSettleSummary out;
  for (const GlbObjectMotion& o : before.objects)
    if (!rooms.count(o.room)) out.objects.push_back(o);
  out.objects.insert(out.objects.end(), part->objects.begin(), part->objects.end());
  for (const GlbObjectMotion& o : out.objects) {
    out.starts_inside += o.motion.start_depth > kStartsInside;
    out.parts += o.motion.parts;
  }
  CountStable(out);
  out.decals = part->decals;
  out.static_triangles = part->static_triangles;
  out.seconds = part->seconds;
  return out;
}

nlohmann::ordered_json StabilityJson(const StabilityCount& c) {
  auto share = [&](int n) { return c.free > 0 ? static_cast<double>(n) / c.free : 1.0; };
  return {{"free", c.free}, {"strict", c.strict}, {"loose", c.loose}, {"strict_share", share(c.strict)}, {"loose_share", share(c.loose)}};
}

nlohmann::ordered_json SettleSummaryJson(const GlbSettleSummary& s, const SettleOptions& options, int movers) {
  std::vector<const GlbObjectMotion*> moved;
  for (const auto& o : s.objects)
    if (!o.motion.welded && !o.motion.strict) moved.push_back(&o);
  std::sort(moved.begin(), moved.end(), [](auto* a, auto* b) { return a->motion.moved > b->motion.moved; });
  if (static_cast<int>(moved.size()) > movers) moved.resize(movers);
  nlohmann::ordered_json by_type = nlohmann::ordered_json::object();
  for (const auto& [type, c] : s.by_room_type) by_type[type] = StabilityJson(c);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (auto* o : moved)
    list.push_back({{"id", o->id},
                    {"category", o->category},
                    {"moved_m", o->motion.moved},
                    {"turned_rad", o->motion.turned},
                    {"shift_m", {o->motion.shift.x, o->motion.shift.y, o->motion.shift.z}},
                    {"start_depth_m", o->motion.start_depth},
                    {"start_against", o->motion.start_against}});
  nlohmann::ordered_json inside = nlohmann::ordered_json::array();
  for (const auto& o : s.objects)
    if (o.motion.start_depth > kStartsInside)
      inside.push_back({{"id", o.id}, {"depth_m", o.motion.start_depth}, {"against", o.motion.start_against}});
  return {{"seconds_simulated", options.seconds}, {"all", StabilityJson(s.all)}, {"by_room_type", by_type},
          {"movers", list}, {"starts_inside", s.starts_inside}, {"inside", inside}, {"decals", s.decals},
          {"convex_parts", s.parts}, {"static_triangles", s.static_triangles}, {"seconds", s.seconds}};
}

}  // namespace villa::physics
