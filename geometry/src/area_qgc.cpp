// Survey area formats GDAL has no driver for, read by our own code: QGC WPL 110 `.waypoints`,
// QGroundControl `.plan` (JSON: survey polygons, geofence, planned home) and Mission Planner
// `.poly`. Each gives a RawArea in lon/lat, labelled for messages (area_internal.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include <GeographicLib/Geodesic.hpp>
#include <nlohmann/json.hpp>

#include "area_internal.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::geometry::detail {
namespace {
using nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& what) { throw SurveyAreaError(source + ": " + what); }

/// Largest distance [m] between a geofence circle and the polygon standing for it (inscribed for an
/// inclusion, so it never reaches outside the fence; circumscribed for an exclusion, so it covers
/// the whole no-fly circle).
constexpr double kCircleTolerance = 0.05;

/// A QGC position [lat, lon(, alt)] of numbers, or a clear error.
GeoPoint qgcLatLon(const json& p, const std::string& where, const std::string& source) {
  if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number()) {
    fail(source, where + ": expected a position [lat, lon] of numbers (QGC writes latitude first)");
  }
  return GeoPoint{p[0].get<double>(), p[1].get<double>(), p.size() > 2 && p[2].is_number() ? p[2].get<double>() : 0.0};
}

/// A QGC polygon [[lat, lon], ...] (open: QGC does not repeat the first vertex).
LabeledPolygon qgcPolygon(const json& poly, const std::string& name, const std::string& source) {
  if (!poly.is_array()) fail(source, name + ": \"polygon\" must be an array of [lat, lon] positions");
  LabeledPolygon p;
  p.outer.name = name;
  p.outer.open = true;
  for (size_t i = 0; i < poly.size(); ++i) {
    const GeoPoint g = qgcLatLon(poly[i], name + ", vertex " + std::to_string(i), source);
    p.outer.pts.emplace_back(g.lon_deg, g.lat_deg);
    p.outer.labels.push_back("vertex " + std::to_string(i));
  }
  return p;
}

/// A geofence circle {"center": [lat, lon], "radius": r} as an inscribed (or, `circumscribed`, a
/// circumscribed) polygon, vertices by
/// the WGS84 geodesic (GeographicLib), enough of them for kCircleTolerance.
LabeledPolygon qgcCircle(const json& c, const std::string& name, const std::string& source, bool circumscribed) {
  if (!c.is_object() || !c.contains("center") || !c.contains("radius") || !c["radius"].is_number()) {
    fail(source, name + ": expected {\"center\": [lat, lon], \"radius\": metres}");
  }
  const GeoPoint centre = qgcLatLon(c["center"], name + ", center", source);
  const double r = c["radius"].get<double>();
  if (!(r >= 1.0 && r <= 100000.0)) fail(source, name + ": radius " + std::to_string(r) + " m, expected 1 to 100000 m");
  try {
    validateGeoPoint(centre, source + ": " + name + ", center");
  } catch (const std::invalid_argument& e) {
    throw SurveyAreaError(e.what());
  }
  // Sagitta of a chord: r (1 - cos(pi / n)) <= tolerance.
  const double n = std::ceil(M_PI / std::acos(1.0 - std::min(1.0, kCircleTolerance / r)));
  const int count = static_cast<int>(std::clamp(n, 16.0, 3600.0));
  const double vertex_r = circumscribed ? r / std::cos(M_PI / count) : r;  // edges tangent to the circle
  LabeledPolygon p;
  p.outer.name = name + " (circle of " + std::to_string(count) + " vertices)";
  for (int i = 0; i < count; ++i) {
    double lat = 0.0, lon = 0.0;
    GeographicLib::Geodesic::WGS84().Direct(centre.lat_deg, centre.lon_deg, 360.0 * i / count, vertex_r, lat, lon);
    p.outer.pts.emplace_back(lon, lat);
    p.outer.labels.push_back("vertex " + std::to_string(i));
  }
  return p;
}

