// The SVG/HTML report toolkit: escaping, finite numbers, ticks, well-formed figures, units on axes.
#include <cmath>
#include <limits>
#include <regex>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "wattswath/report/charts.hpp"
#include "wattswath/report/html.hpp"
#include "wattswath/report/svg.hpp"
#include "xml_check.hpp"

namespace wr = wattswath::report;
using wattswath::test::countOf;
using wattswath::test::xmlProblem;

namespace {

wr::LineChart sampleLine() {
  wr::LineChart c;
  c.title = "power <measured> & \"modelled\"";
  c.x = {"time", "s"};
  c.y = {"power", "W"};
  wr::Series a{"measured", {0, 1, 2, 3, 4}, {100, 180, 150, 160, 90}};
  wr::Series b{"modelled", {0, 1, 2, 3, 4}, {110, 170, 155, 150, 95}};
  b.style = wr::SeriesStyle::LineAndPoints;
  b.dash = wr::seriesDash(1);
  c.series = {a, b};
  c.shaded = {{0, 1, "accelerate", "#E69F00"}, {1, 3, "cruise", "#56B4E9"}, {3, 4, "brake", "#CC79A7"}};
  return c;
}

/// Extracts every numeric attribute value of `attr` in `svg`.
std::vector<double> attrValues(const std::string& svg, const std::string& attr) {
  std::vector<double> out;
  const std::regex re(" " + attr + "=\"([-0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator(); ++it) {
    out.push_back(std::stod((*it)[1]));
  }
  return out;
}

}  // namespace

