// Vehicle files: loading, validation and clear errors.
#include <gtest/gtest.h>

#include <stdexcept>

#include "test_util.hpp"
#include "wattswath/energy/vehicle.hpp"

using namespace wattswath::energy;

namespace {

std::string irisJson() {
  return R"({"name":"t","mass_kg":1.3,"rotor_count":4,"rotor_diameter_m":0.254,"disk_area_m2":0.2027,
  "motor_efficiency":0.9,"propeller_efficiency":0.65,"drag_area_m2":0.01547,"max_acceleration_mps2":1,
  "max_yaw_rate_radps":2.1,"max_speed_mps":16,"air_density_kgpm3":1.2928,"gravity_mps2":9.81})";
}

std::string errorOf(const std::string& text) {
  try {
    parseVehicle(text, "v.json");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Vehicle, ShippedIrisLoadsWithPaperParameters) {
  const Vehicle v = loadVehicle(wattswath::test::sourcePath("data/vehicles/iris.json"));
  EXPECT_DOUBLE_EQ(v.mass_kg, 1.3);
  EXPECT_EQ(v.rotor_count, 4);
  EXPECT_DOUBLE_EQ(v.disk_area_m2, 0.2027);
  EXPECT_DOUBLE_EQ(v.totalEfficiency(), 0.9 * 0.65);
  EXPECT_DOUBLE_EQ(v.drag_area_m2, 0.01547);
  EXPECT_DOUBLE_EQ(v.air_density_kgpm3, 1.2928);
}

TEST(Vehicle, DiskAreaDefaultsToNPiRSquared) {
  std::string t = irisJson();
  t.replace(t.find("\"disk_area_m2\":0.2027,"), std::string("\"disk_area_m2\":0.2027,").size(), "");
  const Vehicle v = parseVehicle(t, "v.json");
  // Four 10-inch propellers: 4 pi (0.127 m)^2 = 0.2027 m^2, the paper's A.
  EXPECT_NEAR(v.disk_area_m2, 0.2027, 5e-5);
}

TEST(Vehicle, NegativeMassIsRejectedNamingFileFieldAndValue) {
  std::string t = irisJson();
  t.replace(t.find("1.3"), 3, "-2");
  const std::string msg = errorOf(t);
  EXPECT_NE(msg.find("v.json"), std::string::npos) << msg;
  EXPECT_NE(msg.find("mass_kg"), std::string::npos) << msg;
  EXPECT_NE(msg.find("-2"), std::string::npos) << msg;
}

TEST(Vehicle, EfficiencyOutsideUnitIntervalIsRejected) {
  std::string t = irisJson();
  t.replace(t.find("0.65"), 4, "1.5");
  const std::string msg = errorOf(t);
  EXPECT_NE(msg.find("propeller_efficiency"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[0.01, 1]"), std::string::npos) << msg;
}

TEST(Vehicle, MissingFieldIsNamed) {
  std::string t = irisJson();
  t.replace(t.find("\"drag_area_m2\":0.01547,"), std::string("\"drag_area_m2\":0.01547,").size(), "");
  EXPECT_NE(errorOf(t).find("missing field 'drag_area_m2'"), std::string::npos) << errorOf(t);
}

TEST(Vehicle, TypoFieldIsRejected) {
  std::string t = irisJson();
  t.replace(t.find("\"mass_kg\""), 9, "\"mas_kg\"");
  EXPECT_NE(errorOf(t).find("unknown field 'mas_kg'"), std::string::npos) << errorOf(t);
}

TEST(Vehicle, WrongTypeAndBrokenJsonAreRejected) {
  std::string t = irisJson();
  t.replace(t.find("1.3"), 3, "\"heavy\"");
  EXPECT_NE(errorOf(t).find("expected a number"), std::string::npos);
  EXPECT_NE(errorOf("{\"mass_kg\": 1.3").find("not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf("[1,2]").find("JSON object"), std::string::npos);
}

TEST(Vehicle, MissingFileIsNamed) {
  try {
    loadVehicle("/nonexistent/vehicle.json");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/vehicle.json"), std::string::npos);
  }
}

TEST(Vehicle, RoundTripsThroughJson) {
  const Vehicle v = loadVehicle(wattswath::test::sourcePath("data/vehicles/iris.json"));
  const Vehicle w = parseVehicle(vehicleToJson(v), "roundtrip");
  EXPECT_DOUBLE_EQ(v.mass_kg, w.mass_kg);
  EXPECT_DOUBLE_EQ(v.drag_area_m2, w.drag_area_m2);
  EXPECT_EQ(v.name, w.name);
}

std::string withAutopilot(const std::string& autopilot) {
  std::string text = irisJson();
  return text.insert(text.size() - 1, R"(,"autopilot":)" + autopilot);
}

TEST(Vehicle, AutopilotObjectIsKeptRawAndRoundTrips) {
  const std::string autopilot = R"({"firmware":"ArduCopter","version":"4.5.7","parameters":{"WPNAV_SPEED":1000,"ATC_INPUT_TC":0.15}})";
  const Vehicle v = parseVehicle(withAutopilot(autopilot), "v.json");
  // The same JSON, re-serialised compactly with the keys sorted.
  EXPECT_EQ(v.autopilot_json,
            R"({"firmware":"ArduCopter","parameters":{"ATC_INPUT_TC":0.15,"WPNAV_SPEED":1000},"version":"4.5.7"})");
  const Vehicle w = parseVehicle(vehicleToJson(v), "roundtrip");
  EXPECT_EQ(w.autopilot_json, v.autopilot_json);
  EXPECT_TRUE(parseVehicle(irisJson(), "v.json").autopilot_json.empty());
  EXPECT_EQ(vehicleToJson(parseVehicle(irisJson(), "v.json")).find("autopilot"), std::string::npos);
}

TEST(Vehicle, AutopilotMustBeAnObject) {
  for (const std::string bad : {"[1,2]", "\"ArduCopter\"", "null", "3"}) {
    const std::string e = errorOf(withAutopilot(bad));
    EXPECT_NE(e.find("v.json: field 'autopilot' = "), std::string::npos) << e;
    EXPECT_NE(e.find("expected an object"), std::string::npos) << e;
  }
}

TEST(Vehicle, IdealMomentumHoverIsHalfOfMarinsEq4) {
  const Vehicle v = loadVehicle(wattswath::test::sourcePath("data/vehicles/iris.json"));
  EXPECT_NEAR(marinsRotorPowerW(v) / idealHoverPowerW(v), 2.0, 1e-12);
}
