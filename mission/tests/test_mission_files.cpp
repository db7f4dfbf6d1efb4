// Mission files in: QGroundControl .plan and QGC WPL 110 .waypoints as QGC, Mission Planner and
// pymavlink write them, the shared real and SITL missions, and the malformed-mission corpus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bad_corpus.hpp"
#include "test_util.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/flight.hpp"

using namespace wattswath::mission;
using wattswath::test::readAll;
using wattswath::test::sourcePath;

namespace {

/// The error message `read` throws (MissionError), or "" when it does not throw.
template <typename F>
std::string errorOf(F read) {
  try {
    read();
  } catch (const MissionError& e) {
    return e.what();
  }
  return "";
}

const std::string kHome = "0\t1\t0\t16\t0\t0\t0\t0\t43.7160040\t10.4613040\t7.15\t1\n";
const std::string kTakeoff = "1\t0\t3\t22\t0\t0\t0\t0\t43.7160040\t10.4613040\t10\t1\n";

}  // namespace

TEST(MissionFiles, QgcSurveyPlanReadsItsStoredItems) {
  const Mission m = readMission(sourcePath("tests/data/good/mission_survey.plan"));
  EXPECT_EQ(m.format, "plan");
  EXPECT_TRUE(m.home_known);
  EXPECT_DOUBLE_EQ(m.home.lat_deg, 43.716004);
  EXPECT_DOUBLE_EQ(m.home.alt_m, 7.2);
  EXPECT_EQ(m.firmware_type, 3);
  EXPECT_EQ(m.vehicle_type, 2);
  EXPECT_DOUBLE_EQ(m.plan_cruise_speed_mps, 15.0);  // an integer in the file
  EXPECT_DOUBLE_EQ(m.plan_hover_speed_mps, 5.5);
  // take-off, speed, the survey's 10 stored items (8 waypoints, trigger on and off), return
  ASSERT_EQ(m.items.size(), 13u);
  EXPECT_EQ(m.items[0].command, 22);
  EXPECT_TRUE(std::isnan(m.items[0].param[3]));  // null in the file
  EXPECT_EQ(m.items[1].command, 178);
  EXPECT_EQ(m.items[3].command, 206);
  EXPECT_DOUBLE_EQ(m.items[3].param[0], 25.0);
  EXPECT_EQ(m.items[12].command, 20);
  for (size_t i = 0; i < m.items.size(); ++i) EXPECT_EQ(m.items[i].seq, static_cast<int>(i) + 1);
  EXPECT_NE(m.items[5].where.find("mission.items[2].TransectStyleComplexItem.Items[3]"), std::string::npos) << m.items[5].where;
  EXPECT_TRUE(m.warnings.empty());
}

