// Example 2: read a survey area, look at its local frame, and generate coverage candidates
// (boustrophedon at several sweep angles, and spirals) from geometry alone: no energy yet.
// Usage (from the repository root): example_02_area_and_candidates [AREA.geojson|.kml|.wkt|.waypoints]
// Links wattswath::geometry only; docs/examples.md shows the output.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "wattswath/geometry/coverage.hpp"
#include "wattswath/geometry/path.hpp"
#include "wattswath/geometry/route.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace geo = wattswath::geometry;

namespace {

// Total length [m] and turns of a set of per-cell paths.
void printPaths(const std::string& label, const std::vector<geo::CoveragePath>& paths) {
  double length = 0.0;
  int turns = 0;
  for (const auto& p : paths) {
    length += p.length();
    turns += p.turnCount();
  }
  std::printf("  %-22s %zu cell(s), %6.0f m, %3d turns\n", label.c_str(), paths.size(), length, turns);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : "data/areas/iris_area.geojson";
  // Read, project to a local East-North-Up frame [m], validate and repair (throws naming the file).
  const geo::SurveyArea area = geo::readSurveyArea(path);
  const geo::PolygonWithHoles& poly = area.polygon();  // throws when the area has several parts
  std::printf("area: %.0f m^2, perimeter %.0f m, %zu vertices, %zu hole(s)\n", area.area(), area.perimeter(),
              poly.outer.size(), poly.holes.size());
  if (area.frame) {
    const geo::GeoPoint o = area.frame->origin();
    std::printf("frame origin: %.6f N, %.6f E\n", o.lat_deg, o.lon_deg);
    const geo::GeoPoint corner = area.frame->toGeodetic(poly.outer.front());  // back to lat/lon
    std::printf("first vertex: (%.1f, %.1f) m = %.6f N, %.6f E\n", poly.outer.front().x(), poly.outer.front().y(),
                corner.lat_deg, corner.lon_deg);
  }
  for (const auto& note : area.repairs) std::printf("repair: %s\n", note.c_str());

  // Rounded corners of radius 5 m where the turn allows it, sharp elsewhere.
  geo::CornerSettings corners;
  corners.style = geo::CornerStyle::Rounded;
  corners.radius = 5.0;

  std::printf("candidates at 15 m spacing:\n");
  for (const double deg : {0.0, 45.0, 90.0, 135.0}) {
    geo::BoustrophedonSettings b;
    b.spacing = 15.0;
    b.sweep_angle = deg * M_PI / 180.0;
    printPaths("boustrophedon " + std::to_string(int(deg)) + " deg", geo::boustrophedonPaths(poly, b, corners));
  }
  geo::SpiralSettings s;
  s.spacing = 15.0;
  printPaths("spiral", geo::spiralPaths(poly, s, corners));
  return 0;
}
