#pragma once
/// @file margin.hpp
/// Keeping clear of no-fly zones and inside a fence: the problem the planner flies when every
/// flown point must keep a margin from the no-fly zones (GPS and tracking error), and the inclusion
/// geofence around the area and the flown path.

#include <string>
#include <vector>

#include "wattswath/geometry/path.hpp"
#include "wattswath/geometry/polygon.hpp"
#include "wattswath/planner/coverage.hpp"

namespace wattswath::planner {

/// [m] Default distance every flown point keeps from the no-fly zones: a few metres for GPS error
/// (a consumer receiver's horizontal error is about 1-2 m, more near buildings) plus the tracking
/// error of the position controller between waypoints and in wind.
inline constexpr double kDefaultNoFlyMargin = 2.0;

/// [m] Added to the margin when the zones are inflated, so that the planner's own hole checks (arcs
/// split into chords of tol::kArcChord) cannot cost the path any of the margin.
inline constexpr double kMarginPad = 0.05;

/// The no-fly zones of `problem` as the flight must avoid them [m]: its holes, then its extra zones.
std::vector<geometry::Ring> noFlyZones(const SurveyProblem& problem);

/// `problem` with every no-fly zone (holes and extra zones) grown by `margin_m` + kMarginPad [m]
/// (geometry::inflateRings) and the area cut by them: a grown zone inside the area is a hole, one
/// that reaches the boundary notches it, zones that overlap merge; all grown zones are its no_fly.
/// Where the margin cuts the area into parts, the largest is kept and `notes` (when given) says how
/// much was left out. `margin_m` 0 returns `problem` unchanged. Throws std::invalid_argument when
/// `margin_m` is negative or not finite, when home lies within the margin of a zone (naming the
/// zone and the distance) or when the margin leaves nothing to cover.
SurveyProblem withNoFlyMargin(const SurveyProblem& problem, double margin_m, std::vector<std::string>* notes = nullptr);

/// An inclusion geofence: the area's outer boundary grown far enough that every flown point keeps
/// a margin inside it.
struct InclusionFence {
  geometry::Ring ring;      ///< [m] counter-clockwise
  double distance_m = 0.0;  ///< [m] how far it lies outside the area's outer boundary
};

/// The fence around `problem`'s outer boundary [m] that keeps every point of `path` and home at
/// least `margin_m` [m] (> 0) inside it: the boundary grown by the margin plus the farthest any
/// flown point goes outside the boundary (sweep run-outs, arcs, transits; geometry::fenceViolations
/// verifies it). Throws std::invalid_argument for a margin that is not positive and finite.
InclusionFence inclusionFence(const SurveyProblem& problem, const geometry::CoveragePath& path, double margin_m);

}  // namespace wattswath::planner
