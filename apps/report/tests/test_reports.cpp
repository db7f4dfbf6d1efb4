// The plan, validation, turn and speed reports: every figure present, well formed, escaped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include "report_samples.hpp"
#include "xml_check.hpp"

using namespace wattswath::test;

namespace {
/// Every inline SVG of a report is well formed; returns how many there are.
int checkFigures(const wr::HtmlReport& r) {
  for (const auto& f : wr::svgFiles(r)) EXPECT_EQ(xmlProblem(f.content), "") << f.file_name;
  const std::string html = r.html();
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(countOf(html, "<svg"), static_cast<int>(r.figures().size()));
  return static_cast<int>(r.figures().size());
}
}  // namespace

TEST(Reports, PlanReportHasMapBreakdownCandidatesAndBattery) {
  const auto r = wr::planReport(samplePlan());
  EXPECT_EQ(checkFigures(r), 5);  // map, breakdown, candidates, SoC, voltage
  const std::string html = r.html();
  EXPECT_NE(html.find("Plan: sample field &lt;test&gt;"), std::string::npos);
  EXPECT_NE(html.find("leg 2 (sweep): 6.00 m/s"), std::string::npos);
  // Table III columns by effect, with the coverage total of Marins et al. Table III's hover column.
  EXPECT_NE(html.find("hover [J]"), std::string::npos);
  EXPECT_NE(html.find("<td>total by effect</td>"), std::string::npos);
  EXPECT_NE(html.find(">50995</td>"), std::string::npos);  // hover: 44295 J coverage (the paper's total) + 6700 J transit
  EXPECT_NE(html.find("home, start"), std::string::npos);   // the path starts at home: one marker
  // Issue 21: the mission items' numbers on the map, take-off and return named at home, a caption
  // that matches the drawing (a hole and a red dashed no-fly zone), Wh beside kJ, savings' base named.
  EXPECT_NE(html.find("home, start, take-off (1), return and landing (12)"), std::string::npos);
  EXPECT_NE(html.find(">11</text>"), std::string::npos);
  EXPECT_NE(html.find("numbers are the mission items"), std::string::npos);
  EXPECT_NE(html.find("holes in the area (white, grey outline) are not flown over; red dashed areas are no-fly zones."),
            std::string::npos);
  EXPECT_NE(html.find("energy [Wh]"), std::string::npos);
  EXPECT_NE(html.find("energy above the chosen plan [% of the chosen plan]"), std::string::npos);
  EXPECT_NE(html.find("chosen: boustrophedon"), std::string::npos);
  EXPECT_NE(html.find("ground-station default"), std::string::npos);
}

namespace {
/// The SVG of the figure named `name` in `r` ("" when there is none).
std::string figureSvg(const wr::HtmlReport& r, const std::string& name) {
  for (const auto& f : r.figures())
    if (f.name == name) return f.svg;
  return "";
}

/// [px] The left edge of a line chart's plot frame (the unfilled grey rect drawn last).
double plotLeft(const std::string& svg) {
  const std::size_t frame = svg.rfind("fill=\"none\" stroke=\"#888888\"");
  const std::size_t rect = svg.rfind("<rect x=\"", frame);
  if (frame == std::string::npos || rect == std::string::npos) return -1.0;
  return std::stod(svg.substr(rect + 9));
}
}  // namespace

// The plan report's battery figure read "state of charge [%]" while it plotted the usable charge
// left, with no reserve line; predict's report draws the same trace as "usable charge left [%]"
// with the reserve. Both are now drawn by one function.
TEST(Reports, PlanBatteryFigureIsPredictsUsableChargeWithTheReserve) {
  const auto r = wr::planReport(samplePlan());
  const std::string svg = figureSvg(r, "plan-battery-soc");
  ASSERT_FALSE(svg.empty());
  EXPECT_NE(svg.find("usable charge left [%]"), std::string::npos);
  EXPECT_NE(svg.find("reserve 25 %"), std::string::npos);
  EXPECT_EQ(svg.find("state of charge"), std::string::npos);
  EXPECT_NE(svg.find("time since the take-off command [min]"), std::string::npos);  // as predict's time axis
  EXPECT_EQ(r.html().find("State of charge over the mission"), std::string::npos);
  EXPECT_NE(r.html().find("counted as the autopilot counts it"), std::string::npos);
}

