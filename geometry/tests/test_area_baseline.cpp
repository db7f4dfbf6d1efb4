// Every bundled area file reads to the area, perimeter, regions, holes and vertex count that the
// hand-written GeoJSON / KML / WKT readers gave before the formats moved to GDAL/OGR (issue 21):
// recorded with `wattswath area info FILE --json` at commit 67e601f, compared to 1e-6 relative.
#include <string>

#include <gtest/gtest.h>

#include "test_util.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace geo = wattswath::geometry;
using wattswath::test::sourcePath;

namespace {

struct Recorded {
  const char* file;     ///< relative to the source folder
  double area_m2;       ///< [m^2]
  double perimeter_m;   ///< [m]
  size_t regions, holes, vertices;
};

size_t holesOf(const geo::SurveyArea& a) {
  size_t n = 0;
  for (const auto& r : a.regions) n += r.holes.size();
  return n;
}

size_t verticesOf(const geo::SurveyArea& a) {
  size_t n = 0;
  for (const auto& r : a.regions) {
    n += r.outer.size();
    for (const auto& h : r.holes) n += h.size();
  }
  return n;
}

}  // namespace

TEST(AreaBaseline, BundledAreasReadAsBeforeGdal) {
  const Recorded recorded[] = {
      {"data/areas/espiral_rectangle.geojson", 29365.507966843274, 736.6253935455131, 1, 0, 4},
      {"data/areas/iris_area.geojson", 20940.90726144292, 709.776596019082, 1, 1, 15},
      {"tests/data/areas/field.kml", 32858.40149538124, 1025.8766794497246, 1, 2, 12},
      {"tests/data/areas/field.waypoints", 35048.95218068604, 759.90904200773, 1, 0, 4},
      {"tests/data/areas/field.wkt", 33646.99409302406, 911.8908504252522, 1, 1, 8},
      {"tests/data/areas/field_metres.wkt", 7500.0, 500.0, 2, 0, 8},
      {"tests/data/areas/multi_nofly.geojson", 41620.6967218937, 1329.8425134852564, 2, 1, 12},
      {"tests/data/areas/nofly_all.wkt", 140195.80858274736, 1519.818083489019, 1, 0, 4},
      {"tests/data/areas/nofly_inside.waypoints", 788.6116086790244, 113.98696470617931, 1, 0, 4},
      {"tests/data/areas/nofly_partial.geojson", 19714.61124721403, 569.9267114858118, 1, 0, 4},
      {"tests/data/areas/square_hole.geojson", 33646.99409302406, 911.8908504252522, 1, 1, 8},
      {"tests/data/good/geo_hole_touching_border.geojson", 32858.35466004684, 1048.194672833852, 1, 1, 7},
  };
  for (const auto& r : recorded) {
    geo::ReadOptions o;
    if (std::string(r.file).find("metres") != std::string::npos) o.wkt_units = geo::WktUnits::Metres;
    const geo::SurveyArea a = geo::readSurveyArea(sourcePath(r.file), o);
    EXPECT_NEAR(a.area(), r.area_m2, 1e-6 * r.area_m2) << r.file;
    EXPECT_NEAR(a.perimeter(), r.perimeter_m, 1e-6 * r.perimeter_m) << r.file;
    EXPECT_EQ(a.regions.size(), r.regions) << r.file;
    EXPECT_EQ(holesOf(a), r.holes) << r.file;
    EXPECT_EQ(verticesOf(a), r.vertices) << r.file;
  }
}
