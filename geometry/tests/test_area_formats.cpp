// Survey areas in the formats survey crews bring: every vector format GDAL reads (each made here
// with ogr2ogr from the bundled IRIS+ area, data/areas/iris_area.geojson), a GeoJSON in UTM metres,
// QGroundControl .plan files (survey polygon, geofence inclusion / exclusion polygons and
// circles, planned home) and Mission Planner .poly; and the hostile inputs of issue 20 that
// reach the area readers (deep nesting, GeometryCollection bombs, many CDATA sections, size).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "area_test_util.hpp"
#include "test_util.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace geo = wattswath::geometry;
namespace fs = std::filesystem;
using wattswath::test::errorOf;
using wattswath::test::sourcePath;

namespace {

const std::string kIris = sourcePath("data/areas/iris_area.geojson");

/// A fresh temporary folder for one test's files.
fs::path tempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("wattswath_area_formats_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

/// Runs ogr2ogr (GDAL's own converter): `args` then destination, source.
void ogr2ogr(const std::string& args, const fs::path& dst, const std::string& src) {
  const std::string cmd = "ogr2ogr " + args + " '" + dst.string() + "' '" + src + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

void writeFile(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// Every outer and hole vertex of `a` lies within `tol` [m] of a vertex of the same ring of `b`
/// (rings may start elsewhere or run the other way in the file: the reader orients them).
void expectSamePolygon(const geo::SurveyArea& a, const geo::SurveyArea& b, double tol) {
  ASSERT_EQ(a.regions.size(), b.regions.size());
  const auto& pa = a.regions.front();
  const auto& pb = b.regions.front();
  ASSERT_EQ(pa.holes.size(), pb.holes.size());
  auto near = [&](const geo::Ring& ra, const geo::Ring& rb) {
    ASSERT_EQ(ra.size(), rb.size());
    for (const auto& p : ra) {
      double best = 1e300;
      for (const auto& q : rb) best = std::min(best, (p - q).norm());
      EXPECT_LT(best, tol);
    }
  };
  near(pa.outer, pb.outer);
  for (size_t k = 0; k < pa.holes.size(); ++k) near(pa.holes[k], pb.holes[k]);
}

struct Conversion {
  const char* name;  ///< test label and file name
  const char* args;  ///< ogr2ogr options
};

}  // namespace

TEST(AreaFormats, EveryGdalFormatGivesTheGeoJsonArea) {
  const geo::SurveyArea ref = geo::readSurveyArea(kIris);
  const fs::path d = tempDir("gdal");
  // Only the area feature goes into formats that hold one geometry type per layer.
  const Conversion conversions[] = {
      {"iris.gpkg", "-f GPKG"},
      {"iris.shp", "-f 'ESRI Shapefile' -where \"role = 'area'\""},
      {"iris.kmz", "-f LIBKML"},
      {"iris.gml", "-f GML"},
      {"iris.csv", "-f CSV -lco GEOMETRY=AS_WKT -where \"role = 'area'\""},
      {"iris.fgb", "-f FlatGeobuf -where \"role = 'area'\""},
      {"iris_utm32n.geojson", "-f GeoJSON -t_srs EPSG:32632"},
      {"iris_etrs89_laea.gpkg", "-f GPKG -t_srs EPSG:3035"},
      {"iris.gpx", "-f GPX -dsco GPX_USE_EXTENSIONS=YES -nlt MULTILINESTRING -where \"role = 'area'\""},
  };
  for (const auto& c : conversions) {
    SCOPED_TRACE(c.name);
    const fs::path out = d / c.name;
    ogr2ogr(c.args, out, kIris);
    const geo::SurveyArea a = geo::readSurveyArea(out.string());
    EXPECT_NEAR(a.area() / ref.area(), 1.0, 1e-6) << a.area() << " m^2 vs " << ref.area();
    expectSamePolygon(a, ref, 0.01);
  }
  fs::remove_all(d);
}

TEST(AreaFormats, LayerAndWhereChooseFeatures) {
  const fs::path d = tempDir("layer");
  const fs::path gpkg = d / "two.gpkg";
  ogr2ogr("-f GPKG -nln fields", gpkg, kIris);
  ogr2ogr("-f GPKG -update -nln other -where \"role = 'area'\"", gpkg, kIris);
  geo::ReadOptions o;
  o.layer = "fields";
  o.where = "role = 'area'";
  const geo::SurveyArea a = geo::readSurveyArea(gpkg.string(), o);
  EXPECT_FALSE(a.home.has_value());  // the home point was filtered out
  o.where = "role = 'nothing'";  // said to match nothing (it read "no polygon found")
  EXPECT_NE(errorOf(gpkg.string(), o).find("--where \"role = 'nothing'\" matched no feature of layer \"fields\""),
            std::string::npos)
      << errorOf(gpkg.string(), o);
  o.layer = "missing";
  const std::string e = errorOf(gpkg.string(), o);
  EXPECT_NE(e.find("no layer named \"missing\" (--layer); the file has: fields, other"), std::string::npos) << e;
  o.layer = "fields";
  o.where = "no_such_field = 1";
  const std::string filter = errorOf(gpkg.string(), o);
  EXPECT_NE(filter.find("no_such_field = 1\" is not a valid OGR SQL filter"), std::string::npos) << filter;
  fs::remove_all(d);
}

// --layer / --where choose the area; the file's no-fly zones (here in a layer "nofly", whose feature
// the filter does not match) and a no-fly file are read whole: the zone was dropped unsaid, and a
// no-fly file was filtered too (failing on a layer it does not have).
TEST(AreaFormats, LayerAndWhereChooseTheAreaNotTheNoFlyZones) {
  const fs::path d = tempDir("layer_nofly");
  const fs::path gpkg = d / "fields.gpkg", zone = d / "zone.geojson";
  writeFile(zone, R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"role":"no_fly","name":"Mast"},
    "geometry":{"type":"Polygon","coordinates":[[[10.46140,43.71540],[10.46150,43.71540],[10.46150,43.71548],[10.46140,43.71548],[10.46140,43.71540]]]}}]})");
  ogr2ogr("-f GPKG -nln fields", gpkg, kIris);
  ogr2ogr("-f GPKG -update -nln nofly", gpkg, zone.string());
  geo::ReadOptions o;
  o.layer = "fields";
  o.where = "role = 'area'";
  const geo::SurveyArea a = geo::readSurveyArea(gpkg.string(), o);
  EXPECT_EQ(a.no_fly.size(), 1U);
  std::string notes;
  for (const auto& n : a.repairs) notes += n + "\n";
  EXPECT_NE(notes.find("no-fly zone(s) read from the whole file"), std::string::npos) << notes;
  // A no-fly file without the area's layer is read whole.
  o.no_fly_files = {zone.string()};
  EXPECT_NO_THROW(geo::readSurveyArea(gpkg.string(), o));
  fs::remove_all(d);
}

