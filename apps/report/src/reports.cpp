// The plan, validation, turn-strategy and optimal-speed reports built from plain data structs.
#include "wattswath/report/reports.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "wattswath/report/charts.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;
constexpr std::size_t kMaxScatterPoints = 2500;  // display only: binned statistics use every sample

std::string kJ(double joules) { return formatNumber(joules / 1000.0, 3); }
std::string J(double joules) { return formatNumber(joules, 0); }

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

void addFacts(HtmlReport& r, const Facts& f) {
  if (!f.empty()) r.facts(f);
}

// ---------------------------------------------------------------- plan

void planMap(HtmlReport& r, const PlanReportData& d) {
  MapView m;
  m.title = d.colour_by == PlanColour::Speed ? "Chosen path, coloured by cruise speed" : "Chosen path, coloured by mean power";
  m.areas = d.areas;
  m.no_fly = d.no_fly;
  m.value_label = d.colour_by == PlanColour::Speed ? "speed" : "power";
  m.value_unit = d.colour_by == PlanColour::Speed ? "m/s" : "W";
  for (std::size_t i = 0; i < d.legs.size(); ++i) {
    const auto& l = d.legs[i];
    if (l.points.size() < 2) continue;  // turns in place have no extent on the map
    const double power = l.time > 0.0 ? l.energy / l.time : 0.0;
    MapPolyline p;
    p.points = l.points;
    p.value = d.colour_by == PlanColour::Speed ? l.speed : power;
    p.dashed = l.role == "transit";
    p.tooltip = "leg " + std::to_string(i + 1) + " (" + l.role + "): " + formatNumber(l.speed, 2) + " m/s, " +
                formatNumber(l.length, 1) + " m, " + formatNumber(l.time, 1) + " s, " + kJ(l.energy) + " kJ, " +
                formatNumber(power, 0) + " W";
    m.path.push_back(std::move(p));
  }
  std::optional<geometry::Point> start;
  for (const auto& l : d.legs) {
    if (!l.points.empty()) {
      start = l.points.front();
      break;
    }
  }
  const bool startAtHome = d.home && start && (*d.home - *start).norm() < 1.0;
  if (d.home) m.markers.push_back({*d.home, startAtHome ? "home, start" : "home", MapMarker::Shape::Square, "#000000"});
  if (start && !startAtHome) m.markers.push_back({*start, "start", MapMarker::Shape::Triangle, "#009E73"});
  if (m.areas.empty() && m.path.empty() && m.markers.empty()) {
    r.paragraph("No area or path was given: no map.");
    return;
  }
  if (m.path.empty()) m.value_label.clear();
  r.figure({"plan-map", renderSvg(m),
            "Map in local metres (east right, north up). Hover a leg for its number, speed, length, time and energy; "
            "dashed legs are transits, red dashed areas are no-fly zones."});
  Table t{"Legs", {"leg", "role", "speed [m/s]", "length [m]", "time [s]", "energy [kJ]"}, {}, {true, false, true, true, true, true}, true};
  for (std::size_t i = 0; i < d.legs.size(); ++i) {
    const auto& l = d.legs[i];
    t.rows.push_back({std::to_string(i + 1), l.role, formatNumber(l.speed, 2), formatNumber(l.length, 1),
                      formatNumber(l.time, 1), kJ(l.energy)});
  }
  if (!t.rows.empty()) r.table(t);
  if (!d.cells.empty()) {
    Table ct{"Cells of the plan (each cell's own pattern and sweep angle), in flight order",
             {"cell", "pattern", "sweep angle [deg]", "area [m^2]", "energy alone [kJ]"},
             {},
             {false, false, true, true, true},
             false};
    for (std::size_t i = 0; i < d.cells.size(); ++i) {
      const auto& cell = d.cells[i];
      const double deg = std::fmod(std::fmod(cell.sweep_angle * kDeg, 180.0) + 180.0, 180.0);
      ct.rows.push_back({std::to_string(i + 1), cell.pattern,
                         cell.pattern == "spiral" ? std::string("-") : formatNumber(deg, 0),
                         formatNumber(cell.area, 0), kJ(cell.energy)});
    }
    r.table(ct);
  }
}

