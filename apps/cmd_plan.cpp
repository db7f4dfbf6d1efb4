// `wattswath plan`: survey area + vehicle -> minimum-energy coverage mission (.plan, .waypoints,
// GeoJSON path, CSV of legs) with baselines scored by the same model in the same run.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli.hpp"
#include "plan_flight.hpp"
#include "predict_options.hpp"
#include "plan_limits.hpp"
#include "plan_fleet.hpp"
#include "plan_sorties.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/model.hpp"
#include "report_data.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/geojson.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/mission/planned_mission.hpp"
#include "wattswath/geometry/clearance.hpp"
#include "wattswath/planner/camera.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/margin.hpp"
#include "wattswath/planner/battery_use.hpp"
#include "wattswath/planner/mission_from_plan.hpp"

namespace wattswath::apps {
namespace geo = wattswath::geometry;
namespace pl = wattswath::planner;
namespace ms = wattswath::mission;
namespace fs = std::filesystem;

namespace {

struct PlanOpts {
  std::string area, vehicle, home, out, corners = "auto", sensor_mm, image_px, layer, where;
  std::vector<std::string> no_fly;
  double spacing = 0.0, altitude = 10.0, fov_deg = 0.0, overlap = -1.0, camera_max_speed = 0.0;
  double fov_along_deg = 0.0, frontal_overlap = -1.0, focal_mm = 0.0;
  double gsd_cm = 0.0, trigger_interval_s = 0.0;  // --gsd [cm/px], --trigger-interval [s] (0: not given)
  double no_fly_margin = pl::kDefaultNoFlyMargin;
  SortieRequest sorties;
  double overshoot = 0.0;  // [m] --overshoot: sweep lines may run on beyond the boundary
  bool force = false, json = false, no_report = false, no_spiral = false, gpkg = false;
  bool allow_large = false;  // --allow-large: plan beyond kMaxSweepLinesWithoutOverride lines or kMaxAreaVerticesWithoutOverride vertices
  std::string report_svg, report;
  std::string wind;  // --wind SPEED,FROM (empty: still air)
};


/// [m] Farthest a take-off point may lie from the area's nearest vertex: the mission's local frame
/// is a plane tangent at the area (a point 500 km away lands 42.7 km off), and no multirotor
/// surveys that far from where it takes off.
constexpr double kMaxHomeDistanceM = 50e3;

/// Throws std::invalid_argument naming `what` when `home` lies more than kMaxHomeDistanceM from
/// every vertex of the area's outer ring (geodesic distances on WGS84).
void checkHomeNear(const geo::GeoPoint& home, const geo::Ring& outer, const geo::LocalFrame& frame, const std::string& what) {
  double nearest = INFINITY;
  for (const auto& v : outer) nearest = std::min(nearest, geo::geodesicDistance(home, frame.toGeodetic(v)));
  if (nearest > kMaxHomeDistanceM)
    throw std::invalid_argument(what + " (" + fixedText(home.lat_deg, 6) + ", " + fixedText(home.lon_deg, 6) + ") is " +
                                fixedText(nearest / 1000.0, 1) + " km from the nearest vertex of the area (WGS84 geodesic), "
                                "more than the " + fixedText(kMaxHomeDistanceM / 1000.0, 0) +
                                " km allowed: the mission's local frame would misplace it and no multirotor flies "
                                "there and back. Check the coordinates (LAT,LON order) or the area");
}

/// The take-off point of `--home LAT,LON` [deg]; throws std::invalid_argument naming the option.
geo::GeoPoint parseHome(const std::string& s) {
  const auto comma = s.find(',');
  double lat = NAN, lon = NAN;
  try {
    if (comma == std::string::npos) throw std::invalid_argument("no comma");
    size_t a = 0, b = 0;
    lat = std::stod(s.substr(0, comma), &a);
    lon = std::stod(s.substr(comma + 1), &b);
    if (a != comma || b != s.size() - comma - 1) throw std::invalid_argument("trailing text");
  } catch (const std::exception&) {
    throw std::invalid_argument("--home '" + s + "': expected LAT,LON in degrees, e.g. 43.7153,10.4616");
  }
  geo::validateGeoPoint({lat, lon, 0.0}, "--home");
  return {lat, lon, 0.0};
}

nlohmann::json candidateJson(const pl::PlanCandidate& c, double plan_energy) {
  if (!c.valid) return nullptr;
  return {{"energy_j", c.flown.energy},
          {"time_s", c.flown.time},
          {"length_m", c.flown.length},
          {"pattern", c.pattern},
          {"sweep_angle_deg", c.sweep_angle_deg},
          {"coverage_pct", c.coverage_pct},
          {"saving_pct", c.flown.energy > 0 ? 100.0 * (c.flown.energy - plan_energy) / c.flown.energy : 0.0}};
}

/// Per-cell choices of the plan (empty unless the per-cell search produced the plan).
nlohmann::json cellPlansJson(const std::vector<pl::CellPlan>& cells) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& c : cells)
    a.push_back({{"pattern", c.pattern}, {"sweep_angle_deg", c.sweep_angle_deg}, {"energy_j", c.energy_j}, {"area_m2", c.area_m2}});
  return a;
}

/// The one-angle boustrophedon energy at every searched sweep angle (null where none was found).
nlohmann::json sweepScanJson(const std::vector<pl::AngleScore>& scan) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& s : scan)
    a.push_back({{"sweep_angle_deg", s.sweep_angle_deg},
                 {"energy_j", std::isfinite(s.energy_j) ? nlohmann::json(s.energy_j) : nlohmann::json(nullptr)}});
  return a;
}

nlohmann::json batteryJson(const std::optional<pl::BatteryUse>& b) {
  if (!b) return nullptr;
  return {{"usable_energy_j", b->usable_energy_j}, {"mission_energy_j", b->mission_energy_j},
          {"margin_j", b->margin_j},             {"margin_pct", b->margin_pct},
          {"remaining_pct", b->remaining_pct},   {"reserve_pct", b->reserve_pct},
          {"fits", b->fits},                     {"depleted", b->depleted},
          {"warning", b->warning.empty() ? nlohmann::json(nullptr) : nlohmann::json(b->warning)}};
}

