#pragma once
/// @file sorties.hpp
/// A coverage flight larger than one battery split into sorties: each flies a run of sweeps (cut
/// into pieces of at most SortieSettings::piece_m) of the plan in the plan's order or reversed, whichever transits less (the next sortie resumes
/// where the last one ended, mid-sweep if need be), from home and back
/// to home along the shortest transit around the no-fly zones, within an energy budget. The cuts
/// take the fewest sorties and, among those (or for a given count), minimise the total energy (dynamic programming over the sweep pieces, closed-form energies: the
/// plan's own leg energies, stop-to-stop transits, a fixed take-off and landing overhead); the
/// naive split (each sortie as long as the budget allows, in flight order) is the baseline. The
/// caller checks each sortie's mission with the flight model (apps, `plan --sorties`), or lets
/// splitIntoFlownSorties ask it which runs of pieces fly.

#include <functional>
#include <vector>

#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/speed.hpp"

namespace wattswath::planner {

/// One sortie: its flown path (transit out, sweeps and their connectors, transit home).
struct Sortie {
  FlownPath flown;        ///< legs and speeds as missionFromPlan reads them (energies: closed form)
  int first_sweep = 0;    ///< [-] index of its first piece among the plan's sweep pieces
  int last_sweep = 0;     ///< [-] index of its last piece
  double estimate_j = 0;  ///< [J] closed-form energy with the overhead
  bool reversed = false;  ///< flown from the end of its last sweep to the start of its first (shorter transits)
};

/// How a plan splits.
struct SortieSplit {
  std::vector<Sortie> sorties;  ///< in flight order
  double estimate_j = 0;        ///< [J] total closed-form energy
};

/// What the split needs.
struct SortieSettings {
  double budget_j = 0.0;    ///< [J] largest closed-form energy of one sortie, > 0
  double overhead_j = 0.0;  ///< [J] take-off and landing energy of every sortie, >= 0
  double scale = 1.0;       ///< [-] factor on the closed-form leg and transit energies (the flight model's over
                            ///< the closed form's on the whole plan), (0, 10]
  int count = 0;            ///< [-] exactly this many sorties (0: the fewest that fit, with the least total energy among those)
  double piece_m = 50.0;    ///< [m] straight sweeps longer than twice this are cut into pieces of at most this,
                            ///< so a sortie may end mid-sweep and the next resume there, [5, 1e4]
  bool naive = false;       ///< true: the naive split (each sortie as long as the budget allows)
  /// [-] per piece of sweep (Sortie::first_sweep.. indices), a factor on its energy (empty: all 1);
  /// the caller raises it where a sortie flown by the autopilot model used more than estimated
  std::vector<double> piece_weight;
};

/// Splits `plan` (a flown coverage path from home to home over `problem`) into sorties; `scorer`
/// prices the transits. Throws std::invalid_argument for settings out of range or a plan without
/// sweeps, std::runtime_error naming the sweep when a single sweep with its transits exceeds the
/// budget or no split into `count` sorties fits.
SortieSplit splitIntoSorties(const FlownPath& plan, const SurveyProblem& problem, RouteScorer& scorer,
                             const SortieSettings& settings);

/// True when `sortie`, written as a mission and flown by the autopilot model, lands with the reserve.
using SortieCheck = std::function<bool(const Sortie& sortie)>;

/// As splitIntoSorties, but each sortie is one `flies` accepts: for every first piece, the longest
/// run of pieces that still flies is found by asking `flies` (starting from the longest run within
/// `settings.budget_j`, stepping one piece at a time; a run is taken to fly when a longer one from
/// the same piece does), then the cuts take the fewest such runs and, among those (or for
/// `settings.count`), the least total closed-form energy. `settings.naive` and `piece_weight` are
/// not used. Throws std::runtime_error naming the piece when a piece alone does not fly, or when no
/// split into `count` sorties does.
SortieSplit splitIntoFlownSorties(const FlownPath& plan, const SurveyProblem& problem, RouteScorer& scorer,
                                  const SortieSettings& settings, const SortieCheck& flies);

}  // namespace wattswath::planner
