// The validation report: measured against modelled power over time, residuals against each
// regressor, leg energies, the error staircase and the diagnosis.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include "chart_common.hpp"
#include "report_common.hpp"
#include "wattswath/report/charts.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report {

using namespace detail;

namespace {

constexpr std::size_t kMaxScatterPoints = 2500;  // display only: binned statistics use every sample

/// Fill colour of a phase name (shared by the power plot's shading and its legend).
std::string phaseColour(const std::string& phase) {
  static const std::map<std::string, std::string> kColours = {
      {"accelerate", "#E69F00"}, {"cruise", "#56B4E9"}, {"brake", "#CC79A7"}, {"turn", "#009E73"},
      {"climb", "#D55E00"},      {"descent", "#0072B2"}, {"hover", "#999999"}, {"ground", "#444444"}};
  const auto it = kColours.find(phase);
  return it == kColours.end() ? "#bbbbbb" : it->second;
}

/// Position of a phase in the legends (flight order: ground, climb, hover, ..., descent), so that
/// every power plot of a report lists the phases in the same order; unknown phases go last.
int phaseRank(const std::string& phase) {
  static const std::vector<std::string> kOrder = {"ground", "climb", "hover", "accelerate", "cruise",
                                                  "brake",  "turn",  "descent"};
  const auto it = std::find(kOrder.begin(), kOrder.end(), phase);
  return static_cast<int>(it - kOrder.begin());
}

void checkSameSize(const std::vector<double>& v, std::size_t n, const char* name) {
  if (!v.empty() && v.size() != n) {
    throw std::invalid_argument(std::string("validation report: ") + name + " has " + std::to_string(v.size()) +
                                " samples but t has " + std::to_string(n));
  }
}

/// Residual (measured - modelled) against one regressor: thinned scatter, binned mean and +-1 sd band.
std::string residualChart(const std::vector<double>& x, const std::vector<double>& res, const Axis& xaxis, int bins) {
  LineChart c;
  c.title = "Residual against " + xaxis.label;
  c.x = xaxis;
  c.y = {"measured - modelled power", "W"};
  c.y_ref = 0.0;
  c.height = 320;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::isfinite(x[i]) && std::isfinite(res[i])) {
      lo = std::min(lo, x[i]);
      hi = std::max(hi, x[i]);
    }
  }
  Series pts;
  pts.name = "samples";
  pts.style = SeriesStyle::Points;
  pts.colour = "#9a9a9a";
  const std::size_t stride = std::max<std::size_t>(1, x.size() / kMaxScatterPoints);
  for (std::size_t i = 0; i < x.size(); i += stride) {
    pts.x.push_back(x[i]);
    pts.y.push_back(res[i]);
  }
  if (stride > 1) pts.name = "samples (1 in " + std::to_string(stride) + " shown)";
  c.series.push_back(pts);
  if (hi > lo) {
    std::vector<double> n(bins, 0.0), s(bins, 0.0), s2(bins, 0.0);
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!std::isfinite(x[i]) || !std::isfinite(res[i])) continue;
      const int b = std::min(bins - 1, static_cast<int>((x[i] - lo) / (hi - lo) * bins));
      n[b] += 1;
      s[b] += res[i];
      s2[b] += res[i] * res[i];
    }
    Series mean;
    mean.name = "binned mean +- 1 sd";
    mean.style = SeriesStyle::LineAndPoints;
    mean.colour = seriesColour(1);
    for (int b = 0; b < bins; ++b) {
      if (n[b] < 3) continue;  // too few samples for a spread
      const double m = s[b] / n[b], sd = std::sqrt(std::max(0.0, s2[b] / n[b] - m * m));
      mean.x.push_back(lo + (b + 0.5) * (hi - lo) / bins);
      mean.y.push_back(m);
      mean.y_low.push_back(m - sd);
      mean.y_high.push_back(m + sd);
    }
    c.series.push_back(mean);
  }
  return renderSvg(c);
}

/// The diagnosis's verdict and the residual (found effects fitted) against the signals carrying it.
void addSignalCurves(HtmlReport& r, const ValidationReportData& d) {
  if (d.verdict.empty() && d.signal_curves.empty()) return;
  r.heading("What the residual keeps");
  if (!d.verdict.empty()) r.paragraph(d.verdict);
  for (const auto& g : d.signal_curves) {
    const std::string what = g.label.empty() ? g.signal : g.label;
    LineChart c;
    c.title = "Residual against " + what + (what == g.signal ? "" : " (" + g.signal + ")");
    c.x = {what, g.unit};
    c.y = {"measured - modelled", "W"};
    c.y_ref = 0.0;
    c.height = 300;
    Series s("binned mean", g.x, g.residual);
    s.style = SeriesStyle::LineAndPoints;
    c.series.push_back(s);
    r.figure({"validation-signal-" + g.signal, renderSvg(c),
              "Residual with the found effects fitted, binned by " + what + ": it " + g.sentence + "."});
  }
}
}  // namespace

HtmlReport validationReport(const ValidationReportData& d) {
  HtmlReport r(d.title);
  addFacts(r, d.facts);
  addValidation(r, d);
  return r;
}

