#pragma once
// How far a calibrated prediction could be off, from what the calibration itself knows: the
// flights disagreed on a parameter (Dispute), or the mission asks for flying the calibration
// flights never did (Coverage). `predict` says both in words and JSON and widens its margin.
#include <optional>
#include <string>
#include <vector>

#include "prediction_setup.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/predict.hpp"

namespace wattswath::apps {

/// The mission flown with each extreme of a parameter the calibration's flights disagreed on.
struct Dispute {
  std::string parameter;  ///< the disputed parameter (PredictionSetup::disputed_parameter)
  double lo = 0.0, hi = 0.0;  ///< the flights' own values [the parameter's unit]
  double energy_lo_j = 0.0, energy_hi_j = 0.0;  ///< [J] the mission's energy with either value
  double time_lo_s = 0.0, time_hi_s = 0.0;      ///< [s] the mission's time with either value
};

/// The dispute of `setup` flown on `m`, or nothing when its flights agreed.
std::optional<Dispute> disputeOf(const mission::Mission& m, const energy::Vehicle& v, const PredictionSetup& setup);

/// The disputed parameter's value fitted on the calibration flights of the mission's kind: when
/// the flights disagreed and some of them (not all) flew missions the mission is inside of
/// (calibration::outsideCalibration empty), their values' mean; they fitted how the vehicle flies
/// this kind of mission, the joint value a mix of kinds.
struct KindChoice {
  double value = 0.0;                ///< [the parameter's unit]
  std::vector<std::string> flights;  ///< the calibration flights it comes from
};

/// The choice for a mission of `kind` (calibration::missionKind) under `setup`, or nothing (no
/// dispute, no recorded kinds, or no flight, or every flight, of the mission's kind).
std::optional<KindChoice> kindChoiceOf(const calibration::MissionKind& kind, const PredictionSetup& setup);

/// One sentence on the dispute, relative to prediction `p` (made with `choice` when there is one).
std::string disputeText(const Dispute& d, const mission::MissionPrediction& p, const std::optional<KindChoice>& choice);

/// The mission is outside what the calibration flew: it is also flown with the behaviour before the
/// calibration (the fitted parameters' starting values, no calibrated take-off delay, corner rule
/// or tracking error; the calibrated energy model kept).
struct Coverage {
  std::vector<std::string> reasons;  ///< why it is outside (calibration::outsideCalibration)
  double energy_j = 0.0;             ///< [J] flown with the behaviour before the calibration
  double time_s = 0.0;               ///< [s] likewise
};

/// The coverage check of `setup` on `m` (of `kind`, calibration::missionKind): nothing when
/// uncalibrated, inside, or the calibration recorded no coverage (files before 2026-11-25).
std::optional<Coverage> coverageOf(const mission::Mission& m, const calibration::MissionKind& kind, const energy::Vehicle& v,
                                   const PredictionSetup& setup);

/// One sentence on the coverage, relative to prediction `p`.
std::string coverageText(const Coverage& c, const mission::MissionPrediction& p);

}  // namespace wattswath::apps
