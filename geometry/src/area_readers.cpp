// Survey area readers (GeoJSON, KML, WKT, QGC WPL 110) and the read pipeline: parse -> choose the
// frame -> project -> validate/repair (area_validate.cpp) -> subtract no-fly zones. No CGAL here.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "area_internal.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::geometry {
namespace detail {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw SurveyAreaError(source + ": " + what);
}

/// Closed formats (GeoJSON, KML, WKT) repeat the first vertex at the end: strip it, or note that
/// the ring was not closed.
void closeRing(LabeledRing& r, std::vector<std::string>& notes, const std::string& source) {
  if (r.pts.size() >= 2 && r.pts.front() == r.pts.back()) {
    r.pts.pop_back();
    r.labels.pop_back();
  } else if (!r.pts.empty()) {
    notes.push_back(source + ": " + r.name + " was not closed (first vertex != last); treated as closed");
  }
}

/// True when a role / name marks a no-fly zone.
bool isNoFlyName(const std::string& s) {
  const std::string l = lower(trim(s));
  for (const char* p : {"no_fly", "no-fly", "nofly", "no fly", "obstacle", "exclusion"}) {
    if (l.rfind(p, 0) == 0) return true;
  }
  return false;
}

// ---------------------------------------------------------------- GeoJSON
using nlohmann::json;

LabeledRing geoJsonRing(const json& coords, const std::string& name, const std::string& source,
                        std::vector<std::string>& notes) {
  if (!coords.is_array()) fail(source, name + ": coordinates must be an array of [lon, lat] positions");
  LabeledRing r;
  r.name = name;
  for (size_t i = 0; i < coords.size(); ++i) {
    const json& p = coords[i];
    const std::string label = "vertex " + std::to_string(i);
    if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number()) {
      fail(source, name + ", " + label + ": expected a position [lon, lat] of numbers, got " + p.dump());
    }
    r.pts.emplace_back(p[0].get<double>(), p[1].get<double>());
    r.labels.push_back(label);
  }
  closeRing(r, notes, source);
  return r;
}

LabeledPolygon geoJsonPolygon(const json& rings, const std::string& name, const std::string& source,
                              std::vector<std::string>& notes) {
  if (!rings.is_array() || rings.empty()) fail(source, name + ": Polygon coordinates must be a non-empty array of rings");
  LabeledPolygon poly;
  poly.outer = geoJsonRing(rings[0], name + ", outer boundary", source, notes);
  for (size_t k = 1; k < rings.size(); ++k) {
    poly.holes.push_back(geoJsonRing(rings[k], name + ", hole " + std::to_string(k - 1), source, notes));
  }
  return poly;
}

void geoJsonGeometry(const json& g, const std::string& name, const std::string& role, const std::string& source,
                     RawArea& out) {
  if (!g.is_object() || !g.contains("type") || !g["type"].is_string()) fail(source, name + ": geometry without a \"type\"");
  const std::string type = g["type"].get<std::string>();
  auto& dest = isNoFlyName(role) ? out.no_fly : out.polygons;
  if (type == "GeometryCollection") {
    const json& gs = g.value("geometries", json::array());
    for (size_t i = 0; i < gs.size(); ++i) geoJsonGeometry(gs[i], name + ", geometry " + std::to_string(i), role, source, out);
    return;
  }
  if (!g.contains("coordinates")) fail(source, name + ": " + type + " without \"coordinates\"");
  const json& c = g["coordinates"];
  if (type == "Polygon") {
    dest.push_back(geoJsonPolygon(c, name, source, out.notes));
  } else if (type == "MultiPolygon") {
    if (!c.is_array()) fail(source, name + ": MultiPolygon coordinates must be an array of polygons");
    for (size_t i = 0; i < c.size(); ++i) dest.push_back(geoJsonPolygon(c[i], name + ", polygon " + std::to_string(i), source, out.notes));
  } else if (type == "Point" && lower(role) == "home") {
    if (!c.is_array() || c.size() < 2 || !c[0].is_number() || !c[1].is_number()) fail(source, name + ": home Point needs [lon, lat]");
    out.home = GeoPoint{c[1].get<double>(), c[0].get<double>(), c.size() > 2 && c[2].is_number() ? c[2].get<double>() : 0.0};
  } else {
    fail(source, name + ": geometry type " + type +
                     " is not an area (expected Polygon, MultiPolygon, or a Point with property role \"home\")");
  }
}

