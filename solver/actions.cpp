#include "solver/actions.h"

#include <cmath>
#include <numbers>
#include <set>

#include "util/excerpt.h"

namespace villa::solver {
namespace {

constexpr std::string_view kKindNames[] = {"add_entity", "remove_entity", "update_pose", "update_scale"};
constexpr std::string_view kStatusNames[] = {"applied", "repaired", "refused"};
constexpr double kDeg = 180.0 / std::numbers::pi;

// SCENE.md: numbers in files carry at most 4 decimals.
double Round4(double v) { return std::round(v * 1e4) / 1e4; }

nlohmann::ordered_json PoseToJson(const Pose& p) {
  nlohmann::ordered_json j;
  j["x"] = Round4(p.x);
  j["y"] = Round4(p.y);
  j["z"] = Round4(p.z);
  j["yaw"] = Round4(WrapAngle(p.yaw) * kDeg);
  return j;
}

nlohmann::ordered_json EdgeToJson(const SemanticEdge& e) {
  nlohmann::ordered_json j;
  j["source"] = e.source;
  j["relation"] = std::string(SemanticRelationName(e.relation));
  j["target"] = e.target;
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  switch (e.relation) {
    case SemanticRelation::kFaceTo: params["max_deg"] = Round4(e.max_angle * kDeg); break;
    case SemanticRelation::kAlign: params["tolerance_deg"] = Round4(e.tolerance * kDeg); break;
    case SemanticRelation::kCentered: params["tolerance"] = Round4(e.tolerance); break;
    case SemanticRelation::kNextTo:
    case SemanticRelation::kNear:
    case SemanticRelation::kFar:
      params["min_gap"] = Round4(e.min_gap);
      if (e.max_gap < 1e8) params["max_gap"] = Round4(e.max_gap);
      break;
    default: break;
  }
  j["params"] = params;
  return j;
}

// Reads one JSON object strictly: every key must be known, each read checks its type.
class Reader {
 public:
  Reader(const nlohmann::json& json, std::string path, std::string* error) : json_(json), path_(std::move(path)), error_(error) {
    if (!json_.is_object()) Fail(path_ + ": must be an object");
  }
  bool ok() const { return error_->empty(); }
  void Fail(const std::string& message) {
    if (error_->empty()) *error_ = message;
  }
  bool Has(const std::string& key) const { return json_.is_object() && json_.contains(key); }
  const nlohmann::json& At(const std::string& key) const { return json_.at(key); }
  std::string Path(const std::string& key) const { return path_ + "." + key; }
  void Known(std::initializer_list<const char*> keys) {
    if (!json_.is_object()) return;
    std::set<std::string> allowed(keys.begin(), keys.end());
    for (auto it = json_.begin(); it != json_.end(); ++it) {
      if (!allowed.count(it.key())) Fail(path_ + ": unknown key \"" + Excerpt(it.key()) + "\"");
    }
  }
  std::string String(const std::string& key, bool required = true) {
    if (!Has(key)) {
      if (required) Fail(Path(key) + ": missing");
      return "";
    }
    if (!At(key).is_string()) {
      Fail(Path(key) + ": must be a string, is " + Excerpt(At(key).dump()));
      return "";
    }
    return At(key).get<std::string>();
  }
  std::optional<double> Number(const std::string& key, bool required, double lo, double hi) {
    if (!Has(key)) {
      if (required) Fail(Path(key) + ": missing");
      return std::nullopt;
    }
    if (!At(key).is_number() || !std::isfinite(At(key).get<double>())) {
      Fail(Path(key) + ": must be a number, is " + Excerpt(At(key).dump()));
      return std::nullopt;
    }
    const double v = At(key).get<double>();
    if (v < lo || v > hi) {
      Fail(Path(key) + ": " + Excerpt(At(key).dump()) + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
      return std::nullopt;
    }
    return v;
  }
  std::optional<int> Index(const std::string& key) {
    auto v = Number(key, false, -1, 1e6);
    if (v && *v != std::floor(*v)) {
      Fail(Path(key) + ": must be a whole number, is " + Excerpt(At(key).dump()));
      return std::nullopt;
    }
    return v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
  }

 private:
  const nlohmann::json& json_;
  std::string path_;
  std::string* error_;
};

std::optional<Pose> PoseFrom(const nlohmann::json& json, const std::string& path, std::string* error) {
  Reader r(json, path, error);
  r.Known({"x", "y", "z", "yaw"});
  Pose p;
  p.x = r.Number("x", true, -1e5, 1e5).value_or(0.0);
  p.y = r.Number("y", true, -1e5, 1e5).value_or(0.0);
  p.z = r.Number("z", false, -1e5, 1e5).value_or(std::nan(""));
  p.yaw = WrapAngle(r.Number("yaw", false, -1e5, 1e5).value_or(0.0) / kDeg);
  if (!r.ok()) return std::nullopt;
  return p;
}

std::optional<SemanticEdge> EdgeFrom(const nlohmann::json& json, const std::string& path, std::string* error) {
  Reader r(json, path, error);
  r.Known({"source", "relation", "target", "params"});
  const std::string relation = r.String("relation");
  auto kind = ParseSemanticRelation(relation);
  if (r.ok() && !kind) r.Fail(r.Path("relation") + ": unknown relation \"" + Excerpt(relation) + "\"");
  if (!r.ok()) return std::nullopt;
  SemanticEdge e = DefaultEdge(r.String("source"), *kind, r.String("target"));
  if (r.Has("params")) {
    Reader p(r.At("params"), r.Path("params"), error);
    p.Known({"max_deg", "tolerance_deg", "tolerance", "min_gap", "max_gap"});
    if (auto v = p.Number("max_deg", false, 0, 180)) e.max_angle = *v / kDeg;
    if (auto v = p.Number("tolerance_deg", false, 0, 45)) e.tolerance = *v / kDeg;
    if (auto v = p.Number("tolerance", false, 0, 10)) e.tolerance = *v;
    if (auto v = p.Number("min_gap", false, 0, 100)) e.min_gap = *v;
    if (auto v = p.Number("max_gap", false, 0, 100)) e.max_gap = *v;
  }
  if (!r.ok()) return std::nullopt;
  return e;
}

}  // namespace

std::string_view ActionKindName(ActionKind kind) { return kKindNames[static_cast<int>(kind)]; }
std::string_view ActionStatusName(ActionStatus status) { return kStatusNames[static_cast<int>(status)]; }

nlohmann::ordered_json ActionToJson(const Action& a) {
  nlohmann::ordered_json j;
  j["action"] = std::string(ActionKindName(a.kind));
  if (a.kind == ActionKind::kAddEntity && a.object) {
    const ProblemObject& o = *a.object;
    nlohmann::ordered_json obj;
    obj["id"] = o.id;
    obj["category"] = o.category;
    obj["asset"] = o.asset.id;
    obj["parent"] = o.parent;
    obj["relation"] = std::string(RelationName(o.relation));
    if (o.surface >= 0) obj["surface"] = o.surface;
    if (o.cavity >= 0) obj["cavity"] = o.cavity;
    if (o.wall >= 0) obj["wall"] = o.wall;
    obj["scale_range"] = {Round4(o.scale_min), Round4(o.scale_max)};
    obj["priority"] = std::string(PriorityName(o.priority));
    if (o.zone) obj["interaction_zone"] = {{"side", o.zone->side}, {"depth", Round4(o.zone->depth)}, {"exempt", o.zone->exempt}};
    j["object"] = obj;
    if (!a.edges.empty()) {
      j["edges"] = nlohmann::ordered_json::array();
      for (const SemanticEdge& e : a.edges) j["edges"].push_back(EdgeToJson(e));
    }
  } else {
    j["id"] = a.id;
  }
  if (a.pose) {
    nlohmann::ordered_json pose = PoseToJson(*a.pose);
    if (std::isnan(a.pose->z)) pose.erase("z");
    j["pose"] = pose;
  }
  if (a.surface) j["surface"] = *a.surface;
  if (a.cavity) j["cavity"] = *a.cavity;
  if (a.wall) j["wall"] = *a.wall;
  if (a.scale) j["scale"] = Round4(*a.scale);
  if (!a.reason.empty()) j["reason"] = a.reason;
  return j;
}

nlohmann::ordered_json ActionResultToJson(const ActionResult& r) {
  nlohmann::ordered_json j = ActionToJson(r.action);
  j["status"] = std::string(ActionStatusName(r.status));
  j["message"] = r.message;
  if (r.final_pose) j["final_pose"] = PoseToJson(*r.final_pose);
  if (!r.removed.empty()) j["removed"] = r.removed;
  return j;
}

Result<Action> ActionFromJson(const nlohmann::json& json, const std::string& where, const AssetResolver& resolve) {
  std::string error;
  Reader r(json, where, &error);
  r.Known({"action", "id", "object", "edges", "pose", "surface", "cavity", "wall", "scale", "reason"});
  Action a;
  const std::string name = r.String("action");
  bool known = false;
  for (int k = 0; k < 4; ++k) {
    if (kKindNames[k] == name) {
      a.kind = static_cast<ActionKind>(k);
      known = true;
    }
  }
  if (r.ok() && !known) r.Fail(r.Path("action") + ": unknown action \"" + Excerpt(name) + "\"");
  a.reason = r.String("reason", false);
  if (!r.ok()) return Error{error};

  if (r.Has("pose")) {
    if (auto pose = PoseFrom(r.At("pose"), r.Path("pose"), &error)) a.pose = pose;
  }
  a.surface = r.Index("surface");
  a.cavity = r.Index("cavity");
  a.wall = r.Index("wall");
  if (a.kind == ActionKind::kAddEntity) {
    if (!r.Has("object")) return Error{r.Path("object") + ": missing (add_entity needs the new object)"};
    Reader o(r.At("object"), r.Path("object"), &error);
    o.Known({"id", "category", "asset", "parent", "relation", "surface", "cavity", "wall", "scale_range", "priority",
             "interaction_zone"});
    ProblemObject obj;
    obj.id = o.String("id");
    obj.category = o.String("category");
    const std::string asset = o.String("asset");
    obj.parent = o.String("parent");
    const std::string relation = o.String("relation");
    if (o.ok()) {
      auto rel = ParseRelation(relation);
      if (!rel) return Error{o.Path("relation") + ": unknown relation \"" + Excerpt(relation) + "\""};
      obj.relation = *rel;
    }
    obj.surface = o.Index("surface").value_or(-1);
    obj.cavity = o.Index("cavity").value_or(-1);
    obj.wall = o.Index("wall").value_or(-1);
    if (o.Has("scale_range")) {
      const nlohmann::json& range = o.At("scale_range");
      if (!range.is_array() || range.size() != 2 || !range[0].is_number() || !range[1].is_number()) {
        return Error{o.Path("scale_range") + ": must be [lo, hi], is " + Excerpt(range.dump())};
      }
      obj.scale_min = range[0].get<double>();
      obj.scale_max = range[1].get<double>();
    }
    const std::string priority = o.String("priority", false);
    if (!priority.empty()) {
      auto p = ParsePriority(priority);
      if (!p) return Error{o.Path("priority") + ": unknown priority \"" + Excerpt(priority) + "\""};
      obj.priority = *p;
    }
    if (o.Has("interaction_zone")) {
      Reader z(o.At("interaction_zone"), o.Path("interaction_zone"), &error);
      z.Known({"side", "depth", "exempt"});
      InteractionZone zone;
      zone.side = z.String("side");
      zone.depth = z.Number("depth", true, 0, 3).value_or(0.0);
      if (z.Has("exempt")) {
        const nlohmann::json& ex = z.At("exempt");
        if (!ex.is_array()) return Error{z.Path("exempt") + ": must be an array of ids"};
        for (const auto& id : ex) {
          if (!id.is_string()) return Error{z.Path("exempt") + ": must hold strings, has " + Excerpt(id.dump())};
          zone.exempt.push_back(id.get<std::string>());
        }
      }
      obj.zone = zone;
    }
    if (!error.empty()) return Error{error};
    if (!resolve) return Error{o.Path("asset") + ": no asset library to resolve \"" + Excerpt(asset) + "\""};
    auto resolved = resolve(asset);
    if (!resolved.ok()) return Error{o.Path("asset") + ": " + resolved.error()};
    obj.asset = resolved->first;
    obj.mesh = resolved->second;
    a.id = obj.id;
    a.object = obj;
    if (r.Has("edges")) {
      const nlohmann::json& edges = r.At("edges");
      if (!edges.is_array()) return Error{r.Path("edges") + ": must be an array"};
      for (size_t k = 0; k < edges.size(); ++k) {
        auto e = EdgeFrom(edges[k], r.Path("edges") + "[" + std::to_string(k) + "]", &error);
        if (!e) return Error{error};
        a.edges.push_back(*e);
      }
    }
  } else {
    a.id = r.String("id");
  }
  if (a.kind == ActionKind::kUpdateScale) a.scale = r.Number("scale", true, 0.1, 10.0);
  if (a.kind == ActionKind::kUpdatePose && r.Has("scale")) a.scale = r.Number("scale", true, 0.1, 10.0);  // moved and resized
  if (a.kind == ActionKind::kUpdatePose && !r.Has("pose")) r.Fail(r.Path("pose") + ": missing (update_pose needs a pose)");
  if (!error.empty()) return Error{error};
  return a;
}

}  // namespace villa::solver