// A battery that runs out: the usable charge dropped to 0 unlabelled while speed and altitude showed
// a normal flight. Every time plot now marks the cut-off, and the caption says it.
TEST(Reports, MissionReportMarksTheBatteryCutOffOnEveryTimePlot) {
  auto d = sampleMission();
  d.battery->cutoff_s = 161.0;
  const auto r = wr::missionReport(d);
  for (const char* name : {"mission-speed", "mission-altitude", "mission-battery"}) {
    const std::string svg = figureSvg(r, name);
    EXPECT_NE(svg.find(">battery cut-off 2:41</text>"), std::string::npos) << name;
    EXPECT_EQ(xmlProblem(svg), "") << name;
  }
  EXPECT_NE(r.html().find("reaches its cut-off 2:41 min:s into the flight"), std::string::npos);
  EXPECT_EQ(figureSvg(wr::missionReport(sampleMission()), "mission-speed").find("battery cut-off"), std::string::npos);
}

// Predict's stacked time plots (speed, altitude, battery) started their plots at different x (their
// tick labels differ in width: "10", "40", "100"), so one moment was not above the same moment.
TEST(Reports, MissionTimePlotsStartAtOneLeftEdge) {
  const auto r = wr::missionReport(sampleMission());
  const double speed = plotLeft(figureSvg(r, "mission-speed"));
  EXPECT_GT(speed, 0.0);
  EXPECT_DOUBLE_EQ(plotLeft(figureSvg(r, "mission-altitude")), speed);
  EXPECT_DOUBLE_EQ(plotLeft(figureSvg(r, "mission-battery")), speed);
  const auto p = wr::planReport(samplePlan());
  EXPECT_DOUBLE_EQ(plotLeft(figureSvg(p, "plan-battery-voltage")), plotLeft(figureSvg(p, "plan-battery-soc")));
}

TEST(Reports, PlanReportWithoutOptionalPartsSaysSo) {
  wr::PlanReportData d;
  d.areas = samplePlan().areas;
  const auto r = wr::planReport(d);
  EXPECT_EQ(checkFigures(r), 1);
  EXPECT_NE(r.html().find("No energy breakdown was given."), std::string::npos);
  EXPECT_NE(r.html().find("No battery model was given"), std::string::npos);
}

TEST(Reports, ValidationReportHasPowerResidualsLegsStaircaseDiagnosis) {
  const auto d = sampleValidation();
  const auto r = wr::validationReport(d);
  EXPECT_EQ(checkFigures(r), 6);  // power, 3 residuals, legs, staircase
  const std::string html = r.html();
  EXPECT_NE(html.find("samples (1 in 2 shown)"), std::string::npos);  // 6000 samples thinned for display
  EXPECT_NE(html.find("binned mean +- 1 sd"), std::string::npos);
  EXPECT_NE(html.find("C_D A = 0.031 +- 0.002 m^2"), std::string::npos);
  EXPECT_NE(html.find("<title>y = x</title>"), std::string::npos);
  auto bad = d;
  bad.speed.pop_back();
  EXPECT_THROW(wr::validationReport(bad), std::invalid_argument);
  bad = d;
  bad.residual_bins = 1;
  EXPECT_THROW(wr::validationReport(bad), std::invalid_argument);
}

TEST(Reports, ValidationReportDrawsPowerOverTimeForEveryLog) {
  // Two logs one after the other: one power figure each (its own phases), residuals pooled.
  auto d = sampleValidation();
  const std::size_t half = d.t.size() / 2;
  d.log_names = {"first.csv", "second.csv"};
  d.log_start = {0, half};
  for (auto& p : d.phases) p.log = p.t0 >= d.t[half] ? 1 : 0;
  const auto r = wr::validationReport(d);
  EXPECT_EQ(checkFigures(r), 7);  // 2 power, 3 residuals, legs, staircase
  const std::string html = r.html();
  EXPECT_NE(html.find("Measured and modelled electrical power: first.csv"), std::string::npos);
  EXPECT_NE(html.find("Measured and modelled electrical power: second.csv"), std::string::npos);
  EXPECT_NE(html.find("samples of 2 logs"), std::string::npos);
  auto bad = d;
  bad.log_start = {0, d.t.size() + 1};
  EXPECT_THROW(wr::validationReport(bad), std::invalid_argument);
  bad = d;
  bad.log_names = {"only-one.csv"};
  EXPECT_THROW(wr::validationReport(bad), std::invalid_argument);
}

namespace {
/// The y tick labels of a chart (right-aligned texts in its ticks group).
std::vector<std::string> yTickLabels(const std::string& svg) {
  std::vector<std::string> out;
  const std::size_t g = svg.find("class=\"ticks\""), end = svg.find("</g>", g);
  for (std::size_t p = svg.find("text-anchor=\"end\"", g); p < end; p = svg.find("text-anchor=\"end\"", p + 1)) {
    const std::size_t a = svg.find('>', p) + 1;
    out.push_back(svg.substr(a, svg.find('<', a) - a));
  }
  return out;
}
}  // namespace

