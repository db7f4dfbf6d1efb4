// How far a calibrated prediction could be off, from what its calibration knows (predict_spread.hpp).
#include "predict_spread.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "wattswath/report/svg.hpp"

namespace wattswath::apps {
namespace {

namespace ms = wattswath::mission;

std::string percent(double x, double of) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(1) << std::showpos << 100.0 * (x / of - 1.0) << " %";
  return os.str();
}

}  // namespace

std::optional<Dispute> disputeOf(const ms::Mission& m, const energy::Vehicle& v, const PredictionSetup& setup) {
  if (setup.disputed_parameter.empty() || setup.disputed_values.size() < 2) return std::nullopt;
  const auto [a, b] = std::minmax_element(setup.disputed_values.begin(), setup.disputed_values.end());
  Dispute d{setup.disputed_parameter, *a, *b, 1e300, -1e300, 1e300, -1e300};
  ms::PredictSettings ps = setup.settings;
  ps.energy_margin = 0.0;
  for (const double x : {d.lo, d.hi}) {
    ms::AutopilotConfig ap = setup.autopilot;
    ap.parameters[d.parameter] = x;
    const ms::MissionPrediction p = ms::predictMission(m, v, setup.model, ap, ps);
    d.energy_lo_j = std::min(d.energy_lo_j, p.total.energy_j), d.energy_hi_j = std::max(d.energy_hi_j, p.total.energy_j);
    d.time_lo_s = std::min(d.time_lo_s, p.total.time_s), d.time_hi_s = std::max(d.time_hi_s, p.total.time_s);
  }
  return d;
}

std::optional<KindChoice> kindChoiceOf(const calibration::MissionKind& kind, const PredictionSetup& setup) {
  const std::size_t n = setup.disputed_values.size();
  if (setup.disputed_parameter.empty() || n < 2 || setup.disputed_kinds.size() != n || setup.disputed_flights.size() != n)
    return std::nullopt;
  KindChoice c;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!calibration::outsideCalibration(kind, setup.disputed_kinds[i]).empty()) continue;
    sum += setup.disputed_values[i];
    c.flights.push_back(setup.disputed_flights[i]);
  }
  if (c.flights.empty() || c.flights.size() == n) return std::nullopt;
  c.value = sum / static_cast<double>(c.flights.size());
  return c;
}

std::string disputeText(const Dispute& d, const ms::MissionPrediction& p, const std::optional<KindChoice>& choice) {
  std::ostringstream os;
  os << std::setprecision(3) << "the calibration's flights disagree on " << d.parameter << " (each wants " << d.lo << " to " << d.hi
     << "): flown with each, " << std::fixed << std::setprecision(1) << d.energy_lo_j / 3600.0 << " to " << d.energy_hi_j / 3600.0
     << " Wh (" << std::showpos << 100.0 * (d.energy_lo_j / p.total.energy_j - 1.0) << " to "
     << 100.0 * (d.energy_hi_j / p.total.energy_j - 1.0) << std::noshowpos << " %), " << report::formatMinSec(d.time_lo_s) << " to "
     << report::formatMinSec(d.time_hi_s) << " min:s; the prediction is ";
  if (choice) {
    os << std::setprecision(3) << std::defaultfloat << d.parameter << " " << choice->value << "'s, fitted on ";
    for (std::size_t i = 0; i < choice->flights.size(); ++i) os << (i ? ", " : "") << choice->flights[i];
    os << ", the calibration flight(s) of this mission's kind,";
  } else {
    os << "the joint value's,";
  }
  os << " and the reserve is checked with " << std::fixed << std::setprecision(0) << 100.0 * p.battery.energy_margin
     << " % more energy";
  return os.str();
}

std::optional<Coverage> coverageOf(const ms::Mission& m, const calibration::MissionKind& kind, const energy::Vehicle& v,
                                   const PredictionSetup& setup) {
  if (!setup.calibrated || !setup.coverage) return std::nullopt;
  Coverage c;
  c.reasons = calibration::outsideCalibration(kind, *setup.coverage);
  if (c.reasons.empty()) return std::nullopt;
  ms::AutopilotConfig before = setup.autopilot;
  for (const auto& [name, value] : setup.behaviour_before) before.parameters[name] = value;
  ms::PredictSettings ps = setup.settings;
  ps.energy_margin = 0.0;
  ps.flight.takeoff_delay_s = -1.0;
  ps.flight.stop_at_waypoints = false;
  ps.flight.speed_change_late = false;
  ps.flight.tracking_error = {};
  const ms::MissionPrediction p = ms::predictMission(m, v, setup.model, before, ps);
  c.energy_j = p.total.energy_j;
  c.time_s = p.total.time_s;
  return c;
}

std::string coverageText(const Coverage& c, const ms::MissionPrediction& p) {
  std::ostringstream os;
  os << "outside what the calibration flew (";
  for (std::size_t i = 0; i < c.reasons.size(); ++i) os << (i ? "; " : "") << c.reasons[i];
  os << "): its fitted flight behaviour may not carry over, and real flights of another kind than the calibration's "
        "were mispredicted by up to 15 % (docs/validation.md 5.2). Flown with the behaviour before the calibration: "
     << std::fixed << std::setprecision(1) << c.energy_j / 3600.0 << " Wh (" << percent(c.energy_j, p.total.energy_j) << "), "
     << report::formatMinSec(c.time_s) << " min:s (" << percent(c.time_s, p.total.time_s)
     << "); the reserve is checked with " << std::setprecision(0) << 100.0 * p.battery.energy_margin << " % more energy";
  return os.str();
}

}  // namespace wattswath::apps
