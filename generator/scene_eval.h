#pragma once
// The paper's micro-level evaluation (Sec. 4, table "quantitative2") on our own outputs, the library
// behind `villa eval --scenes`: requests (or layouts) planned, built and furnished, each layout furnished
// `scenes_per_layout` times (three seeds, as the paper averages three scenes per layout and room type),
// then per room type CR, FR, OBR, CSR and NO (plus RCH and ACC when reachability is plugged in), and the
// macro table (FSR, RR, VCR, brief adherence) over the same requests. The same table is made from
// furnished .glb files of other methods (solver/glb_metrics.h), so they can be put side by side.
//
// Room types: the paper's nine (Living Room, Bedroom, Bathroom, Kitchen, Dining Room, Childroom, Office,
// Meeting Room, Utility Room) are our categories of the same names (children-room is the Childroom,
// utility-room the Utility Room, which holds the staircase in a multi-story villa); balconies and
// unlabelled rooms are outside the nine and get rows of their own, left out of the Average.
//
// Averaging (docs/METRICS.md): per scene and room type the rooms of that type are pooled (CR = colliding
// objects / objects, FR = floating / V_con objects, OBR = out of bounds / objects, CSR = contained /
// inside edges, NO = objects / rooms, RCH = reachable rooms / rooms, ACC = mean over V_int objects); the
// scenes of one layout are averaged, then the layouts; a figure with no denominator anywhere (CSR of a
// type with no inside edge) is "-". The Average row is the mean of the nine types' rows.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generator/text/plan.h"
#include "layout/layout.h"
#include "layout/metrics.h"
#include "solver/furnish.h"
#include "solver/glb_metrics.h"
#include "util/result.h"

namespace villa {

// "Living Room" ... "Utility Room" for the paper's nine; "" for balcony and room.
std::string_view PaperRoomType(Category category);

// One scene's input: a request to plan, or a layout to furnish (with the request's furniture wishes).
struct SceneRequest {
  std::string source;            // "prompts.jsonl:3", "villa.json"
  std::string id;                // the record's "id", else the source
  std::string text;              // the request ("" = the room priors only)
  std::optional<Layout> layout;  // given: furnished as it is; none: planned from `text`
};

// The requests of the inputs: a .jsonl holds one a line, either {"text": ..., "id": ...} (a prompt, with
// an optional "layout": a layout file relative to the JSONL's folder, or an inline layout, furnished
// instead of planning) or a layout record (synth's layouts.jsonl); any other file is one layout. Errors
// name the file and line. At most `limit` requests (0: all).
Result<std::vector<SceneRequest>> ReadSceneRequests(const std::vector<std::filesystem::path>& inputs, int limit = 0);

// One room of one scene, as counted by the exact check.
struct RoomScore {
  int layout = 0;       // index of the request (the layout) it belongs to
  int scene = 0;        // which of the layout's scenes (seed index)
  std::string room;
  Category category = Category::kRoom;
  int objects = 0, colliding = 0, floating = 0, consumers = 0, out_of_bounds = 0, inside_edges = 0, contained = 0;
  std::optional<double> reachable;  // RCH of the room (1 / 0 or a share); none: not measured
  std::vector<double> access;       // ACC of its V_int objects (measured ones)
};

// The room records of a furnished villa (layout order), and of a scored .glb.
std::vector<RoomScore> RoomScoresOf(const solver::FurnishedVilla& villa, int layout, int scene);
std::vector<RoomScore> RoomScoresOf(const solver::GlbMetricsSummary& glb, int layout, int scene);

struct MicroValues {
  std::optional<double> cr, fr, obr, csr, no, rch, acc;  // shares in [0, 1]; NO a count
  int rooms = 0;    // room records behind the row
  int layouts = 0;  // layouts with such a room
};
struct MicroRow {
  std::string type;      // "Living Room", ..., "Balcony", "Other"
  bool in_paper = true;  // one of the nine
  MicroValues values;
};
struct MicroTable {
  std::vector<MicroRow> rows;  // the nine in the paper's order (those present), then the others
  MicroValues average;         // mean of the nine types' rows
  // NO averaged over living, dining, bed, kitchen and children's rooms (the rows' mean), the goal.
  std::optional<double> rich_no;
};
MicroTable MicroTableOf(const std::vector<RoomScore>& rooms);

struct SceneEvalOptions {
  PlanOptions plan;  // for requests given as text: request i is planned with seed plan.seed + i
  // Every scene's furnishing: rooms, jobs, library, solver, the reach hook. Its text is each request's
  // and its seed plan.seed + i + k for scene k of request i.
  solver::FurnishOptions furnish;
  int scenes_per_layout = 3;  // [1, 100]
  // Where each scene's outputs are kept ("" = nowhere): keep/<layout>/<seed>/ holds layout.json,
  // scene.json, furnished.glb, report.json and CREDITS (the files `villa furnish` writes, no pictures),
  // written into a hidden sibling folder and renamed into place, so a scene's folder is whole or absent.
  // <layout> is KeptLayoutName of the request; a scene folder already there is never replaced.
  std::filesystem::path keep;
  std::function<void(size_t scenes)> on_start;  // once, with the number of scenes
  std::function<void()> on_scene_done;          // after each scene