// Google Earth: a placemark in a folder named "No-fly zones" is a no-fly zone whatever its own name
// (it was a second area part, "area polygons 0 and 1 overlap"); a drawn path (an open LineString) is
// no area outline and is left out with a note (it was closed into a triangle).
TEST(AreaFormats, GoogleEarthFoldersAndPaths) {
  const auto folder = geo::readSurveyArea(sourcePath("tests/data/areas/ge_folder_nofly.kml"));
  ASSERT_EQ(folder.regions.size(), 1U);
  EXPECT_EQ(folder.regions.front().holes.size(), 2U);
  const auto path = geo::readSurveyArea(sourcePath("tests/data/areas/ge_with_path.kml"));
  ASSERT_EQ(path.regions.size(), 1U);
  std::string notes;
  for (const auto& n : path.repairs) notes += n + "\n";
  EXPECT_NE(notes.find("an open line (its ends 321 m apart, 803 m long) is a drawn path, not an area outline; ignored"),
            std::string::npos)
      << notes;
  // A GPX route of four corners that does not repeat the first is an outline planned: closed.
  const fs::path d = tempDir("gpx_route");
  writeFile(d / "route.gpx", R"(<?xml version="1.0"?><gpx version="1.1" creator="test" xmlns="http://www.topografix.com/GPX/1/1"><rte>
    <rtept lat="43.7150" lon="10.4600"/><rtept lat="43.7150" lon="10.4620"/><rtept lat="43.7160" lon="10.4620"/><rtept lat="43.7160" lon="10.4600"/>
  </rte></gpx>)");
  EXPECT_EQ(geo::readSurveyArea((d / "route.gpx").string()).regions.size(), 1U);
  fs::remove_all(d);
}