/// Survey complex items' polygons (QGC "survey"; a "StructureScan" or corridor is not an area).
void qgcSurveyItems(const json& mission, const std::string& source, RawArea& out) {
  const json& items = mission.contains("items") ? mission["items"] : json::array();
  if (!items.is_array()) fail(source, "mission.items must be an array");
  for (size_t i = 0; i < items.size(); ++i) {
    const json& it = items[i];
    if (!it.is_object() || it.value("type", "") != "ComplexItem") continue;
    const std::string kind = it.value("complexItemType", "");
    const std::string name = "mission item " + std::to_string(i) + " (" + kind + ")";
    if (kind == "survey") {
      if (!it.contains("polygon")) fail(source, name + ": survey without \"polygon\"");
      out.polygons.push_back(qgcPolygon(it["polygon"], name + ", polygon", source));
    } else {
      out.notes.push_back(source + ": " + name + ": not a survey polygon; ignored");
    }
  }
}

/// geoFence version 2: polygons and circles, inclusion -> area candidates, exclusion -> no-fly.
void qgcGeoFence(const json& fence, const std::string& source, RawArea& out, std::vector<LabeledPolygon>& inclusions) {
  if (!fence.is_object()) fail(source, "geoFence must be an object");
  // QGroundControl's GeoFenceController::load reads no fence of version 1 and loads the rest of the
  // plan; so do we, and say so (a fence without a version it refuses, as we do below).
  if (fence.contains("version") && fence["version"] == 1) {
    out.notes.push_back(source + ": geoFence version 1: its fences are not read (QGroundControl ignores them too)");
    return;
  }
  if (fence.value("version", 0) != 2) {
    fail(source, "geoFence version " + fence.value("version", json(nullptr)).dump() + " is not supported (expected 2, QGroundControl 3.4 and later)");
  }
  for (const char* key : {"polygons", "circles"}) {
    const json& list = fence.contains(key) ? fence[key] : json::array();
    if (!list.is_array()) fail(source, std::string("geoFence.") + key + " must be an array");
    for (size_t i = 0; i < list.size(); ++i) {
      const json& f = list[i];
      const std::string name = std::string("geoFence.") + key + "[" + std::to_string(i) + "]";
      if (!f.is_object() || !f.contains("inclusion") || !f["inclusion"].is_boolean()) {
        fail(source, name + ": expected an object with \"inclusion\": true or false");
      }
      const bool circle = std::string(key) == "circles";
      if (circle && !f.contains("circle")) fail(source, name + ": circle fence without \"circle\"");
      if (!circle && !f.contains("polygon")) fail(source, name + ": polygon fence without \"polygon\"");
      LabeledPolygon p = circle ? qgcCircle(f["circle"], name, source, !f["inclusion"].get<bool>()) : qgcPolygon(f["polygon"], name, source);
      (f["inclusion"].get<bool>() ? inclusions : out.no_fly).push_back(std::move(p));
    }
  }
}

}  // namespace

RawArea parseQgcPlan(const std::string& text, const std::string& source) {
  return parseQgcPlanJson(parseJsonBounded(text, source), source);
}

