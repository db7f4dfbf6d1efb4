// OMPL transits with the energy objective, checked against the visibility graph (TransitRouter).
#include <gtest/gtest.h>

#include "test_util.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/planner/energy_transit.hpp"
#include "wattswath/planner/transit.hpp"

using namespace wattswath;
using namespace wattswath::planner;
using geometry::Point;
using geometry::Ring;

namespace {

Ring square(double cx, double cy, double h) { return {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}}; }

// Transit energy of a polyline as the planner charges it here: stop-to-stop legs [J].
double stopToStop(RouteScorer& sc, const std::vector<Point>& p) {
  double e = 0;
  for (size_t i = 0; i + 1 < p.size(); ++i) e += sc.legEnergy((p[i + 1] - p[i]).norm(), 0, 0, sc.settings().max_speed);
  return e;
}

}  // namespace

TEST(EnergyTransit, AgreesWithTheVisibilityGraph) {
  const auto v = energy::loadVehicle(test::sourcePath("data/vehicles/iris.json"));
  const auto model = energy::marinsModel(v);
  RouteScorer sc(model, SpeedSettings::fromVehicle(v));
  const std::vector<Ring> obstacles{square(0, 0, 20), square(60, 30, 15)};
  const Point a(-80, 5), b(120, 20);
  EnergyTransitSettings s;
  s.iterations = 800;
  const auto t = planEnergyTransit(a, b, obstacles, sc, s);
  ASSERT_TRUE(t.solved);
  ASSERT_GE(t.path.size(), 3u);  // it must go around
  EXPECT_EQ(t.path.front(), a);
  EXPECT_EQ(t.path.back(), b);
  for (size_t i = 0; i + 1 < t.path.size(); ++i)
    for (const auto& o : obstacles) EXPECT_FALSE(segmentEntersRing(t.path[i], t.path[i + 1], o)) << i;
  // The bound is admissible, and the OMPL path costs about what the exact visibility-graph path
  // (2 m clearance, so slightly longer than touching the corners) costs.
  EXPECT_LE(t.heuristic_j, t.energy_j);
  const double vis = stopToStop(sc, TransitRouter(obstacles, TransitSettings{2.0}).route(a, b));
  EXPECT_GT(t.energy_j, 0.9 * vis);
  EXPECT_LT(t.energy_j, 1.15 * vis);
}

TEST(EnergyTransit, StraightWhenClearAndErrors) {
  const auto v = energy::loadVehicle(test::sourcePath("data/vehicles/iris.json"));
  RouteScorer sc(energy::marinsModel(v), SpeedSettings::fromVehicle(v));
  const std::vector<Ring> obstacles{square(0, 100, 10)};
  EnergyTransitSettings s;
  s.iterations = 300;
  const auto t = planEnergyTransit({0, 0}, {100, 0}, obstacles, sc, s);
  ASSERT_TRUE(t.solved);
  EXPECT_EQ(t.path.size(), 2u);
  EXPECT_NEAR(t.energy_j, sc.legEnergy(100, 0, 0, sc.settings().max_speed), 1e-9);
  EXPECT_THROW(planEnergyTransit({0, 100}, {100, 0}, obstacles, sc, s), std::invalid_argument);
  s.time_limit_s = 0;
  EXPECT_THROW(planEnergyTransit({0, 0}, {100, 0}, obstacles, sc, s), std::invalid_argument);
}
