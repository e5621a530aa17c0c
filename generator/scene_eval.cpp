#include "generator/scene_eval.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <thread>

#include "layout/layout_io.h"
#include "scene/acquire.h"
#include "scene/file_digest.h"
#include "util/atomic_file.h"
#include "util/text_table.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
double Round4(double v) { return std::round(v * 1e4) / 1e4; }

// The paper's runtime (appendix "Runtime Analysis"): about 15 minutes a room, 225 a three-floor villa of
// about 15 rooms.
constexpr double kPaperRoomSeconds = 15 * 60.0;
constexpr double kPaperVillaSeconds = 225 * 60.0;

// The paper's nine room types in its table's order, then ours outside them.
const Category kPaperOrder[] = {Category::kLivingRoom, Category::kBedroom, Category::kBathroom,
                                Category::kKitchen,    Category::kDiningRoom, Category::kChildrenRoom,
                                Category::kOffice,     Category::kMeetingRoom, Category::kUtilityRoom};
const Category kRich[] = {Category::kLivingRoom, Category::kDiningRoom, Category::kBedroom, Category::kKitchen,
                          Category::kChildrenRoom};

std::string TypeName(Category c) {
  if (std::string_view paper = PaperRoomType(c); !paper.empty()) return std::string(paper);
  return c == Category::kBalcony ? "Balcony" : "Other";
}

std::optional<double> Mean(const std::vector<double>& v) {
  if (v.empty()) return std::nullopt;
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / v.size();
}

std::string Pct(const std::optional<double>& v) { return v ? FormatFixed(100.0 * *v, 1) : "-"; }
std::string Num(const std::optional<double>& v) { return v ? FormatFixed(*v, 1) : "-"; }
Json JsonOf(const std::optional<double>& v) { return v ? Json(Round4(*v)) : Json(nullptr); }

Json ValuesJson(const MicroValues& v) {
  return {{"CR", JsonOf(v.cr)}, {"FR", JsonOf(v.fr)}, {"OBR", JsonOf(v.obr)}, {"CSR", JsonOf(v.csr)}, {"NO", JsonOf(v.no)},
          {"RCH", JsonOf(v.rch)}, {"ACC", JsonOf(v.acc)}, {"rooms", v.rooms}, {"layouts", v.layouts}};
}

// Scores of one scene's rooms of one type, pooled.
struct Pool {
  int rooms = 0, objects = 0, colliding = 0, floating = 0, consumers = 0, out = 0, inside = 0, contained = 0;
  double rch = 0.0, acc = 0.0;
  int rch_n = 0, acc_n = 0;
  void Add(const RoomScore& r) {
    ++rooms;
    objects += r.objects, colliding += r.colliding, floating += r.floating, consumers += r.consumers;
    out += r.out_of_bounds, inside += r.inside_edges, contained += r.contained;
    if (r.reachable) rch += *r.reachable, ++rch_n;
    for (double a : r.access) acc += a, ++acc_n;
  }
};

// The figures of one pool: no object collides, floats or leaves the room when there is none (0), while
// CSR, RCH and ACC need something to count.
MicroValues ValuesOf(const Pool& p) {
  MicroValues v;
  v.cr = p.objects ? double(p.colliding) / p.objects : 0.0;
  v.fr = p.consumers ? double(p.floating) / p.consumers : 0.0;
  v.obr = p.objects ? double(p.out) / p.objects : 0.0;
  if (p.inside) v.csr = double(p.contained) / p.inside;
  v.no = double(p.objects) / std::max(1, p.rooms);
  if (p.rch_n) v.rch = p.rch / p.rch_n;
  if (p.acc_n) v.acc = p.acc / p.acc_n;
  v.rooms = p.rooms;
  return v;
}

