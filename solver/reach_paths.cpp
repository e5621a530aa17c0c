#include "solver/reach_paths.h"

#include <chrono>
#include <mutex>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/ValidStateSampler.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include "mesh/geometry2d.h"
#include "solver/rng.h"

namespace villa::solver {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;

// OMPL reports every planner start at INFO level; only its errors are worth a person's attention here.
void QuietOmpl() {
  static std::once_flag once;
  std::call_once(once, [] { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); });
}

Point At(const ob::State* s) {
  const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
  return {v->values[0], v->values[1]};
}
void Put(ob::State* s, Point p) {
  auto* v = s->as<ob::RealVectorStateSpace::StateType>();
  v->values[0] = p.x;
  v->values[1] = p.y;
}

bool DiscFree(const RoadmapSpec& spec, Point p) {
  return spec.space->Clearance(PlanShape::Disc(p, spec.radius), spec.z0, spec.z1, 0.0).clearance >= 0.0;
}
bool WalkFree(const RoadmapSpec& spec, Point a, Point b) {
  return spec.space->Clearance(PlanShape::Capsule(a, b, spec.radius), spec.z0, spec.z1, 0.0).clearance >= 0.0;
}

// OMPL's StateValidityChecker on the shared query: the disc is valid where it touches nothing; its
// clearance is the query's (m, looked for up to 1 m).
class DiscChecker : public ob::StateValidityChecker {
 public:
  DiscChecker(const ob::SpaceInformationPtr& si, const RoadmapSpec& spec) : ob::StateValidityChecker(si), spec_(spec) {
    specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;
  }
  bool isValid(const ob::State* s) const override { return DiscFree(spec_, At(s)); }
  double clearance(const ob::State* s) const override {
    return spec_.space->Clearance(PlanShape::Disc(At(s), spec_.radius), spec_.z0, spec_.z1, 1.0).clearance;
  }

 private:
  const RoadmapSpec& spec_;
};

// A straight walk is valid when the capsule it sweeps touches nothing: exact, where OMPL's discrete
// validator would check states a few centimetres apart.
class WalkValidator : public ob::MotionValidator {
 public:
  WalkValidator(const ob::SpaceInformationPtr& si, const RoadmapSpec& spec) : ob::MotionValidator(si), spec_(spec) {}
  bool checkMotion(const ob::State* a, const ob::State* b) const override {
    const bool ok = WalkFree(spec_, At(a), At(b));
    ok ? ++valid_ : ++invalid_;
    return ok;
  }
  bool checkMotion(const ob::State* a, const ob::State* b, std::pair<ob::State*, double>& last) const override {
    if (checkMotion(a, b)) return true;
    // The last free point, stepping by half a cell.
    const Point pa = At(a), pb = At(b);
    const double len = geo::Dist(pa, pb);
    const int steps = std::max(1, static_cast<int>(std::ceil(len / (0.5 * spec_.cell))));
    double t_ok = 0.0;
    for (int k = 1; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      if (!WalkFree(spec_, pa, geo::Lerp(pa, pb, t))) break;
      t_ok = t;
    }
    last.second = t_ok;
    if (last.first) si_->getStateSpace()->interpolate(a, b, t_ok, last.first);
    return false;
  }

 private:
  const RoadmapSpec& spec_;
};

// A uniform point in a uniformly drawn free raster cell (SplitMix64, no std distributions).
Point DrawCell(const RoadmapSpec& spec, Rng& rng) {
  const size_t n = spec.cells.size();
  const size_t k = static_cast<size_t>((static_cast<unsigned __int128>(rng.Next()) * n) >> 64);
  const Point c = spec.cells[k];
  return {c.x + (rng.Unit() - 0.5) * spec.cell, c.y + (rng.Unit() - 0.5) * spec.cell};
}

class CellSampler : public ob::ValidStateSampler {
 public:
  CellSampler(const ob::SpaceInformation* si, const RoadmapSpec& spec, uint64_t seed)
      : ob::ValidStateSampler(si), spec_(spec), rng_(seed) {
    name_ = "free_cells";
  }
  bool sample(ob::State* s) override {
    for (unsigned k = 0; k < attempts_ && !spec_.cells.empty(); ++k) {
      Put(s, DrawCell(spec_, rng_));
      if (si_->isValid(s)) return true;
    }
    return false;
  }
  bool sampleNear(ob::State* s, const ob::State* near, double distance) override {
    const Point c = At(near);
    for (unsigned k = 0; k < attempts_; ++k) {
      Put(s, {c.x + (2.0 * rng_.Unit() - 1.0) * distance, c.y + (2.0 * rng_.Unit() - 1.0) * distance});
      if (si_->satisfiesBounds(s) && si_->isValid(s)) return true;
    }
    return false;
  }