void planBreakdown(HtmlReport& r, const PlanReportData& d) {
  // Rows: coverage phases with energy, then transits; columns: effects (Marins et al. Table III).
  std::vector<std::string> effects = d.coverage.effects;
  for (const auto& e : d.transit.effects) {
    if (std::find(effects.begin(), effects.end(), e) == effects.end()) effects.push_back(e);
  }
  if (effects.empty()) {
    r.paragraph("No energy breakdown was given.");
    return;
  }
  struct Row {
    std::string part, status;
    std::vector<double> e;
  };
  std::vector<Row> rows;
  auto addRows = [&](const energy::Breakdown& b, const std::string& part) {
    for (int p = 0; p < energy::kPhaseCount; ++p) {
      const auto phase = static_cast<energy::Phase>(p);
      Row row{part, energy::toString(phase), {}};
      double sum = 0.0;
      for (const auto& e : effects) {
        row.e.push_back(b.at(e, phase));
        sum += std::abs(row.e.back());
      }
      if (sum > 0.0) rows.push_back(std::move(row));
    }
  };
  addRows(d.coverage, "coverage");
  if (!d.transit.effects.empty()) addRows(d.transit, "transit");
  Table t{"Energy by part and effect [J] (shape of Marins et al. Table III)", {"part", "phase"}, {}, {false, false}, false};
  for (const auto& e : effects) {
    t.header.push_back(e + " [J]");
    t.numeric.push_back(true);
  }
  t.header.push_back("total [J]");
  t.numeric.push_back(true);
  std::vector<double> colTotal(effects.size(), 0.0);
  double grand = 0.0;
  for (const auto& row : rows) {
    std::vector<std::string> cells = {row.part, row.status};
    double sum = 0.0;
    for (std::size_t k = 0; k < effects.size(); ++k) {
      cells.push_back(J(row.e[k]));
      sum += row.e[k];
      colTotal[k] += row.e[k];
    }
    cells.push_back(J(sum));
    grand += sum;
    t.rows.push_back(cells);
  }
  std::vector<std::string> total = {"total by effect", ""};
  for (const double v : colTotal) total.push_back(J(v));
  total.push_back(J(grand));
  t.rows.push_back(total);
  r.table(t);

  BarChart b;
  b.title = "Energy by part and effect";
  b.stacked = true;
  b.series = effects;
  b.values.assign(effects.size(), {});
  for (const auto& row : rows) {
    b.categories.push_back(row.part == "coverage" ? row.status : row.part + " " + row.status);
    for (std::size_t k = 0; k < effects.size(); ++k) b.values[k].push_back(row.e[k] / 1000.0);
  }
  b.y = {"energy", "kJ"};
  b.category_label = "part of the flight";
  r.figure({"plan-breakdown", renderSvg(b), "Stacked energy per part of the flight; hover a bar for its value."});
}

