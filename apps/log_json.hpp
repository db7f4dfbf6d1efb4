#pragma once
/// @file log_json.hpp
/// JSON and text pieces shared by the log commands replay, diagnose and fit (apps/cmd_logs.cpp).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "wattswath/calibration/diagnose.hpp"

namespace wattswath::apps {

/// Error metrics as JSON: samples, rmse_w, energy_error_pct, leg_energy_mape_pct, phases.
nlohmann::json metricsJson(const calibration::ErrorMetrics& m);

/// Residual tables as JSON: {"quantity": {"unit", "bins": [...]}}.
nlohmann::json residualsJson(const std::vector<calibration::ResidualTable>& tables);

/// Per-flight energies of replays as a JSON array.
nlohmann::json flightsJson(const std::vector<calibration::LogReplay>& reps);

/// {"effect": {"coef": value}}, or the same shape with the sigmas (null when unknown) when `sigma`.
nlohmann::json coefficientsJson(const std::vector<calibration::FittedCoefficient>& cs, bool sigma);

/// {"effect": {"coef": {"determined", "fitted", "at_bound", "why_not_determined"}}}.
nlohmann::json identifiabilityJson(const std::vector<calibration::FittedCoefficient>& cs);

/// Prints "LABEL: sample RMSE ... W, whole-flight energy error ... %, leg-energy MAPE ... %" on stdout.
void printMetrics(const std::string& label, const calibration::ErrorMetrics& m);

}  // namespace wattswath::apps
