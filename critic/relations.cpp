#include "critic/relations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

namespace villa::critic {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// The measures' resolution: a relation within a millimetre (lengths) or a tenth of a degree (angles) of
// its bound holds; finer misses are the optimiser's float noise, not something a person could see.
constexpr double kSlack = 1e-3;
constexpr double kAngleSlack = 0.1;

std::string Fixed(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

// The source's centre in the target's frame: (along the target's x, along its y).
std::pair<double, double> InFrameOf(const ObjectBox& target, const ObjectBox& p) {
  const Point d{p.c.x - target.c.x, p.c.y - target.c.y}, u = target.U(), v = target.V();
  return {d.x * u.x + d.y * u.y, d.x * v.x + d.y * v.y};
}

std::string GapRange(double lo, const std::optional<double>& hi) {
  return "[" + Fixed(lo, 2) + ", " + (hi ? Fixed(*hi, 2) : std::string("inf")) + "]";
}

bool FloorCovering(const solver::ProblemObject& o, double scale) {
  return o.parent == "floor" && o.relation == solver::Relation::kOnTop && o.asset.size.z * scale <= 0.03;
}

}  // namespace

ObjectBox BoxOf(const solver::ProblemObject& object, const solver::ObjectPlacement& placement) {
  const solver::Pose& p = placement.pose;
  return {{p.x, p.y}, p.yaw, 0.5 * object.asset.size.x * p.scale, 0.5 * object.asset.size.y * p.scale, p.z,
          p.z + object.asset.size.z * p.scale};
}


EdgeCheck CheckEdge(const scene::SemanticEdge& edge, const ObjectBox& s, const ObjectBox& t) {
  EdgeCheck c;
  c.edge = edge;
  const scene::EdgeParams p = scene::EffectiveParams(edge.relation, edge.params);
  auto gap_check = [&](double lo, const std::optional<double>& hi) {
    const double gap = PlanGap(s, t);
    const bool ok = gap >= lo - kSlack && (!hi || gap <= *hi + kSlack);
    c.violation += std::max(0.0, lo - gap) + (hi ? std::max(0.0, gap - *hi) : 0.0);
    return std::pair{ok, "gap " + Fixed(gap, 2) + " m, wanted " + GapRange(lo, hi)};
  };
  using R = scene::SemanticRelation;
  switch (edge.relation) {
    case R::kFaceTo: {
      const double fx = std::sin(s.yaw), fy = -std::cos(s.yaw);
      const double dx = t.c.x - s.c.x, dy = t.c.y - s.c.y;
      const double angle = std::abs(std::atan2(fx * dy - fy * dx, fx * dx + fy * dy + 1e-12)) / kDeg;
      c.value = angle;
      c.satisfied = angle <= *p.max_deg + kAngleSlack;
      c.violation = std::max(0.0, angle - *p.max_deg) / 30.0;
      c.detail = "facing off by " + Fixed(angle, 1) + " deg, at most " + Fixed(*p.max_deg, 0);
      break;
    }
    case R::kFrontOf:
    case R::kBehind:
    case R::kLeftOf:
    case R::kRightOf: {
      const auto [qx, qy] = InFrameOf(t, s);
      // The source's centre in the target's band on that side: past the target's centre line (`beyond`, m)
      // and within the target's extent across it (`outside` < 0).
      const bool depthwise = edge.relation == R::kFrontOf || edge.relation == R::kBehind;
      const double beyond = edge.relation == R::kFrontOf ? -qy : edge.relation == R::kBehind ? qy : edge.relation == R::kLeftOf ? qx : -qx;
      const double outside = depthwise ? std::abs(qx) - t.hx : std::abs(qy) - t.hy;
      c.value = beyond;
      c.satisfied = beyond >= -kSlack && outside <= kSlack;
      c.violation = std::max(0.0, -beyond) + std::max(0.0, outside);
      const char* face = edge.relation == R::kFrontOf ? "front" : edge.relation == R::kBehind ? "back" : edge.relation == R::kLeftOf ? "left" : "right";
      c.detail = "centre " + Fixed(beyond, 2) + " m to the target's " + face + " of its centre, " +
                 (outside <= kSlack ? std::string("within its width") : Fixed(outside, 2) + " m beyond its side");
      // The gap range only when the edge names one (the sides alone say nothing of distance).
      if (edge.params.min_gap || edge.params.max_gap) {
        auto [ok, words] = gap_check(edge.params.min_gap.value_or(0.0), edge.params.max_gap);
        c.satisfied = c.satisfied && ok;
        c.detail += "; " + words;
      }
      break;
    }
    case R::kNextTo:
    case R::kNear:
    case R::kFar: {
      auto [ok, words] = gap_check(*p.min_gap, p.max_gap);
      c.value = PlanGap(s, t);
      c.satisfied = ok;
      c.detail = words;
      break;
    }
    case R::kAlign: {
      const double d = 4.0 * (s.yaw - t.yaw);
      const double deviation = std::abs(std::atan2(std::sin(d), std::cos(d)) / 4.0) / kDeg;
      c.value = deviation;
      c.satisfied = deviation <= *p.max_deg + kAngleSlack;
      c.violation = std::max(0.0, deviation - *p.max_deg) / 30.0;
      c.detail = "turned " + Fixed(deviation, 1) + " deg from the target's axes, at most " + Fixed(*p.max_deg, 0);
      break;
    }
    case R::kCentered: {
      const double lateral = std::abs(InFrameOf(t, s).first);
      c.value = lateral;
      c.satisfied = lateral <= *p.max_offset + kSlack;
      c.violation = std::max(0.0, lateral - *p.max_offset);
      c.detail = "off the target's axis by " + Fixed(lateral, 3) + " m, at most " + Fixed(*p.max_offset, 3);
      break;
    }
  }
  return c;
}

int RoomRelations::Satisfied() const {
  return static_cast<int>(std::count_if(edges.begin(), edges.end(), [](const EdgeCheck& c) { return c.present && c.satisfied; }));
}
int RoomRelations::Present() const {
  return static_cast<int>(std::count_if(edges.begin(), edges.end(), [](const EdgeCheck& c) { return c.present; }));
}
int RoomRelations::ZonesClear() const {
  return static_cast<int>(std::count_if(zones.begin(), zones.end(), [](const ZoneCheck& z) { return z.clear(); }));
}

RoomRelations MeasureRelations(const std::vector<solver::ProblemObject>& objects,
                               const std::vector<solver::ObjectPlacement>& placements,
                               const std::vector<scene::SemanticEdge>& edges) {
  RoomRelations out;
  std::map<std::string, size_t> index;
  std::vector<ObjectBox> boxes;
  for (size_t i = 0; i < objects.size(); ++i) {
    index[objects[i].id] = i;
    boxes.push_back(BoxOf(objects[i], placements[i]));
  }
  for (const scene::SemanticEdge& e : edges) {
    auto s = index.find(e.source), t = index.find(e.target);
    if (s == index.end() || t == index.end()) {
      EdgeCheck c;
      c.edge = e;
      c.present = false;
      c.detail = "an object of the edge is not in the room";
      out.edges.push_back(std::move(c));
      continue;
    }
    out.edges.push_back(CheckEdge(e, boxes[s->second], boxes[t->second]));
  }

  // Ancestors by index, for the exemptions (what stands on an exempt object is exempt too).
  auto ancestors_include = [&](size_t other, size_t owner) {
    const solver::ProblemObject& o = objects[owner];
    for (size_t a = other;;) {
      if (a == owner) return true;
      if (o.zone && std::find(o.zone->exempt.begin(), o.zone->exempt.end(), objects[a].id) != o.zone->exempt.end()) return true;
      auto p = index.find(objects[a].parent);
      if (p == index.end()) return false;
      a = p->second;
    }
  };
  for (size_t i = 0; i < objects.size(); ++i) {
    const solver::ProblemObject& o = objects[i];
    std::optional<solver::InteractionZone> zone = o.zone;
    if (!zone && o.asset.interaction_zone && o.asset.Has(kInteractor))
      zone = solver::InteractionZone{o.asset.interaction_zone->side, o.asset.interaction_zone->depth, {}};
    if (!zone || zone->depth <= 0.0 || o.relation == solver::Relation::kOnWall || o.relation == solver::Relation::kHanging) continue;
    ZoneCheck check{o.id, zone->side, zone->depth, {}};
    const ObjectBox& b = boxes[i];
    const double k = placements[i].pose.scale, d = zone->depth * k;
    // Zone boxes in the owner's frame: centre offset, half sizes.
    struct Local {
      double cx, cy, hx, hy;
    };
    std::vector<Local> locals;
    if (zone->side == "front" || zone->side == "back")
      locals.push_back({0.0, (zone->side == "front" ? -1.0 : 1.0) * (b.hy + 0.5 * d), b.hx, 0.5 * d});
    else if (zone->side == "left" || zone->side == "right")
      locals.push_back({(zone->side == "left" ? 1.0 : -1.0) * (b.hx + 0.5 * d), 0.0, 0.5 * d, b.hy});
    else
      locals = {{b.hx + 0.5 * d, 0.0, 0.5 * d, b.hy}, {-(b.hx + 0.5 * d), 0.0, 0.5 * d, b.hy}};
    std::set<std::string> seen;
    for (const Local& l : locals) {
      const Point u = b.U(), v = b.V();
      const ObjectBox zone_box{{b.c.x + u.x * l.cx + v.x * l.cy, b.c.y + u.y * l.cx + v.y * l.cy}, b.yaw, l.hx, l.hy, b.z0, b.z1};
      for (size_t j = 0; j < objects.size(); ++j) {
        if (j == i || FloorCovering(objects[j], placements[j].pose.scale) || ancestors_include(j, i)) continue;
        const ObjectBox& other = boxes[j];
        if (std::min(other.z1, zone_box.z1) - std::max(other.z0, zone_box.z0) <= 0.0) continue;
        if (PlanGap(zone_box, other) < -kSlack && seen.insert(objects[j].id).second) check.intruders.push_back(objects[j].id);
      }
    }
    out.zones.push_back(std::move(check));
  }
  return out;
}

void AddToTally(const RoomRelations& relations, RelationTally& tally) {
  for (const EdgeCheck& c : relations.edges) {
    RelationCount& n = tally[std::string(scene::SemanticRelationName(c.edge.relation))];
    if (!c.present) {
      ++n.lost;
      continue;
    }
    ++n.measured;
    n.satisfied += c.satisfied;
  }
  for (const ZoneCheck& z : relations.zones) {
    RelationCount& n = tally["zone"];
    ++n.measured;
    n.satisfied += z.clear();
  }
}

nlohmann::ordered_json TallyJson(const RelationTally& tally) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [name, n] : tally) j[name] = {{"satisfied", n.satisfied}, {"measured", n.measured}, {"lost", n.lost}};
  return j;
}

RelationTally TallyFromJson(const nlohmann::json& json) {
  RelationTally tally;
  if (!json.is_object()) return tally;
  for (const auto& [name, n] : json.items())
    tally[name] = {n.value("satisfied", 0), n.value("measured", 0), n.value("lost", 0)};
  return tally;
}

}  // namespace villa::critic
