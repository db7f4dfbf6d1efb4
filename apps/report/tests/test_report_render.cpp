// Renders every report in headless Chromium and checks what a reader would see: the page loads
// with no console messages (no script errors, no blocked network loads), every SVG is in the DOM
// and well formed for a real XML parser, and the screenshot is not blank. Registered only when
// chromium and libpng are found (scripts/setup.sh installs chromium for tests).
#include <png.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "report_samples.hpp"
#include "test_util.hpp"
#include "xml_check.hpp"

namespace fs = std::filesystem;
using namespace wattswath::test;

namespace {

/// What Chromium made of a page.
struct Rendered {
  int status = -1;     ///< exit status of chromium
  std::string dom;     ///< serialised DOM after load (--dump-dom)
  std::string log;     ///< chromium's stderr
  int console = 0;     ///< console messages (script errors, CSP violations, ...)
};

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// Loads `file` in headless Chromium; with `png` also takes a `width` x `height` screenshot.
Rendered render(const std::string& file, const std::string& png = "", int width = 1200, int height = 1600) {
  const fs::path profile = fs::temp_directory_path() / ("wattswath-chromium-" + std::to_string(::getpid()) + "-" +
                                                        fs::path(file).stem().string());
  const std::string err = profile.string() + ".log";
  std::string cmd = "timeout 120 '" + std::string(WATTSWATH_CHROMIUM) +
                    "' --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking"
                    " --disable-component-update --disable-sync --hide-scrollbars --enable-logging=stderr --v=0"
                    " --user-data-dir='" + profile.string() + "'";
  if (!png.empty()) {
    cmd += " --screenshot='" + png + "' --window-size=" + std::to_string(width) + "," + std::to_string(height);
  }
  cmd += " --dump-dom 'file://" + fs::absolute(file).string() + "' 2>'" + err + "'";
  Rendered r;
  const auto res = run(cmd);
  r.status = res.status;
  r.dom = res.output;
  r.log = readFile(err);
  r.console = countOf(r.log, ":CONSOLE");
  std::error_code ec;
  fs::remove_all(profile, ec);
  fs::remove(err, ec);
  return r;
}

/// Pixel statistics of a screenshot.
struct PngStats {
  int width = 0, height = 0;
  double non_white = 0.0;  ///< share of pixels that are not (near) white
  int colours = 0;         ///< distinct colours at 5 bits per channel
};

PngStats pngStats(const std::string& path) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  PngStats s;
  if (!png_image_begin_read_from_file(&img, path.c_str())) return s;
  img.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> buf(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, buf.data(), 0, nullptr)) return s;
  s.width = static_cast<int>(img.width);
  s.height = static_cast<int>(img.height);
  std::set<int> colours;
  std::size_t nonWhite = 0;
  for (std::size_t i = 0; i + 2 < buf.size(); i += 3) {
    const int r = buf[i], g = buf[i + 1], b = buf[i + 2];
    if (r < 245 || g < 245 || b < 245) ++nonWhite;
    colours.insert((r >> 3) << 10 | (g >> 3) << 5 | (b >> 3));
  }
  s.non_white = static_cast<double>(nonWhite) / (static_cast<double>(buf.size()) / 3.0);
  s.colours = static_cast<int>(colours.size());
  return s;
}

std::string renderDir() {
  const std::string d = WATTSWATH_RENDER_DIR;
  fs::create_directories(d);
  return d;
}

/// Loads the page `html` in Chromium and checks it: no console messages, `figures` SVGs in the DOM,
/// each with drawn content and labels, and a screenshot `png` that is not blank.
void checkPage(const std::string& html, const std::string& png, int figures) {
  const Rendered page = render(html, png);
  ASSERT_EQ(page.status, 0) << page.log;
  EXPECT_EQ(page.console, 0) << "console messages while loading " << html << ":\n" << page.log;
  EXPECT_EQ(countOf(page.dom, "<svg"), figures) << "SVGs missing from the DOM of " << html;
  EXPECT_EQ(page.dom.find("parsererror"), std::string::npos);
  for (std::size_t p = page.dom.find("<svg"); p != std::string::npos; p = page.dom.find("<svg", p + 4)) {
    const std::size_t e = page.dom.find("</svg>", p);
    ASSERT_NE(e, std::string::npos);
    const std::string svg = page.dom.substr(p, e - p);
    EXPECT_GE(countOf(svg, "<path") + countOf(svg, "<polyline") + countOf(svg, "<rect") + countOf(svg, "<circle") + countOf(svg, "<line"), 5)
        << "an SVG without drawn content in " << html;
    EXPECT_GE(countOf(svg, "<text"), 3) << "an SVG without labels in " << html;
  }
  const PngStats st = pngStats(png);
  EXPECT_EQ(st.width, 1200);
  EXPECT_EQ(st.height, 1600);
  EXPECT_GT(st.non_white, 0.02) << png << " is (nearly) blank";
  EXPECT_GT(st.colours, 40) << png << " has too few colours to hold figures";
}

