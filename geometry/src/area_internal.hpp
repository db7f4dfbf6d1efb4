#pragma once
// Internal to geometry/src: raw polygons as parsed (before projection), shared by the format
// parsers (area_formats.cpp), the read pipeline (area_readers.cpp; both without CGAL) and the
// validation (area_validate.cpp, CGAL).
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

RawArea parseGeoJson(const std::string& text, const std::string& source);
RawArea parseKml(const std::string& text, const std::string& source);
RawArea parseWkt(const std::string& text, const std::string& source, bool geodetic);
RawArea parseQgcWpl(const std::string& text, const std::string& source);

/// Validates and repairs one labelled polygon in ENU metres (CGAL); returns repair notes.
std::vector<std::string> validateLabeled(LabeledPolygon& poly, const std::string& source, const RepairSettings& s);
/// Throws when two regions' interiors overlap.
void checkRegionsDisjoint(const std::vector<PolygonWithHoles>& regions, const std::string& source);

}  // namespace wattswath::geometry::detail
