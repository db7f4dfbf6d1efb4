// Issue 22: every flown point inside the survey area and clear of holes and no-fly zones, on
// fields of several shapes, and the line count chosen by energy under the coverage constraint.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "test_util.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/planner/coverage.hpp"

using namespace wattswath;
using namespace wattswath::planner;
using geometry::Ring;

namespace {

struct Field {
  std::string name;
  Ring outer;
  std::vector<Ring> holes;  // clockwise
  std::vector<Ring> no_fly;
};

// The fields of the comparison (10 m spacing): a 200 x 100 m rectangle, an L, a concave
// bay, one and two holes, a triangle, and a no-fly zone given as a zone instead of a hole.
std::vector<Field> fields() {
  return {
      {"rectangle", {{0, 0}, {200, 0}, {200, 100}, {0, 100}}, {}, {}},
      {"L-shape", {{0, 0}, {200, 0}, {200, 60}, {80, 60}, {80, 160}, {0, 160}}, {}, {}},
      {"concave", {{0, 0}, {300, 0}, {300, 200}, {200, 200}, {150, 60}, {100, 200}, {0, 200}}, {}, {}},
      {"one hole", {{0, 0}, {300, 0}, {300, 200}, {0, 200}}, {{{120, 70}, {120, 130}, {180, 130}, {180, 70}}}, {}},
      {"two holes",
       {{0, 0}, {400, 0}, {400, 300}, {0, 300}},
       {{{80, 80}, {80, 150}, {150, 150}, {150, 80}}, {{250, 150}, {250, 230}, {320, 230}, {320, 150}}},
       {}},
      {"triangle", {{0, 0}, {300, 40}, {120, 260}}, {}, {}},
      {"no-fly zone", {{0, 0}, {300, 0}, {300, 200}, {0, 200}}, {}, {{{100, 60}, {200, 60}, {200, 140}, {100, 140}}}},
  };
}

SurveyProblem problemOf(const Field& f) {
  SurveyProblem p;
  p.area.outer = f.outer;
  p.area.holes = f.holes;
  p.no_fly = f.no_fly;
  p.spacing = p.footprint = 10.0;
  p.home = f.outer.front();
  return p;
}

PlanResult planSharp(const SurveyProblem& p, double overshoot = 0.0) {
  const auto v = energy::loadVehicle(test::sourcePath("data/vehicles/iris.json"));
  PlannerSettings ps;
  ps.corners = CornerStrategy::Sharp;
  ps.overshoot = overshoot;
  return planCoverage(p, v, energy::marinsModel(v), ps);
}

}  // namespace

TEST(PlannerInside, NoFlownPointOutsideTheAreaOrInAHoleOnEveryField) {
  for (const auto& f : fields()) {
    SCOPED_TRACE(f.name);
    const auto pr = problemOf(f);
    const auto r = planSharp(pr);
    ASSERT_TRUE(r.plan.valid);
    EXPECT_GE(r.plan.coverage_pct, 99.0);
    const auto inside = planContainment(pr, r.plan.flown.path);
    EXPECT_LE(inside.outside_m, 0.0) << "up to " << inside.max_depth_m << " m outside";
    EXPECT_LE(inside.in_holes_m, 0.0) << "up to " << inside.max_depth_m << " m inside a hole";
  }
}

TEST(PlannerInside, OvershootIsOnlyFlownWhenAskedFor) {
  const auto pr = problemOf(fields().front());
  const auto inside = planContainment(pr, planSharp(pr, 5.0).plan.flown.path);
  EXPECT_GT(inside.outside_m, 10.0);  // every line's two ends run on by up to 5 m
  EXPECT_LE(inside.max_depth_m, 5.0 + 1e-6);
}

TEST(PlannerInside, RectangleIsCheaperThanThePeersAtTheSameCoverage) {
  // Issue 22's figures for 200 x 100 m at 10 m, scored by our model: Fields2Cover 89.2 kJ at 99.0 %,
  // EnergyAwareMCPP 97.7 kJ at 99.5 %; our sharp plan was 103.1 kJ (11 lines of 210 m).
  const auto r = planSharp(problemOf(fields().front()));
  EXPECT_GE(r.plan.coverage_pct, 99.0);
  EXPECT_LE(r.plan.flown.energy, 89.2e3);
}

TEST(PlannerInside, TheLineCountTradeIsReported) {
  // 100.5 m across: 11 lines cover it all, 10 lines 99.5 %. The plan drops the line and reports the
  // neighbour it gave up (one line more: more coverage, more energy).
  Field f{"rectangle", {{0, 0}, {200, 0}, {200, 100.5}, {0, 100.5}}, {}, {}};
  const auto r = planSharp(problemOf(f));
  ASSERT_TRUE(r.line_count_neighbour);
  EXPECT_EQ(r.line_count_neighbour->lines_delta, 1);
  EXPECT_GT(r.line_count_neighbour->candidate.coverage_pct, r.plan.coverage_pct);
  EXPECT_GT(r.line_count_neighbour->candidate.flown.energy, r.plan.flown.energy);
  EXPECT_GE(r.plan.coverage_pct, 99.0);
}
