// The critic loop: the solver's own solve, then rounds of observe / evaluate / act (critic/critic.h).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "assets/category.h"
#include "assets/procedural.h"
#include "critic/critic.h"
#include "critic/observation.h"
#include "critic/offline.h"
#include "critic/prompts.h"
#include "solver/functional.h"
#include "solver/scene_problem.h"
#include "util/atomic_file.h"
#include "util/text_table.h"

namespace villa::critic {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
double Round4(double v) {
  const double r = std::round(v * 1e4) / 1e4;
  return r == 0.0 ? 0.0 : r;
}
constexpr double kDeg = std::numbers::pi / 180.0;

// ---- the round log: <log_dir>/<room>/round-N/

class RoundLog {
 public:
  RoundLog(const fs::path& room_dir, int round) : dir_(room_dir.empty() ? fs::path() : room_dir / ("round-" + std::to_string(round))) {}
  bool on() const { return !dir_.empty(); }
  void Write(const std::string& name, const std::string& bytes) {
    if (!on()) return;
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) {
      errors_.push_back(dir_.string() + ": cannot create the folder: " + ec.message());
      return;
    }
    if (Status s = WriteFileAtomic(dir_ / name, bytes); !s.ok()) errors_.push_back(s.error());
  }
  void WriteJson(const std::string& name, const Json& j) { Write(name, j.dump(2) + "\n"); }
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  fs::path dir_;
  std::vector<std::string> errors_;
};

// The request body as logged: every image data URI replaced by the name of the picture file that holds
// it (the pictures are written beside it), in order.
Json WithPictureNames(Json body, const std::vector<std::string>& names) {
  size_t next = 0;
  for (Json& message : body["messages"]) {
    if (!message["content"].is_array()) continue;
    for (Json& part : message["content"])
      if (part.value("type", "") == "image_url") part["image_url"]["url"] = next < names.size() ? names[next++] : "(picture)";
  }
  return body;
}

Json TurnsJson(const JsonChatResult& chat, const std::vector<std::string>& pictures) {
  Json turns = Json::array();
  for (const JsonChatTurn& t : chat.turns)
    turns.push_back({{"request", WithPictureNames(t.request, pictures)},
                     {"answer", t.answer},
                     {"finish_reason", t.finish_reason},
                     {"error", t.error},
                     {"cached", t.cached},
                     {"http_attempts", t.http_attempts},
                     {"prompt_tokens", t.prompt_tokens},
                     {"completion_tokens", t.completion_tokens},
                     {"seconds", Round4(t.seconds)}});
  return turns;
}

Json EnergyJson(const solver::EnergyTerms& e) {
  return {{"total", Round4(e.total)}, {"collision", Round4(e.collision)}, {"support", Round4(e.support)}, {"semantic", Round4(e.semantic)}};
}

// What does not hold, a line each: "sofa-0 face_to tv-stand-0: angle 42.0 deg > 30", "zone of bed-0 (sides,
// 0.6 m): nightstand-1".
Json UnmetLines(const RoomRelations& r) {
  Json lines = Json::array();
  for (const EdgeCheck& c : r.edges)
    if (c.present && !c.satisfied)
      lines.push_back(c.edge.source + " " + std::string(scene::SemanticRelationName(c.edge.relation)) + " " + c.edge.target + ": " + c.detail);
  for (const ZoneCheck& z : r.zones) {
    if (z.clear()) continue;
    std::string line = "zone of " + z.owner + " (" + z.side + ", " + FormatFixed(z.depth, 2) + " m):";
    for (const std::string& id : z.intruders) line += " " + id;
    lines.push_back(std::move(line));
  }
  return lines;
}

Json RelationsJson(const RoomRelations& r) {
  RelationTally tally;
  AddToTally(r, tally);
  return {{"satisfied", r.Satisfied()},
          {"measured", r.Present()},
          {"edges", r.edges.size()},
          {"zones_clear", r.ZonesClear()},
          {"zones", r.zones.size()},
          {"by_relation", TallyJson(tally)},
          {"unmet", UnmetLines(r)}};
}

// ---- the session helpers

bool HardTrouble(const solver::RoomSolution& s) {
  return !s.summary.metrics.Clean() || s.summary.energy.collision > 0.0 || s.summary.energy.support > 0.0;
}

// ---- the offline rounds

