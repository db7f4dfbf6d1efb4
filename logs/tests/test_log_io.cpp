// Canonical CSV flight logs: malformed fixtures are rejected naming file, line and column;
// BOM/CRLF/geodetic input is read; derived kinematics are exact on polynomials; write -> read
// round trips bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "test_util.hpp"
#include "wattswath/logs/log_io.hpp"

using namespace wattswath::logs;
using wattswath::test::sourcePath;

namespace {

std::string errorOf(const std::string& rel) {
  try {
    readCsvLog(sourcePath(rel));
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

void expectHas(const std::string& msg, const std::string& part) {
  EXPECT_NE(msg.find(part), std::string::npos) << "message: '" << msg << "' lacks '" << part << "'";
}

}  // namespace

TEST(CsvLogBad, MissingColumnNamesFileLineAndColumn) {
  const auto m = errorOf("tests/data/bad/missing_column.csv");
  expectHas(m, "missing_column.csv:1:");
  expectHas(m, "'z_m'");
}

TEST(CsvLogBad, NonNumericValue) {
  const auto m = errorOf("tests/data/bad/non_numeric.csv");
  expectHas(m, "non_numeric.csv:3:");
  expectHas(m, "'y_m'");
  expectHas(m, "'abc'");
}

TEST(CsvLogBad, NonFiniteValue) {
  const auto m = errorOf("tests/data/bad/non_finite.csv");
  expectHas(m, "non_finite.csv:3:");
  expectHas(m, "'voltage_v'");
}

TEST(CsvLogBad, TimeNotIncreasing) {
  const auto m = errorOf("tests/data/bad/time_not_increasing.csv");
  expectHas(m, "time_not_increasing.csv:4:");
  expectHas(m, "'time_s'");
}

TEST(CsvLogBad, FewerThanTwoSamples) { expectHas(errorOf("tests/data/bad/one_sample.csv"), "at least 2"); }

TEST(CsvLogBad, ShortRow) {
  const auto m = errorOf("tests/data/bad/short_row.csv");
  expectHas(m, "short_row.csv:3:");
  expectHas(m, "5 fields");
}

TEST(CsvLogBad, PartialVelocityGroup) { expectHas(errorOf("tests/data/bad/partial_velocity.csv"), "'vy_mps'"); }

TEST(CsvLogBad, EmptyCellInRequiredColumn) {
  const auto m = errorOf("tests/data/bad/empty_cell.csv");
  expectHas(m, "empty_cell.csv:3:");
  expectHas(m, "'voltage_v'");
}

TEST(CsvLogBad, LatitudeOutOfRange) {
  const auto m = errorOf("tests/data/bad/bad_latitude.csv");
  expectHas(m, "bad_latitude.csv:3:");
  expectHas(m, "'lat_deg'");
}

TEST(CsvLogBad, MissingFile) { expectHas(errorOf("tests/data/bad/does_not_exist.csv"), "cannot open"); }

TEST(CsvLog, BomCrlfGeodeticAndExtraColumns) {
  const auto log = readCsvLog(sourcePath("tests/data/good/bom_crlf_geodetic.csv"));
  ASSERT_EQ(log.samples.size(), 4u);
  EXPECT_EQ(log.metadata.at("vehicle"), "iris");
  EXPECT_TRUE(log.has_geodetic_origin);
  EXPECT_NEAR(log.origin_lat_deg, 43.716004, 1e-12);
  // 0.0001 deg of longitude at 43.716 deg N is about 8.04 m east.
  EXPECT_NEAR(log.samples[1].position.x(), 8.04, 0.02);
  EXPECT_NEAR(log.samples[1].position.y(), 0.0, 1e-3);
  EXPECT_NEAR(log.samples[2].position.z(), 1.0, 1e-3);
  EXPECT_NEAR(log.samples[1].power, 12.1 * 21.0, 1e-9);
  ASSERT_EQ(log.extra_columns.size(), 1u);
  EXPECT_EQ(log.extra_values[3][0], "d");
  EXPECT_TRUE(log.velocity_derived);
  EXPECT_TRUE(log.acceleration_derived);
}

TEST(CsvLog, DerivedKinematicsExactOnAParabola) {
  // x = 3 t + 0.5 t^2 with uneven time steps: the quadratic fit is exact.
  std::string csv = "time_s,x_m,y_m,z_m,power_w\n";
  double t = 0.0;
  for (int i = 0; i < 12; ++i) {
    csv += std::to_string(t) + "," + std::to_string(3 * t + 0.5 * t * t) + ",0,0,200\n";
    t += (i % 2) ? 0.1 : 0.13;
  }
  const auto log = parseCsvLog(csv, "parabola.csv");
  for (const auto& s : log.samples) {
    EXPECT_NEAR(s.velocity.x(), 3.0 + s.t, 1e-5);
    EXPECT_NEAR(s.acceleration.x(), 1.0, 1e-4);
  }
}

TEST(CsvLog, WriteReadRoundTripIsExact) {
  FlightLog log;
  log.metadata["vehicle"] = "iris";
  for (int i = 0; i < 5; ++i) {
    LogSample s;
    s.t = 0.1 * i + 1e-7;
    s.position = {std::sqrt(2.0) * i, -1.0 / 3.0 * i, 10.0 + i};
    s.velocity = {1.0 / 7.0, 2.0, -0.5};
    s.acceleration = {0.25, -0.125, M_PI};
    s.yaw = i == 2 ? std::numeric_limits<double>::quiet_NaN() : 0.1 * i;
    s.voltage = 12.0 - 0.01 * i;
    s.current = 20.0 + i / 3.0;
    s.power = s.voltage * s.current;
    log.samples.push_back(s);
  }
  log.extra_columns = {"mode"};
  for (int i = 0; i < 5; ++i) log.extra_values.push_back({"AUTO"});
  const std::string text = writeCsvLog(log);
  const auto back = parseCsvLog(text, "roundtrip.csv");
  ASSERT_EQ(back.samples.size(), log.samples.size());
  EXPECT_FALSE(back.velocity_derived);
  for (size_t i = 0; i < log.samples.size(); ++i) {
    EXPECT_EQ(back.samples[i].t, log.samples[i].t);
    EXPECT_EQ(back.samples[i].position, log.samples[i].position);
    EXPECT_EQ(back.samples[i].velocity, log.samples[i].velocity);
    EXPECT_EQ(back.samples[i].acceleration, log.samples[i].acceleration);
    EXPECT_EQ(back.samples[i].power, log.samples[i].power);
    EXPECT_EQ(std::isnan(back.samples[i].yaw), std::isnan(log.samples[i].yaw));
  }
  EXPECT_EQ(back.extra_values[4][0], "AUTO");
  EXPECT_EQ(writeCsvLog(back), text);
}

TEST(CsvLog, WriterRejectsNonFinitePower) {
  FlightLog log;
  log.samples.resize(2);
  log.samples[1].t = 1.0;
  log.samples[0].power = 100.0;
  try {
    writeCsvLog(log);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sample 1"), std::string::npos) << e.what();
  }
}

TEST(WaypointPath, HeaderCommentsSeparatorsAndCrlf) {
  const auto w = readWaypointPath(sourcePath("tests/data/good/path_lawnmower.txt"));
  ASSERT_EQ(w.size(), 8u);
  EXPECT_EQ(w[2], Eigen::Vector3d(160, 0, 15));
  EXPECT_EQ(w[4], Eigen::Vector3d(0, 25, 15));   // spaces
  EXPECT_EQ(w[5], Eigen::Vector3d(0, 50, 15));   // tabs and CR LF
  EXPECT_THROW(parseWaypointPath("0 0 0\n", "one.txt"), std::runtime_error);
  EXPECT_THROW(parseWaypointPath("0 0 0\n1 2 nan\n", "nan.txt"), std::runtime_error);
  EXPECT_THROW(readWaypointPath(sourcePath("tests/data/bad/does_not_exist.txt")), std::runtime_error);
}

TEST(WaypointPath, LegsShorterThanOneCentimetreAreRefusedNamingTheLine) {
  // Issue 20: 200,000 legs of 1 mm simulated as 200,000 stops and turns (a 985 MB log).
  try {
    parseWaypointPath("0 0 15\n10 0 15\n10.001 0 15\n", "tiny.txt");
    FAIL() << "a 1 mm leg was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("tiny.txt:3: waypoint '10.001 0 15' is 0.001 m from the previous one"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(parseWaypointPath("0 0 15\n10 0 15\n10.02 0 15\n", "ok.txt").size(), 3u);
}