TEST(MissionFiles, CorridorScanAndOldCoordinateItemsRead) {
  const std::string plan = R"({"fileType": "Plan", "version": 1, "groundStation": "QGroundControl",
    "mission": {"version": 2, "firmwareType": 12, "plannedHomePosition": [47.3977, 8.5456, 488],
      "items": [
        {"type": "SimpleItem", "command": 22, "frame": 3, "autoContinue": true, "doJumpId": 1,
         "params": [15, 0, 0, null], "coordinate": [47.3977, 8.5456, 30]},
        {"type": "ComplexItem", "complexItemType": "CorridorScan", "version": 2, "TransectStyleComplexItem": {"Items": [
          {"type": "SimpleItem", "command": 16, "frame": 3, "autoContinue": true, "doJumpId": 2, "params": [0, 0, 0, null, 47.398, 8.546, 30]},
          {"type": "SimpleItem", "command": 16, "frame": 3, "autoContinue": true, "doJumpId": 3, "params": [0, 0, 0, null, 47.399, 8.546, 30]}]}},
        {"type": "SimpleItem", "command": 21, "frame": 3, "autoContinue": true, "doJumpId": 4, "params": [0, 0, 0, null, null, null, 0]}]},
    "geoFence": {"version": 2, "circles": [], "polygons": []}, "rallyPoints": {"version": 2, "points": []}})";
  const Mission m = parseQgcPlan(plan, "corridor.plan");
  ASSERT_EQ(m.items.size(), 4u);
  EXPECT_DOUBLE_EQ(m.items[0].alt_m, 30.0);  // params[4] + coordinate, converted as QGC does
  EXPECT_EQ(m.firmware_type, 12);
  EXPECT_DOUBLE_EQ(m.plan_cruise_speed_mps, 0.0);  // absent
  EXPECT_EQ(m.items[2].seq, 3);
  EXPECT_FALSE(hasPosition(m.items[3]));  // land in place: lat/lon null
  // QGroundControl's CorridorScanComplexItem::load refuses any version but 2 (version 1 stored no
  // items); the version was not checked.
  for (const char* version : {"1", "3"}) {
    std::string v = plan;
    v.replace(v.find("\"CorridorScan\", \"version\": 2"), std::string("\"CorridorScan\", \"version\": 2").size(),
              std::string("\"CorridorScan\", \"version\": ") + version);
    const std::string e = errorOf([&] { parseQgcPlan(v, "corridor.plan"); });
    EXPECT_NE(e.find(std::string("corridor.plan: mission.items[1]: CorridorScan field 'version' = ") + version + ", expected 2"),
              std::string::npos) << e;
  }
}

// A JSON null latitude in a .plan was reported as "latitude = nan": it is "null (unset)", as written.
TEST(MissionFiles, ANullInAPlanIsNamedNullNotNan) {
  const std::string plan = R"({"fileType": "Plan", "version": 1, "groundStation": "QGroundControl",
    "mission": {"version": 2, "firmwareType": 3, "plannedHomePosition": [43.716004, 10.461304, 50],
      "items": [
        {"type": "SimpleItem", "command": 22, "frame": 3, "autoContinue": true, "doJumpId": 1, "params": [0, 0, 0, null, null, null, 10]},
        {"type": "SimpleItem", "command": 16, "frame": 3, "autoContinue": true, "doJumpId": 2, "params": [0, 0, 0, null, null, null, 10]},
        {"type": "SimpleItem", "command": 20, "frame": 2, "autoContinue": true, "doJumpId": 3, "params": [0, 0, 0, 0, 0, 0, 0]}]},
    "geoFence": {"version": 2, "circles": [], "polygons": []}, "rallyPoints": {"version": 2, "points": []}})";
  const std::string e = errorOf([&] { parseQgcPlan(plan, "null.plan"); });
  EXPECT_NE(e.find("null.plan: mission.items[1]: NAV_WAYPOINT latitude = null (unset), expected a latitude in [-90, 90] deg"),
            std::string::npos) << e;
  // A .waypoints "nan" is a number that was written: named so.
  const std::string w = errorOf([&] {
    parseQgcWpl("QGC WPL 110\n" + kHome + "1\t0\t3\t16\t0\t0\t0\t0\tnan\t10.46\t10\t1\n", "nan.waypoints");
  });
  EXPECT_NE(w.find("nan.waypoints:3: NAV_WAYPOINT latitude = nan"), std::string::npos) << w;
}

TEST(MissionFiles, PlanDoJumpTargetIsTheDoJumpIdAndBecomesTheSeq) {
  auto j = readAll(sourcePath("tests/data/good/mission_survey.plan"));
  // Insert a DO_JUMP to doJumpId 2 (the speed change, item 2) before the return.
  const std::string rtl = "\"command\": 20,";
  const auto at = j.rfind("{", j.find(rtl));
  j.insert(at, R"({"autoContinue": true, "command": 177, "doJumpId": 99, "frame": 2,
                   "params": [2, 1, 0, 0, 0, 0, 0], "type": "SimpleItem"}, )");
  const Mission m = parseQgcPlan(j, "jump.plan");
  ASSERT_EQ(m.items[12].command, 177);
  EXPECT_DOUBLE_EQ(m.items[12].param[0], 2.0);
  EXPECT_EQ(unrollJumps(m).size(), 12u + 11u + 1u);  // 1..12, 2..12 once more, return (DO_JUMP left out)
}

