// Line and bar figures rendered to self-contained SVG with the SvgWriter.
#include "wattswath/report/charts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "chart_common.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report {

namespace detail {

std::vector<std::vector<LegendItem>> legendRows(const std::vector<LegendItem>& items, double width) {
  std::vector<std::vector<LegendItem>> rows;
  double x = 0.0;
  for (const auto& it : items) {
    const double w = 30.0 + textWidth(it.name) + 18.0;
    if (rows.empty() || (x + w > width && !rows.back().empty())) {
      rows.emplace_back();
      x = 0.0;
    }
    rows.back().push_back(it);
    x += w;
  }
  return rows;
}

void drawLegend(SvgWriter& svg, const std::vector<std::vector<LegendItem>>& rows, double x0, double y0) {
  double y = y0;
  for (const auto& row : rows) {
    double x = x0;
    for (const auto& it : row) {
      const double cy = y + kLegendRow / 2;
      if (it.kind == LegendKind::Swatch) {
        svg.rect(x, cy - 6, 24, 12, {{"fill", it.colour}, {"fill-opacity", svgNum(it.opacity)}, {"stroke", it.colour},
                                     {"stroke-opacity", svgNum(std::min(1.0, 2.0 * it.opacity))}});
      } else if (it.kind == LegendKind::Points) {
        svg.leaf("circle", {{"cx", svgNum(x + 12)}, {"cy", svgNum(cy)}, {"r", "3"}, {"fill", it.colour}});
      } else {
        Attrs a = {{"stroke", it.colour}, {"stroke-width", "2.2"}};
        if (!it.dash.empty()) a.push_back({"stroke-dasharray", it.dash});
        svg.line(x, cy, x + 24, cy, a);
      }
      svg.text(x + 30, cy + 4, it.name, {{"fill", kInk}});
      x += 30.0 + textWidth(it.name) + 18.0;
    }
    y += kLegendRow;
  }
}

}  // namespace detail

using namespace detail;

namespace {

std::string axisTitle(const Axis& a, const char* which) {
  if (a.label.empty() || a.unit.empty()) {
    throw std::invalid_argument(std::string("chart: the ") + which + " axis needs a label and a unit (got label '" +
                                a.label + "', unit '" + a.unit + "')");
  }
  return a.label + " [" + a.unit + "]";
}

/// Maps data values to pixels along one axis.
struct Scale {
  double lo = 0, hi = 1, p0 = 0, p1 = 1;
  bool log = false;
  double t(double v) const { return log ? std::log10(v) : v; }
  double operator()(double v) const { return p0 + (t(v) - t(lo)) / (t(hi) - t(lo)) * (p1 - p0); }
  bool valid(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
};

/// Axis ticks for the data range [lo, hi] and the axis settings.
Ticks axisTicks(const Axis& a, double lo, double hi) {
  if (a.include_zero && !a.log) {
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
  }
  if (a.min) lo = *a.min;
  if (a.max) hi = *a.max;
  if (a.log && (!(lo > 0.0) || !(hi > 0.0))) {
    throw std::invalid_argument("chart: log axis '" + a.label + "' needs positive values and bounds");
  }
  Ticks t = a.log ? logTicks(lo, hi) : niceTicks(lo, hi);
  if (a.min || a.max) {  // fixed ends: keep them exactly, drop ticks outside
    const double flo = a.min ? *a.min : t.lo, fhi = a.max ? *a.max : t.hi;
    if (!(fhi > flo)) throw std::invalid_argument("chart: axis '" + a.label + "' has max <= min");
    Ticks k;
    k.lo = flo;
    k.hi = fhi;
    const double eps = 1e-9 * (fhi - flo);
    for (std::size_t i = 0; i < t.values.size(); ++i) {
      if (t.values[i] >= flo - eps && t.values[i] <= fhi + eps) {
        k.values.push_back(t.values[i]);
        k.labels.push_back(t.labels[i]);
      }
    }
    return k;
  }
  return t;
}

/// Clips segment (x0,y0)-(x1,y1) to the box (Liang-Barsky). Returns false when fully outside.
bool clipSegment(double& x0, double& y0, double& x1, double& y1, double bx0, double by0, double bx1, double by1) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = x1 - x0, dy = y1 - y0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x0 - bx0, bx1 - x0, y0 - by0, by1 - y0};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
    } else {
      const double r = q[i] / p[i];
      if (p[i] < 0.0) {
        if (r > t1) return false;
        t0 = std::max(t0, r);
      } else {
        if (r < t0) return false;
        t1 = std::min(t1, r);
      }
    }
  }
  const double nx0 = x0 + t0 * dx, ny0 = y0 + t0 * dy, nx1 = x0 + t1 * dx, ny1 = y0 + t1 * dy;
  x0 = nx0;
  y0 = ny0;
  x1 = nx1;
  y1 = ny1;
  return true;
}

