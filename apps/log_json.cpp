// JSON and text pieces shared by replay, diagnose and fit (apps/cmd_logs.cpp).
#include "log_json.hpp"

#include <cmath>
#include <iostream>

#include "wattswath/report/svg.hpp"

namespace wattswath::apps {
namespace en = wattswath::energy;
using nlohmann::json;

json metricsJson(const calibration::ErrorMetrics& m) {
  json phases = json::object();
  for (int k = 0; k < en::kPhaseCount; ++k) {
    const auto& p = m.phases[k];
    if (p.samples == 0) continue;
    phases[en::toString(static_cast<en::Phase>(k))] = {{"samples", p.samples},
                                                       {"rmse_w", p.rmse_w},
                                                       {"measured_mean_w", p.measured_mean_w},
                                                       {"modelled_mean_w", p.modelled_mean_w},
                                                       {"energy_error_pct", p.energy_error_pct}};
  }
  return {{"samples", m.samples},
          {"rmse_w", m.rmse_w},
          {"energy_error_pct", m.energy_error_pct},
          {"leg_energy_mape_pct", m.leg_energy_mape_pct},
          {"phases", phases}};
}

json residualsJson(const std::vector<calibration::ResidualTable>& tables) {
  json out = json::object();
  for (const auto& t : tables) {
    json bins = json::array();
    for (const auto& b : t.bins) {
      bins.push_back({{"lo", b.lo},
                      {"hi", b.hi},
                      {"count", b.count},
                      {"measured_mean_w", b.measured_mean_w},
                      {"modelled_mean_w", b.modelled_mean_w}});
    }
    out[t.quantity] = {{"unit", t.unit}, {"bins", bins}};
  }
  return out;
}

json flightsJson(const std::vector<calibration::LogReplay>& reps) {
  json out = json::array();
  for (const auto& r : reps) {
    out.push_back({{"log", r.source},
                   {"time_s", r.flight.time_s},
                   {"measured_j", r.flight.measured_j},
                   {"modelled_j", r.flight.modelled_j},
                   {"energy_error_pct", r.flight.errorPct()},
                   {"legs", r.legs.size()}});
  }
  return out;
}

// {"effect": {"coef": value}} and the same shape for sigma.
json coefficientsJson(const std::vector<calibration::FittedCoefficient>& cs, bool sigma) {
  json out = json::object();
  for (const auto& c : cs) {
    if (!sigma) {
      out[c.effect][c.name] = c.value;
    } else {
      out[c.effect][c.name] = std::isfinite(c.sigma) ? json(c.sigma) : json(nullptr);
    }
  }
  return out;
}

void printMetrics(const std::string& label, const calibration::ErrorMetrics& m) {
  std::cout << label << ": sample RMSE " << report::formatNumber(m.rmse_w, 1)
            << " W, whole-flight energy error (mean of |error| over the flights) " << report::formatNumber(m.energy_error_pct, 2)
            << " %, leg-energy MAPE " << report::formatNumber(m.leg_energy_mape_pct, 2) << " %\n";
}

json identifiabilityJson(const std::vector<calibration::FittedCoefficient>& cs) {
  json out = json::object();
  for (const auto& c : cs) {
    out[c.effect][c.name] = {{"determined", c.determined},
                             {"fitted", c.fitted},
                             {"at_bound", c.at_bound},
                             {"why_not_determined", c.why_not_determined}};
  }
  return out;
}

}  // namespace wattswath::apps
