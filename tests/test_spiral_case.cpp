// The spiral-coverage 47 kJ case of Marins, Cabreira & Ferreira (Section V-A, Tables III and IV),
// end to end from ../shared/data/espiral/area__rectangle.waypoints.
#include <gtest/gtest.h>

#include "../apps/spiral_case.hpp"
#include "test_util.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace en = wattswath::energy;
namespace g = wattswath::geometry;
using wattswath::apps::runSpiralCase;
using wattswath::apps::SpiralCaseSettings;
using wattswath::test::sharedData;
using wattswath::test::sourcePath;

namespace {

struct SpiralCase : ::testing::Test {
  en::Vehicle iris = en::loadVehicle(sourcePath("data/vehicles/iris.json"));
  g::PolygonWithHoles area = g::readSurveyArea(sharedData("espiral/area__rectangle.waypoints")).polygon();
};

}  // namespace

TEST_F(SpiralCase, Table3_SpiralCoverageWithin3PercentOf46603J) {
  const auto r = runSpiralCase(area, iris, SpiralCaseSettings::table3(iris));
  // Paper (Table III): 46,603 J modelled. Ours must be within 3 % (issue 4).
  EXPECT_NEAR(r.breakdown.total(), 46603.0, 0.03 * 46603.0);
  EXPECT_NEAR(r.spacing, 21.45, 0.01);
  EXPECT_EQ(r.laps, 3);
  EXPECT_EQ(r.path.legs.size(), 21u);  // 11 straights, 10 curves
  EXPECT_TRUE(g::checkPath(r.path, area).empty());
  EXPECT_GE(r.coverage, 0.99);
  // Component totals of Table III: hover 44,295 J, kinetic 940 J, drag 1,368 J.
  EXPECT_NEAR(r.breakdown.byEffect("hover"), 44295.0, 0.03 * 44295.0);
  EXPECT_NEAR(r.breakdown.byEffect("kinetic"), 940.0, 0.10 * 940.0);
  EXPECT_NEAR(r.breakdown.byEffect("parasitic_drag"), 1368.0, 0.10 * 1368.0);
  // Curves: 1,601 J of hover in Table III (the curve time at 4.4 m/s).
  EXPECT_NEAR(r.breakdown.at("hover", en::Phase::Turn), 1601.0, 0.05 * 1601.0);
}

TEST_F(SpiralCase, Table4_CorrectedVariantAgainstMeasured47329J) {
  const auto base = runSpiralCase(area, iris, SpiralCaseSettings::table3(iris));
  const auto r = runSpiralCase(area, iris, SpiralCaseSettings::table4(iris));
  // Paper (Table IV): 47,556 J modelled with corrected speeds; measured 47,329 J. The paper gives
  // no exact corrected speeds; ours (1.2 m/s^2, 4 m/s curves, 7 m/s under 100 m) must land within
  // 3 % of the measured value and above the Table III variant, as the paper's does.
  EXPECT_NEAR(r.breakdown.total(), 47329.0, 0.03 * 47329.0);
  EXPECT_GT(r.breakdown.total(), base.breakdown.total());
}
