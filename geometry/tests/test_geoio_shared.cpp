// Every survey area in ../shared/data loads: the IRIS+ real-flight area with its no-fly zone and
// the six E-Spiral areas (QGC WPL 110 files, row 0 home, rows 1.. vertices), each to the area it had
// before GDAL read GeoJSON, KML and WKT.
#include <string>

#include <gtest/gtest.h>

#include "test_util.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace geo = wattswath::geometry;
using wattswath::test::sharedData;
using wattswath::test::sourcePath;

TEST(SharedAreas, IrisAreaWithObstacleMatchesBundledGeoJson) {
  geo::ReadOptions o;
  o.no_fly_files = {sharedData("iris-flights/plan__real_flight_obstacles.waypoints")};
  const auto a = geo::readSurveyArea(sharedData("iris-flights/plan__real_flight_area.waypoints"), o);
  ASSERT_EQ(a.regions.size(), 1u);
  EXPECT_EQ(a.polygon().outer.size(), 11u);
  EXPECT_EQ(a.polygon().holes.size(), 1u);
  EXPECT_EQ(a.no_fly.size(), 1u);
  EXPECT_TRUE(a.repairs.empty());
  ASSERT_TRUE(a.home.has_value());
  const auto bundled = geo::readSurveyArea(sourcePath("data/areas/iris_area.geojson"));
  EXPECT_NEAR(a.area(), bundled.area(), 1e-6);
  EXPECT_NEAR(a.area(), 20940.9, 0.1);
  // The hole is exactly the obstacle zone: outer area minus the zone's area.
  EXPECT_NEAR(std::abs(geo::signedArea(a.polygon().outer)) - std::abs(geo::signedArea(a.no_fly[0])), a.area(), 1e-6);
}

TEST(SharedAreas, ESpiralRectangleIs252By118) {
  const auto a = geo::readSurveyArea(sharedData("espiral/area__rectangle.waypoints"));
  const auto& p = a.polygon();
  ASSERT_EQ(p.outer.size(), 4u);  // row 5 is the closing vertex, 0.59 m from row 1
  ASSERT_EQ(a.repairs.size(), 1u);
  EXPECT_NE(a.repairs[0].find("treated as the repeated closing vertex"), std::string::npos);
  // Side lengths: 252 m east-west, 118 m north-south (Cabreira et al. 2018; shared/data/README.md).
  double longest = 0, shortest = 1e9;
  for (size_t i = 0; i < 4; ++i) {
    const double l = (p.outer[(i + 1) % 4] - p.outer[i]).norm();
    longest = std::max(longest, l);
    shortest = std::min(shortest, l);
  }
  EXPECT_NEAR(longest, 252.0, 1.0);
  EXPECT_GT(shortest, 116.0);  // the two short sides are 116.3 m and 117.2 m (not quite a rectangle)
  EXPECT_NEAR(a.bboxMax().x() - a.bboxMin().x(), 252.0, 1.0);
  EXPECT_NEAR(a.bboxMax().y() - a.bboxMin().y(), 118.0, 1.0);
  EXPECT_NEAR(a.area(), 252.0 * 117.0, 300.0);
  const auto bundled = geo::readSurveyArea(sourcePath("data/areas/espiral_rectangle.geojson"));
  EXPECT_NEAR(a.area(), bundled.area(), 1e-6);
}

TEST(SharedAreas, AllESpiralAreasLoad) {
  for (const char* name : {"area__area01", "area__polygon", "area__rectangle", "area__rectangle02", "area__spiral_concave",
                           "area__spiral_polygon"}) {
    const auto a = geo::readSurveyArea(sharedData(std::string("espiral/") + name + ".waypoints"));
    ASSERT_EQ(a.regions.size(), 1u) << name;
    EXPECT_GE(a.polygon().outer.size(), 4u) << name;
    EXPECT_GT(a.area(), 20000.0) << name;
    EXPECT_LT(a.area(), 50000.0) << name;
    EXPECT_TRUE(a.home.has_value()) << name;
  }
}

TEST(SharedAreas, ReadAsBeforeGdal) {
  // Recorded with `wattswath area info FILE --json` at commit 67e601f (before GeoJSON, KML and WKT
  // moved to GDAL/OGR, issue 21); compared to 1e-6 relative.
  struct Recorded {
    const char* file;
    double area_m2, perimeter_m;
  };
  const Recorded recorded[] = {
      {"espiral/area__area01.waypoints", 24634.59217704747, 635.0639277804322},
      {"espiral/area__polygon.waypoints", 42798.372520759425, 769.5554511319102},
      {"espiral/area__rectangle.waypoints", 29365.507966843274, 736.6253935455131},
      {"espiral/area__rectangle02.waypoints", 27688.899493562632, 718.4831213795823},
      {"espiral/area__spiral_concave.waypoints", 42520.19369944556, 802.3425229572551},
      {"espiral/area__spiral_polygon.waypoints", 47509.21132576704, 810.9838773530444},
      {"iris-flights/plan__real_flight_area.waypoints", 21248.338262513415, 639.1005029453582},
      {"iris-flights/plan__real_flight_obstacles.waypoints", 307.43100107380695, 70.67609307412052},
  };
  for (const auto& r : recorded) {
    const auto a = geo::readSurveyArea(sharedData(r.file));
    EXPECT_NEAR(a.area(), r.area_m2, 1e-6 * r.area_m2) << r.file;
    EXPECT_NEAR(a.perimeter(), r.perimeter_m, 1e-6 * r.perimeter_m) << r.file;
  }
}
