// The plan's outputs in GIS tools and ground stations (issue 21): path.geojson converted by GDAL's
// ogr2ogr to Shapefile, GPX and GeoPackage keeps every per-leg field, and the plan's own
// mission.plan reads back as a survey area (its inclusion fence, its no-fly zone a hole).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "test_util.hpp"

using wattswath::test::cliBinary;
using wattswath::test::run;
using wattswath::test::sourcePath;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

/// Plans the bundled IRIS+ area into a temporary folder of the test's own (ctest runs tests in parallel).
fs::path plannedIris(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("wattswath_test_gis_" + name);
  fs::remove_all(d);
  const auto r = run(cliBinary() + " plan " + sourcePath("data/areas/iris_area.geojson") + " --vehicle " +
                     sourcePath("data/vehicles/iris.json") + " --spacing 15 --out " + d.string() + " --no-report 2>&1");
  EXPECT_EQ(r.status, 0) << r.output;
  return d;
}

/// The property names of the first feature of a GeoJSON file.
std::set<std::string> fieldsOf(const fs::path& geojson) {
  const auto j = nlohmann::json::parse(slurp(geojson));
  std::set<std::string> names;
  for (const auto& [k, v] : j.at("features").at(0).at("properties").items()) names.insert(k);
  return names;
}

}  // namespace

TEST(CliGis, PathGeoJsonKeepsEveryFieldThroughShapefileGpxAndGeoPackage) {
  const fs::path out = plannedIris("fields");
  const fs::path path = out / "path.geojson";
  const auto fields = fieldsOf(path);
  for (const char* k : {"leg", "role", "kind", "altitude_m", "length_m", "speed_mps", "energy_j", "time_s"}) {
    EXPECT_EQ(fields.count(k), 1u) << k;
  }
  const fs::path d = out / "gis";
  fs::create_directories(d);
  struct Case {
    const char* file;
    const char* args;
    const char* prefix;  ///< what GDAL puts before an extension field's name when reading it back
    const char* layer;   ///< the layer holding the legs
  };
  for (const Case& c : {Case{"legs.shp", "-f 'ESRI Shapefile'", "", "legs"}, Case{"legs.gpkg", "-f GPKG", "", "path"},
                        Case{"legs.gpx", "-f GPX -dsco GPX_USE_EXTENSIONS=YES -nlt LINESTRING", "ogr_", "routes"}}) {
    SCOPED_TRACE(c.file);
    const fs::path converted = d / c.file;
    const fs::path back = d / (std::string(c.file) + ".geojson");
    ASSERT_EQ(run("ogr2ogr " + std::string(c.args) + " '" + converted.string() + "' '" + path.string() + "' 2>&1").status, 0);
    ASSERT_EQ(run("ogr2ogr -f GeoJSON '" + back.string() + "' '" + converted.string() + "' " + c.layer + " 2>&1").status, 0);
    const auto got = fieldsOf(back);
    for (const auto& f : fields) EXPECT_TRUE(got.count(f) || got.count(c.prefix + f)) << f << " dropped";
  }
}

TEST(CliGis, GpkgHoldsTheLegsAndTheAreaAsLayers) {
  const fs::path d = fs::temp_directory_path() / "wattswath_test_gis_gpkg";
  fs::remove_all(d);
  const auto r = run(cliBinary() + " plan " + sourcePath("data/areas/iris_area.geojson") + " --vehicle " +
                     sourcePath("data/vehicles/iris.json") + " --spacing 15 --out " + d.string() + " --gpkg --no-report 2>&1");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto path = nlohmann::json::parse(slurp(d / "path.geojson"));
  for (const char* layer : {"legs", "area"}) {
    const fs::path back = d / (std::string(layer) + ".geojson");
    ASSERT_EQ(run("ogr2ogr -f GeoJSON '" + back.string() + "' '" + (d / "plan.gpkg").string() + "' " + layer + " 2>&1").status, 0)
        << layer;
    const auto j = nlohmann::json::parse(slurp(back));
    if (std::string(layer) == "legs") {
      EXPECT_EQ(j.at("features").size(), path.at("features").size());  // one feature per leg, as path.geojson
    } else {
      EXPECT_EQ(j.at("features").size(), 2u);  // the area (its hole) and home
    }
  }
  // The area layer reads back as the survey area.
  const auto info = run(cliBinary() + " area info " + (d / "plan.gpkg").string() + " --layer area --json 2>/dev/null");
  ASSERT_EQ(info.status, 0) << info.output;
  EXPECT_EQ(nlohmann::json::parse(info.output).at("holes"), 1);
  // Without --force an existing plan.gpkg is refused before any work (the other outputs removed).
  for (const char* f : {"mission.plan", "mission.waypoints", "path.geojson", "legs.csv"}) fs::remove(d / f);
  const auto again = run(cliBinary() + " plan " + sourcePath("data/areas/iris_area.geojson") + " --vehicle " +
                         sourcePath("data/vehicles/iris.json") + " --spacing 15 --out " + d.string() + " --gpkg --no-report 2>&1");
  EXPECT_NE(again.status, 0);
  EXPECT_NE(again.output.find("plan.gpkg: already exists; use --force"), std::string::npos) << again.output;
}

TEST(CliGis, OwnMissionPlanReadsBackAsTheFencedArea) {
  const auto area = run(cliBinary() + " area info " + sourcePath("data/areas/iris_area.geojson") + " --json 2>/dev/null");
  const auto plan = run(cliBinary() + " area info " + (plannedIris("plan") / "mission.plan").string() + " --json 2>/dev/null");
  ASSERT_EQ(plan.status, 0) << plan.output;
  const auto a = nlohmann::json::parse(area.output);
  const auto p = nlohmann::json::parse(plan.output);
  EXPECT_EQ(p.at("holes"), 1);  // the no-fly zone, from the geofence's exclusion polygon
  // The inclusion fence lies the no-fly margin outside the area, so the area read back is larger.
  EXPECT_GT(p.at("area_m2").get<double>(), a.at("area_m2").get<double>());
  EXPECT_LT(p.at("area_m2").get<double>(), 1.5 * a.at("area_m2").get<double>());
  EXPECT_FALSE(p.at("home").is_null());
}
