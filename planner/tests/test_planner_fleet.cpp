// A fleet flying the sorties at once (fleet.hpp): runs that balance the makespan, the separation
// check on the trajectories, and the delays that restore it.
#include <cmath>

#include <gtest/gtest.h>

#include "wattswath/planner/fleet.hpp"

namespace pl = wattswath::planner;
using wattswath::geometry::Point;

namespace {

// A straight flight from a to b over `duration` [s], sampled every 0.1 s, airborne throughout.
pl::Track line(Point a, Point b, double duration) {
  pl::Track t;
  const int n = static_cast<int>(duration / 0.1);
  for (int i = 0; i <= n; ++i) t.push_back({duration * i / n, a + (b - a) * (static_cast<double>(i) / n), true});
  return t;
}

// Least distance between the two tracks flown from starts s0, s1, sampled every 0.01 s.
double bruteForce(const pl::Track& p, const pl::Track& q, double s0, double s1) {
  auto at = [](const pl::Track& t, double tau) -> Point {
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
      if (tau <= t[i + 1].t) return t[i].p + (t[i + 1].p - t[i].p) * ((tau - t[i].t) / (t[i + 1].t - t[i].t));
    return t.back().p;
  };
  double least = 1e300;
  for (double t = std::max(s0, s1); t <= std::min(s0 + p.back().t, s1 + q.back().t); t += 0.01)
    least = std::min(least, (at(p, t - s0) - at(q, t - s1)).norm());
  return least;
}

}  // namespace

TEST(Fleet, RunsBalanceTheMakespan) {
  pl::FleetSettings s;
  s.vehicles = 2;
  s.swap_time_s = 0.0;
  s.launch_interval_s = 0.0;
  EXPECT_EQ(pl::fleetRuns({100, 100, 100, 100}, s), (std::vector<int>{0, 2}));
  EXPECT_EQ(pl::fleetRuns({300, 100, 100, 100}, s), (std::vector<int>{0, 1}));
  s.vehicles = 5;  // more vehicles than sorties: one sortie each
  EXPECT_EQ(pl::fleetRuns({100, 100, 100}, s), (std::vector<int>{0, 1, 2}));
  s.vehicles = 2;
  s.launch_interval_s = 1000.0;  // the second vehicle would take off after the first is done
  EXPECT_EQ(pl::fleetRuns({100, 100}, s), (std::vector<int>{0}));
  EXPECT_THROW(pl::fleetRuns({}, s), std::invalid_argument);
  s.vehicles = 0;
  EXPECT_THROW(pl::fleetRuns({100}, s), std::invalid_argument);
}

// Two sorties crossing at (50, 0) at t = 50 s when both start together: the check finds it (the
// closest approach is 0), and the schedule delays the later one until 15 m are kept, which a
// brute-force scan at 0.01 s confirms.
TEST(Fleet, CrossingSortiesAreDelayedUntilTheSeparationHolds) {
  const std::vector<pl::Track> tracks = {line({0, 0}, {100, 0}, 100.0), line({50, -50}, {50, 50}, 100.0)};
  int conflict = -2;
  EXPECT_LT(pl::minSeparation(tracks, {0, 1}, {0.0, 0.0}, 0.2, 15.0), 1e-9);
  EXPECT_LT(pl::minSeparation(tracks, {0, 1}, {0.0, 0.0}, 0.2, 15.0, &conflict), 15.0);
  EXPECT_EQ(conflict, 1);
  EXPECT_LT(bruteForce(tracks[0], tracks[1], 0.0, 0.0), 0.5);

  pl::FleetSettings s;
  s.vehicles = 2;
  s.launch_interval_s = 0.0;
  s.separation_m = 15.0;
  const auto f = pl::scheduleFleet(tracks, s);
  ASSERT_EQ(f.sorties.size(), 2u);
  EXPECT_EQ(f.sorties[0].vehicle, 0);
  EXPECT_EQ(f.sorties[1].vehicle, 1);
  EXPECT_GT(f.delays, 0);
  EXPECT_GT(f.sorties[1].delay_s, 0.0);
  EXPECT_GE(f.min_separation_m, 15.0);
  EXPECT_GE(bruteForce(tracks[0], tracks[1], f.sorties[0].start_s, f.sorties[1].start_s), 15.0 - 1e-6);
  // Delayed by just enough: one step less and they come closer (within 5 s steps at 1 m/s).
  EXPECT_LT(bruteForce(tracks[0], tracks[1], f.sorties[0].start_s, f.sorties[1].start_s - s.delay_step_s), 15.0);
  EXPECT_DOUBLE_EQ(f.makespan_s, f.sorties[1].end_s);
}

// One vehicle flies its sorties one after the other with the swap between them: no separation
// to keep with itself, makespan = flights + swaps.
TEST(Fleet, OneVehicleFliesInTurnWithSwaps) {
  const std::vector<pl::Track> tracks = {line({0, 0}, {100, 0}, 100.0), line({0, 0}, {100, 0}, 50.0)};
  pl::FleetSettings s;
  s.vehicles = 1;
  s.swap_time_s = 120.0;
  const auto f = pl::scheduleFleet(tracks, s);
  EXPECT_DOUBLE_EQ(f.sorties[1].start_s, 220.0);
  EXPECT_DOUBLE_EQ(f.makespan_s, 270.0);
  EXPECT_TRUE(std::isinf(f.min_separation_m));
  EXPECT_EQ(f.delays, 0);
}
