// profileFromPath: speed profiles over whole geometric paths (lines, arcs, turns in place).
#include <gtest/gtest.h>

#include <cmath>

#include "wattswath/energy/path_profile.hpp"
#include "wattswath/geometry/route.hpp"

namespace en = wattswath::energy;
namespace g = wattswath::geometry;

namespace {

g::CoveragePath square(g::CornerStyle style) {
  g::Route r;
  r.points = {{0, 0}, {100, 0}, {100, 100}};
  r.roles = {g::LegRole::Sweep, g::LegRole::Sweep};
  g::CornerSettings c;
  c.style = style;
  c.radius = 2.0;
  return g::shapeCorners(r, c);
}

}  // namespace

TEST(ProfileFromPath, RoundedCornerFliesTheArcAtCornerSpeed) {
  const auto path = square(g::CornerStyle::Rounded);
  ASSERT_EQ(path.legs.size(), 3u);
  en::SpeedPlan plan;
  plan.cruise = {8.0, 4.0, 8.0};
  plan.junction = {0.0, 4.0, 4.0, 0.0};
  const auto pieces = en::profileFromPath(path, plan, {}, 2.1);
  EXPECT_NEAR(en::totalLength(pieces), path.length(), 1e-9);
  int turns = 0;
  for (const auto& p : pieces) {
    if (p.phase != en::Phase::Turn) continue;
    ++turns;
    EXPECT_NEAR(p.length, M_PI, 1e-9);  // 2 m * pi/2
    EXPECT_NEAR(p.v_start, 4.0, 1e-12);
    EXPECT_NEAR(p.yaw_angle, M_PI / 2, 1e-12);
  }
  EXPECT_EQ(turns, 1);
  // 98 m legs: 0 -> 8 (32 m), cruise, 8 -> 4 (24 m); time of line 1 = 8 + 42/8 + 6.
  EXPECT_NEAR(pieces.front().duration, 8.0, 1e-9);
}

TEST(ProfileFromPath, SharpCornerTurnsInPlaceAtRest) {
  const auto path = square(g::CornerStyle::Sharp);
  ASSERT_EQ(path.legs.size(), 3u);
  en::SpeedPlan plan{{5.0, 0.0, 5.0}, {0.0, 0.0, 0.0, 0.0}};
  const auto pieces = en::profileFromPath(path, plan, {}, M_PI / 4);
  double turn_time = 0.0;
  for (const auto& p : pieces)
    if (p.phase == en::Phase::Turn) turn_time += p.duration;
  EXPECT_NEAR(turn_time, 2.0, 1e-12);
  plan.junction[1] = 1.0;  // cannot enter a turn in place moving
  EXPECT_THROW(en::profileFromPath(path, plan, {}, 1.0), std::invalid_argument);
}

TEST(ProfileFromPath, RejectsMismatchedPlans) {
  const auto path = square(g::CornerStyle::Rounded);
  en::SpeedPlan plan{{8.0, 4.0}, {0.0, 4.0, 4.0, 0.0}};
  EXPECT_THROW(en::profileFromPath(path, plan, {}, 2.1), std::invalid_argument);
  plan.cruise = {8.0, 5.0, 8.0};  // arc cruise differs from its junction speeds
  EXPECT_THROW(en::profileFromPath(path, plan, {}, 2.1), std::invalid_argument);
  plan.cruise = {8.0, 4.0, 8.0};
  plan.junction = {0.0, 4.0, 4.0, 30.0};  // 30 m/s exit needs 442 m, the leg has 98 m
  try {
    en::profileFromPath(path, plan, {}, 2.1);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("leg 2"), std::string::npos) << e.what();
  }
}
