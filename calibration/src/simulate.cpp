// Simulated flight logs: a model flown through waypoints, with noise, as a canonical log (the
// tests' logs with known effects).
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "number_text.hpp"
#include "wattswath/calibration/diagnose.hpp"

namespace wattswath::calibration {
using namespace energy;  // the physics this library compares with measurements
using detail::num;

namespace {

// A piece of the simulated flight with where it starts, its 3-D direction and its start time.
struct Span {
  Piece piece;
  Eigen::Vector3d start, dir;
  double t0;  // [s]
};

// Checks the waypoints (at least 2, finite) and the sample rate.
void checkSimulation(const std::vector<Eigen::Vector3d>& wps, const SimulationSettings& s) {
  if (wps.size() < 2) throw std::invalid_argument("simulateFlight: need at least 2 waypoints");
  for (size_t k = 0; k < wps.size(); ++k) {
    if (!wps[k].allFinite()) {
      throw std::invalid_argument("simulateFlight: waypoint " + std::to_string(k + 1) + " is not finite, expected x y z in m");
    }
  }
  if (!(s.rate_hz >= 0.1 && s.rate_hz <= 1000.0)) {
    throw std::invalid_argument("SimulationSettings.rate_hz = " + std::to_string(s.rate_hz) + ", expected 0.1..1000");
  }
}

// The flight as a timeline of pieces: a hover, then for each leg a turn in place to its heading and
// a stop-to-stop profile (cruise or vertical speed), then a hover at the last heading; each piece
// starts where the previous one ended.
std::vector<Span> timeline(const std::vector<Eigen::Vector3d>& wps, const SimulationSettings& s) {
  std::vector<Span> spans;
  double t = 0.0;
  ProfileLimits lim;
  lim.acceleration = lim.deceleration = s.acceleration;
  double heading = 0.0;
  auto push = [&](const Piece& p, const Eigen::Vector3d& at, const Eigen::Vector3d& dir) {
    spans.push_back({p, at, dir, t});
    t += p.duration;
  };
  push(hover(std::max(s.hover_s, 1e-3)), wps[0], Eigen::Vector3d::Zero());
  for (size_t k = 0; k + 1 < wps.size(); ++k) {
    const Eigen::Vector3d d = wps[k + 1] - wps[k];
    const double len = d.norm();
    if (len < 1e-9) continue;
    const double horiz = d.head<2>().norm();
    if (horiz > 1e-6) {
      const double h = std::atan2(d.y(), d.x());
      const double turn = std::remainder(h - heading, 2.0 * M_PI);
      if (s.yaw_rate > 0.0 && std::abs(turn) > 1e-6) {
        Piece p = turnInPlace(turn, s.yaw_rate, heading);
        p.phase = Phase::Turn;
        push(p, wps[k], Eigen::Vector3d::Zero());
      }
      heading = h;
    }
    const double vc = horiz > std::abs(d.z()) ? s.cruise_speed : s.vertical_speed;
    for (const Piece& p : buildLegProfile(len, 0.0, vc, 0.0, lim, heading, d.z())) push(p, wps[k], d / len);
  }
  Eigen::Vector3d pos = wps[0];
  for (auto& sp : spans) {
    sp.start = pos;
    pos += sp.dir * sp.piece.length;
  }
  Piece last = hover(std::max(s.hover_s, 1e-3));
  last.heading = heading;  // hover keeps the last heading (no yaw jump)
  push(last, wps.back(), Eigen::Vector3d::Zero());
  return spans;
}

// The log sample of `sp` at time `tt` [s]: the true state with noise on the velocity and the power
// (drawn from `rng`), the voltage falling linearly over the flight of `total` [s].
LogSample sampleAt(const Span& sp, double tt, double total, const EnergyModel& truth, const SimulationSettings& s,
                   std::mt19937& rng, std::normal_distribution<double>& noise) {
  const double tau = std::clamp(tt - sp.t0, 0.0, sp.piece.duration);
  MotionState st = stateAt(sp.piece, tau, sp.t0);
  st.t = tt;
  LogSample x;
  x.t = tt;
  double dist = 0.0;
  if (sp.piece.length > 0.0) {
    const double a = (sp.piece.v_end - sp.piece.v_start) / sp.piece.duration;
    dist = sp.piece.v_start * tau + 0.5 * a * tau * tau;
  }
  x.position = sp.start + sp.dir * dist;
  x.velocity = st.velocity + s.velocity_noise_mps * Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  x.acceleration = st.acceleration;
  x.yaw = st.heading;
  const double p = truth.power(st) + s.power_noise_w * noise(rng);
  x.voltage = s.voltage_start_v + (s.voltage_end_v - s.voltage_start_v) * tt / std::max(total, 1e-9);
  x.power = p;
  x.current = p / x.voltage;
  return x;
}

}  // namespace

FlightLog simulateFlight(const std::vector<Eigen::Vector3d>& wps, const EnergyModel& truth,
                         const SimulationSettings& s) {
  checkSimulation(wps, s);
  const std::vector<Span> spans = timeline(wps, s);
  const double total = spans.back().t0 + spans.back().piece.duration;
  std::mt19937 rng(s.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  FlightLog log;
  log.source = "simulated";
  log.format = "simulated";
  log.metadata["vehicle"] = "simulated";
  log.metadata["sample_rate_hz"] = num(s.rate_hz, 6);
  log.metadata["seed"] = std::to_string(s.seed);
  const double dt = 1.0 / s.rate_hz;
  // A waypoint 1e300 m away would otherwise loop for ever filling memory.
  if (!(std::isfinite(total) && total * s.rate_hz < s.max_samples)) {
    throw std::invalid_argument("simulateFlight: the flight lasts " + num(total, 6) + " s, " +
                                num(total * s.rate_hz, 6) + " samples at " + num(s.rate_hz, 6) +
                                " Hz, expected at most " + num(s.max_samples, 12) +
                                " samples (waypoints too far apart, or thousands of stops? a lower --rate gives fewer samples)");
  }
  size_t k = 0;
  for (double tt = 0.0; tt <= total; tt += dt) {
    while (k + 1 < spans.size() && tt >= spans[k].t0 + spans[k].piece.duration) ++k;
    log.samples.push_back(sampleAt(spans[k], tt, total, truth, s, rng, noise));
  }
  return log;
}

}  // namespace wattswath::calibration
