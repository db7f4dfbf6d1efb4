// The turn-strategy report: energy of the two corner strategies (stop and turn in place, or an
// arc) by turn angle and leg length.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "report_common.hpp"
#include "wattswath/report/charts.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report {

using namespace detail;

namespace {

std::vector<double> distinctSorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), v.end());
  return v;
}

}  // namespace

HtmlReport turnReport(const TurnReportData& d) {
  HtmlReport r(d.title);
  addFacts(r, d.facts);
  std::vector<double> betas;
  for (const auto& row : d.rows) betas.push_back(row.beta);
  betas = distinctSorted(betas);
  // The energy of two long branches hardly depends on the angle between them, so the lines of all
  // angles lie on top of each other; then only one angle is drawn (the user's, else the middle one)
  // and the caption gives the spread of the others. The saving chart keeps every angle.
  double spread_sharp = 0.0, spread_rounded = 0.0;  // largest (max - min) / min over angles, per leg length
  {
    std::map<double, std::array<double, 4>> by_length;  // min/max sharp, min/max rounded
    for (const auto& row : d.rows) {
      auto [it, fresh] = by_length.try_emplace(row.leg_length, std::array<double, 4>{row.sharp_energy, row.sharp_energy,
                                                                                      row.rounded_energy, row.rounded_energy});
      auto& m = it->second;
      m[0] = std::min(m[0], row.sharp_energy);
      m[1] = std::max(m[1], row.sharp_energy);
      m[2] = std::min(m[2], row.rounded_energy);
      m[3] = std::max(m[3], row.rounded_energy);
    }
    for (const auto& [length, m] : by_length) {
      if (m[0] > 0.0) spread_sharp = std::max(spread_sharp, (m[1] - m[0]) / m[0]);
      if (m[2] > 0.0) spread_rounded = std::max(spread_rounded, (m[3] - m[2]) / m[2]);
    }
  }
  const double spread = std::max(spread_sharp, spread_rounded);
  const bool one_angle = betas.size() > 1 && spread <= d.overlap_tolerance;
  std::size_t drawn = betas.size() / 2;
  if (d.focus_beta) {
    for (std::size_t i = 0; i < betas.size(); ++i)
      if (std::abs(betas[i] - *d.focus_beta) < 1e-9) drawn = i;
  }
  LineChart e, s;
  e.title = one_angle && !betas.empty()
                ? "Energy against leg length at " + formatNumber(betas[drawn] * kDeg, 0) +
                      " deg: sharp stop (solid) and rounded (dashed)"
                : "Energy against leg length: sharp stop (solid) and rounded (dashed)";
  e.x = {"leg length (each branch)", "m"};
  e.y = {"energy", "kJ"};
  s.title = "Saving of the rounded turn";
  s.x = e.x;
  s.y = {"saving (E_sharp - E_rounded) / E_sharp", "%"};
  s.y_ref = 0.0;
  s.height = 320;
  Series paper;
  paper.name = "paper (Table V)";
  paper.style = SeriesStyle::Points;
  paper.colour = "#000000";
  for (std::size_t i = 0; i < betas.size(); ++i) {
    std::vector<const TurnRow*> rows;
    for (const auto& row : d.rows) {
      if (std::abs(row.beta - betas[i]) < 1e-9) rows.push_back(&row);
    }
    std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->leg_length < b->leg_length; });
    const std::string angle = formatNumber(betas[i] * kDeg, 0) + " deg";
    Series sharp, round, saving;
    sharp.name = "sharp, " + angle;
    round.name = "rounded, " + angle;
    saving.name = angle;
    sharp.colour = round.colour = saving.colour = seriesColour(i);
    round.dash = "6 3";
    sharp.style = round.style = saving.style = SeriesStyle::LineAndPoints;
    for (const auto* row : rows) {
      sharp.x.push_back(row->leg_length);
      sharp.y.push_back(row->sharp_energy / 1000.0);
      round.x.push_back(row->leg_length);
      round.y.push_back(row->rounded_energy / 1000.0);
      saving.x.push_back(row->leg_length);
      saving.y.push_back(row->sharp_energy > 0 ? 100.0 * (row->sharp_energy - row->rounded_energy) / row->sharp_energy
                                               : std::numeric_limits<double>::quiet_NaN());
      if (row->paper_saving_pct) {
        paper.x.push_back(row->leg_length);
        paper.y.push_back(*row->paper_saving_pct);
      }
    }
    if (!one_angle || i == drawn) {
      e.series.push_back(sharp);
      e.series.push_back(round);
    }
    s.series.push_back(saving);
  }
  if (!paper.x.empty()) s.series.push_back(paper);
  double lmin = std::numeric_limits<double>::infinity(), lmax = 0.0;
  for (const auto& row : d.rows) {
    if (row.leg_length > 0.0) lmin = std::min(lmin, row.leg_length);
    lmax = std::max(lmax, row.leg_length);
  }
  e.x.log = s.x.log = lmin > 0.0 && lmax / lmin > 20.0;  // Table V spans decades of leg length
  double emin = std::numeric_limits<double>::infinity(), emax = 0.0;
  for (const auto& row : d.rows) {
    for (const double v : {row.sharp_energy, row.rounded_energy}) {
      emin = std::min(emin, v);
      emax = std::max(emax, v);
    }
  }
  e.y.log = emin > 0.0 && emax / emin > 20.0;  // short legs stay readable next to long ones
  if (!d.rows.empty()) {
    std::string caption = "Two equal branches meeting at interior angle beta (Marins et al. Sec. V-B).";
    if (one_angle) {
      std::string others;
      for (std::size_t i = 0; i < betas.size(); ++i) {
        if (i == drawn) continue;
        others += (others.empty() ? "" : ", ") + formatNumber(betas[i] * kDeg, 0);
      }
      caption += " The other angles (" + others + " deg) lie within " + formatNumber(100.0 * spread, 1) +
                 " % of these lines and would hide them; the table lists every one.";
    } else if (betas.size() > 1 && std::min(spread_sharp, spread_rounded) <= d.overlap_tolerance) {
      const bool sharp = spread_sharp <= spread_rounded;
      caption += std::string(" The ") + (sharp ? "sharp-stop" : "rounded") + " lines of all angles lie within " +
                 formatNumber(100.0 * (sharp ? spread_sharp : spread_rounded), 1) +
                 " % of each other, so they overlap; the table lists every one.";
    }
    r.heading("Energy of the two corner strategies");
    r.figure({"turns-energy", renderSvg(e), caption});
    r.figure({"turns-saving", renderSvg(s), "Positive: the rounded, constant-speed turn uses less energy."});
  }
  Table t{"Turn strategies (shape of Marins et al. Table V)",
          {"angle [deg]", "leg [m]", "sharp speed [m/s]", "E sharp [kJ]", "rounded speed [m/s]", "E rounded [kJ]", "saving [%]", "paper saving [%]"},
          {},
          {true, true, true, true, true, true, true, true},
          false};
  for (const auto& row : d.rows) {
    t.rows.push_back({formatNumber(row.beta * kDeg, 0), formatNumber(row.leg_length, 0), formatNumber(row.sharp_speed, 2),
                      kJ(row.sharp_energy), formatNumber(row.rounded_speed, 2), kJ(row.rounded_energy),
                      row.sharp_energy > 0 ? formatNumber(100.0 * (row.sharp_energy - row.rounded_energy) / row.sharp_energy, 1) : "-",
                      row.paper_saving_pct ? formatNumber(*row.paper_saving_pct, 1) : "-"});
  }
  r.table(t);
  return r;
}

std::string turnReportHtml(const TurnReportData& d) { return turnReport(d).html(); }

}  // namespace wattswath::report