/// Path data "M..L.." for a polyline in pixels, clipped to the box; gaps at non-finite points.
std::string clippedPathData(const std::vector<std::pair<double, double>>& px, double bx0, double by0, double bx1,
                            double by1) {
  std::string d;
  double lastx = std::numeric_limits<double>::quiet_NaN(), lasty = lastx;
  for (std::size_t i = 0; i + 1 < px.size(); ++i) {
    double x0 = px[i].first, y0 = px[i].second, x1 = px[i + 1].first, y1 = px[i + 1].second;
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) continue;
    if (!clipSegment(x0, y0, x1, y1, bx0, by0, bx1, by1)) continue;
    if (!(std::abs(x0 - lastx) < 1e-6 && std::abs(y0 - lasty) < 1e-6)) d += "M" + svgNum(x0) + " " + svgNum(y0);
    d += "L" + svgNum(x1) + " " + svgNum(y1);
    lastx = x1;
    lasty = y1;
  }
  return d;
}

void checkSeries(const Series& s, std::size_t index) {
  const auto name = "series " + std::to_string(index) + " '" + s.name + "'";
  if (s.x.size() != s.y.size()) {
    throw std::invalid_argument("chart: " + name + " has " + std::to_string(s.x.size()) + " x values but " +
                                std::to_string(s.y.size()) + " y values");
  }
  if ((!s.y_low.empty() && s.y_low.size() != s.x.size()) || (!s.y_high.empty() && s.y_high.size() != s.x.size()) ||
      (s.y_low.empty() != s.y_high.empty())) {
    throw std::invalid_argument("chart: " + name + " band edges y_low/y_high must both have one value per x");
  }
}

/// Event ticks just outside the top or bottom edge of the plot [px box], in x order per edge;
/// labels left out where they would overlap the previous one on the same edge.
void drawEvents(SvgWriter& svg, const std::vector<XEvent>& events, const Scale& sx, double px0, double py0, double px1,
                double py1) {
  if (events.empty()) return;
  std::vector<const XEvent*> order;
  for (const auto& e : events) {
    if (sx.valid(e.x) && sx(e.x) >= px0 - 0.5 && sx(e.x) <= px1 + 0.5) order.push_back(&e);
  }
  std::stable_sort(order.begin(), order.end(), [](const XEvent* a, const XEvent* b) { return a->x < b->x; });
  double lastEnd[2] = {-1e300, -1e300};  // [px] right end of the last label, top and bottom
  svg.open("g", {{"class", "events"}, {"font-size", "10"}});
  for (const XEvent* e : order) {
    const double X = sx(e->x);
    svg.open("g", {});
    if (!e->tooltip.empty()) svg.title(e->tooltip);
    if (e->bottom) {
      svg.line(X, py1, X, py1 + 6, {{"stroke", e->colour}, {"stroke-width", "1.6"}});
    } else {
      svg.line(X, py0 - 6, X, py0, {{"stroke", e->colour}, {"stroke-width", "1.6"}});
    }
    const double w = 1.15 * textWidth(e->label, 10.0);
    double& last = lastEnd[e->bottom ? 1 : 0];
    const double lx = std::clamp(X, px0 + w / 2, std::max(px0 + w / 2, px1 - w / 2));  // inside the plot's width
    if (!e->label.empty() && lx - w / 2 > last + 4) {
      svg.text(lx, e->bottom ? py1 + 16 : py0 - 8, e->label, {{"text-anchor", "middle"}, {"fill", e->colour}});
      last = lx + w / 2;
    }
    svg.close();
  }
  svg.close();
}

