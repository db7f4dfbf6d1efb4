// Survey areas through GDAL/OGR: every vector dataset GDAL opens (GeoJSON, KML/KMZ, Shapefile,
// GeoPackage, GML, GPX tracks and routes, CSV with a WKT column, FlatGeobuf, ...), each layer and
// feature reprojected to WGS84 lon/lat by GDAL's PROJ, then labelled for messages (area_internal.hpp).
// The pre-checks GDAL cannot do safely on GeoJSON and KML text are in area_formats.cpp, WKT in
// area_wkt.cpp; GDAL's messages are collected (gdal_util.hpp), never printed.
#include <algorithm>
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include "area_internal.hpp"
#include "gdal_util.hpp"

namespace wattswath::geometry::detail {
namespace {

/// Collections nested deeper than this are refused (a GeometryCollection bomb).
constexpr int kMaxCollectionDepth = 16;

[[noreturn]] void fail(const std::string& source, const std::string& what) { throw SurveyAreaError(source + ": " + what); }

/// The string value of field `name` (any case), or "" when the layer has no such field.
std::string fieldText(OGRFeature& f, const char* name) {
  const OGRFeatureDefn* d = f.GetDefnRef();
  for (int i = 0; i < d->GetFieldCount(); ++i) {
    if (lowerAscii(d->GetFieldDefn(i)->GetNameRef()) == name && f.IsFieldSetAndNotNull(i)) return f.GetFieldAsString(i);
  }
  return "";
}

LabeledRing ringOf(const OGRSimpleCurve& c, const std::string& name, OgrTarget& fc) {
  LabeledRing r;
  r.name = name;
  const int n = c.getNumPoints();
  fc.vertices += static_cast<size_t>(n);
  if (fc.vertices > kMaxVertices) {
    fail(fc.source, name + ": more than " + std::to_string(kMaxVertices) + " vertices in the file (the limit of a survey area)");
  }
  for (int i = 0; i < n; ++i) {
    r.pts.emplace_back(c.getX(i), c.getY(i));
    r.labels.push_back("vertex " + std::to_string(i));
  }
  closeRing(r, fc.out.notes, fc.source);
  return r;
}

void addPolygon(const OGRPolygon& p, const std::string& name, OgrTarget& fc) {
  const OGRLinearRing* ext = p.getExteriorRing();
  if (!ext || ext->getNumPoints() == 0) fail(fc.source, name + ": polygon without an outer boundary (empty geometry)");
  LabeledPolygon poly;
  poly.outer = ringOf(*ext, name + ", outer boundary", fc);
  for (int k = 0; k < p.getNumInteriorRings(); ++k) {
    poly.holes.push_back(ringOf(*p.getInteriorRing(k), name + ", hole " + std::to_string(k), fc));
  }
  (isNoFlyName(fc.role) ? fc.out.no_fly : fc.out.polygons).push_back(std::move(poly));
}

void addGeometry(const OGRGeometry& g, const std::string& name, OgrTarget& fc, int depth);

/// "LineString", "MultiPoint 25D": GDAL's name of the type without its spaces, as GeoJSON writes it.
std::string typeName(const OGRGeometry& g) {
  std::string n = OGRGeometryTypeToName(g.getGeometryType());
  n.erase(std::remove(n.begin(), n.end(), ' '), n.end());
  return n;
}

/// [-] in KML, a line whose ends are farther apart than this share of its length is a drawn path,
/// not an outline (GPX tracks and routes are outlines walked or planned: always closed).
constexpr double kOpenLineShare = 0.05;

/// Lines (GPX tracks and routes, KML LineStrings) are rings: each line one ring, holes found by
/// containment (OGRGeometryFactory::organizePolygons), so a track of outline + obstacle works.
void addLines(const OGRGeometry& g, const std::string& name, OgrTarget& fc) {
  std::vector<OGRGeometry*> polys;
  auto addLine = [&](const OGRLineString& l) {
    // An outline walked or drawn ends near its start; a path that does not (a power line, a route)
    // is no area: left out, said (closing it made a triangle of a path).
    const int n = l.getNumPoints();
    double length = 0.0;
    const double my = 111320.0, mx = my * std::cos(l.getY(0) * M_PI / 180.0);
    for (int k = 1; k < n; ++k) length += std::hypot((l.getX(k) - l.getX(k - 1)) * mx, (l.getY(k) - l.getY(k - 1)) * my);
    const double gap = n > 0 ? std::hypot((l.getX(n - 1) - l.getX(0)) * mx, (l.getY(n - 1) - l.getY(0)) * my) : 0.0;
    if (fc.open_lines_are_paths && n >= 3 && gap > kOpenLineShare * length) {
      fc.out.notes.push_back(fc.source + ": " + name + ": an open line (its ends " + std::to_string(static_cast<long>(std::lround(gap))) +
                             " m apart, " + std::to_string(static_cast<long>(std::lround(length))) +
                             " m long) is a drawn path, not an area outline; ignored");
      return;
    }
    auto* ring = new OGRLinearRing();
    ring->addSubLineString(&l);
    ring->closeRings();
    auto* p = new OGRPolygon();
    p->addRingDirectly(ring);
    polys.push_back(p);
  };
  if (wkbFlatten(g.getGeometryType()) == wkbLineString) {
    addLine(*g.toLineString());
  } else {
    for (const auto* l : *g.toMultiLineString()) addLine(*l);
  }
  if (polys.empty()) {
    if (fc.open_lines_are_paths && !g.IsEmpty()) return;  // every line a path: each said above
    fail(fc.source, name + ": empty line geometry");
  }
  int valid = 0;
  std::unique_ptr<OGRGeometry> organized(
      OGRGeometryFactory::organizePolygons(polys.data(), static_cast<int>(polys.size()), &valid, nullptr));
  fc.out.notes.push_back(fc.source + ": " + name + ": lines read as closed rings (holes by containment)");
  addGeometry(*organized, name, fc, 1);
}

void addGeometry(const OGRGeometry& g, const std::string& name, OgrTarget& fc, int depth) {
  if (depth > kMaxCollectionDepth) {
    fail(fc.source, name + ": geometry collections nested more than " + std::to_string(kMaxCollectionDepth) + " deep");
  }
  const OGRwkbGeometryType t = wkbFlatten(g.getGeometryType());
  if (OGR_GT_IsNonLinear(g.getGeometryType())) {  // GML / GPKG curves: GDAL's default stroking
    std::unique_ptr<OGRGeometry> lin(g.getLinearGeometry());
    if (!lin) fail(fc.source, name + ": cannot linearise the curved geometry" + gdalSays());
    addGeometry(*lin, name, fc, depth + 1);
  } else if (t == wkbPolygon) {
    addPolygon(*g.toPolygon(), name, fc);
  } else if (t == wkbMultiPolygon || t == wkbGeometryCollection) {
    const auto& c = *g.toGeometryCollection();
    for (int i = 0; i < c.getNumGeometries(); ++i) {
      addGeometry(*c.getGeometryRef(i), name + (t == wkbMultiPolygon ? ", polygon " : ", geometry ") + std::to_string(i), fc,
                  depth + 1);
    }
  } else if ((t == wkbLineString || t == wkbMultiLineString) && !fc.strict) {
    addLines(g, name, fc);
  } else if (t == wkbPoint && lowerAscii(fc.role) == "home") {
    if (fc.out.home) {
      fail(fc.source, name + ": a second home point; expected one (which one the vehicle takes off from would be a guess)");
    }
    const auto& p = *g.toPoint();
    fc.out.home = GeoPoint{p.getY(), p.getX(), p.Is3D() ? p.getZ() : 0.0};
  } else if ((t == wkbPoint || t == wkbMultiPoint) && !fc.strict) {
    fc.out.notes.push_back(fc.source + ": " + name + ": point ignored (only a point with role or name \"home\" is used)");
  } else {
    fail(fc.source, name + ": geometry type " + typeName(g) + " is not an area (expected " +
                        (fc.strict ? "Polygon, MultiPolygon, or a Point with property role \"home\")"
                                   : "Polygon, MultiPolygon, closed lines, or a home Point)"));
  }
}

}  // namespace

void addOgrGeometry(const OGRGeometry& g, const std::string& name, OgrTarget& t) { addGeometry(g, name, t, 0); }

namespace {

/// The transformation of a layer's CRS to WGS84 lon/lat, or none when it has no CRS (taken as
/// WGS84) or is WGS84 lon/lat already (no PROJ round trip for a GeoJSON).
std::unique_ptr<OGRCoordinateTransformation> toWgs84(OGRLayer& layer, const std::string& where) {
  const OGRSpatialReference* src = layer.GetSpatialRef();
  if (!src) return nullptr;
  OGRSpatialReference wgs84;
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRSpatialReference> s(src->Clone());
  s->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const char* const sameOptions[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=NO", "CRITERION=EQUIVALENT", nullptr};
  if (s->IsSame(&wgs84, sameOptions)) return nullptr;
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(s.get(), &wgs84));
  if (!ct) {
    const char* n = src->GetName();
    throw SurveyAreaError(where + ": cannot transform its CRS \"" + std::string(n ? n : "?") + "\" to WGS84" + gdalSays());
  }
  return ct;
}

/// A feature without geometry: refused when the reader explains why (GeoJSON), else noted.
void noGeometry(long index, const std::string& name, const std::string& source, const GdalRead& sel, RawArea& out) {
  const std::string why = sel.why_no_geometry && sel.where.empty() ? sel.why_no_geometry(index) : std::string();
  if (!why.empty()) fail(source, name + ": " + why);
  out.notes.push_back(source + ": " + name + ": no geometry; ignored");
}

/// GDAL reported an error while reading a feature: its geometry may lack a part (GDAL drops a ring
/// it cannot read and goes on), so the feature is refused, explained by the reader when it can.
[[noreturn]] void brokenFeature(long index, const std::string& name, const std::string& source, const GdalRead& sel) {
  const std::string why = sel.why_no_geometry && sel.where.empty() ? sel.why_no_geometry(index) : std::string();
  fail(source, name + ": " + (why.empty() ? "GDAL could not read it whole" + gdalSays() : why));
}

void readLayer(OGRLayer& layer, const std::string& source, const GdalRead& sel, RawArea& out, size_t& vertices,
               bool layer_is_role, bool kml) {
  const std::string lname = "layer \"" + std::string(layer.GetName()) + "\"";
  if (!sel.where.empty() && layer.SetAttributeFilter(sel.where.c_str()) != OGRERR_NONE) {
    fail(source, lname + ": --where \"" + sel.where + "\" is not a valid OGR SQL filter on its fields" + gdalSays());
  }
  const auto ct = toWgs84(layer, source + ": " + lname);
  CPLErrorReset();
  long index = 0;
  for (auto& feature : layer) {
    // With --where the n-th feature read is not the file's n-th: named by its FID, not explained by position.
    const long i = sel.where.empty() ? index : static_cast<long>(feature->GetFID());
    ++index;
    const std::string name = (sel.layer_in_names ? lname + ", " : std::string()) + "feature " + std::to_string(i);
    ++out.features;
    if (sel.strict && CPLGetLastErrorType() >= CE_Failure) brokenFeature(i, name, source, sel);  // raised fetching it
    OGRGeometry* g = feature->GetGeometryRef();
    if (!g) {
      noGeometry(i, name, source, sel, out);
      continue;
    }
    if (g->IsEmpty()) {
      const std::string type = OGRGeometryTypeToName(g->getGeometryType());
      const OGRwkbGeometryType t = wkbFlatten(g->getGeometryType());
      if (sel.strict || t == wkbPolygon || t == wkbMultiPolygon) {
        fail(source, name + ": empty " + type + " (no coordinates); expected an outer boundary of at least 3 vertices");
      }
      out.notes.push_back(source + ": " + name + ": empty " + type + "; ignored");
      continue;
    }
    if (ct && g->transform(ct.get()) != OGRERR_NONE) fail(source, name + ": cannot reproject to WGS84" + gdalSays());
    std::string role = fieldText(*feature, "role");
    if (role.empty()) role = fieldText(*feature, "name");
    // A layer named as no-fly zones (a KML folder "No-fly zones", a GeoPackage layer "obstacles")
    // makes its features no-fly zones, whatever their own names (`layer_is_role`: several layers).
    if (layer_is_role && !isNoFlyName(role) && lowerAscii(role) != "home" && isNoFlyName(layer.GetName())) role = layer.GetName();
    OgrTarget target{source, role, sel.strict, out, vertices, kml};
    addGeometry(*g, name, target, 0);
    if (sel.strict) CPLErrorReset();
  }
  // Drivers report a broken feature or a filter that fails on the data (a GeoPackage evaluates
  // --where in SQLite only now) by ending the iteration with an error.
  if (CPLGetLastErrorType() >= CE_Failure) {
    fail(source, lname + ": reading stopped after feature " + std::to_string(index) + gdalSays() +
                     (sel.where.empty() ? std::string() : "; --where \"" + sel.where + "\" is not a valid OGR SQL filter on its fields?"));
  }
}

/// True when `l` declares line geometries (a plan's legs, a track), not areas.
bool isLineLayer(OGRLayer& l) {
  const OGRwkbGeometryType t = wkbFlatten(l.GetGeomType());
  return t == wkbLineString || t == wkbMultiLineString || t == wkbCircularString || t == wkbCompoundCurve ||
         t == wkbMultiCurve;
}

/// True when `ds` has more than one layer and one of them is not declared as lines (it may hold the area).
bool hasAreaLayer(GDALDataset& ds) {
  if (ds.GetLayerCount() < 2) return false;
  for (auto* l : ds.GetLayers()) {
    if (!isLineLayer(*l)) return true;
  }
  return false;
}

/// The NULL-terminated list of `names` (pointers into them).
std::vector<const char*> cList(const std::vector<std::string>& names) {
  std::vector<const char*> l;
  for (const auto& n : names) l.push_back(n.c_str());
  l.push_back(nullptr);
  return l;
}

}  // namespace

RawArea readWithGdal(const std::string& path, const std::string& source, const GdalRead& sel) {
  QuietGdal quiet;
  // CSV: a column named WKT (or geometry / geom / the_geom) holds the geometry.
  const char* const csvOptions[] = {"GEOM_POSSIBLE_NAMES=WKT,geometry,geom,the_geom", "KEEP_GEOM_COLUMNS=NO", nullptr};
  const bool csv = path.size() > 4 && lowerAscii(path.substr(path.size() - 4)) == ".csv";
  const auto drivers = cList(sel.drivers);
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY,
                                            sel.drivers.empty() ? nullptr : drivers.data(), csv ? csvOptions : nullptr, nullptr));
  if (!ds) {
    const std::string why = sel.why_not_opened ? sel.why_not_opened() : std::string();
    if (!why.empty()) fail(source, why);
    if (!sel.drivers.empty()) fail(source, "GDAL's " + sel.drivers.front() + " driver cannot read it" + gdalSays());
    fail(source, "not a survey area file wattswath or GDAL can read" + gdalSays() +
                     "; expected GeoJSON, KML/KMZ, WKT, Shapefile, GeoPackage, GML, GPX, CSV with a WKT column, "
                     "QGC .plan / .waypoints or Mission Planner .poly");
  }
  // GeoJSON is parsed whole when opened: an error then (a ring dropped) is the file's, located by the reader.
  if (sel.strict && quiet.failed()) {
    const std::string why = sel.why_not_opened ? sel.why_not_opened() : std::string();
    fail(source, why.empty() ? "GDAL could not read it whole" + gdalSays() : why);
  }
  RawArea out;
  size_t vertices = 0;
  const auto whereMatchedNothing = [&](RawArea& a) {
    if (!sel.where.empty() && a.features == 0) {
      fail(source, "--where \"" + sel.where + "\" matched no feature" +
                       (sel.layer.empty() ? std::string() : " of layer \"" + sel.layer + "\"") + "; nothing to read");
    }
    return a;
  };
  const std::string driver = ds->GetDriverName();
  const bool kml = driver == "LIBKML" || driver == "KML";
  if (!sel.layer.empty()) {
    OGRLayer* l = ds->GetLayerByName(sel.layer.c_str());
    if (!l) {
      std::string names;
      for (auto* x : ds->GetLayers()) names += (names.empty() ? "" : ", ") + std::string(x->GetName());
      fail(source, "no layer named \"" + sel.layer + "\" (--layer); the file has: " + names);
    }
    readLayer(*l, source, sel, out, vertices, false, kml);
    return whereMatchedNothing(out);
  }
  // In a file of several layers (KML folders, GeoPackage tables) a layer's name says what it holds;
  // a one-layer file's layer is named after the file, which says nothing of the role.
  const bool layer_is_role = sel.layer_in_names && ds->GetLayerCount() > 1;
  const bool gpx = std::string(ds->GetDriverName()) == "GPX";
  const bool lines_skipped = !gpx && hasAreaLayer(*ds);
  for (auto* l : ds->GetLayers()) {
    const std::string n = l->GetName();
    if (gpx && (n == "track_points" || n == "route_points")) continue;  // the same vertices as tracks / routes
    if (lines_skipped && isLineLayer(*l)) {
      out.notes.push_back(source + ": layer \"" + n + "\" skipped: it holds lines, and the file has an area layer (--layer \"" +
                          n + "\" reads its lines as closed rings)");
      continue;
    }
    readLayer(*l, source, sel, out, vertices, layer_is_role, kml);
  }
  return whereMatchedNothing(out);
}