TEST(ReportSvg, EscapesAllMarkupCharacters) {
  EXPECT_EQ(wr::escapeXml("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(wr::escapeXml(std::string("x\x01y")), "x y");  // control characters are not XML
}

TEST(ReportSvg, NumbersAreFiniteAndShort) {
  EXPECT_EQ(wr::svgNum(1.0), "1");
  EXPECT_EQ(wr::svgNum(-0.001), "0");
  EXPECT_EQ(wr::svgNum(12.345), "12.35");
  EXPECT_THROW(wr::svgNum(std::nan("")), std::logic_error);
  EXPECT_THROW(wr::svgNum(std::numeric_limits<double>::infinity()), std::logic_error);
  EXPECT_EQ(wr::formatNumber(std::nan(""), 2), "-");
  EXPECT_EQ(wr::formatNumber(-0.0001, 2), "0.00");
  EXPECT_EQ(wr::formatSignificant(1234.6), "1235");
  EXPECT_EQ(wr::formatSignificant(0.012345), "0.0123");
}

TEST(ReportSvg, NiceTicksCoverTheRangeWithRoundSteps) {
  const auto t = wr::niceTicks(0.3, 9.3, 6);
  ASSERT_GE(t.values.size(), 3u);
  EXPECT_LE(t.lo, 0.3);
  EXPECT_GE(t.hi, 9.3);
  EXPECT_EQ(t.labels.front(), "0");
  EXPECT_EQ(t.labels.back(), "10");
  const double step = t.values[1] - t.values[0];
  EXPECT_NEAR(step, 2.0, 1e-12);
  const auto small = wr::niceTicks(0.0, 0.9, 4);
  EXPECT_NEAR(small.values[1] - small.values[0], 0.25, 1e-12);
  EXPECT_EQ(small.labels[1], "0.25");
  const auto flat = wr::niceTicks(5.0, 5.0);  // degenerate range widened
  EXPECT_LT(flat.lo, 5.0);
  EXPECT_GT(flat.hi, 5.0);
  EXPECT_THROW(wr::niceTicks(0.0, std::nan("")), std::invalid_argument);
  const auto lg = wr::logTicks(3.0, 400.0);
  EXPECT_DOUBLE_EQ(lg.lo, 1.0);
  EXPECT_DOUBLE_EQ(lg.hi, 1000.0);
  EXPECT_THROW(wr::logTicks(0.0, 10.0), std::invalid_argument);
}

TEST(ReportSvg, ColoursArePrintSafeHex) {
  const std::regex hex("#[0-9a-fA-F]{6}");
  for (std::size_t i = 0; i < 10; ++i) EXPECT_TRUE(std::regex_match(wr::seriesColour(i), hex));
  EXPECT_NE(wr::seriesColour(0), wr::seriesColour(1));
  for (double t : {-1.0, 0.0, 0.3, 1.0, 2.0, std::nan("")}) EXPECT_TRUE(std::regex_match(wr::valueColour(t), hex)) << t;
  EXPECT_NE(wr::valueColour(0.0), wr::valueColour(1.0));
  EXPECT_NE(wr::valueColour(1.0), "#fde725");  // the faint yellow end is left out
}

TEST(ReportSvg, WriterChecksNesting) {
  wr::SvgWriter w(100, 50);
  w.open("g");
  EXPECT_THROW(w.str(), std::logic_error);
  w.close();
  EXPECT_THROW(w.close(), std::logic_error);
  EXPECT_EQ(xmlProblem(w.str()), "");
}

TEST(ReportSvg, XmlCheckerCatchesBrokenDocuments) {  // the checker itself must be able to fail
  EXPECT_NE(xmlProblem("<svg><g></svg>"), "");
  EXPECT_NE(xmlProblem("<svg x=\"nan\"/>"), "");
  EXPECT_NE(xmlProblem("<svg>a & b</svg>"), "");
  EXPECT_NE(xmlProblem("<svg a=\"1\" a=\"2\"/>"), "");
  EXPECT_EQ(xmlProblem("<svg a=\"1\"><t>&lt;</t></svg>"), "");
}

TEST(ReportSvg, LineChartIsWellFormedWithUnitsLegendAndPhases) {
  auto c = sampleLine();
  c.series[0].y[2] = std::nan("");  // a gap, never "nan" in the output
  c.diagonal = false;
  c.markers = {{2, 150, "chosen"}};
  const std::string svg = wr::renderSvg(c);
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_NE(svg.find("time [s]"), std::string::npos);
  EXPECT_NE(svg.find("power [W]"), std::string::npos);
  EXPECT_NE(svg.find("power &lt;measured&gt; &amp; &quot;modelled&quot;"), std::string::npos);
  EXPECT_NE(svg.find(">measured</text>"), std::string::npos);
  EXPECT_NE(svg.find(">cruise</text>"), std::string::npos);  // phase swatch in the legend
  EXPECT_EQ(countOf(svg, "fill-opacity=\"0.26\""), 6);           // three shaded phases and their swatches
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("id="), std::string::npos);  // no ids that could collide in one page
  // Every drawn coordinate lies inside the figure.
  for (const char* a : {"x", "y", "cx", "cy", "x1", "x2", "y1", "y2"}) {
    for (const double v : attrValues(svg, a)) {
      EXPECT_GE(v, -1.0) << a;
      EXPECT_LE(v, c.width + 1.0) << a;
    }
  }
}

TEST(ReportSvg, AxesWithoutUnitsAreRejected) {
  auto c = sampleLine();
  c.y.unit = "";
  EXPECT_THROW(wr::renderSvg(c), std::invalid_argument);
  c = sampleLine();
  c.series[1].y.pop_back();
  EXPECT_THROW(wr::renderSvg(c), std::invalid_argument);
  c = sampleLine();
  c.x.log = true;  // x includes 0: a log axis cannot show it
  c.x.min = 0.0;
  EXPECT_THROW(wr::renderSvg(c), std::invalid_argument);
}

TEST(ReportSvg, DiagonalAndLogAxes) {
  wr::LineChart c;
  c.x = {"modelled leg energy", "kJ"};
  c.y = {"measured leg energy", "kJ"};
  c.diagonal = true;
  c.series = {{"legs", {1, 2, 3}, {1.1, 1.9, 3.3}}};
  c.series[0].style = wr::SeriesStyle::Points;
  std::string svg = wr::renderSvg(c);
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_NE(svg.find("<title>y = x</title>"), std::string::npos);
  EXPECT_EQ(countOf(svg, "<circle"), 3 + 1);  // 3 points + legend symbol
  c.diagonal = false;
  c.x.log = true;
  c.series[0].x = {1, 100, 10000};
  svg = wr::renderSvg(c);
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_NE(svg.find(">10000</text>"), std::string::npos);
}

TEST(ReportSvg, LinesOutsideFixedRangeAreClipped) {
  wr::LineChart c;
  c.x = {"x", "m"};
  c.y = {"y", "m"};
  c.y.min = 0.0;
  c.y.max = 1.0;
  c.series = {{"s", {0, 1, 2}, {0.5, 50, 0.5}}};
  const std::string svg = wr::renderSvg(c);
  EXPECT_EQ(xmlProblem(svg), "");
  const std::regex re("d=\"([^\"]*)\"");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, re));
  const std::regex num("[ML]([-0-9.]+) ([-0-9.]+)");
  const std::string d = m[1];
  for (auto it = std::sregex_iterator(d.begin(), d.end(), num); it != std::sregex_iterator(); ++it) {
    EXPECT_GE(std::stod((*it)[2]), 11.9);  // top of the plot area (no title)
  }
}

