#pragma once
/// @file svg.hpp
/// A small SVG writer for the reports: elements with escaped attributes and text, numbers that are
/// always finite, nice axis ticks and print-safe colours. Apps-level only: library modules never draw.

#include <string>
#include <utility>
#include <vector>

namespace wattswath::report {

/// Attribute list of one element, written in order.
using Attrs = std::vector<std::pair<std::string, std::string>>;

/// Escapes `&`, `<`, `>`, `"` and `'` for XML/HTML text and attribute values.
std::string escapeXml(const std::string& text);

/// Formats a coordinate or length for SVG (at most 2 decimals, trailing zeros removed).
/// Throws std::logic_error for NaN or infinity: a chart must never emit them.
std::string svgNum(double value);

/// Formats `value` with `decimals` decimals; "-" for NaN or infinity (tables and tick labels).
std::string formatNumber(double value, int decimals);

/// Formats `value` with `digits` significant digits (at least 0 decimals); "-" when non-finite.
std::string formatSignificant(double value, int digits = 3);

/// Formats a duration [s] as minutes and seconds, "m:ss" (e.g. 307 s -> "5:07"), rounded to the
/// second; "-" when non-finite. Negative durations get a leading "-".
std::string formatMinSec(double seconds);

/// Ticks of an axis: positions in data units and their labels.
struct Ticks {
  std::vector<double> values;       ///< tick positions [data units], increasing
  std::vector<std::string> labels;  ///< one label per tick
  double lo = 0.0;                  ///< [data units] axis start (first tick or below)
  double hi = 1.0;                  ///< [data units] axis end (last tick or above)
};

/// Nice linear ticks (1, 2, 2.5, 5 x 10^k steps) covering [lo, hi] with about `target` ticks
/// (range 2..20). A degenerate range is widened around its value. Throws std::invalid_argument
/// for non-finite bounds.
Ticks niceTicks(double lo, double hi, int target = 6);

/// Decade ticks (1, 2, 5 x 10^k) for a logarithmic axis over [lo, hi]; both must be > 0 and
/// finite (std::invalid_argument otherwise).
Ticks logTicks(double lo, double hi);

/// Colour of series `i` from the Okabe-Ito palette (colour-blind safe, readable in print);
/// black is skipped, the palette repeats after 7.
std::string seriesColour(std::size_t i);

/// A colour on a viridis-like perceptual scale for `t` in [0, 1] (clamped), as "#rrggbb".
/// The light yellow end is left out so thin lines stay visible on white paper.
std::string valueColour(double t);

/// Stroke dash pattern of series `i` ("" = solid) so that lines stay apart in grey-scale print.
std::string seriesDash(std::size_t i);

/// Builds one SVG document element by element. Every open() needs a close(); str() checks it.
class SvgWriter {
 public:
  /// Starts an <svg> of `width` x `height` [px] with the report font and a viewBox.
  SvgWriter(double width, double height);

  /// Opens `<tag attrs>`; attribute values are escaped.
  SvgWriter& open(const std::string& tag, const Attrs& attrs = {});
  /// Closes the innermost open element (throws std::logic_error when none is open).
  SvgWriter& close();
  /// Writes an empty element `<tag attrs/>`.
  SvgWriter& leaf(const std::string& tag, const Attrs& attrs);
  /// Writes `<tag attrs>text</tag>` with `text` escaped.
  SvgWriter& textElement(const std::string& tag, const Attrs& attrs, const std::string& text);
  /// Writes a <text> at (`x`, `y`) [px] with optional extra attributes.
  SvgWriter& text(double x, double y, const std::string& text, const Attrs& attrs = {});
  /// Writes a <title> (hover tooltip) for the enclosing element.
  SvgWriter& title(const std::string& text);
  /// Writes a straight line from (x0, y0) to (x1, y1) [px].
  SvgWriter& line(double x0, double y0, double x1, double y1, const Attrs& attrs = {});
  /// Writes a rectangle [px].
  SvgWriter& rect(double x, double y, double w, double h, const Attrs& attrs = {});

  /// The finished document; throws std::logic_error if elements are still open.
  std::string str() const;

 private:
  std::string out_;
  std::vector<std::string> open_;
};

/// Points of a polyline as an SVG `points` attribute value "x,y x,y ..." [px].
std::string svgPoints(const std::vector<std::pair<double, double>>& pts);

}  // namespace wattswath::report
