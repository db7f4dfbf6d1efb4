#pragma once
/// @file geojson.hpp
/// GeoJSON output (RFC 7946, lon/lat in degrees) of survey areas and coverage paths, back-projected
/// through the area's LocalFrame. Writers return strings; apps write the files.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "wattswath/geometry/frame.hpp"
#include "wattswath/geometry/path.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::geometry {

/// Options of coveragePathToGeoJson().
struct PathGeoJsonOptions {
  /// Extra per-leg numbers, one value per leg, written as a property of each leg's feature under
  /// the map's key (e.g. {"speed_mps", speeds} from the planner; keep keys <= 10 characters for
  /// Shapefile). Geometry does not interpret them.
  std::map<std::string, std::vector<double>> leg_properties;
  double arc_step_rad = 0.1745329251994330;  ///< [rad] arcs are sampled at most this far apart (10 deg); range (0, pi/2]
  int indent = 1;                            ///< JSON indentation (-1: one line)
};

/// One GeoJSON FeatureCollection holding one LineString Feature per leg (arcs sampled; a turn in
/// place repeats its vertex) with scalar properties only, so that GIS formats without lists
/// (Shapefile, GPX with extensions, GeoPackage) keep every field (names of at most 10
/// characters): "path" (index from 0) and "leg" (number from 1, as the plan report counts), "role" ("sweep"/"turn"/"transit"/"climb"), "kind"
/// ("line"/"arc"/"turn_in_place"), "pattern", "cell", "sweep_deg" [deg], "altitude_m" [m],
/// "length_m" [m], and each leg_properties key. Throws std::invalid_argument when a
/// leg_properties vector does not have one value per leg.
std::string coveragePathToGeoJson(const std::vector<CoveragePath>& paths, const LocalFrame& frame,
                                  const PathGeoJsonOptions& options = {});

/// The area as a GeoJSON FeatureCollection: one Polygon Feature per region (role "area", holes
/// are the no-fly zones), and the home Point (role "home") when known. Reading it back gives the
/// same area. Throws SurveyAreaError when the area has no geodetic frame.
std::string surveyAreaToGeoJson(const SurveyArea& area, int indent = 1);

/// Writes GeoJSON FeatureCollections (lon/lat, WGS84) as the layers of one GeoPackage through
/// GDAL: `layers` holds (layer name, GeoJSON text) pairs, e.g. the legs of coveragePathToGeoJson()
/// and the area of surveyAreaToGeoJson(). Replaces `path` only when every layer is written (a
/// temporary beside it, then a rename). Throws std::runtime_error naming the path and the layer.
void writeGeoPackage(const std::string& path, const std::vector<std::pair<std::string, std::string>>& layers);

/// Lower-case name of a leg role ("sweep", "turn", "transit", "climb").
std::string roleName(LegRole role);

}  // namespace wattswath::geometry
