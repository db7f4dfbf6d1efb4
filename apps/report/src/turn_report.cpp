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

/// The largest relative spread (max - min) / min over the angles at one leg length, for each strategy.
struct AngleSpread {
  double sharp = 0.0, rounded = 0.0;
};

/// How much each strategy's energy changes with the angle: the energy of two long branches hardly
/// depends on the angle between them, so then the lines of all angles lie on top of each other.
AngleSpread angleSpread(const std::vector<TurnRow>& rows) {
  std::map<double, std::array<double, 4>> by_length;  // min/max sharp, min/max rounded
  for (const auto& row : rows) {
    auto [it, fresh] = by_length.try_emplace(row.leg_length, std::array<double, 4>{row.sharp_energy, row.sharp_energy,
                                                                                    row.rounded_energy, row.rounded_energy});
    auto& m = it->second;
    m[0] = std::min(m[0], row.sharp_energy);
    m[1] = std::max(m[1], row.sharp_energy);
    m[2] = std::min(m[2], row.rounded_energy);
    m[3] = std::max(m[3], row.rounded_energy);
  }
  AngleSpread s;
  for (const auto& [length, m] : by_length) {
    if (m[0] > 0.0) s.sharp = std::max(s.sharp, (m[1] - m[0]) / m[0]);
    if (m[2] > 0.0) s.rounded = std::max(s.rounded, (m[3] - m[2]) / m[2]);
  }
  return s;
}

/// The saving of the rounded turn over the sharp stop [%], NaN when the sharp stop costs nothing.
double savingPct(const TurnRow& row) {
  return row.sharp_energy > 0 ? 100.0 * (row.sharp_energy - row.rounded_energy) / row.sharp_energy
                              : std::numeric_limits<double>::quiet_NaN();
}

/// The two figures and what goes into them.
struct TurnCharts {
  LineChart energy, saving;
};

/// Adds the angle `betas[i]`: its sharp and rounded energies against leg length (when `draw_energy`)
/// and its saving, with the paper's Table V savings at that angle as points of the same colour.
void addAngle(TurnCharts& c, const TurnReportData& d, const std::vector<double>& betas, std::size_t i, bool draw_energy) {
  std::vector<const TurnRow*> rows;
  for (const auto& row : d.rows) {
    if (std::abs(row.beta - betas[i]) < 1e-9) rows.push_back(&row);
  }
  std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->leg_length < b->leg_length; });
  const std::string angle = formatNumber(betas[i] * kDeg, 0) + " deg";
  Series sharp, round, saving, paper;
  sharp.name = "sharp, " + angle;
  paper.name = "paper (Table V), " + angle;
  paper.style = SeriesStyle::Points;
  paper.colour = seriesColour(i);
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
    saving.y.push_back(savingPct(*row));
    if (row->paper_saving_pct) {
      paper.x.push_back(row->leg_length);
      paper.y.push_back(*row->paper_saving_pct);
    }
  }
  if (draw_energy) {
    c.energy.series.push_back(sharp);
    c.energy.series.push_back(round);
  }
  c.saving.series.push_back(saving);
  if (!paper.x.empty()) c.saving.series.push_back(paper);
}

/// Log axes where the data span more than a factor 20: Table V spans decades of leg length, and
/// short legs' energies stay readable next to long ones'.
void chooseLogAxes(TurnCharts& c, const std::vector<TurnRow>& rows) {
  double lmin = std::numeric_limits<double>::infinity(), lmax = 0.0;
  double emin = std::numeric_limits<double>::infinity(), emax = 0.0;
  for (const auto& row : rows) {
    if (row.leg_length > 0.0) lmin = std::min(lmin, row.leg_length);
    lmax = std::max(lmax, row.leg_length);
    for (const double v : {row.sharp_energy, row.rounded_energy}) {
      emin = std::min(emin, v);
      emax = std::max(emax, v);
    }
  }
  c.energy.x.log = c.saving.x.log = lmin > 0.0 && lmax / lmin > 20.0;
  c.energy.y.log = emin > 0.0 && emax / emin > 20.0;
}

