#include "assets/asset_front.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "assets/asset_library.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// The exact cosine and sine of a quarter turn count (no float noise in the turned records).
std::pair<int, int> QuarterTurn(int quarters) {
  switch (((quarters % 4) + 4) % 4) {
    case 0: return {1, 0};
    case 1: return {0, 1};
    case 2: return {-1, 0};
    default: return {0, -1};
  }
}

Point Turned(Point p, int c, int s) { return {c * p.x - s * p.y, s * p.x + c * p.y}; }

std::string TurnedOpenSide(const std::string& open, int c, int s) {
  Point d;
  if (open == "-y") d = {0, -1};
  else if (open == "+y") d = {0, 1};
  else if (open == "-x") d = {-1, 0};
  else if (open == "+x") d = {1, 0};
  else return open;  // "+z", "closed"
  const Point t = Turned(d, c, s);
  return t.x > 0.5 ? "+x" : t.x < -0.5 ? "-x" : t.y > 0.5 ? "+y" : "-y";
}

std::string Fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

}  // namespace

std::string FrontSystemPrompt() {
  return "You look at four pictures of one piece of furniture or one household object. They were taken from four "
         "sides, 90 degrees apart: picture 1 from one side, then the camera walks round the object counter-clockwise "
         "seen from above, a quarter turn before each next picture. Say which picture shows the object's front: the "
         "side a person faces when using it (the seat of a chair or sofa, the doors, drawers or open shelves of a "
         "cabinet, the screen of a TV or monitor, the side of a bed or desk one approaches; for a mirror or a picture, "
         "the side that shows it). Answer with one JSON object and nothing else: \"front\" (1 to 4), \"confidence\" "
         "(0 to 1) and \"reason\" (a few words).";
}

Json FrontResponseFormat() {
  Json schema{{"type", "object"},
              {"additionalProperties", false},
              {"required", Json::array({"front", "confidence", "reason"})},
              {"properties", Json{{"front", Json{{"type", "integer"}, {"enum", Json::array({1, 2, 3, 4})}}},
                                  {"confidence", Json{{"type", "number"}, {"minimum", 0}, {"maximum", 1}}},
                                  {"reason", Json{{"type", "string"}}}}}};
  return Json{{"type", "json_schema"}, {"json_schema", Json{{"name", "asset_front"}, {"strict", true}, {"schema", schema}}}};
}

Result<FrontPick> PickAssetFront(const AssetRecord& record, const AssetMesh& mesh, const FrontPickOptions& options) {
  std::string message;
  if (!options.llm.IsValid(&message)) return Error{message};
  if (!options.chat.IsValid(&message)) return Error{message};
  AssetViewOptions views = options.views;
  views.overlays = false;
  auto rendered = RenderAssetViews(record, mesh, views);
  if (!rendered.ok()) return Error{rendered.error()};
  std::vector<std::string> pngs;
  for (const AssetView& v : *rendered) {
    auto png = EncodePng(v.image);
    if (!png.ok()) return Error{png.error()};
    pngs.push_back(*png);
  }
  FrontPick pick;
  const JsonCheck check = [&](const nlohmann::json& j) -> std::string {
    if (!j.contains("front") || !j["front"].is_number_integer() || j["front"].get<int>() < 1 || j["front"].get<int>() > 4)
      return "front: " + (j.contains("front") ? j["front"].dump().substr(0, 40) : std::string("missing")) + "; expected 1, 2, 3 or 4";
    pick.view = j["front"].get<int>() - 1;
    pick.confidence = j.contains("confidence") && j["confidence"].is_number() ? std::clamp(j["confidence"].get<double>(), 0.0, 1.0) : 0.0;
    pick.reason = j.contains("reason") && j["reason"].is_string() ? j["reason"].get<std::string>() : "";
    return "";
  };
  const std::string user = "The object: " + record.name + " (" + record.category + "), " + Fixed(record.size.x, 2) + " x " +
                           Fixed(record.size.y, 2) + " x " + Fixed(record.size.z, 2) + " m. Pictures 1 to 4 follow.";
  pick.chat = AskJson(options.llm, {{"system", FrontSystemPrompt(), {}}, {"user", user, pngs}},
                      options.json_schema ? FrontResponseFormat() : nullptr, check, options.chat);
  if (!pick.chat.accepted) return Error{record.id + ": the model gave no usable answer: " + pick.chat.error};
  // -90 x view, in (-180, 180]: 0, -90, 180, 90.
  constexpr int kTurns[4] = {0, -90, 180, 90};
  pick.turn_deg = kTurns[pick.view];
  return pick;
}