// Replaying several logs drew each log's power over its own range, so the figures could not be
// compared at a glance; they share one power axis now.
TEST(Reports, PowerFiguresOfSeveralLogsShareOnePowerAxis) {
  auto d = sampleValidation();
  const std::size_t half = d.t.size() / 2;
  d.log_names = {"first.csv", "second.csv"};
  d.log_start = {0, half};
  for (std::size_t i = half; i < d.t.size(); ++i) d.measured_power[i] *= 1.6, d.modelled_power[i] *= 1.6;
  const auto r = wr::validationReport(d);
  const auto first = yTickLabels(figureSvg(r, "validation-power")), second = yTickLabels(figureSvg(r, "validation-power-2"));
  EXPECT_GE(first.size(), 3u);
  EXPECT_EQ(first, second);
  EXPECT_NE(r.html().find("same power axis"), std::string::npos);
}

// fit's staircase was titled "Error as effects are added" with "each bar is the model after one more
// step" under bars that are the model as given and fitted, on the training and on the test logs, all
// in one colour. Its title and caption are fit's own now, and the bars are coloured by the logs.
TEST(Reports, FitStaircaseSaysWhatItsBarsAreAndColoursTrainAndTest) {
  auto d = sampleValidation();
  d.staircase = {{"as given, train", 30.0, "training logs"}, {"fitted, train", 20.0, "training logs"},
                 {"as given, test", 33.0, "test log"}, {"fitted, test", 24.0, "test log"}};
  d.staircase_title = "Error before and after the fit, on the training and the test logs";
  d.staircase_caption = "as given and fitted";
  const auto r = wr::validationReport(d);
  const std::string svg = figureSvg(r, "validation-staircase");
  EXPECT_NE(svg.find("Error before and after the fit"), std::string::npos);
  EXPECT_EQ(r.html().find("one more step"), std::string::npos);
  EXPECT_NE(svg.find(">training logs</text>"), std::string::npos);  // the legend
  EXPECT_NE(svg.find(">test log</text>"), std::string::npos);
  const std::string train = "<title>training logs, fitted, train", test = "<title>test log, fitted, test";
  ASSERT_NE(svg.find(train), std::string::npos);
  ASSERT_NE(svg.find(test), std::string::npos);
  const auto fillBefore = [&](const std::string& title) {
    const std::size_t p = svg.rfind(" fill=\"", svg.find(title)) + 7;
    return svg.substr(p, 7);
  };
  EXPECT_NE(fillBefore(train), fillBefore(test));
  // diagnose's staircase keeps its own title, bars in one colour
  EXPECT_NE(figureSvg(wr::validationReport(sampleValidation()), "validation-staircase").find("Error as effects are added"),
            std::string::npos);
}

// The residual signal "state_of_charge" is 1 - energy drawn / the log's energy, not the pack's
// state of charge; its figure's axis and caption said only its key name.
TEST(Reports, ResidualSignalIsLabelledWithWhatItIs) {
  auto d = sampleValidation();
  d.verdict = "Verdict: unexplained.";
  d.signal_curves = {{"state_of_charge", "-", "follows the share of this log's energy still to be drawn", {0.1, 0.5, 0.9},
                      {3.0, 0.0, -2.0}, "share of this log's energy still to be drawn"}};
  const auto r = wr::validationReport(d);
  const std::string svg = figureSvg(r, "validation-signal-state_of_charge");
  EXPECT_NE(svg.find("energy still to be drawn [-]"), std::string::npos);  // the x axis
  EXPECT_EQ(svg.find("state_of_charge [-]"), std::string::npos);
  EXPECT_NE(r.html().find("binned by share of this log"), std::string::npos);
}

TEST(Reports, PhaseLegendInFlightOrderWhateverComesFirst) {
  // The legend used to list phases in the order they first occur, so two flights' plots listed
  // them differently; now it is ground, climb, hover, accelerate, cruise, brake, turn, descent.
  auto d = sampleValidation();
  std::reverse(d.phases.begin(), d.phases.end());  // a turn comes first now
  const std::string html = wr::validationReport(d).html();
  const auto at = [&](const std::string& label) { return html.find(">" + label + "</text>"); };
  for (const char* label : {"accelerate", "cruise", "brake", "turn"}) ASSERT_NE(at(label), std::string::npos) << label;
  EXPECT_LT(at("accelerate"), at("cruise"));
  EXPECT_LT(at("cruise"), at("brake"));
  EXPECT_LT(at("brake"), at("turn"));
}

