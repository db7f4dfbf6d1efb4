#include "wattswath/planner/speed.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "wattswath/energy/optimal_speed.hpp"
#include "wattswath/energy/profile.hpp"
#include "wattswath/energy/tolerances.hpp"

namespace wattswath::planner {
namespace {

using geometry::LegRole;
using geometry::Point;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kStraight = 1e-6;     // [rad] deflections below this are straight on
constexpr double kMinCruise = 0.05;    // [m/s] slowest cruise speed the optimiser considers
constexpr double kQuantum = 1e-4;      // [m], [m/s] resolution of the leg-energy cache key
constexpr int kOptions = 6;            // per corner: a stop; the widest arc at 3 speeds, one half as wide at 2

double wrapAngle(double a) {
  while (a > M_PI) a -= 2.0 * M_PI;
  while (a < -M_PI) a += 2.0 * M_PI;
  return a;
}

double heading(const Point& a, const Point& b) { return std::atan2(b.y() - a.y(), b.x() - a.x()); }

// One corner option at a vertex.
struct Option {
  bool rounded = false;
  double v = 0.0;       // [m/s] speed at the corner
  double t = 0.0;       // [m] tangent length cut from each adjacent segment
  double r = 0.0;       // [m] arc radius
  double energy = 0.0;  // [J] energy of the corner itself
};

}  // namespace

CornerStrategy cornerStrategyFromString(const std::string& s) {
  if (s == "sharp") return CornerStrategy::Sharp;
  if (s == "rounded") return CornerStrategy::Rounded;
  if (s == "auto") return CornerStrategy::Auto;
  throw std::invalid_argument("corner strategy '" + s + "' unknown (expected sharp, rounded or auto)");
}

const char* toString(CornerStrategy s) {
  switch (s) {
    case CornerStrategy::Sharp: return "sharp";
    case CornerStrategy::Rounded: return "rounded";
    case CornerStrategy::Auto: return "auto";
  }
  return "auto";
}

void Route::add(const Point& p, LegRole role, double tangent_at_p) {
  if (!points.empty() && (p - points.back()).norm() < energy::tol::kLength) {
    max_tangent.back() = std::min(max_tangent.back(), tangent_at_p);
    return;
  }
  if (!points.empty()) roles.push_back(role);
  points.push_back(p);
  max_tangent.push_back(tangent_at_p);
}

double Route::length() const {
  double s = 0.0;
  for (size_t i = 0; i + 1 < points.size(); ++i) s += (points[i + 1] - points[i]).norm();
  return s;
}

SpeedSettings SpeedSettings::fromVehicle(const energy::Vehicle& v) {
  SpeedSettings s;
  s.max_speed = v.max_speed_mps;
  s.lateral_acceleration = v.max_acceleration_mps2;
  s.limits.acceleration = v.max_acceleration_mps2;
  s.limits.deceleration = v.max_acceleration_mps2;
  s.yaw_rate = v.max_yaw_rate_radps;
  return s;
}

void SpeedSettings::validate() const {
  auto range = [](double v, double lo, double hi, const char* name, bool lo_open) {
    if (!std::isfinite(v) || v > hi || (lo_open ? v <= lo : v < lo))
      throw std::invalid_argument(std::string("SpeedSettings.") + name + " = " + std::to_string(v) + " is outside " +
                                  (lo_open ? "(" : "[") + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  };
  range(max_speed, 0.0, 200.0, "max_speed", true);
  range(camera_max_speed, 0.0, 200.0, "camera_max_speed", false);
  range(fixed_speed, 0.0, 200.0, "fixed_speed", false);
  range(lateral_acceleration, 0.0, 100.0, "lateral_acceleration", true);
  range(limits.acceleration, 0.0, 100.0, "limits.acceleration", true);
  range(limits.deceleration, 0.0, 100.0, "limits.deceleration", true);
  range(yaw_rate, 0.0, 100.0, "yaw_rate", true);
  range(altitude, 0.0, 10000.0, "altitude", false);
}


struct RouteScorer::Cache {
  struct Key {
    long long l, a, b, c;
    bool operator==(const Key& o) const { return l == o.l && a == o.a && b == o.b && c == o.c; }
  };
  struct Hash {
    size_t operator()(const Key& k) const {
      size_t h = std::hash<long long>()(k.l);
      for (long long x : {k.a, k.b, k.c}) h = h * 1000003u ^ std::hash<long long>()(x);
      return h;
    }
  };
  std::unordered_map<Key, std::pair<double, double>, Hash> legs;  // energy, cruise
};

struct RouteScorer::Solved {
  std::vector<std::array<Option, kOptions>> options;  // per vertex; [0] stop, [1..] arcs valid when .rounded
  std::vector<int> choice;                     // chosen option per vertex
  std::vector<double> caps;                    // [m/s] per segment
  double energy = kInf;
};

RouteScorer::RouteScorer(const energy::EnergyModel& model, const SpeedSettings& settings)
    : model_(model), settings_(settings), cache_(std::make_shared<Cache>()) {
  settings_.validate();
  closed_ = energy::MarinsClosedForm::forLegsOf(model_, settings_.limits);
}

double RouteScorer::turnEnergy(double angle) const {
  if (std::abs(angle) < kStraight) return 0.0;
  return model_.energy({energy::turnInPlace(angle, settings_.yaw_rate)});
}

double RouteScorer::optimise(double length, double v_in, double v_out, double cap, double* cruise) {
  const auto& lim = settings_.limits;
  const double need = v_out > v_in ? (v_out * v_out - v_in * v_in) / (2.0 * lim.acceleration)
                                   : (v_in * v_in - v_out * v_out) / (2.0 * lim.deceleration);
  if (length < 0.0 || need > length + 1e-9) return kInf;
  if (length < energy::tol::kLength) {
    *cruise = std::max(v_in, v_out);
    return 0.0;
  }
  const Cache::Key key{std::llround(length / kQuantum), std::llround(v_in / kQuantum), std::llround(v_out / kQuantum),
                       std::llround(cap / kQuantum)};
  const auto it = cache_->legs.find(key);
  if (it != cache_->legs.end()) {
    *cruise = it->second.second;
    return it->second.first;
  }
  auto f = [&](double v) {
    return closed_ ? closed_->legEnergy(length, v_in, v, v_out)
                   : model_.energy(energy::buildLegProfile(length, v_in, v, v_out, lim));
  };
  const double lo = std::max({v_in, v_out, kMinCruise});
  double best_v = std::max(lo, cap);
  double best = kInf;
  if (settings_.fixed_speed > 0.0) {
    best_v = std::max(std::min(settings_.fixed_speed, cap), lo);
    best = f(best_v);
  } else if (cap <= lo + energy::tol::kSpeed) {
    best_v = std::max(cap, lo);
    best = f(best_v);
  } else if (closed_) {
    // Marins' effects only: energy::minimiseOnInterval (grid, then Brent's minimisation around
    // the best sample) over the inlined closed form (f), several times faster than the generic
    // optimiser below (docs/performance.md). A speed the leg cannot hold is NaN there, which the
    // search skips.
    const double hi = std::min(cap, energy::legPeakSpeed(length, v_in, v_out, lim));
    const double low = std::min(kMinCruise, 0.5 * hi);
    best_v = hi > low ? energy::minimiseOnInterval(f, low, hi) : hi;
    best = f(best_v);
    // The closed form accepts speeds a rounding-width past the edge of feasibility, which
    // buildLegProfile (what fly() and the reports use, on lengths recomputed from the leg's end
    // points) may refuse: check once per cached leg on a leg a hair shorter, and when that is
    // refused fly the change itself, cruising at the higher end speed (fits at any length that
    // allows the change).
    bool buildable = std::isfinite(best);
    if (buildable) {
      try {
        (void)energy::buildLegProfile(length * (1.0 - 1e-9) - 1e-9, v_in, best_v, v_out, lim);
      } catch (const std::invalid_argument&) {
        buildable = false;
      }
    }
    if (!buildable) {
      best_v = lo;
      best = f(lo);
    }
  } else {
    // The energy module's optimiser (grid, then a bracketed root of the analytic dE/dv): same
    // optimum as a golden-section search to 1e-14 relative, at about the same cost.
    energy::CruiseSpeedSettings cs;
    cs.min_speed = std::min(kMinCruise, 0.5 * cap);
    const auto opt = energy::optimalCruiseSpeed(model_, length, v_in, v_out, lim, cap, cs);
    best = opt.energy;
    best_v = opt.speed;
    if (std::min(v_in, v_out) < best_v && best_v < std::max(v_in, v_out)) {
      // A cruise between the entry and exit speeds needs room for both changes; at the edge of
      // feasibility (the leg just long enough for the change) rounding can leave none: fly the
      // change itself, cruising at the higher end speed.
      try {
        (void)energy::buildLegProfile(length, v_in, best_v, v_out, lim);
      } catch (const std::invalid_argument&) {
        best_v = lo;
        best = f(lo);
      }
    }
  }
  cache_->legs.emplace(key, std::make_pair(best, best_v));
  *cruise = best_v;
  return best;
}

double RouteScorer::legEnergy(double length, double v_in, double v_out, double cap) {
  double c = 0.0;
  return optimise(length, v_in, v_out, cap, &c);
}

double RouteScorer::legCruise(double length, double v_in, double v_out, double cap) {
  double c = 0.0;
  optimise(length, v_in, v_out, cap, &c);
  return c;
}

namespace {

// The speed cap of each segment [m/s]: the vehicle's, and the camera's on sweeps.
std::vector<double> segmentCaps(const Route& route, const SpeedSettings& st) {
  std::vector<double> caps(route.roles.size());
  for (size_t i = 0; i < caps.size(); ++i) {
    caps[i] = st.max_speed;
    if (route.roles[i] == LegRole::Sweep && st.camera_max_speed > 0.0) caps[i] = std::min(caps[i], st.camera_max_speed);
  }
  return caps;
}

// The deflection at vertex k [rad], signed.
double deflection(const Route& route, size_t k) {
  return wrapAngle(heading(route.points[k], route.points[k + 1]) - heading(route.points[k - 1], route.points[k]));
}

constexpr std::array<double, 2> kChainFraction{1.0, 0.5};  // the chains' tangents, fractions of the widest that fit

// Speeds of chains of arcs (every corner rounded, tangents a fraction kChainFraction of the widest
// that fits) [m/s]: the largest speeds the arcs and the straight room between them allow from rest to
// rest (forward pass under the acceleration, backward pass under the braking limit). Offered as arc
// options at each corner, so a run of close corners (a lap of a round spiral) need not stop: the
// narrower chain leaves room to speed up, the widest then holds the speed reached.
std::array<std::vector<double>, 2> chainSpeeds(const Route& route, const std::vector<double>& len,
                                               const std::vector<double>& caps, const SpeedSettings& st) {
  const size_t n = route.points.size();
  std::array<std::vector<double>, 2> chain_v;
  for (auto& c : chain_v) c.assign(n, 0.0);
  if (!st.arc_chains || st.fixed_speed > 0.0 || st.corners == CornerStrategy::Sharp) return chain_v;
  for (size_t f = 0; f < kChainFraction.size(); ++f) {
    std::vector<double> t(n, 0.0);
    auto& v = chain_v[f];
    for (size_t k = 1; k + 1 < n; ++k) {
      const double theta = deflection(route, k);
      t[k] = kChainFraction[f] * std::min({route.max_tangent[k], 0.5 * len[k - 1], 0.5 * len[k]});
      if (std::abs(theta) < kStraight) {
        t[k] = 0.0;
        v[k] = std::min(caps[k - 1], caps[k]);
      } else if (t[k] > energy::tol::kLength) {
        v[k] = std::min({std::sqrt(st.lateral_acceleration * t[k] / std::tan(0.5 * std::abs(theta))), caps[k - 1], caps[k]});
      } else {
        t[k] = 0.0;
      }
    }
    for (size_t k = 1; k < n; ++k) {
      const double room = std::max(0.0, len[k - 1] - t[k - 1] - t[k]);
      v[k] = std::min(v[k], std::sqrt(v[k - 1] * v[k - 1] + 2.0 * st.limits.acceleration * room));
    }
    for (size_t k = n - 1; k-- > 1;) {
      const double room = std::max(0.0, len[k] - t[k] - t[k + 1]);
      v[k] = std::min(v[k], std::sqrt(v[k + 1] * v[k + 1] + 2.0 * st.limits.deceleration * room));
    }
  }
  return chain_v;
}

// The arc options at vertex k (out[1..]; out[0], the stop, is set by the caller): the widest arc that
// fits (half of each adjacent segment at most) at its largest speed and at the two chain speeds, and
// one half as wide at its largest and at the narrower chain's speed. The chain speeds let a run of
// arcs start and end where the straight room is too short to reach an arc's largest speed; the
// narrower arc leaves room to change speed between arcs. Straight on: one option, no corner.
void arcOptions(const Route& route, size_t k, const std::vector<double>& len, const std::vector<double>& caps,
                const std::array<std::vector<double>, 2>& chain_v, const SpeedSettings& st, const energy::EnergyModel& model,
                std::array<Option, kOptions>& out) {
  const double theta = deflection(route, k);
  const double vcap = std::min(caps[k - 1], caps[k]);
  const double t_max = std::min({route.max_tangent[k], 0.5 * len[k - 1], 0.5 * len[k]});
  // (tangent fraction, speed: >= 0 a fraction of the arc's largest, -1 / -2 the speed of the
  // widest / narrower chain)
  static constexpr std::array<std::pair<double, double>, kOptions - 1> kArcs{
      {{1.0, 1.0}, {1.0, -1.0}, {1.0, -2.0}, {0.5, 1.0}, {0.5, -2.0}}};
  for (int o = 1; o < kOptions; ++o) {
    Option rnd;
    rnd.rounded = true;
    if (std::abs(theta) < kStraight) {
      rnd.v = vcap;  // straight on: no corner, only a junction between roles
      out[o] = rnd;
      return;
    }
    rnd.t = kArcs[static_cast<size_t>(o - 1)].first * t_max;
    if (rnd.t <= energy::tol::kLength) return;
    rnd.r = rnd.t / std::tan(0.5 * std::abs(theta));
    const double fraction = kArcs[static_cast<size_t>(o - 1)].second;
    if (!st.arc_chains && (fraction < 0.0 || o > 1)) return;  // the widest arc at its largest speed only
    const double v_arc = std::min(std::sqrt(st.lateral_acceleration * rnd.r), vcap);
    rnd.v = fraction < 0.0 ? std::min(chain_v[fraction < -1.5 ? 1 : 0][k], v_arc) : fraction * v_arc;
    if (rnd.v <= kMinCruise) continue;
    rnd.energy = model.energy({energy::arc(rnd.r, theta, rnd.v)});
    out[o] = rnd;
  }
}

}  // namespace

RouteScorer::Solved RouteScorer::solve(const Route& route) {
  const size_t n = route.points.size();
  if (n < 2 || route.roles.size() != n - 1 || route.max_tangent.size() != n)
    throw std::invalid_argument("Route: " + std::to_string(n) + " points, " + std::to_string(route.roles.size()) +
                                " roles, " + std::to_string(route.max_tangent.size()) +
                                " tangents (expected at least 2 points, one role per segment, one tangent per point)");
  Solved s;
  s.caps = segmentCaps(route, settings_);
  std::vector<double> len(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) len[i] = (route.points[i + 1] - route.points[i]).norm();
  s.options.assign(n, {});
  const std::array<std::vector<double>, 2> chain_v = chainSpeeds(route, len, s.caps, settings_);
  for (size_t k = 1; k + 1 < n; ++k) {
    s.options[k][0].energy = turnEnergy(deflection(route, k));  // the stop
    if (settings_.fixed_speed > 0.0 || settings_.corners == CornerStrategy::Sharp) continue;
    arcOptions(route, k, len, s.caps, chain_v, settings_, model_, s.options[k]);
  }
  // Dynamic programming over the corners: best[k][c] = least (stops where an arc was possible under
  // the rounded strategy, energy) up to vertex k with option c; lexicographic, so "rounded" keeps a
  // stop only where no arc is feasible.
  using Cost = std::pair<int, double>;
  const Cost none{std::numeric_limits<int>::max(), kInf};
  std::vector<std::array<Cost, kOptions>> best(n);
  std::vector<std::array<int, kOptions>> from(n);
  for (auto& b : best) b.fill(none);
  for (auto& f : from) f.fill(-1);
  best[0][0] = {0, 0.0};
  const bool prefer_arcs = settings_.corners == CornerStrategy::Rounded;
  for (size_t k = 1; k < n; ++k) {
    for (int c = 0; c < kOptions; ++c) {
      const Option& oc = s.options[k][c];
      if (c > 0 && !oc.rounded) continue;
      const int penalty = (prefer_arcs && c == 0 && k + 1 < n && s.options[k][1].rounded) ? 1 : 0;
      for (int p = 0; p < kOptions; ++p) {
        if (!(best[k - 1][p].second < kInf)) continue;
        const Option& op = s.options[k - 1][p];
        // Two widest arcs meeting mid-segment leave a leg of length zero up to rounding.
        const double rest = std::max(0.0, len[k - 1] - op.t - oc.t);
        const double e = legEnergy(rest, op.v, oc.v, s.caps[k - 1]);
        if (!(e < kInf)) continue;
        const Cost tot{best[k - 1][p].first + penalty, best[k - 1][p].second + e + oc.energy};
        if (tot < best[k][c]) {
          best[k][c] = tot;
          from[k][c] = p;
        }
      }
    }
  }
  s.energy = best[n - 1][0].second;
  s.choice.assign(n, 0);
  if (s.energy < kInf)
    for (size_t k = n - 1; k > 0; --k) s.choice[k - 1] = from[k][s.choice[k]];
  return s;
}

double RouteScorer::energy(const Route& route) { return solve(route).energy; }

FlownPath RouteScorer::fly(const Route& route) {
  const Solved s = solve(route);
  if (!(s.energy < kInf)) throw std::runtime_error("flyRoute: no feasible speeds for the route");
  FlownPath out;
  const size_t n = route.points.size();
  auto push = [&](geometry::PathLeg leg, double cruise, double v0, double e, double t) {
    leg.altitude = settings_.altitude;
    out.path.legs.push_back(leg);
    out.speeds.cruise.push_back(cruise);
    out.speeds.junction.push_back(v0);
    out.leg_energy.push_back(e);
    out.leg_time.push_back(t);
  };
  for (size_t i = 0; i + 1 < n; ++i) {
    const Option& a = s.options[i][s.choice[i]];
    const Option& b = s.options[i + 1][s.choice[i + 1]];
    const Point& p = route.points[i];
    const Point& q = route.points[i + 1];
    const Point u = (q - p).normalized();
    const double h = heading(p, q);
    const double L = (q - p).norm() - a.t - b.t;
    if (L > energy::tol::kLength) {
      geometry::PathLeg line;
      line.kind = geometry::PrimitiveKind::Line;
      line.role = route.roles[i];
      line.start = p + u * a.t;
      line.end = q - u * b.t;
      line.heading_start = line.heading_end = h;
      double cruise = legCruise(L, a.v, b.v, s.caps[i]);
      std::vector<energy::Piece> pieces;
      try {
        pieces = energy::buildLegProfile(L, a.v, cruise, b.v, settings_.limits, h);
      } catch (const std::invalid_argument&) {
        // The leg-energy cache keys speeds and lengths to kQuantum: a cruise speed cached for a leg
        // a hair longer may not fit this one when it is just long enough for its speed change.
        // Fly the change itself, cruising at the higher end speed (always fits).
        cruise = std::max(a.v, b.v);
        pieces = energy::buildLegProfile(L, a.v, cruise, b.v, settings_.limits, h);
      }
      push(line, cruise, a.v, model_.energy(pieces), energy::totalTime(pieces));
    }
    if (i + 2 < n) {
      const Point& r = route.points[i + 2];
      const double h2 = heading(q, r);
      const double theta = wrapAngle(h2 - h);
      if (std::abs(theta) < kStraight) continue;  // straight on: a junction, not a corner
      geometry::PathLeg c;
      c.role = LegRole::Turn;
      c.heading_start = h;
      c.heading_end = h2;
      c.turn_angle = theta;
      if (b.rounded) {
        c.kind = geometry::PrimitiveKind::Arc;
        c.start = q - u * b.t;
        c.end = q + (r - q).normalized() * b.t;
        c.radius = b.r;
        const Point left(-u.y(), u.x());
        c.center = c.start + left * (theta > 0 ? b.r : -b.r);
        const auto piece = energy::arc(b.r, theta, b.v, h);
        push(c, b.v, b.v, b.energy, piece.duration);
        ++out.rounded_corners;
      } else {
        c.kind = geometry::PrimitiveKind::TurnInPlace;
        c.start = c.end = q;
        const auto piece = energy::turnInPlace(theta, settings_.yaw_rate, h);
        push(c, 0.0, 0.0, b.energy, piece.duration);
        ++out.sharp_corners;
      }
    }
  }
  out.speeds.junction.push_back(0.0);
  for (size_t i = 0; i < out.leg_energy.size(); ++i) {
    out.energy += out.leg_energy[i];
    out.time += out.leg_time[i];
  }
  out.length = out.path.length();
  return out;
}

}  // namespace wattswath::planner