TEST(ReportSvg, BarChartsGroupedAndStacked) {
  wr::BarChart b;
  b.title = "Energy by phase";
  b.categories = {"accelerate", "cruise", "brake", "turn"};
  b.series = {"hover", "kinetic", "drag"};
  b.values = {{10, 50, 10, 8}, {3, 0, 3, 0}, {0.5, 4, 0.5, 0}};
  b.y = {"energy", "kJ"};
  std::string svg = wr::renderSvg(b);
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_EQ(countOf(svg, "<title>"), 9);  // zero bars are not drawn
  EXPECT_NE(svg.find("<title>kinetic, brake: 3.00 kJ</title>"), std::string::npos);
  b.stacked = true;
  svg = wr::renderSvg(b);
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_NE(svg.find(">54.0</text>"), std::string::npos);  // cruise stack total
  b.values.pop_back();
  EXPECT_THROW(wr::renderSvg(b), std::invalid_argument);
}

// Legend swatches were drawn at fill-opacity 0.6 whatever they stood for: paler than the opaque
// bars, far darker than the phase bands (0.16). A swatch now has the opacity of what it names.
TEST(ReportSvg, LegendSwatchesLookLikeTheBarsAndBandsTheyName) {
  wr::BarChart b;
  b.categories = {"a", "b"};
  b.series = {"hover", "kinetic"};
  b.values = {{1, 2}, {3, 4}};
  b.y = {"energy", "kJ"};
  std::string svg = wr::renderSvg(b);
  EXPECT_EQ(svg.find("fill-opacity=\"0.6\""), std::string::npos);
  std::set<std::string> opacities;
  for (std::size_t p = svg.find("fill-opacity=\""); p != std::string::npos; p = svg.find("fill-opacity=\"", p + 1))
    opacities.insert(svg.substr(p + 14, svg.find('"', p + 14) - p - 14));
  EXPECT_EQ(opacities, std::set<std::string>{"1"});  // legend swatches as opaque as the bars (drawn without opacity)
  svg = wr::renderSvg(sampleLine());  // three phase bands
  std::vector<double> bands;  // translucent fills: the bands and their swatches (points are opaque)
  for (const double o : attrValues(svg, "fill-opacity"))
    if (o < 1.0) bands.push_back(o);
  ASSERT_EQ(bands.size(), 6u);  // 3 bands and 3 swatches
  for (const double o : bands) EXPECT_DOUBLE_EQ(o, bands.front());
  EXPECT_GE(bands.front(), 0.25);  // take-off and landing colours told apart at band opacity
}

// The chosen candidate's ring sat on the plot's bottom frame: the y axis started at its value (the
// lowest energy). A chart with markers leaves room round the data.
TEST(ReportSvg, MarkersAtTheDataEdgeAreNotOnTheFrame) {
  wr::LineChart c;
  c.x = {"sweep angle", "deg"};
  c.y = {"energy", "kJ"};
  c.series = {wr::Series("candidates", {0, 45, 90, 135}, {120, 131, 140, 129})};
  c.markers = {{0, 120, "chosen", "#000000"}};
  const std::string svg = wr::renderSvg(c);
  const std::size_t frame = svg.rfind("fill=\"none\" stroke=\"#888888\"");
  const std::string rect = svg.substr(svg.rfind("<rect", frame), frame - svg.rfind("<rect", frame));
  const auto ys = attrValues(rect, "y"), hs = attrValues(rect, "height");
  ASSERT_EQ(ys.size(), 1u);
  const double bottom = ys[0] + hs[0];
  const std::size_t ring = svg.find("r=\"6\"");
  ASSERT_NE(ring, std::string::npos);
  const std::string circle = svg.substr(svg.rfind("<circle", ring), ring - svg.rfind("<circle", ring));
  const auto cy = attrValues(circle, "cy");
  ASSERT_EQ(cy.size(), 1u);
  EXPECT_LE(cy[0] + 6.0, bottom - 2.0) << "the ring touches the bottom frame";
}