/// The data ranges of a line chart's two axes: series and their bands, markers, shaded ranges,
/// events and the reference line; a unit range when there is no data; one range for both axes when
/// the chart has a diagonal.
std::pair<Range, Range> lineChartRanges(const LineChart& c) {
  Range xr, yr;
  for (std::size_t i = 0; i < c.series.size(); ++i) {
    const auto& s = c.series[i];
    checkSeries(s, i);
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      xr.add(s.x[k], c.x.log);
      yr.add(s.y[k], c.y.log);
      if (!s.y_low.empty()) {
        yr.add(s.y_low[k], c.y.log);
        yr.add(s.y_high[k], c.y.log);
      }
    }
  }
  for (const auto& m : c.markers) {
    xr.add(m.x, c.x.log);
    yr.add(m.y, c.y.log);
  }
  for (const auto& r : c.shaded) {
    xr.add(r.x0, c.x.log);
    xr.add(r.x1, c.x.log);
  }
  for (const auto& e : c.events) xr.add(e.x, c.x.log);
  for (const auto& l : c.x_lines) xr.add(l.x, c.x.log);
  if (c.y_ref) yr.add(*c.y_ref, c.y.log);
  if (!c.markers.empty() && !yr.empty() && !c.y.log && !c.diagonal) {
    // A marker's ring (6 px) at the data's lowest or highest value sat on the frame (the chosen plan
    // at the candidates' lowest energy): the range gets 6 % of room on each side.
    const double pad = 0.06 * std::max(yr.hi - yr.lo, 1e-9 * std::max(1.0, std::abs(yr.hi)));
    yr = {yr.lo - pad, yr.hi + pad};
  }
  if (xr.empty()) xr = {c.x.log ? 1.0 : 0.0, c.x.log ? 10.0 : 1.0};
  if (yr.empty()) yr = {c.y.log ? 1.0 : 0.0, c.y.log ? 10.0 : 1.0};
  if (c.diagonal) {  // measured vs modelled: same range on both axes
    const double lo = std::min(xr.lo, yr.lo), hi = std::max(xr.hi, yr.hi);
    xr = yr = {lo, hi};
  }
  return {xr, yr};
}

/// The legend of a line chart: series with names, then distinct shaded-range labels.
std::vector<LegendItem> lineChartLegend(const LineChart& c) {
  std::vector<LegendItem> items;
  for (std::size_t i = 0; i < c.series.size(); ++i) {
    const auto& s = c.series[i];
    if (s.name.empty()) continue;
    items.push_back({s.name, s.colour.empty() ? seriesColour(i) : s.colour, s.dash,
                     s.style == SeriesStyle::Points ? LegendKind::Points : LegendKind::Line});
  }
  std::map<std::string, bool> seen;
  for (const auto& r : c.shaded) {
    if (r.label.empty() || seen[r.label]) continue;
    seen[r.label] = true;
    items.push_back({r.label, r.colour.empty() ? "#999999" : r.colour, "", LegendKind::Swatch, kBandOpacity});
  }
  return items;
}

/// Where a line chart's plot box sits in its figure [px], and the legend rows below it.
struct PlotFrame {
  double px0 = 0, px1 = 0, py0 = 0, py1 = 0;  ///< [px] the plot box
  double events_bottom = 0;                   ///< [px] room for event ticks under the box
  double height = 0;                          ///< [px] the whole figure, legend included
  std::vector<std::vector<LegendItem>> rows;  ///< the legend, row by row
};

/// The left margin that fits the y tick labels, the axis title and a gap [px].
double leftMargin(const Ticks& yt) {
  std::size_t ylabel_chars = 0;
  for (const auto& l : yt.labels) ylabel_chars = std::max(ylabel_chars, l.size());
  return 30.0 + kCharWidth * static_cast<double>(ylabel_chars) + 8.0;
}

/// Margins around a plot box [px].
struct Margins {
  double left, right, top, bottom;
};

