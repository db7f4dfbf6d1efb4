// The mission report (predict --report): the predicted track on a map by flight phase with the
// waypoint numbers, speed, altitude and battery over time, and the phase table with the verdict.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>

#include "report_common.hpp"
#include "wattswath/report/charts.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report {

namespace detail {

std::string cutoffLabel(double seconds) { return "battery cut-off " + formatMinSec(seconds); }

LineChart usableChargeChart(const BatteryTrace& b, const Axis& time) {
  LineChart c;
  c.title = "Battery: usable charge left" + (b.model.empty() ? std::string() : " (" + b.model + ")");
  c.x = time;
  c.y = {"usable charge left", "%"};
  c.y.min = 0.0;
  c.y.max = 100.0;
  c.height = 320;
  Series left("usable charge left", {}, {});
  const std::size_t n = std::min(b.t.size(), b.soc.size());
  const std::size_t stride = std::max<std::size_t>(1, n / 4000 + 1);  // display only: at most about 4000 points
  for (std::size_t i = 0; i < n; i += stride) {
    left.x.push_back(b.t[i] / 60.0);
    left.y.push_back(b.soc[i]);
  }
  if (n > 0 && (n - 1) % stride != 0) {
    left.x.push_back(b.t[n - 1] / 60.0);
    left.y.push_back(b.soc[n - 1]);
  }
  left.colour = seriesColour(0);
  left.width = 2.0;
  c.series = {std::move(left)};
  if (std::isfinite(b.reserve_pct) && !b.t.empty()) {
    Series reserve("reserve " + formatNumber(b.reserve_pct, 0) + " %", {b.t.front() / 60.0, b.t.back() / 60.0},
                   {b.reserve_pct, b.reserve_pct});
    reserve.colour = seriesColour(1);
    reserve.dash = "6 3";
    reserve.width = 1.6;
    c.series.push_back(std::move(reserve));
  }
  if (b.cutoff_s) c.x_lines.push_back({*b.cutoff_s / 60.0, cutoffLabel(*b.cutoff_s)});
  return c;
}

std::string usableChargeCaption(const BatteryTrace& b) {
  return "Usable charge left (100 % full, 0 % at the cut-off voltage) along the predicted flight" +
         std::string(std::isfinite(b.reserve_pct) ? ", against the reserve to keep on landing," : "") +
         " counted as the autopilot counts it (the charge drawn against the pack's capacity, as a ground station "
         "shows it); a pack drawn hard reaches its cut-off sooner (Peukert), which the verdict checks as well." +
         (b.cutoff_s ? " The battery reaches its cut-off " + formatMinSec(*b.cutoff_s) +
                           " min:s into the flight (the red line): the flight after it is not possible."
                     : std::string());
}

}  // namespace detail

using namespace detail;

