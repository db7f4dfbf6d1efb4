#pragma once
// Internal to geometry/src: raw polygons as read (before projection), shared by the format
// readers (area_formats.cpp, area_wkt.cpp, area_gdal.cpp, area_qgc.cpp), the read pipeline
// (area_readers.cpp; all without CGAL) and the validation (area_validate.cpp, CGAL).
#include <functional>
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
  std::size_t features = 0;              ///< features a GIS reader read (after --layer / --where)
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

/// How GDAL reads one dataset, and how what it drops silently is explained.
struct GdalRead {
  std::string layer;                 ///< only this layer (--layer; empty: all)
  std::string where;                 ///< OGR SQL attribute filter (--where; empty: none)
  std::vector<std::string> drivers;  ///< only these GDAL drivers try the file (empty: any)
  std::string extension;             ///< parseWithGdal: the in-memory file's extension (empty: the source's)
  bool strict = false;               ///< lines, points other than home and features without geometry are errors, not notes
  bool layer_in_names = true;        ///< messages name the layer (false: one-layer formats such as GeoJSON)
  std::function<std::string(long)> why_no_geometry;  ///< why feature i has no geometry, "" to ignore it with a note
  std::function<std::string()> why_not_opened;       ///< why GDAL opened nothing, "" for the general message
};

/// GeoJSON text through GDAL's GeoJSON driver, any CRS (none: WGS84); a QGC plan ("fileType":
/// "Plan") is read as one. JSON nesting is bounded and syntax checked first; a geometry GDAL drops
/// is located (feature, ring, vertex) and refused.
RawArea parseGeoJson(const std::string& text, const std::string& source, const GdalRead& sel);
/// KML text through GDAL's LIBKML (or KML) driver, after refusing a DOCTYPE (entity declarations)
/// and element nesting deeper than kMaxXmlDepth.
RawArea parseKml(const std::string& text, const std::string& source, const GdalRead& sel);
/// WKT / EWKT text (one or more POLYGON / MULTIPOLYGON, ';' or space separated) through
/// OGRGeometryFactory::createFromWkt; `geodetic`: lon/lat [deg] (else metres); an SRID other than
/// 0 and 4326 is reprojected to WGS84 lon/lat.
RawArea parseWkt(const std::string& text, const std::string& source, bool geodetic);
RawArea parseQgcWpl(const std::string& text, const std::string& source);
/// QGroundControl `.plan` (JSON): survey polygons, geofence inclusions and exclusions, planned home.
RawArea parseQgcPlan(const std::string& text, const std::string& source);
/// Mission Planner `.poly`: "lat lon" per line, '#' comments.
RawArea parseMissionPlannerPoly(const std::string& text, const std::string& source);

/// XML element nesting beyond which a KML file is refused (before GDAL's recursive readers).
inline constexpr int kMaxXmlDepth = 64;
/// Any vector dataset GDAL opens at `path` (a file, or a /vsimem/ name), reprojected to WGS84 lon/lat.
RawArea readWithGdal(const std::string& path, const std::string& source, const GdalRead& sel);
/// Same on bytes in memory; `source`'s extension (or sel.extension) tells GDAL's drivers the format.
RawArea parseWithGdal(const std::string& bytes, const std::string& source, const GdalRead& sel);

/// Validates and repairs one labelled polygon in ENU metres (CGAL); returns repair notes.
std::vector<std::string> validateLabeled(LabeledPolygon& poly, const std::string& source, const RepairSettings& s);
/// Throws when two regions' interiors overlap.
void checkRegionsDisjoint(const std::vector<PolygonWithHoles>& regions, const std::string& source,
                          const std::vector<std::string>& names = {});

}  // namespace wattswath::geometry::detail
