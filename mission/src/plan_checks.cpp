// The loaders a written `.plan` must pass, as rules: QGroundControl's JSON loader (keys, types,
// values) and Mission Planner's (Json.NET deserialising into its MissionFile classes).
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "wattswath/mission/planned_mission.hpp"

namespace wattswath::mission {
namespace {

using nlohmann::json;
using vt = json::value_t;

constexpr int kCmdWaypoint = 16;  // MAV_CMD_NAV_WAYPOINT
constexpr int kCmdTakeoff = 22;   // MAV_CMD_NAV_TAKEOFF

/// QGroundControl's JsonHelper::validateKeys in short: `key` present with the `type` (numbers
/// accept integers and reals, integers only integers); a problem recorded otherwise.
class QgcRules {
 public:
  std::vector<std::string> problems;

  bool need(const json& obj, const std::string& where, const std::string& key, vt type) {
    if (!obj.is_object() || !obj.contains(key)) {
      problems.push_back(where + ": missing key '" + key + "'");
      return false;
    }
    const auto t = obj.at(key).type();
    const bool is_int = t == vt::number_integer || t == vt::number_unsigned;
    const bool number_ok = type == vt::number_float && (is_int || t == vt::number_float);
    const bool int_ok = type == vt::number_integer && is_int;
    if (!(t == type || number_ok || int_ok)) {
      problems.push_back(where + ": key '" + key + "' has the wrong type");
      return false;
    }
    return true;
  }

  void item(const json& it, size_t i, int expected_id) {
    const std::string w = "mission item " + std::to_string(i);
    if (need(it, w, "type", vt::string) && it["type"] != "SimpleItem") problems.push_back(w + ": type must be \"SimpleItem\"");
    need(it, w, "frame", vt::number_integer);
    need(it, w, "command", vt::number_integer);
    need(it, w, "autoContinue", vt::boolean);
    if (need(it, w, "doJumpId", vt::number_integer) && it["doJumpId"] != expected_id)
      problems.push_back(w + ": doJumpId " + it["doJumpId"].dump() + ", expected " + std::to_string(expected_id));
    if (!need(it, w, "params", vt::array)) return;
    const auto& p = it["params"];
    if (p.size() != 7) problems.push_back(w + ": params must hold 7 values");
    for (const auto& v : p)
      if (!v.is_number() && !v.is_null()) problems.push_back(w + ": params must be numbers or null");
    if (p.size() == 7 && (it["command"] == kCmdWaypoint || it["command"] == kCmdTakeoff)) {
      if (!p[4].is_number() || !p[5].is_number() || std::abs(p[4].get<double>()) > 90.0 ||
          std::abs(p[5].get<double>()) > 180.0)
        problems.push_back(w + ": latitude/longitude out of range");
    }
  }

  void mission(const json& mi) {
    if (need(mi, "mission", "version", vt::number_integer) && mi["version"] != 2) problems.push_back("mission: version must be 2");
    if (need(mi, "mission", "firmwareType", vt::number_integer)) {
      const int f = mi["firmwareType"];
      if (f != 0 && f != 3 && f != 12) problems.push_back("mission: firmwareType " + std::to_string(f) + " unknown");
    }
    // Optional in QGC's loader (MissionController::_loadJsonMissionFileV2), numbers when present.
    for (const char* k : {"vehicleType", "cruiseSpeed", "hoverSpeed"})
      if (mi.contains(k)) need(mi, "mission", k, std::string(k) == "vehicleType" ? vt::number_integer : vt::number_float);
    if (need(mi, "mission", "plannedHomePosition", vt::array) && mi["plannedHomePosition"].size() != 3)
      problems.push_back("mission: plannedHomePosition must be [lat, lon, alt]");
    if (!need(mi, "mission", "items", vt::array)) return;
    if (mi["items"].empty()) problems.push_back("mission: items must contain at least one item");
    for (size_t i = 0; i < mi["items"].size(); ++i) item(mi["items"][i], i, static_cast<int>(i) + 1);
  }

