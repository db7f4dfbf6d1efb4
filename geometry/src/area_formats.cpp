// Survey area format parsers: GeoJSON, KML, WKT and QGC WPL 110 text -> RawArea (lon/lat or
// metres, labelled for messages; area_internal.hpp). The read pipeline that calls them is in
// area_readers.cpp. No CGAL here.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
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
}  // namespace wattswath::geometry