// A plan's GeoPackage (plan --gpkg) holds its legs as lines beside the area: read back without
// --layer, the area is read and the line layer skipped with a note naming it (it failed on the lines).
TEST(AreaFormats, AGeoPackageWithALineLayerBesideTheAreaReadsTheArea) {
  const geo::SurveyArea ref = geo::readSurveyArea(kIris);
  const fs::path d = tempDir("lines");
  const fs::path gpkg = d / "plan.gpkg";
  ogr2ogr("-f GPKG -nln legs -nlt MULTILINESTRING -where \"role = 'area'\"", gpkg, kIris);
  ogr2ogr("-f GPKG -update -nln area", gpkg, kIris);
  const geo::SurveyArea a = geo::readSurveyArea(gpkg.string());
  expectSamePolygon(a, ref, 0.01);
  std::string notes;
  for (const auto& n : a.repairs) notes += n + "\n";
  EXPECT_NE(notes.find("layer \"legs\" skipped: it holds lines"), std::string::npos) << notes;
  geo::ReadOptions o;
  o.layer = "legs";  // asked for by name, its lines are read as closed rings
  const geo::SurveyArea legs = geo::readSurveyArea(gpkg.string(), o);
  notes.clear();
  for (const auto& n : legs.repairs) notes += n + "\n";
  EXPECT_NE(notes.find("lines read as closed rings"), std::string::npos) << notes;
  fs::remove_all(d);
}

TEST(AreaFormats, UtmGeoJsonIsReprojectedNotCalledSwapped) {
  const fs::path d = tempDir("utm");
  const fs::path utm = d / "utm.geojson";
  ogr2ogr("-f GeoJSON -t_srs EPSG:32632", utm, kIris);
  const geo::SurveyArea a = geo::readSurveyArea(utm.string());
  EXPECT_TRUE(a.home.has_value());  // the home point came through GDAL too
  EXPECT_NEAR(a.area(), geo::readSurveyArea(kIris).area(), 1e-3);
  fs::remove_all(d);
}

TEST(AreaFormats, MetresWithoutACrsAreCalledMetresNotSwapped) {
  const std::string text = R"({"type":"Polygon","coordinates":[[[612000,4841000],[612100,4841000],[612100,4841100],[612000,4841000]]]})";
  try {
    geo::parseSurveyArea(text, "utm_no_crs.geojson");
    FAIL() << "accepted";
  } catch (const geo::SurveyAreaError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("feature 0, outer boundary, vertex 0: (612000.000000, 4841000.000000) is not lon/lat in degrees; it looks "
                     "like projected metres"), std::string::npos) << m;
    EXPECT_EQ(m.find("swapped"), std::string::npos) << m;
  }
}

TEST(AreaFormats, NoFlyByNameInGdalFormatsAndGeoJson) {
  const fs::path d = tempDir("nofly");
  const std::string gj = R"({"type":"FeatureCollection","features":[
 {"type":"Feature","properties":{"name":"field"},"geometry":{"type":"Polygon","coordinates":[[[10.0,43.0],[10.002,43.0],[10.002,43.002],[10.0,43.002],[10.0,43.0]]]}},
 {"type":"Feature","properties":{"name":"No-fly zone: tower"},"geometry":{"type":"Polygon","coordinates":[[[10.0005,43.0005],[10.001,43.0005],[10.001,43.001],[10.0005,43.001],[10.0005,43.0005]]]}}]})";
  writeFile(d / "named.geojson", gj);
  const geo::SurveyArea a = geo::readSurveyArea((d / "named.geojson").string());
  ASSERT_EQ(a.regions.size(), 1U);
  EXPECT_EQ(a.regions.front().holes.size(), 1U);  // named "No-fly zone" is a zone, not surveyed
  ogr2ogr("-f GPKG", d / "named.gpkg", (d / "named.geojson").string());
  const geo::SurveyArea b = geo::readSurveyArea((d / "named.gpkg").string());
  EXPECT_EQ(b.regions.front().holes.size(), 1U);
  EXPECT_NEAR(a.area(), b.area(), 1e-6 * a.area());
  fs::remove_all(d);
}

TEST(AreaFormats, OtherExtensionsGoToGdalUnclaimedTextDoesNot) {
  const fs::path d = tempDir("unknown_ext");
  ogr2ogr("-f GPKG", d / "field.gpkg", kIris);
  fs::copy_file(d / "field.gpkg", d / "field.dat");
  EXPECT_NEAR(geo::readSurveyArea((d / "field.dat").string()).area(), geo::readSurveyArea(kIris).area(), 1e-6);
  // Text in memory without an extension GDAL could own (.txt, none) that no reader of ours claims
  // is not handed to GDAL's drivers (the fuzz target's inputs).
  try {
    geo::parseSurveyArea("garbage", "mystery.txt");
    FAIL() << "accepted";
  } catch (const geo::SurveyAreaError& e) {
    EXPECT_NE(std::string(e.what()).find("mystery.txt: unknown survey area format"), std::string::npos) << e.what();
  }
  fs::remove_all(d);
}

