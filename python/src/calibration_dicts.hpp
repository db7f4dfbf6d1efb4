#pragma once
/// @file calibration_dicts.hpp
/// The calibration library's results as Python dicts (NumPy arrays for per-bin values).
#include "bindings.hpp"
#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/calibration/replay.hpp"

namespace wattswath::python {

/// measured_j, modelled_j, time_s, error_pct of an energy comparison.
py::dict compareDict(const calibration::EnergyCompare& c);
/// samples, rmse_w, energy_error_pct, leg_energy_mape_pct and per-phase errors.
py::dict metricsDict(const calibration::ErrorMetrics& e);
/// {quantity: {unit, lo, hi, count, measured_mean_w, modelled_mean_w, residual_w}} with arrays.
py::dict residualTablesDict(const std::vector<calibration::ResidualTable>& tables);
/// Fitted coefficients as a list of dicts (effect, name, unit, value, sigma, determined, ...).
py::list fittedList(const std::vector<calibration::FittedCoefficient>& c);
/// A diagnosis: validation, physics, baseline, candidates (best first), staircase.
py::dict diagnosisDict(const calibration::Diagnosis& d);
/// A fit report: model, coefficients, before / after metrics, replays, notes.
py::dict fitReportDict(const calibration::FitReport& r);

}  // namespace wattswath::python
