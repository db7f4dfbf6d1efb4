// Survey areas in GeoJSON and KML text: the checks GDAL cannot do safely (JSON nesting and syntax,
// XML DOCTYPE / entity declarations and element nesting), then GDAL's drivers (area_gdal.cpp); a
// GeoJSON geometry GDAL drops or refuses is located here (feature, ring, vertex, value) for the
// message. WKT is in area_wkt.cpp, the read pipeline in area_readers.cpp. No CGAL here.
#include <algorithm>
#include <cctype>
#include <memory>
#include <optional>
#include <unordered_set>

#include <nlohmann/json.hpp>
#include <ogr_geometry.h>

#include "area_internal.hpp"
#include "wattswath/io/strict_json.hpp"
#include "gdal_util.hpp"
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

using nlohmann::json;

/// A value as quoted in messages: scalars as written, short arrays of scalars as written, other
/// arrays and objects by size only, so that a value nested deeply is never dumped recursively.
std::string brief(const json& v) {
  const bool flat = v.is_array() && v.size() <= 4 && std::none_of(v.begin(), v.end(), [](const json& e) { return e.is_structured(); });
  if (flat) return v.dump();
  if (v.is_array()) return "an array of " + std::to_string(v.size()) + " element(s)";
  if (v.is_object()) return "an object of " + std::to_string(v.size()) + " member(s)";
  return v.dump();
}

// ---------------------------------------------------------------- GeoJSON: locating what GDAL drops
/// "outer boundary, vertex 3" (Polygon) / "polygon 1, hole 0, vertex 3" (MultiPolygon) for an
/// index path into "coordinates", else "coordinates[i][j]...".
std::string positionName(const std::string& type, const std::vector<size_t>& at) {
  auto ring = [](size_t r) { return r == 0 ? std::string("outer boundary") : "hole " + std::to_string(r - 1); };
  if (type == "Polygon" && at.size() == 2) return ring(at[0]) + ", vertex " + std::to_string(at[1]);
  if (type == "MultiPolygon" && at.size() == 3) {
    return "polygon " + std::to_string(at[0]) + ", " + ring(at[1]) + ", vertex " + std::to_string(at[2]);
  }
  std::string s = "coordinates";
  for (size_t i : at) s += "[" + std::to_string(i) + "]";
  return s;
}

/// The first position in `c` that is not [lon, lat(, alt)] of numbers, or the first empty array,
/// described; nullopt when all are. Recursion is bounded by the JSON nesting check.
std::optional<std::string> firstBadPosition(const json& c, const std::string& type, std::vector<size_t>& at) {
  if (!c.is_array()) return positionName(type, at) + " = " + brief(c) + ", expected an array";
  if (c.empty()) return positionName(type, at) + " is an empty array, expected [lon, lat] positions or non-empty arrays of them";
  const bool position = std::any_of(c.begin(), c.end(), [](const json& e) { return !e.is_array(); });
  if (position) {
    const bool numbers = c.size() >= 2 && std::all_of(c.begin(), c.end(), [](const json& e) { return e.is_number(); });
    if (numbers) return std::nullopt;
    return positionName(type, at) + ": expected a position [lon, lat] of numbers, got " + brief(c);
  }
  for (size_t i = 0; i < c.size(); ++i) {
    at.push_back(i);
    if (auto bad = firstBadPosition(c[i], type, at)) return bad;
    at.pop_back();
  }
  return std::nullopt;
}

/// Why GDAL read no geometry from `g` (a GeoJSON geometry object): GDAL's own message on it alone,
/// and the first position at fault; "" when GDAL reads it alone without an error (it drops a ring
/// it cannot read from a polygon, with an error only).
std::string explainGeometry(const json& g) {
  if (g.is_null()) return "Feature without geometry (\"geometry\": null), expected a Polygon or MultiPolygon";
  if (!g.is_object() || !g.contains("type") || !g["type"].is_string()) return "geometry without a \"type\"";
  const std::string type = g.at("type").get<std::string>();
  QuietGdal quiet;
  const std::unique_ptr<OGRGeometry> back(OGRGeometryFactory::createFromGeoJson(g.dump().c_str()));
  if (back && !quiet.failed()) return "";  // GDAL reads it alone: nothing to explain
  std::string what = type + " GDAL cannot read" + gdalSays();
  if (type == "GeometryCollection") return what;
  if (!g.contains("coordinates")) return what + ": no \"coordinates\"";
  std::vector<size_t> at;
  if (auto bad = firstBadPosition(g.at("coordinates"), type, at)) return what + ": " + *bad;
  if (type == "Polygon" || type == "MultiPolygon") return what + ": expected rings of at least 4 positions";
  return what;
}

/// The GeoJSON object of feature `i` as GDAL numbers them (a bare geometry or Feature is feature 0).
const json* featureJson(const json& j, long i) {
  if (j.at("type") != "FeatureCollection") return i == 0 ? &j : nullptr;
  const json& fs = j.at("features");
  return i >= 0 && static_cast<size_t>(i) < fs.size() ? &fs[static_cast<size_t>(i)] : nullptr;
}

/// Why feature `i` has no geometry in GDAL's reading.
std::string whyNoGeometry(const json& j, long i) {
  const json* f = featureJson(j, i);
  if (!f) return "";
  // A member without "type" but with "geometry" is taken as the Feature it was meant to be, as GDAL does.
  const bool feature = f->is_object() && (f->value("type", json()) == "Feature" || (!f->contains("type") && f->contains("geometry")));
  if (!feature) return explainGeometry(*f);
  return explainGeometry(f->value("geometry", json()));
}