namespace {

// Checks the data's shape: per-sample arrays of one length, 2..100 residual bins, log starts in
// order, one name per log. Returns the first sample of each log.
std::vector<std::size_t> checkValidationData(const ValidationReportData& d) {
  const std::size_t n = d.t.size();
  checkSameSize(d.measured_power, n, "measured_power");
  checkSameSize(d.modelled_power, n, "modelled_power");
  checkSameSize(d.speed, n, "speed");
  checkSameSize(d.climb_rate, n, "climb_rate");
  checkSameSize(d.heading, n, "heading");
  if (d.residual_bins < 2 || d.residual_bins > 100) {
    throw std::invalid_argument("validation report: residual_bins = " + std::to_string(d.residual_bins) + ", expected 2..100");
  }
  std::vector<std::size_t> starts = d.log_start.empty() ? std::vector<std::size_t>{0} : d.log_start;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    if (starts[k] > n || (k > 0 && starts[k] < starts[k - 1])) {
      throw std::invalid_argument("validation report: log_start[" + std::to_string(k) + "] = " + std::to_string(starts[k]) +
                                  ", expected non-decreasing indices <= " + std::to_string(n));
    }
  }
  if (!d.log_names.empty() && d.log_names.size() != starts.size()) {
    throw std::invalid_argument("validation report: " + std::to_string(d.log_names.size()) + " log_names for " +
                                std::to_string(starts.size()) + " logs");
  }
  return starts;
}

// One figure per log: measured and modelled power over time on the phases of flight.
void addPowerFigures(HtmlReport& r, const ValidationReportData& d, const std::vector<std::size_t>& starts) {
  const std::size_t n = d.t.size();
  if (n == 0) return;
  r.heading("Power over time");
  // One power range for every log's figure, so that the figures compare at a glance (each had its own).
  Range shared;
  for (const auto* v : {&d.measured_power, &d.modelled_power})
    for (const double p : *v) shared.add(p, false);
  std::optional<Ticks> common;
  if (starts.size() > 1 && !shared.empty() && shared.hi > shared.lo) common = niceTicks(shared.lo, shared.hi);
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const std::size_t a = starts[k], b = k + 1 < starts.size() ? starts[k + 1] : n;
    if (a == b) continue;
    auto slice = [a, b](const std::vector<double>& v) {
      return v.empty() ? v : std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(a), v.begin() + static_cast<std::ptrdiff_t>(b));
    };
    const std::vector<double> t = slice(d.t);
    LineChart c;
    const std::string name = d.log_names.empty() ? std::string() : d.log_names[k];
    c.title = "Measured and modelled electrical power" + (name.empty() ? std::string() : ": " + name);
    c.x = {"log time (the log's own clock)", "s"};
    c.y = {"power", "W"};
    if (common) {
      c.y.min = common->lo;
      c.y.max = common->hi;
    }
    if (!d.measured_power.empty()) c.series.push_back(Series("measured", t, slice(d.measured_power)));
    if (!d.modelled_power.empty()) c.series.push_back(Series("modelled", t, slice(d.modelled_power)));
    for (std::size_t i = 0; i < c.series.size(); ++i) c.series[i].width = 1.3;
    if (c.series.size() == 2) c.series[0].colour = "#444444", c.series[1].colour = seriesColour(1);
    for (const auto& p : d.phases)
      if (p.log == k) c.shaded.push_back({p.t0, p.t1, p.phase, phaseColour(p.phase)});
    // The legend lists shaded labels in the order they come: sort by phase so every plot agrees.
    std::stable_sort(c.shaded.begin(), c.shaded.end(),
                     [](const auto& a, const auto& b) { return phaseRank(a.label) < phaseRank(b.label); });
    r.figure({k == 0 ? std::string("validation-power") : "validation-power-" + std::to_string(k + 1), renderSvg(c),
              "Measured and modelled power" + (name.empty() ? std::string() : " of " + name) +
                  "; the background shows the phase of flight." +
                  (common ? std::string(" Every log's power figure has the same power axis.") : std::string())});
  }
}

// The residual (measured - modelled) in words and binned by speed, climb rate and heading.
void addResiduals(HtmlReport& r, const ValidationReportData& d, std::size_t logs) {
  const std::size_t n = d.t.size();
  std::vector<double> res(n);
  double se = 0.0, bias = 0.0;
  int k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    res[i] = d.measured_power[i] - d.modelled_power[i];
    if (std::isfinite(res[i])) {
      se += res[i] * res[i];
      bias += res[i];
      ++k;
    }
  }
  r.heading("Residuals");
  if (k > 0) {
    r.paragraph("Sample residual (measured - modelled): RMS " + formatNumber(std::sqrt(se / k), 1) + " W, mean " +
                formatNumber(bias / k, 1) + " W over " + std::to_string(k) + " samples" +
                (logs > 1 ? " of " + std::to_string(logs) + " logs" : std::string()) +
                ". A binned mean away from zero "
                "that changes with a quantity points to an effect the model lacks.");
  }
  if (!d.speed.empty()) {
    r.figure({"validation-residual-speed", residualChart(d.speed, res, {"horizontal speed", "m/s"}, d.residual_bins), ""});
  }
  if (!d.climb_rate.empty()) {
    r.figure({"validation-residual-climb", residualChart(d.climb_rate, res, {"climb rate", "m/s"}, d.residual_bins), ""});
  }
  if (!d.heading.empty()) {
    std::vector<double> deg(n);
    for (std::size_t i = 0; i < n; ++i) {
      deg[i] = std::isfinite(d.heading[i]) ? std::fmod(std::fmod(d.heading[i] * kDeg, 360.0) + 360.0, 360.0) : d.heading[i];
    }
    Axis a{"track heading (0 = east, CCW)", "deg"};
    a.min = 0.0;
    a.max = 360.0;
    r.figure({"validation-residual-heading", residualChart(deg, res, a, d.residual_bins), ""});
  }
}

