// Every effect's closed-form energy against numerical quadrature of its power, and the breakdown.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/tolerances.hpp"

using namespace wattswath::energy;

namespace {

/// The paper's IRIS, from the bundled vehicle file (data/vehicles/iris.json).
Vehicle iris() {
  static const Vehicle v = loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json");
  return v;
}

std::vector<Piece> randomPieces(std::mt19937& rng) {
  std::uniform_real_distribution<double> len(0.5, 300.0), spd(0.0, 15.0), ang(-M_PI, M_PI);
  std::vector<Piece> out;
  for (int i = 0; i < 40; ++i) {
    const double d = len(rng), vc = 0.5 + spd(rng);
    const double ve = std::min(spd(rng), vc), vx = std::min(spd(rng), vc);
    try {
      for (const auto& p : buildLegProfile(d, ve, vc, vx, {1.0, 1.3}, ang(rng), 0.0)) out.push_back(p);
    } catch (const std::invalid_argument&) {
    }
    out.push_back(turnInPlace(ang(rng), 2.1));
    out.push_back(arc(len(rng) / 30.0, ang(rng), 0.5 + spd(rng)));
  }
  return out;
}

}  // namespace

TEST(Effects, ClosedFormEnergyMatchesQuadratureOfPower) {
  const EnergyModel m = marinsModel(iris());
  std::mt19937 rng(20261122);
  YawRateEffect yaw(3.5);
  const auto pieces = randomPieces(rng);
  ASSERT_GT(pieces.size(), 100u);
  for (const auto& p : pieces) {
    for (const auto& e : m.effects()) {
      const double closed = e->energy(p);
      const double quad = integratePower(*e, p, 64);
      EXPECT_NEAR(closed, quad, 1e-7 * std::max(1.0, std::abs(quad))) << e->name() << " phase " << toString(p.phase);
    }
    EXPECT_NEAR(yaw.energy(p), integratePower(yaw, p, 64), 1e-7 * std::max(1.0, yaw.energy(p)));
  }
}

TEST(Effects, HoverPowerFromVehicle) {
  const HoverEffect h = HoverEffect::fromVehicle(iris());
  EXPECT_NEAR(h.coefficient("hover_power"), marinsHoverPowerW(iris()), 1e-12);
  EXPECT_NEAR(h.energy(hover(10.0)), 10.0 * marinsHoverPowerW(iris()), 1e-9);
}

TEST(Effects, PaperDragApproximationUsesCruiseSpeedOverWholeLeg) {
  const Vehicle v = iris();
  const auto ps = buildLegProfile(600.0, 0.0, 14.9, 0.0, {1.0, 1.0});
  const ParasiticDragEffect paper = ParasiticDragEffect::fromVehicle(v, DragIntegration::PaperCruiseSpeed);
  double e = 0.0;
  for (const auto& p : ps) e += paper.energy(p);
  EXPECT_NEAR(e, 600.0 * 0.5 * 1.2928 * 0.01547 * 14.9 * 14.9 / v.totalEfficiency(), 1e-9);
  const ParasiticDragEffect exact = ParasiticDragEffect::fromVehicle(v);
  double ex = 0.0;
  for (const auto& p : ps) ex += exact.energy(p);
  EXPECT_LT(ex, e);  // the exact integral is lower: accelerating and braking are slower than cruise
}

TEST(Breakdown, SplitsByEffectAndPhaseAndSumsToTotal) {
  const EnergyModel m = marinsModel(iris());
  auto ps = buildLegProfile(300.0, 0.0, 10.0, 0.0, {1.0, 1.0});
  ps.push_back(turnInPlace(M_PI / 2, 2.1));
  const Breakdown b = m.evaluate(ps);
  EXPECT_NEAR(b.total(), m.energy(ps), 1e-9);
  double sum = 0.0;
  for (int k = 0; k < kPhaseCount; ++k) sum += b.byPhase(static_cast<Phase>(k));
  EXPECT_NEAR(sum, b.total(), 1e-9);
  EXPECT_GT(b.at("kinetic", Phase::Accelerate), 0.0);
  EXPECT_EQ(b.at("kinetic", Phase::Cruise), 0.0);
  EXPECT_NEAR(b.at("hover", Phase::Turn), marinsHoverPowerW(iris()) * (M_PI / 2) / 2.1, 1e-9);
  EXPECT_NEAR(b.time, totalTime(ps), 1e-12);
}

TEST(EnergyModel, MinEnergyPerMetreIsALowerBound) {
  const EnergyModel m = marinsModel(iris());
  const double lb = m.minEnergyPerMetre(16.0);
  for (double d : {10.0, 100.0, 1000.0}) {
    for (double v = 1.0; v <= 16.0; v += 1.0) {
      try {
        EXPECT_GE(m.energy(buildLegProfile(d, 0.0, v, 0.0, {1.0, 1.0})) / d, lb);
      } catch (const std::invalid_argument&) {
      }
    }
  }
}
