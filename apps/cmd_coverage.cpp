// `wattswath coverage`: coverage candidates (boustrophedon or spiral) over a survey area.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/coverage.hpp"
#include "wattswath/geometry/geojson.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/geometry/swath.hpp"

namespace wattswath::apps {
namespace g = wattswath::geometry;

namespace {

constexpr double kDeg = M_PI / 180.0;

struct CoverageOpts {  // the options of `coverage`
  std::string area;
  std::string pattern = "boustrophedon";
  double angle_deg = 0.0;
  double spacing = 0.0;
  double altitude = 0.0;
  double fov_deg = 0.0;
  double overlap = 0.0;
  std::string corners = "sharp";
  double radius = 0.0;
  std::string start = "bottom-left";
  bool clockwise = false;
  int start_vertex = 0;
  std::vector<std::string> no_fly;
  std::string out;
  bool json = false, force = false;
};

// One route per cell of `region`: the spiral's or the boustrophedon's, as the options say.
std::vector<g::Route> regionRoutes(const g::PolygonWithHoles& region, const CoverageOpts& o, double spacing) {
  std::vector<g::Route> routes;
  if (o.pattern == "spiral") {
    g::SpiralSettings sp;
    sp.spacing = spacing;
    sp.start_vertex = o.start_vertex;
    sp.clockwise = o.clockwise;
    sp.split_angle = o.angle_deg * kDeg;
    for (const auto& c : g::decomposeSpiral(region, spacing, sp.split_angle)) routes.push_back(g::spiralRoute(c, sp));
    return routes;
  }
  g::BoustrophedonSettings bs;
  bs.spacing = spacing;
  bs.sweep_angle = o.angle_deg * kDeg;
  const char* names[] = {"bottom-left", "bottom-right", "top-left", "top-right"};
  for (int k = 0; k < 4; ++k)
    if (o.start == names[k]) bs.start = static_cast<g::StartCorner>(k);
  const auto d = g::decomposeBoustrophedon(region, bs.sweep_angle);
  for (size_t c = 0; c < d.cells.size(); ++c) routes.push_back(g::boustrophedonRoute(region, d, static_cast<int>(c), bs));
  return routes;
}

// The options of `coverage`.
void addCoverageOptions(CLI::App* cmd, CoverageOpts& o) {
  cmd->add_option("AREA", o.area, "Survey area (GeoJSON, KML, WKT or QGC .waypoints)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--pattern", o.pattern, "Coverage pattern")
      ->check(CLI::IsMember({"spiral", "boustrophedon"}))
      ->capture_default_str();
  cmd->add_option("--angle", o.angle_deg, "Sweep direction [deg] (0 = lines along east, counter-clockwise; 180 is the same lines), -360..360")
      ->check(CLI::Range(-360.0, 360.0))
      ->capture_default_str();
  auto* spacing = cmd->add_option("--spacing", o.spacing, "Distance between passes [m], > 0")->check(kPositive);
  auto* alt = cmd->add_option("--altitude", o.altitude, "Camera height above ground [m], > 0")->check(kPositive);
  auto* fov = cmd->add_option("--fov", o.fov_deg, "Camera field of view across track [deg], in (0, 180)")->check(CLI::Range(0.0, 180.0));
  auto* overlap = cmd->add_option("--overlap", o.overlap, "Side overlap fraction, 0..1")->check(CLI::Range(0.0, 0.99));
  spacing->excludes(alt)->excludes(fov)->excludes(overlap);
  alt->needs(fov);
  fov->needs(alt);
  cmd->add_option("--corners", o.corners, "Corner shape: sharp (stop, turn in place) or rounded (arc)")
      ->check(CLI::IsMember({"sharp", "rounded"}))
      ->capture_default_str();
  cmd->add_option("--radius", o.radius, "Arc radius of rounded corners [m], > 0 with --corners rounded: your cruise speed over the yaw rate limit, v / omega_max")
      ->check(kNonNegative);
  cmd->add_option("--start", o.start, "Boustrophedon start corner in the sweep frame")
      ->check(CLI::IsMember({"bottom-left", "bottom-right", "top-left", "top-right"}))
      ->capture_default_str();
  cmd->add_option("--start-vertex", o.start_vertex, "Spiral: start vertex of the first lap")->capture_default_str();
  cmd->add_flag("--clockwise", o.clockwise, "Spiral: fly the laps clockwise");
  cmd->add_option("--no-fly", o.no_fly, "Extra no-fly zone files, subtracted from the area")->check(CLI::ExistingFile);
  cmd->add_option("--out", o.out, "Path file to write (GeoJSON, lon/lat, one LineString feature per leg with scalar properties)");
  addForceFlag(cmd, o.force);
  addJsonFlag(cmd, o.json);
}

// The distance between passes [m]: --spacing, else the camera's swath at --altitude and --fov.
double passSpacing(const CoverageOpts& o) {
  if (o.spacing > 0.0) return o.spacing;
  if (!(o.fov_deg > 0.0 && o.fov_deg < 180.0)) {
    throw std::runtime_error("--fov = " + formatNumber(o.fov_deg) + " deg, expected a field of view in (0, 180) deg");
  }
  g::CameraSettings cam;
  cam.altitude = o.altitude;
  cam.fov = o.fov_deg * kDeg;
  cam.side_overlap = o.overlap;
  return g::swathSpacing(cam);
}

// The paths over every region of an area and what their checks found.
struct CoverageResult {
  std::vector<g::CoveragePath> paths;
  std::vector<std::string> problems;
  double required = 0.0, covered = 0.0;  // [m^2]
  g::ContainmentReport outside;          // summed over the regions
  int cells = 0;
};

// Covers each region of `area` (cells, routes joined, corners shaped) and checks the path: its
// geometry, the area it covers, where it leaves the region.
CoverageResult coverArea(const g::SurveyArea& area, const CoverageOpts& o, double spacing) {
  g::CornerSettings corners;
  corners.style = o.corners == "rounded" ? g::CornerStyle::Rounded : g::CornerStyle::Sharp;
  corners.radius = o.radius;
  CoverageResult cr;
  for (size_t r = 0; r < area.regions.size(); ++r) {
    const auto& region = area.regions[r];
    const std::vector<g::Route> routes = regionRoutes(region, o, spacing);
    cr.cells += static_cast<int>(routes.size());
    progress("coverage: region " + std::to_string(r) + ": " + std::to_string(routes.size()) + " cells");
    g::CoveragePath p = g::shapeCorners(g::joinRoutes(region, routes), corners, o.altitude, region);
    p.pattern = o.pattern;
    p.sweep_angle = o.angle_deg * kDeg;
    for (const auto& problem : g::checkPath(p, region)) cr.problems.push_back("region " + std::to_string(r) + ": " + problem);
    const auto report = g::checkCoverage(region, {p}, spacing);
    const auto c = g::checkContainment(region, p, false);
    cr.outside.outside_m += c.outside_m;
    cr.outside.in_holes_m += c.in_holes_m;
    cr.outside.max_depth_m = std::max(cr.outside.max_depth_m, c.max_depth_m);
    cr.required += report.required_area;
    cr.covered += report.covered_area;
    cr.paths.push_back(std::move(p));
  }
  return cr;
}

// The widest gap [m] between neighbouring passes of the boustrophedon paths (consecutive sweep legs
// of a cell; the lines are spread evenly, so it is at most the spacing asked); NaN for a spiral.
double widestPassGap(const CoverageResult& cr, const CoverageOpts& o, double spacing) {
  if (o.pattern != "boustrophedon") return std::nan("");
  const g::Point normal(-std::sin(o.angle_deg * kDeg), std::cos(o.angle_deg * kDeg));
  double widest = std::nan("");
  for (const auto& p : cr.paths) {
    std::optional<double> last;
    for (const auto& l : p.legs) {
      if (l.role != g::LegRole::Sweep || l.kind != g::PrimitiveKind::Line) continue;
      const double offset = normal.dot(0.5 * (l.start + l.end));
      const double gap = last ? std::abs(offset - *last) : 0.0;
      if (last && gap > 1e-3 && gap <= 1.001 * spacing) widest = std::isnan(widest) ? gap : std::max(widest, gap);
      last = offset;
    }
  }
  return widest;
}

// What the numbers do not show: arcs smaller than the --radius asked (they must fit between passes).
std::vector<std::string> coverageNotes(const CoverageResult& cr, const CoverageOpts& o) {
  std::vector<std::string> notes;
  if (o.corners != "rounded") return notes;
  double largest = 0.0;
  for (const auto& p : cr.paths)
    for (const auto& l : p.legs)
      if (l.kind == g::PrimitiveKind::Arc) largest = std::max(largest, l.radius);
  if (largest < 0.999 * o.radius) {
    notes.push_back("--radius " + formatNumber(o.radius) + " m does not fit: the arcs use at most " + fixedText(largest, 2) +
                    " m (an arc must fit between neighbouring passes and inside the area)");
  }
  return notes;
}

// Prints the coverage as JSON or text.
void printCoverage(const CoverageResult& cr, const CoverageOpts& o, double spacing) {
  const double gap = widestPassGap(cr, o, spacing);
  const std::vector<std::string> notes = coverageNotes(cr, o);
  size_t legs = 0;
  double length = 0.0;
  int turns = 0;
  for (const auto& p : cr.paths) {
    legs += p.legs.size();
    length += p.length();
    turns += p.turnCount();
  }
  const double coverage_pct = cr.required > 0.0 ? 100.0 * cr.covered / cr.required : 100.0;
  if (o.json) {
    printJson({{"legs", legs},
               {"length_m", length},
               {"turns", turns},
               {"coverage_pct", coverage_pct},
               {"cells", cr.cells},
               {"outside_area_m", cr.outside.outside_m},
               {"in_no_fly_m", cr.outside.in_holes_m},
               {"max_outside_depth_m", cr.outside.max_depth_m},
               {"pattern", o.pattern},
               {"angle_deg", o.angle_deg},
               {"spacing_m", spacing},
               {"widest_pass_gap_m", std::isnan(gap) ? nlohmann::json(nullptr) : nlohmann::json(gap)},
               {"problems", cr.problems},
               {"notes", notes}});
    return;
  }
  std::cout << "pattern:  " << o.pattern << " (sweep angle " << o.angle_deg << " deg)\n"
            << "spacing:  " << (std::isnan(gap) ? "" : "at most ") << spacing << " m"
            << (std::isnan(gap) ? std::string() : " (passes spread evenly across each cell: at most " + fixedText(gap, 2) + " m apart)")
            << "\n"
            << "cells:    " << cr.cells << "\n"
            << "legs:     " << legs << " (" << turns << " turns)\n"
            << "length:   " << length << " m\n"
            << "coverage: " << coverage_pct << " %\n"
            << "outside:  " << cr.outside.outside_m << " m outside the area, " << cr.outside.in_holes_m
            << " m in holes or no-fly zones\n";
  for (const auto& p : cr.problems) std::cout << "problem:  " << p << "\n";
  for (const auto& n : notes) std::cout << "note:     " << n << "\n";
  if (!o.out.empty()) std::cerr << "wrote " << o.out << std::endl;
}

// Runs `coverage` with options `o`.
void runCoverage(const CoverageOpts& o) {
  if (!o.out.empty()) {
    auto inputs = o.no_fly;
    inputs.push_back(o.area);
    checkWritable(o.out, o.force, inputs);
  }
  if (o.spacing <= 0.0 && o.altitude <= 0.0) {
    throw std::runtime_error("coverage: give --spacing M or --altitude M --fov DEG [--overlap F]");
  }
  if (o.corners == "rounded" && !(o.radius > 0.0)) {
    throw std::runtime_error("--corners rounded needs --radius M > 0, the arcs' radius: the cruise speed over the yaw rate "
                             "limit, v / omega_max (8 m/s at 2.1 rad/s: 3.8 m); without it the corners would be sharp");
  }
  g::ReadOptions ro;
  ro.no_fly_files = o.no_fly;
  const g::SurveyArea area = g::readSurveyArea(o.area, ro);
  const double spacing = passSpacing(o);
  const CoverageResult cr = coverArea(area, o, spacing);
  if (!o.out.empty()) {
    if (!area.frame) throw std::runtime_error(o.area + ": no geodetic frame, cannot write lat/lon to " + o.out);
    writeTextFileAtomic(o.out, g::coveragePathToGeoJson(cr.paths, *area.frame));
  }
  printCoverage(cr, o, spacing);
}

}  // namespace

void registerCoverageCommand(CLI::App& app) {
  auto o = std::make_shared<CoverageOpts>();
  auto* cmd = app.add_subcommand("coverage", "Coverage path over a survey area: boustrophedon or spiral");
  addCoverageOptions(cmd, *o);
  cmd->callback([o]() { runCoverage(*o); });
}

}  // namespace wattswath::apps
