#pragma once
/// @file optimal_speed.hpp
/// The cruise speed that minimises the energy of a straight leg, for any EnergyModel (Marins et al.
/// Sec. III-D generalised: any effect set, any entry and exit speeds, triangular legs). For the
/// paper's own closed form (Eq. 10 cubic) see MarinsClosedForm::eq10OptimalSpeed in marins.hpp.
/// Fig. 3's variants are models with an effect removed: `model.remove("kinetic")`.

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/tools/minima.hpp>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/profile.hpp"

namespace wattswath::energy {

/// Energy of a leg and its derivative with respect to the cruise speed.
struct LegEnergySlope {
  double energy = 0.0;      ///< [J] energy of the leg
  double derivative = 0.0;  ///< [J s/m] dE / d v_cruise (one-sided at profile kinks)
  bool analytic = true;     ///< true when every effect gave closed-form gradients (no differencing)
};

/// Energy of the leg buildLegProfile(distance, v_entry, v_cruise, v_exit, limits) and dE/dv_cruise by
/// the chain rule through the pieces (Effect::energyGradient x profile sensitivity); effects without a
/// closed-form gradient are differenced centrally. Throws like buildLegProfile.
LegEnergySlope legEnergySlope(const EnergyModel& model, double distance, double v_entry, double v_cruise,
                              double v_exit, const ProfileLimits& limits);

/// Settings of the cruise-speed search, with their allowed ranges.
struct CruiseSpeedSettings {
  int grid_points = 24;           ///< [-] coarse samples of the speed range before refining, in [4, 10000]
  double min_speed = 0.1;         ///< [m/s] lowest cruise speed considered, in (0, v_max)
  double speed_tolerance = 1e-7;  ///< [m/s] width at which the refinement stops, in [1e-12, 1]
  int max_iterations = 200;       ///< [-] refinement iterations, in [10, 10000]

  /// Throws std::invalid_argument naming the field, its value and the range when out of range.
  void validate() const;
};

/// The result of a cruise-speed search.
struct CruiseSpeedOptimum {
  double speed = 0.0;        ///< [m/s] optimal cruise speed (commanded)
  double energy = 0.0;       ///< [J] energy of the leg at that speed
  double time = 0.0;         ///< [s] duration of the leg at that speed
  double derivative = 0.0;   ///< [J s/m] dE/dv at the optimum (about 0 inside; <= 0 at the upper bound)
  double upper_bound = 0.0;  ///< [m/s] min(v_max, peak speed the leg can reach): the searched range's top
  bool at_upper_bound = false;  ///< the optimum is the upper bound (speed limit or triangular peak)
  bool triangular = false;      ///< the profile at the optimum never cruises (too short to reach it)
  bool analytic_derivative = true;  ///< every effect gave closed-form gradients
  int evaluations = 0;          ///< [-] leg energy evaluations used
};

/// Minimises the energy of a straight leg of `distance` [m] from `v_entry` to `v_exit` [m/s] over the
/// cruise speed in [min_speed, min(v_max, peak)], where peak is the highest speed the leg can reach
/// (above it the profile no longer changes). Coarse grid, then a bracketed root of the analytic
/// dE/dv (TOMS 748) or Brent's minimisation when an effect has no gradient or dE/dv has no sign
/// change. Throws std::invalid_argument naming the value when distance <= 0, speeds are negative or
/// not finite, v_max <= 0, or the leg cannot change from v_entry to v_exit in `distance`.
CruiseSpeedOptimum optimalCruiseSpeed(const EnergyModel& model, double distance, double v_entry, double v_exit,
                                      const ProfileLimits& limits, double v_max,
                                      const CruiseSpeedSettings& settings = {});

namespace detail {
/// Throws std::invalid_argument naming [lo, hi] (minimiseOnInterval's check, out of line).
[[noreturn]] void throwBadInterval(double lo, double hi);
}  // namespace detail

/// Minimises a scalar function `f` (any callable double -> double) over [lo, hi]: grid of
/// `settings.grid_points`, then Brent's method around the best sample. Non-finite values count as
/// +infinity. Inlined and without allocation (the planner runs it once per distinct leg). Returns
/// the argument of the minimum; throws std::invalid_argument for bad settings or a bad interval.
template <class F>
double minimiseOnInterval(const F& f, double lo, double hi, const CruiseSpeedSettings& settings = {}) {
  settings.validate();
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) detail::throwBadInterval(lo, hi);
  if (hi - lo <= settings.speed_tolerance) return 0.5 * (lo + hi);
  const int n = settings.grid_points;
  const auto at = [&](int i) { return i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1); };
  int best = 0;
  double f_best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double v = f(at(i));
    if (std::isfinite(v) && v < f_best) {
      f_best = v;
      best = i;
    }
  }
  const auto safe = [&](double x) {
    const double v = f(x);
    return std::isfinite(v) ? v : std::numeric_limits<double>::max();
  };
  boost::uintmax_t iterations = static_cast<boost::uintmax_t>(settings.max_iterations);
  const double x = boost::math::tools::brent_find_minima(safe, at(std::max(best - 1, 0)), at(std::min(best + 1, n - 1)),
                                                         std::numeric_limits<double>::digits / 2, iterations)
                       .first;
  const double fx = f(x);
  return std::isfinite(fx) && fx <= f_best ? x : at(best);
}

}  // namespace wattswath::energy
