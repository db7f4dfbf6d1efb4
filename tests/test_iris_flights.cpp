// The measured IRIS+ flights (../shared/data/iris-flights): every log reads without rejection,
// and the diagnose / fit commands print the JSON contract of issue 6 with errors that fall.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_util.hpp"
#include "wattswath/energy/log_io.hpp"
#include "wattswath/energy/replay.hpp"

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
    const auto log = energy::readCsvLog(test::sharedData(f));
    EXPECT_GT(log.samples.size(), 300u) << f;  // 1 Hz, ~5.5 min, every row kept
    EXPECT_FALSE(log.velocity_derived);
    const auto p = energy::prepareLog(log);
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
  const auto& c = j.at("candidates");
  ASSERT_GE(c.size(), 5u);
  for (const auto& x : c) {
    for (const char* k : {"effect", "rmse_w", "improvement_pct", "coefficients"}) EXPECT_TRUE(x.contains(k)) << k;
  }
  EXPECT_GE(c[0].at("improvement_pct").get<double>(), c[1].at("improvement_pct").get<double>());
  EXPECT_GT(c[0].at("improvement_pct").get<double>(), 1.0);
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
