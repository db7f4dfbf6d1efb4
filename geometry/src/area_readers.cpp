// The survey area read pipeline: read the file, decide its format, parse (area_formats.cpp) ->
// choose the frame -> project -> validate/repair (area_validate.cpp) -> subtract no-fly zones.
// No CGAL here.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "area_internal.hpp"
#include "wattswath/io/text_file.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::geometry {
namespace {
using namespace detail;

/// Reads a text-format area file whole, refusing files over kMaxAreaFileBytes before reading.
std::string readText(const std::string& path) {
  try {
    return io::readTextFile(path, {kMaxAreaFileBytes, "area files", "simplify the polygon, e.g. ogr2ogr -simplify 0.5"});
  } catch (const io::FileError& e) {
    throw SurveyAreaError(e.what());
  }
}

std::string extensionOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lowerAscii(path.substr(dot + 1));
}

AreaFormat sniff(const std::string& text) {
  size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (i >= text.size()) return AreaFormat::Auto;
  if (text[i] == '{') return AreaFormat::GeoJson;  // a QGC plan too: parseGeoJson tells them apart
  if (text[i] == '<') return AreaFormat::Kml;  // GML and GPX are told by their extension (GDAL)
  if (text.compare(i, 7, "QGC WPL") == 0) return AreaFormat::QgcWpl;
  if (text.compare(i, 24, "#saved by Mission Planner") == 0) return AreaFormat::MissionPlannerPoly;
  const std::string head = lowerAscii(text.substr(i, 16));
  if (head.rfind("polygon", 0) == 0 || head.rfind("multipolygon", 0) == 0 || head.rfind("srid=", 0) == 0) return AreaFormat::Wkt;
  return AreaFormat::Auto;
}

const char* formatName(AreaFormat f) {
  switch (f) {
    case AreaFormat::GeoJson: return "GeoJSON";
    case AreaFormat::Kml: return "KML";
    case AreaFormat::Wkt: return "WKT";
    case AreaFormat::QgcWpl: return "QGC WPL";
    case AreaFormat::QgcPlan: return "QGC plan";
    case AreaFormat::MissionPlannerPoly: return "Mission Planner poly";
    case AreaFormat::Gdal: return "a GDAL format";
    case AreaFormat::Auto: return "unknown";
  }
  return "unknown";
}

/// The format an extension names; Gdal for every extension our text readers do not own.
AreaFormat formatOfExtension(const std::string& ext) {
  if (ext == "geojson" || ext == "json") return AreaFormat::GeoJson;
  if (ext == "kml") return AreaFormat::Kml;
  if (ext == "wkt") return AreaFormat::Wkt;
  if (ext == "waypoints") return AreaFormat::QgcWpl;
  if (ext == "plan") return AreaFormat::QgcPlan;
  if (ext == "poly") return AreaFormat::MissionPlannerPoly;
  if (ext.empty() || ext == "txt" || ext == "area") return AreaFormat::Auto;
  return AreaFormat::Gdal;
}

/// Decides the format of text already read (parseSurveyArea, and files our readers own).
AreaFormat decideFormat(const std::string& source, const std::string& text, AreaFormat requested) {
  if (requested != AreaFormat::Auto) return requested;
  AreaFormat byExt = formatOfExtension(extensionOf(source));
  if (byExt == AreaFormat::Gdal) return byExt;
  const AreaFormat byContent = sniff(text);
  // A .plan and a .json are both JSON; the JSON reader tells GeoJSON and QGC plans apart.
  const bool jsonAlike = byExt == AreaFormat::QgcPlan && byContent == AreaFormat::GeoJson;
  if (byExt != AreaFormat::Auto && byContent != AreaFormat::Auto && byExt != byContent && !jsonAlike) {
    throw SurveyAreaError(source + ": the extension says " + formatName(byExt) + " but the content looks like " +
                          formatName(byContent));
  }
  const AreaFormat f = byExt != AreaFormat::Auto ? byExt : byContent;
  if (f == AreaFormat::Auto) {
    throw SurveyAreaError(source + ": unknown survey area format (expected GeoJSON, KML, WKT, QGC WPL 110, a QGC .plan, "
                          "a Mission Planner .poly, or a GIS file GDAL reads, named by its extension: .shp, .gpkg, .kmz, "
                          ".gml, .gpx, .csv, ...)");
  }
  return f;
}