std::vector<ms::LegRecord> legRecords(const pl::FlownPath& f, const geo::LocalFrame& frame) {
  std::vector<ms::LegRecord> out;
  for (size_t i = 0; i < f.path.legs.size(); ++i) {
    const auto& leg = f.path.legs[i];
    ms::LegRecord l;
    l.start = frame.toGeodetic(leg.start);
    l.end = frame.toGeodetic(leg.end);
    l.kind = leg.kind == geo::PrimitiveKind::Line ? "line" : leg.kind == geo::PrimitiveKind::Arc ? "arc" : "turn_in_place";
    l.role = geo::roleName(leg.role);
    l.length_m = leg.length();
    l.speed_start_mps = f.speeds.junction[i];
    l.speed_cruise_mps = cruiseSpeedFlown(f, i);
    l.speed_end_mps = f.speeds.junction[i + 1];
    l.time_s = f.leg_time[i];
    l.energy_j = f.leg_energy[i];
    out.push_back(l);
  }
  return out;
}

/// The one-angle plan's angle with one sweep line more or fewer: its energy and coverage (null when
/// none was built).
nlohmann::json lineTradeJson(const pl::PlanResult& r) {
  if (!r.line_count_neighbour) return nullptr;
  const auto& c = r.line_count_neighbour->candidate;
  return {{"lines_delta", r.line_count_neighbour->lines_delta},
          {"sweep_angle_deg", c.sweep_angle_deg},
          {"energy_j", c.flown.energy},
          {"coverage_pct", c.coverage_pct}};
}

/// The plan's JSON (issue 5's keys, baselines, battery, files, notes); runPlan adds the mission.
nlohmann::json planJsonOf(const pl::PlanResult& r, const pl::SurveyProblem& pr, const PlanOpts& o, const fs::path& dir,
                          const std::vector<std::string>& notes) {
  const double e = r.plan.flown.energy;
  return {{"energy_j", e},
          {"time_s", r.plan.flown.time},
          {"length_m", r.plan.flown.length},
          {"pattern", r.plan.pattern},
          {"sweep_angle_deg", r.plan.sweep_angle_deg},
          {"coverage_pct", r.plan.coverage_pct},
          {"lower_bound_j", r.lower_bound_j},
          {"bound_ratio", r.lower_bound_j > 0 ? e / r.lower_bound_j : 0.0},
          {"spacing_m", pr.spacing},
          {"footprint_m", pr.footprint},
          {"altitude_m", pr.altitude},
          {"corner_strategy", o.corners},
          {"corners", {{"sharp", r.plan.flown.sharp_corners}, {"rounded", r.plan.flown.rounded_corners}}},
          {"cells", r.plan.cells},
          {"cell_plans", cellPlansJson(r.plan.cell_plans)},
          {"sweep_scan", sweepScanJson(r.sweep_scan)},
          {"per_cell", r.per_cell ? nlohmann::json{{"energy_j", r.per_cell->flown.energy},
                                                   {"pattern", r.per_cell->pattern},
                                                   {"coverage_pct", r.per_cell->coverage_pct},
                                                   {"cell_plans", cellPlansJson(r.per_cell->cell_plans)}}
                                  : nlohmann::json(nullptr)},
          {"line_count_trade", lineTradeJson(r)},
          {"candidates", r.candidates},
          {"baselines",
           {{"shortest_path", candidateJson(r.shortest_path, e)},
            {"ground_station_default", candidateJson(r.ground_station_default, e)},
            {"best_spiral", r.best_spiral ? candidateJson(*r.best_spiral, e) : nlohmann::json(nullptr)}}},
          {"battery", batteryJson(r.battery)},
          {"files", o.gpkg ? nlohmann::json{(dir / "mission.plan").string(), (dir / "mission.waypoints").string(),
                                            (dir / "path.geojson").string(), (dir / "legs.csv").string(), (dir / "plan.gpkg").string()}
                           : nlohmann::json{(dir / "mission.plan").string(), (dir / "mission.waypoints").string(),
                                            (dir / "path.geojson").string(), (dir / "legs.csv").string()}},
          {"notes", notes}};
}

/// The plan as text: what is flown first (the pattern, the flight as the autopilot model flies
/// mission.plan, the battery as predict says it), then the planner's own survey model and baselines.
void printPlanText(const pl::PlanResult& r, const PlanFlight& flight, double whole_area_pct, double margin) {
  const double e = r.plan.flown.energy;
  std::cout << std::fixed << std::setprecision(1);
  std::cout << "plan: " << r.plan.pattern;
  if (r.plan.pattern != "spiral") std::cout << " at " << std::setprecision(0) << r.plan.sweep_angle_deg << " deg";
  std::cout << std::setprecision(1) << ", coverage " << r.plan.coverage_pct << " %";
  if (margin > 0.0)
    std::cout << " of the area planned (" << whole_area_pct << " % of the area outside the no-fly zones, the margin band included)";
  std::cout << "\n";
  printFlight(flight);
  // The battery as predict gives it for mission.plan (its verdict, with --energy-margin).
  if (flight.prediction.battery.known)
    std::cout << "battery: the flight draws " << fixedText(flight.prediction.total.energy_j / 1000.0, 1) << " kJ. "
              << flight.prediction.battery.verdict << "\n";
  std::cout << std::setprecision(1) << "planner's survey model (closed form, first waypoint to last, the figures below compare): "
            << e / 1000.0 << " kJ, " << std::setprecision(0) << r.plan.flown.time << " s, " << r.plan.flown.length << " m\n";
  if (r.line_count_neighbour) {
    const auto& n = *r.line_count_neighbour;
    std::cout << "  line count: the one-angle plan at " << std::setprecision(0) << n.candidate.sweep_angle_deg
              << " deg with one line " << (n.lines_delta > 0 ? "more" : "fewer") << ": " << std::setprecision(1)
              << n.candidate.flown.energy / 1000.0 << " kJ, coverage " << n.candidate.coverage_pct << " %\n";
  }
  for (size_t i = 0; i < r.plan.cell_plans.size(); ++i) {
    const auto& c = r.plan.cell_plans[i];
    std::cout << "  cell " << i + 1 << ": " << c.pattern;
    if (c.pattern != "spiral") std::cout << " at " << std::setprecision(0) << c.sweep_angle_deg << " deg";
    std::cout << std::setprecision(0) << ", " << c.area_m2 << " m^2\n";
  }
  std::cout << std::setprecision(1) << "lower bound " << r.lower_bound_j / 1000.0 << " kJ (plan / bound "
            << std::setprecision(2) << e / r.lower_bound_j << ")\n"
            << std::setprecision(1);
  for (const auto& [name, c] : {std::pair<const char*, const pl::PlanCandidate*>{"shortest path", &r.shortest_path},
                                {"ground-station default", &r.ground_station_default}})
    std::cout << name << ": " << c->flown.energy / 1000.0 << " kJ (plan saves "
              << 100.0 * (c->flown.energy - e) / c->flown.energy << " % of this baseline's energy)\n";
  if (r.best_spiral)
    std::cout << "best spiral: " << r.best_spiral->flown.energy / 1000.0 << " kJ (plan saves "
              << 100.0 * (r.best_spiral->flown.energy - e) / r.best_spiral->flown.energy << " % of this baseline's energy)\n";
}