/// Writes `report` as `name`.html and its figures as `name`.xhtml (strict XML), renders both in
/// Chromium and checks them. The screenshot stays in the render folder for people to look at.
void checkReport(const wr::HtmlReport& report, const std::string& name, int min_figures) {
  const std::string dir = renderDir();
  const std::string html = dir + "/" + name + ".html", xhtml = dir + "/" + name + ".xhtml";
  writeFile(html, report.html());
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<html xmlns=\"http://www.w3.org/1999/xhtml\"><body>\n";
  for (const auto& f : report.figures()) x += f.svg;
  writeFile(xhtml, x + "</body></html>\n");
  ASSERT_GE(static_cast<int>(report.figures().size()), min_figures);
  checkPage(html, dir + "/" + name + ".png", static_cast<int>(report.figures().size()));
  const Rendered strict = render(xhtml);
  ASSERT_EQ(strict.status, 0) << strict.log;
  EXPECT_EQ(strict.dom.find("parsererror"), std::string::npos) << "XML errors in the figures of " << name << ":\n" << strict.dom.substr(0, 2000);
  EXPECT_EQ(countOf(strict.dom, "<svg"), static_cast<int>(report.figures().size()));
}

/// Runs a wattswath command that writes `name`.html and its SVG files, then checks the page and
/// that every written SVG passes the strict XML check.
void checkCommandReport(const std::string& args, const std::string& name, int figures) {
  const std::string dir = renderDir(), html = dir + "/" + name + ".html", svgs = dir + "/" + name + "-svg";
  fs::remove_all(svgs);
  const auto res = run(cliBinary() + " " + args + " --force --report '" + html + "' --report-svg '" + svgs + "' 2>&1");
  ASSERT_EQ(res.status, 0) << res.output;
  int n = 0;
  for (const auto& f : fs::directory_iterator(svgs)) {
    EXPECT_EQ(xmlProblem(readFile(f.path().string())), "") << f.path();
    ++n;
  }
  EXPECT_EQ(n, figures);
  checkPage(html, dir + "/" + name + ".png", figures);
}

}  // namespace

TEST(ReportRender, ChecksCanFail) {  // negative controls: a blank page, a script, a broken SVG
  const std::string dir = renderDir();
  writeFile(dir + "/control-blank.html",
            "<!DOCTYPE html><html><head><meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'\">"
            "</head><body><script>console.log(1)</script></body></html>");
  const Rendered blank = render(dir + "/control-blank.html", dir + "/control-blank.png", 400, 300);
  ASSERT_EQ(blank.status, 0) << blank.log;
  EXPECT_GE(blank.console, 1) << "a blocked inline script must show up as a console message";
  EXPECT_LT(pngStats(dir + "/control-blank.png").non_white, 0.01);
  writeFile(dir + "/control-broken.xhtml",
            "<html xmlns=\"http://www.w3.org/1999/xhtml\"><body><svg xmlns=\"http://www.w3.org/2000/svg\"><g></svg></body></html>");
  EXPECT_NE(render(dir + "/control-broken.xhtml").dom.find("parsererror"), std::string::npos);
}

TEST(ReportRender, PlanReport) { checkReport(wr::planReport(samplePlan()), "sample-plan", 5); }
// The sorties section (issue 23): every sortie in the legend with its own colour and dash
// pattern on the sorties map, the per-sortie table, the price of splitting and the fleet schedule,
// as Chromium shows them.
void checkSortiesInDom(const std::string& dom, const std::vector<std::string>& names) {
  const std::size_t map = dom.find("Sorties, each in its own colour and dash pattern");
  ASSERT_NE(map, std::string::npos) << "no sorties map";
  const std::string svg = dom.substr(map, dom.find("</svg>", map) - map);
  for (const auto& n : names) EXPECT_NE(svg.find(">" + n + "<"), std::string::npos) << "legend lacks " << n;
  std::set<std::string> styles;  // (stroke colour, dash) of the drawn tracks
  for (std::size_t p = svg.find("<polyline"); p != std::string::npos; p = svg.find("<polyline", p + 1)) {
    const std::string el = svg.substr(p, svg.find('>', p) - p);
    const auto attr = [&](const std::string& a) {
      const std::size_t q = el.find(a + "=\"");
      return q == std::string::npos ? std::string() : el.substr(q + a.size() + 2, el.find('"', q + a.size() + 2) - q - a.size() - 2);
    };
    if (!attr("stroke").empty()) styles.insert(attr("stroke") + "|" + attr("stroke-dasharray"));
  }
  EXPECT_GE(styles.size(), names.size()) << "sorties drawn alike";
  std::set<std::string> dashes;
  for (const auto& st : styles) dashes.insert(st.substr(st.find('|')));
  EXPECT_GE(dashes.size(), std::min<std::size_t>(names.size(), 5)) << "dash patterns repeat";
  for (const char* text : {"Price of splitting", "state of charge at landing", "energy [Wh]", "time [min:s]", "photos", "Fleet schedule",
                           "makespan", "Smallest separation found", "Fleet timeline"})
    EXPECT_NE(dom.find(text), std::string::npos) << "missing: " << text;
}

