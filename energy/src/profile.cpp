#include "wattswath/energy/profile.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "wattswath/energy/tolerances.hpp"

namespace wattswath::energy {

const char* toString(Phase p) {
  switch (p) {
    case Phase::Accelerate: return "accelerate";
    case Phase::Cruise: return "cruise";
    case Phase::Brake: return "brake";
    case Phase::Turn: return "turn";
    case Phase::Climb: return "climb";
    case Phase::Descent: return "descent";
    case Phase::Hover: return "hover";
    case Phase::Ground: return "ground";
  }
  return "?";
}

MotionState stateAt(const Piece& p, double tau, double t0) {
  MotionState s;
  s.t = t0 + tau;
  s.heading = p.heading;
  s.airborne = p.phase != Phase::Ground;
  if (p.length <= 0.0) {
    if (p.duration > 0.0) {
      s.yaw_rate = p.yaw_angle / p.duration;
      s.heading = p.heading + p.yaw_angle * (tau / p.duration);
    }
    return s;
  }
  const double at = p.duration > 0.0 ? (p.v_end - p.v_start) / p.duration : 0.0;  // along-path
  const double v = p.v_start + at * tau;
  const double dist = p.v_start * tau + 0.5 * at * tau * tau;
  const double frac = std::clamp(dist / p.length, 0.0, 1.0);
  const double sin_g = std::clamp(p.climb / p.length, -1.0, 1.0);
  const double cos_g = std::sqrt(1.0 - sin_g * sin_g);
  const double curvature = p.yaw_angle / p.length;  // [rad/m] of the horizontal track
  s.heading = p.heading + p.yaw_angle * frac;
  s.yaw_rate = v * cos_g * curvature;
  const Eigen::Vector3d t_dir(cos_g * std::cos(s.heading), cos_g * std::sin(s.heading), sin_g);
  const Eigen::Vector3d n_dir(-std::sin(s.heading), std::cos(s.heading), 0.0);  // left of track
  s.velocity = v * t_dir;
  s.acceleration = at * t_dir + (v * cos_g) * (v * cos_g) * curvature * n_dir;
  return s;
}

namespace {

constexpr double kFitSlack = 1e-9;  // [-] relative shortfall of a leg for its speed changes treated as rounding

std::string describe(double d, double ve, double vc, double vx) {
  std::ostringstream os;
  os << "distance " << d << " m, entry " << ve << " m/s, cruise " << vc << " m/s, exit " << vx << " m/s";
  return os.str();
}

void push(std::vector<Piece>& out, Phase phase, double v0, double v1, double len, double vc, double heading,
          double climb_per_m, std::vector<PieceSensitivity>* sens = nullptr, PieceSensitivity ds = {}) {
  if (len <= tol::kLength) return;
  if (sens) {
    ds.v_cruise = 1.0;
    ds.climb = climb_per_m * ds.length;
    sens->push_back(ds);
  }
  Piece p;
  p.phase = phase;
  p.length = len;
  p.v_start = v0;
  p.v_end = v1;
  p.duration = 2.0 * len / (v0 + v1);
  p.heading = heading;
  p.climb = climb_per_m * len;
  p.v_cruise = vc;
  out.push_back(p);
}

Phase changePhase(double v0, double v1) { return v1 > v0 ? Phase::Accelerate : Phase::Brake; }

}  // namespace

namespace {

std::vector<Piece> buildLeg(double d, double ve, double vc, double vx, const ProfileLimits& lim, double heading,
                            double climb, std::vector<PieceSensitivity>* sens) {
  if (sens) sens->clear();
  if (!(std::isfinite(d) && std::isfinite(ve) && std::isfinite(vc) && std::isfinite(vx)) || d < 0.0 ||
      ve < 0.0 || vc < 0.0 || vx < 0.0) {
    throw std::invalid_argument("leg profile: values must be finite and non-negative (" + describe(d, ve, vc, vx) +
                                ")");
  }
  if (!(lim.acceleration > 0.0) || !(lim.deceleration > 0.0)) {
    throw std::invalid_argument("leg profile: acceleration and deceleration must be positive");
  }
  if (!std::isfinite(climb) || std::abs(climb) > d + tol::kLength) {
    throw std::invalid_argument("leg profile: climb must be finite and no larger than the leg length");
  }
  std::vector<Piece> out;
  out.reserve(3);  // at most accelerate, cruise, brake: no reallocation in the optimisers' inner loops
  if (d <= tol::kLength) {
    if (std::abs(ve - vx) <= tol::kSpeed) return out;
    throw std::invalid_argument("leg profile: a zero-length leg cannot change speed (" + describe(d, ve, vc, vx) + ")");
  }
  if (vc <= tol::kSpeed) {
    throw std::invalid_argument("leg profile: cruise speed must be positive for a leg of non-zero length (" +
                                describe(d, ve, vc, vx) + ")");
  }
  const double au = lim.acceleration, ad = lim.deceleration;
  const double cpm = climb / d;
  auto dist = [&](double v0, double v1) {  // distance to change speed from v0 to v1
    return v1 >= v0 ? (v1 * v1 - v0 * v0) / (2.0 * au) : (v0 * v0 - v1 * v1) / (2.0 * ad);
  };
  double d1 = dist(ve, vc), d3 = dist(vc, vx);
  // A leg just long enough for its speed changes, as computed elsewhere from the same geometry,
  // may come out a few ulps short here: within kFitSlack the changes are shortened to fit.
  const double excess = d1 + d3 - d;
  if (excess > 0.0 && excess <= kFitSlack * std::max(1.0, d)) {
    d1 -= excess * d1 / (d1 + d3);
    d3 = std::max(0.0, d - d1);
  }
  if (d1 + d3 <= d) {
    // d d1 / d vc and d d3 / d vc: v^2 / (2 a) with the acceleration of the change's direction.
    const double dd1 = vc >= ve ? vc / au : -vc / ad;
    const double dd3 = vx >= vc ? -vc / au : vc / ad;
    push(out, changePhase(ve, vc), ve, vc, d1, vc, heading, cpm, sens, {dd1, 0.0, 1.0, 1.0, 0.0});
    push(out, Phase::Cruise, vc, vc, d - d1 - d3, vc, heading, cpm, sens, {-dd1 - dd3, 1.0, 1.0, 1.0, 0.0});
    push(out, changePhase(vc, vx), vc, vx, d3, vc, heading, cpm, sens, {dd3, 1.0, 0.0, 1.0, 0.0});
    return out;
  }
  const double e2 = ve * ve, x2 = vx * vx;
  const double slack = 2.0 * tol::kSpeed * std::max({ve, vx, vc, 1.0});
  if (ve <= vc && vx <= vc) {  // triangular: peak below cruise
    const double p2 = (2.0 * d * au * ad + e2 * ad + x2 * au) / (au + ad);
    if (p2 < std::max(e2, x2) - slack) {
      throw std::invalid_argument("leg profile: leg too short to change speed from entry to exit (" +
                                  describe(d, ve, vc, vx) + ")");
    }
    const double vp = std::sqrt(std::max(p2, std::max(e2, x2)));
    push(out, Phase::Accelerate, ve, vp, (vp * vp - e2) / (2.0 * au), vc, heading, cpm, sens);
    push(out, Phase::Brake, vp, vx, (vp * vp - x2) / (2.0 * ad), vc, heading, cpm, sens);
    return out;
  }
  if (ve >= vc && vx >= vc) {  // valley: entry and exit above cruise, cannot reach it
    const double m2 = (e2 * au + x2 * ad - 2.0 * d * au * ad) / (au + ad);
    if (m2 > std::min(e2, x2) + slack) {
      throw std::invalid_argument("leg profile: leg too short to change speed from entry to exit (" +
                                  describe(d, ve, vc, vx) + ")");
    }
    const double vm = std::sqrt(std::max(0.0, std::min(m2, std::min(e2, x2))));
    push(out, Phase::Brake, ve, vm, (e2 - vm * vm) / (2.0 * ad), vc, heading, cpm, sens);
    push(out, Phase::Accelerate, vm, vx, (x2 - vm * vm) / (2.0 * au), vc, heading, cpm, sens);
    return out;
  }
  // Monotone change through the cruise speed: d1 + d3 is the distance the change itself needs.
  throw std::invalid_argument("leg profile: leg too short to change speed from entry to exit (" +
                              describe(d, ve, vc, vx) + ")");
}

}  // namespace

std::vector<Piece> buildLegProfile(double d, double ve, double vc, double vx, const ProfileLimits& lim,
                                   double heading, double climb) {
  return buildLeg(d, ve, vc, vx, lim, heading, climb, nullptr);
}

std::vector<Piece> buildLegProfileWithSensitivity(double d, double ve, double vc, double vx,
                                                  const ProfileLimits& lim, std::vector<PieceSensitivity>& sens,
                                                  double heading, double climb) {
  return buildLeg(d, ve, vc, vx, lim, heading, climb, &sens);
}

double legPeakSpeed(double d, double ve, double vx, const ProfileLimits& lim) {
  const double au = lim.acceleration, ad = lim.deceleration;
  return std::sqrt((2.0 * d * au * ad + ve * ve * ad + vx * vx * au) / (au + ad));
}

Piece turnInPlace(double angle, double yaw_rate, double heading) {
  if (!std::isfinite(angle) || !(yaw_rate > 0.0) || !std::isfinite(yaw_rate)) {
    throw std::invalid_argument("turn in place: angle must be finite and yaw rate positive");
  }
  Piece p;
  p.phase = Phase::Turn;
  p.yaw_angle = angle;
  p.duration = std::abs(angle) / yaw_rate;
  p.heading = heading;
  return p;
}

Piece arc(double radius, double angle, double speed, double heading) {
  if (!(radius >= 0.0) || !std::isfinite(radius) || !std::isfinite(angle) || !(speed > 0.0) ||
      !std::isfinite(speed)) {
    throw std::invalid_argument("arc: radius must be non-negative, angle finite and speed positive");
  }
  Piece p;
  p.phase = Phase::Turn;
  p.length = radius * std::abs(angle);
  p.v_start = p.v_end = p.v_cruise = speed;
  p.duration = p.length / speed;
  p.heading = heading;
  p.yaw_angle = angle;
  return p;
}

Piece hover(double duration) {
  if (!(duration >= 0.0) || !std::isfinite(duration)) throw std::invalid_argument("hover: duration must be >= 0");
  Piece p;
  p.phase = Phase::Hover;
  p.duration = duration;
  return p;
}

double totalTime(const std::vector<Piece>& pieces) {
  double t = 0.0;
  for (const auto& p : pieces) t += p.duration;
  return t;
}

double totalLength(const std::vector<Piece>& pieces) {
  double l = 0.0;
  for (const auto& p : pieces) l += p.length;
  return l;
}

}  // namespace wattswath::energy