// The mean of each figure over the values that have it.
MicroValues MeanOf(const std::vector<MicroValues>& values) {
  std::vector<double> cr, fr, obr, csr, no, rch, acc;
  MicroValues out;
  for (const MicroValues& v : values) {
    if (v.cr) cr.push_back(*v.cr);
    if (v.fr) fr.push_back(*v.fr);
    if (v.obr) obr.push_back(*v.obr);
    if (v.csr) csr.push_back(*v.csr);
    if (v.no) no.push_back(*v.no);
    if (v.rch) rch.push_back(*v.rch);
    if (v.acc) acc.push_back(*v.acc);
    out.rooms += v.rooms;
  }
  out.cr = Mean(cr), out.fr = Mean(fr), out.obr = Mean(obr), out.csr = Mean(csr), out.no = Mean(no), out.rch = Mean(rch);
  out.acc = Mean(acc);
  return out;
}

void AddRoomRecord(std::vector<RoomScore>& out, int layout, int scene, const std::string& room, Category category,
                   const solver::ExactMetrics* m) {
  RoomScore s;
  s.layout = layout;
  s.scene = scene;
  s.room = room;
  s.category = category;
  if (m) {
    s.objects = m->objects, s.colliding = m->colliding, s.floating = m->floating, s.consumers = m->consumers;
    s.out_of_bounds = m->out_of_bounds, s.inside_edges = m->inside_edges, s.contained = m->contained;
  }
  out.push_back(std::move(s));
}

}  // namespace

std::string_view PaperRoomType(Category category) {
  switch (category) {
    case Category::kLivingRoom: return "Living Room";
    case Category::kBedroom: return "Bedroom";
    case Category::kBathroom: return "Bathroom";
    case Category::kKitchen: return "Kitchen";
    case Category::kDiningRoom: return "Dining Room";
    case Category::kChildrenRoom: return "Childroom";
    case Category::kOffice: return "Office";
    case Category::kMeetingRoom: return "Meeting Room";
    case Category::kUtilityRoom: return "Utility Room";
    default: return "";
  }
}

Result<std::vector<SceneRequest>> ReadSceneRequests(const std::vector<fs::path>& inputs, int limit) {
  std::vector<SceneRequest> out;
  auto full = [&] { return limit > 0 && static_cast<int>(out.size()) >= limit; };
  for (const fs::path& input : inputs) {
    if (full()) break;
    std::error_code ec;
    if (!fs::exists(input, ec)) return Error{input.string() + ": no such file"};
    if (input.extension() != ".jsonl") {
      auto layout = LoadLayout(input);
      if (!layout.ok()) return Error{layout.error()};
      out.push_back({input.string(), input.string(), "", std::move(*layout)});
      continue;
    }
    std::string problem;
    Status read = ReadJsonl(input, [&](const Json& record, int line) {
      const std::string where = input.string() + ":" + std::to_string(line);
      SceneRequest r;
      r.source = where;
      if (record.is_object() && record.contains("id"))
        r.id = record["id"].is_string() ? record["id"].get<std::string>() : record["id"].dump();
      if (record.is_object() && record.contains("text")) {
        if (!record["text"].is_string()) {
          problem = where + ": \"text\" must be a string";
          return false;
        }
        r.text = record["text"].get<std::string>();
        if (record.contains("layout")) {
          const Json& l = record["layout"];
          auto layout = l.is_string() ? LoadLayout(input.parent_path() / l.get<std::string>())
                                      : LayoutFromJson(l, where + ": layout");
          if (!layout.ok()) {
            problem = where + ": " + layout.error();
            return false;
          }
          r.layout = std::move(*layout);
        }
      } else {
        auto layout = LayoutFromRecord(record, where);
        if (!layout.ok()) {
          problem = where + ": neither a request (\"text\") nor a layout: " + layout.error();
          return false;
        }
        r.layout = std::move(*layout);
      }
      if (r.id.empty()) r.id = where;
      out.push_back(std::move(r));
      return !full();
    });
    if (!problem.empty()) return Error{problem};
    if (!read) return Error{read.error()};
  }
  if (out.empty()) return Error{"no requests or layouts in the inputs"};
  return out;
}