TEST(AreaFormats, UnreadableFileNamesTheFormatsExpected) {
  const fs::path d = tempDir("unreadable");
  writeFile(d / "area.shp", "not a shapefile");
  const std::string e = errorOf((d / "area.shp").string());
  EXPECT_NE(e.find("area.shp: not a survey area file wattswath or GDAL can read"), std::string::npos) << e;
  EXPECT_NE(e.find("Shapefile, GeoPackage"), std::string::npos) << e;
  fs::remove_all(d);
}

// ------------------------------------------------------------ QGroundControl .plan
namespace {
/// A QGC plan as QGroundControl 4 writes it: a survey item, fences, a planned home.
std::string qgcPlan(const std::string& items, const std::string& polygons, const std::string& circles) {
  return R"({"fileType":"Plan","groundStation":"QGroundControl","version":1,
 "mission":{"cruiseSpeed":15,"firmwareType":3,"hoverSpeed":5,"vehicleType":2,"version":2,
   "plannedHomePosition":[43.0,10.0,50],"items":[)" + items + R"(]},
 "geoFence":{"version":2,"polygons":[)" + polygons + R"(],"circles":[)" + circles + R"(]},
 "rallyPoints":{"points":[],"version":2}})";
}
const std::string kSurvey = R"({"type":"ComplexItem","complexItemType":"survey","version":5,
  "polygon":[[43.0,10.0],[43.0,10.002],[43.002,10.002],[43.002,10.0]]})";
const std::string kExclusion = R"({"inclusion":false,"version":1,
  "polygon":[[43.0005,10.0005],[43.0005,10.001],[43.001,10.001],[43.001,10.0005]]})";
}  // namespace

TEST(AreaFormats, QgcPlanSurveyPolygonWithExclusionFenceAndHome) {
  const fs::path d = tempDir("plan");
  writeFile(d / "survey.plan", qgcPlan(kSurvey, kExclusion, ""));
  const geo::SurveyArea a = geo::readSurveyArea((d / "survey.plan").string());
  ASSERT_EQ(a.regions.size(), 1U);
  EXPECT_EQ(a.regions.front().holes.size(), 1U);
  ASSERT_TRUE(a.home.has_value());
  EXPECT_NEAR(*a.home_alt_m, 50.0, 1e-12);
  // 0.002 deg x 0.002 deg at 43 N (about 162.9 m x 222.3 m) minus a quarter-size square.
  EXPECT_NEAR(a.area(), (1.0 - 0.0625) * 162.9 * 222.3, 0.01 * 162.9 * 222.3);
  fs::remove_all(d);
}

TEST(AreaFormats, QgcPlanInclusionFenceIsTheAreaAndCirclesArePolygons) {
  const fs::path d = tempDir("plan_circle");
  const std::string inclusion = R"({"inclusion":true,"version":1,
    "polygon":[[43.0,10.0],[43.0,10.002],[43.002,10.002],[43.002,10.0]]})";
  const std::string circle = R"({"inclusion":false,"version":1,"circle":{"center":[43.001,10.001],"radius":20}})";
  writeFile(d / "fence.plan", qgcPlan("", inclusion, circle));
  const geo::SurveyArea a = geo::readSurveyArea((d / "fence.plan").string());
  ASSERT_EQ(a.regions.front().holes.size(), 1U);
  EXPECT_EQ(a.regions.front().outer.size(), 4U);
  // The no-fly circle's polygon is circumscribed within 5 cm: its area lies between pi r^2 and
  // pi (r + 0.05)^2 (inscribed, it left up to 5 cm of the zone outside the polygon).
  EXPECT_GE(a.regions.front().holes.front().size(), 16U);
  const double full = [&] {
    writeFile(d / "no_circle.plan", qgcPlan("", inclusion, ""));
    return geo::readSurveyArea((d / "no_circle.plan").string()).area();
  }();
  const double cut = full - a.area();
  EXPECT_GE(cut, M_PI * 20.0 * 20.0);
  EXPECT_LE(cut, M_PI * 20.05 * 20.05);
  fs::remove_all(d);
}