void geoJsonFeature(const json& f, const std::string& name, const std::string& source, RawArea& out) {
  std::string role;
  if (f.contains("properties") && f["properties"].is_object()) {
    const json& p = f["properties"];
    if (p.contains("role") && p["role"].is_string()) role = p["role"].get<std::string>();
  }
  if (!f.contains("geometry") || f["geometry"].is_null()) fail(source, name + ": Feature without geometry");
  geoJsonGeometry(f["geometry"], name, role, source, out);
}

// ---------------------------------------------------------------- KML
struct XmlCursor {
  const std::string& text;
  size_t pos = 0;
  int lineAt(size_t p) const { return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(std::min(p, text.size())), '\n')); }
};

std::string localName(const std::string& tag) {
  const auto c = tag.find(':');
  return c == std::string::npos ? tag : tag.substr(c + 1);
}

/// Parses "lon,lat[,alt] lon,lat[,alt] ..." (whitespace around commas tolerated).
LabeledRing kmlCoordinates(const std::string& raw, const std::string& name, const std::string& source, int line,
                           std::vector<std::string>& notes) {
  std::string s;
  s.reserve(raw.size());
  // Drop whitespace adjacent to commas so that tuples are whitespace-separated tokens.
  for (size_t i = 0; i < raw.size(); ++i) {
    const char ch = raw[i];
    if (std::isspace(static_cast<unsigned char>(ch))) {
      size_t j = i;
      while (j < raw.size() && std::isspace(static_cast<unsigned char>(raw[j]))) ++j;
      const bool nearComma = (!s.empty() && s.back() == ',') || (j < raw.size() && raw[j] == ',');
      if (!nearComma) s.push_back(' ');
      i = j - 1;
    } else {
      s.push_back(ch);
    }
  }
  LabeledRing r;
  r.name = name;
  std::istringstream in(s);
  std::string tok;
  int i = 0;
  while (in >> tok) {
    std::vector<double> v;
    std::stringstream ts(tok);
    std::string part;
    bool ok = true;
    while (std::getline(ts, part, ',')) {
      char* end = nullptr;
      const double d = std::strtod(part.c_str(), &end);
      if (part.empty() || end != part.c_str() + part.size()) ok = false;
      v.push_back(d);
    }
    const std::string label = "vertex " + std::to_string(i);
    if (!ok || v.size() < 2 || v.size() > 3) {
      fail(source, "line " + std::to_string(line) + ": " + name + ", " + label + ": expected lon,lat[,alt], got \"" + tok + "\"");
    }
    r.pts.emplace_back(v[0], v[1]);
    r.labels.push_back(label);
    ++i;
  }
  closeRing(r, notes, source);
  return r;
}

// ---------------------------------------------------------------- WKT
struct WktLexer {
  const std::string& s;
  const std::string& source;
  size_t pos = 0;
  void skip() {
    while (pos < s.size() && (std::isspace(static_cast<unsigned char>(s[pos])) || s[pos] == ';')) ++pos;
  }
  bool atEnd() { skip(); return pos >= s.size(); }
  [[noreturn]] void error(const std::string& what) const {
    const int line = 1 + static_cast<int>(std::count(s.begin(), s.begin() + static_cast<long>(std::min(pos, s.size())), '\n'));
    fail(source, "line " + std::to_string(line) + ": " + what);
  }
  std::string word() {
    skip();
    size_t b = pos;
    while (pos < s.size() && (std::isalpha(static_cast<unsigned char>(s[pos])) || s[pos] == '_')) ++pos;
    return s.substr(b, pos - b);
  }
  bool peek(char c) { skip(); return pos < s.size() && s[pos] == c; }
  void expect(char c) {
    if (!peek(c)) error(std::string("expected '") + c + "' at offset " + std::to_string(pos));
    ++pos;
  }
  double number() {
    skip();
    const char* b = s.c_str() + pos;
    char* e = nullptr;
    const double d = std::strtod(b, &e);
    if (e == b) error("expected a number at offset " + std::to_string(pos) + ", got \"" + s.substr(pos, 12) + "\"");
    pos += static_cast<size_t>(e - b);
    return d;
  }
};

LabeledRing wktRing(WktLexer& lx, const std::string& name, int dims, std::vector<std::string>& notes) {
  LabeledRing r;
  r.name = name;
  lx.expect('(');
  int i = 0;
  do {
    const double x = lx.number(), y = lx.number();
    for (int d = 2; d < dims; ++d) lx.number();
    r.pts.emplace_back(x, y);
    r.labels.push_back("vertex " + std::to_string(i++));
    if (lx.peek(',')) { ++lx.pos; continue; }
    break;
  } while (true);
  lx.expect(')');
  closeRing(r, notes, lx.source);
  return r;
}