std::vector<RoomScore> RoomScoresOf(const solver::FurnishedVilla& villa, int layout, int scene) {
  std::vector<RoomScore> out;
  for (const solver::RoomReport& r : villa.rooms) {
    if (!r.asked) continue;
    AddRoomRecord(out, layout, scene, r.room, r.category, r.solve ? &r.solve->metrics : nullptr);
    if (!villa.reach) continue;
    RoomScore& s = out.back();
    if (auto it = villa.reach->rch.find(r.room); it != villa.reach->rch.end()) s.reachable = it->second;
    for (const scene::SceneObject& o : villa.scene.objects)
      if (o.room == r.room)
        if (auto it = villa.reach->acc.find(o.id); it != villa.reach->acc.end()) s.access.push_back(it->second);
  }
  return out;
}

std::vector<RoomScore> RoomScoresOf(const solver::GlbMetricsSummary& glb, int layout, int scene) {
  std::vector<RoomScore> out;
  for (const solver::GlbRoomMetrics& r : glb.rooms) AddRoomRecord(out, layout, scene, r.room, r.category, &r.metrics);
  return out;
}

MicroTable MicroTableOf(const std::vector<RoomScore>& rooms) {
  // type -> layout -> scene -> pool
  std::map<Category, std::map<int, std::map<int, Pool>>> pools;
  for (const RoomScore& r : rooms) pools[r.category][r.layout][r.scene].Add(r);
  MicroTable table;
  auto row_of = [&](Category c) {
    MicroRow row;
    row.type = TypeName(c);
    row.in_paper = !PaperRoomType(c).empty();
    std::vector<MicroValues> per_layout;
    for (const auto& [layout, scenes] : pools[c]) {
      std::vector<MicroValues> per_scene;
      for (const auto& [scene, pool] : scenes) per_scene.push_back(ValuesOf(pool));
      per_layout.push_back(MeanOf(per_scene));
    }
    row.values = MeanOf(per_layout);
    row.values.layouts = static_cast<int>(per_layout.size());
    return row;
  };
  std::vector<MicroValues> nine;
  for (Category c : kPaperOrder)
    if (pools.count(c)) {
      table.rows.push_back(row_of(c));
      nine.push_back(table.rows.back().values);
    }
  for (Category c : {Category::kBalcony, Category::kRoom})
    if (pools.count(c)) table.rows.push_back(row_of(c));
  table.average = MeanOf(nine);
  std::vector<double> rich;
  for (const MicroRow& row : table.rows)
    for (Category c : kRich)
      if (row.type == TypeName(c) && row.values.no) rich.push_back(*row.values.no);
  table.rich_no = Mean(rich);
  return table;
}

std::string SceneEvalOptions::Check() const {
  if (scenes_per_layout < 1 || scenes_per_layout > 100)
    return "scenes per layout = " + std::to_string(scenes_per_layout) + ": must be in [1, 100]";
  std::string message;
  if (!plan.IsValid(&message)) return message;
  return furnish.Check();
}

std::string KeptLayoutName(size_t index, const std::string& id) {
  std::string number = std::to_string(index + 1);
  if (number.size() < 3) number.insert(0, 3 - number.size(), '0');
  // A layout file's id is its path: its file name is what tells it apart.
  const std::string base = id.substr(id.find_last_of('/') == std::string::npos ? 0 : id.find_last_of('/') + 1);
  std::string name;
  for (char c : base.substr(0, 60))
    name += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' ? c : '_';
  return number + "-" + name;
}

namespace {

// One scene's outputs under keep/<layout>/<seed>/: written into keep/<layout>/.<seed>.partial, then that
// folder renamed into place (a crash leaves at most a hidden .partial folder, never a half scene).
Status KeepScene(const fs::path& keep, const std::string& layout_name, uint64_t seed, const std::string& layout_text,
                 const solver::FurnishedVilla& villa, const solver::FurnishOptions& furnish) {
  const fs::path parent = keep / layout_name, final_dir = parent / std::to_string(seed);
  const fs::path partial = parent / ("." + std::to_string(seed) + ".partial");
  std::error_code ec;
  if (fs::exists(final_dir, ec)) return Error{final_dir.string() + ": already there; not replaced"};
  fs::remove_all(partial, ec);  // our own leftover of an interrupted run
  fs::create_directories(partial, ec);
  if (ec) return Error{partial.string() + ": cannot create the folder: " + ec.message()};
  solver::FurnishOptions options = furnish;
  options.pictures = false;
  options.force = false;
  auto written = solver::WriteFurnishedVillaFiles(villa, partial, options);
  if (!written.ok()) return Error{written.error()};
  if (Status s = WriteFileAtomic(partial / "layout.json", layout_text); !s) return s;
  fs::rename(partial, final_dir, ec);
  if (ec) return Error{final_dir.string() + ": cannot move the scene's folder into place: " + ec.message()};
  return Status::Ok();
}

}  // namespace