// A survey that reaches outside the plan's own inclusion fence would fly into the fence: refused,
// naming where (the fence was dropped with a note and the mission flew 80 m past it). A fence around
// the survey, or drawn on it, holds it.
TEST(AreaFormats, ASurveyOutsideThePlansInclusionFenceIsRefused) {
  const fs::path d = tempDir("plan_fence");
  const auto fence = [](double lat_max, double lon_max) {
    char buf[200];
    std::snprintf(buf, sizeof buf, R"({"inclusion":true,"version":1,"polygon":[[42.9999,9.9999],[42.9999,%.4f],[%.4f,%.4f],[%.4f,9.9999]]})",
                  lon_max, lat_max, lon_max, lat_max);
    return std::string(buf);
  };
  writeFile(d / "small.plan", qgcPlan(kSurvey, fence(43.0012, 10.0021), ""));
  EXPECT_NE(errorOf((d / "small.plan").string()).find("polygon reaches outside the plan's inclusion geofence (at 43.0012400, 10.0020000, on the edge after vertex 1)"),
            std::string::npos)
      << errorOf((d / "small.plan").string());
  writeFile(d / "around.plan", qgcPlan(kSurvey, fence(43.0021, 10.0021), ""));
  EXPECT_NO_THROW(geo::readSurveyArea((d / "around.plan").string()));
  const std::string on = R"({"inclusion":true,"version":1,"polygon":[[43.0,10.0],[43.0,10.002],[43.002,10.002],[43.002,10.0]]})";
  writeFile(d / "on.plan", qgcPlan(kSurvey, on, ""));
  EXPECT_NO_THROW(geo::readSurveyArea((d / "on.plan").string()));
  fs::remove_all(d);
}

TEST(AreaFormats, QgcPlanErrorsNameTheField) {
  const fs::path d = tempDir("plan_bad");
  writeFile(d / "lonlat.plan", qgcPlan(R"({"type":"ComplexItem","complexItemType":"survey","polygon":[[43.0,"x"]]})", "", ""));
  EXPECT_NE(errorOf((d / "lonlat.plan").string()).find("mission item 0 (survey), polygon, vertex 0: expected a position [lat, lon]"),
            std::string::npos);
  // A fence of version 1 (or none) is not read, as QGroundControl's GeoFenceController::load reads
  // none, and the rest of the plan is: a survey is the area, with a note (it refused the plan).
  // A fence without a version is refused, as QGroundControl refuses it (version is a required key).
  writeFile(d / "noversion.plan", R"({"fileType":"Plan","geoFence":{"polygons":[]}})");
  EXPECT_NE(errorOf((d / "noversion.plan").string()).find("geoFence version null is not supported"), std::string::npos)
      << errorOf((d / "noversion.plan").string());
  writeFile(d / "v1.plan", R"({"fileType":"Plan","geoFence":{"version":1,"polygon":[]}})");
  EXPECT_NE(errorOf((d / "v1.plan").string()).find("no polygon found"), std::string::npos);
  writeFile(d / "v1_survey.plan", R"({"fileType":"Plan","geoFence":{"version":1,"polygon":[]},"mission":{"items":[)" + kSurvey + "]}}");
  const auto v1 = geo::readSurveyArea((d / "v1_survey.plan").string());
  std::string v1_notes;
  for (const auto& n : v1.repairs) v1_notes += n + "\n";
  EXPECT_NE(v1_notes.find("geoFence version 1: its fences are not read"), std::string::npos) << v1_notes;
  // Overlapping area parts are named (it said "area polygons 0 and 1 overlap").
  const std::string a = R"({"inclusion":true,"version":1,"polygon":[[43.0,10.0],[43.0,10.002],[43.002,10.002],[43.002,10.0]]})";
  const std::string b = R"({"inclusion":true,"version":1,"polygon":[[43.001,10.001],[43.001,10.003],[43.003,10.003],[43.003,10.001]]})";
  writeFile(d / "overlap.plan", qgcPlan("", a + "," + b, ""));
  EXPECT_NE(errorOf((d / "overlap.plan").string()).find("geoFence.polygons[0] and geoFence.polygons[1] overlap"), std::string::npos)
      << errorOf((d / "overlap.plan").string());
  writeFile(d / "radius.plan", qgcPlan(kSurvey, "", R"({"inclusion":false,"circle":{"center":[43.001,10.001],"radius":-3}})"));
  EXPECT_NE(errorOf((d / "radius.plan").string()).find("geoFence.circles[0]: radius -3"), std::string::npos);
  fs::remove_all(d);
}