GdalRead selectionOf(const ReadOptions& o) {
  GdalRead r;
  r.layer = o.layer;
  r.where = o.where;
  return r;
}

RawArea parseAny(const std::string& withBom, const std::string& source, const ReadOptions& o) {
  // A UTF-8 byte order mark (Windows editors) is not content in any of the formats.
  const bool bom = withBom.compare(0, 3, "\xEF\xBB\xBF") == 0;
  const std::string text = bom ? withBom.substr(3) : withBom;
  switch (decideFormat(source, text, o.format)) {
    case AreaFormat::GeoJson: return parseGeoJson(text, source, selectionOf(o));
    case AreaFormat::Kml: return parseKml(text, source, selectionOf(o));
    case AreaFormat::Wkt: return parseWkt(text, source, o.wkt_units == WktUnits::LonLatDegrees);
    case AreaFormat::QgcWpl: return parseQgcWpl(text, source);
    case AreaFormat::QgcPlan: return parseQgcPlan(text, source);
    case AreaFormat::MissionPlannerPoly: return parseMissionPlannerPoly(text, source);
    case AreaFormat::Gdal: return parseWithGdal(withBom, source, selectionOf(o));
    case AreaFormat::Auto: break;
  }
  throw SurveyAreaError(source + ": unknown survey area format");
}

/// Reads a file: formats GDAL owns (Shapefile with its sidecars, GeoPackage, ...) are opened by
/// GDAL in place; the text formats are read into memory (bounded) and parsed.
RawArea readAny(const std::string& path, const ReadOptions& o) {
  const bool gdal = o.format == AreaFormat::Gdal ||
                    (o.format == AreaFormat::Auto && formatOfExtension(extensionOf(path)) == AreaFormat::Gdal);
  if (gdal) {
    if (!std::ifstream(path)) throw SurveyAreaError(path + ": cannot open the file");
    return readWithGdal(path, path, selectionOf(o));
  }
  const std::string text = readText(path);
  // A file whose extension and content no reader of ours claims: GDAL's drivers try it (they
  // name the formats expected when none reads it). Text in memory (parseSurveyArea, the fuzz
  // target) is not handed to GDAL unless AreaFormat::Gdal is asked for.
  const bool unclaimed = o.format == AreaFormat::Auto && formatOfExtension(extensionOf(path)) == AreaFormat::Auto &&
                         sniff(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text) == AreaFormat::Auto;
  return unclaimed ? readWithGdal(path, path, selectionOf(o)) : parseAny(text, path, o);
}

/// Throws naming the file, ring and vertex when a lon/lat vertex is not finite or out of range.
void checkGeodeticRing(const LabeledRing& r, const std::string& source) {
  for (size_t i = 0; i < r.pts.size(); ++i) {
    const Point& p = r.pts[i];
    // Projected metres (UTM, a national grid) in a file without a CRS: say so, not "lon/lat swapped?".
    const double big = std::max(std::abs(p.x()), std::abs(p.y()));
    if (big > 360.0 && big < 1e8) {
      throw SurveyAreaError(source + ": " + r.name + ", " + r.labels[i] + ": (" + std::to_string(p.x()) + ", " +
                            std::to_string(p.y()) + ") is not lon/lat in degrees; it looks like projected metres. Give "
                            "the file its CRS (a GeoJSON \"crs\" member as ogr2ogr writes it, a .prj beside a "
                            "Shapefile) or reproject it to WGS84 (ogr2ogr -t_srs EPSG:4326); WKT: --wkt-units metres");
    }
    try {
      validateGeoPoint(GeoPoint{r.pts[i].y(), r.pts[i].x(), 0.0}, source + ": " + r.name + ", " + r.labels[i]);
    } catch (const std::invalid_argument& e) {
      throw SurveyAreaError(e.what());
    }
  }
}

