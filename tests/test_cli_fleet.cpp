// `plan --vehicles N` (issue 23): a fleet flying the sorties at once. Each vehicle's mission files
// are flown by `predict`, whose trajectories (--samples-out) placed at the schedule's take-off
// times keep the stated separation; the makespan is below one vehicle flying every sortie.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "test_util.hpp"

using wattswath::test::cliBinary;
using wattswath::test::run;
using wattswath::test::sourcePath;

namespace {

std::string outDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("wattswath_test_fleet_" + name);
  std::filesystem::remove_all(d);
  return d.string();
}

// Airborne horizontal positions of a predicted trajectory (predict --samples-out CSV) by time step
// of 0.1 s after `start_s`; a sample is airborne when it is above the ground (z > 0.05 m).
std::map<long, std::pair<double, double>> airborne(const std::string& csv, double start_s) {
  std::ifstream f(csv);
  std::string line;
  std::getline(f, line);  // header: t_s,x_m,y_m,z_m,...
  std::map<long, std::pair<double, double>> out;
  while (std::getline(f, line)) {
    std::stringstream ss(line);
    std::string cell;
    double v[4] = {0, 0, 0, 0};
    for (double& x : v) {
      std::getline(ss, cell, ',');
      x = std::stod(cell);
    }
    if (v[3] > 0.05) out[std::lround((start_s + v[0]) * 10.0)] = {v[1], v[2]};
  }
  return out;
}

// Least horizontal distance [m] between any two vehicles airborne at the same 0.1 s step.
double leastDistance(const std::vector<std::pair<int, std::map<long, std::pair<double, double>>>>& flights) {
  double least = INFINITY;
  for (std::size_t a = 0; a < flights.size(); ++a)
    for (std::size_t b = a + 1; b < flights.size(); ++b) {
      if (flights[a].first == flights[b].first) continue;
      for (const auto& [t, p] : flights[a].second) {
        const auto q = flights[b].second.find(t);
        if (q != flights[b].second.end()) least = std::min(least, std::hypot(p.first - q->second.first, p.second - q->second.second));
      }
    }
  return least;
}

}  // namespace

TEST(CliFleet, TwoVehiclesFinishSoonerKeepTheSeparationAndEachSortieFitsItsBattery) {
  const auto out = outDir("two");
  const std::string vehicle = sourcePath("tests/data/iris-small-battery.json");
  const auto r = run(cliBinary() + " plan " + sourcePath("data/areas/iris_area.geojson") + " --vehicle " + vehicle +
                     " --spacing 15 --vehicles 2 --separation 15 --swap-time 120 --reserve 25 --out " + out + " --json 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output).at("sorties");
  const auto& fleet = j.at("fleet");
  ASSERT_FALSE(fleet.is_null());
  EXPECT_EQ(fleet.at("vehicles_used").get<int>(), 2);
  // One vehicle flying every sortie with a 120 s swap between two: the flights plus the swaps.
  double one = 120.0 * (j.at("count").get<double>() - 1.0);
  for (const auto& s : j.at("sorties")) one += s.at("time_s").get<double>();
  EXPECT_NEAR(fleet.at("one_vehicle_makespan_s").get<double>(), one, 1e-6);
  EXPECT_LT(fleet.at("makespan_s").get<double>(), 0.8 * one);
  EXPECT_GE(fleet.at("min_separation_m").get<double>(), 15.0);
  std::vector<std::pair<int, std::map<long, std::pair<double, double>>>> flights, together;
  double last = 0.0;
  for (const auto& s : j.at("sorties")) {
    const std::string file = s.at("file").get<std::string>();
    EXPECT_EQ(file.rfind("vehicle_" + std::to_string(s.at("vehicle").get<int>()) + "_sortie_", 0), 0u) << file;
    const std::string csv = out + "/" + file + ".csv";
    const auto p = run(cliBinary() + " predict " + out + "/" + file + " --vehicle " + vehicle + " --reserve 25 --samples-out " + csv +
                       " --json 2>/dev/null");
    ASSERT_EQ(p.status, 0) << p.output;
    const auto pj = nlohmann::json::parse(p.output);
    EXPECT_TRUE(pj.at("battery").at("fits").get<bool>()) << file;
    EXPECT_NEAR(pj.at("time_s").get<double>(), s.at("time_s").get<double>(), 1e-6 * s.at("time_s").get<double>()) << file;
    const int v = s.at("vehicle").get<int>();
    flights.emplace_back(v, airborne(csv, s.at("start_s").get<double>()));
    // Negative control: each vehicle's first sortie taking off at 0 with no delays.
    if (s.at("vehicle_sortie").get<int>() == 1) together.emplace_back(v, airborne(csv, 0.0));
    last = std::max(last, s.at("end_s").get<double>());
  }
  EXPECT_NEAR(fleet.at("makespan_s").get<double>(), last, 1e-6);
  // The separation on predict's own trajectories at the scheduled times (0.1 s steps; the
  // schedule's check interpolates 0.2 s steps, hence the 0.5 m slack).
  EXPECT_GE(leastDistance(flights), 15.0 - 0.5);
  EXPECT_LT(leastDistance(together), 15.0) << "two vehicles taking off together from one home must be found too close";
}

// With sorties written, the one-flight mission's battery verdict is said of that flight, with no
// WARNING to split what is split, and the sortie files are in the "wrote" line (it printed
// "WARNING: ... split the area or use a larger battery" and listed mission.plan alone).
TEST(CliFleet, TheTextSaysTheSortiesFitAndListsTheirFiles) {
  const auto out = outDir("text");
  const auto r = run(cliBinary() + " plan " + sourcePath("data/areas/iris_area.geojson") + " --vehicle " +
                     sourcePath("tests/data/iris-small-battery.json") + " --spacing 15 --sorties auto --no-report --out " + out +
                     " 2>&1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("WARNING"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("split the area or use a larger battery"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("note: mission.plan, the whole survey in one flight, does not fit the battery"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("legs.csv, 6 sorties (sortie_01.plan to sortie_06.plan, each with its .waypoints)"), std::string::npos)
      << r.output;
}

TEST(CliFleet, BadFleetOptionsAreRefused) {
  const std::string base = cliBinary() + " plan " + sourcePath("data/areas/iris_area.geojson") + " --vehicle " +
                           sourcePath("tests/data/iris-small-battery.json") + " --spacing 15 --out " + outDir("bad");
  const auto zero = run(base + " --vehicles 0 2>&1");
  EXPECT_NE(zero.status, 0);
  EXPECT_NE(zero.output.find("--vehicles"), std::string::npos) << zero.output;
  const auto sep = run(base + " --vehicles 2 --separation -3 2>&1");
  EXPECT_NE(sep.status, 0);
  EXPECT_NE(sep.output.find("--separation"), std::string::npos) << sep.output;
}
