// When a track passes a waypoint: the middle of its dwell near the waypoint, interpolated between
// samples, so a 1 Hz log and a 10 Hz prediction are timed alike (mission_calibration.cpp).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace wattswath::calibration::detail {

/// [m] How much farther than its closest approach the track may be from a waypoint and still be
/// counted as dwelling at it (WPNAV_RADIUS's 2 m default: a stopped vehicle wanders well inside it).
constexpr double kDwellMargin = 2.0;

/// One passage of a track by a waypoint.
struct Passage {
  long index = -1;           ///< the sample closest to the waypoint (-1: not matched)
  double t = 0.0;            ///< [s] the middle of the dwell: between entering and leaving the sphere of
                             ///< the closest approach + kDwellMargin around the waypoint (linear between samples)
  double closest_m = 0.0;    ///< [m] the horizontal distance of the closest sample
};

/// The passage of the track (`t` [s], `pos` [m]) by waypoint `w` [m] at or after sample `from`:
/// its closest sample in three dimensions on the first pass whose horizontal distance is within
/// `match_m` [m] (the search stops 10 m beyond it), then the dwell around it. Unmatched (index -1) when the track never comes within `match_m`.
Passage waypointPassage(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos, const Eigen::Vector3d& w,
                        std::size_t from, double match_m);

/// `y` (cumulative, one value a sample of `t`) linearly interpolated at time `at` [s], clamped to the ends.
double interpolateAt(const std::vector<double>& t, const std::vector<double>& y, double at);

}  // namespace wattswath::calibration::detail