Result<SceneEvalSummary> EvaluateScenes(const std::vector<SceneRequest>& requests, const SceneEvalOptions& options) {
  const auto start = Clock::now();
  if (std::string problem = options.Check(); !problem.empty()) return Error{"usage: " + problem};
  auto library = scene::OpenFurnishingLibrary(options.furnish.library, options.furnish.procedural_only);
  if (!library.ok()) return Error{library.error()};
  SceneEvalSummary summary;
  summary.library_note = library->note;
  summary.kept_in = options.keep.string();
  const int k = options.scenes_per_layout;
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  summary.jobs = options.furnish.jobs > 0 ? options.furnish.jobs : static_cast<int>(hardware);
  if (options.on_start) options.on_start(requests.size() * k);
  std::vector<double> adherence;
  std::map<Category, solver::FunctionalTally> functional;

  for (size_t i = 0; i < requests.size(); ++i) {
    const SceneRequest& request = requests[i];
    LayoutResult lr;
    lr.request = request;
    const uint64_t seed = options.plan.seed + i;  // as `villa eval` plans prompt i
    std::optional<Layout> layout;
    auto t = Clock::now();
    if (request.layout) {
      layout = request.layout;
      lr.metrics = MeasureLayout(*layout);
    } else {
      PlanOptions plan = options.plan;
      plan.seed = seed;
      lr.plan = PlanLayout(request.text, plan);
      lr.metrics = lr.plan->metrics;
      adherence.push_back(lr.plan->check.adherence());
      if (lr.plan->layout) layout = lr.plan->layout;
      else lr.error = "no layout: " + lr.plan->error;
    }
    summary.plan_seconds += Since(t);
    summary.macro.Add(lr.metrics);
    if (layout) lr.rooms = static_cast<int>(layout->rooms.size());
    if (layout && !lr.metrics.format_success) lr.error = "the layout breaks the geometric rules 1-5: not furnished";
    if (!lr.error.empty()) layout.reset();

    const std::string layout_text = layout ? LayoutToString(*layout) : "";
    for (int s = 0; s < k; ++s) {
      SceneResult scene;
      scene.layout = static_cast<int>(i);
      scene.scene = s;
      scene.seed = seed + s;
      if (layout) {
        solver::FurnishOptions furnish = options.furnish;
        furnish.text = request.text;
        furnish.seed = scene.seed;
        t = Clock::now();
        // A kept scene names the layout.json beside it, so `villa reach DIR/scene.json` finds it.
        const std::string layout_ref = options.keep.empty() ? request.id : "layout.json";
        auto villa = solver::FurnishLayout(*layout, {layout_ref, scene::Sha256Hex(layout_text)}, library->library,
                                           library->file, furnish);
        summary.furnish_seconds += Since(t);
        if (villa.ok() && !options.keep.empty()) {
          if (Status kept = KeepScene(options.keep, KeptLayoutName(i, request.id), scene.seed, layout_text, *villa, furnish); !kept)
            return Error{"--keep: " + kept.error()};
          ++summary.kept;
        }
        if (villa.ok()) {
          scene.summary = villa->summary;
          std::vector<RoomScore> rooms = RoomScoresOf(*villa, scene.layout, s);
          summary.rooms.insert(summary.rooms.end(), rooms.begin(), rooms.end());
          for (const solver::RoomReport& r : villa->rooms) {
            if (!r.asked || !r.functional) continue;
            functional[r.category].Add(*r.functional);
            if (!r.functional->ok())
              summary.functional_failing.push_back(request.id + " scene " + std::to_string(s + 1) + " " + r.room + ": " +
                                                   solver::FailingLine(*r.functional));
          }
          summary.functional_all.Add(villa->summary.functional);
          if (villa->physics) {
            summary.physics_measured = true;
            for (const auto& [type, c] : villa->physics->by_room_type) summary.stability[type] += c;
            summary.stability_all += villa->physics->all;
          }
          summary.room_seconds += villa->summary.room_seconds;
          summary.furnished_rooms += villa->summary.furnished;
          if (villa->reach) {
            summary.reach_measured = true;
            std::vector<double> rch;
            for (const auto& [room, value] : villa->reach->rch) rch.push_back(value);
            scene.rch = Mean(rch);
          }
        } else {
          scene.error = villa.error();
        }
      } else {
        scene.error = lr.error;
      }
      summary.scenes.push_back(std::move(scene));
      if (options.on_scene_done) options.on_scene_done();
    }
    summary.layouts.push_back(std::move(lr));
  }
  summary.adherence = Mean(adherence);
  summary.micro = MicroTableOf(summary.rooms);
  for (Category c : kPaperOrder)
    if (functional.count(c)) summary.functional.emplace_back(TypeName(c), functional[c]);
  for (Category c : {Category::kBalcony, Category::kRoom})
    if (functional.count(c)) summary.functional.emplace_back(TypeName(c), functional[c]);
  summary.seconds = Since(start);
  return summary;
}

