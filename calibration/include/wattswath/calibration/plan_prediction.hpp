#pragma once
/// @file plan_prediction.hpp
/// Predict a measured flight's energy from its plan instead of its logged kinematics, and split
/// the model's error into kinematics (how the vehicle really flew) and power physics (issue 6).
///
/// The plan's waypoints are the corners of the logged track (Douglas-Peucker simplification within
/// `simplify_tolerance`), each snapped to the nearest plan vertex within `snap_distance`. This
/// choice is forced by the data: a QGC survey file holds the polygon, not the coverage route flown
/// inside it, so only corners the route shares with the polygon can be taken from the plan; the
/// others are where the vehicle turned. (Leg ends at stops / slow-downs were tried first: they
/// miss corners flown without a clear slow-down and the chords then cut the route short.) The
/// planned pieces are then flown ideally: straight legs at the log's peak speed per leg, stopping
/// (with a turn in place at the maximum yaw rate) or slowing at every waypoint, with the vehicle's
/// acceleration (Marins et al. 2018, Eq. 6 profiles, Eq. 13 turns).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/profile.hpp"
#include "wattswath/calibration/replay.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::calibration {

/// How a flight's plan is built from its log and the plan's vertices.
struct PlanPredictionSettings {
  double corner_speed_fraction = 0.0;  ///< [-] 0: stop at every waypoint and turn in place; (0, 1]:
                                       ///< pass waypoints at this share of the slower neighbouring
                                       ///< leg speed, no turn in place; 0..1
  double snap_distance = 3.0;          ///< [m] a waypoint moves (horizontally) to a plan vertex this close; 0..50
  double simplify_tolerance = 2.0;     ///< [m] largest distance of the logged track from the planned legs; 0.1..20
  double merge_distance = 1.0;         ///< [m] consecutive waypoints closer than this are one; 0.01..10
  double min_leg_speed = 0.5;          ///< [m/s] floor of a leg's commanded speed; 0.1..5
};

/// Throws std::invalid_argument naming the field, its value and the range when out of range.
void validate(const PlanPredictionSettings& s);

/// A flight predicted from its plan.
struct PlanPrediction {
  std::vector<Eigen::Vector3d> waypoints;  ///< [m] planned waypoints, ENU, in flight order
  std::vector<double> leg_speed;           ///< [m/s] commanded speed of each leg (waypoints.size() - 1)
  int snapped = 0;                         ///< waypoints moved onto a plan vertex
  std::vector<Piece> pieces;               ///< the planned flight (climb, legs, turns, descent)
  double energy_j = 0.0;                   ///< [J] model energy of the pieces
  double time_s = 0.0;                     ///< [s] planned flight time
  double distance_m = 0.0;                 ///< [m] planned path length (3-D)
};

/// Builds the planned flight of `log` (track corners snapped to `plan_vertices`, ENU [m] in the
/// log's frame, any order) and evaluates `m` on it. Throws std::invalid_argument when the log has
/// fewer than two distinct waypoints (never moves) or the settings are out of range.
PlanPrediction predictFromPlan(const EnergyModel& m, const Vehicle& v, const PreparedLog& log,
                               const std::vector<Eigen::Vector3d>& plan_vertices,
                               const PlanPredictionSettings& s = {});

/// Measured energy versus the model on logged kinematics (replay) and on planned kinematics.
struct PlanComparison {
  double measured_j = 0.0;       ///< [J] measured energy of the flight
  double replay_j = 0.0;         ///< [J] (a) model on the logged kinematics
  double plan_j = 0.0;           ///< [J] (b) model on the planned kinematics
  double measured_time_s = 0.0;  ///< [s] logged flight time
  double plan_time_s = 0.0;      ///< [s] planned flight time
  /// Kinematics error (b) - (a) [J]: what flying the plan ideally changes.
  double kinematicsErrorJ() const { return plan_j - replay_j; }
  /// Physics error (a) - measured [J]: the power model's own error on the true kinematics.
  double physicsErrorJ() const { return replay_j - measured_j; }
};

/// The comparison of one flight's replay and plan prediction.
PlanComparison comparePlan(const LogReplay& replay, const PlanPrediction& plan);

}  // namespace wattswath::calibration
