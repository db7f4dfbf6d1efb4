#include "wattswath/energy/battery.hpp"
#include "wattswath/energy/format.hpp"

#include <cmath>
#include <algorithm>
#include <regex>
#include <stdexcept>

namespace wattswath::energy {
namespace {

constexpr double kSecondsPerHour = 3600.0;

using detail::formatNumber;

void checkSettings(const DischargeSettings& s) {
  if (!(std::isfinite(s.dt_s) && s.dt_s > 0.0 && s.dt_s <= 600.0)) {
    throw std::invalid_argument("battery discharge: dt = " + formatNumber(s.dt_s) + " s, expected a time step in (0, 600] s");
  }
  if (!(std::isfinite(s.max_time_s) && s.max_time_s > 0.0 && s.max_time_s <= 1e8)) {
    throw std::invalid_argument("battery discharge: max_time = " + formatNumber(s.max_time_s) + " s, expected (0, 1e8] s");
  }
}

void checkPower(double power_w, const char* what) {
  if (!(std::isfinite(power_w) && power_w >= 0.0 && power_w <= 1e7)) {
    throw std::invalid_argument(std::string("battery discharge: ") + what + " = " + formatNumber(power_w) +
                                " W, expected a power in [0, 1e7] W");
  }
}

// The Figure 3 loop for a profile given as a function of time. `power_at(t)` is the power drawn
// during the step starting at t; `end_s` is when the profile ends.
template <class PowerAt>
EnduranceResult discharge(const Battery& b, PowerAt power_at, double end_s, const DischargeSettings& s) {
  validateBattery(b);
  checkSettings(s);
  const double c0 = b.capacityAh();
  const double cutoff = cutoffResidualAh(b);
  const double lambda_c0 = b.pack.usable_fraction * c0;
  EnduranceResult r;
  double residual = c0;  // C_j with j = 0: the battery starts at its nominal capacity (Eq. 13)
  double drawn_ah = 0.0;  // sum of i_n dt
  double t = 0.0;
  if (s.keep_series) r.series.push_back({0.0, 0.0, voltageAt(b, residual), 0.0, residual, (residual - cutoff) / lambda_c0});
  const double stop = std::min(end_s, s.max_time_s);
  while (t < stop) {
    const double h = std::min(s.dt_s, stop - t);
    const double p = power_at(t);
    const double v = voltageAt(b, residual);                          // Eq. 13
    if (!(v > 0.0)) throw std::logic_error("battery discharge: voltage fell to zero before the cut-off");
    const double i = p / v;                                           // Eq. 14
    const double next_drawn = drawn_ah + i * h / kSecondsPerHour;
    // Eq. 15: effective capacity at the present current minus the charge drawn so far. With no
    // draw (motors off) the capacity is the nominal one minus what was drawn.
    const double next = (i > 0.0 ? peukertCapacityAh(b, i) : c0) - next_drawn;
    if (next <= cutoff) {
      // Linear interpolation inside the step: the residual moves from `residual` to `next`.
      const double f = residual > next ? std::clamp((residual - cutoff) / (residual - next), 0.0, 1.0) : 0.0;
      t += f * h;
      r.energy_j += p * f * h;
      drawn_ah += i * f * h / kSecondsPerHour;
      residual = cutoff;
      r.depleted = true;
      if (s.keep_series) r.series.push_back({t, p, v, i, residual, 0.0});
      break;
    }
    t += h;
    r.energy_j += p * h;
    drawn_ah = next_drawn;
    residual = next;
    if (s.keep_series) r.series.push_back({t, p, v, i, residual, (residual - cutoff) / lambda_c0});
  }
  r.endurance_s = t;
  r.charge_ah = drawn_ah;
  r.final_residual_ah = residual;
  return r;
}

}  // namespace

double peukertCapacityAh(const Battery& b, double current_a) {
  if (!(std::isfinite(current_a) && current_a > 0.0)) {
    throw std::invalid_argument("peukertCapacityAh: current = " + formatNumber(current_a) + " A, expected > 0");
  }
  const double c0 = b.capacityAh();
  const double t0_h = b.pack.rated_discharge_time_s / kSecondsPerHour;
  return c0 * std::pow(c0 / (current_a * t0_h), b.pack.peukert_exponent - 1.0);  // Eq. 10
}

double voltageSlope(const Battery& b) {
  return (b.voltageFull() - b.voltageStandard()) / (b.pack.usable_fraction * b.capacityAh());  // Eq. 12
}

double voltageAt(const Battery& b, double residual_ah) {
  return b.voltageFull() - voltageSlope(b) * (b.capacityAh() - residual_ah);  // Eq. 11
}

double cutoffResidualAh(const Battery& b) { return (1.0 - b.pack.usable_fraction) * b.capacityAh(); }

EnduranceResult endurance(const Battery& b, double power_w, double dt) {
  DischargeSettings s;
  s.dt_s = dt;
  return endurance(b, power_w, s);
}

EnduranceResult endurance(const Battery& b, double power_w, const DischargeSettings& s) {
  checkPower(power_w, "power");
  if (!(power_w > 0.0)) throw std::invalid_argument("battery endurance: power = 0 W, expected > 0 W");
  return discharge(b, [power_w](double) { return power_w; }, s.max_time_s, s);
}

EnduranceResult simulateProfile(const Battery& b, const std::vector<PowerStep>& profile, const DischargeSettings& s) {
  std::vector<double> ends;
  double total = 0.0;
  for (size_t k = 0; k < profile.size(); ++k) {
    const auto& step = profile[k];
    if (!(std::isfinite(step.duration_s) && step.duration_s >= 0.0)) {
      throw std::invalid_argument("battery profile: step " + std::to_string(k) + " duration = " +
                                  formatNumber(step.duration_s) + " s, expected >= 0");
    }
    checkPower(step.power_w, ("step " + std::to_string(k) + " power").c_str());
    total += step.duration_s;
    ends.push_back(total);
  }
  size_t k = 0;
  auto power_at = [&](double t) {
    // Steps are visited in time order; a discharge step straddling two profile steps draws the
    // power of the one it starts in (dt should be small against the steps; see DischargeSettings).
    while (k + 1 < ends.size() && t >= ends[k]) ++k;
    return profile.empty() ? 0.0 : profile[k].power_w;
  };
  return discharge(b, power_at, total, s);
}

double energyAvailableJ(const Battery& b, double power_w, double dt) {
  DischargeSettings s;
  s.dt_s = dt;
  s.keep_series = false;
  return endurance(b, power_w, s).energy_j;
}

Battery makeBattery(const BatteryPack& pack, int series, int parallel) {
  Battery b;
  b.pack = pack;
  b.series = series;
  b.parallel = parallel;
  validateBattery(b);
  return b;
}

std::pair<int, int> parseBatteryConfiguration(const std::string& text) {
  static const std::regex re(R"(^\s*(?:(\d+)\s*[sS])?\s*(?:(\d+)\s*[pP])?\s*$)");
  std::smatch m;
  if (text.empty() || !std::regex_match(text, m, re) || (!m[1].matched && !m[2].matched)) {
    throw std::invalid_argument("battery configuration '" + text + "', expected e.g. 2S, 2S2P or 3P");
  }
  const int s = m[1].matched ? std::stoi(m[1].str()) : 1;
  const int p = m[2].matched ? std::stoi(m[2].str()) : 1;
  if (s < 1 || p < 1 || s > 100 || p > 100) {
    throw std::invalid_argument("battery configuration '" + text + "': series and parallel must be in [1, 100]");
  }
  return {s, p};
}

double countedUsableLeft(const Battery& b, const BatterySample& s) {
  if (s.usable_left <= 0.0) return 0.0;  // the cut-off: nothing more can be drawn at that current
  const double c0 = b.capacityAh();
  const double drawn = (s.current_a > 0.0 ? peukertCapacityAh(b, s.current_a) : c0) - s.residual_ah;
  return std::min(1.0 - drawn / (b.pack.usable_fraction * c0), 1.0);
}

}  // namespace wattswath::energy