/// Checks every lon/lat vertex of the polygons (before the frame origin is chosen from them).
void checkGeodeticPolygons(const std::vector<LabeledPolygon>& polys, const std::string& source) {
  for (const auto& p : polys) {
    checkGeodeticRing(p.outer, source);
    for (const auto& h : p.holes) checkGeodeticRing(h, source);
  }
}

/// Projects a lon/lat ring into the frame in place, validating every vertex.
void projectRing(LabeledRing& r, const LocalFrame& frame, const std::string& source) {
  checkGeodeticRing(r, source);
  for (auto& p : r.pts) p = frame.toLocal(p.y(), p.x());
}

/// [m] largest coordinate of an area given in metres: a local frame spans a survey, not a planet
/// (1e308 m squared overflowed to an infinite area).
constexpr double kMaxLocalCoordinate = 1e7;

/// Throws naming the file, ring and vertex when a metre vertex is not finite or beyond kMaxLocalCoordinate.
void checkMetreRing(const LabeledRing& r, const std::string& source) {
  for (size_t i = 0; i < r.pts.size(); ++i) {
    const Point& p = r.pts[i];
    if (!(std::abs(p.x()) <= kMaxLocalCoordinate && std::abs(p.y()) <= kMaxLocalCoordinate)) {
      std::ostringstream v;
      v << "(" << p.x() << ", " << p.y() << ")";
      throw SurveyAreaError(source + ": " + r.name + ", " + r.labels[i] + ": " + v.str() +
                            " m is not a finite coordinate within 1e7 m of the local frame's origin (x east, y north "
                            "in metres); coordinates this large are another CRS: give the file its CRS, or "
                            "--wkt-units lonlat for degrees");
    }
  }
}

void projectPolygon(LabeledPolygon& p, const std::optional<LocalFrame>& frame, bool geodetic, const std::string& source) {
  if (!geodetic) {
    checkMetreRing(p.outer, source);
    for (const auto& h : p.holes) checkMetreRing(h, source);
    return;
  }
  if (!frame) throw SurveyAreaError(source + ": coordinates are lon/lat but the area has no geodetic frame");
  projectRing(p.outer, *frame, source);
  for (auto& h : p.holes) projectRing(h, *frame, source);
}

PolygonWithHoles toPolygon(const LabeledPolygon& p) {
  PolygonWithHoles out;
  out.outer = p.outer.pts;
  for (const auto& h : p.holes) out.holes.push_back(h.pts);
  return out;
}

GeoPoint chooseOrigin(const RawArea& raw, const ReadOptions& o, const std::string& source) {
  switch (o.origin_choice) {
    case OriginChoice::Given:
      if (!o.origin) throw SurveyAreaError(source + ": OriginChoice::Given needs ReadOptions::origin");
      return *o.origin;
    case OriginChoice::Home:
      if (!raw.home) throw SurveyAreaError(source + ": OriginChoice::Home but the file has no home point");
      return GeoPoint{raw.home->lat_deg, raw.home->lon_deg, 0.0};
    case OriginChoice::FirstVertex: {
      if (raw.polygons.front().outer.pts.empty()) {
        throw SurveyAreaError(source + ": " + raw.polygons.front().outer.name + " has no vertex to place the frame origin at");
      }
      const Point& p = raw.polygons.front().outer.pts.front();
      return GeoPoint{p.y(), p.x(), 0.0};
    }
    case OriginChoice::BoundingBoxCenter: break;
  }
  double minLat = std::numeric_limits<double>::infinity(), maxLat = -minLat, minLon = minLat, maxLon = -minLat;
  for (const auto& poly : raw.polygons) {
    for (const auto& p : poly.outer.pts) {
      minLon = std::min(minLon, p.x()); maxLon = std::max(maxLon, p.x());
      minLat = std::min(minLat, p.y()); maxLat = std::max(maxLat, p.y());
    }
  }
  if (!std::isfinite(minLat)) throw SurveyAreaError(source + ": no finite vertex to place the frame origin at");
  return GeoPoint{0.5 * (minLat + maxLat), 0.5 * (minLon + maxLon), 0.0};
}

