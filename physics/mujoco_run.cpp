#include "physics/mujoco_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include <mujoco/mujoco.h>

namespace villa::physics {
namespace {
constexpr double kStartDepth = 0.002;  // m: deeper than this at the start is a defect (issue 28)
}  // namespace

Result<MujocoRun> RunMujoco(const std::filesystem::path& xml, const SettleOptions& options) {
  if (std::string bad = options.Check(); !bad.empty()) return Error{"mujoco: " + bad};
  const auto start = std::chrono::steady_clock::now();
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> model(mj_loadXML(xml.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  if (!model) return Error{xml.string() + ": MuJoCo cannot load it: " + error};
  std::unique_ptr<mjData, void (*)(mjData*)> data(mj_makeData(model.get()), mj_deleteData);
  if (!data)
    return Error{xml.string() + ": MuJoCo cannot make its data (nconmax " + std::to_string(model->nconmax) + ", njmax " +
                 std::to_string(model->njmax) + ": too much memory?)"};
  const mjModel* m = model.get();
  mjData* d = data.get();
  MujocoRun run;
  run.version = std::to_string(mj_version() / 100) + "." + std::to_string(mj_version() / 10 % 10) + "." +
                std::to_string(mj_version() % 10);
  mj_forward(m, d);
  auto body_name = [&](int geom) {
    const char* name = mj_id2name(m, mjOBJ_BODY, m->geom_bodyid[geom]);
    return std::string(name ? name : "world");
  };
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    if (c.dist >= -kStartDepth) continue;
    ++run.deep_at_start;
    if (-c.dist <= run.deepest_at_start) continue;
    run.deepest_at_start = -c.dist;
    run.deepest_pair = body_name(c.geom1) + " and " + body_name(c.geom2);
  }
  const std::vector<double> pos(d->xpos, d->xpos + 3 * m->nbody), quat(d->xquat, d->xquat + 4 * m->nbody);
  const int steps = std::max(1, static_cast<int>(std::lround(options.seconds / m->opt.timestep)));
  // The warnings are read after every step: on a bad acceleration MuJoCo resets the data (every body back
  // where it started, the other warnings cleared), and the run goes on from the start.
  for (int k = 0; k < steps; ++k) {
    mj_step(m, d);
    run.max_contacts = std::max(run.max_contacts, d->ncon);
    run.max_rows = std::max(run.max_rows, d->nefc);
    run.buffers_full = run.buffers_full || d->warning[mjWARN_CONTACTFULL].number > 0 || d->warning[mjWARN_CNSTRFULL].number > 0;
    run.unstable = run.unstable || d->warning[mjWARN_BADQACC].number > 0;
  }
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] == mjJNT_HINGE) ++run.hinges;
    if (m->jnt_type[j] != mjJNT_FREE) continue;
    const int b = m->jnt_bodyid[j];
    double moved2 = 0.0, dot = 0.0;
    for (int i = 0; i < 3; ++i) moved2 += (d->xpos[3 * b + i] - pos[3 * b + i]) * (d->xpos[3 * b + i] - pos[3 * b + i]);
    for (int i = 0; i < 4; ++i) dot += d->xquat[4 * b + i] * quat[4 * b + i];
    const double moved = std::sqrt(moved2), turned = 2.0 * std::acos(std::min(1.0, std::abs(dot)));
    ++run.free;
    // After a reset nothing has moved far: an unstable run shows nothing stable.
    const bool strict = !run.unstable && moved <= options.strict_move && turned <= options.strict_turn;
    run.strict += strict;
    run.loose += !run.unstable && moved <= options.loose_move && turned <= options.loose_turn;
    if (!strict) run.movers.push_back({mj_id2name(m, mjOBJ_BODY, b) ? mj_id2name(m, mjOBJ_BODY, b) : "", moved, turned});
  }
  std::sort(run.movers.begin(), run.movers.end(), [](const MujocoMover& a, const MujocoMover& b) { return a.moved > b.moved; });
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

Result<MjcfExport> ExportMjcf(const std::filesystem::path& glb, const std::filesystem::path& dir,
                              const SettleOptions& options) {
  auto written = WriteMjcf(glb, dir, options);
  if (!written.ok()) return Error{written.error()};
  MjcfExport out{*written, {}};
  const std::filesystem::path xml = dir / "villa.xml";
  for (int nconmax = written->nconmax, njmax = written->njmax;;) {
    auto run = RunMujoco(xml, options);
    if (!run.ok()) return Error{run.error()};
    out.run = *run;
    if (!run->buffers_full) break;
    if (njmax >= kMjcfMaxRows)
      return Error{xml.string() + ": the scene needs more than " + std::to_string(kMjcfMaxRows) +
                   " constraint rows, more than MuJoCo 2.2's buffers hold (split the villa by floor)"};
    nconmax = std::min(2 * nconmax, kMjcfMaxRows / 3);
    njmax = std::min(2 * njmax, kMjcfMaxRows);
    if (Status s = SetMjcfBuffers(xml, nconmax, njmax); !s) return Error{s.error()};
  }
  out.written.nconmax = std::max(100, (5 * out.run.max_contacts + 3) / 4);
  out.written.njmax = std::max(300, (5 * out.run.max_rows + 3) / 4);
  if (Status s = SetMjcfBuffers(xml, out.written.nconmax, out.written.njmax); !s) return Error{s.error()};
  return out;
}

}  // namespace villa::physics
