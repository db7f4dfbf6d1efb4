#pragma once
// Internal to calibration/src: the excitation a coefficient needs before data can determine it
// (issue 19): speed for drag and wind, speed times acceleration for the kinetic term, climbs and
// descents for climb, yaw rate for yaw power. Used by fit.cpp.
#include <string>
#include <vector>

#include "wattswath/calibration/diagnose.hpp"

namespace wattswath::calibration::detail {

/// How much of the excitation a coefficient needs a set of samples offers.
struct Excitation {
  bool rule = false;   ///< false: the coefficient has no excitation rule (only the covariance judges it)
  int excited = 0;     ///< [-] airborne samples offering the excitation
  int required = 0;    ///< [-] samples needed: max(min_samples, min_fraction x airborne samples)
  int airborne = 0;    ///< [-] airborne samples looked at
  std::string what;    ///< the excitation, e.g. "faster than 3 m/s horizontally"
  std::string why;     ///< why it is needed, e.g. "drag power grows with the speed cubed"

  /// True when the samples offer enough of the excitation (or there is no rule).
  bool enough() const { return !rule || excited >= required; }
};

/// The excitation `effect`.`coefficient` needs and how much of it `states` offer.
Excitation excitationOf(const std::string& effect, const std::string& coefficient,
                        const std::vector<const MotionState*>& states, const ExcitationSettings& s);

/// Throws std::invalid_argument naming the field, its value and the range when out of range.
void validate(const ExcitationSettings& s);

}  // namespace wattswath::calibration::detail