/// "A,B" as two positive numbers; throws std::invalid_argument naming `option` and `expected`.
std::pair<double, double> parsePair(const std::string& s, const std::string& option, const std::string& expected) {
  const auto comma = s.find(',');
  try {
    if (comma == std::string::npos) throw std::invalid_argument("no comma");
    size_t a = 0, b = 0;
    const double x = std::stod(s.substr(0, comma), &a), y = std::stod(s.substr(comma + 1), &b);
    if (a != comma || b != s.size() - comma - 1 || !(x > 0.0) || !(y > 0.0)) throw std::invalid_argument("bad");
    return {x, y};
  } catch (const std::exception&) {
    throw std::invalid_argument(option + " '" + s + "': expected " + expected);
  }
}

/// The area read and the problem set up from the options: spacing, or the camera's footprint.
struct PlanSetup {
  geo::SurveyArea area;
  pl::SurveyProblem problem;                 ///< [m] the area with its zones as read (no margin)
  std::optional<pl::PhotoGeometry> photos;   ///< the camera's photos (absent with --spacing)
  double side_overlap = 0.0, frontal_overlap = 0.0;  ///< [-] as used for the photos
  std::vector<std::string> notes;            ///< what the options left to a default
};

/// The camera of the options: --sensor-mm/--focal-mm (and --image-px), else --fov (and --fov-along).
pl::Camera cameraOf(const PlanOpts& o) {
  if (!o.sensor_mm.empty() || o.focal_mm > 0.0) {
    if (o.sensor_mm.empty() || !(o.focal_mm > 0.0))
      throw std::invalid_argument("give both --sensor-mm W,H and --focal-mm F (or --fov)");
    if (o.fov_deg > 0.0 || o.fov_along_deg > 0.0) throw std::invalid_argument("give either --fov or --sensor-mm/--focal-mm, not both");
    const auto sensor = parsePair(o.sensor_mm, "--sensor-mm", "W,H in mm, e.g. 23.2,15.4");
    const auto image = o.image_px.empty() ? std::pair<double, double>{0, 0}
                                          : parsePair(o.image_px, "--image-px", "W,H in pixels, e.g. 5456,3632");
    if (image.first != std::floor(image.first) || image.second != std::floor(image.second) || image.first > 1e6 || image.second > 1e6)
      throw std::invalid_argument("--image-px " + o.image_px + ": expected whole numbers of pixels W,H (at most 1000000), e.g. 5456,3632");
    return pl::Camera::fromSensor(sensor.first, sensor.second, o.focal_mm, static_cast<int>(image.first),
                                  static_cast<int>(image.second));
  }
  if (!(o.fov_deg > 0.0 && o.fov_deg < 180.0))
    throw std::invalid_argument("--fov = " + std::to_string(o.fov_deg) + " deg: expected (0, 180) (or give --spacing)");
  if (!o.image_px.empty()) throw std::invalid_argument("--image-px goes with --sensor-mm and --focal-mm");
  pl::Camera c;
  c.fov_across_rad = o.fov_deg * M_PI / 180.0;
  c.fov_along_rad = (o.fov_along_deg > 0.0 ? o.fov_along_deg : o.fov_deg) * M_PI / 180.0;
  return c;
}

/// Spacing and footprint of `s.problem` from --spacing, or from the camera with its overlaps.
void setSpacing(const PlanOpts& o, PlanSetup& s) {
  auto& pr = s.problem;
  const bool camera = o.fov_deg > 0.0 || o.fov_along_deg > 0.0 || !o.sensor_mm.empty() || o.focal_mm > 0.0 || o.overlap >= 0.0 ||
                      o.gsd_cm > 0.0;
  if (o.spacing > 0.0) {
    if (camera) throw std::invalid_argument("give either --spacing or a camera (--fov or --sensor-mm/--focal-mm, --overlap, --gsd), not both");
    if (o.frontal_overlap >= 0.0)
      throw std::invalid_argument("--frontal-overlap needs a camera (--fov or --sensor-mm/--focal-mm with --overlap), not --spacing");
    pr.spacing = pr.footprint = o.spacing;
    return;
  }
  if (o.overlap < 0.0)  // not given (its placeholder is -1)
    throw std::invalid_argument("a camera needs --overlap (the side overlap of its photos, a fraction in [0, 1), e.g. 0.7), "
                                "or give --spacing instead of a camera");
  if (!(o.overlap < 1.0))
    throw std::invalid_argument("--overlap = " + fixedText(o.overlap, 3) + ": expected a fraction in [0, 1) (or give --spacing)");
  s.side_overlap = o.overlap;
  s.frontal_overlap = o.frontal_overlap >= 0.0 ? o.frontal_overlap : o.overlap;
  if (o.frontal_overlap < 0.0)
    s.notes.push_back("camera: frontal overlap " + fixedText(100.0 * s.frontal_overlap, 0) +
                      " % taken from the side overlap (give --frontal-overlap)");
  const pl::Camera cam = cameraOf(o);
  if (o.gsd_cm > 0.0) {  // the altitude that gives this GSD (QGC's CameraCalc "fixed GSD" mode)
    if (cam.image_width_px <= 0)
      throw std::invalid_argument("--gsd " + fixedText(o.gsd_cm, 2) + " cm/px needs the image width: give --sensor-mm, --focal-mm and --image-px");
    pr.altitude = o.gsd_cm / 100.0 * cam.image_width_px / (2.0 * std::tan(0.5 * cam.fov_across_rad));
    if (!(pr.altitude >= 0.1 && pr.altitude <= 1000.0))
      throw std::invalid_argument("--gsd " + fixedText(o.gsd_cm, 2) + " cm/px gives an altitude of " + fixedText(pr.altitude, 1) +
                                  " m, outside 0.1..1000 m");
    s.notes.push_back("camera: altitude " + fixedText(pr.altitude, 1) + " m for a GSD of " + fixedText(o.gsd_cm, 2) + " cm/px");
  }
  s.photos = pl::photoGeometry(cam, pr.altitude, s.side_overlap, s.frontal_overlap);
  pr.footprint = s.photos->footprint_across_m;
  pr.spacing = s.photos->line_spacing_m;
  if (pr.spacing > 1000.0)
    throw std::invalid_argument("the camera at " + fixedText(pr.altitude, 1) + " m with side overlap " + fixedText(o.overlap, 2) +
                                " gives sweep lines " + fixedText(pr.spacing, 0) + " m apart (footprint " + fixedText(pr.footprint, 0) +
                                " m), more than the 1000 m planned: check --fov / --sensor-mm / --focal-mm and --altitude");
}

