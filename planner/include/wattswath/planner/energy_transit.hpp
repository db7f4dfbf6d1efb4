#pragma once
/// @file energy_transit.hpp
/// Transits planned by OMPL (RRT*, asymptotically optimal) with an energy objective: the cost of a
/// straight motion is the energy of flying it from a stop to a stop at the best speeds (the same
/// leg energy the planner charges transits), the cost-to-go heuristic is the model's lowest energy
/// per metre times the straight-line distance (admissible: no leg costs less per metre). For
/// polygonal no-fly zones the visibility graph (TransitRouter) is exact in length; this router is
/// the general one and the cross-check (tests compare both).

#include <vector>

#include "wattswath/energy/model.hpp"
#include "wattswath/geometry/polygon.hpp"
#include "wattswath/planner/speed.hpp"

namespace wattswath::planner {

/// Settings of the OMPL energy transit.
struct EnergyTransitSettings {
  int iterations = 3000;      ///< RRT* iterations (deterministic for a seed), [1, 1e7]
  double time_limit_s = 5.0;  ///< [s] safety cap on the planning time, (0, 60]
  double margin_m = 50.0;     ///< [m] the sampled box extends this far beyond the end points and obstacles, (0, 1e4]
  double range_m = 0.0;       ///< [m] RRT* steering range (0: OMPL's default from the box size), >= 0
  unsigned seed = 1;          ///< OMPL random seed (set once per process, before the first plan)

  /// Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

/// An OMPL transit.
struct EnergyTransit {
  bool solved = false;                  ///< an exact solution was found in the time limit
  std::vector<geometry::Point> path;    ///< [m] polyline from start to goal (simplified), empty when not solved
  double energy_j = 0.0;                ///< [J] sum of stop-to-stop leg energies of the path's segments
  double heuristic_j = 0.0;             ///< [J] admissible bound: lowest energy per metre x straight distance
};

/// Plans a transit from `a` to `b` [m] around `obstacles` (rings, any orientation) minimising
/// energy (see the file comment); segments never enter an obstacle (checked by segmentEntersRing).
/// Throws std::invalid_argument when `a` or `b` lies inside an obstacle or settings are out of range.
EnergyTransit planEnergyTransit(const geometry::Point& a, const geometry::Point& b,
                                const std::vector<geometry::Ring>& obstacles, RouteScorer& scorer,
                                const EnergyTransitSettings& settings = {});

}  // namespace wattswath::planner
