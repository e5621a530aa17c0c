#include "solver/reach_feedback.h"

#include <chrono>
#include <cmath>
#include <set>

#include "mesh/geometry2d.h"
#include "solver/free_space.h"

namespace villa::solver {
namespace {

using namespace villa::geo;

std::string Fixed(double v, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

// Rectangles along a way on one level, `half` m either side and beyond each end (so consecutive pieces
// overlap at the corners), kept where they come within 0.5 m of the room's bounding box.
std::vector<KeepOut> WalkwayPieces(const std::vector<std::pair<int, std::vector<Point>>>& way, int level, double floor_z,
                                   double head, double half, const Ring& room, const std::string& target) {
  Point lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (const Point& p : room) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  std::vector<KeepOut> out;
  for (const auto& [l, points] : way) {
    if (l != level || points.empty()) continue;
    for (size_t k = 0; k + 1 < points.size() || (points.size() == 1 && k == 0); ++k) {
      const Point a = points[k], b = points.size() == 1 ? points[k] : points[k + 1];
      const Point d = Dist(a, b) > 1e-9 ? Unit(Sub(b, a)) : Point{1.0, 0.0};
      const Point n = Left(d);
      const Point a0 = Sub(a, Scale(d, half)), b0 = Add(b, Scale(d, half));
      Ring rect = {Sub(a0, Scale(n, half)), Sub(b0, Scale(n, half)), Add(b0, Scale(n, half)), Add(a0, Scale(n, half))};
      bool near = false;
      for (const Point& p : rect) near |= p.x >= lo.x - 0.5 && p.x <= hi.x + 0.5 && p.y >= lo.y - 0.5 && p.y <= hi.y + 0.5;
      if (near) out.push_back({std::move(rect), floor_z, floor_z + head, KeepOutKind::kWalkway, "to " + target});
    }
  }
  return out;
}

}  // namespace

bool ReachFeedbackOptions::IsValid(std::string* message) const {
  if (!reach.IsValid(message)) return false;
  if (rounds < 0 || rounds > 20) {
    if (message) *message = "rounds must be in [0, 20], is " + std::to_string(rounds);
    return false;
  }
  if (!(walkway_margin >= 0.0 && walkway_margin <= 0.5)) {
    if (message) *message = "walkway_margin must be in [0, 0.5] m, is " + Fixed(walkway_margin, 3);
    return false;
  }
  return true;
}

std::vector<ReachObject> ReachObjectsOf(const RoomSolution& solution, const std::string& room, int level) {
  std::vector<ReachObject> out;
  const size_t n = std::min(solution.objects.size(), solution.placements.size());
  for (size_t i = 0; i < n; ++i) {
    const ProblemObject& o = solution.objects[i];
    const ObjectPlacement& pl = solution.placements[i];
    if (!pl.placed) continue;
    ReachObject r;
    r.id = o.id;
    r.room = room;
    r.level = level;
    r.box = StandingBox(o, pl.pose);
    r.covering = IsFloorCovering(o);
    std::optional<InteractionZone> zone = o.zone;
    if (!zone && o.asset.interaction_zone && o.asset.Has(kInteractor)) {
      zone = InteractionZone{o.asset.interaction_zone->side, o.asset.interaction_zone->depth, {}};
    }
    const bool hung = o.relation == Relation::kOnWall || o.relation == Relation::kHanging;
    if (zone && zone->depth > 0.0 && !hung) {
      r.zone = ZoneFootprints(r.box, zone->side, zone->depth * pl.pose.scale);
      for (const std::string& id : zone->exempt) {
        for (size_t j = 0; j < n; ++j) {
          if (solution.objects[j].id != id || !solution.placements[j].placed) continue;
          const PlanShape other = PlanShape::Polygon(StandingBox(solution.objects[j], solution.placements[j].pose).Footprint());
          for (const Ring& z : r.zone) r.zone_shared |= PlanClearance(PlanShape::Polygon(z), other) < 0.0;
        }
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

Result<FeedbackSummary> FreeBlockedWays(const ReachInput& building, const std::map<std::string, RoomSolver*>& solvers,
                                        const ReachFeedbackOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  if (!options.IsValid(&message)) return Error{"reach feedback options: " + message};
  std::map<std::string, const ReachTarget*> rooms;
  for (const ReachTarget& t : building.targets) {
    if (t.kind == TargetKind::kRoom) rooms[t.name] = &t;
  }
  // The objects as last checked: room, footprint (world), its area, whether it stands on the floor.
  struct Seen {
    std::string room;
    Ring footprint;
    double area = 0.0;
    bool on_floor = false;
  };
  std::map<std::string, Seen> seen;
  auto check = [&]() -> Result<ReachReport> {
    ReachInput input = building;
    std::vector<ReachObject> objects;
    seen.clear();
    for (const auto& [name, solver] : solvers) {
      const auto it = rooms.find(name);
      const int level = it != rooms.end() ? it->second->level : 0;
      const double floor_z = level < static_cast<int>(building.levels.size()) ? building.levels[level].floor_z : 0.0;
      for (ReachObject& o : ReachObjectsOf(solver->Solution(), name, level)) {
        seen[o.id] = {name, o.box.Footprint(), 4.0 * o.box.hx * o.box.hy, o.box.z0 <= floor_z + 0.02};
        objects.push_back(std::move(o));
      }
    }
    AddObjects(input, objects, options.reach);
    return CheckReach(input, options.reach);
  };
  auto first = check();
  if (!first.ok()) return Error{first.error()};
  FeedbackSummary summary;
  summary.first = *first;
  ReachReport report = *first;
  const double half = options.reach.radius + options.walkway_margin;
  for (int round = 0;; ++round) {
    std::vector<std::string> unreachable;
    for (const TargetResult& t : report.targets) {
      if (!t.reachable) unreachable.push_back(t.name);
    }
    if (unreachable.empty()) {
      summary.all_reachable = true;
      summary.reason = round == 0 ? "every room and zone reachable" : "every room and zone reachable after " + std::to_string(round) + " round(s)";
      break;
    }
    if (round == options.rounds) {
      summary.reason = std::to_string(unreachable.size()) + " target(s) still unreachable after " + std::to_string(round) + " round(s)";
      break;
    }
    FeedbackRound fr;
    fr.unreachable = unreachable;
    std::map<std::string, std::vector<KeepOut>> lay;
    std::set<std::string> rooms_unreached;
    for (const TargetResult& t : report.targets) {
      if (t.kind == TargetKind::kRoom && !t.reachable) rooms_unreached.insert(t.name);
    }
    for (const TargetResult& t : report.targets) {
      if (t.reachable || t.structural) continue;
      if (t.kind == TargetKind::kZone) {
        // A zone in a room that cannot be entered waits for the room's walkway.
        if (rooms_unreached.count(t.room)) continue;
        const auto owner = seen.find(t.name);
        if (owner == seen.end()) continue;
        bool clearable = !t.blockers.empty() && t.door_leaves.empty();
        for (const std::string& id : t.blockers) {
          if (auto b = seen.find(id); b != seen.end() && b->second.area > owner->second.area + 1e-9) clearable = false;
        }
        if (!clearable) {
          const Seen& o = owner->second;
          const auto r = rooms.find(o.room);
          if (!o.on_floor || r == rooms.end() || !solvers.count(o.room)) continue;
          const double floor_z = building.levels[r->second->level].floor_z;
          fr.walkways.push_back({o.room, t.name, 1, "spot"});
          lay[o.room].push_back({o.footprint, floor_z, floor_z + options.reach.head_height, KeepOutKind::kWalkway,
                                 "the unreachable place of " + t.name});
          continue;
        }
      }
      if (t.blockers.empty()) continue;
      std::set<std::string> holders;
      for (const std::string& id : t.blockers) {
        if (auto it = seen.find(id); it != seen.end()) holders.insert(it->second.room);
      }
      for (const std::string& room : holders) {
        const auto r = rooms.find(room);
        if (r == rooms.end() || !solvers.count(room)) continue;
        const int level = r->second->level;
        std::vector<KeepOut> pieces = WalkwayPieces(t.blocked_way, level, building.levels[level].floor_z, options.reach.head_height,
                                                    half, r->second->areas.front().polygon, t.name);
        if (pieces.empty()) continue;
        fr.walkways.push_back({room, t.name, static_cast<int>(pieces.size()), "walkway"});
        auto& list = lay[room];
        list.insert(list.end(), pieces.begin(), pieces.end());
      }
    }
    if (lay.empty()) {
      summary.reason = std::to_string(unreachable.size()) +
                       " target(s) unreachable, none that moving furniture can help (walls, stairs, holes or door leaves close them)";
      summary.rounds.push_back(std::move(fr));
      break;
    }
    for (const auto& [room, zones] : lay) {
      RoomSolver* solver = solvers.at(room);
      const size_t before = solver->Solution().summary.actions.size();
      if (Status s = solver->AddKeepOuts(zones); !s.ok()) return Error{"room " + room + ": walkway: " + s.error()};
      solver->RunAgent();
      const RoomSolution after = solver->Solution();
      for (size_t k = before; k < after.summary.actions.size(); ++k) fr.actions.push_back({room, after.summary.actions[k]});
    }
    summary.rounds.push_back(std::move(fr));
    auto next = check();
    if (!next.ok()) return Error{next.error()};
    report = std::move(*next);
  }
  summary.last = std::move(report);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

std::string FeedbackSummary::BriefReport() const {
  std::string out = "reach feedback: " + reason + " (RCH " + Fixed(first.Rch(), 3) + " -> " + Fixed(last.Rch(), 3) + ", ACC " +
                    Fixed(first.Acc(), 3) + " -> " + Fixed(last.Acc(), 3) + ")\n";
  for (size_t r = 0; r < rounds.size(); ++r) {
    out += "  round " + std::to_string(r + 1) + ": " + std::to_string(rounds[r].unreachable.size()) + " unreachable, " +
           std::to_string(rounds[r].walkways.size()) + " walkway(s)";
    for (const RoomAction& a : rounds[r].actions) {
      out += "; " + a.room + ": " + std::string(ActionKindName(a.result.action.kind)) + " " + a.result.action.id + " (" +
             std::string(ActionStatusName(a.result.status)) + ")";
    }
    out += "\n";
  }
  return out;
}

nlohmann::ordered_json FeedbackSummary::ToJson() const {
  nlohmann::ordered_json j;
  j["all_reachable"] = all_reachable;
  j["reason"] = reason;
  j["rch_before"] = std::round(first.Rch() * 1e4) / 1e4;
  j["acc_before"] = std::round(first.Acc() * 1e4) / 1e4;
  j["rooms_reachable_before"] = first.rooms_reachable;
  j["zones_reachable_before"] = first.zones_reachable;
  j["rounds"] = nlohmann::ordered_json::array();
  for (const FeedbackRound& r : rounds) {
    nlohmann::ordered_json jr;
    jr["unreachable"] = r.unreachable;
    jr["walkways"] = nlohmann::ordered_json::array();
    for (const Walkway& w : r.walkways)
      jr["walkways"].push_back({{"room", w.room}, {"target", w.target}, {"kind", w.kind}, {"pieces", w.pieces}});
    jr["actions"] = nlohmann::ordered_json::array();
    for (const RoomAction& a : r.actions) {
      nlohmann::ordered_json ja = ActionResultToJson(a.result);
      ja["room"] = a.room;
      jr["actions"].push_back(std::move(ja));
    }
    j["rounds"].push_back(std::move(jr));
  }
  return j;
}

}  // namespace villa::solver
