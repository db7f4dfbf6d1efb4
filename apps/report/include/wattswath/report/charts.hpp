#pragma once
/// @file charts.hpp
/// The report figures as plain data: line/scatter plots, bar charts and a map view. Each renders
/// to one self-contained SVG string (no scripts, no external references, no ids to collide when
/// several figures share one HTML page). Every axis needs a label and a unit.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::report {

/// One axis: what it shows and in which unit. render functions throw std::invalid_argument when
/// the label or the unit is empty (use "1" or "%" for dimensionless quantities).
struct Axis {
  Axis() = default;
  /// An axis showing `label` in `unit`.
  Axis(std::string label_, std::string unit_) : label(std::move(label_)), unit(std::move(unit_)) {}

  std::string label;          ///< quantity, e.g. "speed"
  std::string unit;           ///< unit, e.g. "m/s"; shown as "speed [m/s]"
  std::optional<double> min;  ///< [axis unit] fixed lower end (default: from the data)
  std::optional<double> max;  ///< [axis unit] fixed upper end (default: from the data)
  bool log = false;           ///< logarithmic scale (all shown values must be > 0)
  bool include_zero = false;  ///< extend the automatic range to include 0
};

/// How a series is drawn.
enum class SeriesStyle { Line, Points, LineAndPoints, Steps };

/// One data series of a line/scatter plot. Non-finite points break the line (gaps).
struct Series {
  Series() = default;
  /// A named line through (`x`, `y`).
  Series(std::string name_, std::vector<double> x_, std::vector<double> y_)
      : name(std::move(name_)), x(std::move(x_)), y(std::move(y_)) {}

  std::string name;                       ///< legend entry ("" = not in the legend)
  std::vector<double> x;                  ///< [x axis unit] abscissae
  std::vector<double> y;                  ///< [y axis unit] ordinates (same size as x)
  std::vector<double> y_low;              ///< [y axis unit] optional band lower edge (same size, or empty)
  std::vector<double> y_high;             ///< [y axis unit] optional band upper edge (same size, or empty)
  SeriesStyle style = SeriesStyle::Line;  ///< line, points, both, or steps (y[i] held until x[i+1])
  std::string colour;                     ///< "#rrggbb"; "" = palette colour by series index
  std::string dash;                       ///< SVG dash array; "" = solid (use seriesDash(i) for print)
  double width = 1.8;                     ///< [px] line width
};

/// A shaded x-range (phase of flight, for example).
struct XRange {
  double x0 = 0.0;     ///< [x axis unit] start
  double x1 = 0.0;     ///< [x axis unit] end
  std::string label;   ///< legend/tooltip text; equal labels share one legend entry
  std::string colour;  ///< "#rrggbb" fill (drawn translucent)
};

/// A labelled point (the chosen plan among candidates, for example).
struct Marker {
  double x = 0.0;      ///< [x axis unit]
  double y = 0.0;      ///< [y axis unit]
  std::string label;   ///< text next to the marker
  std::string colour = "#000000";  ///< "#rrggbb"
};

/// A moment marked on the x axis (a waypoint reached, for example): a short tick at the plot's top
/// or bottom edge with a short label. A label that would overlap its neighbour is left out (the
/// tick and its tooltip stay).
struct XEvent {
  double x = 0.0;                  ///< [x axis unit]
  std::string label;               ///< short text next to the tick, e.g. "7"
  std::string tooltip;             ///< hover text (<title>)
  std::string colour = "#222222";  ///< "#rrggbb"
  bool bottom = false;             ///< at the bottom edge instead of the top
};

/// A moment marked across the whole plot: a vertical line with a label at its top (the battery's
/// cut-off, for example).
struct XLine {
  double x = 0.0;                  ///< [x axis unit]
  std::string label;               ///< text beside the line's top, e.g. "battery cut-off 2:41"
  std::string colour = "#B00020";  ///< "#rrggbb"
  std::string dash = "5 3";        ///< SVG dash array ("" = solid)
};