RawArea parseWithGdal(const std::string& bytes, const std::string& source, const GdalRead& sel) {
  static std::atomic<unsigned> counter{0};
  const auto slash = source.find_last_of('/');
  std::string base = slash == std::string::npos ? source : source.substr(slash + 1);
  const std::string& ext = sel.extension;
  const std::string lower = lowerAscii(base);
  if (!ext.empty() && (lower.size() < ext.size() || lower.compare(lower.size() - ext.size(), ext.size(), ext) != 0)) {
    base += ext;  // a forced format whose name says otherwise ("fuzz.area" read as KML)
  }
  // A folder per read: the file keeps its own name, so a GeoJSON layer is named as the file.
  const std::string name = "/vsimem/wattswath_area_" + std::to_string(counter++) + "/" + base;
  QuietGdal quiet;  // registers the drivers before the memory file is made
  VSILFILE* f = VSIFileFromMemBuffer(name.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                                     static_cast<vsi_l_offset>(bytes.size()), FALSE);
  if (!f) fail(source, "cannot make an in-memory file for GDAL" + gdalSays());
  VSIFCloseL(f);
  struct Unlink {
    const std::string& n;
    ~Unlink() { VSIUnlink(n.c_str()); }
  } unlink{name};
  return readWithGdal(name, source, sel);
}

}  // namespace wattswath::geometry::detail
