// Writing reports: the HTML page and, on request, its figures as separate SVG files.
#include <filesystem>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "wattswath/report/html.hpp"

namespace wattswath::apps {

void addReportOptions(CLI::App* cmd, std::string& html_path, std::string& svg_dir, bool& force) {
  addForceFlag(cmd, force);
  cmd->add_option("--report", html_path, "Write a self-contained HTML report (inline SVG, no network) to this file");
  cmd->add_option("--report-svg", svg_dir, "Also write each report figure as DIR/NAME.svg (for papers)");
}

namespace {

// The --report-svg folder `svg_dir` without a trailing separator ("figs/" -> "figs").
std::string svgFolder(const std::string& svg_dir) {
  std::filesystem::path p(svg_dir);
  if (!p.has_filename()) p = p.parent_path();
  return p.string();
}

}  // namespace

void checkReportWritable(const std::string& html_path, const std::string& svg_dir, bool force,
                         const std::vector<std::string>& inputs) {
  if (!html_path.empty()) checkWritable(html_path, force, inputs);
  if (!svg_dir.empty()) checkOutputFolder(svgFolder(svg_dir));
  std::error_code ec;
  if (!svg_dir.empty() && std::filesystem::exists(svg_dir, ec) && !std::filesystem::is_directory(svg_dir, ec)) {
    throw std::runtime_error(svg_dir + ": is a file, expected a folder for --report-svg");
  }
}

void writeReport(const report::HtmlReport& report, const std::string& html_path, const std::string& svg_dir,
                 bool force) {
  if (!html_path.empty()) {
    writeTextFileAtomic(html_path, report.html());
    progress("report: " + html_path);
  }
  if (!svg_dir.empty()) {
    // The --report-svg folder itself is made when missing, not its parents (a mistyped path is an error).
    checkOutputFolder(svgFolder(svg_dir));
    std::error_code ec;
    std::filesystem::create_directory(svg_dir, ec);
    if (ec && !std::filesystem::is_directory(svg_dir)) throw std::runtime_error(svg_dir + ": cannot create the --report-svg folder (" + ec.message() + ")");
    for (const auto& f : report::svgFiles(report)) {
      const std::string path = (std::filesystem::path(svg_dir) / f.file_name).string();
      checkWritable(path, force);
      writeTextFileAtomic(path, f.content);
      progress("figure: " + path);
    }
  }
}

}  // namespace wattswath::apps