 private:
  const RoadmapSpec& spec_;
  Rng rng_;
};

// RRTConnect's samples: free cells too (invalid ones are cheap to reject, free ones are where it must go).
class CellStateSampler : public ob::StateSampler {
 public:
  CellStateSampler(const ob::StateSpace* space, const RoadmapSpec& spec, uint64_t seed)
      : ob::StateSampler(space), spec_(spec), rng_(seed) {}
  void sampleUniform(ob::State* s) override {
    if (spec_.cells.empty()) {
      Put(s, {spec_.lo.x + rng_.Unit() * (spec_.hi.x - spec_.lo.x), spec_.lo.y + rng_.Unit() * (spec_.hi.y - spec_.lo.y)});
    } else {
      Put(s, DrawCell(spec_, rng_));
    }
  }
  void sampleUniformNear(ob::State* s, const ob::State* near, double distance) override {
    const Point c = At(near);
    Put(s, {std::clamp(c.x + (2.0 * rng_.Unit() - 1.0) * distance, spec_.lo.x, spec_.hi.x),
            std::clamp(c.y + (2.0 * rng_.Unit() - 1.0) * distance, spec_.lo.y, spec_.hi.y)});
  }
  void sampleGaussian(ob::State* s, const ob::State* mean, double stdDev) override { sampleUniformNear(s, mean, 2.0 * stdDev); }

 private:
  const RoadmapSpec& spec_;
  Rng rng_;
};

// OMPL's PRM with its milestone insertion and its roadmap search (A*) reachable from outside: the
// roadmap is grown once, then every query adds its two ends as milestones and searches.
class Roadmap : public og::PRM {
 public:
  explicit Roadmap(const ob::SpaceInformationPtr& si) : og::PRM(si) {}
  // Nearest milestones by a plain linear search (exact, and the same answer every run); PRM sets the
  // distance function only on the structure it makes itself.
  void UseLinearNeighbours() {
    setNearestNeighbors<ompl::NearestNeighborsLinear>();
    nn_->setDistanceFunction([this](const Vertex a, const Vertex b) { return distanceFunction(a, b); });
  }
  Vertex Add(ob::State* state) { return addMilestone(state); }
  bool Joined(Vertex a, Vertex b) { return sameComponent(a, b); }
  ob::PathPtr Route(Vertex a, Vertex b) { return constructSolution(a, b); }
};

// Cuts corners: from each kept point, on to the farthest later point the straight walk reaches.
std::vector<Point> Shorten(const RoadmapSpec& spec, const std::vector<Point>& path) {
  if (path.size() <= 2) return path;
  std::vector<Point> out = {path.front()};
  size_t i = 0;
  while (i + 1 < path.size()) {
    size_t j = path.size() - 1;
    while (j > i + 1 && !WalkFree(spec, path[i], path[j])) --j;
    out.push_back(path[j]);
    i = j;
  }
  return out;
}

}  // namespace

struct LevelRoadmap::Impl {
  RoadmapSpec spec;
  std::shared_ptr<ob::RealVectorStateSpace> space;
  ob::SpaceInformationPtr si;
  ob::ProblemDefinitionPtr pdef;
  std::shared_ptr<Roadmap> prm;
  uint64_t samplers = 0;  // RRTConnect samplers made, each with its own seed
  double seconds = 0.0;
};

