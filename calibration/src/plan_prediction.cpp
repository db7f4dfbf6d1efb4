#include "wattswath/calibration/plan_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "wattswath/energy/tolerances.hpp"

#include "wattswath/energy/format.hpp"

namespace wattswath::calibration {
using namespace energy;  // the physics this library compares with measurements

namespace {

void checkRange(const char* name, double value, double lo, double hi) {
  energy::detail::checkSettingRange("PlanPredictionSettings", name, value, lo, hi);
}

double wrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

}  // namespace

void validate(const PlanPredictionSettings& s) {
  checkRange("corner_speed_fraction", s.corner_speed_fraction, 0.0, 1.0);
  checkRange("snap_distance", s.snap_distance, 0.0, 50.0);
  checkRange("simplify_tolerance", s.simplify_tolerance, 0.1, 20.0);
  checkRange("merge_distance", s.merge_distance, 0.01, 10.0);
  checkRange("min_leg_speed", s.min_leg_speed, 0.1, 5.0);
}

namespace {

// The samples of `pos` kept by Douglas-Peucker simplification (3-D, `tolerance` [m]): the track's
// corners; hovers and yaw-only stretches collapse into one point.
std::vector<char> simplifyTrack(const std::vector<Eigen::Vector3d>& pos, double tolerance) {
  const int ns = static_cast<int>(pos.size());
  std::vector<char> keep(ns, 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<int, int>> stack{{0, ns - 1}};
  while (!stack.empty()) {
    const auto [i0, i1] = stack.back();
    stack.pop_back();
    const Eigen::Vector3d a0 = pos[i0], d = pos[i1] - a0;
    const double dd = d.squaredNorm();
    double worst = 0.0;
    int at = -1;
    for (int i = i0 + 1; i < i1; ++i) {
      const Eigen::Vector3d r = pos[i] - a0;
      const double u = dd > 0.0 ? std::clamp(r.dot(d) / dd, 0.0, 1.0) : 0.0;
      const double e = (r - u * d).norm();
      if (e > worst) worst = e, at = i;
    }
    if (at >= 0 && worst > tolerance) {
      keep[at] = 1;
      stack.push_back({i0, at});
      stack.push_back({at, i1});
    }
  }
  return keep;
}

// The plan's waypoints from the logged track: its corners, merged when closer than merge_distance,
// each leg's speed the peak logged speed of the samples it spans; then each waypoint snapped
// horizontally to the nearest plan vertex within snap_distance.
void planWaypoints(const PreparedLog& log, const std::vector<Eigen::Vector3d>& plan_vertices,
                   const PlanPredictionSettings& s, PlanPrediction& out) {
  const std::vector<char> keep = simplifyTrack(log.position, s.simplify_tolerance);
  int first = 0;
  out.waypoints.push_back(log.position.front());
  for (int i = 1; i < static_cast<int>(log.position.size()); ++i) {
    if (!keep[i]) continue;
    if ((log.position[i] - out.waypoints.back()).norm() < s.merge_distance) continue;
    double peak = 0.0;
    for (int k = first; k <= i; ++k) peak = std::max(peak, log.states[k].velocity.norm());
    out.waypoints.push_back(log.position[i]);
    out.leg_speed.push_back(std::max(peak, s.min_leg_speed));
    first = i;
  }
  if (out.waypoints.size() < 2) {
    throw std::invalid_argument(log.source + ": the log never moves more than " + std::to_string(s.merge_distance) +
                                " m; no plan legs");
  }
  for (auto& w : out.waypoints) {
    double best = s.snap_distance;
    const Eigen::Vector3d* hit = nullptr;
    for (const auto& q : plan_vertices) {
      const double d = (q.head<2>() - w.head<2>()).norm();
      if (d <= best) best = d, hit = &q;
    }
    if (hit != nullptr && best > 0.0) {
      w.head<2>() = hit->head<2>();
      ++out.snapped;
    }
  }
}

// Speeds at the waypoints [m/s]: 0 at both ends and (stop mode) at every corner; otherwise a share of
// the slower neighbour, lowered where the legs are too short to reach it (forward/backward pass at
// acceleration `a` [m/s^2]).
std::vector<double> cornerSpeeds(const std::vector<double>& leg_speed, const std::vector<double>& length, double a,
                                 double fraction) {
  const int n = static_cast<int>(leg_speed.size());
  std::vector<double> corner(n + 1, 0.0);
  if (fraction <= 0.0) return corner;
  for (int k = 1; k < n; ++k) corner[k] = fraction * std::min(leg_speed[k - 1], leg_speed[k]);
  const double shrink = 1.0 - 1e-9;  // stay strictly inside the reachable speed (rounding)
  for (int k = 1; k <= n; ++k)
    corner[k] = std::min(corner[k], shrink * std::sqrt(corner[k - 1] * corner[k - 1] + 2.0 * a * length[k - 1]));
  for (int k = n - 1; k >= 0; --k)
    corner[k] = std::min(corner[k], shrink * std::sqrt(corner[k + 1] * corner[k + 1] + 2.0 * a * length[k]));
  return corner;
}

}  // namespace

PlanPrediction predictFromPlan(const EnergyModel& m, const Vehicle& v, const PreparedLog& log,
                               const std::vector<Eigen::Vector3d>& plan_vertices, const PlanPredictionSettings& s) {
  validate(s);
  if (log.position.empty() || log.position.size() != log.states.size()) {
    throw std::invalid_argument(log.source + ": no samples to build a plan from");
  }
  PlanPrediction out;
  planWaypoints(log, plan_vertices, s, out);
  const int n = static_cast<int>(out.leg_speed.size());
  const double a = v.max_acceleration_mps2;
  if (!(a > 0.0)) throw std::invalid_argument("vehicle " + v.name + ": max_acceleration_mps2 must be > 0");
  std::vector<double> length(n), heading(n), climb(n), horizontal(n);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d d = out.waypoints[k + 1] - out.waypoints[k];
    length[k] = d.norm();
    climb[k] = d.z();
    horizontal[k] = d.head<2>().norm();
    heading[k] = std::atan2(d.y(), d.x());
  }
  const std::vector<double> corner = cornerSpeeds(out.leg_speed, length, a, s.corner_speed_fraction);
  // The legs' profiles: level legs with a turn in place before them in stop mode; vertical legs
  // (take-off, landing, altitude changes) keep the last heading and count as climb or descent.
  const ProfileLimits limits{a, a};
  double last_heading = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < n; ++k) {
    const bool level = horizontal[k] >= s.merge_distance;
    const double h = level ? heading[k] : (std::isnan(last_heading) ? 0.0 : last_heading);
    if (level && s.corner_speed_fraction == 0.0 && !std::isnan(last_heading)) {
      const double turn = wrapAngle(h - last_heading);
      if (std::abs(turn) > 0.0) out.pieces.push_back(turnInPlace(turn, v.max_yaw_rate_radps, last_heading));
    }
    if (level) last_heading = h;
    for (auto p : buildLegProfile(length[k], corner[k], out.leg_speed[k], corner[k + 1], limits, h, climb[k])) {
      if (!level) p.phase = climb[k] > 0.0 ? Phase::Climb : Phase::Descent;
      out.pieces.push_back(p);
    }
    out.distance_m += length[k];
  }
  out.time_s = totalTime(out.pieces);
  out.energy_j = m.energy(out.pieces);
  return out;
}

PlanComparison comparePlan(const LogReplay& replay, const PlanPrediction& plan) {
  PlanComparison c;
  c.measured_j = replay.flight.measured_j;
  c.replay_j = replay.flight.modelled_j;
  c.measured_time_s = replay.flight.time_s;
  c.plan_j = plan.energy_j;
  c.plan_time_s = plan.time_s;
  return c;
}

}  // namespace wattswath::calibration
