// Plausibility of a log as a measurement of a flying multirotor (issue 19): the position estimate
// (a diverged end cut off) and the measured power against the vehicle's physics hover power.
#include "wattswath/calibration/measurement_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "median.hpp"
#include "number_text.hpp"
#include "wattswath/energy/format.hpp"

namespace wattswath::calibration {
using detail::num;
using detail::upperMedian;
namespace {

void appendWarning(logs::FlightLog& log, const std::string& w) {
  std::string& all = log.metadata["warnings"];
  all += (all.empty() ? "" : " | ") + w;
}

// Why sample `s` cannot be a multirotor's state (empty: it can), against the first sample's height `z0`.
std::string implausibleState(const logs::LogSample& s, double z0, double max_h, const MeasurementLimits& l) {
  const double vz = s.velocity.z(), vh = s.velocity.head<2>().norm(), dz = s.position.z() - z0;
  if (std::abs(vz) > l.max_vertical_speed) {
    return "vertical speed " + num(vz, 4) + " m/s, expected at most " + num(l.max_vertical_speed) + " m/s up or down";
  }
  if (vh > max_h) return "horizontal speed " + num(vh, 4) + " m/s, expected at most " + num(max_h) + " m/s";
  if (std::abs(dz) > l.max_altitude_change) {
    return "altitude " + num(dz, 5) + " m from the first sample, expected within +-" + num(l.max_altitude_change) + " m";
  }
  return {};
}

// Cuts the samples from the first implausible one on; states why in `c`.
void checkPosition(logs::FlightLog& log, const energy::Vehicle& v, const MeasurementLimits& l, MeasurementCheck& c) {
  auto& S = log.samples;
  if (S.empty()) return;
  const double max_h = std::max(l.max_horizontal_speed, 2.0 * v.max_speed_mps);
  const double z0 = S.front().position.z();
  size_t bad = S.size();
  std::string why;
  for (size_t i = 0; i < S.size() && why.empty(); ++i) {
    why = implausibleState(S[i], z0, max_h, l);
    if (!why.empty()) bad = i;
  }
  if (why.empty()) return;
  const std::string what = "the position estimate is not a multirotor's at t = " + num(S[bad].t, 7) + " s (" + why +
                           "): the EKF diverged or the log is corrupt";
  if (bad < 2 || S[bad - 1].t - S.front().t < l.min_kept_s) {
    c.position_problem = what + "; less than " + num(l.min_kept_s) + " s before it, so the log cannot be used" +
                         (bad < 2 ? "" : " (use --to to keep the part before it)");
    return;
  }
  c.cut = true;
  c.cut_at_s = S[bad].t;
  const double dropped_s = S.back().t - S[bad].t;
  c.notes.push_back(what + "; the " + std::to_string(S.size() - bad) + " samples from there on (" + num(dropped_s, 4) +
                    " s) are not used");
  appendWarning(log, c.notes.back());
  S.resize(bad);
  const double end = S.back().t;
  std::vector<logs::TimeWindow> kept;
  for (auto w : log.airborne) {
    if (w.begin > end) continue;
    w.end = std::min(w.end, end);
    kept.push_back(w);
  }
  log.airborne = kept;
}

// Indices of the samples the power is checked on: inside the airborne windows, else higher than
// airborne_height above the lowest sample, else all.
std::vector<size_t> airborneSamples(const logs::FlightLog& log, const MeasurementLimits& l, MeasurementCheck& c) {
  const auto& S = log.samples;
  std::vector<size_t> idx;
  for (size_t i = 0; i < S.size(); ++i) {
    for (const auto& w : log.airborne) {
      if (w.contains(S[i].t)) {
        idx.push_back(i);
        break;
      }
    }
  }
  if (!idx.empty()) return idx;
  double zmin = std::numeric_limits<double>::infinity();
  for (const auto& s : S) zmin = std::min(zmin, s.position.z());
  for (size_t i = 0; i < S.size(); ++i)
    if (S[i].position.z() - zmin > l.airborne_height) idx.push_back(i);
  if (!idx.empty()) return idx;
  c.notes.push_back("no airborne window and no sample higher than " + num(l.airborne_height) +
                    " m above the lowest: the power was checked on all samples");
  for (size_t i = 0; i < S.size(); ++i) idx.push_back(i);
  return idx;
}

// A reading that never changes: (max - min) <= constant_relative * max|x|.
bool constantReading(const std::vector<double>& x, double relative, double& at) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  at = *lo;
  return x.size() >= 3 && *hi - *lo <= relative * std::max(std::abs(*lo), std::abs(*hi));
}

// The voltage of the samples `idx` against the vehicle battery's full voltage (nothing when the
// vehicle has no battery). Beyond [1 / unit_factor, unit_factor] x it the voltage's unit is wrong (a
// voltage logged in millivolts read as a power a thousand times too high, blamed on the current
// sensor): returned as the problem. Beyond [min_voltage_fraction, max_voltage_multiple] x it the
// battery is another (a 6S log with a 3S vehicle file): a note in `c`, as the power is measured
// either way but the battery model's figures are not this vehicle's.
std::string voltageProblem(const logs::FlightLog& log, const std::vector<size_t>& idx, const energy::Vehicle& v,
                           const MeasurementLimits& l, MeasurementCheck& c) {
  if (!v.battery) return {};
  std::vector<double> volts;
  for (size_t i : idx)
    if (std::isfinite(log.samples[i].voltage)) volts.push_back(log.samples[i].voltage);
  const double med = upperMedian(volts), full = v.battery->voltageFull();
  if (!(full > 0.0) || !std::isfinite(med)) return {};
  if (med <= l.max_voltage_multiple * full && med >= l.min_voltage_fraction * full) return {};
  const double ratio = med / full;
  const std::string seen = "the battery voltage while airborne (median " + num(med, 4) +
                           " V) is not that of the vehicle file's battery (fully charged at " + num(full, 4) + " V, '" +
                           v.name + "')";
  if (ratio < l.unit_factor && ratio > 1.0 / l.unit_factor) {
    c.notes.push_back(seen + ": the power is measured either way, but the battery figures of the vehicle file (state "
                      "of charge, endurance) are not this vehicle's");
    return {};
  }
  const std::string hint = ratio > 300.0 && ratio < 3000.0 ? " (about 1000 times: logged in millivolts?)"
                           : ratio > 30.0 && ratio < 300.0 ? " (about 100 times: logged in centivolts?)"
                                                           : "";
  return seen + "; " + num(ratio, 3) + " times it" + hint + ": the voltage's unit is wrong, or the vehicle file is not "
         "the logged vehicle";
}

// Why the measured power of the samples `idx` cannot be a flying multirotor's (empty: it can).
std::string powerProblem(const logs::FlightLog& log, const std::vector<size_t>& idx, const energy::Vehicle& v,
                         const MeasurementLimits& l, MeasurementCheck& c) {
  std::vector<double> cur, pw;
  for (size_t i : idx) {
    const auto& s = log.samples[i];
    if (std::isfinite(s.current)) cur.push_back(s.current);
    pw.push_back(std::isfinite(s.power) ? s.power : s.voltage * s.current);
  }
  c.airborne_samples = static_cast<int>(idx.size());
  // Every sample, on the ground too: the replay needs the power of each.
  size_t no_current = 0, no_voltage = 0, unmeasured = 0;
  for (const auto& s : log.samples) {
    if (std::isfinite(s.power) || std::isfinite(s.voltage * s.current)) continue;
    ++unmeasured;
    no_current += !std::isfinite(s.current);
    no_voltage += !std::isfinite(s.voltage);
  }
  if (unmeasured > 0) {
    c.hover_power_w = energy::marinsHoverPowerW(v);
    const std::string what = no_current >= no_voltage ? "battery current" : "battery voltage";
    return "the " + what + " is not measured in " + std::to_string(unmeasured) + " of " + std::to_string(log.samples.size()) +
           " samples (not finite" +
           (no_current >= no_voltage ? std::string(": ArduPilot logs BAT.Curr as NaN and PX4 current_a as -1 without a current sensor")
                                     : std::string()) +
           "), so the power drawn there is unknown";
  }
  c.median_power_w = upperMedian(pw);
  c.median_current_a = cur.size() == idx.size() ? upperMedian(cur) : std::numeric_limits<double>::quiet_NaN();
  c.hover_power_w = energy::marinsHoverPowerW(v);
  const std::string n = std::to_string(idx.size()) + " airborne samples";
  double at = 0.0;
  if (cur.size() == idx.size() && !cur.empty()) {
    const double largest = std::max(std::abs(*std::min_element(cur.begin(), cur.end())),
                                    std::abs(*std::max_element(cur.begin(), cur.end())));
    if (largest <= l.stuck_current_a) {
      return "the battery current reads 0 A in all " + n + " (largest |current| " + num(largest, 3) +
             " A): the current sensor is not measuring, so the measured power (voltage x current) is not the vehicle's";
    }
    if (constantReading(cur, l.constant_relative, at)) {
      return "the battery current is constant at " + num(at, 6) + " A in all " + n +
             ": a fixed value, not a measurement of the vehicle's power";
    }
  } else if (constantReading(pw, l.constant_relative, at)) {
    return "the measured power is constant at " + num(at, 6) + " W in all " + n + ": a fixed value, not a measurement";
  }
  if (const std::string volt = voltageProblem(log, idx, v, l, c); !volt.empty()) return volt;
  const std::string seen = "median " + num(c.median_power_w, 4) + " W" +
                           (std::isfinite(c.median_current_a) ? " (battery current median " + num(c.median_current_a, 3) + " A)" : "");
  const std::string physics = " against " + num(c.hover_power_w, 4) + " W that '" + v.name + "' needs to hover (physics, marinsHoverPowerW)";
  if (c.median_power_w < l.min_hover_fraction * c.hover_power_w) {
    return "the measured power while airborne is far below hover: " + seen + physics + ", expected at least " +
           num(l.min_hover_fraction) + " x that = " + num(l.min_hover_fraction * c.hover_power_w, 4) +
           " W (less than a perfect rotor needs): the current sensor is not measuring or is miscalibrated, or the "
           "vehicle file is not the logged vehicle";
  }
  if (c.median_power_w > l.max_hover_multiple * c.hover_power_w) {
    return "the measured power while airborne is far above hover: " + seen + physics + ", expected at most " +
           num(l.max_hover_multiple) + " x that = " + num(l.max_hover_multiple * c.hover_power_w, 4) +
           " W (full thrust at a thrust-to-weight ratio of 4): the current sensor is miscalibrated, or the vehicle "
           "file is not the logged vehicle";
  }
  return {};
}

}  // namespace

