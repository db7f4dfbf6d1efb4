// Report structs filled from library results (sweeps for turns/vopt, replays for validation).
#include "report_data.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "marins_paper.hpp"
#include "wattswath/energy/optimal_speed.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::apps {
namespace en = wattswath::energy;

namespace {
constexpr double kDegToRad = M_PI / 180.0;

void addSorted(std::vector<double>& v, double x) {
  for (const double y : v) {
    if (std::abs(x - y) < 1e-9) return;
  }
  v.push_back(x);
  std::sort(v.begin(), v.end());
}

std::string skippedFact(int skipped, const std::string& first) {
  return std::to_string(skipped) + " point(s) could not be flown and are not drawn; first: " + first;
}
}  // namespace

report::TurnReportData turnReportData(const en::EnergyModel& model, const en::ProfileLimits& limits, double max_yaw_rate,
                                      double v_max, const en::TurnSettings& settings, double angle_deg, double distance) {
  std::vector<double> angles(std::begin(marins::kTable5Angle), std::end(marins::kTable5Angle));
  addSorted(angles, angle_deg);
  std::vector<double> lengths = {25.0, 50.0, 100.0, 150.0, 300.0, 600.0, 1200.0, 2400.0};
  addSorted(lengths, distance);
  report::TurnReportData d;
  d.focus_beta = angle_deg * kDegToRad;
  int skipped = 0;
  std::string first;
  for (const double a : angles) {
    for (const double L : lengths) {
      try {
        const auto c = en::compareTurnStrategies(model, L, a * kDegToRad, limits, max_yaw_rate, v_max, settings);
        report::TurnRow row;
        row.beta = a * kDegToRad;
        row.leg_length = L;
        row.sharp_energy = c.sharp_stop.energy;
        row.rounded_energy = c.rounded.energy;
        row.sharp_speed = c.sharp_stop.speed;
        row.rounded_speed = c.rounded.speed;
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 4; ++j) {
            if (std::abs(L - marins::kTable5Distance[i]) < 1e-9 && std::abs(a - marins::kTable5Angle[j]) < 1e-9) {
              row.paper_saving_pct = marins::kTable5[i][j];
            }
          }
        }
        d.rows.push_back(row);
      } catch (const std::invalid_argument& e) {
        if (skipped++ == 0) first = report::formatNumber(L, 0) + " m, " + report::formatNumber(a, 0) + " deg: " + e.what();
      }
    }
  }
  d.facts.push_back({"swept", std::to_string(angles.size()) + " angles x " + std::to_string(lengths.size()) +
                                  " leg lengths (Table V's points included)"});
  if (skipped > 0) d.facts.push_back({"not computed", skippedFact(skipped, first)});
  d.facts.push_back({"paper values", "Marins et al. Table V as printed; see docs/reproduction.md for why they differ"});
  return d;
}

report::SpeedReportData speedReportData(const std::vector<std::pair<std::string, en::EnergyModel>>& variants,
                                        const en::EnergyModel& model, const en::ProfileLimits& limits, double distance,
                                        double entry, double exit, double v_max) {
  report::SpeedReportData d;
  d.v_max = v_max;
  int skipped = 0;
  std::string first;
  for (const auto& [name, m] : variants) {
    report::SpeedCurve c;
    c.name = name;
    for (double L = 5.0; L <= 5000.0 * 1.0001; L *= std::pow(10.0, 0.1)) {
      try {
        const auto best = en::optimalCruiseSpeed(m, L, entry, exit, limits, v_max);
        c.distance.push_back(L);
        c.speed.push_back(best.speed);
      } catch (const std::invalid_argument& e) {
        if (skipped++ == 0) first = name + " at " + report::formatNumber(L, 1) + " m: " + e.what();
      }
    }
    d.curves.push_back(std::move(c));
  }
  for (const double L : {distance, 5.0 * distance}) {
    try {
      const auto best = en::optimalCruiseSpeed(model, L, entry, exit, limits, v_max);
      report::LegEnergyCurve e;
      e.distance = L;
      e.best_speed = best.speed;
      e.best_energy = best.energy;
      for (int k = 1; k <= 60; ++k) {
        const double v = v_max * k / 60.0;
        try {
          e.energy.push_back(en::legEnergySlope(model, L, entry, v, exit, limits).energy);
          e.speed.push_back(v);
        } catch (const std::invalid_argument&) {
          // below the entry/exit speeds the leg cannot be flown: that part of the curve does not exist
        }
      }
      d.legs.push_back(std::move(e));
    } catch (const std::invalid_argument& e) {
      if (skipped++ == 0) first = report::formatNumber(L, 1) + " m leg: " + e.what();
    }
  }
  if (skipped > 0) d.facts.push_back({"not computed", skippedFact(skipped, first)});
  return d;
}

