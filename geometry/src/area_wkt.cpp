// Survey areas in WKT / EWKT text through GDAL/OGR (OGRGeometryFactory::createFromWkt): one or
// more POLYGON / MULTIPOLYGON (Z, M, curves linearised), separated by spaces or ';', each with an
// optional EWKT "SRID=n;" prefix (0 or 4326: as the units say; another EPSG code: reprojected to
// WGS84 lon/lat). Parentheses are checked first (nesting bounded, the first unbalanced one
// located), since GDAL says only "corrupt data".
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

#include <ogr_geometry.h>
#include <ogr_spatialref.h>

#include "area_internal.hpp"
#include "gdal_util.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::geometry::detail {
namespace {

/// Parenthesis nesting beyond which WKT is refused (before GDAL's recursive reader).
constexpr int kMaxWktDepth = 64;

[[noreturn]] void fail(const std::string& source, const std::string& what) { throw SurveyAreaError(source + ": " + what); }

/// 1-based line of offset `p`.
std::string lineAt(const std::string& s, size_t p) {
  return "line " + std::to_string(1 + std::count(s.begin(), s.begin() + static_cast<long>(p), '\n'));
}

/// Throws at the first ')' that closes nothing, the first '(' never closed, or nesting deeper than kMaxWktDepth.
void checkParentheses(const std::string& s, const std::string& source) {
  std::vector<size_t> open;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '(') {
      open.push_back(i);
      if (open.size() > static_cast<size_t>(kMaxWktDepth)) {
        fail(source, lineAt(s, i) + ": parentheses nested more than " + std::to_string(kMaxWktDepth) + " deep at offset " +
                         std::to_string(i) + " (the limit of an area file)");
      }
    } else if (s[i] == ')') {
      if (open.empty()) fail(source, lineAt(s, i) + ": ')' at offset " + std::to_string(i) + " closes nothing");
      open.pop_back();
    }
  }
  if (!open.empty()) {
    fail(source, lineAt(s, open.back()) + ": '(' at offset " + std::to_string(open.back()) +
                     " is never closed: expected ')' before the end at offset " + std::to_string(s.size()));
  }
}

/// Reads an EWKT "SRID=n;" prefix at `pos` (advancing past it); -1 when there is none.
long readSrid(const std::string& s, size_t& pos, const std::string& source) {
  if (lowerAscii(s.substr(pos, 5)) != "srid=") return -1;
  const char* b = s.c_str() + pos + 5;
  char* e = nullptr;
  const long srid = std::strtol(b, &e, 10);
  if (e == b || *e != ';' || srid < 0) {
    fail(source, lineAt(s, pos) + ": \"" + s.substr(pos, 16) + "\": expected SRID=<EPSG code>; before the geometry");
  }
  pos = static_cast<size_t>(e + 1 - s.c_str());
  return srid;
}

/// Reprojects `g` from EPSG:`srid` to WGS84 lon/lat.
void toWgs84(OGRGeometry& g, long srid, const std::string& where) {
  OGRSpatialReference src, wgs84;
  if (src.importFromEPSG(static_cast<int>(srid)) != OGRERR_NONE) {
    throw SurveyAreaError(where + ": SRID=" + std::to_string(srid) + " is not an EPSG code GDAL knows" + gdalSays());
  }
  src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&src, &wgs84));
  if (!ct || g.transform(ct.get()) != OGRERR_NONE) {
    throw SurveyAreaError(where + ": cannot reproject from EPSG:" + std::to_string(srid) + " to WGS84" + gdalSays());
  }
}

