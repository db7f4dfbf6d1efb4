#pragma once
/// @file model.hpp
/// An energy model: a sum of physical effects, evaluated over speed profiles (closed form per
/// piece) or at motion states (for logs), with the energy per effect and per phase.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "wattswath/energy/effect.hpp"
#include "wattswath/energy/profile.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::energy {

/// Energy split by effect and by phase, and the time it took.
struct Breakdown {
  std::vector<std::string> effects;                    ///< effect names, in model order
  std::vector<std::array<double, kPhaseCount>> energy;  ///< [J] energy[effect][phase]
  double time = 0.0;                                    ///< [s] total time
  double length = 0.0;                                  ///< [m] total distance

  /// Total energy [J].
  double total() const;
  /// Energy of effect `name` over all phases [J] (0 when the model has no such effect).
  double byEffect(const std::string& name) const;
  /// Energy of all effects in phase `p` [J].
  double byPhase(Phase p) const;
  /// Energy of effect `name` in phase `p` [J].
  double at(const std::string& name, Phase p) const;
  /// Adds another breakdown with the same effects (throws std::invalid_argument otherwise).
  Breakdown& operator+=(const Breakdown& other);
};

/// A sum of effects. Copyable (effects are deep-copied).
class EnergyModel {
 public:
  EnergyModel() = default;
  EnergyModel(const EnergyModel& other);
  EnergyModel& operator=(const EnergyModel& other);
  EnergyModel(EnergyModel&&) noexcept = default;
  EnergyModel& operator=(EnergyModel&&) noexcept = default;

  /// Appends an effect; throws std::invalid_argument if one with the same name is present.
  EnergyModel& add(std::unique_ptr<Effect> effect);
  /// Appends a copy of `effect`.
  template <class E>
  EnergyModel& add(const E& effect) { return add(effect.clone()); }
  /// Removes the effect named `name` (no-op when absent).
  EnergyModel& remove(const std::string& name);
  /// Whether an effect named `name` is present.
  bool has(const std::string& name) const;
  /// The effect named `name`; throws std::out_of_range when absent.
  Effect& effect(const std::string& name);
  /// The effect named `name`; throws std::out_of_range when absent.
  const Effect& effect(const std::string& name) const;
  /// Effects in order.
  const std::vector<std::unique_ptr<Effect>>& effects() const { return effects_; }
  /// Names of the effects in order.
  std::vector<std::string> effectNames() const;

  /// Total electrical power at one instant [W].
  double power(const MotionState& s) const;
  /// Total energy of a profile [J] (no breakdown: the fast path).
  double energy(const std::vector<Piece>& pieces) const;
  /// Energy of a profile split by effect and phase.
  Breakdown evaluate(const std::vector<Piece>& pieces) const;
  /// Adds the energy of `pieces` into `out` (which must have this model's effects).
  void accumulate(const std::vector<Piece>& pieces, Breakdown& out) const;
  /// An empty breakdown with this model's effects.
  Breakdown emptyBreakdown() const;

  /// Steady level-flight power at ground speed `v` [m/s] heading `heading` [rad] [W].
  double levelPower(double v, double heading = 0.0) const;
  /// A lower bound on energy per metre of level flight over speeds in (0, v_max] [J/m],
  /// min over v of levelPower(v)/v on a fine grid minus a safety margin; admissible for search.
  double minEnergyPerMetre(double v_max) const;

 private:
  std::vector<std::unique_ptr<Effect>> effects_;
};

/// The closed-form model of Marins, Cabreira & Ferreira: hover + kinetic + parasitic drag
/// (+ zero-cost yaw), with coefficients from the vehicle.
EnergyModel marinsModel(const Vehicle& v, DragIntegration drag = DragIntegration::Exact);

}  // namespace wattswath::energy