TEST(MissionFiles, DecimalCommasInTabSeparatedLinesReadAsPoints) {
  const std::string path = sourcePath("tests/data/good/mission_decimal_commas.waypoints");
  const Mission m = readMission(path);  // Mission Planner in a comma locale: BOM, CR LF, tabs
  std::string dots = readAll(path);
  for (char& c : dots) c = c == ',' ? '.' : c;
  const Mission d = parseQgcWpl(dots, "dots.waypoints");
  EXPECT_EQ(m, d);
  // Neither QGroundControl nor a current Mission Planner reads the commas so: the reading is said.
  const auto said = [](const Mission& x) {
    return std::any_of(x.warnings.begin(), x.warnings.end(),
                       [](const std::string& w) { return w.find("decimal commas read as decimal points") != std::string::npos; });
  };
  EXPECT_TRUE(said(m));
  EXPECT_FALSE(said(d));
  EXPECT_DOUBLE_EQ(m.home.alt_m, 7.15);
  EXPECT_DOUBLE_EQ(m.items[1].param[1], 5.18);
  EXPECT_DOUBLE_EQ(m.items[4].alt_m, 12.5);
  // Space-separated: "43,7" could be two columns, so commas are refused there.
  const std::string spaced = "QGC WPL 110\n0 1 0 16 0 0 0 0 43.716 10.461 7 1\n1 0 3 16 0 0 0 0 43,7161 10.4614 10 1\n";
  EXPECT_NE(errorOf([&] { parseQgcWpl(spaced, "s.waypoints"); }).find("s.waypoints:3: latitude = \"43,7161\""), std::string::npos);
  const std::string two = "QGC WPL 110\n" + kHome + "1\t0\t3\t16\t0\t0\t0\t0\t43,71,61\t10.4614\t10\t1\n";
  EXPECT_NE(errorOf([&] { parseQgcWpl(two, "t.waypoints"); }).find("t.waypoints:3: latitude = \"43,71,61\", expected a number"),
            std::string::npos);
}

TEST(MissionFiles, WaypointsAcceptSpacesCommentsBlankLinesAndCrLf) {
  const std::string text = "QGC WPL 110\r\n# written by hand\r\n\r\n0 1 0 16 0 0 0 0 43.716004 10.461304 7.15 1\r\n"
                           "1  0  3  22  0 0 0 0  43.716004  10.461304  10  1\r\n2\t0\t3\t16\t0\t0\t0\t0\t43.7161\t10.4614\t10\t1\r\n";
  const Mission m = parseQgcWpl(text, "h.waypoints");
  ASSERT_EQ(m.items.size(), 2u);
  EXPECT_EQ(m.items[1].where, "h.waypoints:6");
  // Read as pymavlink reads them, but QGroundControl's MissionItem::load(QTextStream) splits on tabs
  // only and needs 12 fields, and Mission Planner splits on tabs and commas: said (it was silent).
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("h.waypoints:4: columns separated by spaces: QGroundControl and Mission Planner would not read "
                               "this file"),
            std::string::npos) << m.warnings[0];
  // A tab at the end of a row makes 13 fields for QGroundControl.
  const Mission trailing = parseQgcWpl("QGC WPL 110\n" + kHome + kTakeoff.substr(0, kTakeoff.size() - 1) + "\t\n", "t.waypoints");
  ASSERT_EQ(trailing.items.size(), 1u);
  ASSERT_EQ(trailing.warnings.size(), 1u);
  EXPECT_NE(trailing.warnings[0].find("t.waypoints:3: 13 tab-separated fields (a tab at the end of the line): QGroundControl "
                                      "would not read this file"),
            std::string::npos) << trailing.warnings[0];
  // Tab-separated rows, as the ground stations write them: nothing to say.
  EXPECT_TRUE(parseQgcWpl("QGC WPL 110\r\n" + kHome + kTakeoff, "ok.waypoints").warnings.empty());
}

