#pragma once
/// @file diagnose_output.hpp
/// What `diagnose` prints: its JSON contract (issue 6 keys plus issue 18's verdict, found and
/// signatures) and the same in words.

#include <nlohmann/json.hpp>

#include "wattswath/calibration/diagnose.hpp"

namespace wattswath::apps {

/// verdict, conclusion, found, signatures, candidates, staircase, search, noise_w, final (the
/// model with the found effects) and the stopping rule as JSON.
nlohmann::json diagnosisJson(const calibration::Diagnosis& d);

/// The diagnosis in words on stdout: verdict, found effects, the residual's signatures, the
/// search and the candidates of the first round.
void printDiagnosis(const calibration::Diagnosis& d);

}  // namespace wattswath::apps