std::string MicroTableText(const MicroTable& table) {
  TextTable t({"room type", "layouts", "rooms", "CR %", "FR %", "OBR %", "CSR %", "NO", "RCH %", "ACC %"});
  auto add = [&](const std::string& name, const MicroValues& v) {
    t.AddRow({name, std::to_string(v.layouts), std::to_string(v.rooms), Pct(v.cr), Pct(v.fr), Pct(v.obr), Pct(v.csr),
              Num(v.no), Pct(v.rch), Pct(v.acc)});
  };
  for (const MicroRow& row : table.rows) add(row.in_paper ? row.type : row.type + " *", row.values);
  MicroValues average = table.average;
  average.layouts = 0;
  for (const MicroRow& row : table.rows) average.layouts = std::max(average.layouts, row.values.layouts);
  add("Average (the nine)", average);
  std::string out = t.Render();
  out += "NO over living, dining, bed, kitchen and children's rooms: " + Num(table.rich_no) + "\n";
  bool extra = false;
  for (const MicroRow& row : table.rows) extra = extra || !row.in_paper;
  if (extra) out += "* not one of the paper's nine room types: left out of the average\n";
  return out;
}

Json MicroTableJson(const MicroTable& table) {
  Json rows = Json::array();
  for (const MicroRow& row : table.rows) {
    Json r{{"type", row.type}, {"in_paper", row.in_paper}};
    r.update(ValuesJson(row.values));
    rows.push_back(std::move(r));
  }
  return {{"rows", std::move(rows)}, {"average", ValuesJson(table.average)}, {"rich_no", JsonOf(table.rich_no)}};
}

std::string MicroTableMarkdown(const MicroTable& table) {
  std::ostringstream out;
  out << "| room type | layouts | rooms | CR % | FR % | OBR % | CSR % | NO | RCH % | ACC % |\n";
  out << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  auto add = [&](const std::string& name, const MicroValues& v) {
    out << "| " << name << " | " << v.layouts << " | " << v.rooms << " | " << Pct(v.cr) << " | " << Pct(v.fr) << " | "
        << Pct(v.obr) << " | " << Pct(v.csr) << " | " << Num(v.no) << " | " << Pct(v.rch) << " | " << Pct(v.acc) << " |\n";
  };
  for (const MicroRow& row : table.rows) add(row.in_paper ? row.type : row.type + " (not in the paper)", row.values);
  MicroValues average = table.average;
  for (const MicroRow& row : table.rows) average.layouts = std::max(average.layouts, row.values.layouts);
  add("**Average** (the nine)", average);
  out << "\nNO over living, dining, bed, kitchen and children's rooms: **" << Num(table.rich_no) << "**\n";
  return out.str();
}