void planCandidates(HtmlReport& r, const PlanReportData& d) {
  if (d.candidates.empty() && d.baselines.empty()) return;
  LineChart c;
  c.title = "Candidate plans: energy against sweep angle";
  c.x = {"sweep angle", "deg"};
  c.y = {"energy", "kJ"};
  c.x.min = 0.0;
  c.x.max = 180.0;
  std::map<std::string, std::vector<const PlanCandidate*>> byPattern;
  std::vector<std::string> order;
  for (const auto& k : d.candidates) {
    if (k.chosen) continue;  // drawn as the marker
    if (!byPattern.count(k.pattern)) order.push_back(k.pattern);
    byPattern[k.pattern].push_back(&k);
  }
  std::size_t colour = 0;
  auto wrapDeg = [](double a) {
    double deg = std::fmod(a * kDeg, 180.0);
    return deg < 0 ? deg + 180.0 : deg;
  };
  for (const auto& pattern : order) {
    auto ks = byPattern[pattern];
    std::sort(ks.begin(), ks.end(), [&](auto* a, auto* b) { return wrapDeg(a->sweep_angle) < wrapDeg(b->sweep_angle); });
    Series s;
    s.name = pattern;
    s.colour = seriesColour(colour);
    bool distinctAngles = false;
    for (const auto* k : ks) distinctAngles |= std::abs(wrapDeg(k->sweep_angle) - wrapDeg(ks.front()->sweep_angle)) > 1e-6;
    if (distinctAngles) {
      s.style = SeriesStyle::LineAndPoints;
      for (const auto* k : ks) {
        s.x.push_back(wrapDeg(k->sweep_angle));
        s.y.push_back(k->energy / 1000.0);
      }
    } else {  // no sweep direction (spiral): its best energy as a level line
      double best = ks.front()->energy;
      for (const auto* k : ks) best = std::min(best, k->energy);
      s.x = {0.0, 180.0};
      s.y = {best / 1000.0, best / 1000.0};
      s.dash = seriesDash(1);
    }
    c.series.push_back(std::move(s));
    ++colour;
  }
  for (std::size_t i = 0; i < d.baselines.size(); ++i) {
    Series s("baseline: " + d.baselines[i].name, {0.0, 180.0}, {d.baselines[i].energy / 1000.0, d.baselines[i].energy / 1000.0});
    s.colour = seriesColour(colour++);
    s.dash = seriesDash(2 + i);
    c.series.push_back(std::move(s));
  }
  for (const auto& k : d.candidates) {
    if (k.chosen) c.markers.push_back({wrapDeg(k.sweep_angle), k.energy / 1000.0, "chosen: " + k.pattern, "#000000"});
  }
  r.figure({"plan-candidates", renderSvg(c),
            "Energy of the candidates against their sweep direction (0 deg = lines along east): the whole area swept "
            "at one angle, at every angle searched (coarse grid, then refined around the best). Patterns without a "
            "sweep direction and the baselines are level lines. The ring marks the chosen plan (a per-cell plan is "
            "placed at the angle of its largest boustrophedon cell). The scan scores each corner as a stop or the "
            "widest arc at its largest speed; the chosen plan is flown with arcs at chain speeds too, so it can lie "
            "below the curve."});
  Table t{"Baselines", {"plan", "energy [kJ]", "length [m]", "time [s]", "vs chosen [%]"}, {}, {false, true, true, true, true}, false};
  double chosen = std::numeric_limits<double>::quiet_NaN();
  for (const auto& k : d.candidates) {
    if (k.chosen) chosen = k.energy;
  }
  auto fmtOpt = [](double v, int dec) { return v > 0.0 ? formatNumber(v, dec) : std::string("-"); };
  for (const auto& b : d.baselines) {
    t.rows.push_back({b.name, kJ(b.energy), fmtOpt(b.length, 0), fmtOpt(b.time, 0),
                      std::isfinite(chosen) && chosen > 0 ? formatNumber(100.0 * (b.energy - chosen) / chosen, 1) : "-"});
  }
  if (!t.rows.empty()) r.table(t);
}

void planBattery(HtmlReport& r, const PlanReportData& d) {
  if (!d.battery) {
    r.paragraph("No battery model was given: state of charge and voltage are not shown.");
    return;
  }
  const auto& b = *d.battery;
  LineChart c;
  c.title = "Battery state of charge" + (b.model.empty() ? std::string() : " (" + b.model + ")");
  c.x = {"time", "s"};
  c.y = {"state of charge", "%"};
  c.y.min = 0.0;
  c.y.max = 100.0;
  c.series = {Series("state of charge", b.t, b.soc)};
  c.height = 300;
  r.figure({"plan-battery-soc", renderSvg(c), "State of charge over the mission."});
  if (!b.voltage.empty()) {
    LineChart v;
    v.title = "Battery voltage";
    v.x = {"time", "s"};
    v.y = {"voltage", "V"};
    v.series = {Series("terminal voltage", b.t, b.voltage)};
    v.series[0].colour = seriesColour(1);
    v.height = 300;
    r.figure({"plan-battery-voltage", renderSvg(v), "Terminal voltage over the mission."});
  }
}

