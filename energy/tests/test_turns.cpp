// Turn strategies (Marins Eq. 12-16): sharp stop vs rounded turn, checked against the paper's
// equations written out by hand, and their behaviour over angles and leg lengths.
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.hpp"
#include "wattswath/energy/marins.hpp"
#include "wattswath/energy/turns.hpp"

using namespace wattswath::energy;

namespace {
Vehicle iris() { return loadVehicle(wattswath::test::sourcePath("data/vehicles/iris.json")); }
const ProfileLimits kUnit{1.0, 1.0};
constexpr double kDeg = M_PI / 180.0;
}  // namespace

TEST(Turns, Eq15ExtraLengthAndItsStraightLimit) {
  // Eq. 15 as printed: 2 R (1 + cos b) / sin b + R (pi + b).
  for (double b : {30.0, 45.0, 60.0, 90.0, 135.0}) {
    const double br = b * kDeg, R = 7.7;
    EXPECT_NEAR(roundedExtraLength(R, br), 2 * R * (1 + std::cos(br)) / std::sin(br) + R * (M_PI + br), 1e-9);
  }
  EXPECT_NEAR(roundedExtraLength(2.0, M_PI), 2.0 * 2.0 * M_PI, 1e-12);  // straight on: a full loop
}

TEST(Turns, SharpStopAndRoundedFollowEq12To16WithPaperDrag) {
  const auto v = iris();
  const auto model = marinsModel(v, DragIntegration::PaperCruiseSpeed);
  const auto m = MarinsClosedForm::fromVehicle(v, DragIntegration::PaperCruiseSpeed);
  const double d = 600.0, beta = 45.0 * kDeg, w = v.max_yaw_rate_radps;
  TurnSettings st;
  st.sharp_speed = m.eq10OptimalSpeed(d);
  st.rounded_speed = m.eq10OptimalSpeed(2 * d);
  const auto c = compareTurnStrategies(model, d, beta, kUnit, w, 100.0, st);
  // Eq. 12-14
  const double e_turn = (M_PI - beta) / w * m.p_hover;
  EXPECT_NEAR(c.sharp_stop.turn_energy, e_turn, 1e-9);
  EXPECT_NEAR(c.sharp_stop.energy, 2 * m.eq9Energy(d, *st.sharp_speed) + e_turn, 1e-6);
  // Eq. 15-16 (drag over eta, as Eq. 9, which Eq. 16 says it uses)
  const double v2 = *st.rounded_speed, R = v2 / w;
  const double L2 = 2 * d + 2 * R * (1 + std::cos(beta)) / std::sin(beta) + R * (M_PI + beta);
  EXPECT_NEAR(c.rounded.radius, R, 1e-12);
  EXPECT_NEAR(c.rounded.path_length, L2, 1e-9);
  EXPECT_NEAR(c.rounded.energy, L2 / v2 * m.p_hover + L2 * m.k_drag * v2 * v2, 1e-6);
  EXPECT_NEAR(c.saving_pct, 100 * (c.sharp_stop.energy - c.rounded.energy) / c.sharp_stop.energy, 1e-12);
  EXPECT_NEAR(c.rounded.breakdown.byEffect("kinetic"), 0.0, 1e-12);  // constant speed: no kinetic term
}

TEST(Turns, OptimisedSpeedsBeatGivenSpeeds) {
  const auto v = iris();
  const auto model = marinsModel(v);
  for (double b : {30.0, 90.0, 150.0}) {
    const auto best = compareTurnStrategies(model, 300.0, b * kDeg, kUnit, v.max_yaw_rate_radps, 40.0);
    for (double s : {8.0, 12.0, 20.0}) {
      TurnSettings st;
      st.sharp_speed = s;
      st.rounded_speed = s;
      const auto c = compareTurnStrategies(model, 300.0, b * kDeg, kUnit, v.max_yaw_rate_radps, 40.0, st);
      EXPECT_LE(best.sharp_stop.energy, c.sharp_stop.energy + 1e-6);
      EXPECT_LE(best.rounded.energy, c.rounded.energy + 1e-6);
    }
  }
}

TEST(Turns, SharperCornersCostTheSharpStopMoreAndRoundedFromRestIsFair) {
  const auto v = iris();
  const auto model = marinsModel(v);
  double prev_turn = 1e300;
  for (double b = 10.0; b <= 180.0; b += 10.0) {
    const auto c = compareTurnStrategies(model, 600.0, b * kDeg, kUnit, v.max_yaw_rate_radps, 16.0);
    EXPECT_LT(c.sharp_stop.turn_energy, prev_turn);  // (pi - beta) shrinks
    prev_turn = c.sharp_stop.turn_energy;
    TurnSettings st;
    st.rounded_from_rest = true;
    const auto r = compareTurnStrategies(model, 600.0, b * kDeg, kUnit, v.max_yaw_rate_radps, 16.0, st);
    EXPECT_GT(r.rounded.energy, c.rounded.energy);  // starting and ending at rest costs more
    EXPECT_LT(r.saving_pct, c.saving_pct);
  }
}

TEST(Turns, BadInputsAreRejectedNamingTheValue) {
  const auto v = iris();
  const auto model = marinsModel(v);
  auto expectThrow = [&](double d, double beta_deg, const char* needle) {
    try {
      compareTurnStrategies(model, d, beta_deg * kDeg, kUnit, v.max_yaw_rate_radps, 16.0);
      ADD_FAILURE() << "no exception for " << d << " m, " << beta_deg << " deg";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expectThrow(-5.0, 45.0, "leg length = -5");
  expectThrow(100.0, 0.0, "beta = 0");
  expectThrow(100.0, 200.0, "beta = 200");
  TurnSettings st;
  st.sharp_speed = 30.0;
  EXPECT_THROW(compareTurnStrategies(model, 100.0, 1.0, kUnit, 2.1, 16.0, st), std::invalid_argument);
}