namespace {

struct Times {
  int scenes = 0, layouts = 0;
  double villa = 0.0, room = 0.0;
};
Times TimesOf(const SceneEvalSummary& s) {
  Times t;
  for (const SceneResult& r : s.scenes) t.scenes += r.error.empty();
  for (const LayoutResult& l : s.layouts) t.layouts += l.error.empty();
  // A villa: its share of planning plus one furnishing, wall time.
  if (t.scenes) t.villa = s.furnish_seconds / t.scenes + (t.layouts ? s.plan_seconds / s.layouts.size() : 0.0);
  if (s.furnished_rooms) t.room = s.room_seconds / s.furnished_rooms;
  return t;
}

std::string TimesLine(const SceneEvalSummary& s) {
  const Times t = TimesOf(s);
  std::string out = std::to_string(t.scenes) + " scenes of " + std::to_string(s.layouts.size()) + " layouts (" +
                    std::to_string(s.furnished_rooms) + " rooms furnished) in " + FormatFixed(s.seconds, 1) +
                    " s wall with " + std::to_string(s.jobs) + " jobs (planning " + FormatFixed(s.plan_seconds, 1) +
                    " s, furnishing " + FormatFixed(s.furnish_seconds, 1) + " s)\n";
  if (t.room > 0)
    out += "a room: " + FormatFixed(t.room, 3) + " s of one core (the paper: ~15 min, " +
           FormatFixed(kPaperRoomSeconds / t.room, 0) + "x); a villa: " + FormatFixed(t.villa, 2) +
           " s wall (the paper: ~225 min, " + FormatFixed(kPaperVillaSeconds / t.villa, 0) + "x)\n";
  out += s.reach_measured ? "RCH and ACC measured by the reachability check\n"
                          : "RCH and ACC not measured: no reachability check is plugged in\n";
  if (!s.library_note.empty()) out += "assets: " + s.library_note + "\n";
  if (!s.kept_in.empty()) out += "kept: " + std::to_string(s.kept) + " scene folder(s) in " + s.kept_in + "\n";
  return out;
}

// Issue 27's checks per room type: a table (text or Markdown), the summary line and the failing rooms.
std::vector<std::vector<std::string>> FunctionalRows(const SceneEvalSummary& s) {
  std::vector<std::vector<std::string>> rows;
  auto add = [&](const std::string& name, const solver::FunctionalTally& t) {
    std::vector<std::string> row{name, std::to_string(t.rooms)};
    for (std::string& c : t.Cells()) row.push_back(std::move(c));
    rows.push_back(std::move(row));
  };
  for (const auto& [type, tally] : s.functional) add(type, tally);
  add("All", s.functional_all);
  return rows;
}

std::vector<std::string> FunctionalHeader() {
  std::vector<std::string> h{"room type", "rooms"};
  for (const std::string& c : solver::FunctionalTally::Header()) h.push_back(c);
  return h;
}

std::string FunctionalText(const SceneEvalSummary& s) {
  if (s.functional_all.rooms == 0) return "";
  TextTable t(FunctionalHeader());
  for (auto& row : FunctionalRows(s)) t.AddRow(row);
  std::string out = "Rooms as rooms (functional checks, docs/METRICS.md), per room type:\n" + t.Render();
  if (!s.functional_failing.empty()) {
    out += "rooms whose functional check fails (" + std::to_string(s.functional_failing.size()) + "):\n";
    for (const std::string& line : s.functional_failing) out += "  " + line + "\n";
  }
  return out;
}

std::string FunctionalMarkdown(const SceneEvalSummary& s) {
  if (s.functional_all.rooms == 0) return "";
  std::string out = "|";
  const std::vector<std::string> header = FunctionalHeader();
  for (const std::string& h : header) out += " " + h + " |";
  out += "\n| --- |";
  for (size_t i = 1; i < header.size(); ++i) out += " ---: |";
  out += "\n";
  for (const auto& row : FunctionalRows(s)) {
    out += "|";
    for (const std::string& c : row) out += " " + c + " |";
    out += "\n";
  }
  return out;
}

std::string MacroLine(const SceneEvalSummary& s, bool markdown) {
  const MetricsSummary& m = s.macro;
  auto pct = [](std::optional<double> r) { return r ? FormatFixed(100.0 * *r, 1) : std::string("-"); };
  const std::vector<std::string> cells{std::to_string(s.layouts.size()), pct(m.fsr()), pct(m.rr()), pct(m.rr_entrance()),
                                       pct(m.vcr()), pct(s.adherence)};
  const std::vector<std::string> header{"layouts", "FSR %", "RR %", "RR (entrance) %", "VCR %", "brief adherence %"};
  if (!markdown) {
    TextTable t(header);
    t.AddRow(cells);
    return t.Render();
  }
  std::string out = "|";
  for (const auto& h : header) out += " " + h + " |";
  out += "\n|";
  for (size_t i = 0; i < header.size(); ++i) out += " ---: |";
  out += "\n|";
  for (const auto& c : cells) out += " " + c + " |";
  return out + "\n";
}

}  // namespace

