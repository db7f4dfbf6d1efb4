#pragma once
/// @file survey_area.hpp
/// Survey areas in: every vector format GDAL/OGR reads (Shapefile, GeoPackage, KMZ, GML, GPX,
/// CSV with a WKT column, FlatGeobuf, GeoJSON in any CRS, ...; reprojected to WGS84), our own
/// GeoJSON (WGS84), KML and WKT readers, and the formats GDAL has no driver for: QGC WPL 110
/// `.waypoints`, QGroundControl `.plan` and Mission Planner `.poly`. Areas are projected to a local
/// ENU frame, validated and (only where unambiguous) repaired. Extra no-fly zones are subtracted
/// from the area. Every error names the file and the layer / feature / ring / vertex.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "wattswath/geometry/frame.hpp"
#include "wattswath/geometry/polygon.hpp"

namespace wattswath::geometry {

/// Thrown for an unreadable or invalid survey area; the message names the file and the
/// feature / ring / vertex (0-based indices as in the file).
class SurveyAreaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Input file formats.
enum class AreaFormat {
  Auto,                ///< by extension, then by content, then whatever GDAL opens
  GeoJson,             ///< GeoJSON, any "crs" (none: WGS84): our JSON checks, then GDAL's GeoJSON driver
  Kml,                 ///< KML: our XML checks, then GDAL's LIBKML driver (KMZ: AreaFormat::Gdal)
  Wkt,                 ///< WKT / EWKT text through OGR (SRID other than 0 / 4326 reprojected)
  QgcWpl,              ///< QGC WPL 110 `.waypoints`: rows 1..n are the vertices
  QgcPlan,             ///< QGroundControl `.plan`: survey polygons, geofence inclusions (area) and exclusions (no-fly)
  MissionPlannerPoly,  ///< Mission Planner `.poly`: one "lat lon" per line, '#' comments
  Gdal                 ///< any vector dataset GDAL/OGR opens, reprojected to WGS84
};

/// Largest area file read into memory [byte] (text formats; GDAL streams its own): 64 MiB.
inline constexpr long long kMaxAreaFileBytes = 64LL * 1024 * 1024;

/// Units of WKT coordinates (GeoJSON and KML are always lon/lat, QGC files always lat/lon).
enum class WktUnits {
  LonLatDegrees,  ///< x = longitude, y = latitude [deg] (WKT as QGIS/PostGIS write it for EPSG:4326)
  Metres          ///< x east, y north [m] in the local frame (origin given by ReadOptions::origin, or none)
};

/// Where the local frame's origin is put.
enum class OriginChoice {
  BoundingBoxCenter,  ///< centre of the lat/lon bounding box of all area vertices, height 0 (default)
  FirstVertex,        ///< first vertex of the first outer boundary as it is in the file, height 0
  Home,               ///< the file's home point (QGC row 0 or a GeoJSON Point with role "home"), else error
  Given               ///< ReadOptions::origin
};

/// Tolerances of the validity checks and repairs (all lengths in the local frame).
struct RepairSettings {
  double duplicate_tolerance = 1e-6;  ///< [m] consecutive vertices closer than this are one vertex; range [0, 0.1]
  double collinear_tolerance = 1e-3;  ///< [m] a vertex closer than this to the segment joining its neighbours is dropped; range [0, 1]
  double closing_tolerance = 2.0;     ///< [m] QGC files only: a last vertex this close to the first is the repeated closing vertex; range [0, 10]
  double min_area = 1e-3;             ///< [m^2] rings with less area than this are degenerate (zero area); range [0, 1]
};

/// Options of readSurveyArea().
struct ReadOptions {
  AreaFormat format = AreaFormat::Auto;              ///< Auto: by extension, then by content
  WktUnits wkt_units = WktUnits::LonLatDegrees;      ///< how WKT coordinates are read
  OriginChoice origin_choice = OriginChoice::BoundingBoxCenter;  ///< where the ENU origin goes
  std::optional<GeoPoint> origin;                    ///< the origin for OriginChoice::Given (and for WKT in metres)
  std::vector<std::string> no_fly_files;             ///< extra no-fly zone files, subtracted from the area
  RepairSettings repair;                             ///< tolerances of checks and repairs
  std::string layer;                                 ///< GDAL formats: read only this layer (default: every layer)
  std::string where;                                 ///< GDAL formats: OGR SQL attribute filter on features, e.g. "name = 'field 3'"
};

/// A validated survey area in the local ENU frame.
struct SurveyArea {
  std::vector<PolygonWithHoles> regions;  ///< [m] flyable parts: outer CCW, holes CW, all no-fly zones subtracted
  std::vector<Ring> no_fly;               ///< [m] the extra no-fly zones as read (CCW), before subtraction
  std::optional<LocalFrame> frame;        ///< geodetic frame; empty only for metric input without an origin
  std::optional<Point> home;              ///< [m] home / launch point when the file has one (ENU)
  std::optional<double> home_alt_m;       ///< [m] home altitude as written in the file (QGC row 0 column 11)
  std::vector<std::string> repairs;       ///< what was repaired or clipped, one human-readable note each
  std::string source;                     ///< file the area was read from