void validate(const MeasurementLimits& l) {
  using energy::detail::checkSettingRange;
  const double inf = std::numeric_limits<double>::infinity();
  checkSettingRange("MeasurementLimits", "min_hover_fraction", l.min_hover_fraction, 0.0, 1.0);
  checkSettingRange("MeasurementLimits", "max_hover_multiple", l.max_hover_multiple, 1.0, inf);
  checkSettingRange("MeasurementLimits", "stuck_current_a", l.stuck_current_a, 0.0, inf);
  checkSettingRange("MeasurementLimits", "constant_relative", l.constant_relative, 0.0, inf);
  checkSettingRange("MeasurementLimits", "max_vertical_speed", l.max_vertical_speed, 1e-9, inf);
  checkSettingRange("MeasurementLimits", "max_horizontal_speed", l.max_horizontal_speed, 1e-9, inf);
  checkSettingRange("MeasurementLimits", "max_altitude_change", l.max_altitude_change, 1e-9, inf);
  checkSettingRange("MeasurementLimits", "airborne_height", l.airborne_height, 0.0, inf);
  checkSettingRange("MeasurementLimits", "min_kept_s", l.min_kept_s, 0.0, inf);
  checkSettingRange("MeasurementLimits", "min_voltage_fraction", l.min_voltage_fraction, 0.0, 1.0);
  checkSettingRange("MeasurementLimits", "max_voltage_multiple", l.max_voltage_multiple, 1.0, inf);
  checkSettingRange("MeasurementLimits", "unit_factor", l.unit_factor, 1.0, inf);
}

