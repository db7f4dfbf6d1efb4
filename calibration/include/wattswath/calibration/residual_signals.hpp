#pragma once
/// @file residual_signals.hpp
/// What a residual keeps when no candidate effect explains it (issue 18): the residual
/// (measured - modelled power) tested against a library of signals - time since take-off,
/// state of charge, current squared, power squared, rate of change of power, altitude, height,
/// speed, speed squared, acceleration, climb rate, yaw rate, heading - with tests that respect the
/// correlation in time of both series, and a plain sentence of what kinds of effect leave each
/// signature.

#include <string>
#include <vector>

#include "wattswath/calibration/replay.hpp"

namespace wattswath::calibration {

/// Settings of the signature tests.
struct SignatureSettings {
  int bins = 10;                  ///< [-] quantile bins of the binned (nonlinear) test; 3..50
  double p_value = 1e-4;          ///< [-] false-alarm probability of each test (13 signals x 2 forms); 1e-12..0.1
  double min_strength = 0.02;     ///< [-] smallest share of the residual's variance worth naming; 0..1
  double same_correlation = 0.98; ///< [-] |correlation| above which two signals cannot be told apart; 0..1
};

/// One bin of a residual-versus-signal curve (for plots).
struct SignatureBin {
  double lo = 0.0;          ///< lower edge, in the signal's unit
  double hi = 0.0;          ///< upper edge, in the signal's unit
  int count = 0;            ///< samples in the bin
  double residual_w = 0.0;  ///< [W] mean residual measured - modelled in the bin
};

/// How much of the residual one signal carries.
struct ResidualSignature {
  std::string signal;         ///< "time", "state_of_charge", "current_squared", "power_squared", "power_rate",
                              ///< "altitude", "height", "speed", "speed_squared", "acceleration",
                              ///< "climb_rate", "yaw_rate" or "heading"
  std::string unit;           ///< unit of the signal, e.g. "s", "A^2", "W/s"
  double strength = 0.0;      ///< [-] share of the residual's variance it explains, bias 1/n_eff removed
  std::string form;           ///< "linear" (straight-line fit; cos/sin for heading) or "binned" (quantile bins)
  double slope = 0.0;         ///< [W per signal unit] straight-line slope of the residual (linear form)
  double statistic = 0.0;     ///< [-] n_eff x explained share, chi-square distributed without a relation
  double threshold = 0.0;     ///< [-] chi-square quantile at 1 - p_value for the form's degrees of freedom
  double effective_samples = 0.0;  ///< [-] n_eff of the pair (Bartlett, from both autocorrelations)
  bool significant = false;   ///< statistic > threshold and strength >= min_strength
  std::vector<std::string> same_as;  ///< signals these data cannot tell from this one (|r| > same_correlation)
  std::string sentence;       ///< what kinds of effect leave this signature, in words
  std::vector<SignatureBin> bins;    ///< residual against the signal, for plots
};

/// The residual measured - `modelled` (per log, per sample [W]) of `logs` against every signal
/// the logs allow (current squared, the modelled power over the logged voltage squared, needs a
/// logged voltage), strongest significant
/// first, signals that cannot be told apart merged into the stronger one's `same_as`.
/// `model_columns` (optional): the fitted model's sensitivity to each of its coefficients [W per
/// coefficient unit], one column over all samples of all logs in order. When given, each signal's
/// straight-line test is an added-variable test: the signal and the residual are first cleared of
/// what a constant and those columns explain, so a signal scores only what refitting the model
/// with it added could explain (a climb effect that absorbed part of I^2 R no longer hands the rest
/// to the signal that tracks it only roughly, such as time).
std::vector<ResidualSignature> residualSignatures(const std::vector<PreparedLog>& logs,
                                                  const std::vector<std::vector<double>>& modelled,
                                                  const SignatureSettings& s = {},
                                                  const std::vector<std::vector<double>>& model_columns = {});

/// Names of every signal residualSignatures tests, in its order.
const std::vector<std::string>& signalNames();

/// What `signal` is, as an axis label: "share of this log's energy still to be drawn" for
/// "state_of_charge" (1 - energy drawn / the log's energy, not the pack's state of charge), else its
/// name with spaces ("climb rate").
std::string signalLabel(const std::string& signal);

/// What kinds of effect leave a residual that follows `signal`, e.g. "rises with current squared:
/// resistive loss in the battery or wiring (I^2 R)"; `rises` says the sign of the relation.
std::string signatureSentence(const std::string& signal, bool rises);

}  // namespace wattswath::calibration
