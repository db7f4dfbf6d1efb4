// A plan split into sorties that each fly (sorties.hpp, splitIntoFlownSorties): the planner asks
// a check which runs of sweep pieces fly and takes the fewest of them, never one the check refused.
#include <gtest/gtest.h>

#include <mutex>
#include <set>
#include <stdexcept>
#include <utility>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/sorties.hpp"
#include "mission_fixtures.hpp"
#include "test_util.hpp"

using namespace wattswath;
using namespace wattswath::planner;

namespace {

struct Fixture {
  geometry::SurveyArea area = geometry::readSurveyArea(test::sourcePath("data/areas/iris_area.geojson"));
  SurveyProblem problem = test::problemOf(area, 15.0);
  energy::Vehicle vehicle = energy::loadVehicle(test::sourcePath("data/vehicles/iris.json"));
  energy::EnergyModel model = energy::marinsModel(vehicle);
  PlanResult result = planCoverage(problem, vehicle, model);
};

}  // namespace

TEST(FlownSorties, TheFewestRunsTheCheckAcceptsTileThePlan) {
  Fixture f;
  ASSERT_TRUE(f.result.plan.valid);
  RouteScorer scorer(f.model, SpeedSettings::fromVehicle(f.vehicle));
  SortieSettings s;
  s.budget_j = 1e9;  // the closed form allows anything: only the check decides
  s.overhead_j = 0.0;
  // The check: at most 4 pieces in a sortie. The fewest sorties is then ceil(pieces / 4).
  std::set<std::pair<int, int>> asked;
  std::mutex asking;  // the check is called from two threads
  const SortieCheck atMostFour = [&](const Sortie& so) {
    const std::lock_guard<std::mutex> lock(asking);
    asked.insert({so.first_sweep, so.last_sweep});
    return so.last_sweep - so.first_sweep < 4;
  };
  const SortieSplit split = splitIntoFlownSorties(f.result.plan.flown, f.problem, scorer, s, atMostFour);
  const int pieces = split.sorties.back().last_sweep + 1;
  ASSERT_GE(pieces, 9);
  EXPECT_EQ(static_cast<int>(split.sorties.size()), (pieces + 3) / 4);
  int next = 0;
  for (const auto& so : split.sorties) {
    EXPECT_EQ(so.first_sweep, next);
    EXPECT_LT(so.last_sweep - so.first_sweep, 4) << "a run the check refused was taken";
    next = so.last_sweep + 1;
  }
  EXPECT_EQ(next, pieces);
  // Each first piece costs a bisection's few flights, not every run: with a budget that says
  // nothing, about log2(pieces) + 1 each (6 allowed), far from the pieces x (pieces + 1) / 2 runs.
  EXPECT_LE(static_cast<int>(asked.size()), 6 * pieces);
  EXPECT_LT(6 * pieces, pieces * (pieces + 1) / 2);
  // A given count within reach is kept; one below the fewest is an error.
  s.count = (pieces + 3) / 4 + 1;
  EXPECT_EQ(static_cast<int>(splitIntoFlownSorties(f.result.plan.flown, f.problem, scorer, s, atMostFour).sorties.size()), s.count);
  s.count = (pieces + 3) / 4 - 1;
  EXPECT_THROW(splitIntoFlownSorties(f.result.plan.flown, f.problem, scorer, s, atMostFour), std::runtime_error);
  // A piece that does not fly alone is named.
  s.count = 0;
  const SortieCheck notThird = [](const Sortie& so) { return so.first_sweep > 2 || so.last_sweep < 2; };
  try {
    splitIntoFlownSorties(f.result.plan.flown, f.problem, scorer, s, notThird);
    FAIL() << "a piece that never flies was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("sweep piece 3 alone"), std::string::npos) << e.what();
  }
}