TEST(Reports, TurnEnergyChartDrawsOneAngleWhenTheAnglesOverlap) {
  // Table V's energies differ by under 1 % between angles, so four angles' lines hid each other.
  auto d = sampleTurns();
  for (auto& row : d.rows) {  // make the angle matter by 1 part in 1000
    row.sharp_energy = 2 * (1800 + 250 * row.leg_length) * (1.0 + 1e-3 * row.beta);
    row.rounded_energy = 2 * 240 * row.leg_length * (1.0 + 1e-3 * row.beta);
  }
  d.focus_beta = 90.0 * kPi() / 180.0;
  std::string html = wr::turnReport(d).html();
  const auto saving = html.find("Saving of the rounded turn");
  ASSERT_NE(saving, std::string::npos);
  const std::string energy = html.substr(0, saving);
  EXPECT_NE(energy.find("at 90 deg"), std::string::npos);
  EXPECT_NE(energy.find("rounded, 90 deg"), std::string::npos);
  EXPECT_EQ(energy.find("rounded, 45 deg"), std::string::npos);
  EXPECT_NE(energy.find("The other angles (45, 135 deg) lie within 0.2 %"), std::string::npos);
  EXPECT_NE(html.find(">45 deg</text>", saving), std::string::npos);  // the saving chart keeps every angle
  // With the sample's angle-dependent energies (16 % apart) every angle is drawn.
  html = wr::turnReport(sampleTurns()).html();
  EXPECT_NE(html.find("rounded, 45 deg"), std::string::npos);
  EXPECT_EQ(html.find("The other angles"), std::string::npos);
  // Only the sharp stops overlap: all angles drawn, and the caption says which lines coincide.
  d = sampleTurns();
  for (auto& row : d.rows) row.sharp_energy = 2 * (1800 + 250 * row.leg_length) * (1.0 + 1e-3 * row.beta);
  html = wr::turnReport(d).html();
  EXPECT_NE(html.find("rounded, 45 deg"), std::string::npos);
  EXPECT_NE(html.find("The sharp-stop lines of all angles lie within 0.2 % of each other"), std::string::npos);
}

TEST(Reports, TurnAndSpeedReports) {
  const auto t = wr::turnReport(sampleTurns());
  EXPECT_EQ(checkFigures(t), 2);
  // The paper's points are told apart by angle (they were all black, under one legend entry).
  EXPECT_NE(t.html().find("paper (Table V), 45 deg"), std::string::npos);
  EXPECT_NE(t.html().find("paper (Table V), 90 deg"), std::string::npos);
  EXPECT_NE(t.html().find("rounded, 90 deg"), std::string::npos);
  const auto s = wr::speedReport(sampleSpeed());
  EXPECT_EQ(checkFigures(s), 2);
  EXPECT_NE(s.html().find("optimal cruise speed [m/s]"), std::string::npos);
  EXPECT_NE(s.html().find(">1000</text>"), std::string::npos);  // log distance axis (2 .. 1000 m)
}

namespace {
/// No "nan"/"inf" anywhere a reader or an XML parser would see it (tables, labels, attributes).
void expectFinite(const std::string& html) {
  for (const char* bad : {"nan", "NaN", "inf", "Inf"}) {
    for (std::size_t p = html.find(bad); p != std::string::npos; p = html.find(bad, p + 1)) {
      // Words that contain the letters ("information", "infinite", "financial") are fine: only a
      // number-like token, i.e. the letters standing alone, is not.
      const bool alone = (p == 0 || !std::isalpha(static_cast<unsigned char>(html[p - 1]))) &&
                         (p + 3 >= html.size() || !std::isalpha(static_cast<unsigned char>(html[p + 3])));
      EXPECT_FALSE(alone) << "'" << bad << "' in: " << html.substr(p > 60 ? p - 60 : 0, 120);
    }
  }
}
}  // namespace

