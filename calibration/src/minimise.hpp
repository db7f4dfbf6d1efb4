#pragma once
// Derivative-free minimisation for the calibration's simulated-flight misfits, by well-kept
// libraries: NLopt's Nelder-Mead on the unit box, and a grid refined by Boost.Math's Brent
// minimisation. The misfits are not smooth (a waypoint's passage moves in steps of the
// prediction's time step), so neither uses a gradient.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include <boost/math/tools/minima.hpp>
#include <nlopt.hpp>

namespace wattswath::calibration::detail {

/// The point of [0, 1]^n that minimises `cost` (a callable taking const std::vector<double>&),
/// by NLopt's Nelder-Mead from `x0` (clamped into the box) with an initial simplex of 0.15 on each
/// axis, stopping after `max_evals` evaluations or when the simplex's values agree within 1e-9.
template <class F>
std::vector<double> nelderMead(F cost, std::vector<double> x0, int max_evals) {
  for (double& v : x0) v = std::clamp(v, 0.0, 1.0);
  if (x0.empty()) return x0;
  nlopt::opt opt(nlopt::LN_NELDERMEAD, static_cast<unsigned>(x0.size()));
  opt.set_lower_bounds(0.0);
  opt.set_upper_bounds(1.0);
  opt.set_initial_step(0.15);  // NLopt steps inwards from a bound
  opt.set_maxeval(std::max(max_evals, 1));
  opt.set_ftol_abs(1e-9);
  auto objective = [](const std::vector<double>& x, std::vector<double>& /*grad*/, void* data) {
    return (*static_cast<F*>(data))(x);
  };
  opt.set_min_objective(objective, &cost);
  double best = std::numeric_limits<double>::infinity();
  try {
    opt.optimize(x0, best);
  } catch (const nlopt::roundoff_limited&) {
    // x0 holds the best point found: a misfit flat to rounding stops the search there
  }
  return x0;
}

/// The minimum of `cost` (a callable taking double) on [0, 1]: the best of a grid of `grid` + 1
/// points, refined by Brent's minimisation (Boost.Math, at most `iters` steps) between its
/// neighbours; the grid point is kept when the refinement finds nothing lower (a time misfit is not
/// unimodal: waypoint passages move in steps).
template <class F>
double gridThenBrent(F cost, int grid, int iters) {
  int best = 0;
  double fbest = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= grid; ++i) {
    const double f = cost(static_cast<double>(i) / grid);
    if (f < fbest) fbest = f, best = i;
  }
  const double a = std::max(0, best - 1) / static_cast<double>(grid), b = std::min(grid, best + 1) / static_cast<double>(grid);
  std::uintmax_t steps = static_cast<std::uintmax_t>(std::max(iters, 1));
  const auto [u, fu] = boost::math::tools::brent_find_minima(cost, a, b, 24, steps);
  return fu <= fbest ? u : static_cast<double>(best) / grid;
}

}  // namespace wattswath::calibration::detail
