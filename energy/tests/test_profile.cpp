// Speed-profile builder: trapezoid, triangle, entry above cruise, zero distance, infeasible requests.
#include <gtest/gtest.h>

#include <cmath>

#include "wattswath/energy/profile.hpp"

using namespace wattswath::energy;

namespace {
const ProfileLimits kUnit{1.0, 1.0};

void expectContinuous(const std::vector<Piece>& ps) {
  for (size_t i = 1; i < ps.size(); ++i) EXPECT_NEAR(ps[i - 1].v_end, ps[i].v_start, 1e-12);
  for (const auto& p : ps) {
    EXPECT_LE(std::abs(p.acceleration()), 1.0 + 1e-9);
    EXPECT_NEAR(p.duration, 2.0 * p.length / (p.v_start + p.v_end), 1e-9);
  }
}
}  // namespace

TEST(LegProfile, StopToStopTrapezoidMatchesMarinsEq6) {
  const auto ps = buildLegProfile(100.0, 0.0, 8.0, 0.0, kUnit);
  ASSERT_EQ(ps.size(), 3u);
  EXPECT_EQ(ps[0].phase, Phase::Accelerate);
  EXPECT_EQ(ps[1].phase, Phase::Cruise);
  EXPECT_EQ(ps[2].phase, Phase::Brake);
  EXPECT_NEAR(ps[0].length, 32.0, 1e-12);  // v^2 / 2a
  EXPECT_NEAR(ps[2].length, 32.0, 1e-12);
  // Eq. 6 time: v/a + d/v - v^2/(a v) + v/a = d/v + v/a for v1 = v2 = v
  EXPECT_NEAR(totalTime(ps), 100.0 / 8.0 + 8.0, 1e-12);
  expectContinuous(ps);
}

TEST(LegProfile, ShortLegIsTriangular) {
  const auto ps = buildLegProfile(50.0, 0.0, 8.0, 0.0, kUnit);  // needs 64 m to reach 8 m/s
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_NEAR(ps[0].v_end, std::sqrt(50.0), 1e-12);
  EXPECT_NEAR(totalLength(ps), 50.0, 1e-12);
  expectContinuous(ps);
}

TEST(LegProfile, EntryAndExitSpeedsArbitrary) {
  const auto ps = buildLegProfile(100.0, 4.4, 8.0, 4.4, kUnit);
  ASSERT_EQ(ps.size(), 3u);
  EXPECT_NEAR(ps[0].length, (64.0 - 4.4 * 4.4) / 2.0, 1e-12);
  EXPECT_NEAR(totalLength(ps), 100.0, 1e-12);
  expectContinuous(ps);
}

TEST(LegProfile, EntrySpeedAboveCruiseBrakesFirst) {
  const auto ps = buildLegProfile(100.0, 10.0, 6.0, 0.0, kUnit);
  ASSERT_EQ(ps.size(), 3u);
  EXPECT_EQ(ps[0].phase, Phase::Brake);
  EXPECT_NEAR(ps[0].v_end, 6.0, 1e-12);
  expectContinuous(ps);
}

TEST(LegProfile, EntryAndExitAboveCruiseOnShortLegDipsBelowNeither) {
  const auto ps = buildLegProfile(10.0, 10.0, 6.0, 10.0, kUnit);
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_NEAR(ps[0].v_end * ps[0].v_end, 100.0 - 10.0, 1e-9);
  expectContinuous(ps);
}

TEST(LegProfile, ZeroDistance) {
  EXPECT_TRUE(buildLegProfile(0.0, 0.0, 8.0, 0.0, kUnit).empty());
  EXPECT_TRUE(buildLegProfile(0.0, 3.0, 8.0, 3.0, kUnit).empty());
  EXPECT_THROW(buildLegProfile(0.0, 0.0, 8.0, 3.0, kUnit), std::invalid_argument);
}

TEST(LegProfile, InfeasibleAndBadValuesThrowNamingThem) {
  try {
    buildLegProfile(10.0, 10.0, 10.0, 0.0, kUnit);  // needs 50 m to stop
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("distance 10"), std::string::npos) << e.what();
  }
  EXPECT_THROW(buildLegProfile(-1.0, 0.0, 8.0, 0.0, kUnit), std::invalid_argument);
  EXPECT_THROW(buildLegProfile(NAN, 0.0, 8.0, 0.0, kUnit), std::invalid_argument);
  EXPECT_THROW(buildLegProfile(10.0, 0.0, 0.0, 0.0, kUnit), std::invalid_argument);
}

TEST(LegProfile, StateAtFollowsPieceKinematics) {
  const auto ps = buildLegProfile(100.0, 0.0, 8.0, 0.0, kUnit, M_PI / 2);
  const MotionState s = stateAt(ps[0], 4.0);
  EXPECT_NEAR(s.velocity.y(), 4.0, 1e-12);  // north at 4 m/s after 4 s at 1 m/s^2
  EXPECT_NEAR(s.velocity.x(), 0.0, 1e-12);
  EXPECT_NEAR(s.acceleration.y(), 1.0, 1e-12);
}

TEST(TurnPieces, TurnInPlaceAndArc) {
  const Piece t = turnInPlace(M_PI * 0.75, 2.1);
  EXPECT_NEAR(t.duration, M_PI * 0.75 / 2.1, 1e-12);
  EXPECT_EQ(t.phase, Phase::Turn);
  const Piece a = arc(7.7, M_PI, 16.2);
  EXPECT_NEAR(a.length, 7.7 * M_PI, 1e-12);
  const MotionState s = stateAt(a, 0.1);
  EXPECT_NEAR(s.acceleration.norm(), 16.2 * 16.2 / 7.7, 1e-9);  // centripetal v^2/r
  EXPECT_NEAR(s.yaw_rate, 16.2 / 7.7, 1e-9);
}
