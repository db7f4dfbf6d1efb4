// Optimal cruise speed: Eq. 10 cubic root, the generic optimiser, its derivative against finite
// differences, triangular legs, entry/exit speeds, and the closed-form fast path against the generic model.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_util.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/marins.hpp"
#include "wattswath/energy/optimal_speed.hpp"

using namespace wattswath::energy;

namespace {

Vehicle iris() { return loadVehicle(wattswath::test::sourcePath("data/vehicles/iris.json")); }
const ProfileLimits kUnit{1.0, 1.0};

EnergyModel legModel(DragIntegration drag = DragIntegration::Exact) { return marinsModel(iris(), drag); }

}  // namespace

TEST(PositiveCubicRoot, MatchesKnownRootsAndFallsBackOnDegenerateCubics) {
  EXPECT_NEAR(positiveCubicRoot(1.0, 0.0, 0.0, -8.0), 2.0, 1e-12);             // x^3 = 8
  EXPECT_NEAR(positiveCubicRoot(1.0, 1.0, 1.0, -3.0), 1.0, 1e-12);             // (x - 1)(x^2 + 2x + 3)
  EXPECT_NEAR(positiveCubicRoot(1.0, 4.0, 1.0, -6.0), 1.0, 1e-12);             // (x - 1)(x + 2)(x + 3): three real roots
  EXPECT_NEAR(positiveCubicRoot(0.0, 1.0, 0.0, -600.0), std::sqrt(600.0), 1e-9);  // no kinetic, no drag: v = sqrt(a d)
  EXPECT_NEAR(positiveCubicRoot(1e-20, 1.0, 0.0, -4.0), 2.0, 1e-9);            // nearly quadratic
  EXPECT_NEAR(positiveCubicRoot(1e6, 1e-9, 0.0, -1e-3), 1e-3, 1e-12);          // tiny root
  EXPECT_THROW(positiveCubicRoot(1.0, 1.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(positiveCubicRoot(-1.0, 1.0, 0.0, -1.0), std::invalid_argument);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-6.0, 6.0);
  for (int i = 0; i < 500; ++i) {
    const double c3 = std::pow(10.0, u(rng)), c2 = std::pow(10.0, u(rng)), c0 = -std::pow(10.0, u(rng));
    const double x = positiveCubicRoot(c3, c2, 0.0, c0);
    ASSERT_GT(x, 0.0);
    EXPECT_LE(std::abs((c3 * x + c2) * x * x + c0), 1e-13 * (std::abs(c0) + c2 * x * x + c3 * x * x * x))
        << c3 << " " << c2 << " " << c0;
  }
}

TEST(OptimalSpeed, Eq10RootMinimisesEq9) {
  const auto m = MarinsClosedForm::fromVehicle(iris(), DragIntegration::PaperCruiseSpeed);
  for (double d : {50.0, 300.0, 600.0, 1200.0, 5000.0}) {
    for (MarinsTerms t : {MarinsTerms{true, true}, MarinsTerms{false, true}, MarinsTerms{true, false}}) {
      const double v = m.eq10OptimalSpeed(d, t);
      EXPECT_LT(m.eq9Energy(d, v, t), m.eq9Energy(d, v * 1.001, t));
      EXPECT_LT(m.eq9Energy(d, v, t), m.eq9Energy(d, v * 0.999, t));
    }
  }
}

TEST(OptimalSpeed, GenericOptimiserEqualsEq10WithPaperDrag) {
  const auto model = legModel(DragIntegration::PaperCruiseSpeed);
  const auto m = MarinsClosedForm::fromVehicle(iris(), DragIntegration::PaperCruiseSpeed);
  for (double d : {50.0, 150.0, 600.0, 1200.0, 3000.0}) {
    const auto r = optimalCruiseSpeed(model, d, 0.0, 0.0, kUnit, 100.0);
    EXPECT_NEAR(r.speed, m.eq10OptimalSpeed(d), 1e-5) << d;
    EXPECT_NEAR(r.energy, m.eq9Energy(d, r.speed), 1e-6 * r.energy);
    EXPECT_TRUE(r.analytic_derivative);
    EXPECT_FALSE(r.at_upper_bound);
    EXPECT_NEAR(r.derivative, 0.0, 1e-3);
  }
}

TEST(OptimalSpeed, DerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> len(5.0, 800.0), spd(0.0, 12.0), frac(0.05, 1.5);
  const ProfileLimits lim{1.0, 1.4};
  for (auto drag : {DragIntegration::Exact, DragIntegration::PaperCruiseSpeed}) {
    const auto model = legModel(drag);
    int checked = 0;
    for (int i = 0; i < 400 && checked < 150; ++i) {
      const double d = len(rng), ve = spd(rng), vx = spd(rng);
      const double vc = 0.5 + frac(rng) * legPeakSpeed(d, ve, vx, lim);
      const double h = 1e-5;
      double ep = 0.0, em = 0.0;
      LegEnergySlope s;
      try {
        s = legEnergySlope(model, d, ve, vc, vx, lim);
        ep = model.energy(buildLegProfile(d, ve, vc + h, vx, lim));
        em = model.energy(buildLegProfile(d, ve, vc - h, vx, lim));
      } catch (const std::invalid_argument&) {
        continue;  // infeasible change of speed on this leg
      }
      // Kinks (cruise equal to entry/exit/peak) are measure zero; skip the few samples next to one.
      if (std::abs(vc - ve) < 1e-3 || std::abs(vc - vx) < 1e-3 ||
          std::abs(vc - legPeakSpeed(d, ve, vx, lim)) < 1e-3)
        continue;
      const double fd = (ep - em) / (2.0 * h);
      EXPECT_NEAR(s.derivative, fd, 1e-4 * std::max(1.0, std::abs(fd))) << d << " " << ve << " " << vc << " " << vx;
      EXPECT_TRUE(s.analytic);
      ++checked;
    }
    EXPECT_GE(checked, 100);
  }
}

TEST(OptimalSpeed, EffectWithoutGradientFallsBackToDifferences) {
  // An effect with power only (quadrature energy, no closed-form gradient).
  struct Quartic final : Effect {
    Quartic() { coeffs_.push_back({"c", 1e-4, "W s^4/m^4", 0.0, 1.0, "test"}); }
    std::string name() const override { return "quartic"; }
    std::string meaning() const override { return "test effect c v^4"; }
    double power(const MotionState& s) const override { return coeffs_[0].value * std::pow(s.velocity.norm(), 4); }
    std::unique_ptr<Effect> clone() const override { return std::make_unique<Quartic>(*this); }
  };
  auto model = legModel();
  model.add(Quartic{});
  const auto s = legEnergySlope(model, 300.0, 0.0, 9.0, 0.0, kUnit);
  EXPECT_FALSE(s.analytic);
  const double fd = (model.energy(buildLegProfile(300.0, 0.0, 9.0 + 1e-5, 0.0, kUnit)) -
                     model.energy(buildLegProfile(300.0, 0.0, 9.0 - 1e-5, 0.0, kUnit))) / 2e-5;
  EXPECT_NEAR(s.derivative, fd, 1e-3 * std::abs(fd));
  const auto r = optimalCruiseSpeed(model, 300.0, 0.0, 0.0, kUnit, 50.0);
  EXPECT_FALSE(r.analytic_derivative);
  EXPECT_LT(r.energy, model.energy(buildLegProfile(300.0, 0.0, r.speed * 1.01, 0.0, kUnit)));
  EXPECT_LT(r.energy, model.energy(buildLegProfile(300.0, 0.0, r.speed * 0.99, 0.0, kUnit)));
}

TEST(OptimalSpeed, MonotonicInDistance) {
  for (auto drag : {DragIntegration::Exact, DragIntegration::PaperCruiseSpeed}) {
    const auto model = legModel(drag);
    double prev = 0.0;
    for (double d = 10.0; d <= 5000.0; d *= 1.3) {
      const double v = optimalCruiseSpeed(model, d, 0.0, 0.0, kUnit, 100.0).speed;
      EXPECT_GT(v, prev) << d;
      prev = v;
    }
    // The long-leg limit (P0 / (rho CdA))^(1/3) bounds it from below.
    EXPECT_LT(prev, MarinsClosedForm::fromVehicle(iris()).longLegOptimalSpeed() + 1e-9);
  }
}

TEST(OptimalSpeed, SpeedLimitAndTriangularLegs) {
  const auto model = legModel();
  // A 5 m leg peaks at sqrt(5) m/s: the search range ends there. Hover time d/v + v/a is smallest
  // exactly at the peak (the triangle), so kinetic and drag pull the optimum just below it.
  const auto shortLeg = optimalCruiseSpeed(model, 5.0, 0.0, 0.0, kUnit, 20.0);
  EXPECT_NEAR(shortLeg.upper_bound, std::sqrt(5.0), 1e-12);
  EXPECT_LT(shortLeg.speed, std::sqrt(5.0));
  EXPECT_GT(shortLeg.speed, 0.8 * std::sqrt(5.0));
  EXPECT_LE(shortLeg.energy, model.energy(buildLegProfile(5.0, 0.0, 20.0, 0.0, kUnit)));  // the triangle
  // Hover alone is minimum time: the triangle, at the top of the range, for unequal a and b too.
  EnergyModel hoverOnly;
  hoverOnly.add(HoverEffect::fromVehicle(iris()));
  const ProfileLimits lim{1.0, 2.0};
  const auto tri = optimalCruiseSpeed(hoverOnly, 5.0, 0.0, 0.0, lim, 20.0);
  EXPECT_TRUE(tri.at_upper_bound);
  EXPECT_NEAR(tri.speed, legPeakSpeed(5.0, 0.0, 0.0, lim), 1e-6);
  EXPECT_NEAR(tri.energy, hoverOnly.energy(buildLegProfile(5.0, 0.0, 20.0, 0.0, lim)), 1e-9 * tri.energy);
  // A speed limit below the unconstrained optimum binds.
  const auto capped = optimalCruiseSpeed(model, 600.0, 0.0, 0.0, kUnit, 10.0);
  EXPECT_DOUBLE_EQ(capped.speed, 10.0);
  EXPECT_TRUE(capped.at_upper_bound);
  EXPECT_LT(capped.derivative, 0.0);
}

TEST(OptimalSpeed, EntryAndExitSpeeds) {
  const auto model = legModel();
  const ProfileLimits lim{1.0, 1.0};
  // Entering fast and leaving fast: the optimum is still a local minimum of the leg energy.
  for (auto [ve, vx] : {std::pair{8.0, 8.0}, std::pair{0.0, 12.0}, std::pair{14.0, 0.0}, std::pair{20.0, 18.0}}) {
    const auto r = optimalCruiseSpeed(model, 400.0, ve, vx, lim, 30.0);
    auto E = [&](double v) { return model.energy(buildLegProfile(400.0, ve, v, vx, lim)); };
    EXPECT_LE(r.energy, E(std::min(r.speed * 1.01, r.upper_bound)) + 1e-6);
    EXPECT_LE(r.energy, E(r.speed * 0.99) + 1e-6);
  }
  EXPECT_THROW(optimalCruiseSpeed(model, 10.0, 0.0, 15.0, lim, 30.0), std::invalid_argument);  // cannot reach 15
  EXPECT_THROW(optimalCruiseSpeed(model, -1.0, 0.0, 0.0, lim, 30.0), std::invalid_argument);
  EXPECT_THROW(optimalCruiseSpeed(model, 0.0, 0.0, 0.0, lim, 30.0), std::invalid_argument);
  EXPECT_THROW(optimalCruiseSpeed(model, 10.0, -1.0, 0.0, lim, 30.0), std::invalid_argument);
  EXPECT_THROW(optimalCruiseSpeed(model, 10.0, 0.0, 0.0, lim, 0.0), std::invalid_argument);
  CruiseSpeedSettings bad;
  bad.grid_points = 2;
  EXPECT_THROW(optimalCruiseSpeed(model, 10.0, 0.0, 0.0, lim, 10.0, bad), std::invalid_argument);
}

TEST(MarinsClosedForm, FastPathEqualsGenericModelOnRandomLegs) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> len(0.5, 900.0), spd(0.0, 18.0);
  const ProfileLimits lim{1.0, 1.0};
  for (auto drag : {DragIntegration::Exact, DragIntegration::PaperCruiseSpeed}) {
    const auto model = legModel(drag);
    const auto fast = MarinsClosedForm::fromVehicle(iris(), drag);
    int feasible = 0, infeasible = 0;
    for (int i = 0; i < 2000; ++i) {
      const double d = len(rng), ve = spd(rng), vc = 0.3 + spd(rng), vx = spd(rng);
      const double e = fast.legEnergy(d, ve, vc, vx);
      try {
        const double ref = model.energy(buildLegProfile(d, ve, vc, vx, lim));
        EXPECT_NEAR(e, ref, 1e-9 * ref) << d << " " << ve << " " << vc << " " << vx;
        ++feasible;
      } catch (const std::invalid_argument&) {
        EXPECT_TRUE(std::isnan(e));
        ++infeasible;
      }
    }
    EXPECT_GT(feasible, 1000);
    EXPECT_GT(infeasible, 10);
  }
}

