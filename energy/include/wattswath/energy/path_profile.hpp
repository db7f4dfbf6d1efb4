#pragma once
/// @file path_profile.hpp
/// Speed profiles for whole geometric paths: every leg of a geometry::CoveragePath gets
/// accelerate / cruise / brake pieces (lines), constant-speed pieces (arcs) or a turn in place.

#include <vector>

#include "wattswath/energy/profile.hpp"
#include "wattswath/geometry/path.hpp"

namespace wattswath::energy {

/// Speeds for a path: a cruise speed per leg and a speed at every junction between legs.
struct SpeedPlan {
  std::vector<double> cruise;    ///< [m/s] cruise speed of leg i (arcs fly at it; ignored for turns in place)
  std::vector<double> junction;  ///< [m/s] speed at the start of leg i (size legs + 1; last = final speed)
};

/// Builds the pieces of `path` flown with `plan` (Marins Eq. 6 per line leg; arcs at constant speed;
/// turns in place at `yaw_rate` [rad/s] starting and ending at rest). Throws std::invalid_argument
/// naming the leg when the plan is infeasible or its sizes do not match the path.
std::vector<Piece> profileFromPath(const geometry::CoveragePath& path, const SpeedPlan& plan,
                                   const ProfileLimits& limits, double yaw_rate);

}  // namespace wattswath::energy