PlanSetup setUp(const PlanOpts& o) {
  PlanSetup s;
  geo::ReadOptions ro;
  ro.no_fly_files = o.no_fly;
  ro.layer = o.layer;
  ro.where = o.where;
  progress("plan: reading " + o.area);
  s.area = geo::readSurveyArea(o.area, ro);
  if (!s.area.frame) throw std::invalid_argument(o.area + ": the area has no geodetic frame (metric WKT without an origin); missions need lat/lon");
  auto& pr = s.problem;
  pr.area = s.area.polygon();
  pr.no_fly = s.area.no_fly;
  pr.altitude = o.altitude;
  setSpacing(o, s);
  if (pr.altitude > 120.0)
    s.notes.push_back("altitude " + fixedText(pr.altitude, 0) + " m above home: higher than the 120 m most rules allow (EU open "
                      "category, US 400 ft) and than ArduPilot's default FENCE_ALT_MAX (100 m); the written geofence has no "
                      "altitude limit, so check your vehicle's and your permission");
  const PlanWorkEstimate work = estimatePlanWork(pr.area, pr.no_fly, pr.spacing);
  progress(work.summary);
  checkPlanWork(work, pr.spacing, !o.sorties.sorties.empty(), o.allow_large, o.area, o.spacing <= 0.0);
  if (!o.home.empty()) {
    const geo::GeoPoint home = parseHome(o.home);
    checkHomeNear(home, pr.area.outer, *s.area.frame, "--home");
    pr.home = s.area.frame->toLocal(home.lat_deg, home.lon_deg);  // near the area, where the local frame is exact enough
  } else if (s.area.home) {
    pr.home = *s.area.home;
    checkHomeNear(s.area.frame->toGeodetic(pr.home), pr.area.outer, *s.area.frame, o.area + ": its home point");
  } else {
    pr.home = pr.area.outer.front();
  }
  return s;
}

/// Throws std::runtime_error when the flown path enters a zone or comes within the margin of one.
void checkFlown(const pl::SurveyProblem& pr, const geo::CoveragePath& path, double margin) {
  const auto problems = pl::checkPlan(pr, path);
  if (!problems.empty()) throw std::runtime_error("plan failed its own check: " + problems.front());
  if (margin <= 0.0) return;
  const auto close = geo::marginViolations(path, pl::noFlyZones(pr), margin);
  if (!close.empty())
    throw std::runtime_error("plan failed its own check: leg " + std::to_string(close.front().leg) + " passes " +
                             fixedText(close.front().distance_m, 2) + " m from no-fly zone " +
                             std::to_string(close.front().zone) + " (--no-fly-margin " + fixedText(margin, 2) + " m)");
}

/// The camera and mission facts of the output: photos, holds, fences, vehicle type.
nlohmann::json missionJson(const PlanSetup& s, const pl::PlanMission& pm, double margin, double photo_pct) {
  nlohmann::json camera = nullptr;
  if (s.photos)
    camera = {{"trigger_distance_m", s.photos->trigger_distance_m},
              {"footprint_across_m", s.photos->footprint_across_m},
              {"footprint_along_m", s.photos->footprint_along_m},
              {"line_spacing_m", s.photos->line_spacing_m},
              {"side_overlap", s.side_overlap},
              {"frontal_overlap", s.frontal_overlap},
              {"gsd_m", s.photos->gsd_m > 0.0 ? nlohmann::json(s.photos->gsd_m) : nlohmann::json(nullptr)},
              {"photos", pm.photos},
              {"photo_coverage_pct", photo_pct},
              {"camera_runs", pm.camera_runs},
              {"camera_length_m", pm.camera_length_m}};
  return {{"camera", camera},
          {"holds", pm.holds},
          {"hold_s", pl::kStopHoldSeconds},
          {"vehicle_type", pm.mission.vehicle_type},
          {"no_fly_margin_m", margin},
          {"waypoint_legs_within_margin", pm.legs_within_margin},
          {"inclusion_fence_distance_m", pm.fence_distance_m}};
}

/// The camera and mission lines of the text output.
void printMission(const PlanSetup& s, const pl::PlanMission& pm, double margin, double photo_pct, double hover_power_w) {
  std::cout << std::fixed << std::setprecision(1);
  if (s.photos) {
    const auto& g = *s.photos;
    std::cout << "camera: a photo every " << std::setprecision(2) << g.trigger_distance_m << " m along " << pm.camera_runs
              << " sweeps (footprint " << std::setprecision(1) << g.footprint_across_m << " x " << g.footprint_along_m
              << " m, lines " << g.line_spacing_m << " m apart";
    if (g.gsd_m > 0.0) std::cout << ", GSD " << std::setprecision(2) << 100.0 * g.gsd_m << " cm/px";
    std::cout << "): " << pm.photos << " photos covering " << std::setprecision(1) << photo_pct
              << " % of the area (turns and transits take none)\n";
  } else {
    std::cout << "camera: no camera commands written (--spacing has no camera; give --altitude with --fov or "
                 "--sensor-mm/--focal-mm, --overlap and --frontal-overlap for photos)\n";
  }
  std::cout << std::setprecision(1) << "mission: " << pm.holds << (pm.holds == 1 ? " planned stop holds " : " planned stops hold ")
            << pl::kStopHoldSeconds
            << " s (about " << pm.holds * pl::kStopHoldSeconds * hover_power_w / 1000.0
            << " kJ of hover not in the plan's energy); legs keep " << margin
            << " m from the no-fly zones; inclusion fence " << pm.fence_distance_m << " m outside the area\n";
}

/// Where the HTML report goes: --report, else DIR/report.html.
std::string reportPath(const PlanOpts& o) { return o.report.empty() ? (fs::path(o.out) / "report.html").string() : o.report; }

/// The run's input files: the area, the vehicle and the no-fly files.
std::vector<std::string> planInputs(const PlanOpts& o) {
  std::vector<std::string> inputs = {o.area, o.vehicle};
  inputs.insert(inputs.end(), o.no_fly.begin(), o.no_fly.end());
  return inputs;
}