namespace {

constexpr std::size_t kMaxLinePoints = 4000;  // display only: longer series are thinned for drawing

/// How a flight phase is drawn: Okabe-Ito colour and dash pattern (told apart in grey-scale print).
struct PhaseStyle {
  std::string colour, dash;
};

PhaseStyle phaseStyle(const std::string& phase) {
  static const std::map<std::string, PhaseStyle> kStyles = {{"takeoff", {"#D55E00", "2 2"}},
                                                            {"mission", {"#0072B2", ""}},
                                                            {"return", {"#009E73", "7 3"}},
                                                            {"landing", {"#CC79A7", "3 2 1 2"}}};
  const auto it = kStyles.find(phase);
  return it == kStyles.end() ? PhaseStyle{"#999999", "1 2"} : it->second;
}

/// A phase as pilots write it ("take-off" for "takeoff").
std::string phaseLabel(const std::string& phase) { return phase == "takeoff" ? "take-off" : phase; }

/// A run of samples [begin, end) in one phase.
struct PhaseRun {
  std::size_t begin = 0, end = 0;
  std::string phase;
};

std::vector<PhaseRun> phaseRuns(const std::vector<std::string>& phase) {
  std::vector<PhaseRun> runs;
  for (std::size_t i = 0; i < phase.size(); ++i) {
    if (runs.empty() || runs.back().phase != phase[i]) runs.push_back({i, i, phase[i]});
    runs.back().end = i + 1;
  }
  return runs;
}

/// Times [s] in minutes (the time axes are in minutes: pilots read min:s).
std::vector<double> minutes(const std::vector<double>& seconds) {
  std::vector<double> out;
  out.reserve(seconds.size());
  for (const double s : seconds) out.push_back(s / 60.0);
  return out;
}

/// The time axis [min] from the take-off command to the last sample.
Axis timeAxis(const MissionReportData& d) {
  Axis a{"time since the take-off command", "min"};
  a.min = 0.0;
  if (!d.t.empty() && d.t.back() > 0.0) a.max = d.t.back() / 60.0;
  return a;
}

/// The phases as shaded ranges of the time axis [min] (a run ends where the next begins).
std::vector<XRange> phaseShading(const MissionReportData& d) {
  std::vector<XRange> out;
  for (const auto& r : phaseRuns(d.phase)) {
    const double t1 = r.end < d.t.size() ? d.t[r.end] : d.t[r.end - 1];
    out.push_back({d.t[r.begin] / 60.0, t1 / 60.0, phaseLabel(r.phase), phaseStyle(r.phase).colour});
  }
  return out;
}

/// Every k-th sample (and the last) so that a line has at most kMaxLinePoints points.
Series thinned(const std::string& name, const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t stride = std::max<std::size_t>(1, x.size() / kMaxLinePoints + 1);
  Series s;
  s.name = name;
  for (std::size_t i = 0; i < x.size(); i += stride) {
    s.x.push_back(x[i]);
    s.y.push_back(y[i]);
  }
  if (!x.empty() && (x.size() - 1) % stride != 0) {
    s.x.push_back(x.back());
    s.y.push_back(y.back());
  }
  return s;
}

/// The item's number in the mission file; "" for steps the autopilot model added (their tick keeps a tooltip).
std::string seqLabel(const MissionMark& m) { return m.seq >= 0 ? std::to_string(m.seq) : ""; }

/// " Take-off and landing are vertical ..." for the phases that hardly move on the map ("" if none).
std::string verticalPhasesNote(const MissionReportData& d) {
  std::vector<std::string> vertical;
  for (const auto& run : phaseRuns(d.phase)) {
    double extent = 0.0;
    for (std::size_t i = run.begin; i < run.end; ++i) {
      extent = std::max(extent, std::hypot(d.x[i] - d.x[run.begin], d.y[i] - d.y[run.begin]));
    }
    const std::string name = phaseLabel(run.phase);
    if (extent < 2.0 && std::find(vertical.begin(), vertical.end(), name) == vertical.end()) vertical.push_back(name);
  }
  if (vertical.empty()) return "";
  std::string names;
  for (std::size_t i = 0; i < vertical.size(); ++i)
    names += (i == 0 ? "" : (i + 1 == vertical.size() ? " and " : ", ")) + vertical[i];
  names[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(names[0])));
  return " " + names + (vertical.size() > 1 ? " are" : " is") +
         " flown vertically, hardly visible here: see the altitude figure.";
}

void missionMap(HtmlReport& r, const MissionReportData& d) {
  MapView m;
  m.title = "Predicted track by flight phase";
  m.axes = true;
  m.height = 560;
  std::vector<std::string> seen;
  for (const auto& run : phaseRuns(d.phase)) {
    MapPolyline p;
    const std::size_t end = std::min(run.end + 1, d.t.size());  // join the next run
    for (std::size_t i = run.begin; i < end; ++i) p.points.emplace_back(d.x[i], d.y[i]);
    const PhaseStyle st = phaseStyle(run.phase);
    p.colour = st.colour;
    p.dash = st.dash;
    p.tooltip =
        phaseLabel(run.phase) + ": " + formatMinSec(d.t[run.begin]) + " to " + formatMinSec(d.t[end - 1]) + " min:s";
    m.path.push_back(std::move(p));
    if (std::find(seen.begin(), seen.end(), run.phase) == seen.end()) {
      seen.push_back(run.phase);
      m.legend.push_back({phaseLabel(run.phase), st.colour, st.dash});
    }
  }
  addWaypointMarkers(m, d.items);
  m.markers.push_back({geometry::Point(0, 0), "home (take-off)", MapMarker::Shape::Square, "#000000"});
  if (!d.t.empty() && std::hypot(d.x.back(), d.y.back()) > 2.0) {
    m.markers.push_back({geometry::Point(d.x.back(), d.y.back()), "landing", MapMarker::Shape::Triangle, "#000000"});
  }
  r.figure({"mission-map", renderSvg(m),
            "Predicted track in metres from home (east right, north up), coloured and dashed by flight phase. "
            "Numbers are the mission items' numbers (seq) in the mission file; hover a piece of track for its times." +
                verticalPhasesNote(d)});
}

/// The battery's cut-off as a line on the time plots [min] (none when it is not reached).
std::vector<XLine> cutoffLines(const MissionReportData& d) {
  if (!d.battery || !d.battery->cutoff_s) return {};
  return {{*d.battery->cutoff_s / 60.0, cutoffLabel(*d.battery->cutoff_s)}};
}

