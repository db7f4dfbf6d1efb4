// QGroundControl `.plan` reader, by QGC's own loading rules: PlanMasterController::loadFromFile,
// MissionController::_loadJsonMissionFileV2, MissionItem::load (SimpleItem), SurveyComplexItem /
// CorridorScanComplexItem / TransectStyleComplexItem::_load and JsonHelper's key validation.
#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "files_internal.hpp"
#include "wattswath/io/strict_json.hpp"

namespace wattswath::mission {
namespace {
using detail::fail;
using detail::numberText;
using nlohmann::json;

/// Items read so far and the doJumpId of each top-level SimpleItem (DO_JUMP targets refer to them).
struct PlanItems {
  std::vector<MissionItem> items;
  std::vector<std::pair<long, int>> jump_ids;  // (doJumpId, seq)
  /// Items in AltitudeMode 3 without a stored altitude: (index in items, height above terrain [m]).
  std::vector<std::pair<std::size_t, double>> above_terrain;
};

std::string shown(const json& v) {
  const std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

const json& required(const json& obj, const char* key, const std::string& where, const char* expected) {
  if (!obj.contains(key)) fail(where, "missing field '" + std::string(key) + "', expected " + expected);
  return obj.at(key);
}

/// A JSON number, or NaN for null when `null_ok` (QGC writes NaN as null).
double realOf(const json& v, const std::string& where, const std::string& field, bool null_ok) {
  if (null_ok && v.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!v.is_number()) fail(where, "field '" + field + "' = " + shown(v) + ", expected a number" + (null_ok ? " or null" : ""));
  return v.get<double>();
}

long integerOf(const json& v, const std::string& where, const std::string& field, long lo, long hi) {
  const double d = v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
  if (!(d == std::floor(d) && d >= lo && d <= hi))
    fail(where, "field '" + field + "' = " + shown(v) + ", expected an integer in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "]");
  return static_cast<long>(d);
}

std::string stringOf(const json& obj, const char* key, const std::string& where) {
  const json& v = required(obj, key, where, "a string");
  if (!v.is_string()) fail(where, "field '" + std::string(key) + "' = " + shown(v) + ", expected a string");
  return v.get<std::string>();
}

/// params[7], or the older params[4] + coordinate [lat, lon, alt] (QGC converts it the same way).
std::vector<double> paramsOf(const json& it, const std::string& where) {
  const json& p = required(it, "params", where, "an array of 7 numbers or nulls");
  json all = p;
  if (p.is_array() && p.size() == 4 && it.contains("coordinate") && it.at("coordinate").is_array())
    for (const auto& c : it.at("coordinate")) all.push_back(c);
  if (!all.is_array() || all.size() != 7)
    fail(where, "field 'params' = " + shown(p) + ", expected an array of 7 numbers or nulls");
  std::vector<double> out;
  for (std::size_t k = 0; k < 7; ++k) out.push_back(realOf(all[k], where, "params[" + std::to_string(k) + "]", true));
  return out;
}

/// QGC: when a positional item has any of its altitude keys it must have all three, numbers or null.
void checkAltitudeKeys(const json& it, const std::string& where) {
  const char* keys[3] = {"AltitudeMode", "Altitude", "AMSLAltAboveTerrain"};
  bool any = false;
  for (const char* k : keys) any = any || it.contains(k);
  if (!any) return;
  for (const char* k : keys) realOf(required(it, k, where, "a number or null (with the other altitude keys)"), where, k, true);
}

MissionItem simpleItem(const json& it, const std::string& where, int seq) {
  if (!it.is_object()) fail(where, "item = " + shown(it) + ", expected a JSON object");
  const std::string type = stringOf(it, "type", where);
  if (type != "SimpleItem") fail(where, "field 'type' = \"" + type + "\", expected \"SimpleItem\"");
  MissionItem m;
  m.seq = seq;
  m.where = where;
  m.command = static_cast<int>(integerOf(required(it, "command", where, "a MAV_CMD number"), where, "command", 0, 65535));
  m.frame = static_cast<int>(integerOf(required(it, "frame", where, "a MAV_FRAME number"), where, "frame", 0, 255));
  const json& ac = required(it, "autoContinue", where, "true or false");
  if (!ac.is_boolean()) fail(where, "field 'autoContinue' = " + shown(ac) + ", expected true or false");
  m.autocontinue = ac.get<bool>();
  const auto p = paramsOf(it, where);
  for (int k = 0; k < 4; ++k) m.param[k] = p[k];
  m.lat_deg = p[4];
  m.lon_deg = p[5];
  m.alt_m = p[6];
  if (isPositional(m.command)) checkAltitudeKeys(it, where);
  return m;
}

/// QGC's AltitudeMode 3 ("calculated above terrain", QGroundControlQmlGlobal::AltitudeModeCalcAboveTerrain):
/// the item is sent in MAV_FRAME_GLOBAL at AMSLAltAboveTerrain, the terrain height under it plus
/// Altitude, which QGC queries from its terrain data when it loads the plan. A file saved before
/// the query answered stores null for both: such an item is noted and placed later at Altitude
/// above home's altitude (flat terrain, placeTerrainItems). The last item of `out` is `it`'s.
void calcAboveTerrain(const json& it, PlanItems& out) {
  MissionItem& m = out.items.back();
  if (!isPositional(m.command) || !it.contains("AltitudeMode") || !it.at("AltitudeMode").is_number() ||
      it.at("AltitudeMode").get<double>() != 3.0 || std::isfinite(m.alt_m))
    return;
  const double amsl = realOf(it.at("AMSLAltAboveTerrain"), m.where, "AMSLAltAboveTerrain", true);
  if (std::isfinite(amsl)) {
    m.alt_m = amsl;
    return;
  }
  const double above = realOf(it.at("Altitude"), m.where, "Altitude", true);
  if (!std::isfinite(above)) {
    fail(m.where, "AltitudeMode 3 (calculated above terrain) with Altitude, AMSLAltAboveTerrain and params[6] all null, "
                  "expected the height above terrain in 'Altitude'");
  }
  out.above_terrain.emplace_back(out.items.size() - 1, above);
}

/// With plannedHomePosition's altitude null: refuses an item given above sea level (frame 0 or 5,
/// not one whose altitude is placed above terrain here), which would need it; otherwise takes 0 m
/// (every altitude is above home) and says so.
void homeAltitudeUnknown(const PlanItems& p, const std::string& where, Mission& m) {
  if (!std::isnan(m.home.alt_m)) return;
  for (std::size_t k = 0; k < p.items.size(); ++k) {
    const MissionItem& it = p.items[k];
    const bool placed = std::any_of(p.above_terrain.begin(), p.above_terrain.end(), [&](const auto& a) { return a.first == k; });
    if ((it.frame == 0 || it.frame == 5) && isPositional(it.command) && !placed) {
      fail(it.where, "frame " + std::to_string(it.frame) + " (altitude above sea level) needs the home altitude, and "
                     "plannedHomePosition[2] is null; give the home's altitude AMSL there");
    }
  }
  m.home.alt_m = 0.0;
  m.warnings.push_back(where + ".plannedHomePosition: altitude null (QGroundControl loads it as unknown); every item's "
                       "altitude is above home, so it is not needed");
}

/// Places the items calcAboveTerrain left without an altitude at their height above home's
/// altitude (no terrain data: flat ground at home's height assumed), and says so once.
void placeTerrainItems(PlanItems& p, Mission& m) {
  if (p.above_terrain.empty()) return;
  for (const auto& [k, above] : p.above_terrain) p.items[k].alt_m = m.home.alt_m + above;
  const MissionItem& first = p.items[p.above_terrain.front().first];
  m.warnings.push_back(first.where + ": " + std::to_string(p.above_terrain.size()) + " item(s) in AltitudeMode 3 (calculated "
                       "above terrain) have no AMSL altitude stored: QGroundControl fills it from terrain data when it loads "
                       "the plan; without terrain data the prediction flies them at their Altitude above home (flat ground at "
                       "home's height), the first at " + numberText(p.above_terrain.front().second) + " m");
}

/// The stored items of a survey / CorridorScan (TransectStyleComplexItem.Items), in order.
void transectItems(const json& it, const std::string& where, PlanItems& out) {
  const json& tsci = required(it, "TransectStyleComplexItem", where, "an object with the survey's Items");
  if (!tsci.is_object()) fail(where, "field 'TransectStyleComplexItem' = " + shown(tsci) + ", expected an object");
  const std::string inner = where + ".TransectStyleComplexItem";
  const json& items = required(tsci, "Items", inner, "the array of the items QGroundControl generated");
  if (!items.is_array()) fail(inner, "field 'Items' = " + shown(items) + ", expected an array of SimpleItems");
  for (std::size_t k = 0; k < items.size(); ++k) {
    const int seq = static_cast<int>(out.items.size()) + 1;
    out.items.push_back(simpleItem(items[k], inner + ".Items[" + std::to_string(k) + "]", seq));
    calcAboveTerrain(items[k], out);
  }
}

void complexItem(const json& it, const std::string& where, PlanItems& out) {
  const std::string kind = stringOf(it, "complexItemType", where);
  const std::string notStored = "\": QGroundControl generates its items when it loads the plan and does not store them, "
                                "so they cannot be read here; expected SimpleItems, a \"survey\" or a \"CorridorScan\"";
  if (kind == "survey") {
    const long version = integerOf(required(it, "version", where, "a number"), where, "version", 0, 1000);
    if (version == 2 || version == 3)
      fail(where, "survey field 'version' = " + std::to_string(version) + " (QGroundControl 3): its items are not stored "
                  "in the file, expected version 4 or 5 (open and save the plan in a current QGroundControl)");
    if (version != 4 && version != 5) fail(where, "survey field 'version' = " + std::to_string(version) + ", expected 4 or 5");
  } else if (kind == "CorridorScan") {
    // CorridorScanComplexItem::load refuses any version but 2 ("CorridorScan complex item version N
    // not supported"); version 1, of QGroundControl's first corridor scans, stored no items.
    const long version = integerOf(required(it, "version", where, "a number"), where, "version", 0, 1000);
    if (version != 2)
      fail(where, "CorridorScan field 'version' = " + std::to_string(version) + ", expected 2 (QGroundControl's "
                  "CorridorScanComplexItem::load refuses any other: \"complex item version " + std::to_string(version) +
                  " not supported\"; open and save the plan in a current QGroundControl)");
  } else {
    fail(where, "complexItemType \"" + kind + notStored);
  }
  transectItems(it, where, out);
}

void readItem(const json& it, const std::string& where, PlanItems& out) {
  if (!it.is_object()) fail(where, "item = " + shown(it) + ", expected a JSON object");
  const std::string type = stringOf(it, "type", where);
  if (type == "ComplexItem") return complexItem(it, where, out);
  if (type != "SimpleItem") fail(where, "field 'type' = \"" + type + "\", expected \"SimpleItem\" or \"ComplexItem\"");
  const int seq = static_cast<int>(out.items.size()) + 1;
  out.items.push_back(simpleItem(it, where, seq));
  calcAboveTerrain(it, out);
  if (it.contains("doJumpId"))
    out.jump_ids.emplace_back(integerOf(it.at("doJumpId"), where, "doJumpId", -1, 1000000000), seq);
}

/// QGC: a DO_JUMP's param1 is the doJumpId of its target; it becomes the target's seq.
void resolveJumps(PlanItems& p) {
  for (auto& it : p.items) {
    if (it.command != static_cast<int>(Command::DoJump)) continue;
    bool found = false;
    for (const auto& [id, seq] : p.jump_ids) {
      if (static_cast<double>(id) != it.param[0]) continue;
      it.param[0] = seq;
      found = true;
      break;
    }
    if (!found)
      fail(it.where, "DO_JUMP param1 (target doJumpId) = " + numberText(it.param[0]) +
                         ", expected the doJumpId of a SimpleItem of the mission");
  }
}

double speedOf(const json& mj, const char* key, const std::string& where) {
  if (!mj.contains(key)) return 0.0;
  const double v = realOf(mj.at(key), where, key, true);
  if (std::isnan(v)) return 0.0;
  if (!(std::isfinite(v) && v >= 0.0)) fail(where, "field '" + std::string(key) + "' = " + numberText(v) + ", expected a speed >= 0 m/s");
  return v;
}

void readHome(const json& mj, const std::string& where, Mission& m) {
  const json& h = required(mj, "plannedHomePosition", where, "[latitude, longitude, altitude AMSL]");
  if (!h.is_array() || h.size() != 3)
    fail(where, "field 'plannedHomePosition' = " + shown(h) + ", expected [latitude, longitude, altitude AMSL]");
  m.home = {realOf(h[0], where, "plannedHomePosition[0]", false), realOf(h[1], where, "plannedHomePosition[1]", false),
            realOf(h[2], where, "plannedHomePosition[2]", true)};
  // QGroundControl loads a null altitude as unknown (JsonHelper::loadGeoCoordinate); it is needed
  // only by items given above sea level, which homeAltitudeUnknown() checks once they are read.
  const bool alt_unknown = std::isnan(m.home.alt_m);
  if (alt_unknown) m.home.alt_m = 0.0;
  detail::checkHomePoint(m.home, where + ".plannedHomePosition");
  if (alt_unknown) m.home.alt_m = std::numeric_limits<double>::quiet_NaN();
  m.home_known = !(m.home.lat_deg == 0.0 && m.home.lon_deg == 0.0);
  if (m.home_known) return;
  m.home = {};  // no home: taken from the first position (checkMission), as in a .waypoints file
  m.warnings.push_back(where + ".plannedHomePosition: no position (0, 0)");
}

void readMissionHeader(const json& mj, const std::string& where, Mission& m) {
  // QGroundControl does not check the mission's version (MissionController::_loadJsonMissionFileV2).
  if (mj.contains("version") && integerOf(mj.at("version"), where, "version", 0, 1000) != 2) {
    m.warnings.push_back(where + ": field 'version' = " + shown(mj.at("version")) + ", where QGroundControl writes 2 and "
                         "reads any; read as version 2");
  }
  m.firmware_type = static_cast<int>(integerOf(required(mj, "firmwareType", where, "a MAV_AUTOPILOT number"), where, "firmwareType", 0, 255));
  if (mj.contains("vehicleType")) m.vehicle_type = static_cast<int>(integerOf(mj.at("vehicleType"), where, "vehicleType", 0, 255));
  m.plan_cruise_speed_mps = speedOf(mj, "cruiseSpeed", where);
  m.plan_hover_speed_mps = speedOf(mj, "hoverSpeed", where);
  readHome(mj, where, m);
}

// Nesting is bounded while parsing (QGroundControl writes about 8 levels; deeper input would
// overflow the stack in the recursive dump() that quotes a value in a message) and a key given twice
// in one object is refused: which one QGroundControl would take is a guess.
constexpr int kMaxPlanJsonDepth = 64;

json parseJson(const std::string& text, const std::string& source) {
  try {
    return io::parseStrictJson(text, kMaxPlanJsonDepth);
  } catch (const io::JsonError& e) {
    const std::string why = e.problem() == io::JsonProblem::duplicate_key ? "; expected each key once (which one counts is a guess)"
                            : e.problem() == io::JsonProblem::too_deep    ? " (the limit of a mission file)"
                                                                          : " (a QGroundControl .plan)";
    fail(source, e.what() + why);
  }
}

const json& missionObject(const json& j, const std::string& source) {
  if (!j.is_object()) fail(source, "top level = " + shown(j) + ", expected a JSON object (a QGroundControl .plan)");
  const std::string fileType = stringOf(j, "fileType", source);
  if (fileType != "Plan") fail(source, "field 'fileType' = \"" + fileType + "\", expected \"Plan\"");
  if (integerOf(required(j, "version", source, "1"), source, "version", 0, 1000) != 1)
    fail(source, "field 'version' = " + shown(j.at("version")) + ", expected 1 (the .plan version QGroundControl writes)");
  const json& mj = required(j, "mission", source, "an object");
  if (!mj.is_object()) fail(source, "field 'mission' = " + shown(mj) + ", expected an object");
  return mj;
}

}  // namespace

Mission parseQgcPlan(const std::string& text, const std::string& source, const ReadOptions& o) {
  const std::string body = detail::withoutBom(text);
  detail::checkText(body, source);
  const json j = parseJson(body, source);
  const json& mj = missionObject(j, source);
  Mission m;
  m.source = source;
  m.format = "plan";
  const std::string where = source + ": mission";
  readMissionHeader(mj, where, m);
  const json& items = required(mj, "items", where, "an array of items");
  if (!items.is_array()) fail(where, "field 'items' = " + shown(items) + ", expected an array of items");
  PlanItems p;
  for (std::size_t i = 0; i < items.size(); ++i) readItem(items[i], where + ".items[" + std::to_string(i) + "]", p);
  if (p.items.empty()) fail(where, "no mission items, expected at least one");
  resolveJumps(p);
  homeAltitudeUnknown(p, where, m);
  placeTerrainItems(p, m);
  m.items = std::move(p.items);
  checkMission(m, o);
  return m;
}

}  // namespace wattswath::mission
