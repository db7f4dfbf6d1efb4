// GeoJSON writers for survey areas and coverage paths (RFC 7946: [lon, lat] in degrees).
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "wattswath/geometry/geojson.hpp"

namespace wattswath::geometry {
namespace {
using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

json position(const LocalFrame& frame, const Point& p) {
  const GeoPoint g = frame.toGeodetic(p);
  return json::array({g.lon_deg, g.lat_deg});
}

/// Closed GeoJSON ring (first vertex repeated at the end).
json ring(const LocalFrame& frame, const Ring& r) {
  json a = json::array();
  for (const auto& p : r) a.push_back(position(frame, p));
  if (!r.empty()) a.push_back(position(frame, r.front()));
  return a;
}

const char* kindName(PrimitiveKind k) {
  switch (k) {
    case PrimitiveKind::Line: return "line";
    case PrimitiveKind::Arc: return "arc";
    case PrimitiveKind::TurnInPlace: return "turn_in_place";
  }
  return "line";
}

}  // namespace

std::string roleName(LegRole role) {
  switch (role) {
    case LegRole::Sweep: return "sweep";
    case LegRole::Turn: return "turn";
    case LegRole::Transit: return "transit";
    case LegRole::Climb: return "climb";
  }
  return "sweep";
}

namespace {
/// The vertices of one leg: its start, an arc's samples, its end (a turn in place: its vertex twice).
json legCoordinates(const PathLeg& l, const LocalFrame& frame, double arc_step_rad) {
  json c = json::array({position(frame, l.start)});
  if (l.kind == PrimitiveKind::Arc && l.radius > 0.0) {
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(l.turn_angle) / arc_step_rad)));
    const double a0 = std::atan2(l.start.y() - l.center.y(), l.start.x() - l.center.x());
    for (int s = 1; s < n; ++s) {
      const double a = a0 + l.turn_angle * s / n;
      c.push_back(position(frame, l.center + l.radius * Point(std::cos(a), std::sin(a))));
    }
  }
  c.push_back(position(frame, l.end));
  return c;
}

void checkLegProperties(const CoveragePath& path, size_t pi, const PathGeoJsonOptions& options) {
  for (const auto& [key, values] : options.leg_properties) {
    if (values.size() != path.legs.size()) {
      throw std::invalid_argument("leg property \"" + key + "\" has " + std::to_string(values.size()) +
                                  " values but path " + std::to_string(pi) + " has " + std::to_string(path.legs.size()) +
                                  " legs; expected one value per leg");
    }
  }
}
}  // namespace

std::string coveragePathToGeoJson(const std::vector<CoveragePath>& paths, const LocalFrame& frame,
                                  const PathGeoJsonOptions& options) {
  if (!(options.arc_step_rad > 0.0) || options.arc_step_rad > kPi / 2) {
    throw std::invalid_argument("PathGeoJsonOptions::arc_step_rad = " + std::to_string(options.arc_step_rad) +
                                " rad; expected (0, pi/2]");
  }
  json features = json::array();
  for (size_t pi = 0; pi < paths.size(); ++pi) {
    const CoveragePath& path = paths[pi];
    checkLegProperties(path, pi, options);
    for (size_t i = 0; i < path.legs.size(); ++i) {
      const PathLeg& l = path.legs[i];
      // Scalar attributes only, names of at most 10 characters: Shapefile, GPX and GeoPackage keep them.
      json props = {{"path", pi},
                    {"leg", i + 1},  // numbered from 1, as the plan report counts legs
                    {"role", roleName(l.role)},
                    {"kind", kindName(l.kind)},
                    {"pattern", path.pattern},
                    {"cell", path.cell},
                    {"sweep_deg", path.sweep_angle * 180.0 / kPi},
                    {"altitude_m", l.altitude},
                    {"length_m", l.length()}};
      for (const auto& [key, values] : options.leg_properties) props[key] = values[i];
      features.push_back({{"type", "Feature"},
                          {"properties", std::move(props)},
                          {"geometry", {{"type", "LineString"}, {"coordinates", legCoordinates(l, frame, options.arc_step_rad)}}}});
    }
  }
  const GeoPoint& o = frame.origin();
  json fc = {{"type", "FeatureCollection"},
             {"properties", {{"frame_origin", {{"lat_deg", o.lat_deg}, {"lon_deg", o.lon_deg}, {"alt_m", o.alt_m}}}}},
             {"features", std::move(features)}};
  return fc.dump(options.indent);
}

std::string surveyAreaToGeoJson(const SurveyArea& area, int indent) {
  if (!area.frame) {
    throw SurveyAreaError(area.source + ": the area has no geodetic frame (metric input without an origin); "
                          "cannot write lon/lat");
  }
  const LocalFrame& frame = *area.frame;
  json features = json::array();
  for (size_t i = 0; i < area.regions.size(); ++i) {
    const PolygonWithHoles& r = area.regions[i];
    json rings = json::array({ring(frame, r.outer)});
    for (const auto& h : r.holes) rings.push_back(ring(frame, h));
    features.push_back({{"type", "Feature"},
                        {"properties", {{"role", "area"}, {"region", i}, {"area_m2", geometry::area(r)}}},
                        {"geometry", {{"type", "Polygon"}, {"coordinates", std::move(rings)}}}});
  }
  if (area.home) {
    features.push_back({{"type", "Feature"},
                        {"properties", {{"role", "home"}}},
                        {"geometry", {{"type", "Point"}, {"coordinates", position(frame, *area.home)}}}});
  }
  json fc = {{"type", "FeatureCollection"}, {"features", std::move(features)}};
  return fc.dump(indent);
}

}  // namespace wattswath::geometry
