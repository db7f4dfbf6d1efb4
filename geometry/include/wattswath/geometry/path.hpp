#pragma once
/// @file path.hpp
/// Coverage paths as geometry only: a sequence of legs, each one primitive (line, arc, turn in
/// place) with a role. No speeds here: the planner gives each leg its speed profile.

#include <string>
#include <vector>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::geometry {

/// Shape of one leg.
enum class PrimitiveKind { Line, Arc, TurnInPlace };

/// What a leg is for.
enum class LegRole { Sweep, Turn, Transit, Climb };

/// One leg of a path. Position and heading are continuous between consecutive legs.
struct PathLeg {
  PrimitiveKind kind = PrimitiveKind::Line;  ///< line, arc or turn in place
  LegRole role = LegRole::Sweep;             ///< sweep, turn, transit or climb
  Point start = Point::Zero();               ///< [m] start position (ENU)
  Point end = Point::Zero();                 ///< [m] end position (equals start for a turn in place)
  double heading_start = 0.0;                ///< [rad] ENU heading at the start (0 = east, CCW)
  double heading_end = 0.0;                  ///< [rad] ENU heading at the end
  Point center = Point::Zero();              ///< [m] arc centre (arcs only)
  double radius = 0.0;                       ///< [m] arc radius (arcs only)
  double turn_angle = 0.0;                   ///< [rad] signed heading change (arcs, turns in place; CCW > 0)
  double altitude = 0.0;                     ///< [m] height above home (constant over a coverage leg)

  /// Length flown along the leg [m] (0 for a turn in place).
  double length() const;
};

/// A coverage path over one cell or a whole area.
struct CoveragePath {
  std::vector<PathLeg> legs;   ///< legs in flight order
  std::string pattern;         ///< "boustrophedon", "spiral", "transit", ...
  double sweep_angle = 0.0;    ///< [rad] sweep direction for boustrophedon (0 = lines along east)
  int cell = -1;               ///< cell index in the decomposition (-1: whole area)

  /// Total length [m].
  double length() const;
  /// Number of legs that are turns (arcs with role Turn, or turns in place).
  int turnCount() const;
};

}  // namespace wattswath::geometry