void speedAndAltitude(HtmlReport& r, const MissionReportData& d) {
  const auto shading = phaseShading(d);
  const std::string cutoff = d.battery && d.battery->cutoff_s
                                 ? " The red line is where the battery reaches its cut-off: the flight after it is not possible."
                                 : "";
  LineChart c;
  c.left_margin = kStackedLeftMargin;  // the time plots stacked on the page start at the same x
  c.x_lines = cutoffLines(d);
  c.title = "Speed along the path";
  c.x = timeAxis(d);
  c.y = {"speed", "m/s"};
  c.y.include_zero = true;
  c.series = {thinned("predicted speed (3-D)", minutes(d.t), d.speed)};
  c.series[0].colour = "#222222";
  c.series[0].width = 1.6;
  c.shaded = shading;
  for (const auto& it : d.items) {
    if (!std::isfinite(it.reached_s)) continue;
    const std::string what = (it.seq >= 0 ? "item " + seqLabel(it) + " " : std::string("added step ")) + it.command;
    c.events.push_back(
        {it.reached_s / 60.0, seqLabel(it), what + " reached at " + formatMinSec(it.reached_s) + " min:s"});
  }
  r.figure(
      {"mission-speed", renderSvg(c),
       "Predicted speed along the path; the background shows the flight phase and the ticks along the top the time "
       "each mission item is reached (its number)." + cutoff});
  LineChart a;
  a.title = "Altitude";
  a.x = c.x;
  a.y = {"height above home", "m"};
  a.y.include_zero = true;
  a.height = 300;
  a.left_margin = kStackedLeftMargin;
  a.x_lines = cutoffLines(d);
  a.series = {thinned("predicted height", minutes(d.t), d.z)};
  a.series[0].colour = "#222222";
  a.shaded = shading;
  r.figure({"mission-altitude", renderSvg(a), "Predicted height above the take-off point." + cutoff});
}

void batteryFigure(HtmlReport& r, const MissionReportData& d) {
  if (!d.battery || d.battery->t.empty()) {
    r.paragraph("The vehicle file has no battery: the usable charge along the flight cannot be shown.");
    return;
  }
  BatteryTrace b = *d.battery;
  if (!std::isfinite(b.reserve_pct)) b.reserve_pct = d.reserve_pct;
  LineChart c = usableChargeChart(b, timeAxis(d));
  c.shaded = phaseShading(d);
  c.left_margin = kStackedLeftMargin;
  r.figure({"mission-battery", renderSvg(c), usableChargeCaption(b)});
}

std::vector<std::string> totalsRow(const MissionPhaseTotals& p, const std::string& name) {
  return {name, formatMinSec(p.time_s), formatNumber(p.energy_j / 3600.0, 2), formatNumber(p.energy_j, 0),
          formatNumber(p.distance_m, 0)};
}

void phaseTable(HtmlReport& r, const MissionReportData& d) {
  Table t{"Time, energy and distance by phase",
          {"phase", "time [min:s]", "energy [Wh]", "energy [J]", "distance [m]"},
          {},
          {false, true, true, true, true},
          false};
  for (const auto& p : d.phases) t.rows.push_back(totalsRow(p, phaseLabel(p.phase)));
  t.rows.push_back(totalsRow(d.total, "take-off to landing"));
  r.table(t);
  if (!d.verdict.empty()) r.paragraph(d.verdict);
  if (d.items.empty()) return;
  Table it{"Mission items, in flight order",
           {"item", "command", "reached [min:s]", "time [min:s]", "energy [Wh]", "distance [m]"},
           {},
           {true, false, true, true, true, true},
           true};
  for (const auto& m : d.items) {
    it.rows.push_back({m.seq >= 0 ? std::to_string(m.seq) : "-", m.command, formatMinSec(m.reached_s),
                       formatMinSec(m.time_s), formatNumber(m.energy_j / 3600.0, 2), formatNumber(m.distance_m, 0)});
  }
  r.table(it);
}

void checkSizes(const MissionReportData& d) {
  const std::size_t n = d.t.size();
  const std::pair<const char*, std::size_t> sizes[] = {
      {"x", d.x.size()}, {"y", d.y.size()}, {"z", d.z.size()}, {"speed", d.speed.size()}, {"phase", d.phase.size()}};
  for (const auto& [name, size] : sizes) {
    if (size != n) {
      throw std::invalid_argument(std::string("mission report: ") + name + " has " + std::to_string(size) +
                                  " samples but t has " + std::to_string(n));
    }
  }
  if (d.battery && d.battery->soc.size() != d.battery->t.size()) {
    throw std::invalid_argument("mission report: the battery trace has " + std::to_string(d.battery->soc.size()) +
                                " values for " + std::to_string(d.battery->t.size()) + " times");
  }
}

}  // namespace

HtmlReport missionReport(const MissionReportData& d) {
  checkSizes(d);
  HtmlReport r(d.title);
  addFacts(r, d.facts);
  r.heading("Time, energy and battery");
  phaseTable(r, d);
  if (d.t.empty()) {
    r.paragraph("The prediction has no trajectory samples: no figures.");
    return r;
  }
  r.heading("Track");
  missionMap(r, d);
  r.heading("Speed and altitude");
  speedAndAltitude(r, d);
  r.heading("Battery");
  batteryFigure(r, d);
  return r;
}

}  // namespace wattswath::report
