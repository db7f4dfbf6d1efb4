// libFuzzer target: the survey-area text readers (GeoJSON, KML and WKT: our pre-checks, then
// GDAL's GeoJSON and LIBKML drivers and OGR's WKT reader; QGC WPL 110, QGC .plan and Mission
// Planner .poly: our own readers) on arbitrary bytes, each format forced in turn and then decided
// by the content. GDAL's other drivers (AreaFormat::Gdal) are not forced here: GDAL itself is fuzzed
// by OSS-Fuzz; what is fuzzed here is our use of it (message capture, dropped parts, reprojection).
// Any std::exception is an accepted answer; a crash, a sanitizer report or an accepted area with a
// non-finite or non-positive area is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

#include "wattswath/geometry/survey_area.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace geo = wattswath::geometry;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (geo::AreaFormat f : {geo::AreaFormat::GeoJson, geo::AreaFormat::Kml, geo::AreaFormat::Wkt,
                            geo::AreaFormat::QgcWpl, geo::AreaFormat::QgcPlan, geo::AreaFormat::MissionPlannerPoly,
                            geo::AreaFormat::Auto}) {
    geo::ReadOptions o;
    o.format = f;
    try {
      const geo::SurveyArea a = geo::parseSurveyArea(text, "fuzz.area", o);
      const double m2 = a.area();
      if (!std::isfinite(m2) || !(m2 > 0.0)) std::abort();
    } catch (const std::exception&) {
    }
  }
  return 0;
}
