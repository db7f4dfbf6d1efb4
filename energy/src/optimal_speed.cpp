#include "wattswath/energy/optimal_speed.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "wattswath/energy/format.hpp"
#include <vector>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include "wattswath/energy/tolerances.hpp"

namespace wattswath::energy {
namespace {

using detail::formatNumber;

/// Samples f on a uniform grid over [lo, hi] and returns the samples and the index of the smallest.
struct Grid {
  std::vector<double> x, f;
  size_t best = 0;
};

Grid sampleGrid(const std::function<double(double)>& f, double lo, double hi, int n) {
  Grid g;
  g.x.resize(n);
  g.f.resize(n);
  for (int i = 0; i < n; ++i) {
    g.x[i] = i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1);
    const double v = f(g.x[i]);
    g.f[i] = std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
    if (g.f[i] < g.f[g.best]) g.best = i;
  }
  return g;
}

double brent(const std::function<double(double)>& f, double a, double b, int max_iter) {
  boost::uintmax_t it = static_cast<boost::uintmax_t>(max_iter);
  auto safe = [&](double x) {
    const double v = f(x);
    return std::isfinite(v) ? v : std::numeric_limits<double>::max();
  };
  return boost::math::tools::brent_find_minima(safe, a, b, std::numeric_limits<double>::digits / 2, it).first;
}

double legEnergy(const EnergyModel& model, double d, double ve, double vc, double vx, const ProfileLimits& lim) {
  return model.energy(buildLegProfile(d, ve, vc, vx, lim));
}

}  // namespace

void CruiseSpeedSettings::validate() const {
  auto fail = [](const std::string& field, double v, const std::string& range) {
    throw std::invalid_argument("cruise-speed settings: '" + field + "' = " + formatNumber(v) + ", expected " + range);
  };
  if (grid_points < 4 || grid_points > 10000) fail("grid_points", grid_points, "an integer in [4, 10000]");
  if (!(min_speed > 0.0) || !std::isfinite(min_speed)) fail("min_speed", min_speed, "a speed > 0 m/s");
  if (!(speed_tolerance >= 1e-12 && speed_tolerance <= 1.0)) fail("speed_tolerance", speed_tolerance, "[1e-12, 1] m/s");
  if (max_iterations < 10 || max_iterations > 10000) fail("max_iterations", max_iterations, "an integer in [10, 10000]");
}

LegEnergySlope legEnergySlope(const EnergyModel& model, double d, double ve, double vc, double vx,
                              const ProfileLimits& lim) {
  std::vector<PieceSensitivity> sens;
  const std::vector<Piece> pieces = buildLegProfileWithSensitivity(d, ve, vc, vx, lim, sens);
  LegEnergySlope out;
  for (const auto& e : model.effects()) {
    double slope = 0.0;
    bool closed = true;
    for (size_t i = 0; i < pieces.size(); ++i) {
      out.energy += e->energy(pieces[i]);
      const auto g = e->energyGradient(pieces[i]);
      if (!g) {
        closed = false;
        continue;
      }
      const PieceSensitivity& s = sens[i];
      slope += g->length * s.length + g->v_start * s.v_start + g->v_end * s.v_end + g->v_cruise * s.v_cruise +
               g->climb * s.climb;
    }
    if (!closed) {  // central difference of this effect alone (forward when vc - h is not flyable)
      out.analytic = false;
      const double h = 1e-6 * std::max(1.0, vc);
      auto effectEnergy = [&](double v) {
        double s = 0.0;
        for (const auto& p : buildLegProfile(d, ve, v, vx, lim)) s += e->energy(p);
        return s;
      };
      try {
        slope = (effectEnergy(vc + h) - effectEnergy(vc - h)) / (2.0 * h);
      } catch (const std::invalid_argument&) {
        slope = (effectEnergy(vc + h) - effectEnergy(vc)) / h;
      }
    }
    out.derivative += slope;
  }
  return out;
}

namespace detail {
void throwBadInterval(double lo, double hi) {
  throw std::invalid_argument("minimiseOnInterval: expected a finite interval lo <= hi, got [" + formatNumber(lo) + ", " +
                              formatNumber(hi) + "]");
}
}  // namespace detail