LabeledPolygon wktPolygon(WktLexer& lx, const std::string& name, int dims, std::vector<std::string>& notes) {
  LabeledPolygon p;
  lx.expect('(');
  p.outer = wktRing(lx, name + ", outer boundary", dims, notes);
  int k = 0;
  while (lx.peek(',')) {
    ++lx.pos;
    p.holes.push_back(wktRing(lx, name + ", hole " + std::to_string(k++), dims, notes));
  }
  lx.expect(')');
  return p;
}

}  // namespace

RawArea parseGeoJson(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    fail(source, std::string("not valid JSON: ") + e.what());
  }
  RawArea out;
  if (!j.is_object() || !j.contains("type") || !j["type"].is_string()) fail(source, "GeoJSON object without a \"type\"");
  const std::string type = j["type"].get<std::string>();
  if (type == "FeatureCollection") {
    const json& fs = j.value("features", json::array());
    if (!fs.is_array()) fail(source, "\"features\" must be an array");
    for (size_t i = 0; i < fs.size(); ++i) geoJsonFeature(fs[i], "feature " + std::to_string(i), source, out);
  } else if (type == "Feature") {
    geoJsonFeature(j, "feature 0", source, out);
  } else {
    geoJsonGeometry(j, "geometry", "", source, out);
  }
  return out;
}

RawArea parseKml(const std::string& text, const std::string& source) {
  RawArea out;
  XmlCursor cur{text};
  std::vector<std::string> stack;  // local names of open elements
  LabeledPolygon polygon;
  bool inPolygon = false;
  int placemark = -1, polyInPlacemark = 0, polygonCount = 0;
  std::string placemarkName;
  std::vector<LabeledPolygon> placemarkPolys;
  size_t textStart = 0;
  auto inside = [&](const char* name) { return std::find(stack.begin(), stack.end(), name) != stack.end(); };
  while (true) {
    const size_t lt = text.find('<', cur.pos);
    if (lt == std::string::npos) break;
    const std::string chars = text.substr(textStart, lt - textStart);
    if (text.compare(lt, 4, "<!--") == 0) {
      const size_t e = text.find("-->", lt);
      if (e == std::string::npos) fail(source, "line " + std::to_string(cur.lineAt(lt)) + ": unterminated comment");
      cur.pos = textStart = e + 3;
      continue;
    }
    if (text.compare(lt, 9, "<![CDATA[") == 0) {
      const size_t e = text.find("]]>", lt);
      if (e == std::string::npos) fail(source, "line " + std::to_string(cur.lineAt(lt)) + ": unterminated CDATA");
      cur.pos = e + 3;  // CDATA stays part of the element text
      continue;
    }
    const size_t gt = text.find('>', lt);
    if (gt == std::string::npos) fail(source, "line " + std::to_string(cur.lineAt(lt)) + ": unterminated tag");
    std::string tag = text.substr(lt + 1, gt - lt - 1);
    cur.pos = textStart = gt + 1;
    if (!tag.empty() && (tag[0] == '?' || tag[0] == '!')) continue;
    // "</>" is both: it starts and ends with the one '/', so decide on the closing slash first.
    const bool closing = !tag.empty() && tag[0] == '/';
    if (closing) tag.erase(0, 1);
    const bool selfClosing = !closing && !tag.empty() && tag.back() == '/';
    if (selfClosing) tag.pop_back();
    if (trim(tag).empty()) {
      fail(source, "line " + std::to_string(cur.lineAt(lt)) + ": tag <" + text.substr(lt + 1, gt - lt - 1) +
                       "> has no element name");
    }
    const size_t sp = tag.find_first_of(" \t\r\n");
    const std::string name = localName(trim(tag.substr(0, sp)));
    if (selfClosing) continue;
    if (!closing) {
      stack.push_back(name);
      if (name == "Placemark") {
        ++placemark;
        polyInPlacemark = 0;
        placemarkName.clear();
        placemarkPolys.clear();
      } else if (name == "Polygon") {
        polygon = LabeledPolygon{};
        inPolygon = true;
      }
      continue;
    }
    // Closing tag: `chars` is the element's text when it has no children.
    if (stack.empty() || stack.back() != name) {
      fail(source, "line " + std::to_string(cur.lineAt(lt)) + ": closing tag </" + name + "> does not match <" +
                       (stack.empty() ? std::string("nothing") : stack.back()) + ">");
    }
    stack.pop_back();
    if (name == "name" && !stack.empty() && stack.back() == "Placemark") {
      std::string n = chars;
      const auto c0 = n.find("<![CDATA[");
      if (c0 != std::string::npos) n = n.substr(c0 + 9, n.find("]]>") - c0 - 9);
      placemarkName = trim(n);
    } else if (name == "coordinates" && inPolygon) {
      const std::string where = (placemark >= 0 ? "placemark " + std::to_string(placemark) : std::string("document")) +
                                ", polygon " + std::to_string(polygonCount);
      if (inside("outerBoundaryIs")) {
        polygon.outer = kmlCoordinates(chars, where + ", outer boundary", source, cur.lineAt(lt), out.notes);
      } else if (inside("innerBoundaryIs")) {
        polygon.holes.push_back(kmlCoordinates(chars, where + ", hole " + std::to_string(polygon.holes.size()), source,
                                               cur.lineAt(lt), out.notes));
      }
    } else if (name == "Polygon") {
      inPolygon = false;
      if (polygon.outer.pts.empty()) fail(source, "line " + std::to_string(cur.lineAt(lt)) + ": Polygon without outerBoundaryIs coordinates");
      ++polygonCount;
      ++polyInPlacemark;
      if (placemark >= 0 && inside("Placemark")) {
        placemarkPolys.push_back(std::move(polygon));
      } else {
        out.polygons.push_back(std::move(polygon));
      }
    } else if (name == "Placemark") {
      auto& dest = isNoFlyName(placemarkName) ? out.no_fly : out.polygons;
      for (auto& p : placemarkPolys) dest.push_back(std::move(p));
      placemarkPolys.clear();
    }
  }
  if (!stack.empty()) fail(source, "unexpected end of file inside <" + stack.back() + ">");
  return out;
}

