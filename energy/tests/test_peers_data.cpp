// Di Franco & Buttazzo against their own published files in ../shared/data/difranco.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_util.hpp"
#include "wattswath/energy/peers.hpp"

using namespace wattswath::energy;
using wattswath::test::sharedData;

namespace {
std::vector<std::vector<double>> readCsv(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> row;
    while (std::getline(ss, cell, ',')) row.push_back(cell == "nan" ? NAN : std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

TEST(DiFrancoData, LoadedModelEqualsPublishedCoefficients) {
  const DiFrancoModel a = DiFrancoModel::load(sharedData("difranco/E_model.json"));
  const DiFrancoModel b = DiFrancoModel::published();
  EXPECT_EQ(a.level_power, b.level_power);
  EXPECT_EQ(a.accelerate_power, b.accelerate_power);
  EXPECT_EQ(a.decelerate_power, b.decelerate_power);
  EXPECT_EQ(a.climb_power_w, b.climb_power_w);
}

TEST(DiFrancoData, PowerTableMatchesThePolynomial) {
  const DiFrancoModel m = DiFrancoModel::load(sharedData("difranco/E_model.json"));
  const auto rows = readCsv(sharedData("difranco/P_of_v_table.csv"));
  ASSERT_GT(rows.size(), 20u);
  for (const auto& r : rows) EXPECT_NEAR(m.levelPower(r[0]), r[1], 0.006) << "v " << r[0];
}

TEST(DiFrancoData, LongLegsApproachTheMinimumEnergyPerMetreSpeed) {
  // For long legs the ramps stop mattering: the optimum tends to argmin P(v)/v, which the file's
  // P_of_v_table puts at 12.0 m/s (20.026 J/m, the lowest of its energy_per_m column).
  const DiFrancoModel m = DiFrancoModel::load(sharedData("difranco/E_model.json"));
  const auto rows = readCsv(sharedData("difranco/P_of_v_table.csv"));
  double best_v = 0.0, best_e = 1e30;
  for (const auto& r : rows)
    if (std::isfinite(r[2]) && r[2] < best_e) best_e = r[2], best_v = r[0];
  EXPECT_NEAR(best_v, 12.0, 1e-12);
  EXPECT_NEAR(m.stopToStopOptimalSpeed(20000.0), best_v, 0.3);
}