/// Lays out a figure `width` x `height` [px] (the legend's rows are added below `height`) with the
/// plot box inside margins `m`; `what` names the chart in the error when the box would be too small.
PlotFrame layoutFrame(double width, double height, const Margins& m, const std::vector<LegendItem>& items, const char* what) {
  PlotFrame f;
  f.rows = legendRows(items, width - m.left - m.right);
  f.height = height + kLegendRow * static_cast<double>(f.rows.size()) + (f.rows.empty() ? 0.0 : 6.0);
  f.px0 = m.left;
  f.px1 = width - m.right;
  f.py0 = m.top;
  f.py1 = height - m.bottom;
  if (f.px1 - f.px0 < 50 || f.py1 - f.py0 < 50) throw std::invalid_argument(std::string(what) + ": figure too small for its axes");
  return f;
}

/// Lays out a line chart: room for the y tick labels, the title, event ticks outside the box (they
/// never hide data) and the legend.
PlotFrame lineChartFrame(const LineChart& c, const Ticks& yt, const std::vector<LegendItem>& items) {
  const auto onEdge = [&](bool bottomEdge) {
    return std::any_of(c.events.begin(), c.events.end(), [&](const XEvent& e) { return e.bottom == bottomEdge; });
  };
  const double events_top = onEdge(false) ? 16.0 : 0.0, events_bottom = onEdge(true) ? 16.0 : 0.0;
  PlotFrame f = layoutFrame(c.width, c.height, {std::max(leftMargin(yt), c.left_margin.value_or(0.0)), 18.0, (c.title.empty() ? 12.0 : 32.0) + events_top,
                                                46.0 + events_bottom},
                            items, "chart");
  f.events_bottom = events_bottom;
  return f;
}

/// Shaded x ranges, drawn under everything else.
void drawShaded(SvgWriter& svg, const LineChart& c, const Scale& sx, const PlotFrame& f) {
  for (const auto& r : c.shaded) {
    if (!sx.valid(r.x0) || !sx.valid(r.x1)) continue;
    const double a = std::clamp(sx(std::min(r.x0, r.x1)), f.px0, f.px1);
    const double b = std::clamp(sx(std::max(r.x0, r.x1)), f.px0, f.px1);
    if (b <= a) continue;
    svg.open("rect", {{"x", svgNum(a)}, {"y", svgNum(f.py0)}, {"width", svgNum(b - a)}, {"height", svgNum(f.py1 - f.py0)},
                      {"fill", r.colour.empty() ? "#999999" : r.colour}, {"fill-opacity", svgNum(kBandOpacity)}});
    svg.title(r.label + ": " + formatNumber(r.x0, 2) + " to " + formatNumber(r.x1, 2) + " " + c.x.unit);
    svg.close();
  }
}

/// Grid, tick labels and the two axis titles.
void drawAxes(SvgWriter& svg, const LineChart& c, const Ticks& xt, const Ticks& yt, const Scale& sx, const Scale& sy,
              const PlotFrame& f) {
  svg.open("g", {{"class", "grid"}, {"stroke", kGrid}, {"stroke-width", "1"}});
  for (const double v : xt.values) svg.line(sx(v), f.py0, sx(v), f.py1);
  for (const double v : yt.values) svg.line(f.px0, sy(v), f.px1, sy(v));
  svg.close();
  svg.open("g", {{"class", "ticks"}, {"fill", kInk}, {"font-size", "11"}});
  for (std::size_t i = 0; i < xt.values.size(); ++i) {
    svg.text(sx(xt.values[i]), f.py1 + 15 + f.events_bottom, xt.labels[i], {{"text-anchor", "middle"}});
  }
  for (std::size_t i = 0; i < yt.values.size(); ++i) {
    svg.text(f.px0 - 5, sy(yt.values[i]) + 4, yt.labels[i], {{"text-anchor", "end"}});
  }
  svg.close();
  svg.text((f.px0 + f.px1) / 2, f.py1 + 34 + f.events_bottom, axisTitle(c.x, "x"),
           {{"text-anchor", "middle"}, {"fill", kInk}});
  svg.text(0, 0, axisTitle(c.y, "y"),
           {{"text-anchor", "middle"}, {"fill", kInk},
            {"transform", "translate(14," + svgNum((f.py0 + f.py1) / 2) + ") rotate(-90)"}});
}

