#pragma once
/// @file diagnose.hpp
/// Learn which physical effect a model is missing and add it: bounded least-squares fits of
/// effect coefficients (Ceres, private), cross-validated ranking of candidate effects, before /
/// after comparisons on training and test logs, and simulated logs with hidden effects.

#include <memory>
#include <string>
#include <vector>

#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/calibration/replay.hpp"
#include "wattswath/calibration/residual_signals.hpp"

namespace wattswath::calibration {

/// The excitation a coefficient needs before the data can determine it (issue 19): a drag area
/// fitted on hover data only, or an effective mass on steady flight, is noise extrapolated, not a
/// measurement. An airborne sample offers the excitation when it is beyond these thresholds; a
/// coefficient is determined only when at least max(min_samples, min_fraction x airborne samples)
/// do. Otherwise it keeps the value it was given (the vehicle's physical value) and is not fitted.
struct ExcitationSettings {
  double drag_speed_mps = 3.0;        ///< [m/s] horizontal speed for drag area, wind, translational lift; 0..100
  double kinetic_power_m2ps3 = 1.0;   ///< [m^2/s^3] |v . a| for the kinetic effective mass; 0..1e4
  double climb_speed_mps = 0.5;       ///< [m/s] climb (descent) rate for climb_mass (descent_mass); 0..100
  double yaw_rate_radps = 0.3;        ///< [rad/s] |yaw rate| for yaw power; 0..100
  int min_samples = 20;               ///< [-] excited samples needed at least; >= 0
  double min_fraction = 0.02;         ///< [-] share of the airborne samples that must be excited; 0..1
};

/// Settings of a coefficient fit.
struct FitSettings {
  int max_samples = 4000;    ///< [samples] training samples used, evenly thinned above this; 100..1e6
  int max_iterations = 60;   ///< [-] Levenberg-Marquardt iterations; 1..1000
  double huber_w = 0.0;      ///< [W] Huber loss scale (0: plain least squares); 0..1e4
  ExcitationSettings excitation;  ///< what the data must offer for each coefficient to be fitted
};

/// A fitted coefficient with its uncertainty.
struct FittedCoefficient {
  std::string effect;    ///< effect name
  std::string name;      ///< coefficient name
  std::string unit;      ///< SI unit
  std::string meaning;   ///< plain-language meaning
  double value = 0.0;    ///< fitted value, in `unit`
  double sigma = 0.0;    ///< 1-sigma: Ceres covariance times residual variance times the residual's
                         ///< autocorrelation time (NaN if unknown)
  bool at_bound = false; ///< true when the fit stopped on a sign/range bound
  /// False when the data do not determine this coefficient: they lack the excitation it needs
  /// (ExcitationSettings; it then keeps the value it was given, the vehicle's physical value, and is
  /// not fitted), or the modelled power does not change with it at the fitted values (e.g. a wind
  /// speed once the drag area has gone to 0; its value is arbitrary). Its sigma is then NaN.
  bool determined = true;
  /// Why it is not determined, in words (empty when it is), e.g. "0 of 412 airborne samples faster
  /// than 3 m/s horizontally (20 needed): ...; kept at 0.0155 m^2, its starting value (...)".
  std::string why_not_determined;
  /// False when the coefficient was held at the value it was given for lack of excitation.
  bool fitted = true;
};

/// Result of fitting a model's coefficients.
struct FitResult {
  EnergyModel model;                            ///< the model with fitted coefficients
  std::vector<FittedCoefficient> coefficients;  ///< every coefficient of every effect, model order
  double train_rmse_w = 0.0;                    ///< [W] RMSE on the samples used by the fit
  int samples = 0;                              ///< samples used
  std::vector<std::string> notes;               ///< correlated coefficients, singular covariance, ...
  /// [samples] integrated autocorrelation time of the residual; the sigmas are the formal ones
  /// times sqrt(of it), since correlated samples carry less information than independent ones
  double autocorrelation_time = 1.0;
};

/// Samples of one prepared log taken into a fit or an evaluation.
struct SampleSet {
  const PreparedLog* log = nullptr;  ///< the log
  std::vector<int> index;            ///< sample indices (empty: all samples)
};

/// Fits every coefficient of `start` (its values are the initial guess) to the measured power
/// of `data` within the coefficients' bounds (Ceres Levenberg-Marquardt, central differences).
FitResult fitModel(const EnergyModel& start, const std::vector<SampleSet>& data, const FitSettings& s = {});

/// Settings of a diagnosis.
struct DiagnoseSettings {
  FitSettings fit;                   ///< fit settings
  int folds = 5;                     ///< [-] contiguous time blocks for one log, each held out in turn; 2..10
  double indistinct_correlation = 0.9;  ///< [-] two effects whose fitted power contributions
                                        ///< correlate above this cannot be told apart; 0..1
  std::vector<std::string> candidates;  ///< effects to try (empty: every known effect not in the model)
  /// User-defined effects (user_effect.hpp) tried as candidates too, after the built-in ones
  std::vector<std::shared_ptr<const energy::Effect>> extra_candidates;
  /// [-] an effect is kept only when its held-out likelihood ratio n_eff ln(MSE_before / MSE_after)
  /// exceeds the chi-square quantile at 1 - p_value for its number of coefficients; n_eff = n / tau
  /// with tau the autocorrelation time of the held-out residual with the effect (a stand-in that
  /// leaves a correlated residual counts fewer independent samples); 1e-9..0.1. 1e-3 per candidate
  /// is about 1 % per round of 7 candidates.
  double p_value = 1e-3;
  /// [-] ... and only when it removes at least this share of the held-out variance above the
  /// white noise (a stand-in that fits part of an unknown structure removes less); 0..1
  double min_excess_share = 0.5;
  int max_effects = 4;               ///< [-] rounds of the greedy search at most; 1..10
  SignatureSettings signatures;      ///< tests of the residual against the signal library
};

/// One candidate effect tried by the diagnosis.
struct CandidateResult {
  std::string effect;                           ///< effect name
  double rmse_w = 0.0;                          ///< [W] held-out sample RMSE with the effect added
  double improvement_pct = 0.0;                 ///< [%] held-out RMSE reduction against the refitted base
  double energy_error_pct = 0.0;                ///< [%] held-out whole-flight energy error
  double leg_energy_mape_pct = 0.0;             ///< [%] held-out leg-energy MAPE
  std::vector<FittedCoefficient> coefficients;  ///< the effect's coefficients fitted on all data
  std::string summary;                          ///< physical reading, e.g. "drag area 0.019 +- 0.002 m^2"
  std::vector<std::string> indistinct_from;     ///< candidates this one cannot be told apart from
  std::vector<std::string> notes;               ///< fit notes (correlations, bounds)
  /// [-] held-out likelihood ratio n_eff ln(MSE_before / MSE_after), n_eff = n / tau of the
  /// residual with the effect (DiagnoseSettings::p_value)
  double lr_statistic = 0.0;
  double lr_threshold = 0.0;  ///< [-] chi-square quantile it had to exceed
  double effective_samples = 0.0;  ///< [-] n / tau of the held-out residual with the effect
  double excess_share = 0.0;  ///< [-] share of the held-out variance above the white noise it removes
  bool kept = false;          ///< true when it passed the stopping rule (significant, explains, not at a bound)
  std::string why_not_kept;   ///< in words, when not kept
};

/// One step of the error staircase: a model and its held-out errors.
struct StaircaseStep {
  std::string label;     ///< e.g. "vehicle physics", "refit base", "+ translational_lift"
  ErrorMetrics metrics;  ///< held-out metrics (all data for the unfitted model)
};

/// [-] Share of the residual's variance a signal that is not significant must carry to be cited as a
/// lead of an "unexplained" verdict (at most three, strongest first).
inline constexpr double kMinLeadStrength = 0.05;

/// What the diagnosis found.
struct Diagnosis {
  std::string validation;                   ///< "leave-one-flight-out" or "5 contiguous time blocks"
  ErrorMetrics physics;                     ///< the model as given (vehicle physics), on all data
  ErrorMetrics baseline;                    ///< the model refitted, held-out
  std::vector<CandidateResult> candidates;  ///< first round, best first (largest held-out improvement)
  std::vector<StaircaseStep> staircase;     ///< physics -> refit -> + each found effect
  std::vector<LogReplay> physics_replay;    ///< the model as given, per log (for plots)
  std::vector<ResidualTable> residuals;     ///< residual tables of the model as given
  /// "missing_effect" (found effects leave no structure), "nothing_missing" (no effect kept, no
  /// structure), "unexplained" (a structure remains that no candidate explains) or "cannot_tell"
  /// (too few independent samples, no signal could be tested, or nothing found among the
  /// candidates tested while others could not be tested: no verdict)
  std::string verdict;
  std::vector<CandidateResult> found;       ///< the kept effects in the order they were added
  std::vector<std::string> search;          ///< the greedy search step by step, in words
  double noise_w = 0.0;                     ///< [W] white noise of the data (successive differences)
  double autocorrelation_time = 1.0;        ///< [samples] of the refitted model's residual
  double final_rmse_w = 0.0;                ///< [W] in-sample RMSE with the found effects fitted
  ErrorMetrics final_heldout;               ///< held-out metrics with the found effects
  /// The residual (measured - modelled, found effects fitted) against the signal library,
  /// strongest significant first
  std::vector<ResidualSignature> signatures;
  std::vector<std::vector<double>> final_power;  ///< [W] per log, the model with the found effects
  /// The effects of the final model, in order: the set `fit --effects` accepts (wind replaces
  /// parasitic_drag, being drag at air speed, so the two never appear together)
  std::vector<std::string> final_effects;
  std::string conclusion;                   ///< the verdict in one or two sentences
  /// Candidates these data cannot test (none of their coefficients could be fitted), each as
  /// "effect: why" (e.g. "wind: 0 of 278 airborne samples faster than 3 m/s ..."): a verdict of
  /// nothing missing is then "cannot_tell"
  std::vector<std::string> untested;
};

/// Greedy search with a stopping rule (issue 18): each round tries the effects not in the model,
/// fitted together with it; the one with the largest held-out improvement is kept when that
/// improvement is significant against the residual's own noise and correlation (block bootstrap),
/// removes most of the variance above the white noise and has no coefficient at a bound; then
/// each earlier kept effect is tried without (or replaced by a simpler significant candidate)
/// and removed when it no longer matters. The residual of the final model is tested against the
/// signal library. Validation: leave-one-flight-out with two or more logs, contiguous time blocks
/// with one (an effect switching on or off at a time stays fair).
Diagnosis diagnose(const EnergyModel& model, const Vehicle& v, const std::vector<PreparedLog>& logs,
                   const DiagnoseSettings& s = {});

/// Before / after comparison of a fit.
struct FitReport {
  FitResult fit;                ///< the fit on the training logs
  ErrorMetrics train_before;    ///< model as given, training logs
  ErrorMetrics train_after;     ///< fitted model, training logs
  ErrorMetrics test_before;     ///< model as given, test logs (empty when none)
  ErrorMetrics test_after;      ///< fitted model, test logs
  std::vector<LogReplay> train_replay;  ///< fitted model per training log (for plots)
  std::vector<LogReplay> test_replay;   ///< fitted model per test log
};

/// Fits `model` on `train` and compares before/after on `train` and `test`.
FitReport fitAndCompare(const EnergyModel& model, const std::vector<PreparedLog>& train,
                        const std::vector<PreparedLog>& test, const FitSettings& s = {});

/// A plain-language reading of an effect's fitted coefficients, e.g.
/// "wind 4.2 +- 0.3 m/s towards 300 deg" or "payload 0.35 kg released at t = 148 s".
std::string describeEffect(const std::string& effect, const std::vector<FittedCoefficient>& c);

/// Settings of a simulated flight.
struct SimulationSettings {
  double rate_hz = 10.0;           ///< [Hz] sample rate; 0.1..1000
  double cruise_speed = 8.0;       ///< [m/s] horizontal cruise speed; 0.5..40
  double vertical_speed = 2.0;     ///< [m/s] speed of vertical legs; 0.2..10
  double acceleration = 1.0;       ///< [m/s^2] acceleration and braking; 0.1..10
  double yaw_rate = 1.0;           ///< [rad/s] turn-in-place rate at corners (0: no turns); 0..5
  double hover_s = 3.0;            ///< [s] hover before the first and after the last leg; 0..600
  double power_noise_w = 5.0;      ///< [W] standard deviation of power noise; 0..1000
  double velocity_noise_mps = 0.05;  ///< [m/s] standard deviation of velocity noise; 0..10
  double voltage_start_v = 12.4;   ///< [V] battery voltage at the start (linear sag); 1..1000
  double voltage_end_v = 11.2;     ///< [V] battery voltage at the end
  unsigned seed = 1;               ///< random seed (fixed: same log every time)
  double max_samples = 2e6;        ///< [-] refuse flights needing more samples (about 400 MB of CSV, 1 GB of memory); 1..1e9
};

/// A canonical log of `truth` flown through `waypoints` (ENU [m]): at each waypoint the vehicle
/// stops, turns in place to the next leg, then flies it with accelerate / cruise / brake pieces
/// (buildLegProfile). Power is the model's plus Gaussian noise; velocity gets Gaussian noise;
/// current = power / voltage. format = "simulated"; the hidden effects are not written.
/// Throws std::invalid_argument for fewer than 2 waypoints, a non-finite waypoint, or a flight
/// needing more than `s.max_samples` samples (instead of running out of memory).
FlightLog simulateFlight(const std::vector<Eigen::Vector3d>& waypoints, const EnergyModel& truth,
                         const SimulationSettings& s = {});

}  // namespace wattswath::calibration
