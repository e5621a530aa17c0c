#include "critic/observation.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace villa::critic {
namespace {

std::string Fixed(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, std::abs(v) < 0.5 * std::pow(10.0, -digits) ? 0.0 : v);
  return text;
}
double Degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

std::string Point2(const Point& p) { return std::string("(") + Fixed(p.x, 2) + ", " + Fixed(p.y, 2) + ")"; }

std::string Physical(const std::string& room, const solver::ProblemObject& o, const solver::ObjectPlacement& pl) {
  std::string out(solver::RelationName(o.relation));
  if (o.relation == solver::Relation::kAgainstWall || o.relation == solver::Relation::kOnWall)
    return out + " wall " + std::to_string(pl.wall);
  if (o.parent == "floor" || o.parent == "ceiling") return out + " " + o.parent;
  out += ' ';
  out += ShortId(room, o.parent);
  if (o.relation == solver::Relation::kOnTop && pl.surface >= 0) out += " surface " + std::to_string(pl.surface);
  if (o.relation == solver::Relation::kInside && pl.cavity >= 0) out += " cavity " + std::to_string(pl.cavity);
  return out;
}

}  // namespace

std::string ShortId(const std::string& room, const std::string& id) {
  if (id.size() > room.size() + 1 && id.compare(0, room.size(), room) == 0 && id[room.size()] == '/') return id.substr(room.size() + 1);
  return id;
}

std::string FullId(const std::string& room, const std::string& id) {
  if (id.compare(0, room.size() + 1, room + "/") == 0) return id;
  return room + "/" + id;
}