namespace {
/// [m] a survey point this close to a fence's edge counts as inside it (a fence drawn on the survey).
constexpr double kOnFenceM = 0.5;

/// A survey whose boundary leaves every inclusion fence of the same plan would be flown into the
/// fence (the autopilot's fence action): refused, naming the survey point outside (its edges are
/// checked at 50 points each). QGroundControl keeps the two apart; the vehicle enforces the fence.
void checkSurveyInsideFences(const std::vector<LabeledPolygon>& surveys, const std::vector<LabeledPolygon>& fences,
                             const std::string& source) {
  constexpr int kSteps = 50;
  // The fences in metres about the first survey vertex (GeographicLib), tested with the geometry
  // library's own ring predicates.
  const Point& o = surveys.front().outer.pts.front();
  const LocalFrame frame({o.y(), o.x(), 0.0});
  std::vector<Ring> rings;
  for (const auto& g : fences) {
    Ring r;
    for (const Point& p : g.outer.pts) r.push_back(frame.toLocal(p.y(), p.x()));
    rings.push_back(std::move(r));
  }
  for (const auto& s : surveys) {
    const Ring& r = s.outer.pts;
    for (size_t i = 0; i < r.size(); ++i) {
      const Point& a = r[i];
      const Point& b = r[(i + 1) % r.size()];
      for (int k = 0; k < kSteps; ++k) {
        const double f = static_cast<double>(k) / kSteps;
        const double x = a.x() + f * (b.x() - a.x()), y = a.y() + f * (b.y() - a.y());
        const Point p = frame.toLocal(y, x);
        const bool held = std::any_of(rings.begin(), rings.end(), [&](const Ring& fence) {
          return insideRing(fence, p) || distanceToRing(fence, p) <= kOnFenceM;
        });
        if (held) continue;
        char where[96];
        std::snprintf(where, sizeof where, "%.7f, %.7f", y, x);
        fail(source, s.outer.name + " reaches outside the plan's inclusion geofence (at " + std::string(where) + ", " +
                         (k == 0 ? s.outer.labels[i] : "on the edge after " + s.outer.labels[i]) +
                         "): the vehicle would meet its fence there; move the survey inside the fence, or the fence out");
      }
    }
  }
}

RawArea qgcPlan(const json& j, const std::string& source) {
  if (!j.is_object() || !j.contains("fileType") || j["fileType"] != "Plan") {
    fail(source, "not a QGroundControl plan (expected a JSON object with \"fileType\": \"Plan\")");
  }
  RawArea out;
  std::vector<LabeledPolygon> inclusions;
  if (j.contains("mission")) {
    const json& m = j["mission"];
    if (!m.is_object()) fail(source, "\"mission\" must be an object");
    qgcSurveyItems(m, source, out);
    if (m.contains("plannedHomePosition")) {
      const GeoPoint h = qgcLatLon(m["plannedHomePosition"], "mission.plannedHomePosition", source);
      if (h.lat_deg != 0.0 || h.lon_deg != 0.0) out.home = h;
    }
  }
  if (j.contains("geoFence")) qgcGeoFence(j["geoFence"], source, out, inclusions);
  // The area: the survey polygons; without any, the inclusion fences (wattswath's own mission.plan
  // has no survey item, and its inclusion fence lies the no-fly margin's distance outside the area).
  if (out.polygons.empty()) {
    if (!inclusions.empty()) out.notes.push_back(source + ": no survey item; the area is the geofence's inclusion polygon(s)");
    out.polygons = std::move(inclusions);
  } else if (!inclusions.empty()) {
    checkSurveyInsideFences(out.polygons, inclusions, source);
    out.notes.push_back(source + ": " + std::to_string(inclusions.size()) +
                        " inclusion fence(s) hold the survey polygons, which are the area; the fence mission.plan is "
                        "written with is wattswath's own (around the area), not these");
  }
  return out;
}
}  // namespace

RawArea parseQgcPlanJson(const json& j, const std::string& source) {
  try {
    return qgcPlan(j, source);
  } catch (const json::exception& e) {  // a member of the wrong JSON type (e.g. "version": "2")
    fail(source, std::string("not a QGroundControl plan as QGC writes it: ") + e.what());
  }
}

RawArea parseMissionPlannerPoly(const std::string& text, const std::string& source) {
  RawArea out;
  LabeledPolygon poly;
  poly.outer.name = "polygon";
  poly.outer.open = true;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trimSpace(line);
    if (t.empty() || t[0] == '#') continue;
    std::istringstream ls(t);
    double lat = 0.0, lon = 0.0;
    std::string extra;
    if (!(ls >> lat >> lon) || (ls >> extra)) {
      fail(source, "line " + std::to_string(lineNo) + ": expected \"latitude longitude\" in degrees, got \"" + t + "\"");
    }
    poly.outer.pts.emplace_back(lon, lat);
    poly.outer.labels.push_back("vertex " + std::to_string(poly.outer.pts.size() - 1) + " (line " + std::to_string(lineNo) + ")");
  }
  if (poly.outer.pts.empty()) fail(source, "no vertex (expected one \"latitude longitude\" line per vertex, as Mission Planner saves a .poly)");
  out.polygons.push_back(std::move(poly));
  return out;
}

