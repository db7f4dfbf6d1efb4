// GeoJSON, KML and WKT through GDAL/OGR (issue 21): what GDAL accepts silently or reports vaguely
// is still refused naming the file, feature, ring, vertex and value; the pre-checks GDAL cannot
// do safely (XML DOCTYPE / entities, nesting) stay; EWKT's SRID is honoured; GDAL prints nothing.
#include <cstdlib>
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

/// The SurveyAreaError message of parsing `text` as `source` ("" when accepted).
std::string parseError(const std::string& text, const std::string& source, const geo::ReadOptions& o = {}) {
  try {
    geo::parseSurveyArea(text, source, o);
  } catch (const geo::SurveyAreaError& e) {
    return e.what();
  }
  return "";
}

const char* kSquare = "[[7,45],[7.002,45],[7.002,45.002],[7,45.002],[7,45]]";

}  // namespace

TEST(AreaTextGdal, GeoJsonRingGdalDropsIsRefusedWithFeatureRingVertexAndValue) {
  // GDAL reads this polygon without its hole (an error message, then the rest): a silent loss of a
  // hole would send the drone over it.
  const std::string text = std::string(R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[)") + kSquare + R"(]}},
    {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[7.01,45],[7.012,45],[7.012,45.002],[7.01,45]],
      [[7.0105,45.0002],[7.0106,"x"],[7.0107,45.0003],[7.0105,45.0002]]]}}]})";
  const std::string e = parseError(text, "dropped.geojson");
  EXPECT_NE(e.find("dropped.geojson: feature 1: Polygon GDAL cannot read"), std::string::npos) << e;
  EXPECT_NE(e.find("hole 0, vertex 1: expected a position [lon, lat] of numbers, got [7.0106,\"x\"]"), std::string::npos) << e;
}

TEST(AreaTextGdal, GeoJsonFeatureWithoutTypeIsExplainedNotAnAssertion) {
  // fuzz_area: a feature without "type" whose ring GDAL dropped was looked up with the const
  // operator[] of a missing key (an assertion in nlohmann, undefined behaviour in a release build).
  const std::string text = R"({"type":"FeatureCollection","features":[{"tyep":"Featurd","properties":{"role":"no-fly"},
    "geometry":{"type":"Polygon","coordinates":[[[10.0005,43.0005],[10.001,43.0005],[10.001,"x"],[10.0005,43.0005]]]}}]})";
  const std::string e = parseError(text, "untyped.geojson");
  EXPECT_NE(e.find("untyped.geojson: feature 0: Polygon GDAL cannot read"), std::string::npos) << e;
  EXPECT_NE(e.find("outer boundary, vertex 2: expected a position [lon, lat] of numbers, got [10.001,\"x\"]"), std::string::npos) << e;
}

TEST(AreaTextGdal, GeoJsonFeatureWithoutGeometryAndNonAreaTypesAreRefused) {
  std::string e = parseError(R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":null}]})",
                             "null.geojson");
  EXPECT_NE(e.find("null.geojson: feature 0: Feature without geometry"), std::string::npos) << e;
  e = parseError(R"({"type":"Feature","properties":{"role":"area"},"geometry":{"type":"Point","coordinates":[7,45]}})", "pt.geojson");
  EXPECT_NE(e.find("pt.geojson: feature 0: geometry type Point is not an area (expected Polygon, MultiPolygon, or a Point "
                   "with property role \"home\")"), std::string::npos) << e;
}

TEST(AreaTextGdal, KmlDoctypeAndEntitiesAreRefusedBeforeGdal) {
  // "Billion laughs": ten entities of ten references each expand to 10^9 copies.
  std::string ents = "<!DOCTYPE kml [\n<!ENTITY a0 \"lol\">\n";
  for (int i = 1; i < 10; ++i) {
    ents += "<!ENTITY a" + std::to_string(i) + " \"";
    for (int k = 0; k < 10; ++k) ents += "&a" + std::to_string(i - 1) + ";";
    ents += "\">\n";
  }
  const std::string kml = "<?xml version=\"1.0\"?>\n" + ents + "]>\n<kml><Placemark><name>&a9;</name></Placemark></kml>";
  const std::string e = parseError(kml, "laughs.kml");
  EXPECT_NE(e.find("laughs.kml: line 2: \"<!DOCTYPE km...\": a DOCTYPE or entity declaration"), std::string::npos) << e;
}