TEST(ReportSvg, MapWithHolesPathMarkersAndBars) {
  wr::MapView m;
  m.title = "Plan";
  wattswath::geometry::PolygonWithHoles a;
  a.outer = {{0, 0}, {200, 0}, {200, 100}, {0, 100}};
  a.holes = {{{50, 40}, {50, 60}, {80, 60}, {80, 40}}};
  m.areas = {a};
  m.no_fly = {{{120, 20}, {140, 20}, {140, 40}}};
  m.path = {{{{10, 10}, {190, 10}}, 8.0, "leg 1 <sweep>"}, {{{190, 10}, {190, 30}}, 3.0, "leg 2 turn"},
            {{{190, 30}, {10, 30}}, 8.0, "leg 3 sweep"}};
  m.path[1].dashed = true;
  m.markers = {{{0, 0}, "home", wr::MapMarker::Shape::Square}, {{10, 10}, "start", wr::MapMarker::Shape::Triangle, "#009E73"}};
  m.value_label = "speed";
  m.value_unit = "m/s";
  const std::string svg = wr::renderSvg(m);
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_EQ(countOf(svg, "<polyline"), 3);
  EXPECT_NE(svg.find("<title>leg 1 &lt;sweep&gt;</title>"), std::string::npos);
  EXPECT_NE(svg.find("fill-rule=\"evenodd\""), std::string::npos);
  EXPECT_NE(svg.find(">20 m</text>"), std::string::npos);  // scale bar: a round length below 1/5 of the map width (~42 m)
  EXPECT_NE(svg.find(">[m/s]</text>"), std::string::npos);
  EXPECT_NE(svg.find(wr::valueColour(0.0)), std::string::npos);  // slowest leg at the low end
  m.value_unit = "";
  EXPECT_THROW(wr::renderSvg(m), std::invalid_argument);
  EXPECT_THROW(wr::renderSvg(wr::MapView{}), std::invalid_argument);
}

TEST(ReportSvg, MapByCategoryWithLegendAndMetreAxes) {
  // A path coloured by phase needs no colour bar (and no value label); axes in metres replace the scale bar.
  wr::MapView m;
  m.title = "Track";
  m.axes = true;
  m.path = {{{{0, 0}, {100, 0}}, 0.0, "mission"}, {{{100, 0}, {0, 0}}, 0.0, "return"}};
  m.path[0].colour = "#0072B2";
  m.path[1].colour = "#009E73";
  m.path[1].dash = "7 3";
  m.legend = {{"mission", "#0072B2", ""}, {"return", "#009E73", "7 3"}};
  wr::MapMarker wp{{100, 0}, "3, 7", wr::MapMarker::Shape::Circle, "#222222"};
  wp.size = 3.0;
  m.markers = {wp};
  const std::string svg = wr::renderSvg(m);
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_EQ(svg.find("colourbar"), std::string::npos);
  EXPECT_EQ(svg.find("scalebar"), std::string::npos);
  EXPECT_NE(svg.find(">east of home [m]</text>"), std::string::npos);
  EXPECT_NE(svg.find(">north of home [m]</text>"), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"#009E73\" stroke-dasharray=\"7 3\""), std::string::npos);
  EXPECT_NE(svg.find(">return</text>"), std::string::npos);  // legend
  EXPECT_NE(svg.find("r=\"3\""), std::string::npos);          // the small waypoint dot
  m.path[1].colour.clear();                                   // one piece by value: the colour bar needs its unit
  EXPECT_THROW(wr::renderSvg(m), std::invalid_argument);
}