/// The horizontal reference line and the y = x diagonal, where the chart asks for them.
void drawReferenceLines(SvgWriter& svg, const LineChart& c, const Ticks& xt, const Ticks& yt, const Scale& sx,
                        const Scale& sy, const PlotFrame& f) {
  if (c.y_ref && sy.valid(*c.y_ref) && *c.y_ref >= std::min(yt.lo, yt.hi) && *c.y_ref <= std::max(yt.lo, yt.hi)) {
    svg.line(f.px0, sy(*c.y_ref), f.px1, sy(*c.y_ref), {{"stroke", "#666666"}, {"stroke-width", "1"}});
  }
  if (!c.diagonal) return;
  const double lo = std::max(xt.lo, yt.lo), hi = std::min(xt.hi, yt.hi);
  if (hi > lo && sx.valid(lo) && sy.valid(lo)) {
    svg.open("line", {{"x1", svgNum(sx(lo))}, {"y1", svgNum(sy(lo))}, {"x2", svgNum(sx(hi))}, {"y2", svgNum(sy(hi))},
                      {"stroke", "#555555"}, {"stroke-width", "1.2"}, {"stroke-dasharray", "5 4"}});
    svg.title("y = x");
    svg.close();
  }
}

/// A series' band between y_low and y_high, as one filled polygon.
void drawBand(SvgWriter& svg, const Series& s, const std::string& colour, const Scale& sx, const Scale& sy,
              const PlotFrame& f) {
  std::vector<std::pair<double, double>> up, lowv;
  for (std::size_t k = 0; k < s.x.size(); ++k) {
    if (!sx.valid(s.x[k]) || !sy.valid(s.y_low[k]) || !sy.valid(s.y_high[k])) continue;
    const double x = std::clamp(sx(s.x[k]), f.px0, f.px1);
    up.push_back({x, std::clamp(sy(s.y_high[k]), f.py0, f.py1)});
    lowv.push_back({x, std::clamp(sy(s.y_low[k]), f.py0, f.py1)});
  }
  std::reverse(lowv.begin(), lowv.end());
  up.insert(up.end(), lowv.begin(), lowv.end());
  if (up.size() >= 3) svg.leaf("polygon", {{"points", svgPoints(up)}, {"fill", colour}, {"fill-opacity", "0.18"}, {"stroke", "none"}});
}

/// A series' line (or steps), clipped to the plot box, with gaps at values the axes cannot show.
void drawLine(SvgWriter& svg, const Series& s, const std::string& colour, const Scale& sx, const Scale& sy,
              const PlotFrame& f) {
  std::vector<std::pair<double, double>> px;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < s.x.size(); ++k) {
    const bool ok = sx.valid(s.x[k]) && sy.valid(s.y[k]);
    const double X = ok ? sx(s.x[k]) : nan, Y = ok ? sy(s.y[k]) : nan;
    px.push_back({X, Y});
    if (s.style == SeriesStyle::Steps && k + 1 < s.x.size()) {
      const bool ok2 = ok && sx.valid(s.x[k + 1]);
      px.push_back({ok2 ? sx(s.x[k + 1]) : nan, Y});
    }
  }
  const std::string d = clippedPathData(px, f.px0, f.py0, f.px1, f.py1);
  if (d.empty()) return;
  Attrs a = {{"d", d}, {"fill", "none"}, {"stroke", colour}, {"stroke-width", svgNum(s.width)}, {"stroke-linejoin", "round"}};
  if (!s.dash.empty()) a.push_back({"stroke-dasharray", s.dash});
  svg.leaf("path", a);
}

/// True when the pixel (X, Y) lies in the plot box (half a pixel of tolerance).
bool inBox(const PlotFrame& f, double X, double Y) {
  return !(X < f.px0 - 0.5 || X > f.px1 + 0.5 || Y < f.py0 - 0.5 || Y > f.py1 + 0.5);
}

