#pragma once
/// @file html.hpp
/// One self-contained HTML page: headings, paragraphs, tables and inline SVG figures. No scripts,
/// no network (a Content-Security-Policy forbids it), system fonts only. Figures can also be
/// written as separate .svg files for papers.

#include <string>
#include <vector>

namespace wattswath::report {

/// A table: header, rows of already formatted cells, and which columns are numeric (right-aligned).
struct Table {
  std::string caption;                          ///< shown above the table ("" = none)
  std::vector<std::string> header;              ///< column titles, with units, e.g. "energy [kJ]"
  std::vector<std::vector<std::string>> rows;   ///< cells (escaped on output)
  std::vector<bool> numeric;                    ///< per column: right-align (missing = text)
  bool collapsed = false;                       ///< inside a closed <details> (long tables)
};

/// One inline SVG figure with its caption.
struct Figure {
  std::string name;     ///< file stem when written as .svg (letters, digits, '-', '_')
  std::string svg;      ///< the SVG document (from renderSvg)
  std::string caption;  ///< caption under the figure
};

/// Builds a report page piece by piece.
class HtmlReport {
 public:
  /// Starts a report titled `title`.
  explicit HtmlReport(std::string title);

  /// Adds a heading of `level` 2..4 (the title is level 1).
  void heading(const std::string& text, int level = 2);
  /// Adds a paragraph of plain text (escaped).
  void paragraph(const std::string& text);
  /// Adds a short key/value list (e.g. inputs and totals).
  void facts(const std::vector<std::pair<std::string, std::string>>& items);
  /// Adds a table; throws std::invalid_argument when a row has more cells than the header.
  void table(const Table& t);
  /// Adds a figure inline; throws std::invalid_argument for a bad name or an empty SVG.
  void figure(const Figure& f);

  /// The whole page.
  std::string html() const;
  /// Figures added so far (to write them as separate .svg files).
  const std::vector<Figure>& figures() const { return figures_; }

 private:
  std::string title_;
  std::string body_;
  std::vector<Figure> figures_;
};

/// A standalone SVG file of one figure.
struct SvgFile {
  std::string file_name;  ///< `name`.svg
  std::string content;    ///< XML declaration + the SVG document
};

/// Each figure of `report` as a standalone .svg file (for papers); apps write them.
std::vector<SvgFile> svgFiles(const HtmlReport& report);

}  // namespace wattswath::report