namespace {

// "physics": {"all": {...}, "by_room_type": {...}} (physics::StabilityJson), null when not measured.
Json PhysicsJsonOf(const SceneEvalSummary& s) {
  if (!s.physics_measured) return nullptr;
  Json by_type = Json::object();
  for (const auto& [type, c] : s.stability) by_type[type] = physics::StabilityJson(c);
  return {{"all", physics::StabilityJson(s.stability_all)}, {"by_room_type", by_type}};
}

// One line per room type and one over all: free objects, the strict and loose stable shares.
std::string PhysicsLine(const SceneEvalSummary& s) {
  if (!s.physics_measured) return "";
  auto line = [](const std::string& name, const physics::StabilityCount& c) {
    return "  " + name + ": " + std::to_string(c.free) + " free, " + FormatPercent(c.strict, c.free) + " strict, " +
           FormatPercent(c.loose, c.free) + " loose\n";
  };
  std::string out = "Physics (2 s in Bullet; strict: <= 1 cm and 0.1 rad, loose: <= 20 cm and 8 degrees):\n";
  for (const auto& [type, c] : s.stability) out += line(type, c);
  return out + line("all", s.stability_all) + "\n";
}

}  // namespace

std::string SceneEvalText(const SceneEvalSummary& s) {
  std::ostringstream out;
  TextTable scenes({"#", "request", "scene", "seed", "rooms", "objects", "CR %", "FR %", "OBR %", "CSR %", "E<=1", "s"});
  for (const SceneResult& r : s.scenes) {
    const LayoutResult& l = s.layouts[r.layout];
    std::string label = l.request.id;
    if (label.size() > 32) label = label.substr(0, 29) + "...";
    if (!r.error.empty()) {
      scenes.AddRow({std::to_string(r.layout + 1), label, std::to_string(r.scene + 1), std::to_string(r.seed), "-", "-", "-",
                     "-", "-", "-", "-", "-"});
      continue;
    }
    const solver::FurnishSummary& f = r.summary;
    scenes.AddRow({std::to_string(r.layout + 1), label, std::to_string(r.scene + 1), std::to_string(r.seed),
                   std::to_string(f.furnished), std::to_string(f.objects), Pct(f.cr()), Pct(f.fr()), Pct(f.obr()),
                   f.inside_edges ? Pct(f.csr()) : "-", std::to_string(f.converged) + "/" + std::to_string(f.furnished),
                   FormatFixed(f.seconds, 2)});
  }
  out << scenes.Render() << "\n";
  for (const LayoutResult& l : s.layouts)
    if (!l.error.empty()) out << l.request.source << ": " << l.error << "\n";
  for (const SceneResult& r : s.scenes)
    if (!r.error.empty() && s.layouts[r.layout].error.empty())
      out << s.layouts[r.layout].request.source << " scene " << r.scene + 1 << ": " << r.error << "\n";
  out << "Micro level, per room type (mean of " << (s.scenes.empty() ? 0 : s.scenes.size() / std::max<size_t>(1, s.layouts.size()))
      << " scenes per layout, then over layouts):\n";
  out << MicroTableText(s.micro) << "\n";
  out << FunctionalText(s) << "\n";
  out << PhysicsLine(s);
  out << "Macro level:\n" << MacroLine(s, false) << "\n";
  out << TimesLine(s);
  return out.str();
}