std::string RoomStateText(const solver::RoomCriticInput& input, const solver::RoomSolution& solution,
                          const RoomRelations& relations, const std::vector<solver::ActionResult>& last) {
  const solver::RoomProblem& problem = *input.problem;
  const std::string& room = problem.room;
  std::string out;
  out += "room " + room + " (" + std::string(CategoryDisplayName(input.context->category)) + ", level " +
         std::to_string(input.context->level) + "), floor at z " + Fixed(problem.floor_z, 3) + " m, ceiling " +
         Fixed(problem.clear_height, 2) + " m above it\n";
  out += "free floor (m, counter-clockwise):";
  for (const Point& p : problem.free_floor) out += ' ' + Point2(p);
  out += "\nwalls (index: from -> to; the room is on the left; openings as m along the wall):\n";
  for (size_t w = 0; w < problem.walls.size(); ++w) {
    const solver::WallEdge& wall = problem.walls[w];
    out += "  " + std::to_string(w) + ": " + Point2(wall.a) + " -> " + Point2(wall.b);
    for (const solver::WallOpening& o : wall.openings)
      out += ", opening " + Fixed(o.t0, 2) + "-" + Fixed(o.t1, 2) + " m from z " + Fixed(o.z0 - problem.floor_z, 2) + " to " +
             Fixed(o.z1 - problem.floor_z, 2);
    out += "\n";
  }
  // Hard keep-outs, then the corridors a person walks through the room (issue 27's circulation: better
  // free, not a constraint).
  for (const bool hard : {true, false}) {
    std::string lines;
    for (const solver::KeepOut& k : problem.keep_outs) {
      if ((k.kind == solver::KeepOutKind::kCirculation) == hard) continue;
      lines += "  " + std::string(solver::KeepOutKindName(k.kind)) + ":";
      for (const Point& p : k.polygon) lines += ' ' + Point2(p);
      lines += "\n";
    }
    if (!lines.empty()) out += (hard ? "keep free (no object may enter):\n" : "walked through (better left free):\n") + lines;
  }
  out += "objects (id: category; physical edge; centre x, y and bottom z in m; yaw in degrees, 0 faces -y, 90 faces +x; "
         "size w x d x h in m; scale):\n";
  for (size_t i = 0; i < solution.objects.size(); ++i) {
    const solver::ProblemObject& o = solution.objects[i];
    const solver::ObjectPlacement& pl = solution.placements[i];
    const double k = pl.pose.scale;
    out += "  " + ShortId(room, o.id) + ": " + o.category + "; " + Physical(room, o, pl) + "; " + Fixed(pl.pose.x, 2) + ", " +
           Fixed(pl.pose.y, 2) + ", " + Fixed(pl.pose.z, 2) + "; " + Fixed(Degrees(pl.pose.yaw), 0) + "; " +
           Fixed(o.asset.size.x * k, 2) + " x " + Fixed(o.asset.size.y * k, 2) + " x " + Fixed(o.asset.size.z * k, 2) +
           "; " + Fixed(k, 2) + "\n";
  }
  out += "relations of the graph (ok / UNMET):\n";
  for (const EdgeCheck& c : relations.edges) {
    if (!c.present) continue;
    out += std::string(c.satisfied ? "  ok    " : "  UNMET ") + ShortId(room, c.edge.source) + " " +
           std::string(scene::SemanticRelationName(c.edge.relation)) + " " + ShortId(room, c.edge.target) + ": " + c.detail + "\n";
  }
  if (!relations.zones.empty()) {
    out += "interaction zones (kept free in front of or beside an object):\n";
    for (const ZoneCheck& z : relations.zones) {
      out += "  " + ShortId(room, z.owner) + " " + z.side + " " + Fixed(z.depth, 2) + " m: ";
      if (z.clear()) {
        out += "clear\n";
        continue;
      }
      out += "entered by";
      for (const std::string& id : z.intruders) out += ' ' + ShortId(room, id);
      out += "\n";
    }
  }
  const solver::EnergyTerms& e = solution.summary.energy;
  out += "energy: E " + Fixed(e.total, 3) + " = 5 x " + Fixed(e.collision, 4) + " (box overlaps, m3) + 2 x " + Fixed(e.support, 3) +
         " (support) + " + Fixed(e.semantic, 3) + " (unmet relations and zones)\n";
  const solver::ExactMetrics& m = solution.summary.metrics;
  if (m.Clean()) {
    out += "exact check: clean (no collision, nothing floating, nothing out of the room)\n";
  } else {
    out += "exact check:";
    for (const solver::CollisionPair& p : m.pairs) out += " collision " + ShortId(room, p.a) + " x " + ShortId(room, p.b) + ";";
    for (const solver::ObjectCheck& c : m.per_object) {
      if (c.floating) out += " floating " + ShortId(room, c.id) + ";";
      if (c.out_of_bounds) out += " out of the room " + ShortId(room, c.id) + ";";
      if (c.inside_edge && !c.contained) out += " not inside its cavity " + ShortId(room, c.id) + ";";
    }
    out += "\n";
  }
  if (!last.empty()) {
    out += "your last actions and what the solver did with them:\n";
    for (const solver::ActionResult& r : last)
      out += "  " + std::string(solver::ActionKindName(r.action.kind)) + " " + ShortId(room, r.action.id) + ": " +
             std::string(solver::ActionStatusName(r.status)) + " (" + r.message + ")\n";
  }
  return out;
}

Result<std::vector<solver::RoomViewImage>> RoomViews(const solver::RoomCriticInput& input, const solver::RoomSolution& solution,
                                                     const solver::RoomViewOptions& options) {
  solver::RoomViewInput view;
  view.building = input.building;
  view.room = input.context->name;
  view.level = input.context->level;
  view.polygon = input.context->polygon;
  view.floor_z = input.context->floor_z;
  view.clear_height = input.context->clear_height;
  for (size_t i = 0; i < solution.objects.size(); ++i) {
    const solver::ProblemObject& o = solution.objects[i];
    if (!solution.placements[i].placed) continue;
    view.objects.push_back({ShortId(input.problem->room, o.id), o.mesh, solution.placements[i].pose});
  }
  return solver::RenderRoomViews(view, options);
}

}  // namespace villa::critic