TEST(MissionFiles, HomeRowVariants) {
  // Home row in frame 3: its altitude is not AMSL.
  Mission m = parseQgcWpl("QGC WPL 110\n0\t1\t3\t16\t0\t0\t0\t0\t43.716\t10.461\t5\t1\n" + kTakeoff, "f3.waypoints");
  EXPECT_TRUE(m.home_known);
  EXPECT_DOUBLE_EQ(m.home.alt_m, 0.0);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("f3.waypoints:2: home row frame = 3"), std::string::npos) << m.warnings[0];
  // Home (0, 0): the first position is used.
  m = parseQgcWpl("QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t0\t0\t0\t1\n" + kTakeoff, "zero.waypoints");
  EXPECT_FALSE(m.home_known);
  EXPECT_DOUBLE_EQ(m.home.lat_deg, 43.716004);
  // The warning says how to give the real home: predict's --launch (it said nothing of it); not
  // when the launch point is given.
  const auto says_launch = [](const Mission& x) {
    return std::any_of(x.warnings.begin(), x.warnings.end(), [](const std::string& w) {
      return w.find("zero.waypoints: no home position; the first position (zero.waypoints:3) is used as home, at altitude 0 m: "
                    "the autopilot sets home where the vehicle arms, so give that point with predict --launch LAT,LON") !=
             std::string::npos;
    });
  };
  EXPECT_TRUE(says_launch(m));
  ReadOptions launched;
  launched.distances_from = wattswath::geometry::GeoPoint{43.716, 10.461, 0.0};
  EXPECT_FALSE(says_launch(parseQgcWpl("QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t0\t0\t0\t1\n" + kTakeoff, "zero.waypoints", launched)));
  // No home row (Mission Planner: a first row numbered 1): every row is an item.
  m = parseQgcWpl("QGC WPL 110\n" + kTakeoff + "2\t0\t3\t16\t0\t0\t0\t0\t43.7161\t10.4614\t10\t1\n", "nohome.waypoints");
  EXPECT_FALSE(m.home_known);
  ASSERT_EQ(m.items.size(), 2u);
  EXPECT_EQ(m.items[1].seq, 2);
}

TEST(MissionFiles, HeaderAndFormatErrorsNameTheFile) {
  EXPECT_NE(errorOf([] { parseQgcWpl("QGC WPL 120\n", "v.waypoints"); }).find("v.waypoints:1: QGC WPL version 120 is not supported"),
            std::string::npos);
  EXPECT_NE(errorOf([] { parseQgcWpl("", "e.waypoints"); }).find("e.waypoints: empty file"), std::string::npos);
  EXPECT_NE(errorOf([] { parseQgcWpl("QGC WPL 110\n" + kHome, "h.waypoints"); }).find("no mission items"), std::string::npos);
  const auto dir = std::filesystem::temp_directory_path() / "wattswath_test_mission_files";
  std::filesystem::create_directories(dir);
  const std::string wrong = (dir / "looks_like_wpl.plan").string();
  std::ofstream(wrong) << "QGC WPL 110\n" << kHome << kTakeoff;
  EXPECT_NE(errorOf([&] { readMission(wrong); }).find("the extension says .plan (JSON) but the content looks like QGC WPL 110"),
            std::string::npos);
  const std::string unknown = (dir / "mission.csv").string();
  std::ofstream(unknown) << "a,b\n";
  EXPECT_NE(errorOf([&] { readMission(unknown); }).find("unknown mission format"), std::string::npos);
  EXPECT_NE(errorOf([&] { readMission((dir / "missing.plan").string()); }).find("cannot open the file"), std::string::npos);
}