struct LoopState {
  const solver::RoomCriticInput& input;
  const CriticOptions& options;
  solver::RoomSolver& session;
  std::vector<scene::SemanticEdge> graph;
  fs::path room_log;
  Json rounds = Json::array();
  std::vector<std::string> log_errors;
  solver::CriticFigures figures;
  std::string stopped;
  int kept_round = 0;  // the model critic went back to this round's arrangement (0: it did not)
  // The offline critic's best arrangement seen (fewest unmet relations, physically clean): an undo the
  // solver had to repair (shift) can leave a room worse than before the attempt; the loop ends on the best.
  std::shared_ptr<const solver::RoomSolver::Snapshot> best_room;
  Unmet best_unmet;
  bool back_to_best = false;
};

// Notes the session's arrangement as the best seen when it is physically clean with fewer unmet relations.
void NoteBest(LoopState& st);

RoomRelations Measure(const LoopState& st, const solver::RoomSolution& s) { return MeasureRelations(s.objects, s.placements, st.graph); }

// The functional checks' group problems and missing essentials of an arrangement (the floor not measured).
int GroupProblems(const LoopState& st, const solver::RoomSolution& s) {
  if (!st.input.context || !st.input.problem || !st.input.planned) return 0;
  const std::vector<scene::SceneObject> objects = solver::SolvedSceneObjects(*st.input.problem, s, *st.input.planned);
  solver::FunctionalInput in;
  in.context = st.input.context;
  for (const scene::SceneObject& o : objects) in.objects.push_back(&o);
  if (st.input.edges) in.edges = *st.input.edges;
  in.measure_floor = false;
  const solver::FunctionalCheck check = solver::CheckRoomFunction(in);
  int n = static_cast<int>(check.missing.size());
  for (const solver::GroupCheck& g : check.groups) n += static_cast<int>(g.problems.size());
  return n;
}

// Unmet relations and zones, with the group problems first.
Unmet UnmetAll(const LoopState& st, const solver::RoomSolution& s, const RoomRelations& relations) {
  Unmet u = UnmetOf(relations);
  u.groups = GroupProblems(st, s);
  return u;
}

void LogViews(RoundLog& log, const std::vector<solver::RoomViewImage>& views, std::vector<std::string>* names) {
  for (const solver::RoomViewImage& v : views) {
    const std::string name = "view-" + v.name + ".png";
    auto png = EncodePng(v.image);
    if (png.ok()) log.Write(name, *png);
    if (names) names->push_back(name);
  }
}

void NoteBest(LoopState& st) {
  const solver::RoomSolution now = st.session.Solution();
  if (HardTrouble(now)) return;
  const Unmet u = UnmetAll(st, now, Measure(st, now));
  if (st.best_room && !(u < st.best_unmet)) return;
  st.best_room = st.session.Save();
  st.best_unmet = u;
}

// Ends the offline rounds on the best arrangement seen, when the present one is worse.
void BackToBest(LoopState& st) {
  if (!st.best_room) return;
  const solver::RoomSolution now = st.session.Solution();
  if (!HardTrouble(now) && !(st.best_unmet < UnmetAll(st, now, Measure(st, now)))) return;
  st.session.Restore(*st.best_room);
  st.back_to_best = true;
}

