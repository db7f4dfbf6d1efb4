#pragma once
// Internal to geometry/src: raw polygons as parsed (before projection), shared by the format
// parsers (area_formats.cpp), the read pipeline (area_readers.cpp; both without CGAL) and the
// validation (area_validate.cpp, CGAL).
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "wattswath/geometry/frame.hpp"
#include "wattswath/geometry/polygon.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::geometry::detail {

/// A ring with a label per vertex (for messages). Coordinates are lon/lat [deg] (x = lon) or
/// metres, depending on RawArea::geodetic.
struct LabeledRing {
  Ring pts;                         ///< vertices, without the closing vertex for closed formats
  std::vector<std::string> labels;  ///< one label per vertex ("vertex 3", "row 4 (line 6)")
  std::string name;                 ///< "feature 0, outer boundary"
  bool open = false;                ///< closure not required by the format (QGC): a near-closing last vertex may be dropped
};

/// A polygon with holes as read.
struct LabeledPolygon {
  LabeledRing outer;               ///< outer boundary
  std::vector<LabeledRing> holes;  ///< holes
};

/// Everything a reader found in one file.
struct RawArea {
  std::vector<LabeledPolygon> polygons;  ///< area parts
  std::vector<LabeledPolygon> no_fly;    ///< features marked as no-fly zones in the same file
  std::optional<GeoPoint> home;          ///< home point (lat/lon) if the file has one
  bool geodetic = true;                  ///< lon/lat degrees (true) or metres (false)
  std::vector<std::string> notes;        ///< format-level repair notes
};

/// ASCII lower case.
std::string lowerAscii(std::string s);
/// `s` without leading and trailing spaces, tabs and line ends.
std::string trimSpace(const std::string& s);
/// Closed formats repeat the first vertex at the end: strips it, or notes that the ring was not closed.
void closeRing(LabeledRing& r, std::vector<std::string>& notes, const std::string& source);
/// True when a role or name marks a no-fly zone (no-fly, no_fly, nofly, no fly, obstacle, exclusion...).
bool isNoFlyName(const std::string& s);

/// JSON nesting beyond which an area file is refused.
inline constexpr int kMaxJsonDepth = 64;
/// Parses JSON with nesting bounded by kMaxJsonDepth; throws SurveyAreaError naming `source`.
nlohmann::json parseJsonBounded(const std::string& text, const std::string& source);
/// A QGC plan already parsed (see parseQgcPlan).
RawArea parseQgcPlanJson(const nlohmann::json& j, const std::string& source);

/// GeoJSON text; a QGC plan ("fileType": "Plan") is read as one, a "crs" other than WGS84 through GDAL.
RawArea parseGeoJson(const std::string& text, const std::string& source);
RawArea parseKml(const std::string& text, const std::string& source);
RawArea parseWkt(const std::string& text, const std::string& source, bool geodetic);
RawArea parseQgcWpl(const std::string& text, const std::string& source);
/// QGroundControl `.plan` (JSON): survey polygons, geofence inclusions and exclusions, planned home.
RawArea parseQgcPlan(const std::string& text, const std::string& source);
/// Mission Planner `.poly`: "lat lon" per line, '#' comments.
RawArea parseMissionPlannerPoly(const std::string& text, const std::string& source);

/// Options of the GDAL reader.
struct GdalSelection {
  std::string layer;  ///< only this layer (empty: all)
  std::string where;  ///< OGR SQL attribute filter (empty: none)
};
/// Any vector dataset GDAL opens at `path` (a file, or a /vsimem/ name), reprojected to WGS84 lon/lat.
RawArea readWithGdal(const std::string& path, const std::string& source, const GdalSelection& sel);
/// Same on bytes in memory; `source`'s extension tells GDAL's drivers the format.
RawArea parseWithGdal(const std::string& bytes, const std::string& source, const GdalSelection& sel);

/// Validates and repairs one labelled polygon in ENU metres (CGAL); returns repair notes.
std::vector<std::string> validateLabeled(LabeledPolygon& poly, const std::string& source, const RepairSettings& s);
/// Throws when two regions' interiors overlap.
void checkRegionsDisjoint(const std::vector<PolygonWithHoles>& regions, const std::string& source);

}  // namespace wattswath::geometry::detail