std::vector<Ring> zonesFromRaw(RawArea& raw, std::vector<LabeledPolygon>& polys, const std::optional<LocalFrame>& frame,
                               const std::string& source, const RepairSettings& rs, std::vector<std::string>& notes) {
  std::vector<Ring> zones;
  for (auto& z : polys) {
    if (!z.holes.empty()) throw SurveyAreaError(source + ": " + z.outer.name + ": a no-fly zone with holes is not supported");
    z.outer.name = "no-fly zone " + std::to_string(zones.size()) + " (" + z.outer.name + ")";
    projectPolygon(z, frame, raw.geodetic, source);
    auto n = validateLabeled(z, source, rs);
    notes.insert(notes.end(), n.begin(), n.end());
    zones.push_back(z.outer.pts);
  }
  return zones;
}

}  // namespace

const PolygonWithHoles& SurveyArea::polygon() const {
  if (regions.size() != 1) {
    throw SurveyAreaError(source + ": the area has " + std::to_string(regions.size()) +
                          " separate regions (features or parts that do not touch): plan one at a time, chosen "
                          "with --layer / --where or from a file holding only it (library: SurveyArea::regions)");
  }
  return regions.front();
}

double SurveyArea::area() const {
  double a = 0.0;
  for (const auto& r : regions) a += geometry::area(r);
  return a;
}

double SurveyArea::perimeter() const {
  auto ringLength = [](const Ring& r) {
    double l = 0.0;
    for (size_t i = 0; i < r.size(); ++i) l += (r[(i + 1) % r.size()] - r[i]).norm();
    return l;
  };
  double l = 0.0;
  for (const auto& r : regions) {
    l += ringLength(r.outer);
    for (const auto& h : r.holes) l += ringLength(h);
  }
  return l;
}

Point SurveyArea::bboxMin() const {
  Point m = Point::Constant(std::numeric_limits<double>::infinity());
  for (const auto& r : regions)
    for (const auto& p : r.outer) m = m.cwiseMin(p);
  return m;
}

Point SurveyArea::bboxMax() const {
  Point m = Point::Constant(-std::numeric_limits<double>::infinity());
  for (const auto& r : regions)
    for (const auto& p : r.outer) m = m.cwiseMax(p);
  return m;
}

namespace {
/// Refuses an area whose longitudes span more than 180 deg: it crosses the 180 deg meridian, where
/// a local frame centred on the longitudes' mean lands on the other side of the Earth (a field at
/// 179.999 E / 179.999 W was planned at 0.001 E, 49.7 S).
void checkNotAcrossTheAntimeridian(const RawArea& raw, const std::string& source) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto* polys : {&raw.polygons, &raw.no_fly})
    for (const auto& poly : *polys)
      for (const auto& p : poly.outer.pts) {
        lo = std::min(lo, p.x());
        hi = std::max(hi, p.x());
      }
  if (hi - lo > 180.0) {
    throw SurveyAreaError(source + ": the area's longitudes run from " + std::to_string(lo) + " to " + std::to_string(hi) +
                          " deg: it crosses the 180 deg meridian (antimeridian), which wattswath does not handle; expected "
                          "an area on one side of it");
  }
}

