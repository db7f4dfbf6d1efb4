#pragma once
/// @file user_effect.hpp
/// A user-defined effect (issue 18): electrical power from a formula of the motion and vehicle
/// variables with named, bounded coefficients, read from a JSON model file, fitted and diagnosed
/// like the built-in effects. The formula is parsed by muparser (private to calibration/src), so
/// the effect lives here rather than in energy/ (whose headers stay free of heavy dependencies).
///
/// File: {"effects": [{"name": "motor_heating", "meaning": "...", "power": "k * hover_power * (1 - exp(-t / tau))",
///   "coefficients": [{"name": "k", "unit": "-", "value": 0.02, "lower": 0, "upper": 0.5, "meaning": "..."}, ...]}]}
/// Variables of the formula: t [s], speed [m/s] (horizontal), vx, vy, vz [m/s], climb_rate [m/s],
/// accel [m/s^2] (|a|), ax, ay, az [m/s^2], yaw_rate [rad/s], heading [rad], airborne (0 or 1),
/// mass [kg], g [m/s^2], hover_power [W] (the vehicle's momentum-theory hover power), and the
/// coefficients by name. The power is added to the model's while airborne.

#include <memory>
#include <string>
#include <vector>

#include "wattswath/energy/effect.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::calibration {

/// What a user-defined effect is: its name, formula and coefficients.
struct FormulaEffectSpec {
  std::string name;     ///< effect name, an identifier not used by a built-in effect
  std::string meaning;  ///< one sentence on the physical effect
  std::string power;    ///< [W] formula of the power drawn (muparser syntax)
  std::vector<energy::Coefficient> coefficients;  ///< named coefficients with units and bounds (value = start)
  std::string source;   ///< file it was read from (for messages)
};

/// Names of the variables a formula may use, in the order of user_effect.hpp's list.
const std::vector<std::string>& formulaVariables();

/// The effect of `spec` for vehicle `v` (mass, g and hover power from its physics). Throws
/// std::invalid_argument naming the source, the field and the value when the formula does not parse
/// (with muparser's message and position), uses an unknown variable, or is not finite at hover.
std::unique_ptr<energy::Effect> makeFormulaEffect(const FormulaEffectSpec& spec, const energy::Vehicle& v);

/// The effects of a JSON model file (an object with "effects": [...], or one effect object).
/// Throws std::invalid_argument naming the file, the field (e.g. effects[0].coefficients[1].lower),
/// the value and what was expected.
std::vector<FormulaEffectSpec> parseEffectFile(const std::string& text, const std::string& source);

/// A model of the named effects: built-in names from vehicle physics (energy::buildModel), then the
/// user-defined ones of `user` named in `names`, in order. Throws std::invalid_argument for a name
/// that is neither, listing both kinds.
energy::EnergyModel buildModelWith(const energy::Vehicle& v, const std::vector<std::string>& names,
                                   const std::vector<FormulaEffectSpec>& user);

/// Largest effect model file read [B] (read whole).
inline constexpr long long kMaxEffectFileBytes = 16LL * 1024 * 1024;

/// parseEffectFile of the file at `path`; throws std::runtime_error when it cannot be read or is
/// over kMaxEffectFileBytes.
std::vector<FormulaEffectSpec> readEffectFile(const std::string& path);

}  // namespace wattswath::calibration