// The files of this run, checked: none may overwrite an input (even with --force), each may
// replace an existing file only with --force.
void checkPlanOutputs(const PlanOpts& o) {
  std::vector<std::string> files = {"mission.plan", "mission.waypoints", "path.geojson", "legs.csv"};
  if (!o.no_report && o.report.empty()) files.push_back("report.html");
  if (o.gpkg) files.push_back("plan.gpkg");
  const std::vector<std::string> inputs = planInputs(o);
  for (const auto& f : files) checkWritable((fs::path(o.out) / f).string(), o.force, inputs);
  if (!o.no_report && !o.report.empty()) checkWritable(o.report, o.force, inputs);
}

// The search's settings from the options; a trigger interval caps the sweeps' speed (one photo per
// trigger distance at most every interval), with a note.
pl::PlannerSettings plannerSettings(const PlanOpts& o, PlanSetup& s, const energy::Vehicle& vehicle) {
  pl::PlannerSettings ps;
  ps.corners = pl::cornerStrategyFromString(o.corners);
  ps.camera_max_speed = o.camera_max_speed;
  if (o.trigger_interval_s > 0.0) {
    if (!s.photos) throw std::invalid_argument("--trigger-interval needs a camera (--fov or --sensor-mm/--focal-mm with --overlap)");
    const double cap = s.photos->trigger_distance_m / o.trigger_interval_s;
    ps.camera_max_speed = ps.camera_max_speed > 0.0 ? std::min(ps.camera_max_speed, cap) : cap;
    s.notes.push_back("camera: sweeps at most " + fixedText(ps.camera_max_speed, 2) + " m/s (a photo every " +
                      fixedText(s.photos->trigger_distance_m, 2) + " m, at least " + fixedText(o.trigger_interval_s, 2) + " s apart)");
  }
  checkCommandableSpeeds(vehicle.max_speed_mps, ps.camera_max_speed, o.vehicle);
  ps.spirals = !o.no_spiral;
  ps.overshoot = o.overshoot;
  return ps;
}

// How the finalists are flown: the area, its frame and home altitude, the mission options (camera
// trigger, fences, margins), the vehicle and the run's wind.
pl::FlightScoring flightScoring(const PlanOpts& o, const PlanSetup& s, const energy::Vehicle& vehicle,
                                const std::optional<Wind>& wind) {
  pl::MissionOptions mo;
  mo.trigger_distance_m = s.photos ? s.photos->trigger_distance_m : 0.0;
  mo.rotor_count = vehicle.rotor_count;
  mo.fence_margin_m = o.no_fly_margin > 0.0 ? o.no_fly_margin : pl::kDefaultNoFlyMargin;
  mo.no_fly_margin_m = o.no_fly_margin;
  pl::FlightScoring scoring;
  scoring.problem = &s.problem;
  scoring.frame = &*s.area.frame;
  scoring.home_altitude_amsl_m = s.area.home_alt_m.value_or(s.area.frame->origin().alt_m);
  scoring.mission = mo;
  scoring.vehicle = &vehicle;
  if (wind) scoring.settings.wind = wind->air();
  scoring.settings.reserve_fraction = o.sorties.reserve_pct / 100.0;  // --reserve, for the flight's verdict
  scoring.settings.energy_margin = o.sorties.energy_margin_pct / 100.0;  // --energy-margin, as predict's verdict
  return scoring;
}

// Writes the mission (.plan, .waypoints), the path (GeoJSON, legs.csv, the GeoPackage with --gpkg)
// into --out; returns the .plan text.
std::string writePlanFiles(const PlanOpts& o, const PlanSetup& s, const pl::PlanResult& r, const pl::PlanMission& pm) {
  const auto& frame = *s.area.frame;
  geo::PathGeoJsonOptions go;
  go.leg_properties["speed_mps"] = r.plan.flown.speeds.cruise;
  go.leg_properties["energy_j"] = r.plan.flown.leg_energy;
  go.leg_properties["time_s"] = r.plan.flown.leg_time;
  const fs::path dir(o.out);
  const std::string plan_text = ms::toQgcPlan(pm.mission);
  writeTextFileAtomic((dir / "mission.plan").string(), plan_text);
  writeTextFileAtomic((dir / "mission.waypoints").string(), ms::toQgcWpl(pm.mission));
  const std::string path_geojson = geo::coveragePathToGeoJson({r.plan.flown.path}, frame, go);
  writeTextFileAtomic((dir / "path.geojson").string(), path_geojson);
  if (o.gpkg)
    stageOutput((dir / "plan.gpkg").string(), [&](const std::string& tmp) {
      geo::writeGeoPackage(tmp, {{"legs", path_geojson}, {"area", geo::surveyAreaToGeoJson(s.area)}});
    });
  writeTextFileAtomic((dir / "legs.csv").string(), ms::toLegCsv(legRecords(r.plan.flown, frame)));
  return plan_text;
}

// The plan report: the search, the mission as the ground station numbers it, the flight, the photos
// and the sorties.
void writePlanReport(const PlanOpts& o, const PlanSetup& s, const pl::PlanResult& r, const energy::Vehicle& vehicle,
                     const energy::EnergyModel& model, const PlanFlight& flight, const std::string& plan_text,
                     const std::optional<SortieOutcome>& split) {
  const auto& pm = flight.mission;
  auto data = planReportData(r, s.problem, vehicle, model, o.area, flight.prediction);
  data.items = planMapItems(ms::parseQgcPlan(plan_text, "mission.plan"), *s.area.frame);
  const std::string gsd = s.photos && s.photos->gsd_m > 0.0 ? ", GSD " + fixedText(100.0 * s.photos->gsd_m, 2) + " cm/px" : "";
  data.facts.push_back({"flown by", flight.autopilot + ": " + fixedText(flight.prediction.total.energy_j / 1000.0, 1) + " kJ, " +
                                        report::formatMinSec(flight.prediction.total.time_s) +
                                        " min:s from take-off to landing (what predict gives for mission.plan)"});
  data.facts.push_back({"photos", s.photos ? std::to_string(pm.photos) + " (a photo every " +
                                                 fixedText(s.photos->trigger_distance_m, 2) + " m" + gsd + ")"
                                           : std::string("no camera commands")});
  if (split) data.sorties = split->view;
  writeReport(report::planReport(data), o.no_report ? std::string() : reportPath(o), o.report_svg, o.force);
}