// Waypoints close together on a map (a stop and the next leg's start, home and the last item) have
// their numbers placed around the dot where they overlap no other label; a fifth at the same place
// keeps its tooltip and leaves its label out rather than printing it over the others.
TEST(ReportSvg, MapLabelsAreMovedRoundTheirMarkerNotDrawnOverEachOther) {
  wr::MapView m;
  m.axes = true;
  m.path = {{{{0, 0}, {100, 0}}, 0.0, "mission"}};
  m.path[0].colour = "#0072B2";
  for (const char* label : {"11", "12", "13", "14", "15"}) {
    wr::MapMarker wp{{50, 0}, label, wr::MapMarker::Shape::Circle, "#222222"};
    wp.size = 3.0;
    m.markers.push_back(wp);
  }
  const std::string svg = wr::renderSvg(m);
  EXPECT_EQ(xmlProblem(svg), "");
  std::set<std::pair<std::string, std::string>> corners;  // (x, y) of each label drawn
  for (const char* label : {"11", "12", "13", "14"}) {
    const std::size_t end = svg.find(std::string(">") + label + "</text>");
    ASSERT_NE(end, std::string::npos) << label;
    const std::size_t start = svg.rfind("<text", end);
    const std::string tag = svg.substr(start, end - start);
    const auto attr = [&](const std::string& name) {
      const std::size_t a = tag.find(" " + name + "=\"") + name.size() + 3;
      return tag.substr(a, tag.find('"', a) - a);
    };
    corners.insert({attr("x"), attr("y")});
  }
  EXPECT_EQ(corners.size(), 4u);                                // four places round the dot
  EXPECT_EQ(svg.find(">15</text>"), std::string::npos);         // no fifth place: left out
  EXPECT_NE(svg.find("<title>15 ("), std::string::npos);        // its tooltip stays
}

namespace {

/// The x and y attributes of the <text> whose content is `label` in `svg` (NaN when not drawn).
std::pair<double, double> textAt(const std::string& svg, const std::string& label) {
  const std::size_t end = svg.find(">" + label + "</text>");
  if (end == std::string::npos) return {std::nan(""), std::nan("")};
  const std::string tag = svg.substr(svg.rfind("<text", end), end - svg.rfind("<text", end));
  const auto attr = [&](const std::string& name) {
    const std::size_t a = tag.find(" " + name + "=\"") + name.size() + 3;
    return std::stod(tag.substr(a, tag.find('"', a) - a));
  };
  return {attr("x"), attr("y")};
}

}  // namespace

// The plan map's home label ("home, start, take-off (1), return and landing (70)") was placed
// right of a home at the map's edge, starting at x=-220 / running past the viewBox: a label now goes
// to the next place round its marker when the first is not inside the plot area. Waypoint numbers
// "50" and "49" side by side ran together as "5049": the width assumed per bold digit (0.62 em) was
// less than DejaVu Sans Bold's 0.696 em; labels on one line now keep apart by their drawn width.
TEST(ReportSvg, MapLabelsStayInsideThePlotAndApartAsDrawn) {
  const std::string home = "home, start, take-off (1), return and landing (70)";
  for (const double hx : {0.0, 100.0}) {  // home at the left edge, then at the right edge
    wr::MapView m;
    m.path = {{{{0, 0}, {100, 0}}, 0.0, "mission"}};
    m.path[0].colour = "#0072B2";
    wr::MapMarker last{{hx, 0.5}, "69", wr::MapMarker::Shape::Circle, "#222222"};  // the last waypoint, at home
    last.size = 3.0;
    m.markers.push_back(last);
    m.markers.push_back({{hx, 0}, home, wr::MapMarker::Shape::Square, "#000000"});
    const std::string svg = wr::renderSvg(m);
    const auto [x, y] = textAt(svg, home);
    ASSERT_TRUE(std::isfinite(x)) << "home label left out";
    EXPECT_GE(x, 0.0) << "home at " << hx;
    EXPECT_LE(x + 0.696 * 12 * static_cast<double>(home.size()), m.width) << "home at " << hx;
  }
  for (double d = 1.0; d <= 3.0; d += 0.05) {  // [m] apart: on the screen about 8 to 25 px
    wr::MapView m;
    m.path = {{{{0, 0}, {100, 0}}, 0.0, "mission"}};
    m.path[0].colour = "#0072B2";
    for (const auto& [label, x] : {std::pair<std::string, double>{"50", 50.0}, {"49", 50.0 + d}}) {
      wr::MapMarker wp{{x, 0}, label, wr::MapMarker::Shape::Circle, "#222222"};
      wp.size = 3.0;
      m.markers.push_back(wp);
    }
    const std::string svg = wr::renderSvg(m);
    const auto a = textAt(svg, "50"), b = textAt(svg, "49");
    if (!std::isfinite(a.first) || !std::isfinite(b.first) || a.second != b.second) continue;  // on different lines
    const double drawn = 0.696 * 11 * 2;  // [px] two bold 11 px digits in DejaVu Sans Bold
    EXPECT_GE(std::abs(b.first - a.first), drawn + 1.0) << "labels run together at " << d << " m apart";
  }
}

