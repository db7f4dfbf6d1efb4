#pragma once
/// @file fleet.hpp
/// A fleet flying the sorties of one split at once (`plan --vehicles N`): the sorties, in their
/// flight order, dealt to the vehicles in contiguous runs (each vehicle covers its own part of
/// the area) so the latest landing, the makespan, is least; each vehicle flies its run one
/// sortie after the other with a battery swap on the ground between them, the vehicles taking off
/// in turn. No two airborne vehicles may come closer than a horizontal separation: it is checked
/// on the flown trajectories (each sortie's samples at its scheduled time) and a sortie that
/// would come closer starts later (its vehicle's later sorties with it) until none does.

#include <vector>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::planner {

/// One sample of a flown sortie.
struct TrackSample {
  double t = 0.0;                                  ///< [s] since the sortie's take-off command
  geometry::Point p = geometry::Point::Zero();     ///< [m] horizontal position, local ENU
  bool airborne = true;                            ///< false while on the ground (spool-up, landed)
};

/// A flown sortie: samples in time order, the last at its landing.
using Track = std::vector<TrackSample>;

/// How the fleet flies.
struct FleetSettings {
  int vehicles = 2;                 ///< [-] vehicles flying at once, 1..100
  double swap_time_s = 120.0;       ///< [s] on the ground between two sorties of one vehicle (battery swap), >= 0
  double launch_interval_s = 30.0;  ///< [s] between the vehicles' first take-off commands, >= 0
  double separation_m = 15.0;       ///< [m] least horizontal distance between two airborne vehicles, >= 0
  double check_dt_s = 0.2;          ///< [s] time step of the separation check (closest approach within each step), 0.01..5
  double delay_step_s = 5.0;        ///< [s] a conflicting sortie's start moves by this much at a time, 0.1..600
  int max_delays = 5000;            ///< [-] give up after this many delays
};

/// When one sortie flies.
struct ScheduledSortie {
  int vehicle = 0;       ///< [-] 0-based vehicle flying it
  int order = 0;         ///< [-] 0-based place among that vehicle's sorties
  double start_s = 0.0;  ///< [s] take-off command, since the fleet's first
  double end_s = 0.0;    ///< [s] landing
  double delay_s = 0.0;  ///< [s] added to its start (and its vehicle's later ones) for the separation
};

/// The fleet's schedule.
struct FleetSchedule {
  std::vector<ScheduledSortie> sorties;  ///< one per sortie, in the split's order
  double makespan_s = 0.0;               ///< [s] the fleet's first take-off command to its last landing
  double min_separation_m = 0.0;         ///< [m] least horizontal distance between airborne vehicles (inf: never two at once)
  int delays = 0;                        ///< [-] delays applied to keep the separation
};

/// The sorties' durations dealt to `vehicles` in contiguous runs of the split's order that
/// minimise the makespan (vehicle k's first take-off at k x launch interval, swaps between its
/// sorties); returns the first sortie index of each vehicle's run (at most min(vehicles, sorties):
/// fewer when another vehicle would not shorten the makespan).
/// Throws std::invalid_argument for no sorties or settings out of range.
std::vector<int> fleetRuns(const std::vector<double>& durations_s, const FleetSettings& s);

/// Least horizontal distance [m] between any two airborne vehicles when sortie i is flown from
/// `start_s[i]` by `vehicle[i]`, and, in `conflict_at` (when given), the first time [s] it falls
/// below `separation_m` with the later-started of the two sorties in `conflict_sortie` (-1: none;
/// the scan stops there and returns that step's distance). Positions are linear between samples;
/// within each `check_dt_s` step the exact closest approach of the two is taken.
double minSeparation(const std::vector<Track>& tracks, const std::vector<int>& vehicle, const std::vector<double>& start_s,
                     double check_dt_s, double separation_m, int* conflict_sortie = nullptr);

/// The fleet's schedule for `tracks` (the split's sorties as flown, in order): runs by fleetRuns,
/// then delays until the separation holds. Throws std::invalid_argument for settings out of range or
/// an empty track, std::runtime_error when max_delays do not separate the vehicles.
FleetSchedule scheduleFleet(const std::vector<Track>& tracks, const FleetSettings& s);

}  // namespace wattswath::planner
