#pragma once
// Legs and problems for the tests of a plan's mission, built in code.
#include <cmath>

#include "wattswath/geometry/path.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/planner/coverage.hpp"

namespace wattswath::test {

/// A straight leg from `a` to `b` [m] with `role`.
inline geometry::PathLeg line(geometry::Point a, geometry::Point b, geometry::LegRole role = geometry::LegRole::Sweep) {
  geometry::PathLeg l;
  l.kind = geometry::PrimitiveKind::Line;
  l.role = role;
  l.start = a;
  l.end = b;
  return l;
}

/// A turn in place at `at` [m] with `role`.
inline geometry::PathLeg turnInPlace(geometry::Point at, geometry::LegRole role = geometry::LegRole::Turn) {
  auto t = line(at, at, role);
  t.kind = geometry::PrimitiveKind::TurnInPlace;
  return t;
}

/// The problem `wattswath plan AREA --spacing S` (or --altitude 10 --fov 100 --overlap 0.1 when
/// `spacing` is 0) sets up from a survey area file.
inline planner::SurveyProblem problemOf(const geometry::SurveyArea& area, double spacing) {
  planner::SurveyProblem pr;
  pr.area = area.polygon();
  pr.no_fly = area.no_fly;
  pr.altitude = 10.0;
  pr.footprint = spacing > 0 ? spacing : 2.0 * pr.altitude * std::tan(50.0 * M_PI / 180.0);
  pr.spacing = spacing > 0 ? spacing : 0.9 * pr.footprint;
  pr.home = area.home ? *area.home : pr.area.outer.front();
  return pr;
}

}  // namespace wattswath::test
