// The measured IRIS+ flights (../shared/data/iris-flights): every log reads without rejection,
// and the diagnose / fit commands print the JSON contract of issue 6 with errors that fall.
#include <cmath>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_util.hpp"
#include "wattswath/logs/log_io.hpp"
#include "wattswath/calibration/replay.hpp"

using namespace wattswath;

namespace {
const char* kFlights[] = {"iris-flights/2017-10-18_1436_energy14.csv", "iris-flights/2017-10-18_1449_normal29.csv",
                          "iris-flights/2017-11-20_1610_energy14.csv"};
std::string logArgs(bool all = true) {
  std::string a;
  for (int i = 0; i < (all ? 3 : 2); ++i) a += " --log " + test::sharedData(kFlights[i]);
  return a;
}
}  // namespace

TEST(IrisFlights, ReadAndSegmentEveryRow) {
  for (const char* f : kFlights) {
    const auto log = wattswath::logs::readCsvLog(test::sharedData(f));
    EXPECT_GT(log.samples.size(), 300u) << f;  // 1 Hz, ~5.5 min, every row kept
    EXPECT_FALSE(log.velocity_derived);
    const auto p = wattswath::calibration::prepareLog(log);
    EXPECT_GT(p.legs.size(), 10u) << f;  // 20-30 legs with stops or slow-downs at waypoints
  }
}