/// The energy figure's caption: the geometry, and which lines overlap and are left out or said to.
std::string energyCaption(const TurnReportData& d, const std::vector<double>& betas, std::size_t drawn, bool one_angle,
                          const AngleSpread& sp) {
  std::string caption = "Two equal branches meeting at interior angle beta (Marins et al. Sec. V-B).";
  if (one_angle) {
    std::string others;
    for (std::size_t i = 0; i < betas.size(); ++i) {
      if (i == drawn) continue;
      others += (others.empty() ? "" : ", ") + formatNumber(betas[i] * kDeg, 0);
    }
    caption += " The other angles (" + others + " deg) lie within " + formatNumber(100.0 * std::max(sp.sharp, sp.rounded), 1) +
               " % of these lines and would hide them; the table lists every one.";
  } else if (betas.size() > 1 && std::min(sp.sharp, sp.rounded) <= d.overlap_tolerance) {
    const bool sharp = sp.sharp <= sp.rounded;
    caption += std::string(" The ") + (sharp ? "sharp-stop" : "rounded") + " lines of all angles lie within " +
               formatNumber(100.0 * (sharp ? sp.sharp : sp.rounded), 1) +
               " % of each other, so they overlap; the table lists every one.";
  }
  return caption;
}

/// Every row as the table of Marins et al. Table V's shape.
Table turnTable(const TurnReportData& d) {
  Table t{"Turn strategies (shape of Marins et al. Table V)",
          {"angle [deg]", "leg [m]", "sharp speed [m/s]", "E sharp [kJ]", "rounded speed [m/s]", "E rounded [kJ]", "saving [%]", "paper saving [%]"},
          {},
          {true, true, true, true, true, true, true, true},
          false};
  for (const auto& row : d.rows) {
    t.rows.push_back({formatNumber(row.beta * kDeg, 0), formatNumber(row.leg_length, 0), formatNumber(row.sharp_speed, 2),
                      kJ(row.sharp_energy), formatNumber(row.rounded_speed, 2), kJ(row.rounded_energy),
                      row.sharp_energy > 0 ? formatNumber(savingPct(row), 1) : "-",
                      row.paper_saving_pct ? formatNumber(*row.paper_saving_pct, 1) : "-"});
  }
  return t;
}

}  // namespace

HtmlReport turnReport(const TurnReportData& d) {
  HtmlReport r(d.title);
  addFacts(r, d.facts);
  std::vector<double> betas;
  for (const auto& row : d.rows) betas.push_back(row.beta);
  betas = distinctSorted(betas);
  // When the lines of all angles lie on top of each other only one angle is drawn (the user's, else
  // the middle one) and the caption gives the spread of the others. The saving chart keeps every angle.
  const AngleSpread sp = angleSpread(d.rows);
  const bool one_angle = betas.size() > 1 && std::max(sp.sharp, sp.rounded) <= d.overlap_tolerance;
  std::size_t drawn = betas.size() / 2;
  if (d.focus_beta) {
    for (std::size_t i = 0; i < betas.size(); ++i)
      if (std::abs(betas[i] - *d.focus_beta) < 1e-9) drawn = i;
  }
  TurnCharts c;
  c.energy.title = one_angle && !betas.empty()
                       ? "Energy against leg length at " + formatNumber(betas[drawn] * kDeg, 0) +
                             " deg: sharp stop (solid) and rounded (dashed)"
                       : "Energy against leg length: sharp stop (solid) and rounded (dashed)";
  c.energy.x = {"leg length (each branch)", "m"};
  c.energy.y = {"energy", "kJ"};
  c.saving.title = "Saving of the rounded turn";
  c.saving.x = c.energy.x;
  c.saving.y = {"saving (E_sharp - E_rounded) / E_sharp", "%"};
  c.saving.y_ref = 0.0;
  c.saving.height = 320;
  for (std::size_t i = 0; i < betas.size(); ++i) addAngle(c, d, betas, i, !one_angle || i == drawn);
  chooseLogAxes(c, d.rows);
  if (!d.rows.empty()) {
    r.heading("Energy of the two corner strategies");
    r.figure({"turns-energy", renderSvg(c.energy), energyCaption(d, betas, drawn, one_angle, sp)});
    r.figure({"turns-saving", renderSvg(c.saving), "Positive: the rounded, constant-speed turn uses less energy. Lines: this model; points: the savings "
                                                 "the paper's Table V gives, in the colour of their angle."});
  }
  r.table(turnTable(d));
  return r;
}

}  // namespace wattswath::report