namespace {
/// A log whose position and velocity do not change at all while it counts as airborne (all zero:
/// no position logged, or a run on the ground) measures no flight: a model compared with it, fitted
/// to it or diagnosed on it says nothing. Real sensors jitter by centimetres, so only an exactly
/// still record is refused.
std::string stillKinematicsProblem(const logs::FlightLog& log, const std::vector<size_t>& idx) {
  if (idx.size() < 10) return "";
  Eigen::Vector3d lo = log.samples[idx.front()].position, hi = lo;
  double fastest = 0.0;
  for (size_t i : idx) {
    const auto& s = log.samples[i];
    lo = lo.cwiseMin(s.position);
    hi = hi.cwiseMax(s.position);
    fastest = std::max(fastest, s.velocity.norm());
  }
  if ((hi - lo).maxCoeff() >= 1e-3 || fastest >= 1e-3) return "";
  return "the logged position and velocity do not change at all over the " + std::to_string(idx.size()) +
         " samples counted as airborne (position range " + num((hi - lo).maxCoeff(), 3) + " m, speed at most " + num(fastest, 3) +
         " m/s): no flight was measured (a log without position, or of the vehicle on the ground)";
}
}  // namespace

MeasurementCheck checkMeasurement(logs::FlightLog& log, const energy::Vehicle& v, const MeasurementLimits& l) {
  validate(l);
  MeasurementCheck c;
  c.median_current_a = std::numeric_limits<double>::quiet_NaN();
  c.hover_power_w = energy::marinsHoverPowerW(v);
  checkPosition(log, v, l, c);
  if (!c.position_problem.empty() || log.samples.empty()) return c;
  const auto idx = airborneSamples(log, l, c);
  c.position_problem = stillKinematicsProblem(log, idx);
  if (!c.position_problem.empty()) return c;
  c.power_problem = powerProblem(log, idx, v, l, c);
  return c;
}

}  // namespace wattswath::calibration