  void geoFence(const json& g) {
    if (need(g, "geoFence", "version", vt::number_integer) && g["version"] != 2) problems.push_back("geoFence: version must be 2");
    need(g, "geoFence", "circles", vt::array);
    if (!need(g, "geoFence", "polygons", vt::array)) return;
    for (size_t i = 0; i < g["polygons"].size(); ++i) {
      const auto& p = g["polygons"][i];
      const std::string w = "geoFence polygon " + std::to_string(i);
      need(p, w, "inclusion", vt::boolean);
      need(p, w, "version", vt::number_integer);
      if (!need(p, w, "polygon", vt::array)) continue;
      if (p["polygon"].size() < 3) problems.push_back(w + ": fewer than 3 vertices");
      for (const auto& v : p["polygon"])
        if (!v.is_array() || v.size() != 2) problems.push_back(w + ": vertices must be [lat, lon]");
    }
  }
};

/// How Json.NET reads a JSON value into a C# member of Mission Planner's MissionFile classes.
enum class Net {
  Int,          ///< int: an integer token only (5.0 and null are errors)
  IntOpt,       ///< int?: an integer or null
  Bool,         ///< bool: true or false only
  BoolOpt,      ///< bool?: true, false or null
  Double,       ///< double: a number
  Str,          ///< string: a string or null
  Doubles,      ///< List<double>: null, or an array of numbers
  DoublesOpt,   ///< List<double?>: null, or an array of numbers or nulls
  DoublesList,  ///< List<List<double>>: null, or an array of arrays of numbers
  DoublesOptList,  ///< List<List<double?>>
  Object,       ///< a class: null or an object (its members checked by their schema)
  Objects       ///< List<class>: null or an array of objects
};

using Schema = std::map<std::string, std::pair<Net, std::string>>;  // member -> (kind, schema of objects)

/// MissionFile's classes (ArduPilot/MissionPlanner ExtLibs/Utilities/MissionFile.cs); members
/// Json.NET does not know are ignored, as its default MissingMemberHandling.Ignore does.
const std::map<std::string, Schema>& missionFileClasses() {
  static const std::map<std::string, Schema> classes = {
      {"RootObject", {{"fileType", {Net::Str, ""}}, {"groundStation", {Net::Str, ""}}, {"version", {Net::Int, ""}},
                      {"mission", {Net::Object, "Mission"}}, {"geoFence", {Net::Object, "GeoFence"}},
                      {"rallyPoints", {Net::Object, "RallyPoints"}}}},
      {"Mission", {{"cruiseSpeed", {Net::Int, ""}}, {"firmwareType", {Net::Int, ""}}, {"hoverSpeed", {Net::Int, ""}},
                   {"items", {Net::Objects, "Item"}}, {"plannedHomePosition", {Net::Doubles, ""}},
                   {"vehicleType", {Net::Int, ""}}, {"version", {Net::Int, ""}}}},
      {"Item", {{"autoContinue", {Net::Bool, ""}}, {"command", {Net::Int, ""}}, {"doJumpId", {Net::Int, ""}},
                {"frame", {Net::Int, ""}}, {"params", {Net::DoublesOpt, ""}}, {"type", {Net::Str, ""}},
                {"TransectStyleComplexItem", {Net::Object, "TransectStyleComplexItem"}}, {"angle", {Net::IntOpt, ""}},
                {"complexItemType", {Net::Str, ""}}, {"entryLocation", {Net::IntOpt, ""}},
                {"flyAlternateTransects", {Net::BoolOpt, ""}}, {"polygon", {Net::DoublesOptList, ""}},
                {"splitConcavePolygons", {Net::BoolOpt, ""}}, {"version", {Net::IntOpt, ""}}}},
      {"TransectStyleComplexItem",
       {{"CameraCalc", {Net::Object, "CameraCalc"}}, {"CameraShots", {Net::Int, ""}},
        {"CameraTriggerInTurnAround", {Net::Bool, ""}}, {"FollowTerrain", {Net::Bool, ""}},
        {"HoverAndCapture", {Net::Bool, ""}}, {"Items", {Net::Objects, "Item"}}, {"Refly90Degrees", {Net::Bool, ""}},
        {"TurnAroundDistance", {Net::Int, ""}}, {"VisualTransectPoints", {Net::DoublesList, ""}},
        {"version", {Net::Int, ""}}}},
      {"CameraCalc", {{"AdjustedFootprintFrontal", {Net::Int, ""}}, {"AdjustedFootprintSide", {Net::Int, ""}},
                      {"CameraName", {Net::Str, ""}}, {"DistanceToSurface", {Net::Int, ""}},
                      {"DistanceToSurfaceRelative", {Net::Bool, ""}}, {"version", {Net::Int, ""}}}},
      {"GeoFence", {{"circles", {Net::Objects, "Circle"}}, {"polygons", {Net::Objects, "Polygon"}},
                    {"version", {Net::Int, ""}}}},
      {"Circle", {{"circle", {Net::Object, "Circle2"}}, {"inclusion", {Net::Bool, ""}}, {"version", {Net::Int, ""}}}},
      {"Circle2", {{"center", {Net::Doubles, ""}}, {"radius", {Net::Double, ""}}}},
      {"Polygon", {{"inclusion", {Net::Bool, ""}}, {"polygon", {Net::DoublesList, ""}}, {"version", {Net::Int, ""}}}},
      {"RallyPoints", {{"points", {Net::DoublesList, ""}}, {"version", {Net::Int, ""}}}}};
  return classes;
}

bool isInt32(const json& v) {
  if (v.is_number_unsigned()) return v.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<int>::max());
  return v.is_number_integer() && v.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
         v.get<std::int64_t>() <= std::numeric_limits<int>::max();
}

bool numbers(const json& v, bool nulls_ok) {
  if (!v.is_array()) return false;
  for (const auto& e : v)
    if (!e.is_number() && !(nulls_ok && e.is_null())) return false;
  return true;
}

/// Json.NET's verdict on `v` read as `kind` (true: it deserialises).
bool readsAs(const json& v, Net kind) {
  switch (kind) {
    case Net::Int: return isInt32(v);
    case Net::IntOpt: return v.is_null() || isInt32(v);
    case Net::Bool: return v.is_boolean();
    case Net::BoolOpt: return v.is_null() || v.is_boolean();
    case Net::Double: return v.is_number();
    case Net::Str: return v.is_null() || v.is_string();
    case Net::Doubles: return v.is_null() || numbers(v, false);
    case Net::DoublesOpt: return v.is_null() || numbers(v, true);
    case Net::DoublesList:
    case Net::DoublesOptList:
      if (v.is_null()) return true;
      if (!v.is_array()) return false;
      for (const auto& e : v)
        if (!e.is_null() && !numbers(e, kind == Net::DoublesOptList)) return false;
      return true;
    case Net::Object: return v.is_null() || v.is_object();
    case Net::Objects: return v.is_null() || v.is_array();
  }
  return false;
}

/// Deserialises `obj` as class `cls` the way Json.NET would, recording what it refuses.
void readClass(const json& obj, const std::string& cls, const std::string& where, std::vector<std::string>& problems) {
  for (const auto& [key, spec] : missionFileClasses().at(cls)) {
    if (!obj.contains(key)) continue;  // absent: the C# default
    const json& v = obj.at(key);
    if (!readsAs(v, spec.first)) {
      problems.push_back(where + "." + key + " = " + v.dump() + ": Mission Planner reads it as " + cls + "." + key +
                         (spec.first == Net::Int ? " (int: a JSON integer, not a real or null)" : ", of another type"));
      continue;
    }
    if (spec.first == Net::Object && v.is_object()) readClass(v, spec.second, where + "." + key, problems);
    if (spec.first == Net::Objects && v.is_array())
      for (size_t i = 0; i < v.size(); ++i) {
        const std::string w = where + "." + key + "[" + std::to_string(i) + "]";
        if (v[i].is_object()) readClass(v[i], spec.second, w, problems);
        else if (!v[i].is_null()) problems.push_back(w + ": Mission Planner expects an object");
      }
  }
}

/// MissionFile.ConvertToLocationwps on the deserialised plan: home [0..2], every item's params[0..6].
void convertToLocationwps(const json& mission, std::vector<std::string>& problems) {
  const json& home = mission.value("plannedHomePosition", json());
  if (!home.is_array() || home.size() < 3) problems.push_back("mission.plannedHomePosition: Mission Planner needs 3 numbers");
  const json& items = mission.value("items", json());
  if (!items.is_array()) {
    problems.push_back("mission.items: Mission Planner needs a list of items");
    return;
  }
  auto params7 = [&](const json& it, const std::string& w) {
    if (!it.contains("params") || !it["params"].is_array() || it["params"].size() < 7)
      problems.push_back(w + ".params: Mission Planner reads params[0..6] (7 values needed)");
  };
  for (size_t i = 0; i < items.size(); ++i) {
    const json& it = items[i];
    const std::string w = "mission.items[" + std::to_string(i) + "]";
    if (!it.is_object()) continue;
    if (it.value("type", "") == "SimpleItem") params7(it, w);
    if (it.value("type", "") != "ComplexItem") continue;
    const json& tsci = it.value("TransectStyleComplexItem", json());
    if (!tsci.is_object() || !tsci.contains("Items") || !tsci["Items"].is_array()) {
      problems.push_back(w + ": Mission Planner reads a ComplexItem's TransectStyleComplexItem.Items");
      continue;
    }
    for (size_t k = 0; k < tsci["Items"].size(); ++k)
      params7(tsci["Items"][k], w + ".TransectStyleComplexItem.Items[" + std::to_string(k) + "]");
  }
}

}  // namespace