TEST(AreaTextGdal, KmlNestingAndMismatchedTagsAreNamedByLine) {
  std::string deep = "<kml>\n";
  for (int i = 0; i < 200; ++i) deep += "<MultiGeometry x=\"/>\">";  // a quoted "/>" is not a self-closing tag
  std::string e = parseError(deep, "deep.kml");
  EXPECT_NE(e.find("deep.kml: line 2: XML elements nested more than 64 deep"), std::string::npos) << e;
  e = parseError("<kml>\n<Placemark>\n</Polygon></kml>", "mismatch.kml");
  EXPECT_NE(e.find("mismatch.kml: line 3: closing tag </Polygon> does not match <Placemark>"), std::string::npos) << e;
}

TEST(AreaTextGdal, EwktSridIsReprojectedAndRefusedWithMetres) {
  const fs::path d = fs::temp_directory_path() / "wattswath_area_text_gdal";
  fs::remove_all(d);
  fs::create_directories(d);
  // The IRIS area polygon in UTM 32N as GDAL writes WKT (ogr2ogr to CSV), given its EWKT SRID.
  const std::string iris = sourcePath("data/areas/iris_area.geojson");
  const std::string cmd = "ogr2ogr -f CSV -lco GEOMETRY=AS_WKT -t_srs EPSG:32632 -where \"role = 'area'\" -select role '" +
                          (d / "utm.csv").string() + "' '" + iris + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream csv(d / "utm.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  const auto b = row.find('"'), e = row.find('"', b + 1);
  ASSERT_NE(e, std::string::npos) << row;
  const std::string wkt = "SRID=32632;" + row.substr(b + 1, e - b - 1);
  const geo::SurveyArea a = geo::parseSurveyArea(wkt, "utm.wkt");
  EXPECT_NEAR(a.area(), geo::readSurveyArea(iris).area(), 1e-6 * a.area());
  geo::ReadOptions metres;
  metres.wkt_units = geo::WktUnits::Metres;
  const std::string m = parseError(wkt, "utm.wkt", metres);
  EXPECT_NE(m.find("utm.wkt: line 1, geometry 0: SRID=32632 with WKT in metres (--wkt-units metres)"), std::string::npos) << m;
  fs::remove_all(d);
}

TEST(AreaTextGdal, WktParenthesesAreCheckedBeforeGdal) {
  geo::ReadOptions wkt;
  wkt.format = geo::AreaFormat::Wkt;
  std::string e = parseError(std::string(100, '(') + std::string(100, ')'), "deep.wkt", wkt);
  EXPECT_NE(e.find("deep.wkt: line 1: parentheses nested more than 64 deep at offset 64"), std::string::npos) << e;
  e = parseError("POLYGON ((7 45, 7.1 45, 7.1 45.1, 7 45)))", "extra.wkt");
  EXPECT_NE(e.find("extra.wkt: line 1: ')' at offset 40 closes nothing"), std::string::npos) << e;
  // fuzz_area: a ';' inside a geometry GDAL refused looped for ever while the bad token was sought.
  e = parseError("POLYGON ((7 45;, 7.1 45, 7.1 45.1, 7 45))", "semicolon.wkt");
  EXPECT_NE(e.find("semicolon.wkt: line 1, geometry 0 at offset 0"), std::string::npos) << e;
  e = parseError("POLYGON ((7 45, 7.1 45, seven 45.1, 7 45))", "word.wkt");
  EXPECT_NE(e.find("word.wkt: geometry 0, line 1 (offset 24): \"seven\" is not a number"), std::string::npos) << e;
}

TEST(AreaTextGdal, GdalPrintsNothing) {
  testing::internal::CaptureStderr();
  for (const char* f : {"geo_string_coordinate.geojson", "geo_empty_geometry.geojson", "geo_truncated.kml", "nan.wkt",
                        "geo_unbalanced.wkt", "hole_crossing.kml"}) {
    EXPECT_FALSE(errorOf(sourcePath(std::string("tests/data/bad/") + f)).empty()) << f;
  }
  // GDAL warns "Non closed ring detected": our note says it instead (SurveyArea::repairs).
  const geo::SurveyArea open = geo::parseSurveyArea(R"({"type":"Polygon","coordinates":[[[7,45],[7.1,45],[7.1,45.1]]]})", "open.geojson");
  ASSERT_EQ(open.repairs.size(), 1U);
  EXPECT_NE(open.repairs[0].find("open.geojson: feature 0, outer boundary was not closed"), std::string::npos) << open.repairs[0];
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}