// ---------------------------------------------------------------- validation

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

// ---------------------------------------------------------------- turns / speed helpers

std::vector<double> distinctSorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), v.end());
  return v;
}

}  // namespace

HtmlReport planReport(const PlanReportData& d) {
  HtmlReport r(d.title);
  addFacts(r, d.facts);
  r.heading("Map");
  planMap(r, d);
  r.heading("Energy breakdown");
  planBreakdown(r, d);
  if (!d.candidates.empty() || !d.baselines.empty()) {
    r.heading("Candidates and baselines");
    planCandidates(r, d);
  }
  r.heading("Battery");
  planBattery(r, d);
  return r;
}

std::string planReportHtml(const PlanReportData& d) { return planReport(d).html(); }

HtmlReport validationReport(const ValidationReportData& d) {
  const std::size_t n = d.t.size();
  checkSameSize(d.measured_power, n, "measured_power");
  checkSameSize(d.modelled_power, n, "modelled_power");
  checkSameSize(d.speed, n, "speed");
  checkSameSize(d.climb_rate, n, "climb_rate");
  checkSameSize(d.heading, n, "heading");
  if (d.residual_bins < 2 || d.residual_bins > 100) {
    throw std::invalid_argument("validation report: residual_bins = " + std::to_string(d.residual_bins) + ", expected 2..100");
  }
  HtmlReport r(d.title);
  addFacts(r, d.facts);
  const bool haveBoth = n > 0 && d.measured_power.size() == n && d.modelled_power.size() == n;
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
  if (n > 0) r.heading("Power over time");
  for (std::size_t k = 0; k < starts.size() && n > 0; ++k) {
    const std::size_t a = starts[k], b = k + 1 < starts.size() ? starts[k + 1] : n;
    if (a == b) continue;
    auto slice = [a, b](const std::vector<double>& v) {
      return v.empty() ? v : std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(a), v.begin() + static_cast<std::ptrdiff_t>(b));
    };
    const std::vector<double> t = slice(d.t);
    LineChart c;
    const std::string name = d.log_names.empty() ? std::string() : d.log_names[k];
    c.title = "Measured and modelled electrical power" + (name.empty() ? std::string() : ": " + name);
    c.x = {"time", "s"};
    c.y = {"power", "W"};
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
                  "; the background shows the phase of flight."});
  }
  if (haveBoth) {
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
                  (starts.size() > 1 ? " of " + std::to_string(starts.size()) + " logs" : std::string()) +
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
  if (!d.legs.empty()) {
    r.heading("Leg energies");
    LineChart c;
    c.title = "Leg energy: measured against modelled";
    c.x = {"modelled energy", "kJ"};
    c.y = {"measured energy", "kJ"};
    c.diagonal = true;
    c.width = 520;
    c.height = 480;
    Series s;
    s.name = "legs";
    s.style = SeriesStyle::Points;
    for (const auto& l : d.legs) {
      s.x.push_back(l.modelled / 1000.0);
      s.y.push_back(l.measured / 1000.0);
    }
    c.series.push_back(s);
    r.figure({"validation-legs", renderSvg(c), "Points on the dashed diagonal are legs the model gets exactly right."});
    Table t{"Leg energies", {"leg", "measured [kJ]", "modelled [kJ]", "error [%]"}, {}, {false, true, true, true}, true};
    for (const auto& l : d.legs) {
      t.rows.push_back({l.label, kJ(l.measured), kJ(l.modelled),
                        l.measured != 0.0 ? formatNumber(100.0 * (l.modelled - l.measured) / l.measured, 1) : "-"});
    }
    r.table(t);
  }
  if (!d.staircase.empty()) {
    r.heading("Error staircase");
    BarChart b;
    b.title = "Error as effects are added";
    for (const auto& s : d.staircase) b.categories.push_back(s.label);
    b.series = {d.error_label};
    b.values = {{}};
    for (const auto& s : d.staircase) b.values[0].push_back(s.error);
    b.y = {d.error_label, d.error_unit};
    b.colours = {seriesColour(0)};
    b.height = 320;
    r.figure({"validation-staircase", renderSvg(b), "Each bar is the model after one more step; lower is better."});
  }
  if (!d.diagnosis.empty()) {
    r.heading("Diagnosis");
    Table t{d.diagnosis_caption, {"effect", "held-out error reduction [%]", "fitted values", "physical meaning", "kept"}, {},
            {false, true, false, false, false}, false};
    for (const auto& row : d.diagnosis) {
      t.rows.push_back({row.effect, formatNumber(row.improvement_pct, 1), row.fitted, row.meaning, row.accepted ? "yes" : "no"});
    }
    r.table(t);
  }
  return r;
}

