#include "wattswath/calibration/replay.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "median.hpp"
#include "wattswath/energy/format.hpp"
#include "wattswath/logs/local_fit.hpp"

namespace wattswath::calibration {
using namespace energy;  // the physics this library compares with measurements
namespace {

void checkRange(const char* field, double v, double lo, double hi) {
  energy::detail::checkSettingRange("SegmentSettings", field, v, lo, hi);
}

// Unwraps angles so consecutive values differ by less than pi.
std::vector<double> unwrap(const std::vector<double>& a) {
  std::vector<double> out(a);
  for (size_t i = 1; i < out.size(); ++i) {
    double d = a[i] - a[i - 1];
    d = std::remainder(d, 2.0 * M_PI);
    out[i] = out[i - 1] + d;
  }
  return out;
}

std::vector<LegSpan> legsFromBoundaries(const std::vector<int>& starts, const std::vector<Eigen::Vector3d>& pos,
                                        const std::vector<MotionState>& st, const std::vector<double>& t,
                                        double stop_speed) {
  std::vector<LegSpan> legs;
  const int n = static_cast<int>(t.size());
  for (size_t k = 0; k < starts.size(); ++k) {
    LegSpan L;
    L.first = starts[k];
    L.last = k + 1 < starts.size() ? starts[k + 1] - 1 : n - 1;
    if (L.last < L.first) continue;
    L.t_start = t[L.first];
    L.t_end = t[L.last];
    double peak = 0.0;
    for (int i = L.first; i <= L.last; ++i) {
      if (i > L.first) L.distance += (pos[i] - pos[i - 1]).norm();
      peak = std::max(peak, st[i].velocity.head<2>().norm());
    }
    L.moving = peak > stop_speed;
    legs.push_back(L);
  }
  return legs;
}

// Copies the log's samples into `P` (positions, voltages, currents, measured power) and returns
// their times [s]; a sample without power is an error naming it.
std::vector<double> copySamples(const FlightLog& log, PreparedLog& P) {
  const auto& S = log.samples;
  const int n = static_cast<int>(S.size());
  P.source = log.source;
  P.states.resize(n);
  P.measured.resize(n);
  P.weight.resize(n);
  P.phase.resize(n);
  P.position.resize(n);
  P.voltage.resize(n);
  P.current.resize(n);
  std::vector<double> t(n);
  for (int i = 0; i < n; ++i) {
    t[i] = S[i].t;
    P.position[i] = S[i].position;
    P.voltage[i] = S[i].voltage;
    P.current[i] = S[i].current;
    P.measured[i] = std::isfinite(S[i].power) ? S[i].power : S[i].voltage * S[i].current;
    if (!std::isfinite(P.measured[i])) {
      throw std::invalid_argument(log.source + ": sample " + std::to_string(i) + " (t = " + std::to_string(t[i]) +
                                  " s) has no power (power_w or voltage_v * current_a)");
    }
  }
  for (int i = 0; i < n; ++i) {  // each sample stands for half the time to each neighbour
    const double prev = i > 0 ? t[i] - t[i - 1] : 0.0;
    const double next = i + 1 < n ? t[i + 1] - t[i] : 0.0;
    P.weight[i] = 0.5 * (prev + next);
  }
  return t;
}

// The heading of each sample [rad]: the logged yaw when most samples have one, else the track
// (held while the vehicle is slower than `stop_speed` [m/s]).
std::vector<double> headings(const std::vector<LogSample>& S, double stop_speed) {
  // The logged yaw when most samples have one; a cell without (an empty yaw_rad) holds the last
  // logged yaw (the first one before it), so one gap does not switch the whole log to the track (it
  // did). With yaw in fewer than half the samples, the track.
  const auto with_yaw = std::count_if(S.begin(), S.end(), [](const LogSample& x) { return std::isfinite(x.yaw); });
  const bool use_yaw = 2 * static_cast<size_t>(with_yaw) > S.size();
  const auto first_yaw = std::find_if(S.begin(), S.end(), [](const LogSample& x) { return std::isfinite(x.yaw); });
  std::vector<double> heading(S.size());
  double last_track = 0.0, last_yaw = first_yaw == S.end() ? 0.0 : first_yaw->yaw;
  for (size_t i = 0; i < S.size(); ++i) {
    if (S[i].velocity.head<2>().norm() > stop_speed) last_track = std::atan2(S[i].velocity.y(), S[i].velocity.x());
    if (std::isfinite(S[i].yaw)) last_yaw = S[i].yaw;
    heading[i] = use_yaw ? last_yaw : last_track;
  }
  return heading;
}

// The flight phase of an airborne state: climbing or descending, at rest (hover, or a turn on the
// spot), turning along a track, accelerating, braking or cruising.
Phase airbornePhase(const MotionState& m, const SegmentSettings& set) {
  const double vz = m.velocity.z(), hs = m.velocity.head<2>().norm();
  if (vz > set.vertical_speed) return Phase::Climb;
  if (vz < -set.vertical_speed) return Phase::Descent;
  if (hs < set.stop_speed) return std::abs(m.yaw_rate) > set.turn_rate ? Phase::Turn : Phase::Hover;
  const Eigen::Vector2d vh = m.velocity.head<2>(), ah = m.acceleration.head<2>();
  const double along = vh.dot(ah) / hs;
  const double track_rate = std::abs(vh.x() * ah.y() - vh.y() * ah.x()) / (hs * hs);
  if (track_rate > set.turn_rate) return Phase::Turn;
  if (along > set.acceleration) return Phase::Accelerate;
  if (along < -set.acceleration) return Phase::Brake;
  return Phase::Cruise;
}

// Fills the motion states and phases of `P`. On the ground: near the lowest height, at rest and
// drawing well under the median power (motors idle).
void classifySamples(const std::vector<LogSample>& S, const std::vector<double>& t, const SegmentSettings& set,
                     const std::vector<logs::TimeWindow>& air, PreparedLog& P) {
  const int n = static_cast<int>(S.size());
  const std::vector<double> heading = headings(S, set.stop_speed);
  const std::vector<double> uw = unwrap(heading);
  const int half = static_cast<int>(set.yaw_rate_window);
  double zmin = S[0].position.z();
  for (const auto& x : S) zmin = std::min(zmin, x.position.z());
  const double pmed = detail::upperMedian(P.measured);  // P.measured has n >= 1 samples
  for (int i = 0; i < n; ++i) {
    MotionState& m = P.states[i];
    m.t = t[i];
    m.velocity = S[i].velocity;
    m.acceleration = S[i].acceleration;
    m.heading = heading[i];
    m.yaw_rate = logs::detail::localSlope(n, i, half, [&](int j) { return t[j]; }, [&](int j) { return uw[j]; });
    // Outside every airborne window the log's reader found (landed flags, current), the vehicle is on
    // the ground whatever its altitude estimate says (an EKF's z drifts on the ground).
    const bool in_air_window =
        air.empty() || std::any_of(air.begin(), air.end(), [&](const logs::TimeWindow& w) { return w.contains(S[i].t); });
    m.airborne = in_air_window &&
                 !(S[i].position.z() - zmin < set.ground_height && S[i].velocity.head<2>().norm() < set.stop_speed &&
                   std::abs(S[i].velocity.z()) < set.vertical_speed && P.measured[i] < set.ground_power_fraction * pmed);
    P.phase[i] = m.airborne ? airbornePhase(m, set) : Phase::Ground;
  }
}

// Leg starts at the waypoints: for each in turn, the first local minimum of the distance to it
// within 3 m of the closest approach after the previous one (a later pass may come closer).
std::vector<int> legStartsAtWaypoints(const std::vector<Eigen::Vector3d>& position,
                                      const std::vector<Eigen::Vector3d>& waypoints) {
  const int n = static_cast<int>(position.size());
  std::vector<int> starts = {0};
  int from = 0;
  for (const auto& w : waypoints) {
    std::vector<double> d(n, 0.0);
    double dmin = 1e300;
    for (int i = from; i < n; ++i) {
      d[i] = (position[i] - w).norm();
      dmin = std::min(dmin, d[i]);
    }
    int pick = -1;
    for (int i = from; i < n && pick < 0; ++i) {
      const bool local_min = (i == from || d[i] <= d[i - 1]) && (i + 1 == n || d[i] <= d[i + 1]);
      if (local_min && d[i] <= dmin + 3.0) pick = i;
    }
    if (pick > starts.back()) starts.push_back(pick);
    from = std::max(pick, from);
  }
  return starts;
}

// Splits the moving run of samples i..j at marked slow-downs: local minima of the horizontal speed
// `hs` [m/s] below leg_slowdown times the fastest speed since the last split and up to the run's end.
// The suffix maxima make a day-long moving run cost linear time, not a scan per local minimum.
void splitAtSlowdowns(const std::vector<double>& hs, int i, int j, double leg_slowdown, std::vector<int>& starts) {
  std::vector<double> after_max(static_cast<size_t>(j - i + 1));
  after_max.back() = hs[j];
  for (int k = j - 1; k >= i; --k) after_max[k - i] = std::max(hs[k], after_max[k - i + 1]);
  double before_max = std::max(hs[i], hs[i + 1]);
  for (int k = i + 2; k <= j - 2; ++k) {
    before_max = std::max(before_max, hs[k]);
    bool local_min = true;
    for (int q = k - 2; q <= k + 2; ++q) local_min = local_min && hs[k] <= hs[q];
    if (!local_min) continue;
    if (hs[k] < leg_slowdown * std::min(before_max, after_max[k - i])) {
      starts.push_back(k);
      before_max = hs[k];
    }
  }
}

// Leg starts without waypoints: stopped runs are legs of their own; moving runs split at marked
// slow-downs.
std::vector<int> legStartsFromSpeed(const std::vector<LogSample>& S, const SegmentSettings& set) {
  const int n = static_cast<int>(S.size());
  std::vector<double> hs(n);
  for (int i = 0; i < n; ++i) hs[i] = S[i].velocity.head<2>().norm();
  std::vector<int> starts = {0};
  int i = 0;
  while (i < n) {
    const bool stopped = hs[i] < set.stop_speed;
    int j = i;
    while (j + 1 < n && (hs[j + 1] < set.stop_speed) == stopped) ++j;
    if (i > 0) starts.push_back(i);
    if (!stopped && j - i >= 4) splitAtSlowdowns(hs, i, j, set.leg_slowdown, starts);
    i = j + 1;
  }
  return starts;
}

}  // namespace

void validate(const SegmentSettings& s) {
  checkRange("stop_speed", s.stop_speed, 0.1, 3.0);
  checkRange("vertical_speed", s.vertical_speed, 0.1, 3.0);
  checkRange("acceleration", s.acceleration, 0.05, 3.0);
  checkRange("turn_rate", s.turn_rate, 0.05, 3.0);
  checkRange("ground_height", s.ground_height, 0.0, 5.0);
  checkRange("ground_power_fraction", s.ground_power_fraction, 0.0, 1.0);
  checkRange("leg_slowdown", s.leg_slowdown, 0.1, 1.0);
  checkRange("yaw_rate_window", s.yaw_rate_window, 1.0, 50.0);
}

PreparedLog prepareLog(const FlightLog& log, const SegmentSettings& set, const std::vector<Eigen::Vector3d>& waypoints) {
  validate(set);
  const int n = static_cast<int>(log.samples.size());
  if (n < 2) throw std::invalid_argument(log.source + ": a log needs at least 2 samples to replay");
  PreparedLog P;
  const std::vector<double> t = copySamples(log, P);
  classifySamples(log.samples, t, set, log.airborne, P);
  const std::vector<int> starts =
      waypoints.empty() ? legStartsFromSpeed(log.samples, set) : legStartsAtWaypoints(P.position, waypoints);
  P.legs = legsFromBoundaries(starts, P.position, P.states, t, set.stop_speed);
  P.leg.assign(n, 0);
  for (size_t k = 0; k < P.legs.size(); ++k)
    for (int i = P.legs[k].first; i <= P.legs[k].last; ++i) P.leg[i] = static_cast<int>(k);
  return P;
}

std::vector<double> modelPower(const EnergyModel& m, const PreparedLog& log) {
  std::vector<double> p(log.states.size());
  for (size_t i = 0; i < p.size(); ++i) p[i] = m.power(log.states[i]);
  return p;
}

LogReplay assembleReplay(const PreparedLog& log, const std::vector<double>& modelled) {
  if (modelled.size() != log.states.size()) throw std::invalid_argument("assembleReplay: size mismatch");
  LogReplay r;
  r.source = log.source;
  r.legs.resize(log.legs.size());
  r.samples.resize(modelled.size());
  for (size_t i = 0; i < modelled.size(); ++i) {
    const auto& st = log.states[i];
    ReplaySample& s = r.samples[i];
    s.t = st.t;
    s.phase = log.phase[i];
    s.leg = log.leg[i];
    s.measured_w = log.measured[i];
    s.modelled_w = modelled[i];
    s.speed = st.velocity.head<2>().norm();
    s.climb_rate = st.velocity.z();
    s.acceleration = s.speed > 1e-9 ? st.velocity.head<2>().dot(st.acceleration.head<2>()) / s.speed : 0.0;
    s.heading = std::atan2(st.velocity.y(), st.velocity.x());
    const double w = log.weight[i];
    for (EnergyCompare* e : {&r.legs[s.leg], &r.phases[static_cast<int>(s.phase)], &r.flight}) {
      e->measured_j += w * s.measured_w;
      e->modelled_j += w * s.modelled_w;
      e->time_s += w;
    }
  }
  return r;
}

LogReplay replay(const EnergyModel& m, const PreparedLog& log) { return assembleReplay(log, modelPower(m, log)); }

ErrorMetrics errorMetrics(const std::vector<LogReplay>& replays) {
  ErrorMetrics out;
  double se = 0.0;
  std::array<double, kPhaseCount> pse{}, pmeas{}, pmod{}, pe_meas{}, pe_mod{};
  double energy_abs = 0.0, leg_abs = 0.0;
  int legs = 0;
  for (const auto& r : replays) {
    for (const auto& s : r.samples) {
      const double d = s.modelled_w - s.measured_w;
      se += d * d;
      const int k = static_cast<int>(s.phase);
      out.phases[k].samples++;
      pse[k] += d * d;
      pmeas[k] += s.measured_w;
      pmod[k] += s.modelled_w;
    }
    out.samples += static_cast<int>(r.samples.size());
    energy_abs += std::abs(r.flight.errorPct());
    for (int k = 0; k < kPhaseCount; ++k) {
      pe_meas[k] += r.phases[k].measured_j;
      pe_mod[k] += r.phases[k].modelled_j;
    }
    for (const auto& L : r.legs) {
      // Leg MAPE over legs of at least 3 s with some energy (tiny legs are all noise).
      if (L.time_s >= 3.0 && L.measured_j > 0.0) {
        leg_abs += std::abs(L.errorPct());
        ++legs;
      }
    }
  }
  out.rmse_w = out.samples ? std::sqrt(se / out.samples) : 0.0;
  out.energy_error_pct = replays.empty() ? 0.0 : energy_abs / replays.size();
  out.leg_energy_mape_pct = legs ? leg_abs / legs : 0.0;
  for (int k = 0; k < kPhaseCount; ++k) {
    auto& p = out.phases[k];
    if (p.samples == 0) continue;
    p.rmse_w = std::sqrt(pse[k] / p.samples);
    p.measured_mean_w = pmeas[k] / p.samples;
    p.modelled_mean_w = pmod[k] / p.samples;
    p.energy_error_pct = pe_meas[k] != 0.0 ? 100.0 * (pe_mod[k] - pe_meas[k]) / pe_meas[k] : 0.0;
  }
  return out;
}

std::vector<ResidualTable> residualTables(const std::vector<LogReplay>& replays) {
  struct Spec {
    const char* q;
    const char* unit;
    double width;
  };
  const Spec specs[] = {{"speed", "m/s", 1.0},    {"climb_rate", "m/s", 0.5}, {"acceleration", "m/s^2", 0.25},
                        {"heading", "deg", 45.0}, {"time", "s", 60.0}};
  std::vector<ResidualTable> out;
  for (const auto& sp : specs) {
    std::map<long, ResidualBin> bins;
    for (const auto& r : replays) {
      for (const auto& s : r.samples) {
        double x = 0.0;
        const std::string q = sp.q;
        if (q == "speed") x = s.speed;
        else if (q == "climb_rate") x = s.climb_rate;
        else if (q == "acceleration") x = s.acceleration;
        else if (q == "time") x = s.t;
        else {
          if (s.speed < 2.0) continue;  // heading only means something when moving
          x = std::fmod(90.0 - s.heading * 180.0 / M_PI + 720.0, 360.0);  // compass bearing
        }
        const long k = static_cast<long>(std::floor(x / sp.width));
        auto& b = bins[k];
        b.lo = k * sp.width;
        b.hi = (k + 1) * sp.width;
        b.count++;
        b.measured_mean_w += s.measured_w;
        b.modelled_mean_w += s.modelled_w;
      }
    }
    ResidualTable t;
    t.quantity = sp.q;
    t.unit = sp.unit;
    for (auto& [k, b] : bins) {
      b.measured_mean_w /= b.count;
      b.modelled_mean_w /= b.count;
      t.bins.push_back(b);
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace wattswath::calibration