void OfflineRounds(LoopState& st) {
  NoteBest(st);
  std::set<std::string> given_up;
  double best_score = -1.0;
  int tries = 0;
  bool escalating = false;  // the last round gave single moves up: group moves come next
  int last_kept = 0;        // alternatives the last round kept
  OfflineProposalOptions proposal;
  proposal.clearance = st.options.clearance;
  for (int round = 1; round <= st.options.rounds; ++round) {
    RoundLog log(st.room_log, round);
    const solver::RoomSolution now = st.session.Solution();
    const RoomRelations relations = Measure(st, now);
    const double score = OfflineScore(relations);
    const std::vector<std::string> problems = OfflineProblems(st.input.problem->room, relations);
    Json record{{"round", round},
                {"score", Round4(score)},
                {"energy", EnergyJson(now.summary.energy)},
                {"relations", RelationsJson(relations)},
                {"problems", problems}};
    if (log.on()) {
      log.Write("state.txt", RoomStateText(st.input, now, relations, {}));
      if (st.options.log_pictures) {
        auto views = RoomViews(st.input, now, st.options.views);
        if (views.ok()) LogViews(log, *views, nullptr);
      }
    }
    ++st.figures.rounds;
    auto finish_round = [&](const std::string& why) {
      st.stopped = why;
      record["stopped"] = why;
      log.WriteJson("round.json", record);
      st.rounds.push_back(record);
      st.log_errors.insert(st.log_errors.end(), log.errors().begin(), log.errors().end());
    };
    if (problems.empty()) return finish_round("every relation of the graph holds and every zone is clear");
    // The score counts relations; a round may bring one nearer to holding without mending it (the painting
    // made smaller, nearer the sofa's axis), and the next round builds on it. So the loop stops at a low E
    // only when the last round kept nothing at all; a round that only gave problems up still has their group
    // moves to try in the next one.
    if (now.summary.energy.total <= st.options.energy_threshold && score <= best_score + 1e-9 && last_kept == 0 && !escalating)
      return finish_round("E <= " + std::to_string(st.options.energy_threshold).substr(0, 4) + " and the score stopped improving");
    best_score = std::max(best_score, score);
    if (tries >= st.options.max_tries) return finish_round("the critic's tries are spent");
    const std::vector<Attempt> attempts = ProposeOffline(st.session, *st.input.problem, now, st.graph, relations, proposal, given_up);
    if (attempts.empty()) return finish_round("no candidate pose is left for the unmet relations");
    Json tried = Json::array();
    int kept = 0;
    escalating = false;
    for (const Attempt& attempt : attempts) {
      if (tries >= st.options.max_tries) break;
      const solver::RoomSolution before = st.session.Solution();
      const RoomRelations before_relations = Measure(st, before);
      const Unmet unmet_before = UnmetAll(st, before, before_relations);
      Json entry{{"problem", attempt.problem}, {"kept", false}, {"actions", Json::array()}};
      bool helped = false;
      for (const std::vector<Step>& alternative : attempt.alternatives) {
        if (tries >= st.options.max_tries) break;
        std::vector<solver::ActionResult> results;
        // An alternative that does not help is undone by going back to the room as it was before it
        // (RoomSolver::Save / Restore): moving each object back one by one can be refused where another has
        // taken its place (what the solver re-placed around a group), and a bed made smaller with its
        // pillows laid out again cannot grow back over pillows already put back.
        const std::shared_ptr<const solver::RoomSolver::Snapshot> undo = st.session.Save();
        bool refused = false;
        for (const Step& step : alternative) {
          solver::Action a = step.action;
          if (step.suggest) {
            // Where the solver would put it now, after the steps before this one.
            auto slot = st.session.Suggest(a.id);
            if (!slot) continue;
            a.pose = slot->pose;
            for (const solver::ProblemObject& o : before.objects)
              if (o.id == a.id && o.relation != solver::Relation::kOnWall) a.pose->z = std::nan("");
            if (slot->wall >= 0) a.wall = slot->wall;
            if (slot->surface >= 0) a.surface = slot->surface;
            if (slot->cavity >= 0) a.cavity = slot->cavity;
          }
          results.push_back(st.session.Apply(a));
          ++tries;
          if (results.back().status == solver::ActionStatus::kRefused && !step.suggest) {
            refused = true;
            break;
          }
        }
        const solver::RoomSolution after = st.session.Solution();
        const RoomRelations after_relations = Measure(st, after);
        helped = !HardTrouble(after) && !results.empty() && !refused && UnmetAll(st, after, after_relations) < unmet_before;
        if (!helped) st.session.Restore(*undo);
        for (const solver::ActionResult& r : results) entry["actions"].push_back(solver::ActionResultToJson(r));
        if (helped) break;
      }
      entry["kept"] = helped;
      kept += helped;
      NoteBest(st);
      if (!helped) {
        given_up.insert(attempt.problem);
        escalating = escalating || attempt.problem.find(" [group]") == std::string::npos;
      }
      tried.push_back(std::move(entry));
    }
    record["attempts"] = std::move(tried);
    record["kept"] = kept;
    last_kept = kept;
    // The critic owns the semantics: what it kept stays (the agent's best state is the proxy E's choice);
    // anything physically wrong goes back to the rule agent.
    st.session.KeepCurrent();
    if (HardTrouble(st.session.Solution())) st.session.RunAgent();
    record["energy_after"] = EnergyJson(st.session.Solution().summary.energy);
    log.WriteJson("round.json", record);
    st.rounds.push_back(record);
    st.log_errors.insert(st.log_errors.end(), log.errors().begin(), log.errors().end());
    if (round == st.options.rounds) st.stopped = "the round budget is spent";
  }
}