  /// The single region; throws SurveyAreaError when the area has 0 or several separate parts.
  const PolygonWithHoles& polygon() const;
  /// Flyable area of all regions [m^2].
  double area() const;
  /// Length of all outer boundaries and holes [m].
  double perimeter() const;
  /// Lower-left corner of the bounding box of all outer boundaries [m].
  Point bboxMin() const;
  /// Upper-right corner of the bounding box of all outer boundaries [m].
  Point bboxMax() const;
};

/// Reads, projects, validates and repairs a survey area, then subtracts options.no_fly_files.
/// Formats (AreaFormat::Auto): `.geojson`/`.json` GeoJSON (a `.plan` inside is read as QGC plan),
/// `.kml` KML, `.wkt` WKT (these three through GDAL/OGR), `.waypoints` QGC WPL 110,
/// `.plan` QGroundControl plan, `.poly` Mission Planner polygon; any other file is decided by its
/// content, else opened by GDAL (Shapefile, GeoPackage, KMZ, GML, GPX, CSV with WKT, ...).
/// No-fly zones in the file: a feature whose "role" (or, failing that, "name") starts with
/// no-fly, no_fly, nofly, obstacle or exclusion; a QGC geofence exclusion.
/// Throws SurveyAreaError naming the file (and line / feature / vertex) on any problem.
SurveyArea readSurveyArea(const std::string& path, const ReadOptions& options = {});

/// Same as readSurveyArea() on text already in memory; `source` names it in messages and
/// `format` must not be Auto unless the content decides it.
SurveyArea parseSurveyArea(const std::string& text, const std::string& source, const ReadOptions& options = {});

/// No-fly zones read from a file, in an area's frame.
struct NoFlyZones {
  std::vector<Ring> zones;           ///< [m] validated zones, CCW
  std::vector<std::string> repairs;  ///< repair notes of reading them
  std::string source;                ///< file (or name) they came from
};

/// Reads a file of no-fly zones (every polygon in it, in any format above; a QGC file's rows 1..n
/// are one zone) and projects it into `area`'s frame; `options`' layer and where choose the area
/// only, a no-fly file is read whole. Throws SurveyAreaError naming the file.
NoFlyZones readNoFlyZones(const std::string& path, const SurveyArea& area, const ReadOptions& options = {});

/// Subtracts no-fly zones [m] from `area` (CGAL Boolean operations): a zone inside becomes a hole,
/// a zone partly outside is clipped (noted in area.repairs), a zone wholly outside is ignored
/// (noted), a zone covering the whole area throws SurveyAreaError naming zones.source and the
/// zone. Appends the zones to area.no_fly and zones.repairs to area.repairs.
void subtractNoFlyZones(SurveyArea& area, const NoFlyZones& zones);

/// Validates a polygon with holes [m] in place and repairs only the unambiguous (orientation,
/// consecutive duplicate vertices, collinear vertices). Returns the repair notes; throws
/// SurveyAreaError naming `source` and the ring / vertex for fewer than 3 distinct vertices,
/// non-finite coordinates, self-intersection (naming both edges), zero area, a hole outside or
/// crossing the boundary, or overlapping holes. Vertex indices in messages are those of the input.
std::vector<std::string> validatePolygon(PolygonWithHoles& poly, const std::string& source,
                                         const RepairSettings& settings = {});

}  // namespace wattswath::geometry