/// A line / scatter plot with a legend.
struct LineChart {
  std::string title;               ///< drawn above the plot
  Axis x;                          ///< horizontal axis
  Axis y;                          ///< vertical axis
  std::vector<Series> series;      ///< data, drawn in order
  std::vector<XRange> shaded;      ///< shaded x-ranges, drawn under the data
  std::vector<Marker> markers;     ///< labelled points, drawn over the data
  std::vector<XEvent> events;      ///< ticks on the top or bottom edge, drawn over the data
  std::vector<XLine> x_lines;      ///< labelled vertical lines across the plot, drawn over the data
  bool diagonal = false;           ///< draw the y = x reference line (measured vs modelled)
  std::optional<double> y_ref;     ///< [y axis unit] draw a horizontal reference line (e.g. 0)
  double width = 900.0;            ///< [px] figure width
  double height = 380.0;           ///< [px] figure height (legend rows are added below)
  /// [px] left margin at least this wide: charts stacked over one time axis given the same
  /// (kStackedLeftMargin) start their plots at the same x whatever their tick labels' widths.
  std::optional<double> left_margin;
};

/// [px] The left margin of line charts stacked over one x axis (room for 5-character tick labels).
inline constexpr double kStackedLeftMargin = 72.0;

/// Renders a line chart to SVG.
std::string renderSvg(const LineChart& chart);

/// A bar chart: one group of bars per category, one bar per series (or stacked).
struct BarChart {
  std::string title;                        ///< drawn above the plot
  std::vector<std::string> categories;      ///< x groups, e.g. "accelerate", "cruise"
  std::vector<std::string> series;          ///< bars in a group / layers of a stack (legend)
  std::vector<std::vector<double>> values;  ///< [y axis unit] values[series][category]
  bool stacked = false;                     ///< stack the series instead of placing them side by side
  std::string category_label;               ///< what the categories are (x axis title; may be empty)
  Axis y;                                   ///< value axis (label and unit required)
  std::vector<std::string> colours;         ///< per series; empty = palette
  double width = 900.0;                     ///< [px] figure width
  double height = 360.0;                    ///< [px] figure height (legend rows are added below)
};

/// Renders a bar chart to SVG; throws std::invalid_argument when the value table's shape does not
/// match the series and categories.
std::string renderSvg(const BarChart& chart);

/// One polyline of the map coloured by a value (one leg of a path, for example).
struct MapPolyline {
  std::vector<geometry::Point> points;  ///< [m] local ENU vertices (arcs already sampled)
  double value = 0.0;                   ///< [value unit] colour value (speed, power, ...)
  std::string tooltip;                  ///< hover text (<title>), e.g. "leg 12 sweep 8.1 m/s"
  bool dashed = false;                  ///< dashed (transits)
  std::string colour{};                 ///< "#rrggbb" fixed colour (a category, e.g. flight phase); "" = `value` on the colour bar
  std::string dash{};                   ///< SVG dash array; overrides `dashed` when not empty
};

/// One line entry of a map's legend (categorical path colours).
struct MapLegendEntry {
  std::string name;    ///< text, e.g. "take-off"
  std::string colour;  ///< "#rrggbb"
  std::string dash;    ///< SVG dash array ("" = solid)
};

/// A point of interest on the map.
struct MapMarker {
  geometry::Point position = geometry::Point::Zero();  ///< [m] local ENU
  std::string label;                                   ///< short text ("start", "home")
  enum class Shape { Circle, Square, Triangle } shape = Shape::Circle;  ///< symbol
  std::string colour = "#000000";                      ///< "#rrggbb"
  double size = 6.0;                                   ///< [px] symbol radius (a waypoint dot: 3)
};

/// A map in local metres (north up, equal scale): areas with holes, no-fly zones, a path coloured
/// by a value with a colour bar (or by category with a legend) and a scale bar or metre axes.
struct MapView {
  std::string title;                                 ///< drawn above the map
  std::vector<geometry::PolygonWithHoles> areas;     ///< survey areas (holes left unfilled)
  std::vector<geometry::Ring> no_fly;                ///< no-fly zones (drawn hatched-red)
  std::vector<MapPolyline> path;                     ///< path pieces coloured by value
  std::vector<MapMarker> markers;                    ///< start, home, ...
  std::string value_label;                           ///< colour-bar quantity, e.g. "speed"
  std::string value_unit;                            ///< colour-bar unit, e.g. "m/s"
  std::vector<MapLegendEntry> legend;                ///< line legend under the map (for fixed path colours)
  bool axes = false;                                 ///< east/north axes with ticks in metres instead of the scale bar
  double width = 900.0;                              ///< [px] figure width
  double height = 600.0;                             ///< [px] figure height (legend rows are added below)
};

/// Renders a map to SVG; throws std::invalid_argument when there is nothing to draw or the value
/// label/unit are missing while a path piece is coloured by value.
std::string renderSvg(const MapView& map);

}  // namespace wattswath::report
