// The plan report: map, energy breakdown, candidates and baselines, battery.
#include <algorithm>
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

std::string J(double joules) { return formatNumber(joules, 0); }

/// The home marker's label: home, the path's start, and the take-off and return items there
/// with their numbers ("home: take-off (1), return and landing (42)").
std::string homeLabel(const std::vector<MissionMark>& items, bool startAtHome) {
  std::string label = startAtHome ? "home, start" : "home";
  for (const auto& it : items) {
    if (it.command == "NAV_TAKEOFF") label += ", take-off (" + std::to_string(it.seq) + ")";
    if (it.command == "NAV_RETURN_TO_LAUNCH") label += ", return and landing (" + std::to_string(it.seq) + ")";
  }
  return label;
}

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
  addWaypointMarkers(m, d.items);
  if (d.home) m.markers.push_back({*d.home, homeLabel(d.items, startAtHome), MapMarker::Shape::Square, "#000000"});
  if (start && !startAtHome) m.markers.push_back({*start, "start", MapMarker::Shape::Triangle, "#009E73"});
  if (m.areas.empty() && m.path.empty() && m.markers.empty()) {
    r.paragraph("No area or path was given: no map.");
    return;
  }
  if (m.path.empty()) m.value_label.clear();
  std::size_t holes = 0;
  for (const auto& a : d.areas) holes += a.holes.size();
  r.figure({"plan-map", renderSvg(m),
            "Map in local metres (east right, north up). Hover a leg for its number, speed, length, time and energy; "
            "dashed legs are transits" +
                std::string(d.items.empty() ? "" : "; numbers are the mission items' numbers (seq) as QGroundControl and "
                                                   "Mission Planner show them") +
                std::string(holes > 0 ? "; holes in the area (white, grey outline) are not flown over" : "") +
                (d.no_fly.empty() ? "" : "; red dashed areas are no-fly zones") + "."});
  Table t{"Legs", {"leg", "role", "speed [m/s]", "length [m]", "time [s]", "energy [kJ]", "energy [Wh]"}, {},
          {true, false, true, true, true, true, true}, true};
  for (std::size_t i = 0; i < d.legs.size(); ++i) {
    const auto& l = d.legs[i];
    t.rows.push_back({std::to_string(i + 1), l.role, formatNumber(l.speed, 2), formatNumber(l.length, 1),
                      formatNumber(l.time, 1), kJ(l.energy), formatNumber(l.energy / 3600.0, 2)});
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
  Table t{"Baselines", {"plan", "energy [kJ]", "length [m]", "time [s]", "energy above the chosen plan [% of the chosen plan]"}, {}, {false, true, true, true, true}, false};
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
  if (!d.battery || d.battery->t.empty()) {
    r.paragraph("No battery model was given: the usable charge and voltage are not shown.");
    return;
  }
  const auto& b = *d.battery;
  Axis time{"time since the take-off command", "min"};
  time.min = 0.0;
  if (b.t.back() > 0.0) time.max = b.t.back() / 60.0;
  LineChart c = usableChargeChart(b, time);  // as predict's report draws it
  c.left_margin = kStackedLeftMargin;
  r.figure({"plan-battery-soc", renderSvg(c), usableChargeCaption(b)});
  if (!b.voltage.empty()) {
    LineChart v;
    v.title = "Battery voltage";
    v.x = time;
    v.y = {"voltage", "V"};
    std::vector<double> minutes;
    for (const double t : b.t) minutes.push_back(t / 60.0);
    v.series = {Series("terminal voltage", minutes, b.voltage)};
    v.series[0].colour = seriesColour(1);
    v.height = 300;
    v.left_margin = kStackedLeftMargin;
    if (b.cutoff_s) v.x_lines.push_back({*b.cutoff_s / 60.0, cutoffLabel(*b.cutoff_s)});
    r.figure({"plan-battery-voltage", renderSvg(v), "Terminal voltage over the flight."});
  }
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
  addPlanSorties(r, d);
  return r;
}

}  // namespace wattswath::report
