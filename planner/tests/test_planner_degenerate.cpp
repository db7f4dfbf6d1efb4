// Degenerate geometry the planner must survive (issue 8): areas narrower than one swath, offsets
// that split or vanish, cells too thin for a sweep line, duplicate and collinear vertices still
// give a valid plan (finite energy, coverage, no no-fly entry); a home inside a no-fly zone, a
// no-fly zone over the whole area, a bow-tie and a 2-point ring give a clear error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "test_util.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/planner/coverage.hpp"

using namespace wattswath;
using namespace wattswath::planner;
using geometry::Point;
using geometry::Ring;

namespace {

energy::Vehicle iris() { return energy::loadVehicle(test::sourcePath("data/vehicles/iris.json")); }

/// Coarse angle search: these tests are about survival, not optimality.
PlannerSettings quick() {
  PlannerSettings s;
  s.coarse_step_deg = 30.0;
  s.fine_step_deg = 10.0;
  s.threads = 1;
  return s;
}

SurveyProblem problem(const Ring& outer, double spacing = 20.0) {
  SurveyProblem p;
  p.area.outer = outer;
  p.spacing = spacing;
  p.footprint = spacing / 0.9;
  p.home = {-5, -5};
  return p;
}

PlanResult plan(const SurveyProblem& p) {
  const auto v = iris();
  return planCoverage(p, v, energy::marinsModel(v), quick());
}

void expectPlanned(const SurveyProblem& p, double min_coverage_pct = 95.0) {
  PlanResult r;
  ASSERT_NO_THROW(r = plan(p));
  ASSERT_TRUE(r.plan.valid);
  EXPECT_TRUE(std::isfinite(r.plan.flown.energy) && r.plan.flown.energy > 0.0) << r.plan.flown.energy;
  EXPECT_GE(r.plan.coverage_pct, min_coverage_pct);
  const auto problems = checkPlan(p, r.plan.flown.path);
  EXPECT_TRUE(problems.empty()) << problems.front();
}

/// The planner's error message when it rejects `p`; empty when it planned.
std::string errorOf(const SurveyProblem& p) {
  try {
    plan(p);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PlannerDegenerate, AreaNarrowerThanOneSwathIsPlanned) {
  expectPlanned(problem({{0, 0}, {200, 0}, {200, 5}, {0, 5}}));
}

TEST(PlannerDegenerate, AreaSmallerThanOneSwathBothWaysIsPlanned) {
  expectPlanned(problem({{0, 0}, {6, 0}, {6, 4}, {0, 4}}));
}

TEST(PlannerDegenerate, DuplicateAndCollinearVerticesArePlanned) {
  expectPlanned(problem({{0, 0}, {50, 0}, {50, 0}, {100, 0}, {100, 60}, {100, 60}, {50, 60}, {0, 60}, {0, 30}}));
}

TEST(PlannerDegenerate, ThinCorridorWhereOffsetsSplitIsPlanned) {
  // Two 60 m squares joined by a 3 m corridor: the inward offset by the clearance splits it.
  expectPlanned(problem({{0, 0}, {60, 0}, {60, 28}, {100, 28}, {100, 0}, {160, 0}, {160, 60}, {100, 60},
                         {100, 31}, {60, 31}, {60, 60}, {0, 60}}),
                90.0);
}

TEST(PlannerDegenerate, HoleLeavingSliversWithoutSweepLinesIsPlanned) {
  SurveyProblem p = problem({{0, 0}, {100, 0}, {100, 100}, {0, 100}});
  p.area.holes = {{{1, 40}, {1, 60}, {99, 60}, {99, 40}}};  // 1 m slivers left and right
  expectPlanned(p, 90.0);
}

TEST(PlannerDegenerate, HomeInsideANoFlyZoneIsAnError) {
  SurveyProblem p = problem({{0, 0}, {100, 0}, {100, 100}, {0, 100}});
  p.no_fly = {{{-20, -20}, {-1, -20}, {-1, -1}, {-20, -1}}};
  const std::string m = errorOf(p);
  EXPECT_NE(m.find("home"), std::string::npos) << "'" << m << "'";
}

TEST(PlannerDegenerate, NoFlyZoneOverTheWholeAreaIsAnError) {
  SurveyProblem p = problem({{0, 0}, {100, 0}, {100, 100}, {0, 100}});
  p.no_fly = {{{-1, -1}, {101, -1}, {101, 101}, {-1, 101}}};
  p.home = {-20, -20};
  const std::string m = errorOf(p);
  EXPECT_NE(m.find("no_fly[0] covers the whole area"), std::string::npos) << "'" << m << "'";
}

TEST(PlannerDegenerate, BowTieIsAnError) {
  const std::string m = errorOf(problem({{0, 0}, {100, 100}, {100, 0}, {0, 100}}));
  EXPECT_NE(m.find("area"), std::string::npos) << "'" << m << "'";
}

TEST(PlannerDegenerate, TwoPointRingIsAnError) {
  const std::string m = errorOf(problem({{0, 0}, {100, 0}}));
  EXPECT_NE(m.find("at least 3"), std::string::npos) << "'" << m << "'";
}
