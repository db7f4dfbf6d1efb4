#pragma once
// The work of a plan estimated before it starts (issue 20): a lower bound on the sweep lines any
// direction needs, and the refusals it supports.
#include <cstddef>
#include <string>
#include <vector>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::apps {

/// Sweep lines planned without --allow-large: planning time and memory grow with the line count
/// (1 km^2 at 0.05 m spacing, 20,000 lines, ran 9 minutes and wrote a 99,815-item mission).
inline constexpr double kMaxSweepLinesWithoutOverride = 5000;

/// Vertices (area boundary, holes and no-fly zones) planned without --allow-large: the transit
/// router and the coverage checks grow faster than linearly with them (a wiggly 1,800-vertex field
/// took over 2 minutes; 1,000 stay within about a minute on the 2-core build machine).
inline constexpr size_t kMaxAreaVerticesWithoutOverride = 1000;

/// What a plan of `area` at `spacing` [m] needs at least, before any work.
struct PlanWorkEstimate {
  size_t vertices = 0;        ///< vertices of the area's rings and the no-fly zones
  double min_width_m = 0.0;   ///< [m] the area's minimum width (CGAL's minimum enclosing strip)
  double min_lines = 0.0;     ///< sweep lines any direction needs: floor(width / spacing)
  double sweep_km = 0.0;      ///< [km] about area / spacing of sweeps
  std::string summary;        ///< one line for the progress output
};

/// The estimate for `area` (with the extra `no_fly` zones) at `spacing` [m] (> 0).
PlanWorkEstimate estimatePlanWork(const geometry::PolygonWithHoles& area, const std::vector<geometry::Ring>& no_fly,
                                  double spacing);

/// Throws std::invalid_argument naming `source`, the width, the spacing and the bound when the
/// plan cannot fit one mission (2 waypoints per line beyond mission::kMaxMissionItems, unless
/// `split` into sorties) or needs more than kMaxSweepLinesWithoutOverride lines (unless
/// `allow_large`) or more than kMaxAreaVerticesWithoutOverride vertices (unless `allow_large`),
/// saying which option changes it.
/// `from_camera`: the spacing came from the camera's footprint and --overlap (the message names
/// those options instead of --spacing).
void checkPlanWork(const PlanWorkEstimate& e, double spacing, bool split, bool allow_large, const std::string& source,
                   bool from_camera = false);

/// Throws std::invalid_argument when the vehicle's max speed or the camera's sweep-speed cap [m/s]
/// (0: none) is below planner::kMinCommandedSpeed: a mission cannot command such a speed
/// (ArduCopter ignores slower DO_CHANGE_SPEED), so it would fly faster than the limit.
void checkCommandableSpeeds(double vehicle_max_speed, double camera_max_speed, const std::string& vehicle_source);

}  // namespace wattswath::apps
