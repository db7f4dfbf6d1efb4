#include "wattswath/planner/energy_transit.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/Time.h>
#include <ompl/util/RandomNumbers.h>

#include "wattswath/geometry/check.hpp"
#include "wattswath/planner/transit.hpp"

namespace wattswath::planner {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::Point;

Point pointOf(const ob::State* s) {
  const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
  return {v->values[0], v->values[1]};
}

// Motion cost: energy of the straight motion from a stop to a stop [J]; heuristic: lowest energy
// per metre times the distance [J] (admissible).
class EnergyObjective : public ob::OptimizationObjective {
 public:
  EnergyObjective(const ob::SpaceInformationPtr& si, RouteScorer& scorer, double per_metre)
      : ob::OptimizationObjective(si), scorer_(scorer), per_metre_(per_metre) {
    description_ = "leg energy";
  }
  ob::Cost stateCost(const ob::State*) const override { return identityCost(); }
  ob::Cost motionCost(const ob::State* s1, const ob::State* s2) const override {
    const double L = (pointOf(s2) - pointOf(s1)).norm();
    return ob::Cost(L <= 0.0 ? 0.0 : scorer_.legEnergy(L, 0.0, 0.0, scorer_.settings().max_speed));
  }
  ob::Cost motionCostHeuristic(const ob::State* s1, const ob::State* s2) const override {
    return ob::Cost(per_metre_ * (pointOf(s2) - pointOf(s1)).norm());
  }

 private:
  RouteScorer& scorer_;
  double per_metre_;
};

}  // namespace

void EnergyTransitSettings::validate() const {
  auto bad = [](const std::string& f, double v, const std::string& range) {
    throw std::invalid_argument("EnergyTransitSettings." + f + " = " + std::to_string(v) + " is outside " + range);
  };
  if (!(time_limit_s > 0.0 && time_limit_s <= 60.0)) bad("time_limit_s", time_limit_s, "(0, 60]");
  if (!(margin_m > 0.0 && margin_m <= 1e4)) bad("margin_m", margin_m, "(0, 1e4]");
  if (iterations < 1 || iterations > 10000000) bad("iterations", iterations, "[1, 1e7]");
  if (!(range_m >= 0.0 && std::isfinite(range_m))) bad("range_m", range_m, "[0, inf)");
}

EnergyTransit planEnergyTransit(const Point& a, const Point& b, const std::vector<geometry::Ring>& obstacles,
                                RouteScorer& scorer, const EnergyTransitSettings& s) {
  s.validate();
  for (const auto& r : obstacles) {
    if (geometry::insideRing(r, a)) throw std::invalid_argument("energy transit: the start point is inside a no-fly zone");
    if (geometry::insideRing(r, b)) throw std::invalid_argument("energy transit: the goal point is inside a no-fly zone");
  }
  static const bool seeded = [&s]() {
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);  // library code never prints (set before any OMPL call)
    ompl::RNG::setSeed(s.seed);
    return true;
  }();
  (void)seeded;
  Point lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  for (const auto& r : obstacles)
    for (const auto& p : r) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  for (int d = 0; d < 2; ++d) {
    bounds.setLow(d, lo[d] - s.margin_m);
    bounds.setHigh(d, hi[d] + s.margin_m);
  }
  space->setBounds(bounds);
  og::SimpleSetup ss(space);
  auto si = ss.getSpaceInformation();
  ss.setStateValidityChecker([&obstacles](const ob::State* st) {
    const Point p = pointOf(st);
    return std::none_of(obstacles.begin(), obstacles.end(), [&](const geometry::Ring& r) { return geometry::insideRing(r, p); });
  });
  // Motions are checked exactly against the polygons, not by sampling.
  class SegmentValidator : public ob::MotionValidator {
   public:
    SegmentValidator(const ob::SpaceInformationPtr& si, const std::vector<geometry::Ring>& obs)
        : ob::MotionValidator(si), obs_(obs) {}
    bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
      const Point p = pointOf(s1), q = pointOf(s2);
      return std::none_of(obs_.begin(), obs_.end(), [&](const geometry::Ring& r) { return segmentEntersRing(p, q, r); });
    }
    bool checkMotion(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>& last) const override {
      const bool ok = checkMotion(s1, s2);
      if (!ok) {
        si_->copyState(last.first, s1);
        last.second = 0.0;
      }
      return ok;
    }

   private:
    const std::vector<geometry::Ring>& obs_;
  };
  si->setMotionValidator(std::make_shared<SegmentValidator>(si, obstacles));
  const double per_metre = scorer.model().minEnergyPerMetre(scorer.settings().max_speed);
  ss.setOptimizationObjective(std::make_shared<EnergyObjective>(si, scorer, per_metre));
  ob::ScopedState<> start(space), goal(space);
  start[0] = a.x();
  start[1] = a.y();
  goal[0] = b.x();
  goal[1] = b.y();
  ss.setStartAndGoalStates(start, goal);
  auto planner = std::make_shared<og::RRTstar>(si);
  if (s.range_m > 0.0) planner->setRange(s.range_m);
  ss.setPlanner(planner);
  EnergyTransit out;
  out.heuristic_j = per_metre * (b - a).norm();
  // Stop after `iterations` checks of the condition (deterministic for a seed) or at the time limit.
  int checks = 0;
  const auto deadline = ompl::time::now() + ompl::time::seconds(s.time_limit_s);
  const ob::PlannerTerminationCondition ptc([&checks, &s, deadline]() {
    return ++checks > s.iterations || ompl::time::now() > deadline;
  });
  const auto status = ss.solve(ptc);
  if (status != ob::PlannerStatus::EXACT_SOLUTION) return out;
  ss.simplifySolution();
  const auto& path = ss.getSolutionPath();
  for (size_t i = 0; i < path.getStateCount(); ++i) out.path.push_back(pointOf(path.getState(i)));
  for (size_t i = 0; i + 1 < out.path.size(); ++i) {
    const double L = (out.path[i + 1] - out.path[i]).norm();
    if (L > 0.0) out.energy_j += scorer.legEnergy(L, 0.0, 0.0, scorer.settings().max_speed);
  }
  out.solved = true;
  return out;
}

}  // namespace wattswath::planner