RawArea parseWkt(const std::string& text, const std::string& source, bool geodetic) {
  RawArea out;
  out.geodetic = geodetic;
  std::string s = text;
  WktLexer lx{s, source};
  int geometry = 0;
  while (!lx.atEnd()) {
    std::string w = lower(lx.word());
    if (w == "srid") {  // EWKT prefix SRID=4326;
      lx.expect('=');
      lx.number();
      continue;
    }
    if (w.empty()) lx.error("expected POLYGON or MULTIPOLYGON, got \"" + s.substr(lx.pos, 12) + "\"");
    if (w != "polygon" && w != "multipolygon") lx.error("geometry type " + w + " is not an area (expected POLYGON or MULTIPOLYGON)");
    int dims = 2;
    size_t save = lx.pos;
    const std::string mod = lower(lx.word());
    if (mod == "z" || mod == "m") dims = 3;
    else if (mod == "zm") dims = 4;
    else if (mod == "empty") lx.error(w + " EMPTY has no area");
    else lx.pos = save;
    const std::string name = "geometry " + std::to_string(geometry++);
    if (w == "polygon") {
      out.polygons.push_back(wktPolygon(lx, name, dims, out.notes));
    } else {
      lx.expect('(');
      int k = 0;
      do {
        out.polygons.push_back(wktPolygon(lx, name + ", polygon " + std::to_string(k++), dims, out.notes));
        if (lx.peek(',')) { ++lx.pos; continue; }
        break;
      } while (true);
      lx.expect(')');
    }
  }
  return out;
}

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
      if (trim(line).rfind("QGC WPL", 0) != 0) fail(source, "line 1: expected the header \"QGC WPL 110\", got \"" + line + "\"");
      const std::string version = trim(trim(line).substr(7));
      if (version != "110") {
        fail(source, "line 1: QGC WPL version \"" + version + "\" is not supported (expected the header \"QGC WPL 110\")");
      }
      continue;
    }
    if (trim(line).empty()) continue;
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
      poly.outer.pts.emplace_back(lon, lat);
      poly.outer.labels.push_back("vertex " + std::to_string(poly.outer.pts.size() - 1) + " (row " + std::to_string(row) + ", line " + std::to_string(lineNo) + ")");
    }
    ++row;
  }
  if (lineNo == 0) fail(source, "empty file (expected the header \"QGC WPL 110\")");
  out.polygons.push_back(std::move(poly));
  return out;
}

}  // namespace detail

// ---------------------------------------------------------------- pipeline
namespace {
using namespace detail;

std::string readText(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw SurveyAreaError(path + ": cannot open the file");
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string extensionOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

AreaFormat sniff(const std::string& text) {
  size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (i >= text.size()) return AreaFormat::Auto;
  if (text[i] == '{') return AreaFormat::GeoJson;
  if (text[i] == '<') return AreaFormat::Kml;
  if (text.compare(i, 7, "QGC WPL") == 0) return AreaFormat::QgcWpl;
  std::string head;
  for (size_t j = i; j < text.size() && j < i + 16; ++j) head.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(text[j]))));
  if (head.rfind("POLYGON", 0) == 0 || head.rfind("MULTIPOLYGON", 0) == 0 || head.rfind("SRID=", 0) == 0) return AreaFormat::Wkt;
  return AreaFormat::Auto;
}