TEST(MissionFiles, UnknownCommandIsAnErrorOrWithLenientAWarningAndDropped) {
  const std::string path = sourcePath("tests/data/bad/mission_unknown_command.waypoints");
  EXPECT_NE(errorOf([&] { readMission(path); }).find("use --lenient to skip it"), std::string::npos);
  ReadOptions o;
  o.lenient = true;
  const Mission m = readMission(path, o);
  ASSERT_EQ(m.items.size(), 3u);  // take-off, waypoint, (gripper dropped), return
  EXPECT_EQ(m.items[2].seq, 4);   // the autopilot's numbering is kept
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("mission_unknown_command.waypoints:5: command = 211 (DO_GRIPPER)"), std::string::npos);
  EXPECT_NE(m.warnings[0].find("skipped (--lenient)"), std::string::npos);
}

// A navigation command moves the vehicle: leaving it out would fly another path, so --lenient does
// not skip it (it did, silently changing the route, until 2026-11-27: ArduPilot's NAV_ARC_WAYPOINT,
// NAV_PAYLOAD_PLACE and NAV_LOITER_TO_ALT test missions lost their arcs, descents and climbs).
TEST(MissionFiles, LenientNeverSkipsANavigationCommand) {
  const std::string path = sourcePath("tests/data/bad/mission_unknown_nav_command.waypoints");
  ReadOptions o;
  o.lenient = true;
  const std::string e = errorOf([&] { readMission(path, o); });
  EXPECT_NE(e.find("mission_unknown_nav_command.waypoints:5: command = 84 (NAV_VTOL_TAKEOFF)"), std::string::npos) << e;
  EXPECT_NE(e.find("not even with --lenient"), std::string::npos) << e;
}

// AP_Mission stops at a NAV_LAND or NAV_RETURN_TO_LAUNCH, so an item after it is never run: an
// unsupported command there is no error (ArduPilot's AUTO_LAND_TO_BRAKE test mission has a
// DO_GRIPPER after its landing), unless a DO_JUMP before the landing leads to it.
TEST(MissionFiles, AnUnsupportedCommandTheMissionNeverReachesIsKeptUnread) {
  const std::string head = "QGC WPL 110\n" + kHome + kTakeoff + "2\t0\t3\t16\t0\t0\t0\t0\t43.7161\t10.4614\t10\t1\n";
  const std::string land = "3\t0\t3\t21\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const std::string gripper = "4\t0\t2\t211\t1\t0\t0\t0\t0\t0\t0\t1\n";
  const Mission m = parseQgcWpl(head + land + gripper, "after_land.waypoints");
  ASSERT_EQ(m.items.size(), 4u);
  EXPECT_EQ(m.items[3].command, 211);  // kept as written, never run
  std::vector<std::string> notes;
  sequenceMission(m, &notes);
  bool said = false;
  for (const auto& n : notes) said = said || n.find("after_land.waypoints:6: items after NAV_LAND are never flown (1 ignored)") != std::string::npos;
  EXPECT_TRUE(said);
  // A DO_JUMP before the landing to the gripper reaches it: an error again.
  const std::string jump = "3\t0\t2\t177\t5\t1\t0\t0\t0\t0\t0\t1\n";
  const std::string reached = head + jump + "4\t0\t3\t21\t0\t0\t0\t0\t0\t0\t0\t1\n" + "5\t0\t2\t211\t1\t0\t0\t0\t0\t0\t0\t1\n";
  EXPECT_NE(errorOf([&] { parseQgcWpl(reached, "jump.waypoints"); }).find("jump.waypoints:7: command = 211 (DO_GRIPPER)"),
            std::string::npos);
}

// Found by fuzz_mission: a lenient read that skipped every item returned an empty mission.
TEST(MissionFiles, LenientReadOfOnlyUnsupportedItemsIsAnError) {
  ReadOptions o;
  o.lenient = true;
  const std::string text = "QGC WPL 110\n" + kHome + "1\t0\t2\t216\t0\t0\t0\t0\t0\t0\t0\t1\n";
  EXPECT_NE(errorOf([&] { parseQgcWpl(text, "only23.waypoints", o); })
                .find("only23.waypoints: all 1 items have unsupported commands (skipped with --lenient), expected at least one"),
            std::string::npos);
}