TEST(AreaFormats, QgcSurveyFixtureReadsItsPolygon) {
  // tests/data/good/mission_survey.plan is a survey written by QGroundControl itself.
  const geo::SurveyArea a = geo::readSurveyArea(sourcePath("tests/data/good/mission_survey.plan"));
  EXPECT_GT(a.area(), 1000.0);
  EXPECT_TRUE(a.home.has_value());
}

TEST(AreaFormats, MissionPlannerPoly) {
  const fs::path d = tempDir("poly");
  writeFile(d / "field.poly",
            "#saved by Mission Planner 1.3.80\n43.0 10.0\n43.0 10.002\n43.002 10.002\n43.002 10.0\n43.0 10.0\n");
  const geo::SurveyArea a = geo::readSurveyArea((d / "field.poly").string());
  EXPECT_EQ(a.regions.front().outer.size(), 4U);  // the repeated first vertex is the closing one
  EXPECT_NEAR(a.area(), 162.9 * 222.3, 0.01 * 162.9 * 222.3);
  writeFile(d / "bad.poly", "#saved by Mission Planner\n43.0 10.0\n43.0 ten\n");
  EXPECT_NE(errorOf((d / "bad.poly").string()).find("bad.poly: line 3: expected \"latitude longitude\""), std::string::npos);
  fs::remove_all(d);
}

// ------------------------------------------------------------ issue 20: hostile area files
TEST(AreaFormats, DeeplyNestedGeoJsonPositionIsRefusedNotACrash) {
  // ~70,000 levels: the message used to be built with a recursive dump() and overflowed the stack.
  const std::string deep = std::string(70000, '[') + std::string(70000, ']');
  const std::string text = R"({"type":"Polygon","coordinates":[[)" + deep + "]]}";
  try {
    geo::parseSurveyArea(text, "deep.geojson");
    FAIL() << "accepted";
  } catch (const geo::SurveyAreaError& e) {
    EXPECT_NE(std::string(e.what()).find("deep.geojson: JSON nested more than 64 levels deep"), std::string::npos) << e.what();
  }
}

TEST(AreaFormats, NestedGeometryCollectionsAreBounded) {
  std::string g = R"({"type":"Polygon","coordinates":[[[10,43],[10.001,43],[10.001,43.001],[10,43]]]})";
  for (int i = 0; i < 5000; ++i) g = R"({"type":"GeometryCollection","geometries":[)" + g + "]}";
  try {
    geo::parseSurveyArea(g, "bomb.geojson");
    FAIL() << "accepted";
  } catch (const geo::SurveyAreaError& e) {
    EXPECT_NE(std::string(e.what()).find("nested more than 64 levels"), std::string::npos) << e.what();
  }
  // Shallow collections still read.
  std::string ok = R"({"type":"Polygon","coordinates":[[[10,43],[10.001,43],[10.001,43.001],[10,43]]]})";
  for (int i = 0; i < 10; ++i) ok = R"({"type":"GeometryCollection","geometries":[)" + ok + "]}";
  EXPECT_GT(geo::parseSurveyArea(ok, "ok.geojson").area(), 1000.0);
}

TEST(AreaFormats, ManyCdataSectionsInOneKmlElementStayLinear) {
  // 200,000 CDATA sections in one <name>: quadratic copying made this take minutes; it is one pass
  // now (a regression makes the test time out under ctest's limit rather than pass slowly).
  std::string cdata;
  for (int i = 0; i < 200000; ++i) cdata += "<![CDATA[x]]>";
  const std::string kml = "<kml><Placemark><name>" + cdata +
                          "</name><Polygon><outerBoundaryIs><LinearRing><coordinates>10,43 10.001,43 10.001,43.001 10,43"
                          "</coordinates></LinearRing></outerBoundaryIs></Polygon></Placemark></kml>";
  EXPECT_GT(geo::parseSurveyArea(kml, "cdata.kml").area(), 1000.0);
}

TEST(AreaFormats, HugeAreaFileGetsASizeErrorNotAnAbort) {
  const fs::path d = tempDir("huge");
  const fs::path big = d / "big.geojson";
  {
    std::ofstream f(big, std::ios::binary);
    f << R"({"type":"Polygon","coordinates":[[)";
    const std::string pad(1 << 20, ' ');
    for (long long written = 0; written <= geo::kMaxAreaFileBytes; written += static_cast<long long>(pad.size())) f << pad;
    f << "]]}";
  }
  const std::string e = errorOf(big.string());
  EXPECT_NE(e.find("area files of at most 67108864 bytes (64 MiB) are read"), std::string::npos) << e;
  fs::remove_all(d);
}