const char* formatName(AreaFormat f) {
  switch (f) {
    case AreaFormat::GeoJson: return "GeoJSON";
    case AreaFormat::Kml: return "KML";
    case AreaFormat::Wkt: return "WKT";
    case AreaFormat::QgcWpl: return "QGC WPL";
    case AreaFormat::Auto: return "unknown";
  }
  return "unknown";
}

AreaFormat decideFormat(const std::string& source, const std::string& text, AreaFormat requested) {
  if (requested != AreaFormat::Auto) return requested;
  const std::string ext = extensionOf(source);
  AreaFormat byExt = AreaFormat::Auto;
  if (ext == "geojson" || ext == "json") byExt = AreaFormat::GeoJson;
  else if (ext == "kml") byExt = AreaFormat::Kml;
  else if (ext == "wkt") byExt = AreaFormat::Wkt;
  else if (ext == "waypoints") byExt = AreaFormat::QgcWpl;
  const AreaFormat byContent = sniff(text);
  if (byExt != AreaFormat::Auto && byContent != AreaFormat::Auto && byExt != byContent) {
    throw SurveyAreaError(source + ": the extension says " + formatName(byExt) + " but the content looks like " +
                          formatName(byContent));
  }
  const AreaFormat f = byExt != AreaFormat::Auto ? byExt : byContent;
  if (f == AreaFormat::Auto) {
    throw SurveyAreaError(source + ": unknown survey area format (expected GeoJSON, KML, WKT or QGC WPL 110)");
  }
  return f;
}

RawArea parseAny(const std::string& withBom, const std::string& source, const ReadOptions& o) {
  // A UTF-8 byte order mark (Windows editors) is not content in any of the formats.
  const bool bom = withBom.compare(0, 3, "\xEF\xBB\xBF") == 0;
  const std::string text = bom ? withBom.substr(3) : withBom;
  switch (decideFormat(source, text, o.format)) {
    case AreaFormat::GeoJson: return parseGeoJson(text, source);
    case AreaFormat::Kml: return parseKml(text, source);
    case AreaFormat::Wkt: return parseWkt(text, source, o.wkt_units == WktUnits::LonLatDegrees);
    case AreaFormat::QgcWpl: return parseQgcWpl(text, source);
    case AreaFormat::Auto: break;
  }
  throw SurveyAreaError(source + ": unknown survey area format");
}

/// Throws naming the file, ring and vertex when a lon/lat vertex is not finite or out of range.
void checkGeodeticRing(const LabeledRing& r, const std::string& source) {
  for (size_t i = 0; i < r.pts.size(); ++i) {
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

void projectPolygon(LabeledPolygon& p, const std::optional<LocalFrame>& frame, bool geodetic, const std::string& source) {
  if (!geodetic) return;
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
                          " separate regions; use SurveyArea::regions");
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

SurveyArea parseSurveyArea(const std::string& text, const std::string& source, const ReadOptions& options) {
  RawArea raw = parseAny(text, source, options);
  if (raw.polygons.empty()) throw SurveyAreaError(source + ": no polygon found (expected at least one area polygon)");
  SurveyArea area;
  area.source = source;
  area.repairs = raw.notes;
  if (raw.geodetic) {
    checkGeodeticPolygons(raw.polygons, source);
    checkGeodeticPolygons(raw.no_fly, source);
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
  for (auto& p : raw.polygons) {
    projectPolygon(p, area.frame, raw.geodetic, source);
    auto notes = validateLabeled(p, source, options.repair);
    area.repairs.insert(area.repairs.end(), notes.begin(), notes.end());
    area.regions.push_back(toPolygon(p));
  }
  checkRegionsDisjoint(area.regions, source);
  if (!raw.no_fly.empty()) {
    NoFlyZones zones;
    zones.source = source;
    zones.zones = zonesFromRaw(raw, raw.no_fly, area.frame, source, options.repair, zones.repairs);
    subtractNoFlyZones(area, zones);
  }
  return area;
}

SurveyArea readSurveyArea(const std::string& path, const ReadOptions& options) {
  SurveyArea area = parseSurveyArea(readText(path), path, options);
  for (const auto& f : options.no_fly_files) subtractNoFlyZones(area, readNoFlyZones(f, area, options));
  return area;
}

NoFlyZones readNoFlyZones(const std::string& path, const SurveyArea& area, const ReadOptions& options) {
  RawArea raw = parseAny(readText(path), path, options);
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
