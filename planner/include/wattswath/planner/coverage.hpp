#pragma once
/// @file coverage.hpp
/// The minimum-energy coverage planner. Two searches compete: (1) one sweep angle for the whole
/// area (coarse then refined), its cells ordered by GTSP; (2) per cell: the area cut into
/// boustrophedon cells (geometry::decomposeBoustrophedon at the best angle of (1)), every cell
/// offering boustrophedon routes at its own best angle (each start corner) and straight-skeleton
/// spirals (each start vertex, both directions), the GTSP picking one candidate per cell and the
/// order. Corner strategy and speeds per leg; transits around no-fly zones; baselines scored by
/// the same model in the same run, and a physical lower bound.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/polygon.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/planner/battery_use.hpp"
#include "wattswath/planner/speed.hpp"

namespace wattswath::planner {

/// What to cover, in the local ENU frame [m].
struct SurveyProblem {
  geometry::PolygonWithHoles area;      ///< survey area; its holes are not flown over
  std::vector<geometry::Ring> no_fly;   ///< further no-fly zones (inside or outside the area)
  geometry::Point home = geometry::Point::Zero();  ///< [m] take-off and landing point
  double spacing = 20.0;                ///< [m] distance between sweep lines, (0, 1000]
  double footprint = 20.0;              ///< [m] camera footprint width across track (>= spacing)
  double altitude = 10.0;               ///< [m] flight height above home, (0, 1000]

  /// Throws std::invalid_argument naming the field and value when out of range or degenerate.
  void validate() const;
};

/// Planner settings.
struct PlannerSettings {
  CornerStrategy corners = CornerStrategy::Auto;  ///< corner strategy of the plan
  double camera_max_speed = 0.0;     ///< [m/s] cap on sweep legs from the camera (0: none), [0, 200]
  double coarse_step_deg = 10.0;     ///< [deg] coarse sweep-angle step, (0, 90]
  double fine_step_deg = 1.0;        ///< [deg] refined step around the best coarse angles, (0, coarse_step_deg]
  int threads = 2;                   ///< worker threads for the angle search, [1, 64]
  double ground_station_speed = 5.0; ///< [m/s] constant speed of the ground-station baseline (ArduPilot WPNAV_SPEED default)
  double clearance = 2.0;            ///< [m] distance kept from holes and no-fly zones, (0, 100]
  int exact_max_cells = 8;           ///< exact cell ordering up to this many cells, heuristic beyond, [0, 12]
  bool spirals = true;               ///< let spirals compete (off: straight parallel lines only, as photogrammetry
                                     ///< often wants for consistent image headings)
  double overshoot = 0.0;            ///< [m] how far sweep lines may run on beyond the outer boundary for the turn
                                     ///< (QGC's turnaround distance), [0, 100]; 0: every flown point stays inside
  bool per_cell = true;              ///< also search per cell: each cell of the decomposition at the best angle
                                     ///< picks its own pattern (boustrophedon at its own angle, or spiral)

  /// Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

/// How one cell of a plan is covered (per-cell choice of the mixed search).
struct CellPlan {
  std::string pattern;           ///< "boustrophedon" or "spiral"
  double sweep_angle_deg = 0.0;  ///< [deg] sweep direction of a boustrophedon cell (0 = east, CCW); spirals: 0
  double energy_j = 0.0;         ///< [J] energy of the cell's route flown alone, from rest to rest
  double area_m2 = 0.0;          ///< [m^2] area of the cell
};

/// Energy of the one-angle boustrophedon plan at one sweep angle (a point of the angle search).
struct AngleScore {
  double sweep_angle_deg = 0.0;  ///< [deg] sweep direction (0 = east, CCW), [0, 180)
  double energy_j = 0.0;         ///< [J] energy of the assembled plan at that angle (infinite: none)
};

/// One scored plan.
struct PlanCandidate {
  FlownPath flown;              ///< the path with speeds and energies
  std::string pattern;          ///< "boustrophedon", "spiral" or "mixed" (cells covered by different patterns)
  double sweep_angle_deg = 0.0; ///< [deg] sweep direction (0 = east, counter-clockwise); spirals: 0; mixed:
                                ///< the angle of the largest boustrophedon cell
  double coverage_pct = 0.0;    ///< [%] of the area (minus holes and no-fly zones) inside the footprint
  int cells = 0;                ///< number of cells covered
  std::vector<CellPlan> cell_plans;  ///< per cell, in flight order (filled by the per-cell search)
  bool valid = false;           ///< false when no candidate could be built
};

/// The plan's sweep angle flown with the other line count: the energy-versus-coverage trade of the
/// line-count choice (issue 22).
struct LineCountNeighbour {
  PlanCandidate candidate;  ///< the same angle with one line more or one fewer, flown and checked
  int lines_delta = 0;      ///< +1: one line more than the plan (the plan dropped one), -1: one fewer
};

/// Result of planning: the plan, the baselines and the lower bound.
struct PlanResult {
  PlanCandidate plan;                     ///< the minimum-energy plan
  PlanCandidate shortest_path;            ///< baseline: the shortest path (length objective), our speeds
  PlanCandidate ground_station_default;   ///< baseline: sweep parallel to the longest edge, constant speed, stops
  std::optional<PlanCandidate> best_spiral;  ///< baseline: the best spiral (absent when no spiral fits)
  std::optional<PlanCandidate> per_cell;     ///< the per-cell search's plan, kept or not (absent when not run)
  double lower_bound_j = 0.0;             ///< [J] physical lower bound on the coverage energy
  int candidates = 0;                     ///< candidate routes scored (whole plans and per-cell routes)
  std::vector<AngleScore> sweep_scan;     ///< one-angle boustrophedon energy at every searched angle, by angle
  std::optional<LineCountNeighbour> line_count_neighbour;  ///< the one-angle plan's angle with the other line count
  std::vector<std::string> notes;         ///< facts for the user (e.g. why no spiral)
  std::optional<BatteryUse> battery;      ///< predicted battery use of the plan (when the vehicle has a battery)
};

/// Progress callback: a line of text (the app prints it on stderr).
using ProgressFn = std::function<void(const std::string&)>;

/// Plans the minimum-energy coverage of `problem` with `vehicle` scored by `model`.
PlanResult planCoverage(const SurveyProblem& problem, const energy::Vehicle& vehicle, const energy::EnergyModel& model,
                        const PlannerSettings& settings = {}, const ProgressFn& progress = {});

/// Percentage of the area (minus holes and no-fly zones) within the footprint of the sweep and
/// turn legs of `path` (square footprint `footprint` wide, centred on the leg) [%]: exact, by
/// geometry::checkCoverage (CGAL Boolean union of the swaths).
double coveragePercent(const SurveyProblem& problem, const geometry::CoveragePath& path);

/// Problems with `path` against `problem`: gaps between legs, legs entering a hole or no-fly zone.
/// Empty means valid.
std::vector<std::string> checkPlan(const SurveyProblem& problem, const geometry::CoveragePath& path);

/// Length of `path` outside the problem's area and inside its holes or no-fly zones
/// (geometry::checkContainment with the zones as holes; the approach from home and the return
/// are left out, home may lie outside).
geometry::ContainmentReport planContainment(const SurveyProblem& problem, const geometry::CoveragePath& path);

}  // namespace wattswath::planner