/// One series: its band, then its line, then its points.
void drawSeries(SvgWriter& svg, const Series& s, const std::string& colour, const Scale& sx, const Scale& sy,
                const PlotFrame& f) {
  svg.open("g", {{"class", "series"}});
  if (!s.name.empty()) svg.title(s.name);
  if (!s.y_low.empty()) drawBand(svg, s, colour, sx, sy, f);
  if (s.style != SeriesStyle::Points) drawLine(svg, s, colour, sx, sy, f);
  if (s.style == SeriesStyle::Points || s.style == SeriesStyle::LineAndPoints) {
    svg.open("g", {{"fill", colour}, {"fill-opacity", s.style == SeriesStyle::Points ? "0.55" : "1"}});
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      if (!sx.valid(s.x[k]) || !sy.valid(s.y[k])) continue;
      const double X = sx(s.x[k]), Y = sy(s.y[k]);
      if (inBox(f, X, Y)) svg.leaf("circle", {{"cx", svgNum(X)}, {"cy", svgNum(Y)}, {"r", "2.6"}});
    }
    svg.close();
  }
  svg.close();
}

/// Labelled markers, drawn on top of the series.
void drawMarkers(SvgWriter& svg, const LineChart& c, const Scale& sx, const Scale& sy, const PlotFrame& f) {
  for (const auto& m : c.markers) {
    if (!sx.valid(m.x) || !sy.valid(m.y)) continue;
    const double X = sx(m.x), Y = sy(m.y);
    if (!inBox(f, X, Y)) continue;
    svg.open("g", {{"class", "marker"}});
    svg.title(m.label + " (" + formatNumber(m.x, 2) + " " + c.x.unit + ", " + formatNumber(m.y, 2) + " " + c.y.unit + ")");
    svg.leaf("circle", {{"cx", svgNum(X)}, {"cy", svgNum(Y)}, {"r", "6"}, {"fill", "none"}, {"stroke", m.colour}, {"stroke-width", "2"}});
    const bool leftSide = X > (f.px0 + f.px1) / 2;
    svg.text(X + (leftSide ? -9 : 9), Y - 8, m.label, {{"fill", m.colour}, {"text-anchor", leftSide ? "end" : "start"}, {"font-weight", "bold"}});
    svg.close();
  }
}

/// Labelled vertical lines across the plot (a battery cut-off), drawn over the data; the label sits
/// at the line's top, inside the plot, on the side with room.
void drawXLines(SvgWriter& svg, const LineChart& c, const Scale& sx, const PlotFrame& f) {
  for (const auto& l : c.x_lines) {
    if (!sx.valid(l.x)) continue;
    const double X = sx(l.x);
    if (X < f.px0 - 0.5 || X > f.px1 + 0.5) continue;
    svg.open("g", {{"class", "x-line"}});
    svg.title(l.label);
    Attrs a = {{"stroke", l.colour}, {"stroke-width", "1.8"}};
    if (!l.dash.empty()) a.push_back({"stroke-dasharray", l.dash});
    svg.line(X, f.py0, X, f.py1, a);
    const bool leftSide = X + 6 + textWidth(l.label, 11) > f.px1;
    svg.text(X + (leftSide ? -5 : 5), f.py0 + 14, l.label,
             {{"fill", l.colour}, {"font-size", "11"}, {"font-weight", "bold"}, {"text-anchor", leftSide ? "end" : "start"},
              {"stroke", "#ffffff"}, {"stroke-width", "3"}, {"paint-order", "stroke"}});
    svg.close();
  }
}

}  // namespace