// ---- the model's rounds

// A solver action for a model's proposal; an error (the action is reported refused) when it cannot be
// made, e.g. no asset for a new object's category.
Result<solver::Action> ToSolverAction(const ProposedAction& p, const solver::RoomSolution& now, const solver::RoomCriticInput& input,
                                      uint64_t seed) {
  solver::Action a;
  a.reason = "critic: " + p.reason;
  a.id = p.id;
  auto at = [&](const std::string& id) -> const solver::ObjectPlacement* {
    for (size_t k = 0; k < now.objects.size(); ++k)
      if (now.objects[k].id == id) return &now.placements[k];
    return nullptr;
  };
  if (p.action == "remove_entity") {
    // Issue 27: the room's essential pieces and what the request named stay; the model may move, turn or
    // shrink them.
    for (const solver::ProblemObject& o : now.objects)
      if (o.id == p.id && solver::IsProtected(o.priority))
        return Error{p.id + " is " + std::string(solver::PriorityName(o.priority)) + " to the room: it is kept (move, turn or shrink it instead)"};
    a.kind = solver::ActionKind::kRemoveEntity;
    return a;
  }
  if (p.action == "update_scale") {
    a.kind = solver::ActionKind::kUpdateScale;
    a.scale = *p.scale;
    return a;
  }
  if (p.action == "update_pose") {
    a.kind = solver::ActionKind::kUpdatePose;
    const solver::ObjectPlacement* pl = at(p.id);
    if (!pl) return Error{"no object " + p.id};
    solver::Pose pose = pl->pose;
    if (p.x) pose.x = *p.x, pose.y = *p.y;
    if (p.yaw_deg) pose.yaw = solver::WrapAngle(*p.yaw_deg * kDeg);
    int k = 0;
    for (; k < static_cast<int>(now.objects.size()) && now.objects[k].id != p.id; ++k) {
    }
    if (now.objects[k].relation != solver::Relation::kOnWall) pose.z = std::nan("");
    a.pose = pose;
    if (p.wall) a.wall = *p.wall;
    return a;
  }
  // add_entity: a procedural asset of the category at its usual size, the next free id.
  a.kind = solver::ActionKind::kAddEntity;
  const CategoryInfo* category = FindCategory(p.category);
  if (!category) return Error{"unknown category " + p.category};
  std::string id;
  for (int k = 0;; ++k) {
    id = input.problem->room + "/" + p.category + "-" + std::to_string(k);
    if (!at(id) && input.problem->Find(id) < 0) break;
  }
  const Vec3 size = (category->size_min + category->size_max) * 0.5;
  auto asset_id = ProceduralAssetId(p.category, size, "modern", static_cast<uint32_t>(seed));
  if (!asset_id.ok()) return Error{"no asset for a " + p.category + ": " + asset_id.error()};
  if (!input.resolve) return Error{"no asset resolver"};
  auto resolved = input.resolve(*asset_id);
  if (!resolved.ok()) return Error{resolved.error()};
  solver::ProblemObject o;
  o.id = id;
  o.category = p.category;
  o.asset = resolved->first;
  o.mesh = resolved->second;
  auto relation = solver::ParseRelation(p.relation);
  o.relation = relation ? *relation : solver::Relation::kOnTop;
  o.parent = o.relation == solver::Relation::kOnWall    ? "wall"
             : o.relation == solver::Relation::kHanging ? "ceiling"
             : o.relation == solver::Relation::kAgainstWall ? "floor"
                                                            : (p.parent.empty() ? "floor" : p.parent);
  if (o.relation == solver::Relation::kInside && scene::IsRootParent(o.parent)) return Error{"inside needs an object as parent"};
  o.scale_min = 0.8;
  o.scale_max = 1.0;
  o.priority = solver::Priority::kDecorative;
  if (category->zone && o.asset.Has(kInteractor)) o.zone = solver::InteractionZone{category->zone->side, category->zone->depth, {}};
  a.id = id;
  a.object = o;
  if (p.x) {
    solver::Pose pose;
    pose.x = *p.x;
    pose.y = *p.y;
    pose.z = std::nan("");
    pose.yaw = p.yaw_deg ? solver::WrapAngle(*p.yaw_deg * kDeg) : 0.0;
    a.pose = pose;
  }
  return a;
}