CruiseSpeedOptimum optimalCruiseSpeed(const EnergyModel& model, double d, double ve, double vx,
                                      const ProfileLimits& lim, double v_max, const CruiseSpeedSettings& settings) {
  settings.validate();
  if (!(d > 0.0) || !std::isfinite(d)) {
    throw std::invalid_argument("optimal cruise speed: distance = " + formatNumber(d) + " m, expected a finite value > 0");
  }
  if (!(ve >= 0.0) || !std::isfinite(ve) || !(vx >= 0.0) || !std::isfinite(vx)) {
    throw std::invalid_argument("optimal cruise speed: entry speed = " + formatNumber(ve) + " m/s, exit speed = " + formatNumber(vx) +
                                " m/s, expected finite values >= 0");
  }
  if (!(v_max > 0.0) || !std::isfinite(v_max)) {
    throw std::invalid_argument("optimal cruise speed: v_max = " + formatNumber(v_max) + " m/s, expected a finite value > 0");
  }
  // Throws a clear message when the leg cannot change from entry to exit speed at all.
  (void)buildLegProfile(d, ve, std::max({ve, vx, tol::kSpeed * 10.0}), vx, lim);

  CruiseSpeedOptimum r;
  r.upper_bound = std::min(v_max, legPeakSpeed(d, ve, vx, lim));
  const double hi = r.upper_bound;
  const double lo = std::min(settings.min_speed, 0.5 * hi);
  // A cruise speed the leg cannot hold (below both end speeds with no room to dip, or at the edge of
  // feasibility where rounding leaves none) is infinitely dear, not an error: the leg itself is
  // feasible (checked above), so the grid finds a speed that fits.
  auto E = [&](double v) {
    ++r.evaluations;
    try {
      return legEnergy(model, d, ve, v, vx, lim);
    } catch (const std::invalid_argument&) {
      return std::numeric_limits<double>::infinity();
    }
  };
  auto slope = [&](double v) {
    ++r.evaluations;
    try {
      return legEnergySlope(model, d, ve, v, vx, lim);
    } catch (const std::invalid_argument&) {
      return LegEnergySlope{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(), false};
    }
  };
  const Grid g = sampleGrid(E, lo, hi, settings.grid_points);
  const size_t n = g.x.size();
  double v = g.x[g.best];
  LegEnergySlope s = slope(v);
  r.analytic_derivative = s.analytic;
  if (g.best == n - 1 && s.derivative <= 0.0) {
    v = hi;  // still descending at the top of the range
  } else {
    const double a = g.x[g.best == 0 ? 0 : g.best - 1], b = g.x[std::min(g.best + 1, n - 1)];
    double refined = std::numeric_limits<double>::quiet_NaN();
    if (s.analytic) {
      const double ga = slope(a).derivative, gb = slope(b).derivative;
      if (ga < 0.0 && gb > 0.0) {
        boost::uintmax_t it = static_cast<boost::uintmax_t>(settings.max_iterations);
        const double tol = settings.speed_tolerance;
        const auto root = boost::math::tools::toms748_solve(
            [&](double x) { return slope(x).derivative; }, a, b, ga, gb,
            [tol](double x0, double x1) { return std::abs(x1 - x0) <= tol; }, it);
        refined = 0.5 * (root.first + root.second);
      }
    }
    if (!std::isfinite(refined)) refined = brent(E, a, b, settings.max_iterations);
    if (E(refined) <= g.f[g.best]) v = refined;
  }
  if (!std::isfinite(E(v))) v = std::max(ve, vx);  // no grid speed fits: fly the change itself
  s = slope(v);
  const auto pieces = buildLegProfile(d, ve, v, vx, lim);
  r.speed = v;
  r.energy = s.energy;
  r.derivative = s.derivative;
  r.time = totalTime(pieces);
  r.at_upper_bound = v >= hi - settings.speed_tolerance;
  r.triangular = std::none_of(pieces.begin(), pieces.end(), [](const Piece& p) { return p.phase == Phase::Cruise; });
  return r;
}

}  // namespace wattswath::energy