TEST(Reports, MissionReportHasMapSpeedAltitudeBatteryAndPhaseTable) {
  const auto r = wr::missionReport(sampleMission());
  EXPECT_EQ(checkFigures(r), 4);  // map, speed, altitude, battery
  const std::string html = r.html();
  expectFinite(html);
  EXPECT_NE(html.find("Mission: sample &lt;survey&gt;"), std::string::npos);
  for (const char* axis : {"east of home [m]", "north of home [m]", "speed [m/s]", "time since the take-off command [min]",
                           "height above home [m]", "usable charge left [%]"}) {
    EXPECT_NE(html.find(axis), std::string::npos) << axis;
  }
  // Phases in the map legend, the table and the shading; the reserve line; waypoint numbers (two at one spot).
  for (const char* text : {">take-off</text>", ">mission</text>", ">return</text>", ">landing</text>", "reserve 25 %",
                           ">2, 10</text>", ">12</text>", "home (take-off)", "time [min:s]", "energy [Wh]", "energy [J]",
                           "<td>take-off to landing</td>", "<td class=\"num\">5:10</td>", "<td class=\"num\">18.89</td>",
                           "Fits: lands with 53.5 %", "NAV_RETURN_TO_LAUNCH reached at 5:00 min:s"}) {
    EXPECT_NE(html.find(text), std::string::npos) << text;
  }
  EXPECT_NE(html.find("Take-off and landing are flown vertically"), std::string::npos);
  // Phase colours with dash patterns, so that the phases stay apart in grey-scale print.
  EXPECT_NE(html.find("stroke=\"#009E73\" stroke-dasharray=\"7 3\""), std::string::npos);
}

TEST(Reports, MissionReportWithoutBatterySaysSoAndChecksSizes) {
  auto d = sampleMission();
  d.battery.reset();
  d.verdict = "The vehicle file has no battery: no state of charge or reserve verdict can be given.";
  const auto r = wr::missionReport(d);
  EXPECT_EQ(checkFigures(r), 3);
  EXPECT_NE(r.html().find("The vehicle file has no battery: the usable charge along the flight cannot be shown."), std::string::npos);
  auto bad = sampleMission();
  bad.speed.pop_back();
  EXPECT_THROW(wr::missionReport(bad), std::invalid_argument);
  bad = sampleMission();
  bad.battery->soc.pop_back();
  EXPECT_THROW(wr::missionReport(bad), std::invalid_argument);
  wr::MissionReportData empty;  // no samples: the table, and a sentence instead of figures
  EXPECT_EQ(checkFigures(wr::missionReport(empty)), 0);
  EXPECT_NE(wr::missionReport(empty).html().find("no trajectory samples"), std::string::npos);
}

TEST(Reports, MissionReplayAddsSpeedLegEnergyAndLegTimePerFlight) {
  wr::HtmlReport r("replay");
  wr::addMissionReplay(r, sampleMissionReplay());
  EXPECT_EQ(checkFigures(r), 6);  // per flight: speed, leg energy, leg time
  const std::string html = r.html();
  expectFinite(html);
  for (const char* text : {"Speed along the path: predicted and measured", "time since the take-off command [s]", "speed [m/s]",
                           "Energy per leg", "energy [kJ]", "Time per leg", "time [s]", "measured (log)",
                           "predicted from the mission", ">3-5</text>", "mission &lt;2&gt;.waypoints",
                           "kinematics -5.1 kJ, physics -2.0 kJ", "74.7 kJ (20.8 Wh) in 5:32 min:s",
                           "67.6 kJ (18.8 Wh) in 5:07 min:s: energy -9.6 %, time -7.5 %", "14.4 % over 7 legs",
                           "waypoint 11 passed (measured) at 2:34 min:s"}) {
    EXPECT_NE(html.find(text), std::string::npos) << text;
  }
  // Two series in distinct colours, the predicted one dashed.
  EXPECT_NE(html.find("stroke=\"#444444\""), std::string::npos);
  EXPECT_NE(html.find("stroke=\"#D55E00\" stroke-width=\"1.8\" stroke-linejoin=\"round\" stroke-dasharray=\"6 3\""), std::string::npos);
  // The second flight's unmatched waypoint has no predicted tick; its legs no predicted bars.
  EXPECT_EQ(html.find("waypoint 11 passed (predicted)", html.find("Flight 2")), std::string::npos);
  auto bad = sampleMissionReplay();
  bad.flights[0].measured_speed.pop_back();
  EXPECT_THROW(wr::addMissionReplay(r, bad), std::invalid_argument);
  bad = sampleMissionReplay();
  bad.flights[1].waypoint_labels.pop_back();
  wr::HtmlReport r2("replay");
  EXPECT_THROW(wr::addMissionReplay(r2, bad), std::invalid_argument);
}

TEST(Reports, ReplayReportPutsTheMissionsBeforeTheValidation) {
  wr::HtmlReport r("replay");
  wr::addMissionReplay(r, sampleMissionReplay());
  wr::addValidation(r, sampleValidation());
  EXPECT_EQ(checkFigures(r), 12);  // 6 mission figures, then power, 3 residuals, legs, staircase
  const std::string html = r.html();
  EXPECT_LT(html.find("Missions: predicted flight against the log"), html.find("Power over time"));
}