/// Why GDAL opened nothing: the first feature whose geometry it cannot read, or GDAL's message.
std::string whyNotOpened(const json& j) {
  const size_t n = j.at("type") == "FeatureCollection" ? j.at("features").size() : 1;
  for (size_t i = 0; i < n; ++i) {
    const std::string why = whyNoGeometry(j, static_cast<long>(i));
    if (!why.empty()) return "feature " + std::to_string(i) + ": " + why;
  }
  return "";
}

// ---------------------------------------------------------------- KML: what expat must not see
/// Throws for a DOCTYPE (entity declarations: an entity expansion or external entity attack), for
/// element nesting deeper than kMaxXmlDepth, and, naming the line and element, for a tag without a
/// name, a closing tag that does not match and an end of file inside an element (expat would say
/// only "mismatched tag" or "no element found"). Comments, CDATA, processing instructions and
/// quoted attribute values are skipped; the rest of XML is GDAL's (expat) to check.
void checkXmlSafe(const std::string& text, const std::string& source) {
  auto lineAt = [&](size_t p) { return "line " + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(p), '\n')); };
  auto skipTo = [&](size_t from, const std::string& end, const char* what) {
    const size_t e = text.find(end, from);
    if (e == std::string::npos) fail(source, lineAt(from) + ": unterminated " + what);
    return e + end.size();
  };
  std::vector<std::string> open;  // names of the open elements (at most kMaxXmlDepth)
  size_t i = 0;
  while ((i = text.find('<', i)) != std::string::npos) {
    if (text.compare(i, 4, "<!--") == 0) { i = skipTo(i + 4, "-->", "comment"); continue; }
    if (text.compare(i, 9, "<![CDATA[") == 0) { i = skipTo(i + 9, "]]>", "CDATA"); continue; }
    if (text.compare(i, 2, "<?") == 0) { i = skipTo(i + 2, "?>", "processing instruction"); continue; }
    if (text.compare(i, 2, "<!") == 0) {
      fail(source, lineAt(i) + ": \"" + text.substr(i, std::min<size_t>(12, text.size() - i)) +
                       "...\": a DOCTYPE or entity declaration; KML has none, and entities are refused (they can expand "
                       "without bound or read other files): remove it");
    }
    size_t e = i + 1;
    for (char quote = 0; e < text.size() && (quote || text[e] != '>'); ++e) {
      if (quote && text[e] == quote) quote = 0;
      else if (!quote && (text[e] == '"' || text[e] == '\'')) quote = text[e];
    }
    if (e >= text.size()) fail(source, lineAt(i) + ": unterminated tag");
    const bool closing = text[i + 1] == '/', selfClosing = !closing && text[e - 1] == '/';
    const size_t nb = i + (closing ? 2 : 1);
    const std::string name = text.substr(nb, text.find_first_of(" \t\r\n/>", nb) - nb);
    if (name.empty()) fail(source, lineAt(i) + ": tag " + text.substr(i, e + 1 - i) + " has no element name");
    if (closing) {
      if (open.empty() || open.back() != name) {
        fail(source, lineAt(i) + ": closing tag </" + name + "> does not match <" + (open.empty() ? "nothing" : open.back()) + ">");
      }
      open.pop_back();
    } else if (!selfClosing) {
      open.push_back(name);
      if (open.size() > static_cast<size_t>(kMaxXmlDepth)) {
        fail(source, lineAt(i) + ": XML elements nested more than " + std::to_string(kMaxXmlDepth) + " deep (the limit of an area file)");
      }
    }
    i = e + 1;
  }
  if (!open.empty()) fail(source, "unexpected end of file inside <" + open.back() + ">");
}

}  // namespace

json parseJsonBounded(const std::string& text, const std::string& source) {
  // Nesting is bounded while parsing (GeoJSON needs 8 levels, a GeometryCollection 2 more each):
  // deeper input would overflow the stack in the recursive readers or in dump().
  // A key given twice in one object is refused: JSON readers disagree on which one counts (ours
  // and GDAL's keep the last), so the area would be a guess.
  try {
    return io::parseStrictJson(text, kMaxJsonDepth);
  } catch (const io::JsonError& e) {
    switch (e.problem()) {
      case io::JsonProblem::too_deep: fail(source, std::string(e.what()) + " (the limit of an area file)");
      case io::JsonProblem::duplicate_key:
        fail(source, std::string(e.what()) + "; expected each key once (which one counts is a guess)");
      case io::JsonProblem::invalid: break;
    }
    fail(source, e.what());
  }
}

RawArea parseGeoJson(const std::string& text, const std::string& source, const GdalRead& sel) {
  const json j = parseJsonBounded(text, source);
  if (j.is_object() && j.contains("fileType") && j["fileType"] == "Plan") return parseQgcPlanJson(j, source);
  if (!j.is_object() || !j.contains("type") || !j["type"].is_string()) {
    fail(source, "GeoJSON object without a \"type\" (expected a FeatureCollection, Feature or geometry; a QGC plan has \"fileType\": \"Plan\")");
  }
  if (j["type"] == "FeatureCollection" && !(j.contains("features") && j["features"].is_array())) {
    fail(source, "FeatureCollection: \"features\" must be an array of Features");
  }
  GdalRead r = sel;
  r.drivers = {"GeoJSON"};
  r.extension = ".geojson";
  r.strict = true;
  r.layer_in_names = false;
  r.why_no_geometry = [&j](long i) { return whyNoGeometry(j, i); };
  r.why_not_opened = [&j] { return whyNotOpened(j); };
  return parseWithGdal(text, source, r);
}

RawArea parseKml(const std::string& text, const std::string& source, const GdalRead& sel) {
  checkXmlSafe(text, source);
  GdalRead r = sel;
  r.drivers = {"LIBKML", "KML"};
  r.extension = ".kml";
  return parseWithGdal(text, source, r);
}

}  // namespace detail
}  // namespace wattswath::geometry