TEST(MarinsClosedForm, ForLegsOfAModelWithMarinsEffectsOnly) {
  // The planner flies legs with the closed form when the model holds Marins' effects only, with
  // whatever coefficients (fitted ones too) and limits: it must equal the model on every leg.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> len(0.5, 900.0), spd(0.0, 18.0);
  const ProfileLimits lim{1.3, 0.7};
  for (auto drag : {DragIntegration::Exact, DragIntegration::PaperCruiseSpeed}) {
    auto model = legModel(drag);
    model.effect("hover").setCoefficientValues({231.5});
    model.effect("kinetic").setCoefficientValues({2.9});
    model.effect("parasitic_drag").setCoefficientValues({0.21});
    const auto fast = MarinsClosedForm::forLegsOf(model, lim);
    ASSERT_TRUE(fast.has_value());
    EXPECT_TRUE(std::isnan(fast->p0));  // a model does not split hover power into P0 and eta
    int feasible = 0;
    for (int i = 0; i < 1000; ++i) {
      const double d = len(rng), ve = spd(rng), vc = 0.3 + spd(rng), vx = spd(rng);
      try {
        const double ref = model.energy(buildLegProfile(d, ve, vc, vx, lim));
        EXPECT_NEAR(fast->legEnergy(d, ve, vc, vx), ref, 1e-9 * ref) << d << " " << ve << " " << vc << " " << vx;
        ++feasible;
      } catch (const std::invalid_argument&) {
        EXPECT_TRUE(std::isnan(fast->legEnergy(d, ve, vc, vx)));
      }
    }
    EXPECT_GT(feasible, 500);
  }
  // Without the drag effect: drag costs nothing; with any other effect: no closed form.
  auto no_drag = legModel();
  no_drag.remove("parasitic_drag");
  const auto nd = MarinsClosedForm::forLegsOf(no_drag, lim);
  ASSERT_TRUE(nd.has_value());
  EXPECT_NEAR(nd->legEnergy(300.0, 0.0, 10.0, 0.0), no_drag.energy(buildLegProfile(300.0, 0.0, 10.0, 0.0, lim)), 1e-9);
  auto climb = legModel();
  climb.add(ClimbEffect(1.0, 0.0));
  EXPECT_FALSE(MarinsClosedForm::forLegsOf(climb, lim).has_value());
}

