#pragma once
// Internal to apps/report/src: layout constants, legends and data ranges shared by the line, bar
// and map figures (charts.cpp, map_chart.cpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "wattswath/report/svg.hpp"

namespace wattswath::report::detail {

constexpr double kCharWidth = 6.6;           ///< [px] rough width of one 12 px character, for layout
constexpr double kLegendRow = 18.0;          ///< [px] height of one legend row
inline const char* const kGrid = "#e3e3e3";  ///< grid line colour
inline const char* const kInk = "#222222";   ///< text and axis colour
/// Fill opacity of a line chart's shaded x ranges (flight phases) and of their legend swatches; at
/// the 0.16 used before, take-off (#D55E00) and landing (#CC79A7) bands were hard to tell apart.
constexpr double kBandOpacity = 0.26;

/// Rough width [px] of `s` in a `font` px font.
inline double textWidth(const std::string& s, double font = 12.0) {
  return kCharWidth * font / 12.0 * static_cast<double>(s.size());
}

/// Legend entry kinds.
enum class LegendKind { Line, Points, Swatch };

/// One legend entry: a line (with its dash), a point or a filled swatch.
struct LegendItem {
  std::string name;                    ///< text
  std::string colour;                  ///< "#rrggbb"
  std::string dash;                    ///< SVG dash array ("" = solid)
  LegendKind kind = LegendKind::Line;  ///< symbol
  double opacity = 1.0;                ///< a swatch's fill opacity: that of what it stands for (a bar 1, a band kBandOpacity)
};

/// The legend laid out in rows that fit `width` [px].
std::vector<std::vector<LegendItem>> legendRows(const std::vector<LegendItem>& items, double width);

/// Draws legend `rows` from (`x0`, `y0`) [px] down.
void drawLegend(SvgWriter& svg, const std::vector<std::vector<LegendItem>>& rows, double x0, double y0);

/// Running min/max over finite values.
struct Range {
  double lo = std::numeric_limits<double>::infinity();   ///< smallest value seen
  double hi = -std::numeric_limits<double>::infinity();  ///< largest value seen
  /// Adds `v` unless it is not finite (or not positive on a log axis).
  void add(double v, bool log) {
    if (!std::isfinite(v) || (log && v <= 0.0)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  /// True when no value was added.
  bool empty() const { return lo > hi; }
};

}  // namespace wattswath::report::detail