TEST(MissionFiles, FarWaypointLimitIsAnOption) {
  const std::string path = sourcePath("tests/data/bad/mission_far_waypoint.waypoints");
  ReadOptions o;
  o.max_distance_m = 600e3;
  EXPECT_EQ(readMission(path, o).items.size(), 4u);
  o.max_distance_m = 5.0;
  const std::string e = errorOf([&] { readMission(path, o); });
  EXPECT_NE(e.find("mission_far_waypoint.waypoints:4: NAV_WAYPOINT at (43.7161, 10.4614) is 0.013 km from home"), std::string::npos) << e;
  EXPECT_NE(e.find("expected at most 0.005 km"), std::string::npos) << e;
  o.max_distance_m = -1.0;
  EXPECT_THROW(readMission(path, o), std::invalid_argument);
}

// Each malformed mission of tests/data/bad/ (LIBRARY_EXPECTED.tsv) is refused with an error naming
// the file, the line or item, the field, the value and what was expected.
TEST(MissionFiles, MalformedCorpusGivesClearErrors) {
  int n = 0;
  for (const auto& c : wattswath::test::loadCases("LIBRARY_EXPECTED.tsv")) {
    if (c.command != "mission") continue;
    ++n;
    const std::string rel = "tests/data/bad/" + c.file;
    const std::string e = errorOf([&] { readMission(sourcePath(rel)); });
    ASSERT_FALSE(e.empty()) << c.file << " was accepted";
    for (const auto& s : c.substrings) EXPECT_NE(e.find(s), std::string::npos) << c.file << ": lacks '" << s << "' in\n" << e;
  }
  EXPECT_GE(n, 20);
}

#ifdef WATTSWATH_TEST_SHARED_DATA
// The missions of the real IRIS+ flights (rebuilt from their logs) and of the SITL flights read
// without warnings; the SITL ones item for item as their items.csv lists them.
TEST(MissionFilesShared, IrisAndSitlMissionsRead) {
  namespace fs = std::filesystem;
  int files = 0;
  for (const char* dir : {"iris-flights", "sitl"}) {
    for (const auto& e : fs::directory_iterator(wattswath::test::sharedData(dir))) {
      const std::string name = e.path().filename().string();
      if (e.path().extension() != ".waypoints" || name.rfind("plan__", 0) == 0) continue;
      ++files;
      const Mission m = readMission(e.path().string());
      EXPECT_TRUE(m.home_known) << name;
      EXPECT_TRUE(m.warnings.empty()) << name << ": " << m.warnings.front();
      ASSERT_GE(m.items.size(), 5u) << name;
      EXPECT_EQ(m.items.front().command, static_cast<int>(Command::NavTakeoff)) << name;
      EXPECT_EQ(m.items.back().command, static_cast<int>(Command::NavReturnToLaunch)) << name;
      EXPECT_EQ(unrollJumps(m).size(), m.items.size()) << name;
      const std::string csv = e.path().string().substr(0, e.path().string().size() - 10) + ".items.csv";
      if (!fs::exists(csv)) continue;
      std::istringstream in(readAll(csv));
      std::string row;
      std::getline(in, row);
      while (std::getline(in, row)) {
        const int item = std::atoi(row.c_str());
        if (item < 1) continue;  // "landed"
        ASSERT_LE(item, static_cast<int>(m.items.size())) << name;
        EXPECT_EQ(m.items[item - 1].seq, item);
        EXPECT_EQ(commandName(m.items[item - 1].command), row.substr(row.find(',') + 1, row.find(',', row.find(',') + 1) - row.find(',') - 1))
            << name << " item " << item;
      }
    }
  }
  EXPECT_EQ(files, 6);
}
#endif

