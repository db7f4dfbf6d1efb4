// Reproduction of Marins, Cabreira & Ferreira (2018): every test states the paper's number, ours and
// the tolerance. Where the paper does not follow from its own equations, the test pins our value and
// checks the explanation given in docs/reproduction.md (apps/marins_paper.hpp holds the paper's numbers).
#include <gtest/gtest.h>

#include <cmath>

#include "../apps/marins_paper.hpp"
#include "test_util.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/turns.hpp"

using namespace wattswath::energy;
namespace mp = wattswath::apps::marins;

namespace {
Vehicle iris() { return loadVehicle(wattswath::test::sourcePath("data/vehicles/iris.json")); }
MarinsClosedForm paperForm() { return MarinsClosedForm::fromVehicle(iris(), DragIntegration::PaperCruiseSpeed); }
double rel(double ours, double paper) { return std::abs(ours - paper) / std::abs(paper); }
}  // namespace

TEST(Marins, Eq4_P0_125_6W) {
  const double ours = marinsRotorPowerW(iris());  // 125.82 W with g = 9.81
  EXPECT_LT(rel(ours, mp::kP0), 0.002) << "paper 125.6 W, ours " << ours << " W, tolerance 0.2 %";
  Vehicle g98 = iris();
  g98.gravity_mps2 = 9.80;  // what the paper must have used
  EXPECT_NEAR(marinsRotorPowerW(g98), mp::kP0, 0.05);
}

TEST(Marins, Eq5_PHover_214_7W) {
  const double ours = marinsHoverPowerW(iris());  // 215.07 W
  EXPECT_LT(rel(ours, mp::kPHover), 0.002) << "paper 214.7 W, ours " << ours << " W, tolerance 0.2 %";
}

TEST(Marins, Eq4_IsExactlyTwiceIdealMomentumTheory) {
  EXPECT_NEAR(marinsRotorPowerW(iris()) / idealHoverPowerW(iris()), 2.0, 1e-12);
}

TEST(Marins, Fig3_OptimalVelocity600m) {
  const double ours = paperForm().eq10OptimalSpeed(600.0);  // 14.845 m/s
  EXPECT_NEAR(ours, mp::kVopt600, 0.06) << "paper 14.9 m/s, ours " << ours << ", tolerance 0.06 m/s (rounding)";
}

TEST(Marins, Fig3_OptimalVelocity1200m) {
  // Paper 16.2 m/s; Eq. 10 with the stated parameters gives 16.39 m/s (documented +1.2 %; 16.2 is the
  // root at ~1,080 m). Tolerance 1.5 % and a pin on our value.
  const double ours = paperForm().eq10OptimalSpeed(1200.0);
  EXPECT_LT(rel(ours, mp::kVopt1200), 0.015) << "paper 16.2, ours " << ours;
  EXPECT_NEAR(ours, 16.3927, 1e-3);
}

TEST(Marins, Fig3_VariantsAndLongLegLimit) {
  const auto m = paperForm();
  // Without kinetic: a few per cent higher; without drag: far higher and unbounded (Fig. 3's message).
  EXPECT_NEAR(m.eq10OptimalSpeed(600.0, {false, true}) / m.eq10OptimalSpeed(600.0), 1.047, 0.005);
  EXPECT_GT(m.eq10OptimalSpeed(600.0, {true, false}) / m.eq10OptimalSpeed(600.0), 1.35);
  EXPECT_NEAR(m.eq10OptimalSpeed(1e7), m.longLegOptimalSpeed(), 0.01);
  EXPECT_NEAR(m.longLegOptimalSpeed(), 18.46, 0.01);
}

TEST(Marins, Strategy1_600m_beta45) {
  const auto s = mp::strategies(paperForm(), 2.1, 600.0, 45.0, {false, marinsHoverPowerW(iris()), marinsHoverPowerW(iris())});
  // Paper 30,351 J = 15,043 + 265 + 15,043; ours 29,512 J (-2.8 %: leg unexplained, turn at 236 W).
  EXPECT_LT(rel(s.total1, mp::kTotal1), 0.03) << "paper 30,351 J, ours " << s.total1 << ", tolerance 3 %";
  EXPECT_LT(rel(s.leg, mp::kLeg600), 0.03) << "paper 15,043 J, ours " << s.leg << ", tolerance 3 %";
  EXPECT_NEAR(s.turn, 241.3, 0.1);  // paper 265 J
  // The paper's 265 J is (pi - 45 deg) / 2.1 rad/s at 1.10 x P_hov.
  EXPECT_NEAR(mp::impliedTurnPower(2.1) / mp::kPHover, 1.100, 0.001);
}

