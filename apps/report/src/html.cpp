// Self-contained HTML pages with inline SVG figures and tables.
#include "wattswath/report/html.hpp"

#include <cctype>
#include <stdexcept>

#include "wattswath/report/svg.hpp"

namespace wattswath::report {

namespace {
const char* const kStyle =
    "body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,'DejaVu Sans',Helvetica,Arial,sans-serif;"
    "color:#222;background:#fff;max-width:1000px;margin:0 auto;padding:16px 24px;line-height:1.4}"
    "h1{font-size:1.6em;margin:.2em 0 .6em}h2{font-size:1.25em;margin-top:1.6em;border-bottom:1px solid #ddd}"
    "table{border-collapse:collapse;margin:.6em 0;font-size:.92em}"
    "caption{text-align:left;font-weight:bold;padding:.3em 0}"
    "th,td{border:1px solid #ccc;padding:3px 8px}th{background:#f3f3f3;text-align:left}"
    "td.num{text-align:right;font-variant-numeric:tabular-nums}"
    "figure{margin:1em 0}figcaption{font-size:.9em;color:#444;margin-top:.3em}"
    "svg{max-width:100%;height:auto}dl.facts{display:grid;grid-template-columns:max-content auto;gap:2px 16px}"
    "dl.facts dt{font-weight:bold}dl.facts dd{margin:0}"
    "summary{cursor:pointer;font-weight:bold;margin:.6em 0}footer{margin-top:2em;font-size:.8em;color:#666}"
    "@media print{body{max-width:none}h2{break-after:avoid}figure{break-inside:avoid}}";

bool validName(const std::string& n) {
  if (n.empty()) return false;
  for (const char c : n) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') return false;
  }
  return true;
}
}  // namespace

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

void HtmlReport::heading(const std::string& text, int level) {
  const std::string l = std::to_string(level < 2 ? 2 : (level > 4 ? 4 : level));
  body_ += "<h" + l + ">" + escapeXml(text) + "</h" + l + ">\n";
}

void HtmlReport::paragraph(const std::string& text) { body_ += "<p>" + escapeXml(text) + "</p>\n"; }

void HtmlReport::facts(const std::vector<std::pair<std::string, std::string>>& items) {
  body_ += "<dl class=\"facts\">\n";
  for (const auto& [k, v] : items) body_ += "<dt>" + escapeXml(k) + "</dt><dd>" + escapeXml(v) + "</dd>\n";
  body_ += "</dl>\n";
}

void HtmlReport::table(const Table& t) {
  if (t.collapsed) body_ += "<details><summary>" + escapeXml(t.caption.empty() ? "table" : t.caption) + "</summary>\n";
  body_ += "<table>\n";
  if (!t.caption.empty() && !t.collapsed) body_ += "<caption>" + escapeXml(t.caption) + "</caption>\n";
  body_ += "<thead><tr>";
  for (const auto& h : t.header) body_ += "<th>" + escapeXml(h) + "</th>";
  body_ += "</tr></thead>\n<tbody>\n";
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.rows[r].size() > t.header.size()) {
      throw std::invalid_argument("report table '" + t.caption + "': row " + std::to_string(r) + " has " +
                                  std::to_string(t.rows[r].size()) + " cells for " + std::to_string(t.header.size()) +
                                  " columns");
    }
    body_ += "<tr>";
    for (std::size_t c = 0; c < t.rows[r].size(); ++c) {
      const bool num = c < t.numeric.size() && t.numeric[c];
      body_ += std::string(num ? "<td class=\"num\">" : "<td>") + escapeXml(t.rows[r][c]) + "</td>";
    }
    body_ += "</tr>\n";
  }
  body_ += "</tbody>\n</table>\n";
  if (t.collapsed) body_ += "</details>\n";
}

void HtmlReport::figure(const Figure& f) {
  if (!validName(f.name)) throw std::invalid_argument("report figure name '" + f.name + "' must be letters, digits, '-' or '_'");
  if (f.svg.rfind("<svg", 0) != 0) throw std::invalid_argument("report figure '" + f.name + "' is not an SVG document");
  for (const auto& g : figures_) {
    if (g.name == f.name) throw std::invalid_argument("report figure name '" + f.name + "' used twice");
  }
  body_ += "<figure id=\"fig-" + f.name + "\">\n" + f.svg;
  if (!f.caption.empty()) body_ += "<figcaption>" + escapeXml(f.caption) + "</figcaption>\n";
  body_ += "</figure>\n";
  figures_.push_back(f);
}

std::string HtmlReport::html() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; "
         "img-src data:\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         escapeXml(title_) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" + escapeXml(title_) +
         "</h1>\n" + body_ + "<footer>Written by wattswath. Self-contained: no scripts, no network.</footer>\n</body>\n</html>\n";
}

std::vector<SvgFile> svgFiles(const HtmlReport& report) {
  std::vector<SvgFile> out;
  for (const auto& f : report.figures()) {
    out.push_back({f.name + ".svg", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + f.svg});
  }
  return out;
}

}  // namespace wattswath::report
