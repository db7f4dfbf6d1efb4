// The excitation each fitted coefficient needs before the data can determine it (issue 19).
#include "excitation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "number_text.hpp"
#include "wattswath/energy/format.hpp"

namespace wattswath::calibration::detail {
namespace {

using Test = std::function<bool(const MotionState&)>;

struct Rule {
  std::string what, why;
  Test excited;
};

// The rule of `effect`.`coefficient`; `what` empty when there is none.
Rule ruleOf(const std::string& effect, const std::string& c, const ExcitationSettings& s) {
  const double v = s.drag_speed_mps, va = s.kinetic_power_m2ps3, vz = s.climb_speed_mps, yr = s.yaw_rate_radps;
  auto fast = [v](const MotionState& m) { return m.velocity.head<2>().norm() >= v; };
  const std::string fast_what = "faster than " + num(v) + " m/s horizontally";
  if ((effect == "parasitic_drag" && c == "drag_area") || effect == "wind") {
    return {fast_what, "drag power grows with the air speed cubed, so only fast flight separates it from hover power", fast};
  }
  if (effect == "translational_lift") {
    return {fast_what, "the induced power falls with forward speed, so only fast flight shows it", fast};
  }
  if (effect == "kinetic" && c == "effective_mass") {
    return {"with |v . a| of at least " + num(va) + " m^2/s^3 (speeding up or braking)",
            "the kinetic power is m_eff |v . a|, so only speed changes show it",
            [va](const MotionState& m) { return std::abs(m.velocity.dot(m.acceleration)) >= va; }};
  }
  if (effect == "climb" && c == "climb_mass") {
    return {"climbing at " + num(vz) + " m/s or faster", "the climb power is proportional to the climb rate",
            [vz](const MotionState& m) { return m.velocity.z() >= vz; }};
  }
  if (effect == "climb" && c == "descent_mass") {
    return {"descending at " + num(vz) + " m/s or faster", "the power saved is proportional to the descent rate",
            [vz](const MotionState& m) { return m.velocity.z() <= -vz; }};
  }
  if (effect == "yaw_rate" && c == "yaw_power") {
    return {"yawing at " + num(yr) + " rad/s or faster", "the yaw power is proportional to the yaw rate",
            [yr](const MotionState& m) { return std::abs(m.yaw_rate) >= yr; }};
  }
  return {};
}

}  // namespace

Excitation excitationOf(const std::string& effect, const std::string& coefficient,
                        const std::vector<const MotionState*>& states, const ExcitationSettings& s) {
  Excitation e;
  const Rule r = ruleOf(effect, coefficient, s);
  if (r.what.empty()) return e;
  e.rule = true;
  e.what = r.what;
  e.why = r.why;
  for (const MotionState* m : states) {
    if (!m->airborne) continue;
    ++e.airborne;
    if (r.excited(*m)) ++e.excited;
  }
  e.required = std::max(s.min_samples, static_cast<int>(std::ceil(s.min_fraction * e.airborne)));
  return e;
}

void validate(const ExcitationSettings& s) {
  using energy::detail::checkSettingRange;
  const double inf = std::numeric_limits<double>::infinity();
  checkSettingRange("ExcitationSettings", "drag_speed_mps", s.drag_speed_mps, 0.0, 100.0);
  checkSettingRange("ExcitationSettings", "kinetic_power_m2ps3", s.kinetic_power_m2ps3, 0.0, 1e4);
  checkSettingRange("ExcitationSettings", "climb_speed_mps", s.climb_speed_mps, 0.0, 100.0);
  checkSettingRange("ExcitationSettings", "yaw_rate_radps", s.yaw_rate_radps, 0.0, 100.0);
  checkSettingRange("ExcitationSettings", "min_samples", s.min_samples, 0.0, inf);
  checkSettingRange("ExcitationSettings", "min_fraction", s.min_fraction, 0.0, 1.0);
}

}  // namespace wattswath::calibration::detail