std::string renderSvg(const LineChart& c) {
  axisTitle(c.x, "x");  // both axes need a label and a unit, checked before anything is laid out
  axisTitle(c.y, "y");
  const auto [xr, yr] = lineChartRanges(c);
  const Ticks xt = axisTicks(c.x, xr.lo, xr.hi), yt = axisTicks(c.y, yr.lo, yr.hi);
  const PlotFrame f = lineChartFrame(c, yt, lineChartLegend(c));
  const Scale sx{xt.lo, xt.hi, f.px0, f.px1, c.x.log}, sy{yt.lo, yt.hi, f.py1, f.py0, c.y.log};

  SvgWriter svg(c.width, f.height);
  svg.rect(0, 0, c.width, f.height, {{"fill", "#ffffff"}});
  if (!c.title.empty()) svg.text(f.px0, 20, c.title, {{"font-size", "14"}, {"font-weight", "bold"}, {"fill", kInk}});
  drawShaded(svg, c, sx, f);
  drawAxes(svg, c, xt, yt, sx, sy, f);
  drawReferenceLines(svg, c, xt, yt, sx, sy, f);
  for (std::size_t i = 0; i < c.series.size(); ++i) {
    const auto& s = c.series[i];
    drawSeries(svg, s, s.colour.empty() ? seriesColour(i) : s.colour, sx, sy, f);
  }
  drawMarkers(svg, c, sx, sy, f);
  drawXLines(svg, c, sx, f);
  drawEvents(svg, c.events, sx, f.px0, f.py0, f.px1, f.py1);
  svg.rect(f.px0, f.py0, f.px1 - f.px0, f.py1 - f.py0, {{"fill", "none"}, {"stroke", "#888888"}, {"stroke-width", "1"}});
  drawLegend(svg, f.rows, f.px0, c.height - 4);
  return svg.str();
}

namespace {

/// Checks a bar chart's shape: a linear value axis, one value row per series, one value per category.
void checkBarChart(const BarChart& c) {
  axisTitle(c.y, "value");
  if (c.y.log) throw std::invalid_argument("bar chart: a logarithmic value axis is not supported");
  if (c.values.size() != c.series.size()) {
    throw std::invalid_argument("bar chart '" + c.title + "': " + std::to_string(c.values.size()) + " value rows for " +
                                std::to_string(c.series.size()) + " series");
  }
  for (std::size_t s = 0; s < c.values.size(); ++s) {
    if (c.values[s].size() != c.categories.size()) {
      throw std::invalid_argument("bar chart '" + c.title + "': series '" + c.series[s] + "' has " +
                                  std::to_string(c.values[s].size()) + " values for " +
                                  std::to_string(c.categories.size()) + " categories");
    }
  }
}

/// The value range a bar chart shows: zero, every bar, and every stack's positive and negative sums.
Range barValueRange(const BarChart& c) {
  Range r;
  r.add(0.0, false);
  for (std::size_t k = 0; k < c.categories.size(); ++k) {
    double pos = 0.0, neg = 0.0;
    for (std::size_t s = 0; s < c.series.size(); ++s) {
      const double v = c.values[s][k];
      if (!std::isfinite(v)) continue;
      if (c.stacked) {
        (v >= 0 ? pos : neg) += v;
      } else {
        r.add(v, false);
      }
    }
    r.add(pos, false);
    r.add(neg, false);
  }
  return r;
}

/// The colour of bar series `s`: the chart's own, else the palette's.
std::string barColour(const BarChart& c, std::size_t s) {
  return s < c.colours.size() && !c.colours[s].empty() ? c.colours[s] : seriesColour(s);
}

/// Lays out a bar chart: room for the value tick labels, the title, the category label and the legend.
PlotFrame barChartFrame(const BarChart& c, const Ticks& yt) {
  std::vector<LegendItem> items;
  for (std::size_t s = 0; s < c.series.size(); ++s) items.push_back({c.series[s], barColour(c, s), "", LegendKind::Swatch});
  return layoutFrame(c.width, c.height,
                     {leftMargin(yt), 18.0, c.title.empty() ? 12.0 : 32.0, c.category_label.empty() ? 30.0 : 46.0}, items,
                     "bar chart");
}

/// Grid, value tick labels, the value axis title and the category label.
void drawBarAxes(SvgWriter& svg, const BarChart& c, const Ticks& yt, const Scale& sy, const PlotFrame& f) {
  svg.open("g", {{"class", "grid"}, {"stroke", kGrid}});
  for (const double v : yt.values) svg.line(f.px0, sy(v), f.px1, sy(v));
  svg.close();
  svg.open("g", {{"class", "ticks"}, {"fill", kInk}, {"font-size", "11"}});
  for (std::size_t i = 0; i < yt.values.size(); ++i) svg.text(f.px0 - 5, sy(yt.values[i]) + 4, yt.labels[i], {{"text-anchor", "end"}});
  svg.close();
  svg.text(0, 0, axisTitle(c.y, "value"),
           {{"text-anchor", "middle"}, {"fill", kInk}, {"transform", "translate(14," + svgNum((f.py0 + f.py1) / 2) + ") rotate(-90)"}});
  if (!c.category_label.empty()) {
    svg.text((f.px0 + f.px1) / 2, f.py1 + 36, c.category_label, {{"text-anchor", "middle"}, {"fill", kInk}});
  }
}

/// Category `k`: its label (shrunk, down to 8 px, to keep a gap to its neighbours), its bars side
/// by side or stacked, and a stack's total above it.
void drawCategory(SvgWriter& svg, const BarChart& c, std::size_t k, const Scale& sy, const PlotFrame& f) {
  const std::size_t nc = c.categories.size(), ns = c.series.size();
  const double band = (f.px1 - f.px0) / static_cast<double>(nc);
  const double group = 0.76 * band;
  const double barw = c.stacked || ns == 0 ? group : group / static_cast<double>(ns);
  const double gx = f.px0 + band * static_cast<double>(k) + (band - group) / 2;
  const double fs = std::min(12.0, std::max(8.0, (band - 5.0) / std::max<std::size_t>(1, c.categories[k].size()) / 0.62));
  svg.text(f.px0 + band * (static_cast<double>(k) + 0.5), f.py1 + 16, c.categories[k],
           {{"text-anchor", "middle"}, {"fill", kInk}, {"font-size", svgNum(fs)}});
  double pos = 0.0, neg = 0.0;
  for (std::size_t s = 0; s < ns; ++s) {
    const double v = c.values[s][k];
    if (!std::isfinite(v) || v == 0.0) continue;
    double a = 0.0, b = v, x = gx + barw * static_cast<double>(s);
    if (c.stacked) {
      double& base = v >= 0 ? pos : neg;
      a = base;
      b = base + v;
      base = b;
      x = gx;
    }
    const double y0 = std::clamp(sy(std::max(a, b)), f.py0, f.py1), y1 = std::clamp(sy(std::min(a, b)), f.py0, f.py1);
    svg.open("rect", {{"x", svgNum(x)}, {"y", svgNum(y0)}, {"width", svgNum(std::max(1.0, barw - 1.0))},
                      {"height", svgNum(std::max(0.0, y1 - y0))}, {"fill", barColour(c, s)}, {"stroke", "#ffffff"},
                      {"stroke-width", "0.5"}});
    svg.title(c.series[s] + ", " + c.categories[k] + ": " + formatSignificant(v) + " " + c.y.unit);
    svg.close();
  }
  if (c.stacked && ns > 1 && pos > 0.0) {
    svg.text(gx + group / 2, std::clamp(sy(pos), f.py0, f.py1) - 4, formatSignificant(pos),
             {{"text-anchor", "middle"}, {"font-size", "10"}, {"fill", kInk}});
  }
}

}  // namespace

