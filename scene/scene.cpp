#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <regex>

#include "util/atomic_file.h"

namespace villa::scene {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

template <class E, size_t N>
std::optional<E> ParseName(const std::array<std::string_view, N>& names, std::string_view name) {
  for (size_t i = 0; i < N; ++i)
    if (names[i] == name) return static_cast<E>(i);
  return std::nullopt;
}

template <size_t N>
std::string OneOf(const std::array<std::string_view, N>& names) {
  std::string out;
  for (size_t i = 0; i < N; ++i) out += (i ? ", " : "") + std::string(names[i]);
  return out;
}

constexpr std::array<std::string_view, 5> kRelationNames = {"ontop", "inside", "against_wall", "on_wall", "hanging"};
constexpr std::array<std::string_view, kSemanticRelationCount> kSemanticNames = {
    "face_to", "front_of", "behind", "left_of", "right_of", "next_to", "near", "far", "align", "centered"};
constexpr std::array<std::string_view, 3> kOriginNames = {"prompt", "prior", "critic"};
constexpr std::array<std::string_view, 3> kOutcomeNames = {"converged", "budget", "infeasible"};
constexpr std::array<std::string_view, 9> kMetricNames = {"CR", "FR", "OBR", "CSR", "NO", "NAV", "ACC", "OPC", "RCH"};
constexpr std::array<std::string_view, 5> kHints = {kHintFarFromDoor, kHintNearWindow, kHintMiddle, kHintCorner, kHintOpenFloor};
constexpr std::array<std::string_view, 5> kZoneSides = {"front", "back", "left", "right", "sides"};

// ---------------------------------------------------------------------------------------------------
// Writing

Json Num(double v) { return Round4(v); }

Json Vec(const Vec3& v) { return Json::array({Num(v.x), Num(v.y), Num(v.z)}); }

Json ParamsJson(const EdgeParams& p) {
  Json out = Json::object();
  if (p.max_deg) out["max_deg"] = Num(*p.max_deg);
  if (p.min_gap) out["min_gap"] = Num(*p.min_gap);
  if (p.max_gap) out["max_gap"] = Num(*p.max_gap);
  if (p.max_offset) out["max_offset"] = Num(*p.max_offset);
  return out;
}

Json MetricsJson(const Metrics& m) {
  Json out = Json::object();
  for (const auto& [name, value] : m.values) out[name] = Num(value);
  return out;
}

// Degrees in (-180, 180] after rounding: a yaw that rounds to -180 is written as 180.
double YawDegrees(double radians) {
  double d = Round4(WrapYaw(radians) * kDegPerRad);
  return d <= -180.0 ? 180.0 : d;
}

// ---------------------------------------------------------------------------------------------------
// Reading (throws JsonReadError; SceneFromJson catches)

template <size_t N, class E>
E ReadEnum(ObjectReader& r, std::string_view key, const std::array<std::string_view, N>& names,
           std::optional<E> (*parse)(std::string_view)) {
  std::string name = r.String(key);
  auto v = parse(name);
  if (!v) FailAt(r.PathOf(key), Shown(Json(name)) + ": expected one of " + OneOf(names));
  return *v;
}

double NonNegative(ObjectReader& r, std::string_view key) {
  double v = r.Number(key);
  if (v < 0.0) FailAt(r.PathOf(key), Shown(r.Required(key)) + ": must be >= 0");
  return v;
}

Vec3 ReadSize(ObjectReader& r) {
  auto v = r.Numbers("size", 3);
  for (size_t i = 0; i < 3; ++i)
    if (v[i] <= 0.0) FailAt(ElementPath(r.PathOf("size"), i), Shown(r.Required("size")[i]) + ": a size is > 0");
  return {v[0], v[1], v[2]};
}

FileRef ReadFileRef(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  FileRef ref;
  ref.file = r.String("file");
  if (ref.file.empty()) FailAt(r.PathOf("file"), "empty file name");
  ref.sha256 = r.String("sha256");
  static const std::regex hex("[0-9a-f]{64}");
  if (!std::regex_match(ref.sha256, hex))
    FailAt(r.PathOf("sha256"), Shown(Json(ref.sha256)) + ": expected 64 lowercase hex digits");
  r.Finish();
  return ref;
}

BuildRecord ReadBuild(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  BuildRecord b;
  for (auto [key, field] : {std::pair<std::string_view, double*>{"slab_thickness", &b.slab_thickness},
                            {"exterior_wall_thickness", &b.exterior_wall_thickness},
                            {"interior_wall_thickness", &b.interior_wall_thickness}}) {
    *field = r.Number(key);
    if (*field <= 0.0 || *field > 1.0) FailAt(r.PathOf(key), Shown(r.Required(key)) + ": must be in (0, 1] m");
  }
  r.Finish();
  return b;
}

Metrics ReadMetrics(const Json& value, const std::string& path) {
  if (!value.is_object()) FailAt(path, "expected an object, got " + Shown(value));
  Metrics m;
  for (auto it = value.begin(); it != value.end(); ++it) {
    std::string at = MemberPath(path, it.key());
    if (!IsKnownMetric(it.key())) FailAt(at, "unknown metric; expected one of " + OneOf(kMetricNames));
    m.values.emplace_back(it.key(), NumberAt(it.value(), at));
  }
  return m;
}

EdgeParams ReadParams(const Json& value, const std::string& path, SemanticRelation relation) {
  ObjectReader r(value, path);
  EdgeParams p;
  std::vector<std::string_view> allowed = ParamsAllowed(relation);
  for (std::string_view key : {"max_deg", "min_gap", "max_gap", "max_offset"}) {
    if (!r.Has(key)) continue;
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      FailAt(r.PathOf(key), std::string(SemanticRelationName(relation)) + " takes no " + std::string(key));
    double v = NonNegative(r, key);
    if (key == "max_deg") {
      if (v > 180.0) FailAt(r.PathOf(key), Shown(r.Required(key)) + ": must be in [0, 180] degrees");
      p.max_deg = v;
    } else if (key == "min_gap") {
      p.min_gap = v;
    } else if (key == "max_gap") {
      p.max_gap = v;
    } else {
      p.max_offset = v;
    }
  }
  r.Finish();
  if (p.min_gap && p.max_gap && *p.min_gap > *p.max_gap)
    FailAt(path, "min_gap " + Shown(r.Required("min_gap")) + " is above max_gap " + Shown(r.Required("max_gap")));
  return p;
}

SemanticEdge ReadEdge(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  SemanticEdge e;
  e.source = r.String("source");
  e.relation = ReadEnum(r, "relation", kSemanticNames, &ParseSemanticRelation);
  e.target = r.String("target");
  if (const Json* params = r.Optional("params")) e.params = ReadParams(*params, r.PathOf("params"), e.relation);
  r.Finish();
  return e;
}

InteractionZone ReadZone(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  InteractionZone z;
  z.side = r.String("side");
  if (std::find(kZoneSides.begin(), kZoneSides.end(), z.side) == kZoneSides.end())
    FailAt(r.PathOf("side"), Shown(Json(z.side)) + ": expected one of " + OneOf(kZoneSides));
  z.depth = NonNegative(r, "depth");
  if (r.Has("exempt")) z.exempt = r.Strings("exempt");
  r.Finish();
  return z;
}

Pose ReadPose(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  Pose p;
  p.x = r.Number("x");
  p.y = r.Number("y");
  p.z = r.Number("z");
  double yaw = r.Number("yaw");
  if (!(yaw > -180.0 && yaw <= 180.0)) FailAt(r.PathOf("yaw"), Shown(r.Required("yaw")) + ": yaw is in (-180, 180] degrees");
  p.yaw = WrapYaw(yaw / kDegPerRad);
  r.Finish();
  return p;
}

SceneObject ReadObject(const std::string& id, const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  SceneObject o;
  o.id = id;
  o.asset = r.String("asset");
  o.category = r.String("category");
  if (o.category.empty()) FailAt(r.PathOf("category"), "empty category");
  o.room = r.String("room");
  o.level = r.Integer("level");
  if (o.level < 0) FailAt(r.PathOf("level"), Shown(Json(o.level)) + ": levels count from 0");
  if (const Json* pose = r.Optional("pose")) o.pose = ReadPose(*pose, r.PathOf("pose"));
  if (r.Has("scale")) {
    auto s = r.Numbers("scale", 3);
    for (size_t i = 0; i < 3; ++i) {
      if (s[i] <= 0.0) FailAt(ElementPath(r.PathOf("scale"), i), Shown(r.Required("scale")[i]) + ": a scale is > 0");
      o.scale[i] = s[i];
    }
  }
  o.size = ReadSize(r);
  {
    auto names = r.Strings("affordances");
    auto bits = ParseAffordances(names);
    if (!bits) FailAt(r.PathOf("affordances"), Shown(r.Required("affordances")) + ": expected distinct V_con, V_pro, V_int");
    o.affordances = *bits;
  }
  o.parent = r.String("parent");
  if (o.parent.empty()) FailAt(r.PathOf("parent"), "empty parent");
  o.relation = ReadEnum(r, "relation", kRelationNames, &ParseRelation);
  o.surface = r.OptionalInteger("surface");
  if (o.surface && *o.surface < 0) FailAt(r.PathOf("surface"), Shown(Json(*o.surface)) + ": an index is >= 0");
  o.cavity = r.OptionalInteger("cavity");
  if (o.cavity && *o.cavity < 0) FailAt(r.PathOf("cavity"), Shown(Json(*o.cavity)) + ": an index is >= 0");
  if (const Json* wall = r.Optional("wall")) {
    ObjectReader w(*wall, r.PathOf("wall"));
    WallRef ref;
    ref.edge = w.Integer("edge");
    if (ref.edge < 0) FailAt(w.PathOf("edge"), Shown(Json(ref.edge)) + ": an edge index is >= 0");
    if (w.Has("gap")) ref.gap = NonNegative(w, "gap");
    w.Finish();
    o.wall = ref;
  }
  if (const Json* zone = r.Optional("interaction_zone")) o.interaction_zone = ReadZone(*zone, r.PathOf("interaction_zone"));
  o.origin = ReadEnum(r, "origin", kOriginNames, &ParseOrigin);
  if (r.Has("hints")) {
    o.hints = r.Strings("hints");
    for (size_t i = 0; i < o.hints.size(); ++i)
      if (!IsKnownHint(o.hints[i]))
        FailAt(ElementPath(r.PathOf("hints"), i), Shown(Json(o.hints[i])) + ": expected one of " + OneOf(kHints));
  }
  r.Finish();
  return o;
}

RoomSolve ReadSolve(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  RoomSolve s;
  s.outcome = ReadEnum(r, "outcome", kOutcomeNames, &ParseSolveOutcome);
  s.iterations = r.Integer("iterations");
  if (s.iterations < 0) FailAt(r.PathOf("iterations"), Shown(Json(s.iterations)) + ": must be >= 0");
  s.energy = NonNegative(r, "energy");
  if (r.Has("removed")) s.removed = r.Strings("removed");
  if (const Json* actions = r.Optional("actions")) {
    if (!actions->is_array()) FailAt(r.PathOf("actions"), "expected an array, got " + Shown(*actions));
    for (size_t i = 0; i < actions->size(); ++i)
      if (!(*actions)[i].is_object())
        FailAt(ElementPath(r.PathOf("actions"), i), "expected an object, got " + Shown((*actions)[i]));
    s.actions = *actions;
  }
  if (auto note = r.OptionalString("note")) s.note = *note;
  r.Finish();
  return s;
}

RoomEntry ReadRoom(const std::string& name, const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  RoomEntry room;
  room.name = name;
  {
    ObjectReader g(r.Required("graph"), r.PathOf("graph"));
    if (g.Has("planner")) {
      PlanRecord plan;
      plan.planner = g.String("planner");
      const Json& seed = g.Required("seed");
      if (!seed.is_number_unsigned()) FailAt(g.PathOf("seed"), "expected an integer >= 0, got " + Shown(seed));
      plan.seed = seed.get<uint64_t>();
      if (auto text = g.OptionalString("text")) plan.text = *text;
      if (g.Has("notes")) plan.notes = g.Strings("notes");
      room.plan = plan;
    }
    const Json& edges = g.Required("edges_sem");
    if (!edges.is_array()) FailAt(g.PathOf("edges_sem"), "expected an array, got " + Shown(edges));
    for (size_t i = 0; i < edges.size(); ++i) room.edges_sem.push_back(ReadEdge(edges[i], ElementPath(g.PathOf("edges_sem"), i)));
    g.Finish();
  }
  if (const Json* solve = r.Optional("solve")) room.solve = ReadSolve(*solve, r.PathOf("solve"));
  if (const Json* metrics = r.Optional("metrics")) room.metrics = ReadMetrics(*metrics, r.PathOf("metrics"));
  r.Finish();
  return room;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------

std::string_view RelationName(Relation relation) { return kRelationNames[static_cast<size_t>(relation)]; }
std::optional<Relation> ParseRelation(std::string_view name) { return ParseName<Relation>(kRelationNames, name); }

std::string_view SemanticRelationName(SemanticRelation relation) { return kSemanticNames[static_cast<size_t>(relation)]; }
std::optional<SemanticRelation> ParseSemanticRelation(std::string_view name) {
  return ParseName<SemanticRelation>(kSemanticNames, name);
}

std::vector<std::string_view> ParamsAllowed(SemanticRelation relation) {
  switch (relation) {
    case SemanticRelation::kFaceTo:
    case SemanticRelation::kAlign: return {"max_deg"};
    case SemanticRelation::kCentered: return {"max_offset"};
    default: return {"min_gap", "max_gap"};
  }
}

EdgeParams EffectiveParams(SemanticRelation relation, const EdgeParams& params) {
  EdgeParams p = params;
  switch (relation) {
    case SemanticRelation::kFaceTo: p.max_deg = p.max_deg.value_or(30.0); break;
    case SemanticRelation::kAlign: p.max_deg = p.max_deg.value_or(5.0); break;
    case SemanticRelation::kCentered: p.max_offset = p.max_offset.value_or(0.05); break;
    case SemanticRelation::kNextTo:
      p.min_gap = p.min_gap.value_or(0.0);
      p.max_gap = p.max_gap.value_or(0.5);
      break;
    case SemanticRelation::kNear:
      p.min_gap = p.min_gap.value_or(0.5);
      p.max_gap = p.max_gap.value_or(1.5);
      break;
    case SemanticRelation::kFar: p.min_gap = p.min_gap.value_or(1.5); break;
    default: p.min_gap = p.min_gap.value_or(0.0); break;  // the four sides: any gap unless given
  }
  return p;
}

double WrapYaw(double radians) {
  const double two_pi = 2.0 * std::numbers::pi;
  double r = std::fmod(radians, two_pi);
  if (r <= -std::numbers::pi) r += two_pi;
  if (r > std::numbers::pi) r -= two_pi;
  return r;
}

std::string_view OriginName(Origin origin) { return kOriginNames[static_cast<size_t>(origin)]; }
std::optional<Origin> ParseOrigin(std::string_view name) { return ParseName<Origin>(kOriginNames, name); }

std::string_view SolveOutcomeName(SolveOutcome outcome) { return kOutcomeNames[static_cast<size_t>(outcome)]; }
std::optional<SolveOutcome> ParseSolveOutcome(std::string_view name) { return ParseName<SolveOutcome>(kOutcomeNames, name); }

bool IsKnownHint(std::string_view hint) { return std::find(kHints.begin(), kHints.end(), hint) != kHints.end(); }
bool IsKnownMetric(std::string_view name) {
  return std::find(kMetricNames.begin(), kMetricNames.end(), name) != kMetricNames.end();
}
bool IsRootParent(std::string_view parent) {
  return parent == kParentFloor || parent == kParentWall || parent == kParentCeiling;
}

const SceneObject* SceneFile::FindObject(std::string_view id) const {
  for (const SceneObject& o : objects)
    if (o.id == id) return &o;
  return nullptr;
}

const RoomEntry* SceneFile::FindRoom(std::string_view name) const {
  for (const RoomEntry& r : rooms)
    if (r.name == name) return &r;
  return nullptr;
}

Json EdgeToJson(const SemanticEdge& edge) {
  Json e;
  e["source"] = edge.source;
  e["relation"] = SemanticRelationName(edge.relation);
  e["target"] = edge.target;
  Json params = ParamsJson(edge.params);
  if (!params.empty()) e["params"] = params;
  return e;
}

Json ObjectToJson(const SceneObject& o) {
  Json j;
  j["asset"] = o.asset;
  j["category"] = o.category;
  j["room"] = o.room;
  j["level"] = o.level;
  if (o.pose)
    j["pose"] = {{"x", Num(o.pose->x)}, {"y", Num(o.pose->y)}, {"z", Num(o.pose->z)}, {"yaw", YawDegrees(o.pose->yaw)}};
  j["scale"] = Json::array({Num(o.scale[0]), Num(o.scale[1]), Num(o.scale[2])});
  j["size"] = Vec(o.size);
  j["affordances"] = AffordanceNames(o.affordances);
  j["parent"] = o.parent;
  j["relation"] = RelationName(o.relation);
  if (o.surface) j["surface"] = *o.surface;
  if (o.cavity) j["cavity"] = *o.cavity;
  if (o.wall) j["wall"] = {{"edge", o.wall->edge}, {"gap", Num(o.wall->gap)}};
  if (o.interaction_zone) {
    Json z;
    z["side"] = o.interaction_zone->side;
    z["depth"] = Num(o.interaction_zone->depth);
    if (!o.interaction_zone->exempt.empty()) z["exempt"] = o.interaction_zone->exempt;
    j["interaction_zone"] = z;
  }
  j["origin"] = OriginName(o.origin);
  if (!o.hints.empty()) j["hints"] = o.hints;
  return j;
}

Json SceneToJson(const SceneFile& scene) {
  Json j;
  j["format"] = kSceneFormat;
  j["layout"] = {{"file", scene.layout.file}, {"sha256", scene.layout.sha256}};
  if (scene.library) j["library"] = {{"file", scene.library->file}, {"sha256", scene.library->sha256}};
  j["build"] = {{"slab_thickness", Num(scene.build.slab_thickness)},
                {"exterior_wall_thickness", Num(scene.build.exterior_wall_thickness)},
                {"interior_wall_thickness", Num(scene.build.interior_wall_thickness)}};
  Json rooms = Json::object();
  for (const RoomEntry& room : scene.rooms) {
    Json graph;
    if (room.plan) {
      graph["planner"] = room.plan->planner;
      graph["seed"] = room.plan->seed;
      if (!room.plan->text.empty()) graph["text"] = room.plan->text;
      if (!room.plan->notes.empty()) graph["notes"] = room.plan->notes;
    }
    Json edges = Json::array();
    for (const SemanticEdge& e : room.edges_sem) edges.push_back(EdgeToJson(e));
    graph["edges_sem"] = edges;
    Json r;
    r["graph"] = graph;
    if (room.solve) {
      Json s;
      s["outcome"] = SolveOutcomeName(room.solve->outcome);
      s["iterations"] = room.solve->iterations;
      s["energy"] = Num(room.solve->energy);
      s["removed"] = room.solve->removed;
      s["actions"] = room.solve->actions;
      if (!room.solve->note.empty()) s["note"] = room.solve->note;
      r["solve"] = s;
    }
    if (room.metrics) r["metrics"] = MetricsJson(*room.metrics);
    rooms[room.name] = r;
  }
  j["rooms"] = rooms;
  Json objects = Json::object();
  for (const SceneObject& o : scene.objects) objects[o.id] = ObjectToJson(o);
  j["objects"] = objects;
  if (scene.metrics) j["metrics"] = MetricsJson(*scene.metrics);
  return j;
}

// Text that is not UTF-8 (a request typed in another encoding) is written with U+FFFD in its place rather
// than failing the whole file.
std::string SceneToText(const SceneFile& scene) {
  return SceneToJson(scene).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

Result<SceneFile> SceneFromJson(const Json& json, const std::string& source) {
  try {
    ObjectReader r(json, "");
    std::string format = r.String("format");
    if (format != kSceneFormat)
      FailAt("format", Shown(Json(format)) + ": expected \"" + std::string(kSceneFormat) + "\"");
    SceneFile scene;
    scene.layout = ReadFileRef(r.Required("layout"), "layout");
    if (const Json* library = r.Optional("library")) scene.library = ReadFileRef(*library, "library");
    scene.build = ReadBuild(r.Required("build"), "build");
    const Json& rooms = r.Required("rooms");
    if (!rooms.is_object()) FailAt("rooms", "expected an object, got " + Shown(rooms));
    for (auto it = rooms.begin(); it != rooms.end(); ++it)
      scene.rooms.push_back(ReadRoom(it.key(), it.value(), MemberPath("rooms", it.key())));
    const Json& objects = r.Required("objects");
    if (!objects.is_object()) FailAt("objects", "expected an object, got " + Shown(objects));
    for (auto it = objects.begin(); it != objects.end(); ++it)
      scene.objects.push_back(ReadObject(it.key(), it.value(), MemberPath("objects", it.key())));
    if (const Json* metrics = r.Optional("metrics")) scene.metrics = ReadMetrics(*metrics, "metrics");
    r.Finish();
    return scene;
  } catch (const JsonReadError& e) {
    return Error{source + ": " + e.what()};
  }
}

Result<SceneFile> ParseSceneText(std::string_view text, const std::string& source) {
  auto json = ParseStrictJson(text, source);
  if (!json) return Error{json.error()};
  return SceneFromJson(*json, source);
}

Result<SceneFile> ReadScene(const std::filesystem::path& path) {
  auto text = ReadFile(path);
  if (!text) return Error{text.error()};
  return ParseSceneText(*text, path.string());
}

Status WriteScene(const SceneFile& scene, const std::filesystem::path& path) {
  return WriteFileAtomic(path, SceneToText(scene));
}

}  // namespace villa::scene
