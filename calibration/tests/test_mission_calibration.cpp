// Mission calibration's measuring tools on hand-made trajectories: the track alignment recovers a
// known shift, passages and leg times of a constant-speed track are exact, unmatched waypoints are
// NaN, never a guess.
#include <gtest/gtest.h>

#include <cmath>

#include "wattswath/calibration/mission_calibration.hpp"

using namespace wattswath::calibration;

namespace {

// A square flown at 5 m/s sampled at 10 Hz, 10 m up, shifted by `shift`.
void square(const Eigen::Vector2d& shift, std::vector<double>& t, std::vector<Eigen::Vector3d>& pos, std::vector<double>& power) {
  const std::vector<Eigen::Vector2d> corners = {{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}};
  double time = 0.0;
  for (std::size_t c = 1; c < corners.size(); ++c) {
    for (double s = 0.0; s < 100.0; s += 0.5) {
      const Eigen::Vector2d p = corners[c - 1] + (corners[c] - corners[c - 1]) * (s / 100.0) + shift;
      t.push_back(time);
      pos.emplace_back(p.x(), p.y(), 10.0);
      power.push_back(200.0);
      time += 0.1;
    }
  }
}

std::vector<Eigen::Vector3d> waypoints() { return {{100, 0, 10}, {100, 100, 10}, {0, 100, 10}, {0, 0, 10}}; }

}  // namespace

TEST(MissionCalibration, AlignmentRecoversAKnownShift) {
  std::vector<double> t, power;
  std::vector<Eigen::Vector3d> pos;
  square({7.3, -4.1}, t, pos, power);
  const Eigen::Vector2d d = alignTrack(pos, waypoints());
  EXPECT_NEAR(d.x(), 7.3, 0.11);
  EXPECT_NEAR(d.y(), -4.1, 0.11);
}

TEST(MissionCalibration, ConstantSpeedTrackGivesExactLegTimesAndEnergy) {
  std::vector<double> t, power;
  std::vector<Eigen::Vector3d> pos;
  square({0, 0}, t, pos, power);
  const FlightTimes ft = flightTimes(t, pos, power, waypoints());
  ASSERT_EQ(ft.leg_s.size(), 3u);
  for (double l : ft.leg_s) EXPECT_NEAR(l, 20.0, 0.11);
  for (double v : ft.leg_speed_mps) EXPECT_NEAR(v, 5.0, 0.05);
  for (double e : ft.leg_energy_j) EXPECT_NEAR(e, 200.0 * 20.0, 25.0);
  EXPECT_NEAR(ft.energy_j, 200.0 * t.back(), 1e-6);
}

TEST(MissionCalibration, WaypointTheTrackNeverComesNearIsNotMatched) {
  std::vector<double> t, power;
  std::vector<Eigen::Vector3d> pos;
  square({0, 0}, t, pos, power);
  auto w = waypoints();
  w.insert(w.begin() + 1, Eigen::Vector3d(300, 300, 10));
  const FlightTimes ft = flightTimes(t, pos, power, w);
  EXPECT_TRUE(std::isnan(ft.passage_s[1]));
  EXPECT_TRUE(std::isnan(ft.leg_s[0]));
  EXPECT_TRUE(std::isnan(ft.leg_s[1]));
  EXPECT_NEAR(ft.leg_s[2], 20.0, 0.11);  // the matched neighbours still give their leg
}
