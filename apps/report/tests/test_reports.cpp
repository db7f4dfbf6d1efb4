// The plan, validation, turn and speed reports: every figure present, well formed, escaped.
#include <gtest/gtest.h>

#include <algorithm>

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
  EXPECT_NE(html.find("chosen: boustrophedon"), std::string::npos);
  EXPECT_NE(html.find("ground-station default"), std::string::npos);
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
  EXPECT_NE(t.html().find("paper (Table V)"), std::string::npos);
  EXPECT_NE(t.html().find("rounded, 90 deg"), std::string::npos);
  const auto s = wr::speedReport(sampleSpeed());
  EXPECT_EQ(checkFigures(s), 2);
  EXPECT_NE(s.html().find("optimal cruise speed [m/s]"), std::string::npos);
  EXPECT_NE(s.html().find(">1000</text>"), std::string::npos);  // log distance axis (2 .. 1000 m)
}