namespace {

/// Throws unless `frame` (column 3 of a WPL row) is a global MAV_FRAME, whose x / y are lat / lon:
/// a local frame's are metres from an origin the file does not give. Altitude frames differ, but an
/// area's vertices use no altitude, so all global frames read alike.
void checkGlobalFrame(double frame, const std::string& text, const std::string& source, const std::string& where) {
  for (double global : {0.0, 3.0, 5.0, 6.0, 10.0, 11.0})
    if (frame == global) return;
  const char* local = frame == 1.0 ? " (MAV_FRAME_LOCAL_NED: metres)" : frame == 4.0 ? " (MAV_FRAME_LOCAL_ENU: metres)"
                      : frame == 2.0                                  ? " (MAV_FRAME_MISSION: not a position)"
                                                                      : "";
  fail(source, where + ", column 3 (frame): " + text + local +
                   " is not a global frame; a survey area's vertices need lat/lon (frame 0, 3, 5, 6, 10 or 11)");
}

}  // namespace

RawArea parseQgcWpl(const std::string& text, const std::string& source) {
  RawArea out;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0, row = 0;
  LabeledPolygon poly;
  poly.outer.name = "polygon";
  poly.outer.open = true;
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (lineNo == 1) {
      if (trimSpace(line).rfind("QGC WPL", 0) != 0) fail(source, "line 1: expected the header \"QGC WPL 110\", got \"" + line + "\"");
      const std::string version = trimSpace(trimSpace(line).substr(7));
      if (version != "110") {
        fail(source, "line 1: QGC WPL version \"" + version + "\" is not supported (expected the header \"QGC WPL 110\")");
      }
      continue;
    }
    if (trimSpace(line).empty()) continue;
    std::istringstream ls(line);
    std::vector<std::string> cols;
    std::string c;
    while (ls >> c) cols.push_back(c);
    const std::string where = "line " + std::to_string(lineNo) + " (row " + std::to_string(row) + ")";
    if (cols.size() < 12) fail(source, where + ": expected 12 tab-separated columns, got " + std::to_string(cols.size()));
    double v[12];
    for (int i = 0; i < 12; ++i) {
      char* end = nullptr;
      v[i] = std::strtod(cols[i].c_str(), &end);
      if (end != cols[i].c_str() + cols[i].size()) {
        fail(source, where + ", column " + std::to_string(i + 1) + ": expected a number, got \"" + cols[i] + "\"");
      }
    }
    const double lat = v[8], lon = v[9], alt = v[10];
    // MAV_CMD is a 16-bit unsigned integer: anything else (2e35, -1, 16.5, nan) is not a command.
    if (!(v[3] >= 0.0 && v[3] <= 65535.0 && v[3] == std::floor(v[3]))) {
      fail(source, where + ", column 4 (command): expected a MAV_CMD number, an integer in [0, 65535], got \"" +
                       cols[3] + "\"");
    }
    const int command = static_cast<int>(v[3]);
    if (row == 0) {
      if (lat == 0.0 && lon == 0.0) out.notes.push_back(source + ": " + where + ": home row has no position (0, 0); no home point");
      else out.home = GeoPoint{lat, lon, alt};
    } else if (command != 16) {
      out.notes.push_back(source + ": " + where + ": skipped MAV_CMD " + std::to_string(command) +
                          " (not a NAV_WAYPOINT, so not a vertex)");
    } else {
      checkGlobalFrame(v[2], cols[2], source, where);
      poly.outer.pts.emplace_back(lon, lat);
      poly.outer.labels.push_back("vertex " + std::to_string(poly.outer.pts.size() - 1) + " (row " + std::to_string(row) + ", line " + std::to_string(lineNo) + ")");
    }
    ++row;
  }
  if (lineNo == 0) fail(source, "empty file (expected the header \"QGC WPL 110\")");
  out.polygons.push_back(std::move(poly));
  return out;
}

}  // namespace wattswath::geometry::detail
