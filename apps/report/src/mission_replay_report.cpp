// The mission section of the replay report (replay --mission --report): per logged flight, the
// predicted against the measured speed along the path, energy and time per leg, and the totals
// with the error split into kinematics and physics.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "report_common.hpp"
#include "wattswath/report/charts.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report {

using namespace detail;

namespace {

const char* const kMeasuredColour = "#444444";   // measured: dark grey, solid
const char* const kPredictedColour = "#D55E00";  // predicted: Okabe-Ito vermillion, dashed
const char* const kPredictedDash = "6 3";

void checkFlight(const MissionReplayFlight& f) {
  if (f.measured_t.size() != f.measured_speed.size() || f.predicted_t.size() != f.predicted_speed.size()) {
    throw std::invalid_argument("mission replay report: " + f.name +
                                ": the speed series and their times differ in length");
  }
  if (f.measured_passage_s.size() != f.predicted_passage_s.size() ||
      (!f.waypoint_labels.empty() && f.waypoint_labels.size() != f.measured_passage_s.size())) {
    throw std::invalid_argument("mission replay report: " + f.name + ": waypoint passages and labels differ in number");
  }
}

/// "+5.2 %" of `a` against `b`; "-" when `b` is 0 or either is not finite.
std::string pct(double a, double b) {
  if (!std::isfinite(a) || !std::isfinite(b) || b == 0.0) return "-";
  const double p = 100.0 * (a - b) / b;
  return (p > 0 ? "+" : "") + formatNumber(p, 1) + " %";
}

/// Energy [J] as "74.7 kJ" (a tenth of a kJ: the measurement is not better than that).
std::string kJ1(double j) { return formatNumber(j / 1000.0, 1) + " kJ"; }

/// Energy [J] as "74.7 kJ (20.8 Wh)".
std::string kJWh(double j) { return kJ1(j) + " (" + formatNumber(j / 3600.0, 1) + " Wh)"; }

void speedFigure(HtmlReport& r, const MissionReplayFlight& f, const std::string& suffix) {
  LineChart c;
  c.title = "Speed along the path: predicted and measured";
  c.x = {"time since the take-off command", "s"};
  c.x.min = 0.0;
  const double end =
      std::max(f.measured_t.empty() ? 0.0 : f.measured_t.back(), f.predicted_t.empty() ? 0.0 : f.predicted_t.back());
  if (end > 0.0) c.x.max = end;
  c.y = {"speed", "m/s"};
  c.y.include_zero = true;
  Series m("measured (log)", f.measured_t, f.measured_speed);
  m.colour = kMeasuredColour;
  m.width = 1.8;
  Series p("predicted from the mission", f.predicted_t, f.predicted_speed);
  p.colour = kPredictedColour;
  p.dash = kPredictedDash;
  p.width = 1.8;
  c.series = {m, p};
  for (std::size_t k = 0; k < f.measured_passage_s.size(); ++k) {
    const std::string label = k < f.waypoint_labels.size() ? f.waypoint_labels[k] : std::to_string(k + 1);
    if (std::isfinite(f.predicted_passage_s[k])) {
      c.events.push_back(
          {f.predicted_passage_s[k], label,
           "waypoint " + label + " passed (predicted) at " + formatMinSec(f.predicted_passage_s[k]) + " min:s",
           kPredictedColour, false});
    }
    if (std::isfinite(f.measured_passage_s[k])) {
      c.events.push_back(
          {f.measured_passage_s[k], label,
           "waypoint " + label + " passed (measured) at " + formatMinSec(f.measured_passage_s[k]) + " min:s",
           kMeasuredColour, true});
    }
  }
  r.figure({"mission-speed" + suffix, renderSvg(c),
            "Speed along the path (3-D) of the logged flight and of the flight predicted from its mission file. Ticks: "
            "the passage of each waypoint (its number; the middle of a stop there), predicted along the top, measured along the bottom; "
            "where they drift apart the prediction runs ahead or behind."});
}

/// Grouped bars, measured against predicted, one group per leg.
BarChart legBars(const MissionReplayFlight& f, const std::string& title, const Axis& y, double scale, bool energy) {
  BarChart b;
  b.title = title;
  b.series = {"measured", "predicted"};
  b.colours = {kMeasuredColour, kPredictedColour};
  b.values = {{}, {}};
  for (const auto& l : f.legs) {
    b.categories.push_back(l.label);
    b.values[0].push_back((energy ? l.measured_j : l.measured_s) * scale);
    b.values[1].push_back((energy ? l.predicted_j : l.predicted_s) * scale);
  }
  b.y = y;
  double top = 0.0;  // headroom above the tallest bar, so that it does not look cut off
  for (const auto& row : b.values)
    for (const double v : row)
      if (std::isfinite(v)) top = std::max(top, v);
  if (top > 0.0) b.y.max = niceTicks(0.0, 1.06 * top).hi;
  b.category_label = "leg (from waypoint - to waypoint)";
  b.height = 320;
  return b;
}

void flightSection(HtmlReport& r, const MissionReplayFlight& f, const std::string& suffix, bool several) {
  checkFlight(f);
  r.heading((several ? "Flight " + suffix.substr(1) + ": " : std::string()) + f.name + " against " + f.mission, 3);
  const double kin = f.predicted_energy_j - f.replay_energy_j, phys = f.replay_energy_j - f.measured_energy_j;
  Facts facts = {{"measured", kJWh(f.measured_energy_j) + " in " + formatMinSec(f.measured_time_s) + " min:s"},
                 {"predicted", kJWh(f.predicted_energy_j) + " in " + formatMinSec(f.predicted_time_s) + " min:s: energy " +
                                   pct(f.predicted_energy_j, f.measured_energy_j) + ", time " +
                                   pct(f.predicted_time_s, f.measured_time_s)},
                 {"energy error split", "kinematics " + kJ1(kin) + ", physics " + kJ1(phys)},
                 {"leg time error (MAPE)",
                  std::isfinite(f.leg_time_mape_pct)
                      ? formatNumber(f.leg_time_mape_pct, 1) + " % over " + std::to_string(f.legs.size()) + " legs"
                      : std::string("no leg matched")}};
  if (!f.kinematics_note.empty()) facts.push_back({"where the kinematics differ", f.kinematics_note});
  r.facts(facts);
  r.paragraph("Kinematics: the predicted flight minus the same energy model on the logged kinematics (" +
              kJ1(f.replay_energy_j) +
              "), i.e. what the flight-behaviour model gets wrong. Physics: that replay minus "
              "the measurement, i.e. what the energy model gets wrong on the flight as flown.");
  if (!f.measured_t.empty() || !f.predicted_t.empty()) speedFigure(r, f, suffix);
  if (f.legs.empty()) {
    r.paragraph("No leg between two matched waypoints: no leg figures.");
    return;
  }
  r.figure({"mission-leg-energy" + suffix, renderSvg(legBars(f, "Energy per leg", {"energy", "kJ"}, 1e-3, true)),
            "Energy of each leg between consecutive waypoint passages, measured (logged power) and predicted. Totals: "
            "measured " +
                kJWh(f.measured_energy_j) + ", predicted " + kJWh(f.predicted_energy_j) + " (" +
                pct(f.predicted_energy_j, f.measured_energy_j) + "); kinematics " + kJ1(kin) + ", physics " + kJ1(phys) +
                "."});
  r.figure(
      {"mission-leg-time" + suffix, renderSvg(legBars(f, "Time per leg", {"time", "s"}, 1.0, false)),
       "Time of each leg between consecutive waypoint passages (each passage the middle of the track's dwell within "
       "2 m of its closest approach, interpolated between samples, on the log and the prediction alike). Totals: measured " +
           formatMinSec(f.measured_time_s) + " min:s, predicted " + formatMinSec(f.predicted_time_s) + " min:s (" +
           pct(f.predicted_time_s, f.measured_time_s) + ")."});
}

}  // namespace

void addMissionReplay(HtmlReport& r, const MissionReplayData& d) {
  r.heading("Missions: predicted flight against the log");
  r.paragraph("Each logged flight against the flight predicted from its mission file alone (flight-behaviour model: " +
              (d.autopilot.empty() ? std::string("-") : d.autopilot) +
              "; energy model: " + (d.model.empty() ? std::string("-") : d.model) +
              "). The energy error is split into kinematics and physics.");
  for (std::size_t k = 0; k < d.flights.size(); ++k) {
    flightSection(r, d.flights[k], "-" + std::to_string(k + 1), d.flights.size() > 1);
  }
}

}  // namespace wattswath::report