report::ValidationReportData validationFromReplays(const std::vector<calibration::LogReplay>& replays) {
  report::ValidationReportData d;
  if (replays.empty()) return d;
  // Every log's samples one after the other (residuals pool them; power over time per log).
  for (std::size_t k = 0; k < replays.size(); ++k) {
    const auto& r = replays[k];
    d.log_names.push_back(std::filesystem::path(r.source).filename().string());
    d.log_start.push_back(d.t.size());
    for (const auto& s : r.samples) {
      d.t.push_back(s.t);
      d.measured_power.push_back(s.measured_w);
      d.modelled_power.push_back(s.modelled_w);
      d.speed.push_back(s.speed);
      d.climb_rate.push_back(s.climb_rate);
      d.heading.push_back(s.heading);
    }
    // Phase spans: runs of equal phase, each ending where the next begins.
    for (std::size_t i = 0; i < r.samples.size();) {
      std::size_t j = i;
      while (j + 1 < r.samples.size() && r.samples[j + 1].phase == r.samples[i].phase) ++j;
      const double t1 = j + 1 < r.samples.size() ? r.samples[j + 1].t : r.samples[j].t;
      d.phases.push_back({r.samples[i].t, t1, en::toString(r.samples[i].phase), k});
      i = j + 1;
    }
  }
  for (std::size_t k = 0; k < replays.size(); ++k) {
    for (std::size_t i = 0; i < replays[k].legs.size(); ++i) {
      const auto& l = replays[k].legs[i];
      const std::string label = (replays.size() > 1 ? "log " + std::to_string(k + 1) + " " : std::string()) + "segment " +
                                std::to_string(i + 1) + " (" + report::formatNumber(l.time_s, 1) + " s)";
      d.legs.push_back({label, l.measured_j, l.modelled_j});
    }
  }
  if (replays.size() > 1)
    d.facts.push_back({"logs", std::to_string(replays.size()) +
                                   " (power over time for each; residuals and leg energies pool them)"});
  for (const auto& r : replays)
    d.facts.push_back({replays.size() > 1 ? "whole flight, " + std::filesystem::path(r.source).filename().string()
                                          : std::string("whole flight"),
                       "measured " + report::formatNumber(r.flight.measured_j / 1000.0, 2) + " kJ, modelled " +
                           report::formatNumber(r.flight.modelled_j / 1000.0, 2) + " kJ (" +
                           report::formatNumber(r.flight.errorPct(), 1) + " %)"});
  return d;
}

std::string fittedValuesText(const std::vector<calibration::FittedCoefficient>& coefficients, const std::string& effect) {
  std::string text;
  for (const auto& x : coefficients) {
    if (!effect.empty() && x.effect != effect) continue;
    if (!text.empty()) text += "; ";
    // Dimensionless coefficients carry the unit "-" in the effect tables; leave it out of the text.
    const std::string unit = x.unit == "-" || x.unit == "1" ? std::string() : " " + x.unit;
    text += x.name + " = " + report::formatSignificant(x.value, 3) +
            (std::isfinite(x.sigma) ? " +- " + report::formatSignificant(x.sigma, 2) : std::string()) + unit +
            (x.at_bound ? " (at bound)" : "") + (x.determined ? "" : " (not determined by the data)");
  }
  return text;
}

std::vector<report::DiagnosisRow> diagnosisRows(const calibration::Diagnosis& d) {
  std::vector<report::DiagnosisRow> rows;
  for (std::size_t i = 0; i < d.candidates.size(); ++i) {
    const auto& c = d.candidates[i];
    const std::string fitted = fittedValuesText(c.coefficients);
    std::string meaning = c.summary;
    if (!c.indistinct_from.empty()) {
      meaning += " (cannot be told apart from";
      for (const auto& n : c.indistinct_from) meaning += " " + n;
      meaning += ")";
    }
    if (!c.kept) meaning += " [not kept: " + c.why_not_kept + "]";
    // Kept: it passed the stopping rule in the first round of the search (diagnose.hpp).
    rows.push_back({c.effect, c.improvement_pct, fitted, meaning, c.kept});
  }
  return rows;
}

}  // namespace wattswath::apps