std::set<std::string> Ids(const solver::RoomSolution& s) {
  std::set<std::string> ids;
  for (const solver::ProblemObject& o : s.objects) ids.insert(o.id);
  return ids;
}

void Account(solver::CriticFigures& f, const JsonChatResult& chat) {
  f.requests += chat.requests;
  f.cache_hits += chat.cache_hits;
  f.prompt_tokens += chat.prompt_tokens;
  f.completion_tokens += chat.completion_tokens;
}

Status ModelRounds(LoopState& st) {
  const std::string& room = st.input.problem->room;
  double best_score = -1.0;
  // The best round judged so far (the lowest E with the model's score) and its arrangement: a round judged
  // worse goes back to it and the loop ends there.
  int best_round = 0;
  double best_energy = 0.0;
  std::shared_ptr<const solver::RoomSolver::Snapshot> best_room;
  std::vector<solver::ActionResult> last;
  solver::RoomViewOptions views = st.options.views;
  for (int round = 1; round <= st.options.rounds; ++round) {
    RoundLog log(st.room_log, round);
    const solver::RoomSolution now = st.session.Solution();
    const RoomRelations relations = Measure(st, now);
    const std::string state = RoomStateText(st.input, now, relations, last);
    auto rendered = RoomViews(st.input, now, views);
    if (!rendered.ok()) return Error{rendered.error()};
    std::vector<std::string> pngs, names;
    for (const solver::RoomViewImage& v : *rendered) {
      auto png = EncodePng(v.image);
      if (!png.ok()) return Error{png.error()};
      pngs.push_back(*png);
      names.push_back("view-" + v.name + ".png");
      log.Write(names.back(), pngs.back());
    }
    log.Write("state.txt", state);
    ++st.figures.rounds;
    Json record{{"round", round}, {"energy", EnergyJson(now.summary.energy)}, {"relations", RelationsJson(relations)}};
    auto finish_round = [&](const std::string& why) {
      if (!why.empty()) {
        st.stopped = why;
        record["stopped"] = why;
      }
      log.WriteJson("round.json", record);
      st.rounds.push_back(record);
      st.log_errors.insert(st.log_errors.end(), log.errors().begin(), log.errors().end());
    };

    // Evaluate.
    const std::set<std::string> ids = Ids(now);
    Evaluation evaluation;
    const JsonCheck check_evaluation = [&](const nlohmann::json& j) {
      auto e = ReadEvaluation(j, room, ids);
      if (!e.ok()) return e.error();
      evaluation = *e;
      return std::string();
    };
    const JsonChatResult asked = AskJson(st.options.llm,
                                         {{"system", EvaluationSystemPrompt(), {}},
                                          {"user", EvaluationUserText(st.input.text, state), pngs}},
                                         st.options.json_schema ? EvaluationResponseFormat() : nullptr, check_evaluation,
                                         st.options.chat);
    Account(st.figures, asked);
    log.WriteJson("evaluation.json", TurnsJson(asked, names));
    if (!asked.accepted) {
      record["error"] = asked.error;
      finish_round("the model gave no usable evaluation: " + asked.error);
      return Status::Ok();  // the room keeps the solver's arrangement; the log says why
    }
    const solver::EnergyTerms& e = now.summary.energy;
    const double energy = 5.0 * e.collision + 2.0 * e.support + (10.0 - evaluation.score);
    Json problems = Json::array();
    for (const Evaluation::Problem& p : evaluation.problems) problems.push_back({{"objects", p.objects}, {"problem", p.problem}});
    record["score"] = Round4(evaluation.score);
    record["energy_with_score"] = Round4(energy);
    record["problems"] = problems;
    if (best_round > 0 && energy > best_energy + 1e-9) {
      st.session.Restore(*best_room);
      record["rolled_back_to"] = best_round;
      st.kept_round = best_round;
      finish_round("E rose to " + FormatFixed(energy, 2) + " from round " + std::to_string(best_round) + "'s " + FormatFixed(best_energy, 2) +
                   ": back to round " + std::to_string(best_round) + "'s arrangement");
      return Status::Ok();
    }
    if (best_round == 0 || energy < best_energy - 1e-9) {
      best_round = round;
      best_energy = energy;
      best_room = st.session.Save();
    }
    if (energy <= st.options.energy_threshold && evaluation.score <= best_score + 1e-9) {
      finish_round("E <= " + std::to_string(st.options.energy_threshold).substr(0, 4) + " and the score stopped improving");
      return Status::Ok();
    }
    if (evaluation.score >= 10.0 - 1e-9 && evaluation.problems.empty()) {
      finish_round("the model finds nothing to improve");
      return Status::Ok();
    }
    best_score = std::max(best_score, evaluation.score);

    // Act.
    std::vector<ProposedAction> proposed;
    const int walls = static_cast<int>(st.input.problem->walls.size());
    const JsonCheck check_actions = [&](const nlohmann::json& j) {
      auto a = ReadActions(j, room, ids, walls, st.options.max_actions);
      if (!a.ok()) return a.error();
      proposed = *a;
      return std::string();
    };
    const JsonChatResult acted = AskJson(st.options.llm,
                                         {{"system", ActionsSystemPrompt(), {}},
                                          {"user", ActionsUserText(st.input.text, state, evaluation, room), pngs}},
                                         st.options.json_schema ? ActionsResponseFormat() : nullptr, check_actions, st.options.chat);
    Account(st.figures, acted);
    log.WriteJson("actions-request.json", TurnsJson(acted, names));
    if (!acted.accepted) {
      record["error"] = acted.error;
      finish_round("the model gave no usable actions: " + acted.error);
      return Status::Ok();
    }
    if (proposed.empty()) {
      finish_round("the model proposes no action");
      return Status::Ok();
    }
    last.clear();
    for (size_t k = 0; k < proposed.size(); ++k) {
      auto action = ToSolverAction(proposed[k], st.session.Solution(), st.input, st.input.solve.seed + 7919 * round + k);
      if (!action.ok()) {
        solver::ActionResult refused;
        refused.action.id = proposed[k].id;
        refused.action.kind = proposed[k].action == "add_entity" ? solver::ActionKind::kAddEntity : solver::ActionKind::kUpdatePose;
        refused.action.reason = "critic: " + proposed[k].reason;
        refused.status = solver::ActionStatus::kRefused;
        refused.message = action.error();
        last.push_back(refused);
        continue;
      }
      last.push_back(st.session.Apply(*action));
    }
    st.session.KeepCurrent();
    if (HardTrouble(st.session.Solution())) st.session.RunAgent();
    Json results = Json::array();
    for (const solver::ActionResult& r : last) results.push_back(solver::ActionResultToJson(r));
    record["actions"] = std::move(results);
    record["energy_after"] = EnergyJson(st.session.Solution().summary.energy);
    finish_round(round == st.options.rounds ? "the round budget is spent" : "");
  }
  return Status::Ok();
}

}  // namespace