TurnedAsset TurnAsset(const AssetRecord& record, const AssetMesh& mesh, int view) {
  TurnedAsset out{record, mesh};
  if (view % 4 == 0) return out;
  // Turning by -90 x view degrees about z (through the bottom centre, so the box stays centred).
  const auto [c, s] = QuarterTurn(-view);
  for (AssetMeshPart& part : out.mesh.parts)
    for (Vec3& v : part.mesh.vertices) {
      const Point p = Turned({v.x, v.y}, c, s);
      v.x = p.x, v.y = p.y;
    }
  AssetRecord& r = out.record;
  if (view % 2 != 0) std::swap(r.size.x, r.size.y);
  for (int k = 0; k < 4; ++k) {
    const double x = record.to_asset[0][k], y = record.to_asset[1][k];
    r.to_asset[0][k] = c * x - s * y;
    r.to_asset[1][k] = s * x + c * y;
  }
  for (SupportSurface& surface : r.support_surfaces)
    for (Point& p : surface.polygon) p = Turned(p, c, s);
  for (Cavity& cavity : r.cavities) {
    const Point a = Turned({cavity.min.x, cavity.min.y}, c, s), b = Turned({cavity.max.x, cavity.max.y}, c, s);
    cavity.min.x = std::min(a.x, b.x), cavity.max.x = std::max(a.x, b.x);
    cavity.min.y = std::min(a.y, b.y), cavity.max.y = std::max(a.y, b.y);
    cavity.open = TurnedOpenSide(cavity.open, c, s);
  }
  r.front_yaw_offset = ((r.front_yaw_offset - 90 * view) % 360 + 360) % 360;
  return out;
}

Result<AssetRecord> WriteAssetFront(const fs::path& dir, const std::string& id, int view, const std::string& decided_by) {
  const fs::path file = dir / kLibraryRecordsFile;
  auto records = ReadAssetRecords(file.string());
  if (!records.ok()) return Error{records.error()};
  AssetRecord* record = nullptr;
  for (AssetRecord& r : *records)
    if (r.id == id) record = &r;
  if (!record) return Error{dir.string() + ": no asset " + id + " in the library"};
  if (record->source.kind == "procedural" || id.rfind("proc:", 0) == 0)
    return Error{id + ": a procedural asset's front is -y by construction; nothing to decide"};
  if (view < 0 || view > 3) return Error{id + ": view " + std::to_string(view) + " is not 0..3"};
  if (view != 0) {
    if (record->mesh.file.empty()) return Error{id + ": the record names no mesh file to turn"};
    auto mesh = ReadAssetMesh(dir / record->mesh.file);
    if (!mesh.ok()) return Error{mesh.error()};
    TurnedAsset turned = TurnAsset(*record, *mesh, view);
    // A new mesh file beside the old one: the records keep pointing at a whole mesh at every moment.
    fs::path relative(record->mesh.file);
    std::string stem = relative.stem().string();
    if (auto at = stem.find("@front"); at != std::string::npos) stem.resize(at);
    relative.replace_filename(stem + "@front" + std::to_string(turned.record.front_yaw_offset) + relative.extension().string());
    if (Status s = WriteAssetMesh(dir / relative, turned.mesh); !s.ok()) return Error{s.error()};
    turned.record.mesh.file = relative.generic_string();
    *record = std::move(turned.record);
  }
  record->front_decided_by = decided_by;
  if (Status s = WriteAssetRecords(file.string(), *records); !s.ok()) return Error{s.error()};
  return *record;
}

}  // namespace villa
