// predict's notes on what a .plan says it was written for (firmwareType, vehicleType) against the
// vehicle that flies it.
#include <gtest/gtest.h>

#include <string>

#include "flight_test_util.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/mission/predict.hpp"

using namespace wattswath::mission;
using wattswath::mission::testing::localMission;

namespace {

// The notes of `m` predicted for the IRIS vehicle flown by `ap`, joined one per line.
std::string notesOf(const Mission& m, const AutopilotConfig& ap) {
  const wattswath::energy::Vehicle v =
      wattswath::energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json");
  const wattswath::energy::EnergyModel model = wattswath::energy::buildModel(v, {"hover", "kinetic"});
  std::string all;
  for (const std::string& w : predictMission(m, v, model, ap, PredictSettings{}).warnings) all += w + "\n";
  return all;
}

AutopilotConfig px4() {
  AutopilotConfig a;
  a.family = AutopilotFamily::PX4;
  a.firmware = "PX4";
  a.version = "1.15";
  return a;
}

}  // namespace

TEST(PredictNotes, APlanWrittenForTheOtherFirmwareSaysSoAndWhichFirmwareFliesIt) {
  Mission m = localMission({{100, 0, 10}});
  m.source = "survey.plan";
  m.firmware_type = 3;  // ArduPilot
  m.vehicle_type = 2;
  EXPECT_EQ(notesOf(m, AutopilotConfig{}).find("was written for"), std::string::npos);
  const std::string on_px4 = notesOf(m, px4());
  EXPECT_NE(on_px4.find("survey.plan: the .plan was written for ArduPilot (firmwareType 3) and is predicted as the "
                        "vehicle's PX4 1.15 flies it"),
            std::string::npos)
      << on_px4;
  m.firmware_type = 12;  // PX4
  EXPECT_EQ(notesOf(m, px4()).find("was written for"), std::string::npos);
  EXPECT_NE(notesOf(m, AutopilotConfig{}).find("was written for PX4 (firmwareType 12) and is predicted as the vehicle's "
                                               "ArduCopter 4.5 flies it"),
            std::string::npos);
  m.firmware_type = 0;  // a WPL file or a generic .plan says nothing
  EXPECT_EQ(notesOf(m, px4()).find("was written for"), std::string::npos);
}

TEST(PredictNotes, APlanWrittenForAFixedWingOrVtolIsFlownAsTheMulticopterAndSaysSo) {
  Mission m = localMission({{100, 0, 10}});
  m.source = "plane.plan";
  m.firmware_type = 3;
  for (int rotary : {0, 2, 13, 14}) {
    m.vehicle_type = rotary;
    EXPECT_EQ(notesOf(m, AutopilotConfig{}).find("was written for"), std::string::npos) << rotary;
  }
  m.vehicle_type = 1;
  EXPECT_NE(notesOf(m, AutopilotConfig{}).find("plane.plan: the .plan was written for a fixed-wing aircraft (vehicleType "
                                               "1); it is predicted as the vehicle file's multicopter flies it"),
            std::string::npos);
  m.vehicle_type = 20;
  EXPECT_NE(notesOf(m, AutopilotConfig{}).find("a VTOL aircraft (vehicleType 20)"), std::string::npos);
}