// Segment energies (the log cut at its stops and slow-downs, SegmentSettings; not the mission's
// legs): measured against modelled on the diagonal, and as a table.
void addLegEnergies(HtmlReport& r, const ValidationReportData& d) {
  r.heading("Segment energies");
  LineChart c;
  c.title = "Segment energy: measured against modelled";
  c.x = {"modelled energy", "kJ"};
  c.y = {"measured energy", "kJ"};
  c.diagonal = true;
  c.width = 520;
  c.height = 480;
  Series s;
  s.name = "segments";
  s.style = SeriesStyle::Points;
  for (const auto& l : d.legs) {
    s.x.push_back(l.modelled / 1000.0);
    s.y.push_back(l.measured / 1000.0);
  }
  c.series.push_back(s);
  r.figure({"validation-legs", renderSvg(c), "The logged flight cut into segments at its stops and slow-downs (not the mission's legs); points on the dashed "
               "diagonal are segments the model gets exactly right."});
  Table t{"Segment energies", {"segment", "measured [kJ]", "modelled [kJ]", "error [%]"}, {}, {false, true, true, true}, true};
  for (const auto& l : d.legs) {
    t.rows.push_back({l.label, kJ(l.measured), kJ(l.modelled),
                      l.measured != 0.0 ? formatNumber(100.0 * (l.modelled - l.measured) / l.measured, 1) : "-"});
  }
  r.table(t);
}

// The error staircase: one bar per step, coloured by the logs it is computed on when the steps
// name them (fit: as given and fitted, on the training logs and on the test log).
void addStaircase(HtmlReport& r, const ValidationReportData& d) {
  r.heading("Error staircase");
  BarChart b;
  b.title = d.staircase_title;
  for (const auto& s : d.staircase) b.categories.push_back(s.label);
  std::vector<std::string> groups;
  for (const auto& s : d.staircase)
    if (!s.group.empty() && std::find(groups.begin(), groups.end(), s.group) == groups.end()) groups.push_back(s.group);
  if (groups.empty()) {
    b.series = {d.error_label};
    b.values = {{}};
    for (const auto& s : d.staircase) b.values[0].push_back(s.error);
    b.colours = {seriesColour(0)};
  } else {  // one series per group, each bar in its group's series only: one full-width bar per step
    b.stacked = true;
    b.series = groups;
    b.values.assign(groups.size(), std::vector<double>(d.staircase.size(), std::numeric_limits<double>::quiet_NaN()));
    for (std::size_t k = 0; k < d.staircase.size(); ++k) {
      const auto g = std::find(groups.begin(), groups.end(), d.staircase[k].group) - groups.begin();
      if (static_cast<std::size_t>(g) < groups.size()) b.values[static_cast<std::size_t>(g)][k] = d.staircase[k].error;
    }
    for (std::size_t g = 0; g < groups.size(); ++g) b.colours.push_back(seriesColour(g));
  }
  b.y = {d.error_label, d.error_unit};
  b.height = 320;
  r.figure({"validation-staircase", renderSvg(b), d.staircase_caption});
}

// The diagnosis: each candidate effect, its held-out improvement and whether it was kept.
void addDiagnosis(HtmlReport& r, const ValidationReportData& d) {
  r.heading("Diagnosis");
  Table t{d.diagnosis_caption, {"effect", "held-out error reduction [%]", "fitted values", "physical meaning", "kept"}, {},
          {false, true, false, false, false}, false};
  for (const auto& row : d.diagnosis) {
    t.rows.push_back({row.effect, formatNumber(row.improvement_pct, 1), row.fitted, row.meaning, row.accepted ? "yes" : "no"});
  }
  r.table(t);
}

}  // namespace

void addValidation(HtmlReport& r, const ValidationReportData& d) {
  const std::vector<std::size_t> starts = checkValidationData(d);
  const std::size_t n = d.t.size();
  addPowerFigures(r, d, starts);
  if (n > 0 && d.measured_power.size() == n && d.modelled_power.size() == n) addResiduals(r, d, starts.size());
  addSignalCurves(r, d);
  if (!d.legs.empty()) addLegEnergies(r, d);
  if (!d.staircase.empty()) addStaircase(r, d);
  if (!d.diagnosis.empty()) addDiagnosis(r, d);
}

}  // namespace wattswath::report