std::vector<std::string> checkQgcPlan(const std::string& json_text) {
  QgcRules r;
  json j;
  try {
    j = json::parse(json_text);
  } catch (const std::exception& e) {
    return {std::string("not JSON: ") + e.what()};
  }
  if (r.need(j, "plan", "fileType", vt::string) && j["fileType"] != "Plan") r.problems.push_back("plan: fileType must be \"Plan\"");
  if (r.need(j, "plan", "version", vt::number_integer) && j["version"] != 1) r.problems.push_back("plan: version must be 1");
  r.need(j, "plan", "groundStation", vt::string);
  if (r.need(j, "plan", "mission", vt::object)) r.mission(j["mission"]);
  if (j.contains("geoFence")) r.geoFence(j["geoFence"]);
  if (j.contains("rallyPoints")) {
    const auto& rp = j["rallyPoints"];
    if (r.need(rp, "rallyPoints", "version", vt::number_integer) && rp["version"] != 2)
      r.problems.push_back("rallyPoints: version must be 2");
    r.need(rp, "rallyPoints", "points", vt::array);
  }
  return r.problems;
}

std::vector<std::string> checkMissionPlannerPlan(const std::string& json_text) {
  json j;
  try {
    j = json::parse(json_text);
  } catch (const std::exception& e) {
    return {std::string("not JSON: ") + e.what()};
  }
  if (!j.is_object()) return {"plan: Mission Planner expects a JSON object"};
  std::vector<std::string> problems;
  readClass(j, "RootObject", "plan", problems);
  if (!problems.empty()) return problems;  // Json.NET stops at the first error; ConvertToLocationwps never runs
  if (!j.contains("mission") || !j["mission"].is_object()) return {"plan.mission: Mission Planner needs a mission"};
  convertToLocationwps(j["mission"], problems);
  return problems;
}

}  // namespace wattswath::mission