// What the written path covers and where it strays, checked after the files are written.
struct PlanChecks {
  double whole_area_pct = 0.0;  // [%] coverage of the whole area, the no-fly margin band counted
  double photo_pct = 0.0;       // [%] coverage of the legs the camera is on along
  geo::ContainmentReport inside;  // the path outside the area and in no-fly zones
};

/// [s] Photos closer together in time than this get a note asking to check the camera (many survey
/// cameras take one every 1-2 s).
constexpr double kCheckTriggerIntervalS = 1.5;

// [%] The share of the area the photos cover: the camera's footprint along the legs it is on along.
double photoCoveragePct(const pl::SurveyProblem& flown_pr, const pl::PlanResult& r, const pl::PlanMission& pm) {
  geo::CoveragePath photographed;
  for (int i : pm.camera_legs) photographed.legs.push_back(r.plan.flown.path.legs[static_cast<size_t>(i)]);
  return pl::coveragePercent(flown_pr, photographed);
}

// Checks the written path's coverage, its photos' and its containment; adds notes when the photos
// cover less than the plan or the path strays.
PlanChecks checkPlan(const PlanOpts& o, const PlanSetup& s, const pl::SurveyProblem& flown_pr, const pl::PlanResult& r,
                     const pl::PlanMission& pm, std::vector<std::string>& notes) {
  const auto& pr = s.problem;
  PlanChecks c;
  const bool margin_cut = o.no_fly_margin > 0.0 && !pl::noFlyZones(pr).empty();
  c.whole_area_pct = margin_cut ? pl::coveragePercent(pr, r.plan.flown.path) : r.plan.coverage_pct;
  c.photo_pct = s.photos ? photoCoveragePct(flown_pr, r, pm) : 0.0;
  if (s.photos && c.photo_pct < 99.0)
    notes.push_back("camera: the photos cover " + fixedText(c.photo_pct, 1) +
                    " % of the area, less than the plan's coverage: the camera is off along turns (a spiral's corner "
                    "arcs too), whose footprint the plan's coverage counts");
  if (s.photos && o.trigger_interval_s <= 0.0) {
    // A camera takes a photo at most so often; without --trigger-interval the sweeps are not capped for it.
    double fastest = 0.0;
    for (int i : pm.camera_legs) fastest = std::max(fastest, r.plan.flown.speeds.cruise[static_cast<size_t>(i)]);
    const double every = fastest > 0.0 ? s.photos->trigger_distance_m / fastest : 0.0;
    if (every > 0.0 && every < kCheckTriggerIntervalS)
      notes.push_back("camera: the sweeps are flown at up to " + fixedText(fastest, 1) + " m/s with a photo every " +
                      fixedText(s.photos->trigger_distance_m, 2) + " m, one every " + fixedText(every, 2) +
                      " s: check that the camera triggers that fast, or give --trigger-interval S (its shortest interval) "
                      "to cap the sweep speed");
  }
  c.inside = pl::planContainment(pr, r.plan.flown.path);
  if (c.inside.total() > 0.0 && o.overshoot <= 0.0)  // the tests hold this at 0; say so if it ever is not
    notes.push_back("the path runs " + fixedText(c.inside.outside_m, 2) + " m outside the area and " +
                    fixedText(c.inside.in_holes_m, 2) + " m in no-fly zones (up to " + fixedText(c.inside.max_depth_m, 2) +
                    " m deep); please report the area");
  return c;
}

// [%] Photos must cover at least this much of the area before a plan with arcs (a spiral's corners,
// where the camera is off) is written for a camera; else straight sweeps are planned instead.
constexpr double kPhotoCoverageMinPct = 99.0;

// A camera is off along turns, and a spiral turns at every corner, so the cheapest plan can
// photograph far less than its swath covers (63 % of the E-Spiral polygon). When the chosen plan's
// photos miss kPhotoCoverageMinPct, the area is planned again with straight sweeps only (as
// --no-spiral), and that plan is kept when its photos cover more; a note says what was traded.
void straightIfPhotosMiss(const pl::SurveyProblem& flown_pr, const energy::Vehicle& vehicle, const energy::EnergyModel& model,
                          const pl::PlannerSettings& ps, const pl::FlightScoring& scoring, const std::string& vehicle_path,
                          pl::PlanResult& r, PlanFlight& flight, std::vector<std::string>& flight_notes) {
  if (r.plan.pattern == "boustrophedon") return;  // straight sweeps already: nothing to trade
  const double pct = photoCoveragePct(flown_pr, r, flight.mission);
  if (pct >= kPhotoCoverageMinPct) return;
  progress("plan: the photos of the " + r.plan.pattern + " plan cover " + fixedText(pct, 1) +
           " % of the area; planning again with straight sweeps only");
  pl::PlannerSettings straight = ps;
  straight.spirals = false;
  pl::PlanResult r2 = pl::planCoverage(flown_pr, vehicle, model, straight, [](const std::string& line) { progress(line); });
  std::vector<std::string> notes2;
  PlanFlight f2 = flyFinalists(r2, scoring, vehicle_path, notes2);
  const double pct2 = photoCoveragePct(flown_pr, r2, f2.mission);
  const std::string was = "the cheapest plan (" + r.plan.pattern + ", " + fixedText(flight.prediction.total.energy_j / 1000.0, 1) +
                          " kJ as flown) photographs " + fixedText(pct, 1) + " % of the area (the camera is off along its turns)";
  if (pct2 <= pct) {
    flight_notes.push_back("camera: " + was + "; straight sweeps would photograph " + fixedText(pct2, 1) + " %, so it is kept");
    return;
  }
  notes2.push_back("camera: " + was + "; written instead: straight sweeps (" + r2.plan.pattern + ", " +
                   fixedText(f2.prediction.total.energy_j / 1000.0, 1) + " kJ as flown), whose photos cover " +
                   fixedText(pct2, 1) + " % (--no-spiral plans so from the start)");
  r = std::move(r2);
  flight = std::move(f2);
  flight_notes = std::move(notes2);
}