LevelRoadmap::LevelRoadmap(RoadmapSpec spec) : impl_(new Impl) {
  QuietOmpl();
  const auto t = Clock::now();
  Impl& im = *impl_;
  im.spec = std::move(spec);
  const RoadmapSpec& s = im.spec;
  im.space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, s.lo.x);
  bounds.setLow(1, s.lo.y);
  bounds.setHigh(0, s.hi.x);
  bounds.setHigh(1, s.hi.y);
  im.space->setBounds(bounds);
  im.space->setStateSamplerAllocator([&im](const ob::StateSpace* space) -> ob::StateSamplerPtr {
    return std::make_shared<CellStateSampler>(space, im.spec, im.spec.seed * 0x9E3779B97F4A7C15ull + ++im.samplers);
  });
  im.si = std::make_shared<ob::SpaceInformation>(im.space);
  im.si->setStateValidityChecker(std::make_shared<DiscChecker>(im.si, im.spec));
  im.si->setMotionValidator(std::make_shared<WalkValidator>(im.si, im.spec));
  im.si->setValidStateSamplerAllocator([&im](const ob::SpaceInformation* si) -> ob::ValidStateSamplerPtr {
    return std::make_shared<CellSampler>(si, im.spec, im.spec.seed);
  });
  im.si->setup();
  im.pdef = std::make_shared<ob::ProblemDefinition>(im.si);
  im.pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(im.si));
  im.prm = std::make_shared<Roadmap>(im.si);
  im.prm->UseLinearNeighbours();
  im.prm->setProblemDefinition(im.pdef);
  im.prm->setup();
  for (const Point& p : s.anchors) {
    if (!DiscFree(s, p)) continue;
    ob::State* state = im.si->allocState();
    Put(state, p);
    im.prm->Add(state);
  }
  if (!s.cells.empty()) {
    // Grow to the milestone count; the attempt cap only guards against a floor where samples keep failing.
    long checks = 0;
    const long cap = 50L * std::max(1, s.milestones);
    im.prm->growRoadmap(ob::PlannerTerminationCondition([&] {
      return static_cast<long>(im.prm->milestoneCount()) >= s.milestones || ++checks > cap;
    }));
  }
  im.seconds = std::chrono::duration<double>(Clock::now() - t).count();
}

LevelRoadmap::~LevelRoadmap() = default;

bool LevelRoadmap::FreeAt(Point p) const { return DiscFree(impl_->spec, p); }
bool LevelRoadmap::FreeWalk(Point a, Point b) const { return WalkFree(impl_->spec, a, b); }
int LevelRoadmap::milestones() const { return static_cast<int>(impl_->prm->milestoneCount()); }
int LevelRoadmap::edges() const { return static_cast<int>(impl_->prm->edgeCount()); }
double LevelRoadmap::seconds_build() const { return impl_->seconds; }

std::optional<std::vector<Point>> LevelRoadmap::Path(Point a, Point b, std::string* planner) {
  Impl& im = *impl_;
  if (!DiscFree(im.spec, a) || !DiscFree(im.spec, b)) return std::nullopt;
  if (WalkFree(im.spec, a, b)) {
    *planner = "straight";
    return std::vector<Point>{a, b};
  }
  std::vector<Point> raw;
  ob::State* sa = im.si->allocState();
  ob::State* sb = im.si->allocState();
  Put(sa, a);
  Put(sb, b);
  const auto va = im.prm->Add(sa);  // the roadmap owns them now
  const auto vb = im.prm->Add(sb);
  if (im.prm->Joined(va, vb)) {
    if (auto path = std::dynamic_pointer_cast<og::PathGeometric>(im.prm->Route(va, vb))) {
      for (size_t k = 0; k < path->getStateCount(); ++k) raw.push_back(At(path->getState(k)));
      *planner = "prm";
    }
  }
  if (raw.empty() && im.spec.rrt_iterations > 0) {
    auto pdef = std::make_shared<ob::ProblemDefinition>(im.si);
    ob::ScopedState<ob::RealVectorStateSpace> start(im.space), goal(im.space);
    start[0] = a.x, start[1] = a.y, goal[0] = b.x, goal[1] = b.y;
    pdef->setStartAndGoalStates(start, goal);
    og::RRTConnect rrt(im.si);
    rrt.setProblemDefinition(pdef);
    rrt.setup();
    long iterations = 0;
    rrt.solve(ob::PlannerTerminationCondition([&] { return ++iterations > im.spec.rrt_iterations; }));
    if (pdef->hasExactSolution()) {
      if (auto path = std::dynamic_pointer_cast<og::PathGeometric>(pdef->getSolutionPath())) {
        for (size_t k = 0; k < path->getStateCount(); ++k) raw.push_back(At(path->getState(k)));
        *planner = "rrt_connect";
      }
    }
  }
  if (raw.empty()) return std::nullopt;
  raw.front() = a;
  raw.back() = b;
  return Shorten(im.spec, raw);
}

}  // namespace villa::solver