std::string renderSvg(const BarChart& c) {
  checkBarChart(c);
  const Range r = barValueRange(c);
  const Ticks yt = axisTicks(c.y, r.lo, r.hi * (c.stacked ? 1.06 : 1.0));
  const PlotFrame f = barChartFrame(c, yt);
  const Scale sy{yt.lo, yt.hi, f.py1, f.py0, false};

  SvgWriter svg(c.width, f.height);
  svg.rect(0, 0, c.width, f.height, {{"fill", "#ffffff"}});
  if (!c.title.empty()) svg.text(f.px0, 20, c.title, {{"font-size", "14"}, {"font-weight", "bold"}, {"fill", kInk}});
  drawBarAxes(svg, c, yt, sy, f);
  for (std::size_t k = 0; k < c.categories.size(); ++k) drawCategory(svg, c, k, sy, f);
  if (sy.valid(0.0) && yt.lo <= 0.0 && yt.hi >= 0.0) svg.line(f.px0, sy(0.0), f.px1, sy(0.0), {{"stroke", "#444444"}});
  svg.rect(f.px0, f.py0, f.px1 - f.px0, f.py1 - f.py0, {{"fill", "none"}, {"stroke", "#888888"}});
  drawLegend(svg, f.rows, f.px0, c.height - 4);
  return svg.str();
}

}  // namespace wattswath::report
