// Survey areas in (GeoJSON, KML, WKT, QGC WPL), validation and repairs, the local frame, and the
// GeoJSON writers. Fixtures: tests/data/areas (valid) and tests/data/bad (malformed).
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "area_test_util.hpp"
#include "test_util.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/geometry/geojson.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace geo = wattswath::geometry;
using wattswath::test::errorOf;
using wattswath::test::sourcePath;

namespace {

std::string area(const std::string& name) { return sourcePath("tests/data/areas/" + name); }
std::string bad(const std::string& name) { return sourcePath("tests/data/bad/" + name); }

bool anyContains(const std::vector<std::string>& notes, const std::string& s) {
  for (const auto& n : notes)
    if (n.find(s) != std::string::npos) return true;
  return false;
}

// The 0.002 deg x 0.002 deg square at 45 N 7 E: about 157.4 m x 222.4 m.
constexpr double kSquareLonM = 157.4, kSquareLatM = 222.4;

}  // namespace

TEST(Frame, RoundTripBelowMicrometre) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> lat(-80.0, 80.0), lon(-179.0, 179.0), off(-0.05, 0.05);
  for (int i = 0; i < 200; ++i) {
    const geo::LocalFrame f({lat(rng), lon(rng), 0.0});
    const double la = f.origin().lat_deg + off(rng), lo = f.origin().lon_deg + off(rng);
    const geo::Point p = f.toLocal(la, lo);
    const geo::GeoPoint g = f.toGeodetic(p);
    EXPECT_LT((f.toLocal(g.lat_deg, g.lon_deg) - p).norm(), 1e-6);
    EXPECT_NEAR(g.lat_deg, la, 1e-11);
    EXPECT_NEAR(g.lon_deg, lo, 1e-11);
    const Eigen::Vector3d q = f.toLocal3({la, lo, 35.0});
    const geo::GeoPoint g3 = f.toGeodetic3(q);
    EXPECT_NEAR(g3.alt_m, 35.0, 1e-6);
  }
}

TEST(Frame, MetresMatchGeodesy) {
  // 0.001 deg of latitude at 45 N is 111.132 m (WGS84 meridian arc); of longitude 78.847 m.
  const geo::LocalFrame f({45.0, 7.0, 0.0});
  EXPECT_NEAR(f.toLocal(45.001, 7.0).y(), 111.132, 0.01);
  EXPECT_NEAR(f.toLocal(45.0, 7.001).x(), 78.847, 0.01);
}