std::string validationReportHtml(const ValidationReportData& d) { return validationReport(d).html(); }

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

HtmlReport speedReport(const SpeedReportData& d) {
  HtmlReport r(d.title);
  addFacts(r, d.facts);
  if (!d.curves.empty()) {
    LineChart c;
    c.title = "Optimal cruise speed against leg length";
    c.x = {"leg length", "m"};
    c.y = {"optimal cruise speed", "m/s"};
    c.y.include_zero = true;
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (std::size_t i = 0; i < d.curves.size(); ++i) {
      Series s(d.curves[i].name, d.curves[i].distance, d.curves[i].speed);
      s.dash = seriesDash(i);
      c.series.push_back(s);
      for (const double x : d.curves[i].distance) {
        if (x > 0.0) lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
    }
    c.x.log = lo > 0.0 && hi / lo > 50.0;
    if (d.v_max) {
      Series v("speed limit", {lo, hi}, {*d.v_max, *d.v_max});
      v.colour = "#666666";
      v.dash = "2 3";
      v.width = 1.2;
      if (std::isfinite(lo)) c.series.push_back(v);
    }
    r.heading("Optimal speed (Marins et al. Fig. 3)");
    r.figure({"vopt-distance", renderSvg(c), "The speed that minimises a stop-to-stop leg's energy, for model variants."});
    Table t{"Optimal cruise speed [m/s]", {"model variant", "leg length [m]", "v_opt [m/s]"}, {}, {false, true, true}, true};
    for (const auto& k : d.curves) {
      for (std::size_t i = 0; i < k.distance.size() && i < k.speed.size(); ++i) {
        t.rows.push_back({k.name, formatNumber(k.distance[i], 1), formatNumber(k.speed[i], 3)});
      }
    }
    r.table(t);
  }
  if (!d.legs.empty()) {
    LineChart c;
    c.title = "Energy per metre against cruise speed";
    c.x = {"cruise speed", "m/s"};
    c.y = {"leg energy / leg length", "J/m"};
    for (std::size_t i = 0; i < d.legs.size(); ++i) {
      const auto& l = d.legs[i];
      Series s;
      s.name = formatNumber(l.distance, 0) + " m leg";
      s.dash = seriesDash(i);
      for (std::size_t k = 0; k < l.speed.size() && k < l.energy.size(); ++k) {
        s.x.push_back(l.speed[k]);
        s.y.push_back(l.distance > 0 ? l.energy[k] / l.distance : std::numeric_limits<double>::quiet_NaN());
      }
      c.series.push_back(s);
      if (l.distance > 0) c.markers.push_back({l.best_speed, l.best_energy / l.distance, formatNumber(l.best_speed, 2) + " m/s", seriesColour(i)});
    }
    double best = 0.0;
    for (const auto& l : d.legs) {
      if (l.distance > 0) best = std::max(best, l.best_energy / l.distance);
    }
    if (best > 0.0) {  // the slow end grows without bound (hover time): show the region around the optima
      c.y.min = 0.0;
      c.y.max = 2.5 * best;
    }
    r.heading("Leg energy against speed");
    r.figure({"vopt-energy", renderSvg(c), "Rings mark the optimal cruise speed of each leg length."});
  }
  return r;
}

std::string speedReportHtml(const SpeedReportData& d) { return speedReport(d).html(); }

}  // namespace wattswath::report