TEST(Marins, Strategy2_600m_beta45) {
  const auto s = mp::strategies(paperForm(), 2.1, 600.0, 45.0, {false, marinsHoverPowerW(iris()), marinsHoverPowerW(iris())});
  // Paper 25,087 J = 18,337 + 6,750; ours 22,467 J (-10.4 %, explained in part, see reproduction.md).
  EXPECT_LT(rel(s.total2, mp::kTotal2), 0.11) << "paper 25,087 J, ours " << s.total2 << ", tolerance 11 %";
  EXPECT_NEAR(s.total2, 22467.0, 2.0);
  EXPECT_LT(rel(s.radius, mp::kRadius), 0.015) << "paper R = 7.7 m, ours " << s.radius;
  EXPECT_LT(rel(s.l2, mp::kL2), 0.01) << "paper L2 = 1,258 m, ours " << s.l2;
  // The paper's hover term is 1,258 m / 16.2 m/s at the same 1.10 x P_hov as its turn.
  EXPECT_NEAR(mp::impliedRoundedHoverPower() / mp::impliedTurnPower(2.1), 1.0, 0.001);
}

TEST(Marins, Strategy2_L2_1258m_NeedsCosSinOfBetaInRadians) {
  const double R = mp::kVopt1200 / 2.1;  // the paper's R with its 16.2 m/s
  const double correct = 1200.0 + roundedExtraLength(R, M_PI / 4.0);
  const double as_radians = 1200.0 + 2.0 * R * (1.0 + std::cos(45.0)) / std::sin(45.0) + R * (M_PI + M_PI / 4.0);
  EXPECT_NEAR(as_radians, mp::kL2, 0.5) << "paper 1,258 m, with cos/sin(45 rad) " << as_radians;
  EXPECT_GT(correct - mp::kL2, 9.0) << "Eq. 15 done right gives " << correct;
}

TEST(Marins, Table5_PaperProcedureInferredWithin2Points) {
  const auto m = paperForm();
  const double p = mp::impliedTurnPower(2.1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      const double ours = mp::strategies(m, 2.1, mp::kTable5Distance[i], mp::kTable5Angle[j], {true, p, p}).saving;
      EXPECT_NEAR(ours, mp::kTable5[i][j], 2.0) << "Table V " << mp::kTable5Distance[i] << " m, "
                                                << mp::kTable5Angle[j] << " deg: paper " << mp::kTable5[i][j]
                                                << " %, inferred procedure " << ours << " %, tolerance 2 points";
    }
}

TEST(Marins, Table5_PaperEquationsGrowWithBetaUnlikeThePrintedTable) {
  const auto m = paperForm();
  const double ph = marinsHoverPowerW(iris());
  for (int i = 0; i < 3; ++i) {
    double prev = -1e9;
    for (int j = 0; j < 4; ++j) {
      const double ours = mp::strategies(m, 2.1, mp::kTable5Distance[i], mp::kTable5Angle[j], {false, ph, ph}).saving;
      EXPECT_GT(ours, prev);
      EXPECT_NEAR(ours, mp::kTable5[i][j], 7.0) << "paper " << mp::kTable5[i][j] << " %, ours " << ours
                                                << " %, tolerance 7 points (documented)";
      prev = ours;
    }
  }
  // 600 m, 45 deg pinned: paper 17.3 %, ours 23.87 %.
  EXPECT_NEAR(mp::strategies(m, 2.1, 600.0, 45.0, {false, ph, ph}).saving, 23.87, 0.01);
}

TEST(Marins, Table5_LibraryTurnsEqualThePaperEquations) {
  // compareTurnStrategies with the paper's drag and speeds is the same computation as Eq. 12-16.
  const auto v = iris();
  const auto m = paperForm();
  const double ph = marinsHoverPowerW(v);
  for (double d : mp::kTable5Distance)
    for (double b : mp::kTable5Angle) {
      TurnSettings st;
      st.sharp_speed = m.eq10OptimalSpeed(d);
      st.rounded_speed = m.eq10OptimalSpeed(2 * d);
      const auto c = compareTurnStrategies(marinsModel(v, DragIntegration::PaperCruiseSpeed), d, b * M_PI / 180.0,
                                           {1.0, 1.0}, 2.1, 1e3, st);
      EXPECT_NEAR(c.saving_pct, mp::strategies(m, 2.1, d, b, {false, ph, ph}).saving, 1e-9);
    }
}
