#pragma once
/// @file route.hpp
/// Routes (waypoint polylines with a role per segment) and their conversion to paths with shaped
/// corners: a sharp corner (stop and turn in place) or a rounded one (a circular arc).

#include <vector>

#include "wattswath/geometry/path.hpp"

namespace wattswath::geometry {

/// A route before its corners are shaped: segment i goes from points[i] to points[i + 1] with
/// role roles[i] (so roles.size() == points.size() - 1).
struct Route {
  std::vector<Point> points;   ///< [m] waypoints in flight order (ENU)
  std::vector<LegRole> roles;  ///< role of each segment

  /// Appends `other`, joining it with one segment of role `join_role` (no segment when the
  /// routes already meet).
  void append(const Route& other, LegRole join_role);
  /// Route length [m] (sum of the segments).
  double length() const;
};

/// Largest tangent length [m] of a circular arc at a corner turning by `turn` [rad] whose arc stays
/// within `margin` [m] of the vertex (0 for a straight corner or no margin).
double tangentWithin(double turn, double margin);

/// How a corner between two straight segments is flown.
enum class CornerStyle {
  Sharp,   ///< stop at the vertex and turn in place
  Rounded  ///< fly a circular arc tangent to both segments
};

/// Corner shaping settings.
struct CornerSettings {
  CornerStyle style = CornerStyle::Sharp;  ///< sharp or rounded
  double radius = 0.0;  ///< [m] arc radius for rounded corners, >= 0 (v / omega_max for a speed v);
                        ///< reduced where the segments are too short; 0 means sharp
  double max_rounded_angle = 3.0;  ///< [rad] corners turning more than this are flown sharp, in (0, pi)
};

/// Builds the path of `route` with corners shaped by `corners`; every leg gets `altitude` [m].
/// A rounded corner of turn angle t cuts its segments by r tan(|t| / 2), where r is the radius
/// reduced so no segment loses more than half its length (all of it for the first and last).
/// A rounded corner (inside `keep_out`) whose arc would enter a hole of `keep_out` or leave its
/// outer boundary gets half the radius, then a quarter, then is flown sharp. Zero-length segments and collinear waypoints are dropped.
/// Position and heading are continuous. Throws std::invalid_argument when roles and points do
/// not match or a value is not finite.
CoveragePath shapeCorners(const Route& route, const CornerSettings& corners, double altitude = 0.0,
                          const PolygonWithHoles& keep_out = {});

}  // namespace wattswath::geometry