std::string_view CriticKindName(CriticKind kind) {
  switch (kind) {
    case CriticKind::kNone: return "none";
    case CriticKind::kOffline: return "offline";
    case CriticKind::kMllm: return "mllm";
  }
  return "none";
}

std::optional<CriticKind> ParseCriticKind(std::string_view name) {
  for (CriticKind k : {CriticKind::kNone, CriticKind::kOffline, CriticKind::kMllm})
    if (CriticKindName(k) == name) return k;
  return std::nullopt;
}

std::string CriticOptions::Check() const {
  if (rounds < 1 || rounds > 50) return "critic rounds " + std::to_string(rounds) + ": must be in [1, 50]";
  if (!(energy_threshold > 0.0 && energy_threshold <= 100.0)) return "critic energy threshold: must be in (0, 100]";
  if (max_tries < 1 || max_tries > 2000) return "critic tries " + std::to_string(max_tries) + ": must be in [1, 2000]";
  if (!(clearance >= 0.0 && clearance <= 0.2)) return "critic clearance: must be in [0, 0.2] m";
  if (max_actions < 1 || max_actions > 50) return "critic actions per answer " + std::to_string(max_actions) + ": must be in [1, 50]";
  if (std::string p = views.Check(); !p.empty()) return "critic views: " + p;
  std::string message;
  if (!chat.IsValid(&message)) return "critic: " + message;
  if (kind == CriticKind::kMllm && !llm.IsValid(&message)) return "critic: " + message;
  return "";
}

