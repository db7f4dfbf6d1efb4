// The work of a plan estimated before it starts (issue 20).
#include "plan_limits.hpp"

#include <cmath>
#include <stdexcept>

#include "cli.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/planner/mission_from_plan.hpp"

namespace wattswath::apps {

namespace {

/// A spacing [m] as the messages write it: 2 decimals, or 3 significant digits below 1 cm (a
/// camera's --overlap near 1 gives micrometres, which "0.00 m" hid).
std::string spacingText(double spacing) { return spacing >= 0.01 ? fixedText(spacing, 2) : formatNumber(spacing); }

}  // namespace

PlanWorkEstimate estimatePlanWork(const geometry::PolygonWithHoles& area, const std::vector<geometry::Ring>& no_fly,
                                  double spacing) {
  if (!(spacing > 0.0)) throw std::invalid_argument("estimatePlanWork: spacing must be > 0");
  PlanWorkEstimate e;
  e.vertices = area.outer.size();
  for (const auto& h : area.holes) e.vertices += h.size();
  for (const auto& z : no_fly) e.vertices += z.size();
  e.min_width_m = geometry::minimumWidth(area.outer);
  e.min_lines = std::floor(e.min_width_m / spacing);
  e.sweep_km = geometry::area(area) / spacing / 1000.0;
  e.summary = "plan: the area is at least " + fixedText(e.min_width_m, 1) + " m wide: at least " + fixedText(e.min_lines, 0) +
              " sweep lines at " + spacingText(spacing) + " m spacing, about " + fixedText(e.sweep_km, 1) + " km of sweeps";
  return e;
}

void checkPlanWork(const PlanWorkEstimate& e, double spacing, bool split, bool allow_large, const std::string& source,
                   bool from_camera) {
  const double items = 2.0 * e.min_lines;  // every line is entered and left: two waypoints at least
  const double max_items = static_cast<double>(mission::kMaxMissionItems);
  if (!split && items > max_items) {
    throw std::invalid_argument(
        source + ": at " + spacingText(spacing) + " m spacing" + (from_camera ? " (the camera's footprint and --overlap)" : "") +
        " the area (at least " + fixedText(e.min_width_m, 1) + " m wide) needs at least " + fixedText(e.min_lines, 0) +
        " sweep lines, so at least " + fixedText(items, 0) + " waypoints: more than one mission can hold (" +
        std::to_string(mission::kMaxMissionItems) + " items, MAVLink's limit). " +
        (from_camera ? "Lower --overlap (or fly higher) for a spacing of at least " : "Widen --spacing to at least ") +
        fixedText(std::ceil(e.min_width_m * 2.0 / max_items * 100.0) / 100.0, 2) + " m, or split the survey with --sorties");
  }
  if (!allow_large && e.vertices > kMaxAreaVerticesWithoutOverride) {
    throw std::invalid_argument(source + ": the area and its no-fly zones have " + std::to_string(e.vertices) +
                                " vertices, more than the " + std::to_string(kMaxAreaVerticesWithoutOverride) +
                                " planned without --allow-large (routing around the boundary grows faster than the "
                                "vertex count: minutes for a few thousand); simplify the boundary first (QGIS "
                                "Simplify, or ogr2ogr -simplify in a metric CRS; a tolerance of 0.5 m keeps the "
                                "shape), or give --allow-large to plan it anyway");
  }
  if (!allow_large && e.min_lines > kMaxSweepLinesWithoutOverride) {
    throw std::invalid_argument(source + ": at " + spacingText(spacing) + " m spacing the area (at least " +
                                fixedText(e.min_width_m, 1) + " m wide) needs at least " + fixedText(e.min_lines, 0) +
                                " sweep lines (about " + fixedText(e.sweep_km, 0) + " km of sweeps), more than the " +
                                fixedText(kMaxSweepLinesWithoutOverride, 0) +
                                " planned without --allow-large (planning time and memory grow with the line count); "
                                "check --spacing, or give --allow-large to plan it anyway");
  }
}

void checkCommandableSpeeds(double vehicle_max_speed, double camera_max_speed, const std::string& vehicle_source) {
  const double floor = planner::kMinCommandedSpeed;
  const std::string why = " m/s, the slowest speed a mission can command (ArduCopter 3.x ignores DO_CHANGE_SPEED below " +
                          fixedText(floor, 1) + " m/s), so the mission would fly faster than the limit; ";
  if (vehicle_max_speed < floor) {
    throw std::invalid_argument(vehicle_source + ": max_speed_mps " + fixedText(vehicle_max_speed, 2) + " m/s is below " +
                                fixedText(floor, 1) + why +
                                "raise it, or fly such a vehicle with the autopilot's own speed parameter (WPNAV_SPEED) set "
                                "and no speed commands");
  }
  if (camera_max_speed > 0.0 && camera_max_speed < floor) {
    throw std::invalid_argument("the camera's sweep speed limit " + fixedText(camera_max_speed, 2) + " m/s (--camera-max-speed "
                                "or trigger distance / --trigger-interval) is below " + fixedText(floor, 1) + why +
                                "lower --frontal-overlap or --trigger-interval, or fly higher");
  }
}

}  // namespace wattswath::apps