  std::string Check() const;  // empty when usable
};

struct SceneResult {
  int layout = 0, scene = 0;
  uint64_t seed = 0;
  solver::FurnishSummary summary;
  std::optional<double> rch;  // mean over rooms when measured
  std::string error;          // set when this scene could not be furnished
};
struct LayoutResult {
  SceneRequest request;
  std::optional<PlanSummary> plan;  // when planned from text
  LayoutMetrics metrics;            // FSR, RR, VCR of the layout
  int rooms = 0;
  std::string error;                // no valid layout: not furnished
};
struct SceneEvalSummary {
  std::vector<LayoutResult> layouts;
  std::vector<SceneResult> scenes;
  std::vector<RoomScore> rooms;
  MicroTable micro;
  // Issue 27's functional checks (solver/functional.h) summed per room type (TypeName order: the paper's
  // nine, then balconies and others) and over every furnished room.
  std::vector<std::pair<std::string, solver::FunctionalTally>> functional;
  solver::FunctionalTally functional_all;
  std::vector<std::string> functional_failing;  // "<request id> scene k <room>: what fails", one a room
  MetricsSummary macro;             // over every layout
  std::optional<double> adherence;  // mean over the planned requests
  bool reach_measured = false;
  // Issue 28: the settle of every scene (physics/glb_settle.h), free objects and the stable ones summed per
  // room type and over all; none measured with --no-physics.
  std::map<std::string, physics::StabilityCount> stability;
  physics::StabilityCount stability_all;
  bool physics_measured = false;
  std::string library_note;
  double seconds = 0.0;             // wall, the whole run
  double plan_seconds = 0.0;        // wall, planning
  double furnish_seconds = 0.0;     // wall, furnishing (every scene)
  double room_seconds = 0.0;        // summed over furnished rooms (plan + acquire + solve), as on one core
  int furnished_rooms = 0;          // room furnishings behind room_seconds
  int jobs = 0;
  int kept = 0;                     // scene folders written under options.keep
  std::string kept_in;              // options.keep ("" = none)
};

// The folder of request `index` (0-based) under --keep: "001-" and the request's id (its last path
// component) with every character outside [A-Za-z0-9._-] as '_', cut to 60 characters ("001-cottage",
// "002-two-floor-house.json").
std::string KeptLayoutName(size_t index, const std::string& id);

// Plans, builds and furnishes every request (options checked first). Errors: bad options, a library that
// cannot be opened; a request that gives no valid layout is reported in its LayoutResult.
Result<SceneEvalSummary> EvaluateScenes(const std::vector<SceneRequest>& requests, const SceneEvalOptions& options);

// The outputs of `villa eval --scenes`: a text report (a row per scene, the micro table, the functional
// checks per room type with the failing rooms, the macro table, times and the ratio to the paper's ~15 min
// a room and ~225 min a villa), JSON, and Markdown tables.
std::string SceneEvalText(const SceneEvalSummary& summary);
nlohmann::ordered_json SceneEvalJson(const SceneEvalSummary& summary);
std::string SceneEvalMarkdown(const SceneEvalSummary& summary);

// The micro table alone, for scored .glb files (`villa eval --scenes --glb`): text, JSON, Markdown.
std::string MicroTableText(const MicroTable& table);
nlohmann::ordered_json MicroTableJson(const MicroTable& table);
std::string MicroTableMarkdown(const MicroTable& table);

}  // namespace villa
