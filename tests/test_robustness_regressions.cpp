// Regression tests of the bugs the robustness work (issue 8) found, one per bug, named after it
// (docs/robustness.md, "Findings"). Each failed before its fix.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_util.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/calibration/user_effect.hpp"
#include "wattswath/logs/log_io.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/survey_area.hpp"

using namespace wattswath::energy;
using namespace wattswath::logs;
using namespace wattswath::calibration;
using wattswath::test::readAll;
using wattswath::test::runCli;
using wattswath::test::sourcePath;

namespace {

std::string iris() { return readAll(sourcePath("data/vehicles/iris.json")); }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string vehicleError(const std::string& text) {
  try {
    parseVehicle(text, "v.json");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string areaError(const std::string& text, const std::string& source) {
  try {
    wattswath::geometry::parseSurveyArea(text, source);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string logError(const std::string& text) {
  try {
    parseCsvLog(text, "log.csv");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// get<int>() wrapped 4294967300 to 4: a typo'd rotor count was accepted as a quadcopter.
TEST(Regression, VehicleRotorCountIntOverflowWrappedTo4) {
  const std::string m = vehicleError(replaced(iris(), "\"rotor_count\": 4", "\"rotor_count\": 4294967300"));
  EXPECT_NE(m.find("v.json: field 'rotor_count' = 4294967300, expected an integer"), std::string::npos) << m;
}

// nlohmann keeps the last of two equal keys: "mass_kg" given twice silently used the second.
TEST(Regression, VehicleDuplicateFieldSilentlyKeptLast) {
  const std::string m = vehicleError(replaced(iris(), "\"mass_kg\": 1.3,", "\"mass_kg\": 1.3, \"mass_kg\": 13,"));
  EXPECT_NE(m.find("v.json: field 'mass_kg' appears twice"), std::string::npos) << m;
}

// 1e999 raised json out_of_range, which was not caught: the message did not name the file.
TEST(Regression, VehicleNumberOverflowMessageLackedFileName) {
  const std::string m = vehicleError(replaced(iris(), "\"mass_kg\": 1.3", "\"mass_kg\": 1e999"));
  EXPECT_NE(m.find("v.json: not valid JSON"), std::string::npos) << m;
}

// A positive but subnormal disk area or efficiency passed "(0, x]" and made the hover power infinite.
TEST(Regression, VehicleTinyDiskAreaGaveInfiniteHoverPower) {
  EXPECT_NE(vehicleError(replaced(iris(), "\"disk_area_m2\": 0.2027", "\"disk_area_m2\": 1e-320")).find("disk_area_m2"),
            std::string::npos);
  EXPECT_NE(vehicleError(replaced(iris(), "\"motor_efficiency\": 0.90", "\"motor_efficiency\": 1e-300"))
                .find("motor_efficiency"),
            std::string::npos);
  const Vehicle v = parseVehicle(replaced(iris(), "\"disk_area_m2\": 0.2027", "\"disk_area_m2\": 0.0001"), "v.json");
  EXPECT_TRUE(std::isfinite(marinsHoverPowerW(v)));
}

// Positions of 1e306 m were read; the model's v^3 overflowed and replay printed null energies.
TEST(Regression, LogHugePositionsGaveNullEnergies) {
  const std::string m = logError("time_s,x_m,y_m,z_m,power_w\n0,0,0,0,200\n1,1e306,0,0,200\n2,2e306,0,0,200\n");
  EXPECT_NE(m.find("log.csv:3: column 'x_m' (field 2): value '1e306' is too large"), std::string::npos) << m;
}

// Time steps of 1e-320 s were accepted and gave a 4e-320 s flight with meaningless energies.
TEST(Regression, LogSubnormalTimeStepsAccepted) {
  const std::string m = logError("time_s,x_m,y_m,z_m,power_w\n0,0,0,0,200\n1e-320,1,0,0,200\n2e-320,2,0,0,200\n");
  EXPECT_NE(m.find("log.csv:3: column 'time_s'"), std::string::npos) << m;
  EXPECT_NE(m.find("expected steps of at least"), std::string::npos) << m;
}

// std::stod read the origin "43.7abc" as 43.7 (and accepted "nan" and 143.7).
TEST(Regression, LogOriginMetadataPartiallyParsed) {
  const std::string body = "# origin_lon_deg: 10.4\n# origin_alt_m: 7\ntime_s,x_m,y_m,z_m,power_w\n0,0,0,0,200\n1,1,0,0,200\n";
  for (const std::string lat : {"43.7abc", "nan", "143.7"}) {
    const std::string m = logError("# origin_lat_deg: " + lat + "\n" + body);
    EXPECT_NE(m.find("metadata 'origin_lat_deg': value '" + lat + "', expected a latitude"), std::string::npos) << m;
  }
  const FlightLog ok = parseCsvLog("# origin_lat_deg: 43.7\n" + body, "log.csv");
  EXPECT_TRUE(ok.has_geodetic_origin);
  EXPECT_DOUBLE_EQ(ok.origin_lat_deg, 43.7);
}

// A waypoint 4e7 m away made simulateFlight loop for 5e7 samples (and 1e300 m for ever).
TEST(Regression, SimulateFarWaypointRanOutOfMemory) {
  const EnergyModel m = buildModel(loadVehicle(sourcePath("data/vehicles/iris.json")), {"hover", "kinetic"});
  try {
    simulateFlight({{0, 0, 10}, {4e7, 0, 10}}, m);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("expected at most"), std::string::npos) << e.what();
  }
  EXPECT_THROW(simulateFlight({{0, 0, 10}, {NAN, 0, 10}}, m), std::invalid_argument);
}

// readPath skipped ANY unreadable first line as a header, so a typo in the first waypoint
// silently dropped it; a fourth number on a line was silently ignored.
TEST(Regression, PathFirstRowOfNumbersSkippedAsHeader) {
  const std::string dir = std::filesystem::temp_directory_path() / ("wattswath_path_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/p.txt") << "0 0 1O\n10 0 10\n20 0 10\n";
  const auto r = runCli({"simulate", "--vehicle", "data/vehicles/iris.json", "--path", dir + "/p.txt", "--out",
                         dir + "/out.csv"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("p.txt:1: expected three numbers"), std::string::npos) << r.err;
  std::ofstream(dir + "/h.txt") << "x y z\n0 0 10\n10 0 10\n";
  const auto ok = runCli({"simulate", "--vehicle", "data/vehicles/iris.json", "--path", dir + "/h.txt", "--out",
                          dir + "/out.csv"});
  EXPECT_EQ(ok.status, 0) << ok.err;
  std::filesystem::remove_all(dir);
}

// The KML tag "</>" both starts and ends with its one '/': it was taken as closing and
// self-closing, the name "" lost its last character (pop_back on an empty string) and the
// next substr read far past the stack buffer (fuzz_area, ASan stack-buffer-overflow).
TEST(Regression, KmlEmptyClosingTagOverflowedTheStack) {
  const std::string fuzzed = readAll(sourcePath("tests/data/bad/geo_kml_empty_closing_tag.kml"));
  std::string m = areaError(fuzzed, "f.kml");
  EXPECT_NE(m.find("f.kml: line 1: tag </> has no element name"), std::string::npos) << m;
  m = areaError("<kml>\n<Placemark>\n</>\n</Placemark></kml>", "g.kml");
  EXPECT_NE(m.find("g.kml: line 3: tag </> has no element name"), std::string::npos) << m;
  for (const char* tag : {"<>", "< />", "</ >"}) {
    m = areaError(std::string("<kml>") + tag + "</kml>", "h.kml");
    EXPECT_NE(m.find("h.kml: line 1: tag " + std::string(tag) + " has no element name"), std::string::npos) << m;
  }
}

// A GeoJSON vertex at longitude 187 or 1e308 moved the bounding-box centre out of range, and the
// error named only "frame origin", not the file or the vertex.
TEST(Regression, AreaVertexOutOfRangeReportedAsFrameOrigin) {
  std::string m = areaError(R"({"type": "Polygon", "coordinates": [[[7, 45], [187, 45], [7.002, 45.002], [7, 45]]]})",
                            "a.geojson");
  EXPECT_NE(m.find("a.geojson: feature 0, outer boundary, vertex 1: longitude 187 deg is outside [-180, 180]"),
            std::string::npos) << m;
  m = areaError(R"({"type": "Polygon", "coordinates": [[[7, 45], [7.002, 45], [7.002, 45.002], [7, 45]],
                    [[7.001, 45.001], [7.0011, 1e308], [7.0012, 45.001], [7.001, 45.001]]]})",
                "b.geojson");
  EXPECT_NE(m.find("b.geojson: feature 0, hole 0, vertex 1: latitude 1e+308 deg is outside [-90, 90]"), std::string::npos)
      << m;
}

// The WKT reader did not skip a UTF-8 byte order mark: "expected POLYGON or MULTIPOLYGON".
TEST(Regression, WktByteOrderMarkRejected) {
  const std::string wkt = "POLYGON ((7 45, 7.002 45, 7.002 45.002, 7 45.002, 7 45))";
  wattswath::geometry::ReadOptions o;
  o.wkt_units = wattswath::geometry::WktUnits::LonLatDegrees;
  const auto plain = wattswath::geometry::parseSurveyArea(wkt, "a.wkt", o);
  const auto bom = wattswath::geometry::parseSurveyArea("\xEF\xBB\xBF" + wkt, "a.wkt", o);
  EXPECT_NEAR(bom.area(), plain.area(), 1e-6);
  EXPECT_GT(plain.area(), 30000.0);
}

// "QGC WPL 999" was read as version 110 and failed later with "no finite vertex".
TEST(Regression, QgcWplWrongVersionReportedAsNoVertex) {
  const std::string rows = "0\t1\t0\t16\t0\t0\t0\t0\t45.0\t7.0\t10\t1\n";
  const std::string m = areaError("QGC WPL 999\n" + rows, "m.waypoints");
  EXPECT_NE(m.find("m.waypoints: line 1: QGC WPL version \"999\" is not supported (expected the header \"QGC WPL 110\")"),
            std::string::npos) << m;
}

// fuzz_area in CI (20 s): a QGC WPL row with command 2e35 was cast to int (undefined behaviour,
// UBSan "outside the range of representable values of type 'int'"). Now the command must be an
// integer in [0, 65535] (MAV_CMD), named with its line and column.
TEST(Regression, QgcWplCommandOutOfRangeWasCastToInt) {
  std::string m = areaError(readAll(sourcePath("tests/data/bad/geo_command_out_of_range.waypoints")), "c.waypoints");
  EXPECT_NE(m.find("c.waypoints: line 4 (row 2), column 4 (command): expected a MAV_CMD number, an integer in [0, 65535]"),
            std::string::npos) << m;
  const std::string head = "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t45.0\t7.0\t10\t1\n";
  for (const char* cmd : {"-1", "16.5", "nan", "65536"}) {
    m = areaError(head + "1\t0\t3\t" + cmd + "\t0\t0\t0\t0\t45.0\t7.0\t10\t1\n", "d.waypoints");
    EXPECT_NE(m.find("column 4 (command)"), std::string::npos) << cmd << ": " << m;
  }
}

// fuzz_csv_log (120 s): a geodetic log with a first altitude of 361407 m was read, but writeCsvLog
// wrote that altitude as origin_alt_m, which the reader bounds to 100 km: the log did not read back.
TEST(Regression, LogAltitudeAcceptedButItsOriginRejected) {
  const std::string head = "time_s,lat_deg,lon_deg,alt_m,power_w\n";
  const std::string m = logError(head + "0,43.7,10.4,361407,240\n1,43.7,10.40001,7,240\n");
  EXPECT_NE(m.find("log.csv:2: column 'alt_m': value 361407 is outside -100000..100000 m"), std::string::npos) << m;
  const FlightLog high = parseCsvLog(head + "0,43.7,10.4,99999,240\n1,43.7,10.40001,99999,240\n", "log.csv");
  const FlightLog back = parseCsvLog(writeCsvLog(high), "back.csv");
  ASSERT_EQ(back.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(back.origin_alt_m, 99999.0);
}

// fuzz_csv_log in a CI run (20 s): voltage 12 V x current 266666660 A was accepted as a power of
// 3.2e9 W (each factor within the 1e9 bound), written back as power_w and then rejected: the log did
// not read back. The derived power is bounded like a written one.
TEST(Regression, LogDerivedPowerBeyondTheBoundDidNotReadBack) {
  const std::string head = "time_s,x_m,y_m,z_m,voltage_v,current_a\n";
  const std::string m = logError(head + "0,0,0,10,12,266666660\n1,0,0,10,12,20\n");
  EXPECT_NE(m.find("log.csv:2: columns 'voltage_v' x 'current_a': power 3199999920 W is too large"), std::string::npos) << m;
  const FlightLog ok = parseCsvLog(head + "0,0,0,10,12,20\n1,1,0,10,12,20\n", "log.csv");
  const FlightLog back = parseCsvLog(writeCsvLog(ok), "back.csv");
  ASSERT_EQ(back.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(back.samples[0].power, 240.0);
}

// fuzz_dataflash (120 s, --lenient): "at least two position samples" was checked before the samples
// with non-increasing time were dropped; one was left and the interpolation read pt[1] past the end
// (ASan heap-buffer-overflow in assemble). Same code path for ULog.
TEST(Regression, DataFlashPositionTimesBackwardsReadPastTheEnd) {
  const std::string bytes = readAll(sourcePath("tests/data/bad/log_dataflash_time_backwards.bin"));
  LogReadOptions o;
  o.lenient = true;
  try {
    readDataFlashBytes(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), "df.bin", o);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("df.bin: fewer than two position samples (1, 1 more with non-increasing"),
              std::string::npos) << e.what();
  }
}

// Issue 20: absurd plans are refused before any work, from the area's minimum width (CGAL's
// minimum enclosing strip): 1 km^2 at 0.05 m spacing (20,000 lines) used to run 9 minutes.
TEST(Regression, PlanWorkIsEstimatedAndAbsurdPlansRefusedUpFront) {
  const auto dir = std::filesystem::temp_directory_path() / ("wattswath_planwork_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string area = (dir / "km.geojson").string();
  std::ofstream(area) << R"({"type":"Polygon","coordinates":[[[10.0,43.0],[10.0125,43.0],[10.0125,43.009],[10.0,43.009],[10.0,43.0]]]})";
  auto r = runCli({"plan", area, "--vehicle", "data/vehicles/iris.json", "--spacing", "0.05", "--out", (dir / "o").string()}, 20);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("needs at least 19996 sweep lines"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--allow-large"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at least 999.8 m wide"), std::string::npos) << r.err;
  r = runCli({"plan", area, "--vehicle", "data/vehicles/iris.json", "--spacing", "0.01", "--allow-large", "--out",
              (dir / "o").string()}, 20);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("199966 waypoints: more than one mission can hold (65534 items"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Widen --spacing to at least 0.04 m, or split the survey with --sorties"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o" / "mission.plan"));
  std::filesystem::remove_all(dir);
}

// Issue 20: a home point 500 km away (or at the antipode) was silently moved by the local
// tangent-plane frame (42.7 km off at 500 km). It is refused beyond 50 km from the area's nearest
// vertex (WGS84 geodesic), given as --home or as the area file's home.
TEST(Regression, PlanFarHomeIsRefusedNotSilentlyMoved) {
  const auto dir = std::filesystem::temp_directory_path() / ("wattswath_farhome_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto r = runCli({"plan", sourcePath("data/areas/espiral_rectangle.geojson"), "--vehicle", "data/vehicles/iris.json",
                   "--spacing", "20", "--home", "43.7,-170.5", "--out", (dir / "a").string()});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("--home (43.700000, -170.500000) is 10320.4 km from the nearest vertex"), std::string::npos) << r.err;
  const std::string wpl = (dir / "far_home.waypoints").string();
  std::ofstream(wpl) << "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t39.2\t9.1\t20\t1\n"  // Cagliari, about 560 km away
                        "1\t0\t0\t16\t0\t0\t0\t0\t43.717946\t10.430821\t10\t1\n2\t0\t0\t16\t0\t0\t0\t0\t43.717931\t10.433954\t10\t1\n"
                        "3\t0\t0\t16\t0\t0\t0\t0\t43.718985\t10.433954\t10\t1\n4\t0\t0\t16\t0\t0\t0\t0\t43.718993\t10.430843\t10\t1\n";
  r = runCli({"plan", wpl, "--vehicle", "data/vehicles/iris.json", "--spacing", "20", "--out", (dir / "b").string()});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(wpl + ": its home point"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("more than the 50 km allowed"), std::string::npos) << r.err;
  r = runCli({"plan", sourcePath("data/areas/espiral_rectangle.geojson"), "--vehicle", "data/vehicles/iris.json",
              "--spacing", "20", "--home", "43.7185,10.4330", "--out", (dir / "c").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  std::filesystem::remove_all(dir);
}

namespace {

TEST(Regression, PlanRefusesSpeedLimitsNoMissionCanCommand) {
  // Issue 20: a vehicle limited to 0.5 m/s (or a camera limited to 0.3 m/s) got a mission
  // commanding 1 m/s, the slowest DO_CHANGE_SPEED ArduCopter 3.x obeys, with only a note.
  const auto dir = std::filesystem::temp_directory_path() / ("wattswath_slow_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ifstream in(sourcePath("data/vehicles/iris.json"));
  std::string v((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = "\"max_speed_mps\": 16.0";
  ASSERT_NE(v.find(key), std::string::npos);
  v.replace(v.find(key), key.size(), "\"max_speed_mps\": 0.5");
  const std::string slow = (dir / "slow.json").string();
  std::ofstream(slow) << v;
  auto r = runCli({"plan", sourcePath("data/areas/espiral_rectangle.geojson"), "--vehicle", slow, "--spacing", "20", "--out",
                   (dir / "a").string()});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("slow.json: max_speed_mps 0.50 m/s is below 1.0 m/s, the slowest speed a mission can command"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "a" / "mission.plan"));
  r = runCli({"plan", sourcePath("data/areas/espiral_rectangle.geojson"), "--vehicle", "data/vehicles/iris.json", "--spacing",
              "20", "--camera-max-speed", "0.3", "--out", (dir / "b").string()});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("the camera's sweep speed limit 0.30 m/s"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

TEST(Regression, TurnsAtAHairpinAreBoundedAndTheOvershootIsSaid) {
  // Issue 20: at an interior angle of 1e-6 deg Marins' rounded loop was 32,000 km long (1.4 km at
  // 1 deg), printed as a -79 % "saving" with no word on why.
  auto r = runCli({"turns", "--vehicle", "data/vehicles/iris.json", "--distance", "100", "--angle", "1e-6"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("option --angle = 1e-06, expected an interior angle in [0.5, 180] deg"), std::string::npos) << r.err;
  r = runCli({"turns", "--vehicle", "data/vehicles/iris.json", "--distance", "100", "--angle", "1"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("note: the rounded turn overshoots the vertex by 493.5 m on each branch"), std::string::npos) << r.out;
  r = runCli({"turns", "--vehicle", "data/vehicles/iris.json", "--distance", "100", "--angle", "90"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("note:"), std::string::npos) << r.out;  // a right angle overshoots by R only
}

}  // namespace

namespace {

TEST(Regression, PlanRefusesThousandsOfVerticesUnlessAllowedLarge) {
  // Issue 20: a 10,000-vertex polygon took 13 GB and no answer in 10 minutes (now about 30 s);
  // a wiggly 1,811-vertex field still took over 2 minutes. Beyond 1,000 vertices plan asks for a
  // simplified boundary or --allow-large, before any work.
  const auto dir = std::filesystem::temp_directory_path() / ("wattswath_vertices_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string area = (dir / "wiggly.geojson").string();
  std::ostringstream ring;
  ring.precision(10);
  const int n = 1200;
  for (int i = 0; i <= n; ++i) {  // 300 m circle with 7 lobes of 20 m near Pisa, closed
    const double a = 2.0 * M_PI * (i % n) / n, r = 300.0 + 20.0 * std::sin(7.0 * a);
    ring << (i ? "," : "") << "[" << 10.40 + r * std::cos(a) / (111320.0 * std::cos(43.72 * M_PI / 180.0)) << ","
         << 43.72 + r * std::sin(a) / 110540.0 << "]";
  }
  std::ofstream(area) << R"({"type":"Polygon","coordinates":[[)" << ring.str() << "]]}";
  const auto r = runCli({"plan", area, "--vehicle", "data/vehicles/iris.json", "--spacing", "20", "--out", (dir / "o").string()}, 20);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("vertices, more than the 1000 planned without --allow-large"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("simplify the boundary first"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o" / "mission.plan"));
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

TEST(Regression, AnOverlapNearOneIsRefusedUpFrontNamingTheOverlap) {
  // Issue 20: --overlap 0.9999999 filled 3.8 GB and then said only "std::bad_alloc". The work
  // estimate refuses it before planning, and names the camera's options, not --spacing.
  const auto dir = std::filesystem::temp_directory_path() / ("wattswath_overlap_" + std::to_string(::getpid()));
  const auto r = runCli({"plan", sourcePath("data/areas/espiral_rectangle.geojson"), "--vehicle", "data/vehicles/iris.json",
                         "--fov", "60", "--altitude", "50", "--overlap", "0.9999999", "--out", (dir / "o").string()},
                        20);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("m spacing (the camera's footprint and --overlap)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Lower --overlap (or fly higher)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("bad_alloc"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o" / "mission.plan"));
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

// A sparse file of `bytes` bytes (no disk used): the size limits are checked before reading.
std::string sparseFile(const std::string& name, long long bytes) {
  const auto p = std::filesystem::temp_directory_path() / ("wattswath_" + name + "_" + std::to_string(::getpid()));
  std::ofstream(p) << "{";
  std::filesystem::resize_file(p, static_cast<std::uintmax_t>(bytes));
  return p.string();
}

TEST(Regression, MissionVehicleEffectAndPathFilesOverTheirLimitAreRefusedBeforeReading) {
  // Mission, vehicle, effect and waypoint-path files used to be read whole whatever their size
  // (a 20 GB file named by mistake filled the memory). Each reader now refuses a file over its
  // limit by its size, naming the file, the size and the limit.
  struct Case {
    std::vector<std::string> args;
    std::string file, expected;
  };
  const std::string vehicle = sparseFile("vehicle.json", wattswath::energy::kMaxVehicleFileBytes + 1);
  const std::string mission = sparseFile("mission.plan", 64LL * 1024 * 1024 + 1);
  const std::string effect = sparseFile("effect.json", 16LL * 1024 * 1024 + 1);
  const std::string path = sparseFile("path.txt", wattswath::logs::kMaxPathFileBytes + 1);
  const std::vector<Case> cases = {
      {{"predict", sourcePath("tests/data/good/mission_survey.plan"), "--vehicle", vehicle}, vehicle,
       "bytes; vehicle files of at most 16777216 bytes (16 MiB) are read"},
      {{"predict", mission, "--vehicle", "data/vehicles/iris.json"}, mission,
       "bytes; mission files of at most 67108864 bytes (64 MiB) are read"},
      {{"simulate", "--vehicle", "data/vehicles/iris.json", "--path", path, "--out", path + ".csv"}, path,
       "bytes; path files of at most 67108864 bytes (64 MiB) are read"},
  };
  for (const auto& c : cases) {
    const auto r = runCli(c.args, 20);
    EXPECT_NE(r.status, 0) << c.file;
    EXPECT_NE(r.err.find(c.file + ": the file has "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
  }
  try {
    wattswath::calibration::readEffectFile(effect);
    ADD_FAILURE() << "an oversized effect file was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("effect files of at most 16777216 bytes (16 MiB) are read"), std::string::npos) << e.what();
  }
  for (const auto& f : {vehicle, mission, effect, path}) std::filesystem::remove(f);
}

}  // namespace

// With --json an error printed nothing on stdout: a pipeline parsing it got no document. It is now
// {"error": message} on stdout (and the message on stderr), exit status 1.
TEST(Regression, AnErrorUnderJsonIsAJsonObjectOnStdout) {
  using wattswath::test::run;
  const auto r = run(wattswath::test::cliBinary() + " log info " + wattswath::test::sourcePath("tests/data/bad/log_empty.csv") +
                     " --json 2>/dev/null");
  EXPECT_EQ(r.status, 1);
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_NE(j.at("error").get<std::string>().find("empty file (0 bytes)"), std::string::npos) << r.output;
  // Without --json, stdout stays empty.
  EXPECT_EQ(run(wattswath::test::cliBinary() + " log info " + wattswath::test::sourcePath("tests/data/bad/log_empty.csv") +
                " 2>/dev/null")
                .output,
            "");
}