void runPlan(const PlanOpts& o) {
  const std::optional<Wind> wind = windOption(o.wind);
  const auto vehicle = energy::loadVehicle(o.vehicle);
  PlanSetup s = setUp(o);
  const auto& pr = s.problem;
  // Every file of this run is staged and renamed into place together at the end (OutputSet), and
  // --out stays locked until then: a failure midway keeps the previous run's files, and a second
  // run into the same folder is refused instead of clobbering them.
  OutputSet out_set(o.out);
  checkPlanOutputs(o);
  const pl::PlannerSettings ps = plannerSettings(o, s, vehicle);
  // In wind the search takes the drag at air speed, so a leg's energy depends on its heading.
  const auto marins = energy::marinsModel(vehicle);
  const auto model = wind ? energy::withWind(marins, vehicle, wind->air().x(), wind->air().y()) : marins;
  if (wind) s.notes.push_back("wind: " + wind->text() + "; the sweep direction and speeds are chosen for it");
  const std::size_t notes_before = s.notes.size();
  const auto flown_pr = pl::withNoFlyMargin(pr, o.no_fly_margin, &s.notes);
  for (std::size_t k = notes_before; k < s.notes.size(); ++k)
    if (s.notes[k].rfind("WARNING", 0) == 0) progress(s.notes[k]);  // at once, not only at the end
  auto r = pl::planCoverage(flown_pr, vehicle, model, ps, [](const std::string& line) { progress(line); });

  pl::FlightScoring scoring = flightScoring(o, s, vehicle, wind);
  std::vector<std::string> flight_notes;
  progress("plan: flying the finalists' missions with the vehicle's autopilot model");
  PlanFlight flight = flyFinalists(r, scoring, o.vehicle, flight_notes);
  if (s.photos && ps.spirals) straightIfPhotosMiss(flown_pr, vehicle, model, ps, scoring, o.vehicle, r, flight, flight_notes);
  // The battery as the written mission flies, take-off to landing (the flight model's pieces), with
  // --reserve: the verdict, the chart and predict on mission.plan agree.
  if (vehicle.battery) {
    pl::BatteryUseSettings bs;
    bs.reserve_fraction = o.sorties.reserve_pct / 100.0;
    // The search's own warning (its idealised plan) gives way to the flight's.
    if (r.battery && !r.battery->warning.empty())
      r.notes.erase(std::remove(r.notes.begin(), r.notes.end(), r.battery->warning), r.notes.end());
    r.battery = pl::predictBatteryUse(ms::powerProfile(flight.prediction), *vehicle.battery, bs);
    // With --sorties the one flight is what is split (each sortie written fits, or the split fails).
    if (!r.battery->fits) {
      std::string why = r.battery->warning;
      if (const auto cut = why.find("; split the area"); cut != std::string::npos) why.erase(cut);
      r.notes.push_back(o.sorties.sorties.empty() ? r.battery->warning
                                                  : "mission.plan, the whole survey in one flight, does not fit the battery (" +
                                                        why + "): fly the sorties written beside it, "
                                                        "each of which lands with the reserve");
    }
  }
  if (r.battery && !r.battery->fits && o.sorties.sorties.empty()) progress("WARNING: " + r.battery->warning);
  checkFlown(pr, r.plan.flown.path, o.no_fly_margin);
  const auto& pm = flight.mission;
  std::vector<std::string> notes = s.notes;
  notes.insert(notes.end(), flight_notes.begin(), flight_notes.end());
  notes.insert(notes.end(), r.notes.begin(), r.notes.end());
  notes.insert(notes.end(), pm.notes.begin(), pm.notes.end());
  if (flight.calibration_note) notes.push_back(*flight.calibration_note);
  const fs::path dir(o.out);
  const std::string plan_text = writePlanFiles(o, s, r, pm);
  const std::size_t written_items = ms::parseQgcPlan(plan_text, "mission.plan").items.size();
  if (std::string n = ms::missionSizeNote(written_items, flight.flown_by, "mission.plan"); !n.empty()) notes.push_back(n);
  std::optional<SortieOutcome> split;
  if (!o.sorties.sorties.empty()) {
    progress("plan: splitting into sorties for the battery (" + o.sorties.sorties + ", reserve " + fixedText(o.sorties.reserve_pct, 0) + " %)");
    scoring.mission.arc_waypoints = flight.arc_waypoints;  // the sorties are written as the mission was
    scoring.mission.speeds_a_waypoint_early = flight.speeds_a_waypoint_early;
    SortieRequest req = o.sorties;
    req.force = o.force;
    req.inputs = planInputs(o);
    split = planSorties(r.plan, flight, scoring, o.vehicle, req, dir);
  }
  // Sortie files an earlier run left here would be flown with this mission's: refused, or with
  // --force removed once this run's files are in place.
  const auto stale = staleSortieFiles(dir, split ? split->files : std::vector<std::string>{}, planInputs(o));
  if (!stale.empty() && !o.force) {
    std::string list;
    for (const auto& f : stale) list += (list.empty() ? "" : ", ") + f;
    throw std::runtime_error(o.out + " holds sortie files an earlier run wrote and this one does not (" + list +
                             "): a pilot flying every sortie file there would fly another survey; remove them, or give "
                             "--force to have them removed");
  }
  const nlohmann::json sorties = split ? split->json : nlohmann::json(nullptr);
  if (!o.no_report || !o.report_svg.empty()) writePlanReport(o, s, r, vehicle, model, flight, plan_text, split);
  out_set.commit();
  for (const auto& f : stale) {
    std::error_code ec;
    fs::remove(dir / f, ec);
    notes.push_back(ec ? "could not remove " + (dir / f).string() + ", left by an earlier run: " + ec.message()
                       : "removed " + f + ", a sortie file an earlier run left in " + o.out + " (--force)");
  }
  const PlanChecks c = checkPlan(o, s, flown_pr, r, pm, notes);
  if (o.json) {
    auto j = planJsonOf(r, pr, o, dir, notes);
    j["coverage_outside_zones_pct"] = c.whole_area_pct;
    j["outside_area_m"] = c.inside.outside_m;
    j["in_no_fly_m"] = c.inside.in_holes_m;
    j["max_outside_depth_m"] = c.inside.max_depth_m;
    j["mission"] = missionJson(s, pm, o.no_fly_margin, c.photo_pct);
    j["flight"] = flightJson(flight);
    if (j["battery"].is_object()) {  // predict's verdict on mission.plan, with --energy-margin
      const auto& b = flight.prediction.battery;
      j["battery"]["energy_margin_pct"] = 100.0 * b.energy_margin;
      j["battery"]["fits_with_margin"] = b.fits_with_margin;
      j["battery"]["verdict"] = b.verdict;
    }
    j["sorties"] = sorties;
    j["wind"] = windJson(wind);
    printJson(j);
    return;
  }
  printPlanText(r, flight, c.whole_area_pct, o.no_fly_margin);
  printMission(s, pm, o.no_fly_margin, c.photo_pct, energy::marinsHoverPowerW(vehicle));
  if (!sorties.is_null()) printSorties(sorties);
  for (const auto& n : notes) std::cout << "note: " << n << "\n";
  std::string sortie_files;
  if (!sorties.is_null() && !sorties["sorties"].empty()) {
    const auto& list = sorties["sorties"];
    sortie_files = ", " + std::to_string(list.size()) + " sorties (" + list.front()["file"].get<std::string>() +
                   (list.size() > 1 ? " to " + list.back()["file"].get<std::string>() : "") + ", each with its .waypoints)";
  }
  std::cout << "wrote " << (dir / "mission.plan").string() << ", mission.waypoints, path.geojson, legs.csv"
            << (o.gpkg ? ", plan.gpkg" : "") << sortie_files << (o.no_report ? std::string() : ", " + reportPath(o)) << "\n";
}

}  // namespace

