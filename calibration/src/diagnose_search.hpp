#pragma once
// The held-out validation and the greedy search of diagnose() (issue 18): contiguous-block or
// leave-one-flight-out folds, held-out residuals, and the stopping rule.
#include <string>
#include <vector>

#include "wattswath/calibration/diagnose.hpp"

namespace wattswath::calibration::detail {

/// Training and test sample sets of each fold.
struct Folds {
  std::vector<std::vector<SampleSet>> train;  ///< per fold
  std::vector<std::vector<SampleSet>> test;   ///< per fold
  std::string label;                          ///< e.g. "5 contiguous time blocks"
};

/// Leave-one-flight-out with two or more logs, else `s.folds` contiguous time blocks of the one log.
Folds makeFolds(const std::vector<PreparedLog>& logs, const DiagnoseSettings& s);

/// A model evaluated: held-out predictions and the fit on all data.
struct Evaluation {
  std::vector<std::string> added;        ///< effects added to the diagnosed model, in order
  EnergyModel start;                     ///< the model before fitting
  ErrorMetrics heldout;                  ///< held-out metrics
  std::vector<double> heldout_residual;  ///< [W] held-out modelled - measured, all logs in order
  FitResult full;                        ///< fitted on all data
};

/// Evaluates `start` (the diagnosed model plus `added`) by the folds and a fit on all data.
Evaluation evaluate(const EnergyModel& start, const std::vector<std::string>& added, const std::vector<PreparedLog>& logs,
                    const Folds& folds, const FitSettings& fs);

/// Held-out likelihood ratio of `better` over `base`: n_eff ln(MSE_base / MSE_better) with
/// n_eff = n / tau of better's held-out residual [-]; `n_eff` receives n_eff.
double likelihoodRatio(const Evaluation& base, const Evaluation& better, double* n_eff = nullptr);

/// The diagnosed model plus `added` (each from vehicle physics, withCandidate order, or a copy of
/// the user-defined effect of that name in `extra`).
EnergyModel withEffects(const EnergyModel& model, const std::vector<std::string>& added, const Vehicle& v,
                        const std::vector<std::shared_ptr<const energy::Effect>>& extra = {});

/// The greedy search: fills d.candidates (first round), d.found, d.search and d.staircase; returns
/// the final evaluation. `noise_w` is the white noise of the data [W].
Evaluation searchEffects(const EnergyModel& model, const Vehicle& v, const std::vector<PreparedLog>& logs,
                         const Folds& folds, const DiagnoseSettings& s, double noise_w, const Evaluation& base,
                         Diagnosis& d);

}  // namespace wattswath::calibration::detail