TEST(Frame, RejectsOutOfRangeOrigin) {
  EXPECT_THROW(geo::LocalFrame({91.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(geo::LocalFrame({0.0, -181.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(geo::LocalFrame({NAN, 0.0, 0.0}), std::invalid_argument);
}

TEST(ReadGeoJson, PolygonWithHole) {
  const auto a = geo::readSurveyArea(area("square_hole.geojson"));
  ASSERT_EQ(a.regions.size(), 1u);
  const auto& p = a.polygon();
  EXPECT_EQ(p.outer.size(), 4u);
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_GT(geo::signedArea(p.outer), 0.0);
  EXPECT_LT(geo::signedArea(p.holes[0]), 0.0);
  EXPECT_NEAR(a.bboxMax().x() - a.bboxMin().x(), kSquareLonM, 0.5);
  EXPECT_NEAR(a.bboxMax().y() - a.bboxMin().y(), kSquareLatM, 0.5);
  EXPECT_NEAR(a.area(), kSquareLonM * kSquareLatM * (1.0 - 0.04), 60.0);
  EXPECT_TRUE(a.repairs.empty());
  // Default origin: centre of the lat/lon bounding box.
  EXPECT_NEAR(a.frame->origin().lat_deg, 45.001, 1e-12);
  EXPECT_NEAR(a.frame->origin().lon_deg, 7.001, 1e-12);
}

TEST(ReadGeoJson, MultiPolygonNoFlyFeatureAndHome) {
  const auto a = geo::readSurveyArea(area("multi_nofly.geojson"));
  EXPECT_EQ(a.regions.size(), 2u);
  EXPECT_EQ(a.no_fly.size(), 1u);
  ASSERT_TRUE(a.home.has_value());
  size_t holes = 0;
  for (const auto& r : a.regions) holes += r.holes.size();
  EXPECT_EQ(holes, 1u);  // the in-file no-fly zone became a hole of the big square
  EXPECT_THROW(a.polygon(), geo::SurveyAreaError);
}

TEST(ReadKml, NamespacesCommentsCdataAndNoFlyPlacemark) {
  const auto a = geo::readSurveyArea(area("field.kml"));
  ASSERT_EQ(a.regions.size(), 1u);
  EXPECT_EQ(a.regions[0].holes.size(), 2u);  // its own inner boundary plus the "No-fly: tower" placemark
  EXPECT_EQ(a.no_fly.size(), 1u);
  const auto ref = geo::readSurveyArea(area("square_hole.geojson"));
  EXPECT_NEAR(a.area(), ref.area() - std::abs(geo::signedArea(a.no_fly[0])), 1e-3);
}

TEST(ReadWkt, LonLatMatchesGeoJson) {
  const auto a = geo::readSurveyArea(area("field.wkt"));
  const auto b = geo::readSurveyArea(area("square_hole.geojson"));
  EXPECT_NEAR(a.area(), b.area(), 1e-6);
  EXPECT_NEAR(a.perimeter(), b.perimeter(), 1e-6);
}

TEST(ReadWkt, MetresWithoutAndWithOrigin) {
  geo::ReadOptions o;
  o.wkt_units = geo::WktUnits::Metres;
  const auto a = geo::readSurveyArea(area("field_metres.wkt"), o);
  EXPECT_EQ(a.regions.size(), 2u);
  EXPECT_FALSE(a.frame.has_value());
  EXPECT_NEAR(a.area(), 100.0 * 50.0 + 50.0 * 50.0, 1e-9);
  EXPECT_THROW(geo::surveyAreaToGeoJson(a), geo::SurveyAreaError);
  o.origin = geo::GeoPoint{45.0, 7.0, 0.0};
  const auto b = geo::readSurveyArea(area("field_metres.wkt"), o);
  ASSERT_TRUE(b.frame.has_value());
  EXPECT_NO_THROW(geo::surveyAreaToGeoJson(b));
}

TEST(ReadQgcWpl, RepairsAreReported) {
  const auto a = geo::readSurveyArea(area("field.waypoints"));
  const auto& p = a.polygon();
  EXPECT_EQ(p.outer.size(), 4u);
  EXPECT_GT(geo::signedArea(p.outer), 0.0);
  ASSERT_TRUE(a.home.has_value());
  ASSERT_TRUE(a.home_alt_m.has_value());
  EXPECT_DOUBLE_EQ(*a.home_alt_m, 12.5);
  EXPECT_TRUE(anyContains(a.repairs, "vertex 5 (row 6, line 8), a duplicate of the preceding vertex 4"));
  EXPECT_TRUE(anyContains(a.repairs, "repeated closing vertex"));
  EXPECT_TRUE(anyContains(a.repairs, "removed vertex 2 (row 3, line 5), collinear"));
  EXPECT_TRUE(anyContains(a.repairs, "reversed the vertex order to counter-clockwise"));
  EXPECT_EQ(a.repairs.size(), 4u);
}

TEST(ReadQgcWpl, OriginAtHome) {
  geo::ReadOptions o;
  o.origin_choice = geo::OriginChoice::Home;
  const auto a = geo::readSurveyArea(area("field.waypoints"), o);
  EXPECT_LT(a.home->norm(), 1e-9);
  o.origin_choice = geo::OriginChoice::FirstVertex;
  const auto b = geo::readSurveyArea(area("field.waypoints"), o);
  EXPECT_DOUBLE_EQ(b.frame->origin().lat_deg, 45.0);
  EXPECT_NEAR(a.area(), b.area(), 1e-3);
}

TEST(NoFly, InsideBecomesHole) {
  geo::ReadOptions o;
  o.no_fly_files = {area("nofly_inside.waypoints")};
  const auto a = geo::readSurveyArea(area("field.wkt"), o);
  const auto ref = geo::readSurveyArea(area("field.wkt"));
  EXPECT_EQ(a.polygon().holes.size(), 2u);
  EXPECT_NEAR(ref.area() - a.area(), std::abs(geo::signedArea(a.no_fly[0])), 1e-3);
}

TEST(NoFly, PartlyOutsideIsClippedAndSaid) {
  geo::ReadOptions o;
  o.no_fly_files = {area("nofly_partial.geojson")};
  const auto a = geo::readSurveyArea(area("field.wkt"), o);
  EXPECT_TRUE(anyContains(a.repairs, "nofly_partial.geojson: no-fly zone 0 extends outside the area"));
  EXPECT_EQ(a.polygon().holes.size(), 1u);
  EXPECT_GT(a.polygon().outer.size(), 4u);  // the zone took a corner
  const auto ref = geo::readSurveyArea(area("field.wkt"));
  EXPECT_NEAR(ref.area() - a.area(), kSquareLonM * kSquareLatM / 16.0, 10.0);  // a quarter of each side inside
}

TEST(NoFly, CoveringTheWholeAreaIsAnError) {
  geo::ReadOptions o;
  o.no_fly_files = {area("nofly_all.wkt")};
  const std::string e = errorOf(area("field.wkt"), o);
  EXPECT_NE(e.find("nofly_all.wkt: no-fly zone 0 covers the whole survey area"), std::string::npos) << e;
}

TEST(NoFly, OutsideIsIgnoredAndSaid) {
  const auto a = geo::readSurveyArea(area("square_hole.geojson"));
  auto b = a;
  geo::NoFlyZones z;
  z.source = "test";
  z.zones = {{{1000, 1000}, {1010, 1000}, {1010, 1010}, {1000, 1010}}};
  geo::subtractNoFlyZones(b, z);
  EXPECT_TRUE(anyContains(b.repairs, "test: no-fly zone 0 does not overlap the flyable area; ignored"));
  EXPECT_DOUBLE_EQ(a.area(), b.area());
}

TEST(ReadErrors, EachNamesFileAndVertexOrFeature) {
  struct Case {
    std::string file;
    std::vector<std::string> expect;
  };
  const std::vector<Case> cases = {
      {"bowtie.geojson", {"bowtie.geojson: feature 0, outer boundary: self-intersection: edge 0 (vertex 0 -> vertex 1) and edge 2 (vertex 2 -> vertex 3)"}},
      {"two_vertices.waypoints", {"two_vertices.waypoints: polygon: fewer than 3 distinct vertices (3 given, 2 distinct)"}},
      {"collinear.wkt", {"collinear.wkt: geometry 0, outer boundary: zero area"}},
      {"hole_outside.geojson", {"hole_outside.geojson: feature 0, hole 0, vertex 0: lies outside feature 0, outer boundary"}},
      {"hole_crossing.kml", {"hole_crossing.kml: layer \"hole_crossing\", feature 0, hole 0: edge", "crosses layer \"hole_crossing\", feature 0, outer boundary edge 1"}},
      {"lat_range.geojson", {"lat_range.geojson: feature 0, outer boundary, vertex 2: latitude 95.002 deg is outside [-90, 90]"}},
      {"not_json.geojson", {"not_json.geojson: not valid JSON"}},
      {"linestring.geojson", {"linestring.geojson: feature 0: geometry type LineString is not an area"}},
      {"bad_column.waypoints", {"bad_column.waypoints: line 3 (row 1), column 10: expected a number, got \"seven\""}},
      {"unclosed.kml", {"unclosed.kml: unexpected end of file inside <Polygon>"}},
      {"nan.wkt", {"nan.wkt: geometry 0, line 1 (offset 38): non-finite coordinate \"nan\""}},
      {"overlapping_holes.geojson", {"overlapping_holes.geojson: feature 0, hole 1: overlaps feature 0, hole 0"}},
      {"spike.wkt", {"spike.wkt: geometry 0, outer boundary: self-intersection: edge 0 (vertex 0 -> vertex 2) and edge 2 (vertex 3 -> vertex 4)"}},
  };
  for (const auto& c : cases) {
    const std::string e = errorOf(bad(c.file));
    ASSERT_FALSE(e.empty()) << c.file << " was accepted";
    EXPECT_EQ(e.rfind(bad(c.file), 0), 0u) << e;  // starts with the full path
    for (const auto& s : c.expect) EXPECT_NE(e.find(s), std::string::npos) << c.file << ": " << e;
  }
}

TEST(ReadErrors, MissingFileAndUnknownFormat) {
  EXPECT_NE(errorOf(bad("does_not_exist.geojson")).find("cannot open"), std::string::npos);
  geo::ReadOptions o;
  EXPECT_THROW(geo::parseSurveyArea("hello", "memory.txt", o), geo::SurveyAreaError);
  o.format = geo::AreaFormat::Wkt;
  EXPECT_NO_THROW(geo::parseSurveyArea("POLYGON((7 45, 7.001 45, 7.001 45.001, 7 45))", "memory.txt", o));
}

TEST(Validate, InMemoryPolygonRepairsAndErrors) {
  geo::PolygonWithHoles p;
  p.outer = {{0, 0}, {0, 10}, {10, 10}, {10, 5}, {10, 0}};  // clockwise, collinear vertex 3
  const auto notes = geo::validatePolygon(p, "mem");
  EXPECT_EQ(p.outer.size(), 4u);
  EXPECT_GT(geo::signedArea(p.outer), 0.0);
  EXPECT_EQ(notes.size(), 2u);
  geo::PolygonWithHoles touching = p;
  touching.holes = {{{0, 2}, {3, 5}, {3, 2}}};  // touches the boundary at one point: allowed
  EXPECT_NO_THROW(geo::validatePolygon(touching, "mem"));
  geo::PolygonWithHoles alongEdge = p;
  alongEdge.holes = {{{0, 2}, {0, 5}, {3, 5}, {3, 2}}};  // shares part of an edge
  EXPECT_THROW(geo::validatePolygon(alongEdge, "mem"), geo::SurveyAreaError);
  geo::PolygonWithHoles sliver;
  sliver.outer = {{0, 0}, {100, 0}, {50, 1e-6}};
  EXPECT_THROW(geo::validatePolygon(sliver, "mem"), geo::SurveyAreaError);
  geo::PolygonWithHoles spike;
  spike.outer = {{0, 0}, {10, 0}, {10, 10}, {10, 5}, {0, 10}};
  try {
    geo::validatePolygon(spike, "mem");
    FAIL() << "spike accepted";
  } catch (const geo::SurveyAreaError& e) {
    EXPECT_NE(std::string(e.what()).find("edge 1 (vertex 1 -> vertex 2) and edge 2 (vertex 2 -> vertex 3) fold back"), std::string::npos)
        << e.what();
  }
}

TEST(WriteGeoJson, AreaRoundTrip) {
  const auto a = geo::readSurveyArea(area("multi_nofly.geojson"));
  const std::string text = geo::surveyAreaToGeoJson(a);
  geo::ReadOptions o;
  o.format = geo::AreaFormat::GeoJson;
  o.origin_choice = geo::OriginChoice::Given;
  o.origin = a.frame->origin();
  const auto b = geo::parseSurveyArea(text, "written.geojson", o);
  ASSERT_EQ(b.regions.size(), a.regions.size());
  EXPECT_NEAR(b.area(), a.area(), 1e-6);
  for (size_t r = 0; r < a.regions.size(); ++r) {
    ASSERT_EQ(b.regions[r].outer.size(), a.regions[r].outer.size());
    for (size_t i = 0; i < a.regions[r].outer.size(); ++i) EXPECT_LT((b.regions[r].outer[i] - a.regions[r].outer[i]).norm(), 1e-6);
  }
  EXPECT_LT((*b.home - *a.home).norm(), 1e-6);
}

TEST(WriteGeoJson, PathOneFeaturePerLegWithScalarProperties) {
  const geo::LocalFrame f({45.0, 7.0, 0.0});
  geo::CoveragePath path;
  path.pattern = "boustrophedon";
  geo::PathLeg l1;
  l1.start = {0, 0};
  l1.end = {100, 0};
  l1.altitude = 10;
  geo::PathLeg arc;
  arc.kind = geo::PrimitiveKind::Arc;
  arc.role = geo::LegRole::Turn;
  arc.start = {100, 0};
  arc.end = {100, 20};
  arc.center = {100, 10};
  arc.radius = 10;
  arc.turn_angle = M_PI;
  arc.altitude = 10;
  geo::PathLeg spin;
  spin.kind = geo::PrimitiveKind::TurnInPlace;
  spin.role = geo::LegRole::Turn;
  spin.start = spin.end = {100, 20};
  geo::PathLeg l2 = l1;
  l2.start = {100, 20};
  l2.end = {0, 20};
  path.legs = {l1, arc, spin, l2};
  geo::PathGeoJsonOptions o;
  o.leg_properties["speed_mps"] = {8.0, 4.4, 0.0, 8.0};
  const auto j = nlohmann::json::parse(geo::coveragePathToGeoJson({path}, f, o));
  // One feature per leg with scalar properties (GIS formats without lists keep them).
  const auto& feats = j["features"];
  ASSERT_EQ(feats.size(), 4u);
  for (size_t i = 0; i < feats.size(); ++i) {
    EXPECT_EQ(feats[i]["properties"]["leg"], i + 1);  // as the plan report counts
    for (const auto& [key, value] : feats[i]["properties"].items()) {
      EXPECT_TRUE(value.is_primitive()) << key;
      EXPECT_LE(key.size(), 10u) << key;  // Shapefile's limit on field names
    }
  }
  // A line: its 2 ends; the arc: 19 vertices (10 deg steps over 180 deg); a turn in place: its vertex twice.
  EXPECT_EQ(feats[0]["geometry"]["coordinates"].size(), 2u);
  const auto& c = feats[1]["geometry"]["coordinates"];
  ASSERT_EQ(c.size(), 19u);
  EXPECT_EQ(feats[2]["geometry"]["coordinates"].size(), 2u);
  EXPECT_EQ(feats[1]["properties"]["role"], "turn");
  EXPECT_EQ(feats[1]["properties"]["kind"], "arc");
  EXPECT_EQ(feats[1]["properties"]["speed_mps"], 4.4);
  EXPECT_NEAR(feats[1]["properties"]["length_m"].get<double>(), 10.0 * M_PI, 1e-9);
  // Every vertex projects back onto the path to < 1e-6 m; the arc's middle vertex is at (110, 10).
  const geo::Point mid = f.toLocal(c[9][1].get<double>(), c[9][0].get<double>());
  EXPECT_LT((mid - geo::Point(110, 10)).norm(), 1e-6);
  const auto& c3 = feats[3]["geometry"]["coordinates"];
  const geo::Point last = f.toLocal(c3[1][1].get<double>(), c3[1][0].get<double>());
  EXPECT_LT((last - geo::Point(0, 20)).norm(), 1e-6);
  o.leg_properties["speed_mps"].pop_back();
  EXPECT_THROW(geo::coveragePathToGeoJson({path}, f, o), std::invalid_argument);
}

TEST(BundledAreas, LoadWithoutRepairs) {
  const auto iris = geo::readSurveyArea(sourcePath("data/areas/iris_area.geojson"));
  EXPECT_EQ(iris.polygon().outer.size(), 11u);
  EXPECT_EQ(iris.polygon().holes.size(), 1u);
  EXPECT_TRUE(iris.repairs.empty());
  const auto rect = geo::readSurveyArea(sourcePath("data/areas/espiral_rectangle.geojson"));
  EXPECT_NEAR(rect.bboxMax().x() - rect.bboxMin().x(), 252.0, 1.0);
  EXPECT_NEAR(rect.bboxMax().y() - rect.bboxMin().y(), 118.0, 1.0);
}

TEST(AreaInfoCli, JsonContract) {
  const auto r = wattswath::test::run(wattswath::test::cliBinary() + " area info " + sourcePath("data/areas/iris_area.geojson") + " --json");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  for (const char* key : {"vertices", "holes", "area_m2", "perimeter_m", "bbox", "origin", "repairs"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["vertices"], 15);
  EXPECT_EQ(j["holes"], 1);
  const auto bad = wattswath::test::run(wattswath::test::cliBinary() + " area info " + sourcePath("tests/data/bad/bowtie.geojson") + " 2>&1");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.output.find("self-intersection"), std::string::npos);
}