void registerPlanCommand(CLI::App& app) {
  auto o = std::make_shared<PlanOpts>();
  auto* cmd = app.add_subcommand("plan", "Plan the minimum-energy coverage flight of a survey area and write the mission");
  cmd->add_option("AREA", o->area,
                  "survey area: GeoJSON, KML, WKT, QGC .waypoints or .plan, Mission Planner .poly, or any polygon "
                  "format GDAL reads (GeoPackage, Shapefile, GML, ...; see `wattswath area info --help`)")
      ->required()
      ->check(CLI::ExistingFile);
  addVehicleOption(cmd, o->vehicle);
  cmd->add_option("--no-fly", o->no_fly, "no-fly zone file(s)")->check(CLI::ExistingFile);
  addAreaSelectOptions(cmd, o->layer, o->where);
  cmd->add_option("--home", o->home, "take-off point LAT,LON [deg] (default: the area file's home, else its first vertex)");
  cmd->add_option("--spacing", o->spacing, "distance between sweep lines [m], (0, 1000]")->check(kPositive)->check(CLI::Range(0.0, 1000.0));
  cmd->add_flag("--allow-large", o->allow_large,
                "Plan even when the area needs more than 5000 sweep lines at this spacing or has more than 1000 "
                "vertices (refused by default: planning time and memory grow with them)");
  auto* altitude = cmd->add_option("--altitude", o->altitude, "flight height above home [m] (default 10)")->check(CLI::Range(0.1, 1000.0));
  cmd->add_option("--gsd", o->gsd_cm, "ground sampling distance [cm/px] that sets the altitude (with --sensor-mm, --focal-mm, --image-px; instead of --altitude)")
      ->check(CLI::Range(0.01, 1000.0))
      ->excludes(altitude);
  cmd->add_option("--trigger-interval", o->trigger_interval_s, "shortest time between photos the camera allows [s]: caps the sweep speed at trigger distance / interval")
      ->check(CLI::Range(0.01, 3600.0));
  cmd->add_option("--fov", o->fov_deg, "camera field of view across track [deg], (0, 180)")->check(kPositive)->check(CLI::Range(0.0, 179.9));
  cmd->add_option("--fov-along", o->fov_along_deg, "camera field of view along track [deg] (default: --fov, a square footprint)")
      ->check(CLI::Range(0.0, 180.0));
  cmd->add_option("--sensor-mm", o->sensor_mm, "camera sensor width,height [mm], with --focal-mm (instead of --fov)");
  cmd->add_option("--focal-mm", o->focal_mm, "camera focal length [mm], with --sensor-mm")->check(kPositive);
  cmd->add_option("--image-px", o->image_px, "image width,height [px], with --sensor-mm: ground sampling distance");
  cmd->add_option("--overlap", o->overlap, "side overlap between neighbouring swaths, fraction in [0, 1)")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--frontal-overlap", o->frontal_overlap,
                  "overlap between consecutive photos along a sweep, fraction in [0, 1) (default: --overlap); sets the "
                  "camera trigger distance")
      ->check(CLI::Range(0.0, 0.999));
  cmd->add_option("--no-fly-margin", o->no_fly_margin,
                  "distance every flown point keeps from the no-fly zones, for GPS and tracking error [m] (default 2; 0: none)")
      ->check(CLI::Range(0.0, 100.0));
  addSortieOptions(cmd, o->sorties);
  cmd->add_option("--overshoot", o->overshoot,
                  "let sweep lines run on this far beyond the area's boundary to turn there (QGC's turnaround distance) "
                  "[m] (default 0: every flown point from the first sweep to the last stays inside the area; the way out from "
                  "home and back is not counted, as home may lie outside it)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--camera-max-speed", o->camera_max_speed, "largest ground speed on sweep legs the camera allows [m/s] (0: none)")
      ->check(CLI::Range(0.0, 200.0));
  cmd->add_option("--corner-strategy", o->corners, "sharp, rounded or auto (cheapest per corner)")
      ->check(CLI::IsMember({"sharp", "rounded", "auto"}));
  cmd->add_option("--wind", o->wind,
                  "Steady wind SPEED,FROM: SPEED [m/s] blowing from the compass bearing FROM [deg] (0 north, 90 east), as a "
                  "forecast gives it, e.g. 6,45: the search takes the drag at air speed and the finalists are flown in it "
                  "(default: still air)");
  cmd->add_option("--out", o->out, "output folder for mission.plan, mission.waypoints, path.geojson, legs.csv")->required();
  cmd->add_flag("--force", o->force,
                "overwrite existing output files, and remove sortie files (sortie_NN.*, vehicle_K_sortie_NN.*) an earlier "
                "run left in --out that this run does not write (never an input file)");
  cmd->add_flag("--no-spiral", o->no_spiral,
                "straight parallel lines only: spirals do not compete (consistent image headings for photogrammetry)");
  cmd->add_flag("--no-report", o->no_report, "do not write DIR/report.html (the HTML plan report, on by default)");
  cmd->add_flag("--gpkg", o->gpkg, "also write DIR/plan.gpkg: the legs and the area (holes, home) as GeoPackage layers for QGIS");
  cmd->add_option("--report", o->report, "write the HTML report here instead of DIR/report.html");
  cmd->add_option("--report-svg", o->report_svg, "also write the report's figures as SVG files into this folder");
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    if (o->spacing <= 0.0 && o->fov_deg <= 0.0 && o->sensor_mm.empty())
      throw std::invalid_argument("give --spacing M, or --altitude M --fov DEG --overlap F (or --sensor-mm W,H --focal-mm F)");
    if (o->sorties.vehicles > 0 && o->sorties.sorties.empty()) o->sorties.sorties = "auto";
    runPlan(*o);
  });
}

}  // namespace wattswath::apps