// QGroundControl's AltitudeMode 3 ("calculated above terrain") stores params[6] and
// AMSLAltAboveTerrain as null until its terrain query answers; QGroundControl's own test plans are
// saved so. Such an item is flown at its Altitude above home's altitude (flat ground) and said; a
// stored AMSLAltAboveTerrain is the altitude. They were refused as "altitude = nan".
TEST(MissionFiles, APlanItemCalculatedAboveTerrainWithoutItsAltitudeIsFlownAboveHomeAndSaid) {
  auto plan = [](const std::string& amsl) {
    return R"({"fileType":"Plan","version":1,"groundStation":"QGroundControl","mission":{"version":2,"firmwareType":3,
      "vehicleType":2,"cruiseSpeed":15,"hoverSpeed":5,"plannedHomePosition":[43.716,10.4613,584],"items":[
      {"type":"SimpleItem","command":22,"frame":3,"autoContinue":true,"params":[0,0,0,null,43.716,10.4613,30],
       "AltitudeMode":1,"Altitude":30,"AMSLAltAboveTerrain":null,"doJumpId":1},
      {"type":"SimpleItem","command":16,"frame":0,"autoContinue":true,"params":[0,0,0,null,43.717,10.4613,null],
       "AltitudeMode":3,"Altitude":80,"AMSLAltAboveTerrain":)" + amsl + R"(,"doJumpId":2},
      {"type":"SimpleItem","command":20,"frame":2,"autoContinue":true,"params":[0,0,0,0,0,0,0],"doJumpId":3}]},
      "geoFence":{"circles":[],"polygons":[],"version":2},"rallyPoints":{"points":[],"version":2}})";
  };
  const Mission m = parseQgcPlan(plan("null"), "terrain.plan");
  EXPECT_DOUBLE_EQ(m.items[1].alt_m, 584.0 + 80.0);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("terrain.plan: mission.items[1]: 1 item(s) in AltitudeMode 3 (calculated above terrain) have "
                               "no AMSL altitude stored"),
            std::string::npos) << m.warnings[0];
  const Mission stored = parseQgcPlan(plan("702.5"), "stored.plan");
  EXPECT_DOUBLE_EQ(stored.items[1].alt_m, 702.5);
  EXPECT_TRUE(stored.warnings.empty());
}

// Text a reader cannot take is named for what it is: UTF-16 (Notepad's "Unicode"), a NUL byte (a
// damaged file) by line and column; lines ended by CR alone are read as lines. Before, the first
// was shown as raw bytes, the second cut the message at the NUL, and the third echoed the whole
// file as its "header".
TEST(MissionFiles, Utf16NulBytesAndCrOnlyLineEndsAreNamedOrRead) {
  const std::string wpl = "QGC WPL 110\n" + kHome + kTakeoff + "2\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  std::string cr = wpl;
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  EXPECT_EQ(parseQgcWpl(cr, "mac.waypoints").items.size(), 2u);
  std::string utf16 = "\xFF\xFE";
  for (char c : wpl) utf16 += std::string{c, '\0'};
  EXPECT_NE(errorOf([&] { parseQgcWpl(utf16, "u16.waypoints"); }).find("u16.waypoints: the file is UTF-16 text, expected UTF-8"),
            std::string::npos);
  std::string nul = wpl;
  nul[wpl.find("22\t") + 3] = '\0';
  EXPECT_NE(errorOf([&] { parseQgcWpl(nul, "nul.waypoints"); }).find("nul.waypoints:3: a NUL byte at column 10"),
            std::string::npos) << errorOf([&] { parseQgcWpl(nul, "nul.waypoints"); });
  EXPECT_NE(errorOf([&] { parseQgcPlan(std::string("{\"a\":\0}", 7), "nul.plan"); }).find("NUL byte"), std::string::npos);
}