/// After GDAL refused the geometry at `pos`: the first token inside its parentheses that is not a
/// finite number (keywords before a '(' and EMPTY / Z / M / ZM aside), with its line and offset; "".
std::string firstBadToken(const std::string& s, size_t pos) {
  int depth = 0;
  for (size_t i = pos; i < s.size();) {
    const char c = s[i];
    if (c == '(' || c == ')' || c == ',' || c == ';' || std::isspace(static_cast<unsigned char>(c))) {
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      if (depth == 0 && c == ')') return "";
      ++i;
      continue;
    }
    const size_t end = std::min(s.find_first_of("(),; \t\r\n\v\f", i), s.size());  // > i: s[i] is none of them
    const std::string tok = s.substr(i, end - i);
    char* stop = nullptr;
    const double v = std::strtod(tok.c_str(), &stop);
    const bool number = !tok.empty() && stop == tok.c_str() + tok.size();
    const size_t next = std::min(s.find_first_not_of(" \t\r\n", end), s.size());
    const std::string word = lowerAscii(tok);
    const bool keyword = !number && (depth == 0 || (next < s.size() && s[next] == '(') || word == "empty" || word == "z" ||
                                     word == "m" || word == "zm");
    auto at = [&] { return lineAt(s, i) + " (offset " + std::to_string(i) + ")"; };
    if (number && !std::isfinite(v)) return at() + ": non-finite coordinate \"" + tok + "\"; expected finite numbers";
    if (!number && !keyword) return at() + ": \"" + tok + "\" is not a number; expected coordinates x y[ z]";
    i = end;
  }
  return "";
}

/// Checks the type of a geometry GDAL read and that it has coordinates.
void checkAreaType(const OGRGeometry& g, const std::string& where) {
  const OGRwkbGeometryType t = wkbFlatten(g.getGeometryType());
  const bool area = t == wkbPolygon || t == wkbMultiPolygon || t == wkbCurvePolygon || t == wkbMultiSurface;
  std::string type = lowerAscii(OGRGeometryTypeToName(g.getGeometryType()));
  type.erase(std::remove(type.begin(), type.end(), ' '), type.end());
  if (!area) throw SurveyAreaError(where + ": geometry type " + type + " is not an area (expected POLYGON or MULTIPOLYGON)");
  if (g.IsEmpty()) throw SurveyAreaError(where + ": " + type + " EMPTY has no area");
}

}  // namespace

RawArea parseWkt(const std::string& text, const std::string& source, bool geodetic) {
  checkParentheses(text, source);
  QuietGdal quiet;
  RawArea out;
  out.geodetic = geodetic;
  size_t vertices = 0, pos = 0;
  for (int geometry = 0;; ++geometry) {
    while (pos < text.size() && (std::isspace(static_cast<unsigned char>(text[pos])) || text[pos] == ';')) ++pos;
    if (pos >= text.size()) break;
    const long srid = readSrid(text, pos, source);
    const std::string where = source + ": " + lineAt(text, pos) + ", geometry " + std::to_string(geometry);
    const char* begin = text.c_str() + pos;
    const char* p = begin;
    OGRGeometry* raw = nullptr;
    quiet.clear();
    const OGRErr err = OGRGeometryFactory::createFromWkt(&p, nullptr, &raw);
    const std::unique_ptr<OGRGeometry> g(raw);
    if (err != OGRERR_NONE || !g || p == begin) {
      const std::string token = firstBadToken(text, pos);
      if (!token.empty()) fail(source, "geometry " + std::to_string(geometry) + ", " + token);
      throw SurveyAreaError(where + " at offset " + std::to_string(pos) + ": \"" + text.substr(pos, 24) +
                            "...\" is not WKT GDAL reads" + gdalSays() + "; expected POLYGON ((x y, x y, ...), ...) or MULTIPOLYGON");
    }
    pos = static_cast<size_t>(p - text.c_str());
    checkAreaType(*g, where);
    if (srid > 0 && srid != 4326) {
      if (!geodetic) fail(source, where.substr(source.size() + 2) + ": SRID=" + std::to_string(srid) +
                                      " with WKT in metres (--wkt-units metres); expected SRID=0, or lon/lat units to reproject");
      toWgs84(*g, srid, where);
    }
    OgrTarget target{source, "", true, out, vertices};
    addOgrGeometry(*g, "geometry " + std::to_string(geometry), target);
  }
  return out;
}

}  // namespace wattswath::geometry::detail