TEST(MarinsClosedForm, ExactDragIsBelowPaperDragByKv4Over2a) {
  // Stop to stop, trapezoid: the exact integral is k (d v^2 - v^4 / (2 a)); Eq. 9 charges k d v^2.
  const auto ex = MarinsClosedForm::fromVehicle(iris(), DragIntegration::Exact);
  const auto pa = MarinsClosedForm::fromVehicle(iris(), DragIntegration::PaperCruiseSpeed);
  const double d = 600.0, v = 14.845;
  EXPECT_NEAR(pa.legEnergy(d, 0, v, 0) - ex.legEnergy(d, 0, v, 0), ex.k_drag * std::pow(v, 4) / 2.0, 1e-9);
  EXPECT_NEAR(pa.legEnergy(d, 0, v, 0), pa.eq9Energy(d, v), 1e-9 * pa.eq9Energy(d, v));
}

TEST(OptimalSpeed, LegJustLongEnoughForItsSpeedChange) {
  // Regression: a leg just long enough to brake from entry to exit speed (the planner's arcs met
  // one such leg) made the grid of cruise speeds throw "leg too short" at speeds below the exit
  // speed instead of skipping them. Now: a finite optimum whose profile builds.
  const auto m = legModel();
  const ProfileLimits lim{1.0, 1.0};
  for (const auto& [ve, vx] : {std::pair<double, double>{4.93163, 2.0787}, {2.0787, 4.93163}, {8.0, 0.5}}) {
    const double need = std::abs(ve * ve - vx * vx) / 2.0;
    for (const double d : {need, need * (1.0 + 1e-12), need * (1.0 + 1e-6)}) {
      CruiseSpeedSettings cs;
      cs.min_speed = 0.05;
      const auto r = optimalCruiseSpeed(m, d, ve, vx, lim, 16.0, cs);
      EXPECT_TRUE(std::isfinite(r.energy)) << ve << " " << vx << " " << d;
      EXPECT_NO_THROW(buildLegProfile(d, ve, r.speed, vx, lim)) << ve << " " << vx << " " << d << " " << r.speed;
    }
  }
}