/// Frame, projection, validation and the file's own no-fly zones, for a RawArea from any reader.
SurveyArea buildArea(RawArea raw, const std::string& source, const ReadOptions& options) {
  if (raw.polygons.empty()) throw SurveyAreaError(source + ": no polygon found (expected at least one area polygon)");
  SurveyArea area;
  area.source = source;
  area.repairs = raw.notes;
  if (raw.geodetic) {
    checkGeodeticPolygons(raw.polygons, source);
    checkGeodeticPolygons(raw.no_fly, source);
    checkNotAcrossTheAntimeridian(raw, source);
    area.frame = LocalFrame(chooseOrigin(raw, options, source));
  } else if (options.origin) {
    area.frame = LocalFrame(*options.origin);
  }
  if (raw.home) {
    try {
      validateGeoPoint(*raw.home, source + ": home point");
    } catch (const std::invalid_argument& e) {
      throw SurveyAreaError(e.what());
    }
    if (area.frame) area.home = area.frame->toLocal(raw.home->lat_deg, raw.home->lon_deg);
    area.home_alt_m = raw.home->alt_m;
  }
  std::vector<std::string> names;
  for (auto& p : raw.polygons) {
    projectPolygon(p, area.frame, raw.geodetic, source);
    auto notes = validateLabeled(p, source, options.repair);
    area.repairs.insert(area.repairs.end(), notes.begin(), notes.end());
    area.regions.push_back(toPolygon(p));
    names.push_back(p.outer.name);
  }
  checkRegionsDisjoint(area.regions, source, names);
  if (!raw.no_fly.empty()) {
    NoFlyZones zones;
    zones.source = source;
    zones.zones = zonesFromRaw(raw, raw.no_fly, area.frame, source, options.repair, zones.repairs);
    subtractNoFlyZones(area, zones);
  }
  return area;
}

}  // namespace

SurveyArea parseSurveyArea(const std::string& text, const std::string& source, const ReadOptions& options) {
  return buildArea(parseAny(text, source, options), source, options);
}

SurveyArea readSurveyArea(const std::string& path, const ReadOptions& options) {
  RawArea raw = readAny(path, options);
  if (!options.layer.empty() || !options.where.empty()) {
    // --layer / --where choose the area; the file's no-fly zones stay no-fly zones whatever was
    // chosen (a filter on the field's name dropped the zone "Mast" of the layer "nofly" unsaid).
    ReadOptions all = options;
    all.layer.clear();
    all.where.clear();
    RawArea every;
    try {
      every = readAny(path, all);
    } catch (const std::exception& e) {  // a part the filter left out cannot be read: the chosen part stands
      raw.notes.push_back(path + ": the file's no-fly zones outside what --layer / --where chose were not read (" + e.what() + ")");
    }
    if (every.no_fly.size() > raw.no_fly.size()) {
      raw.notes.push_back(path + ": " + std::to_string(every.no_fly.size()) + " no-fly zone(s) read from the whole file, not "
                          "only from what --layer / --where chose");
      raw.no_fly = std::move(every.no_fly);
    }
  }
  SurveyArea area = buildArea(std::move(raw), path, options);
  for (const auto& f : options.no_fly_files) subtractNoFlyZones(area, readNoFlyZones(f, area, options));
  return area;
}

NoFlyZones readNoFlyZones(const std::string& path, const SurveyArea& area, const ReadOptions& options) {
  // --layer / --where choose the area in the area file; a no-fly file is read whole (with them it
  // read the chosen field itself as a no-fly zone, or failed on a layer it does not have).
  ReadOptions whole = options;
  whole.layer.clear();
  whole.where.clear();
  RawArea raw = readAny(path, whole);
  std::vector<LabeledPolygon> all = std::move(raw.polygons);
  for (auto& p : raw.no_fly) all.push_back(std::move(p));
  if (all.empty()) throw SurveyAreaError(path + ": no polygon found (expected at least one no-fly zone)");
  NoFlyZones out;
  out.source = path;
  out.repairs = raw.notes;
  out.zones = zonesFromRaw(raw, all, area.frame, path, options.repair, out.repairs);
  return out;
}

}  // namespace wattswath::geometry