// What QGroundControl loads and ArduPilot or PX4 fly is read, not refused: a null home altitude
// (JsonHelper::loadGeoCoordinate takes it as unknown) when no item needs it, a mission version other
// than 2 (QGC does not check it), DO_CHANGE_SPEED -2 (MAVLink: back to the default speed).
TEST(MissionFiles, WhatQgcLoadsIsReadWithANote) {
  auto plan = [](const std::string& home_alt, int version, int frame, double alt, double speed) {
    return std::string(R"({"fileType":"Plan","version":1,"groundStation":"QGroundControl","mission":{"version":)") +
           std::to_string(version) + R"(,"firmwareType":12,"vehicleType":2,"plannedHomePosition":[43.716,10.4613,)" +
           home_alt + R"(],"items":[
      {"type":"SimpleItem","command":22,"frame":3,"autoContinue":true,"params":[0,0,0,null,43.716,10.4613,30],"doJumpId":1},
      {"type":"SimpleItem","command":178,"frame":2,"autoContinue":true,"params":[1,)" + std::to_string(speed) +
           R"(,-1,0,0,0,0],"doJumpId":2},
      {"type":"SimpleItem","command":16,"frame":)" + std::to_string(frame) + R"(,"autoContinue":true,"params":[0,0,0,null,43.717,10.4613,)" +
           std::to_string(alt) + R"(],"doJumpId":3},
      {"type":"SimpleItem","command":20,"frame":2,"autoContinue":true,"params":[0,0,0,0,0,0,0],"doJumpId":4}]}})";
  };
  auto notes = [](const Mission& m) {
    std::string all;
    for (const auto& w : m.warnings) all += w + "\n";
    return all;
  };
  const Mission unknown = parseQgcPlan(plan("null", 2, 3, 30, 5), "h.plan");
  EXPECT_DOUBLE_EQ(unknown.home.alt_m, 0.0);
  EXPECT_NE(notes(unknown).find("h.plan: mission.plannedHomePosition: altitude null (QGroundControl loads it as unknown)"),
            std::string::npos) << notes(unknown);
  EXPECT_NE(errorOf([&] { parseQgcPlan(plan("null", 2, 0, 630, 5), "amsl.plan"); })
                .find("amsl.plan: mission.items[2]: frame 0 (altitude above sea level) needs the home altitude, and "
                      "plannedHomePosition[2] is null"),
            std::string::npos);
  const Mission v3 = parseQgcPlan(plan("600", 3, 3, 30, 5), "v.plan");
  EXPECT_NE(notes(v3).find("v.plan: mission: field 'version' = 3, where QGroundControl writes 2 and reads any"), std::string::npos)
      << notes(v3);
  EXPECT_EQ(notes(parseQgcPlan(plan("600", 2, 3, 30, 5), "ok.plan")), "");
  EXPECT_NO_THROW(parseQgcPlan(plan("600", 2, 3, 30, -2), "default.plan"));
  EXPECT_NE(errorOf([&] { parseQgcPlan(plan("600", 2, 3, 30, 0), "zero.plan"); }).find("param2 (speed) = 0"), std::string::npos);
  EXPECT_NE(errorOf([&] { parseQgcPlan(plan("600", 2, 3, 30, -3), "minus3.plan"); }).find("param2 (speed) = -3"), std::string::npos);
}

// A yaw of NaN ("unchanged") is written to .waypoints as Mission Planner writes it, NaN, and read
// back the same; it was written 0, a commanded heading of north at every PX4 waypoint.
TEST(MissionFiles, AnUnchangedYawIsWrittenAsNaNAndReadBack) {
  const std::string text = "QGC WPL 110\n" + kHome + "1\t0\t3\t22\t0\t0\t0\tNaN\t43.7160040\t10.4613040\t10\t1\n";
  const Mission m = parseQgcWpl(text, "yaw.waypoints");
  ASSERT_TRUE(std::isnan(m.items[0].param[3]));
  const std::string written = toQgcWpl(m);
  EXPECT_NE(written.find("\t22\t0\t0\t0\tNaN\t"), std::string::npos) << written;
  EXPECT_EQ(parseQgcWpl(written, "again.waypoints"), m);
}