TEST(IrisFlights, DiagnoseJsonContract) {
  const auto r = test::run(test::cliBinary() + " diagnose --vehicle " + test::sourcePath("data/vehicles/iris.json") +
                           " --effects hover,kinetic,parasitic_drag" + logArgs() + " --json 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_GT(j.at("baseline").at("rmse_w").get<double>(), 0.0);
  EXPECT_TRUE(j.at("baseline").contains("energy_error_pct"));
  // Issue 18: a verdict, the found effects and, when unexplained, the signals carrying the residual.
  const auto verdict = j.at("verdict").get<std::string>();
  EXPECT_TRUE(verdict == "missing_effect" || verdict == "nothing_missing" || verdict == "unexplained") << verdict;
  EXPECT_TRUE(j.at("found").is_array());
  for (const auto& g : j.at("signatures")) {
    for (const char* k : {"signal", "strength", "sentence"}) EXPECT_TRUE(g.contains(k)) << k;
  }
  if (verdict == "unexplained") {
    EXPECT_FALSE(j.at("signatures").empty());
  }
  const auto& c = j.at("candidates");
  ASSERT_GE(c.size(), 5u);
  for (const auto& x : c) {
    for (const char* k : {"effect", "rmse_w", "improvement_pct", "coefficients"}) EXPECT_TRUE(x.contains(k)) << k;
  }
  EXPECT_GE(c[0].at("improvement_pct").get<double>(), c[1].at("improvement_pct").get<double>());
  EXPECT_GT(c[0].at("improvement_pct").get<double>(), 1.0);
  // An uncertainty is a positive number or null (not determined by the data), never an exact 0: on
  // these flights the wind candidate's drag area goes to 0, after which the wind does not change
  // the modelled power, and "wind 1.7 +- 0 m/s" was reported before the fix.
  bool wind_seen = false;
  for (const auto& x : c) {
    for (const auto& [name, sigma] : x.at("uncertainty").items())
      EXPECT_TRUE(sigma.is_null() || sigma.get<double>() > 0.0) << x.at("effect") << "." << name << ": " << sigma;
    if (x.at("effect") == "wind" && x.at("coefficients").at("drag_area").get<double>() < 1e-9) {
      wind_seen = true;
      EXPECT_TRUE(x.at("uncertainty").at("wind_east").is_null());
      EXPECT_NE(x.at("summary").get<std::string>().find("not determined"), std::string::npos) << x.at("summary");
    }
  }
  EXPECT_TRUE(wind_seen) << "the wind candidate no longer ends at drag area 0: revisit this check";
}

TEST(IrisFlights, FitJsonContractAndHeldOutFlightImproves) {
  const auto r = test::run(test::cliBinary() + " fit --vehicle " + test::sourcePath("data/vehicles/iris.json") +
                           " --effects hover,kinetic,parasitic_drag,translational_lift" + logArgs(false) +
                           " --test-log " + test::sharedData(kFlights[2]) + " --json 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_TRUE(j.at("coefficients").at("translational_lift").contains("induced_power"));
  for (const char* side : {"train", "test"}) {
    for (const char* k : {"rmse_w", "energy_error_pct", "leg_energy_mape_pct"}) EXPECT_TRUE(j.at(side).contains(k));
  }
  EXPECT_LT(j.at("test").at("rmse_w").get<double>(), j.at("test").at("before").at("rmse_w").get<double>());
}

// On the first flight, translational lift's induced power and speed scale trade off almost
// exactly (only P / v_h^2 shows at 8 m/s): fit said "induced power 3.38e+03 +- 0.036 W" with r = -1,
// since a pseudo-inverse of the unscaled normal matrix dropped the near-null direction, made mostly
// of the watts. Neither may now look known to better than 10 %, unless it is said not determined.
TEST(IrisFlights, ConfoundedLiftCoefficientsAreNotReportedAsPrecise) {
  const auto r = test::run(test::cliBinary() + " fit --vehicle " +
                           test::sourcePath("data/vehicles/iris-plus-arducopter3.json") +
                           " --effects hover,kinetic,parasitic_drag,translational_lift --log " +
                           test::sharedData(kFlights[0]) + " --json 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  for (const char* name : {"induced_power", "induced_velocity"}) {
    const double value = j.at("coefficients").at("translational_lift").at(name).get<double>();
    const auto& sigma = j.at("uncertainty").at("translational_lift").at(name);
    EXPECT_TRUE(sigma.is_null() || sigma.get<double>() > 0.1 * std::abs(value)) << name << " " << value << " +- " << sigma;
  }
}

// Issue 6, "Real flights": each flight predicted from its plan (leg end points snapped to the
// plan's vertices, stop-to-stop with turns in place, or slowing at corners), with the error split
// into kinematics (plan - replay) and physics (replay - measured). Numbers: docs/validation.md.
TEST(IrisFlights, PlanPredictionSplitsKinematicsAndPhysics) {
  for (const char* corner : {"0", "0.5"}) {
    const auto r = test::run(test::cliBinary() + " replay --vehicle " + test::sourcePath("data/vehicles/iris.json") +
                             logArgs() + " --plan " + test::sharedData("iris-flights/plan__real_flight_area.waypoints") +
                             " --plan-corner-fraction " + corner + " --json 2>/dev/null");
    ASSERT_EQ(r.status, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    const auto& p = j.at("plan_prediction");
    ASSERT_EQ(p.size(), 3u);
    for (const auto& f : p) {
      const double e = f.at("energy_j"), t = f.at("time_s"), meas = f.at("measured_j"), rep = f.at("replay_j");
      ASSERT_TRUE(std::isfinite(e) && std::isfinite(t)) << f;
      // Stop-to-stop overestimates (up to +30 %), slowing to half speed underestimates (down to
      // -25 %); beyond 0.6..1.45 x measured the plan would be wrong, not the corners.
      EXPECT_GT(e, 0.6 * meas) << f;
      EXPECT_LT(e, 1.45 * meas) << f;
      // The planned path follows the logged one within the simplification tolerance.
      EXPECT_NEAR(f.at("distance_m").get<double>(), f.at("measured_distance_m").get<double>(),
                  0.1 * f.at("measured_distance_m").get<double>());
      EXPECT_GT(t, 0.6 * f.at("measured_time_s").get<double>()) << f;
      EXPECT_GT(f.at("legs").get<int>(), 10) << f;
      // The split adds up: measured + physics + kinematics = plan.
      EXPECT_NEAR(meas + f.at("physics_error_j").get<double>() + f.at("kinematics_error_j").get<double>(), e, 1e-6 * e);
      EXPECT_NEAR(f.at("kinematics_error_j").get<double>(), e - rep, 1e-6 * e);
    }
  }
}