TEST(ReportSvg, EventTicksSitOutsideThePlotAndLabelsDoNotOverlap) {
  wr::LineChart c = sampleLine();
  c.events = {{1.0, "12", "waypoint 12", "#222222", false}, {1.01, "13", "waypoint 13", "#222222", false},
              {3.0, "14", "waypoint 14 (log)", "#444444", true}};
  const std::string svg = wr::renderSvg(c);
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_NE(svg.find("<title>waypoint 13</title>"), std::string::npos);  // every tick keeps its tooltip
  EXPECT_NE(svg.find(">12</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">13</text>"), std::string::npos);  // too close to 12: label left out
  EXPECT_NE(svg.find(">14</text>"), std::string::npos);
  // The plot frame starts below the top ticks: nothing is drawn over the data.
  const auto frame = svg.find("fill=\"none\" stroke=\"#888888\"");
  ASSERT_NE(frame, std::string::npos);
  EXPECT_NE(svg.rfind("<rect x=\"", frame), std::string::npos);
  EXPECT_NE(svg.substr(svg.rfind("<rect x=\"", frame), frame - svg.rfind("<rect x=\"", frame)).find("y=\"48\""), std::string::npos)
      << svg.substr(svg.rfind("<rect x=\"", frame), 200);
}

TEST(ReportSvg, MinutesAndSeconds) {
  EXPECT_EQ(wr::formatMinSec(0.0), "0:00");
  EXPECT_EQ(wr::formatMinSec(307.4), "5:07");
  EXPECT_EQ(wr::formatMinSec(59.6), "1:00");
  EXPECT_EQ(wr::formatMinSec(3725.0), "62:05");
  EXPECT_EQ(wr::formatMinSec(-65.0), "-1:05");
  EXPECT_EQ(wr::formatMinSec(std::numeric_limits<double>::quiet_NaN()), "-");
}

TEST(ReportHtml, SelfContainedPageWithTablesAndFigures) {
  wr::HtmlReport r("Report <1>");
  r.heading("Figures");
  r.paragraph("a & b");
  r.facts({{"total energy", "12.3 kJ"}});
  r.table({"Table III", {"phase", "energy [kJ]"}, {{"cruise", "50.0"}, {"<b>", "1"}}, {false, true}});
  r.figure({"power", wr::renderSvg(sampleLine()), "Power over time"});
  const std::string html = r.html();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("Content-Security-Policy"), std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("http://www.w3.org/2000/svg"), html.find("http:"));  // the only URL is the SVG namespace
  EXPECT_EQ(html.find("https:"), std::string::npos);
  EXPECT_EQ(countOf(html, "<svg"), 1);
  EXPECT_EQ(countOf(html, "<td class=\"num\">"), 2);
  const auto files = wr::svgFiles(r);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].file_name, "power.svg");
  EXPECT_EQ(xmlProblem(files[0].content), "");
  EXPECT_THROW(r.figure({"power", wr::renderSvg(sampleLine()), ""}), std::invalid_argument);  // name used twice
  EXPECT_THROW(r.figure({"bad name", wr::renderSvg(sampleLine()), ""}), std::invalid_argument);
  EXPECT_THROW(r.table({"t", {"a"}, {{"1", "2"}}, {}}), std::invalid_argument);
}
