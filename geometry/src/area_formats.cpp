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
std::string lowerAscii(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trimSpace(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

void closeRing(LabeledRing& r, std::vector<std::string>& notes, const std::string& source) {
  if (r.pts.size() >= 2 && r.pts.front() == r.pts.back()) {
    r.pts.pop_back();
    r.labels.pop_back();
  } else if (!r.pts.empty()) {
    notes.push_back(source + ": " + r.name + " was not closed (first vertex != last); treated as closed");
  }
}

bool isNoFlyName(const std::string& s) {
  const std::string l = lowerAscii(trimSpace(s));
  for (const char* p : {"no_fly", "no-fly", "nofly", "no fly", "obstacle", "exclusion"}) {
    if (l.rfind(p, 0) == 0) return true;
  }
  return false;
}

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw SurveyAreaError(source + ": " + what);
}


// ---------------------------------------------------------------- GeoJSON
using nlohmann::json;

/// A value as quoted in messages: scalars as written, arrays and objects by size only, so that a
/// value nested deeply is never dumped recursively.
std::string brief(const json& v) {
  if (v.is_array()) return "an array of " + std::to_string(v.size()) + " element(s)";
  if (v.is_object()) return "an object of " + std::to_string(v.size()) + " member(s)";
  return v.dump();
}

LabeledRing geoJsonRing(const json& coords, const std::string& name, const std::string& source,
                        std::vector<std::string>& notes) {
  if (!coords.is_array()) fail(source, name + ": coordinates must be an array of [lon, lat] positions");
  LabeledRing r;
  r.name = name;
  for (size_t i = 0; i < coords.size(); ++i) {
    const json& p = coords[i];
    const std::string label = "vertex " + std::to_string(i);
    if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number()) {
      fail(source, name + ", " + label + ": expected a position [lon, lat] of numbers, got " + brief(p));
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
  } else if (type == "Point" && lowerAscii(role) == "home") {
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
    else if (p.contains("name") && p["name"].is_string()) role = p["name"].get<std::string>();  // as KML and GDAL formats
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

json parseJsonBounded(const std::string& text, const std::string& source) {
  // Nesting is bounded while parsing (GeoJSON needs 8 levels, a GeometryCollection 2 more each):
  // deeper input would overflow the stack in the recursive readers or in dump().
  const json::parser_callback_t bound = [&](int depth, json::parse_event_t, json&) {
    if (depth > kMaxJsonDepth) {
      fail(source, "JSON nested more than " + std::to_string(kMaxJsonDepth) + " levels deep (the limit of an area file)");
    }
    return true;
  };
  try {
    return json::parse(text, bound);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number like 1e999
    fail(source, std::string("not valid JSON: ") + e.what());
  }
}

namespace {
/// True when a GeoJSON "crs" member names something other than WGS84 lon/lat.
bool hasOtherCrs(const json& j) {
  if (!j.contains("crs") || !j["crs"].is_object()) return false;
  const json& c = j["crs"];
  const json* name = c.contains("properties") && c["properties"].is_object() && c["properties"].contains("name")
                         ? &c["properties"]["name"] : nullptr;
  if (!name || !name->is_string()) return true;  // a linked or odd CRS: GDAL decides
  const std::string n = lowerAscii(name->get<std::string>());
  for (const char* wgs : {"urn:ogc:def:crs:ogc:1.3:crs84", "urn:ogc:def:crs:epsg::4326", "epsg:4326", "ogc:crs84"}) {
    if (n == wgs) return false;
  }
  return true;
}
}  // namespace

RawArea parseGeoJson(const std::string& text, const std::string& source) {
  const json j = parseJsonBounded(text, source);
  if (j.is_object() && j.contains("fileType") && j["fileType"] == "Plan") return parseQgcPlanJson(j, source);
  if (j.is_object() && hasOtherCrs(j)) return parseWithGdal(text, source, GdalSelection{});
  RawArea out;
  if (!j.is_object() || !j.contains("type") || !j["type"].is_string()) {
    fail(source, "GeoJSON object without a \"type\" (expected a FeatureCollection, Feature or geometry; a QGC plan has \"fileType\": \"Plan\")");
  }
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
    // The element's text is copied only at a closing tag: copying it at every '<' was quadratic in
    // the number of CDATA sections in one element.
    const size_t charsBegin = textStart;
    auto chars = [&] { return text.substr(charsBegin, lt - charsBegin); };
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
    if (trimSpace(tag).empty()) {
      fail(source, "line " + std::to_string(cur.lineAt(lt)) + ": tag <" + text.substr(lt + 1, gt - lt - 1) +
                       "> has no element name");
    }
    const size_t sp = tag.find_first_of(" \t\r\n");
    const std::string name = localName(trimSpace(tag.substr(0, sp)));
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
      std::string n = chars();
      const auto c0 = n.find("<![CDATA[");
      if (c0 != std::string::npos) n = n.substr(c0 + 9, n.find("]]>") - c0 - 9);
      placemarkName = trimSpace(n);
    } else if (name == "coordinates" && inPolygon) {
      const std::string where = (placemark >= 0 ? "placemark " + std::to_string(placemark) : std::string("document")) +
                                ", polygon " + std::to_string(polygonCount);
      if (inside("outerBoundaryIs")) {
        polygon.outer = kmlCoordinates(chars(), where + ", outer boundary", source, cur.lineAt(lt), out.notes);
      } else if (inside("innerBoundaryIs")) {
        polygon.holes.push_back(kmlCoordinates(chars(), where + ", hole " + std::to_string(polygon.holes.size()), source,
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
    std::string w = lowerAscii(lx.word());
    if (w == "srid") {  // EWKT prefix SRID=4326;
      lx.expect('=');
      lx.number();
      continue;
    }
    if (w.empty()) lx.error("expected POLYGON or MULTIPOLYGON, got \"" + s.substr(lx.pos, 12) + "\"");
    if (w != "polygon" && w != "multipolygon") lx.error("geometry type " + w + " is not an area (expected POLYGON or MULTIPOLYGON)");
    int dims = 2;
    size_t save = lx.pos;
    const std::string mod = lowerAscii(lx.word());
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

}  // namespace detail
}  // namespace wattswath::geometry