TEST(ReportRender, PlanReportWithSortiesAndFleet) {
  const auto d = samplePlanWithSorties();
  checkReport(wr::planReport(d), "sample-plan-sorties", 7);
  const Rendered page = render(renderDir() + "/sample-plan-sorties.html");
  ASSERT_EQ(page.status, 0) << page.log;
  checkSortiesInDom(page.dom, {"vehicle 1, sortie 1", "vehicle 1, sortie 2", "vehicle 2, sortie 1"});
  EXPECT_NE(page.dom.find("12:20"), std::string::npos) << "the makespan (740 s) in min:s";
}

TEST(ReportRender, PlanCommandReportWithFleet) {
  const std::string dir = renderDir();
  fs::remove_all(dir + "/cli-plan-fleet-out");
  checkCommandReport("plan '" + sourcePath("data/areas/iris_area.geojson") + "' --vehicle '" + sourcePath("tests/data/iris-small-battery.json") +
                         "' --spacing 15 --vehicles 2 --out '" + dir + "/cli-plan-fleet-out'",
                     "cli-plan-fleet", 7);
  const Rendered page = render(dir + "/cli-plan-fleet.html");
  checkSortiesInDom(page.dom, {"vehicle 1, sortie 1", "vehicle 1, sortie 2", "vehicle 2, sortie 1", "vehicle 2, sortie 2"});
}

TEST(ReportRender, ValidationReport) { checkReport(wr::validationReport(sampleValidation()), "sample-validation", 6); }
TEST(ReportRender, TurnReport) { checkReport(wr::turnReport(sampleTurns()), "sample-turns", 2); }
TEST(ReportRender, SpeedReport) { checkReport(wr::speedReport(sampleSpeed()), "sample-speed", 2); }
TEST(ReportRender, MissionReport) { checkReport(wr::missionReport(sampleMission()), "sample-mission", 4); }
TEST(ReportRender, MissionReplayReport) {
  wr::HtmlReport r("Replay: missions against their logs");
  wr::addMissionReplay(r, sampleMissionReplay());
  wr::addValidation(r, sampleValidation());
  checkReport(r, "sample-replay-mission", 12);
}
TEST(ReportRender, VoptCommandReport) {
  checkCommandReport("vopt --vehicle '" + sourcePath("data/vehicles/iris.json") + "' --distance 100", "cli-vopt", 2);
}
TEST(ReportRender, TurnsCommandReport) {
  checkCommandReport("turns --vehicle '" + sourcePath("data/vehicles/iris.json") + "' --distance 300 --angle 45", "cli-turns", 2);
}
TEST(ReportRender, DiagnoseCommandReport) {
  const std::string f = sharedData("iris-flights/2017-10-18_1436_energy14.csv");
  if (!fs::exists(f)) GTEST_SKIP() << "no " << f;
  // 6 figures plus the residual against the 2 signals carrying it (unexplained: speed squared, speed).
  checkCommandReport("diagnose --vehicle '" + sourcePath("data/vehicles/iris.json") + "' --log '" + f + "'", "cli-diagnose", 8);
}
TEST(ReportRender, DiagnoseCommandReportOfThreeFlights) {
  // Power over time for every log: 3 power figures, 3 residual plots, leg energies, staircase, and
  // the residual against the 3 signals carrying it (unexplained: speed, speed squared, climb rate).
  std::string logs;
  for (const char* name : {"2017-10-18_1436_energy14.csv", "2017-10-18_1449_normal29.csv", "2017-11-20_1610_energy14.csv"}) {
    const std::string f = sharedData(std::string("iris-flights/") + name);
    if (!fs::exists(f)) GTEST_SKIP() << "no " << f;
    logs += " --log '" + f + "'";
  }
  checkCommandReport("diagnose --vehicle '" + sourcePath("data/vehicles/iris.json") + "'" + logs, "cli-diagnose-3", 11);
}
TEST(ReportRender, PredictCommandReport) {
  // Map, speed, altitude and battery of the IRIS+ mission flown by the ArduCopter 3.x model.
  const std::string m = sharedData("iris-flights/mission__2017-10-18_1436_energy14.waypoints");
  if (!fs::exists(m)) GTEST_SKIP() << "no " << m;
  checkCommandReport("predict '" + m + "' --vehicle '" + sourcePath("data/vehicles/iris-plus-arducopter3.json") + "'",
                     "cli-predict", 4);
}
TEST(ReportRender, ReplayMissionCommandReport) {
  // The mission section (speed, leg energy, leg time) and the validation (power, 3 residuals, legs).
  const std::string f = sharedData("iris-flights/2017-10-18_1436_energy14.csv");
  const std::string m = sharedData("iris-flights/mission__2017-10-18_1436_energy14.waypoints");
  if (!fs::exists(f) || !fs::exists(m)) GTEST_SKIP() << "no " << f << " or " << m;
  checkCommandReport("replay --vehicle '" + sourcePath("data/vehicles/iris-plus-arducopter3.json") + "' --log '" + f +
                         "' --mission '" + m + "'",
                     "cli-replay-mission", 8);
}
