#pragma once
/// @file effect.hpp
/// Physical effects: each one source of electrical power draw, with named coefficients that
/// depend only on the vehicle, a power at an instant and an energy over a constant-acceleration
/// piece (closed form where one exists, Gauss-Legendre quadrature otherwise).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wattswath/energy/profile.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::energy {

/// A named coefficient of an effect, with unit, physical bounds and meaning (for fitting and reports).
struct Coefficient {
  std::string name;     ///< identifier, e.g. "drag_area"
  double value = 0.0;   ///< current value, in `unit`
  std::string unit;     ///< SI unit, e.g. "m^2"
  double lower = 0.0;   ///< smallest physically allowed value, in `unit` (sign constraint)
  double upper = 1e9;   ///< largest physically allowed value, in `unit`
  std::string meaning;  ///< plain-language meaning, e.g. "drag area C_D A of the airframe"
};

/// Partial derivatives of an effect's energy over one piece with respect to the piece's free
/// parameters (duration follows from them: 2 L / (v0 + v1) for pieces of non-zero length).
struct PieceEnergyGradient {
  double length = 0.0;    ///< [J/m] dE / d length
  double v_start = 0.0;   ///< [J s/m] dE / d v_start
  double v_end = 0.0;     ///< [J s/m] dE / d v_end
  double v_cruise = 0.0;  ///< [J s/m] dE / d v_cruise (only the paper's drag approximation uses it)
  double climb = 0.0;     ///< [J/m] dE / d climb
};

/// One physical term of the power model.
class Effect {
 public:
  virtual ~Effect() = default;
  /// Stable identifier used in breakdowns, JSON and the CLI ("hover", "kinetic", ...).
  virtual std::string name() const = 0;
  /// One sentence on what physical effect this is.
  virtual std::string meaning() const = 0;
  /// Electrical power drawn at one instant [W].
  virtual double power(const MotionState& s) const = 0;
  /// Electrical energy over piece `p` [J]. Default: 8-point Gauss-Legendre quadrature of power().
  virtual double energy(const Piece& p) const;
  /// Closed-form partial derivatives of energy(p) for pieces of non-zero length; std::nullopt when
  /// the effect has none (callers then difference energy() numerically). Default: std::nullopt.
  virtual std::optional<PieceEnergyGradient> energyGradient(const Piece& p) const;
  /// A deep copy.
  virtual std::unique_ptr<Effect> clone() const = 0;

  /// The coefficients, in a fixed order.
  const std::vector<Coefficient>& coefficients() const { return coeffs_; }
  /// Sets coefficient values in the order of coefficients(); throws on size mismatch.
  void setCoefficientValues(const std::vector<double>& values);
  /// Value of the coefficient named `name`; throws std::out_of_range when absent.
  double coefficient(const std::string& name) const;

 protected:
  std::vector<Coefficient> coeffs_;  ///< owned by the effect, read by power()/energy()
};

/// Quadrature of `e.power` over piece `p` with `points` Gauss-Legendre nodes per piece [J].
double integratePower(const Effect& e, const Piece& p, int points = 8);

/// Hover: momentum-theory rotor power over total efficiency while airborne, P = P_hov
/// (Marins Eq. 1-5). Coefficient "hover_power" [W].
class HoverEffect final : public Effect {
 public:
  /// Hover effect with electrical hover power `p_hover_w` [W].
  explicit HoverEffect(double p_hover_w);
  /// Hover effect with the vehicle's Marins Eq. 5 hover power.
  static HoverEffect fromVehicle(const Vehicle& v);
  std::string name() const override { return "hover"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  double energy(const Piece& p) const override;
  std::optional<PieceEnergyGradient> energyGradient(const Piece& p) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<HoverEffect>(*this); }
};

/// Kinetic: the work of changing speed, paid when accelerating and again when braking
/// (non-regenerative, as Marins Eq. 6 counts it), P = m_eff |v . a|.
/// Coefficient "effective_mass" = m / eta_tot [kg].
class KineticEffect final : public Effect {
 public:
  /// Kinetic effect with effective mass `m_eff_kg` = m / eta [kg].
  explicit KineticEffect(double m_eff_kg);
  /// Kinetic effect with the vehicle's m / eta_tot.
  static KineticEffect fromVehicle(const Vehicle& v);
  std::string name() const override { return "kinetic"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  double energy(const Piece& p) const override;
  std::optional<PieceEnergyGradient> energyGradient(const Piece& p) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<KineticEffect>(*this); }
};

/// How the parasitic-drag energy of a piece is integrated.
enum class DragIntegration {
  Exact,            ///< integral of v^3 dt over the piece (default)
  PaperCruiseSpeed  ///< Marins Eq. 9: the leg's cruise speed over the whole distance
};

/// Parasitic drag: P = rho/2 * CdA * v^3 / eta_tot (Marins Eq. 8-9), v the ground speed.
/// Coefficient "drag_area" = C_D A [m^2]; rho and eta come from the vehicle.
class ParasiticDragEffect final : public Effect {
 public:
  /// Drag effect with drag area `cda_m2` [m^2], air density `rho` [kg/m^3], efficiency `eta` [-].
  ParasiticDragEffect(double cda_m2, double rho, double eta, DragIntegration mode = DragIntegration::Exact);
  /// Drag effect with the vehicle's drag area, density and total efficiency.
  static ParasiticDragEffect fromVehicle(const Vehicle& v, DragIntegration mode = DragIntegration::Exact);
  std::string name() const override { return "parasitic_drag"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  double energy(const Piece& p) const override;
  std::optional<PieceEnergyGradient> energyGradient(const Piece& p) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<ParasiticDragEffect>(*this); }
  /// The integration mode.
  DragIntegration mode() const { return mode_; }
  /// rho/2 * C_D A / eta_tot: electrical drag power over v^3 [kg/m].
  double powerCoefficient() const { return 0.5 * rho_ * coeffs_[0].value / eta_; }

 private:
  double rho_;
  double eta_;
  DragIntegration mode_;
};

/// Extra power while yawing, P = k |yaw rate| (Marins Eq. 14 takes k = 0: a turn in place
/// costs hover power for (pi - beta)/omega_max, which the hover effect already counts).
/// Coefficient "yaw_power" [W s/rad].
class YawRateEffect final : public Effect {
 public:
  /// Yaw effect with `k` [W s/rad].
  explicit YawRateEffect(double k = 0.0);
  std::string name() const override { return "yaw_rate"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  double energy(const Piece& p) const override;
  std::optional<PieceEnergyGradient> energyGradient(const Piece& p) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<YawRateEffect>(*this); }
};

}  // namespace wattswath::energy