std::string RoomLogFolder(const std::string& room) {
  std::string name = room;
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

Result<CritiqueResult> CritiqueRoom(const solver::RoomCriticInput& input, const CriticOptions& options) {
  if (std::string problem = options.Check(); !problem.empty()) return Error{problem};
  std::unique_ptr<solver::RoomSolver> own;
  if (!input.session) {
    own = std::make_unique<solver::RoomSolver>(*input.problem, input.solve, input.check);
    if (Status s = own->Initialise(); !s.ok()) return Error{s.error()};
    own->RunAgent();
  }
  solver::RoomSolver& session = input.session ? *input.session : *own;
  const auto start = Clock::now();

  LoopState st{input, options, session, {}, {}, Json::array(), {}, {}, "", 0, nullptr, {}, false};
  // The graph's edges between objects the solver was given (edges of objects dropped before solving are
  // no critic's business).
  for (const scene::SemanticEdge& e : *input.edges)
    if (input.problem->Find(e.source) >= 0 && input.problem->Find(e.target) >= 0) st.graph.push_back(e);
  if (!options.log_dir.empty()) {
    st.room_log = options.log_dir / RoomLogFolder(input.problem->room);
    // An earlier run's rounds of this room (ours: round-N folders and critic.json) would mix with these.
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(st.room_log, ec)) {
      const std::string name = entry.path().filename().string();
      const bool round = name.rfind("round-", 0) == 0 && name.size() > 6 &&
                         std::all_of(name.begin() + 6, name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
      if (round || name == "critic.json") fs::remove_all(entry.path(), ec);
    }
  }
  st.figures.critic = std::string(CriticKindName(options.kind));
  const RoomRelations before = Measure(st, session.Solution());

  if (options.kind == CriticKind::kOffline) {
    OfflineRounds(st);
    BackToBest(st);
  } else if (options.kind == CriticKind::kMllm) {
    if (Status s = ModelRounds(st); !s.ok()) return Error{input.problem->room + ": critic: " + s.error()};
  }
  session.KeepCurrent();
  session.Finish();
  CritiqueResult out;
  out.solution = session.Solution();
  const RoomRelations after = Measure(st, out.solution);
  st.figures.seconds = Since(start);
  // The report keeps each round's score, energy and what was done; the log keeps everything.
  Json rounds = Json::array();
  for (const Json& r : st.rounds) {
    Json brief{{"round", r["round"]}};
    for (const char* key : {"score", "energy_with_score", "kept", "stopped", "error", "rolled_back_to"})
      if (r.contains(key)) brief[key] = r[key];
    brief["energy"] = r["energy"]["total"];
    if (r.contains("energy_after")) brief["energy_after"] = r["energy_after"]["total"];
    if (r.contains("actions")) brief["actions"] = r["actions"].size();
    if (r.contains("attempts")) brief["attempts"] = r["attempts"].size();
    brief["unmet"] = r["problems"].size();
    rounds.push_back(std::move(brief));
  }
  Json record{{"critic", st.figures.critic},
              {"rounds", std::move(rounds)},
              {"stopped", st.stopped},
              {"relations_before", RelationsJson(before)},
              {"relations_after", RelationsJson(after)}};
  if (st.kept_round > 0) record["kept_round"] = st.kept_round;
  if (st.back_to_best) record["back_to_best"] = true;  // the offline rounds ended worse than their best
  if (!st.log_errors.empty()) record["log_errors"] = st.log_errors;
  if (!st.room_log.empty()) {
    std::error_code ec;
    fs::create_directories(st.room_log, ec);
    Json index{{"room", input.problem->room}, {"critic", st.figures.critic}, {"rounds", st.figures.rounds}, {"stopped", st.stopped},
               {"relations_before", RelationsJson(before)}, {"relations_after", RelationsJson(after)}};
    if (st.kept_round > 0) index["kept_round"] = st.kept_round;
    if (Status s = WriteFileAtomic(st.room_log / "critic.json", index.dump(2) + "\n"); !s.ok()) record["log_errors"].push_back(s.error());
  }
  st.figures.record = std::move(record);
  out.figures = std::move(st.figures);
  return out;
}

solver::RoomCritic MakeRoomCritic(const CriticOptions& options) {
  if (options.kind == CriticKind::kNone) return {};
  return [options](const solver::RoomCriticInput& input) -> Result<solver::CriticFigures> {
    auto result = CritiqueRoom(input, options);
    if (!result.ok()) return Error{result.error()};
    return std::move(result->figures);
  };
}

}  // namespace villa::critic