namespace {
Json FunctionalJsonOf(const SceneEvalSummary& s) {
  Json by_type = Json::object();
  for (const auto& [type, tally] : s.functional) by_type[type] = tally.ToJson();
  return {{"by_room_type", std::move(by_type)}, {"all", s.functional_all.ToJson()}, {"failing", s.functional_failing}};
}
}  // namespace

Json SceneEvalJson(const SceneEvalSummary& s) {
  Json layouts = Json::array();
  for (const LayoutResult& l : s.layouts) {
    MetricsSummary one;
    one.Add(l.metrics);
    auto ratio = [](std::optional<double> r) { return r ? Json(*r) : Json(nullptr); };
    Json j{{"source", l.request.source}, {"id", l.request.id}, {"text", l.request.text}, {"planned", l.plan.has_value()},
           {"rooms", l.rooms}, {"FSR", ratio(one.fsr())}, {"RR", ratio(one.rr())}, {"VCR", ratio(one.vcr())}};
    if (l.plan) j["brief_adherence"] = Round4(l.plan->check.adherence());
    if (!l.error.empty()) j["error"] = l.error;
    layouts.push_back(std::move(j));
  }
  Json scenes = Json::array();
  for (const SceneResult& r : s.scenes) {
    Json j{{"layout", r.layout}, {"scene", r.scene}, {"seed", r.seed}};
    if (!r.error.empty()) {
      j["error"] = r.error;
    } else {
      const solver::FurnishSummary& f = r.summary;
      j["rooms"] = f.furnished;
      j["objects"] = f.objects;
      j["converged"] = f.converged;
      j["CR"] = Round4(f.cr());
      j["FR"] = Round4(f.fr());
      j["OBR"] = Round4(f.obr());
      j["CSR"] = f.inside_edges ? Json(Round4(f.csr())) : Json(nullptr);
      j["RCH"] = JsonOf(r.rch);
      j["seconds"] = Round4(f.seconds);
      j["room_seconds"] = Round4(f.room_seconds);
    }
    scenes.push_back(std::move(j));
  }
  const Times t = TimesOf(s);
  auto ratio = [](std::optional<double> r) { return r ? Json(Round4(*r)) : Json(nullptr); };
  return {{"format", "villa-scene-eval/1"},
          {"layouts", std::move(layouts)},
          {"scenes", std::move(scenes)},
          {"micro", MicroTableJson(s.micro)},
          {"functional", FunctionalJsonOf(s)},
          {"macro", {{"layouts", s.layouts.size()}, {"FSR", ratio(s.macro.fsr())}, {"RR", ratio(s.macro.rr())},
                     {"RR_entrance", ratio(s.macro.rr_entrance())}, {"VCR", ratio(s.macro.vcr())},
                     {"brief_adherence", ratio(s.adherence)}}},
          {"reach", s.reach_measured ? "measured" : "not measured"},
          {"physics", PhysicsJsonOf(s)},
          {"library", s.library_note},
          {"kept", s.kept},
          {"seconds", {{"total", Round4(s.seconds)}, {"plan", Round4(s.plan_seconds)}, {"furnish", Round4(s.furnish_seconds)},
                       {"room_seconds", Round4(s.room_seconds)}, {"rooms", s.furnished_rooms},
                       {"per_room", Round4(t.room)}, {"per_villa", Round4(t.villa)}, {"jobs", s.jobs},
                       {"paper_per_room", kPaperRoomSeconds}, {"paper_per_villa", kPaperVillaSeconds}}}};
}

std::string SceneEvalMarkdown(const SceneEvalSummary& s) {
  std::string out = "Micro level, per room type:\n\n" + MicroTableMarkdown(s.micro);
  if (const std::string f = FunctionalMarkdown(s); !f.empty()) out += "\nRooms as rooms (functional checks), per room type:\n\n" + f;
  out += "\nMacro level:\n\n" + MacroLine(s, true) + "\n";
  return out + TimesLine(s);
}

}  // namespace villa
