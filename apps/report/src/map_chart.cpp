// The map figure: areas, no-fly zones, a path coloured by value or by category, markers, a north
// arrow and a scale bar or metre axes, rendered to self-contained SVG with the SvgWriter.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "chart_common.hpp"
#include "wattswath/report/charts.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report {

using namespace detail;

namespace {

/// Where the map's metres land in pixels (equal scale, north up).
struct MapFrame {
  double left = 0, top = 0, pw = 0, ph = 0;  // [px] plot area
  double scale = 1;                          // [px/m]
  double cx = 0, cy = 0;                     // [m] centre of the data
  double X(double x) const { return left + pw / 2 + (x - cx) * scale; }
  double Y(double y) const { return top + ph / 2 - (y - cy) * scale; }
};

/// True when some path piece takes its colour from its value (so a colour bar is needed).
bool needsColourBar(const MapView& m) {
  return std::any_of(m.path.begin(), m.path.end(), [](const MapPolyline& l) { return l.colour.empty(); });
}

/// A label's box on the map [px].
struct LabelBox {
  double x0, y0, x1, y1;
  bool overlaps(const LabelBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

/// [em] Width of one character of a bold label: DejaVu Sans Bold's digits advance 0.696 em, wider
/// than the 0.62 em once assumed, which let "50" and "49" run together as "5049".
constexpr double kBoldCharEm = 0.72;
/// [px] Space kept between two labels (and between a label and the plot's edge).
constexpr double kLabelGap = 2.0;

/// Where the label of a marker of radius `r` at (x, y) goes: above right, below right, above left or
/// below left of it, the first that lies inside `bounds` (the plot area) and keeps kLabelGap from
/// every label in `placed` (added to it). When no place is inside, the first of them that overlaps
/// nothing is moved inside; none when all overlap (the marker's tooltip still names it).
std::optional<LabelBox> placeLabel(double x, double y, double r, const std::string& label, double font_px,
                                   const LabelBox& bounds, std::vector<LabelBox>& placed) {
  const double w = kBoldCharEm * font_px * static_cast<double>(label.size()), h = font_px;
  const double gap = r + 3;
  const LabelBox candidates[] = {{x + gap, y - r - 1 - h, x + gap + w, y - r - 1},
                                 {x + gap, y + r + 1, x + gap + w, y + r + 1 + h},
                                 {x - gap - w, y - r - 1 - h, x - gap, y - r - 1},
                                 {x - gap - w, y + r + 1, x - gap, y + r + 1 + h}};
  const auto free = [&](const LabelBox& c) {
    const LabelBox grown{c.x0 - kLabelGap, c.y0 - kLabelGap, c.x1 + kLabelGap, c.y1 + kLabelGap};
    return std::none_of(placed.begin(), placed.end(), [&](const LabelBox& p) { return p.overlaps(grown); });
  };
  const auto inside = [&](const LabelBox& c) {
    return c.x0 >= bounds.x0 && c.x1 <= bounds.x1 && c.y0 >= bounds.y0 && c.y1 <= bounds.y1;
  };
  for (const auto& c : candidates) {
    if (inside(c) && free(c)) {
      placed.push_back(c);
      return c;
    }
  }
  for (const auto& c : candidates) {  // a label longer than the room on either side: moved inside
    const double dx = std::clamp(c.x0, bounds.x0, std::max(bounds.x0, bounds.x1 - w)) - c.x0;
    const double dy = std::clamp(c.y0, bounds.y0, std::max(bounds.y0, bounds.y1 - h)) - c.y0;
    const LabelBox moved{c.x0 + dx, c.y0 + dy, c.x1 + dx, c.y1 + dy};
    if (free(moved)) {
      placed.push_back(moved);
      return moved;
    }
  }
  return std::nullopt;
}

/// [m] The scale bar's length: 1, 2 or 5 times a power of ten, at most a fifth of the map's width.
double scaleBarLength(const MapFrame& f) {
  const double target = 0.2 * f.pw / f.scale;
  const double mag = std::pow(10.0, std::floor(std::log10(target)));
  double len = mag;
  for (const double k : {1.0, 2.0, 5.0}) {
    if (k * mag <= target) len = k * mag;
  }
  return len;
}

/// Where the north arrow and (without axes) the scale bar are drawn [px]: no label goes over them.
std::vector<LabelBox> mapFurniture(const MapView& m, const MapFrame& f) {
  const double nx = f.left + (m.axes ? 16.0 : 14.0), ny = f.top + (m.axes ? 6.0 : 4.0);
  std::vector<LabelBox> out = {{nx - 8, ny, nx + 8, ny + 32}};
  if (!m.axes) {
    const double by = f.top + f.ph - 10, bw = scaleBarLength(f) * f.scale;
    out.push_back({f.left + 8, by - 14, f.left + 8 + bw + 6 + 50, by + 2});
  }
  return out;
}

void drawMarkers(SvgWriter& svg, const MapView& m, const MapFrame& f) {
  std::vector<LabelBox> placed = mapFurniture(m, f);
  const LabelBox bounds{f.left, f.top, f.left + f.pw, f.top + f.ph};
  // Labels are placed larger markers first (home and start before the waypoint dots), so that a
  // waypoint number at home never takes the place the home label needs: the number is the one
  // left out then (its tooltip stays).
  std::vector<std::size_t> order(m.markers.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return m.markers[a].size > m.markers[b].size; });
  std::vector<std::optional<LabelBox>> boxes(m.markers.size());
  for (const std::size_t i : order) {
    const auto& k = m.markers[i];
    boxes[i] = placeLabel(f.X(k.position.x()), f.Y(k.position.y()), k.size, k.label, k.size < 5 ? 11 : 12, bounds, placed);
  }
  for (std::size_t i = 0; i < m.markers.size(); ++i) {
    const auto& k = m.markers[i];
    const double x = f.X(k.position.x()), y = f.Y(k.position.y()), r = k.size;
    svg.open("g", {{"class", "marker"}});
    svg.title(k.label + " (" + formatNumber(k.position.x(), 1) + " m E, " + formatNumber(k.position.y(), 1) + " m N)");
    const Attrs style = {{"fill", k.colour}, {"stroke", "#ffffff"}, {"stroke-width", r < 5 ? "1" : "1.5"}};
    Attrs a;
    if (k.shape == MapMarker::Shape::Square) {
      a = {{"x", svgNum(x - r)}, {"y", svgNum(y - r)}, {"width", svgNum(2 * r)}, {"height", svgNum(2 * r)}};
      a.insert(a.end(), style.begin(), style.end());
      svg.leaf("rect", a);
    } else if (k.shape == MapMarker::Shape::Triangle) {
      a = {{"points", svgPoints({{x, y - 1.35 * r}, {x - 1.15 * r, y + 0.85 * r}, {x + 1.15 * r, y + 0.85 * r}})}};
      a.insert(a.end(), style.begin(), style.end());
      svg.leaf("polygon", a);
    } else {
      a = {{"cx", svgNum(x)}, {"cy", svgNum(y)}, {"r", svgNum(r)}};
      a.insert(a.end(), style.begin(), style.end());
      svg.leaf("circle", a);
    }
    if (const auto& box = boxes[i]) {
      svg.text(box->x0, box->y1, k.label,
               {{"fill", k.colour},
                {"font-weight", "bold"},
                {"font-size", r < 5 ? "11" : "12"},
                {"stroke", "#ffffff"},
                {"stroke-width", "3"},
                {"paint-order", "stroke"}});
    }
    svg.close();
  }
}

void drawScaleBar(SvgWriter& svg, const MapFrame& f, double y_base) {
  const double len = scaleBarLength(f);
  const double bx = f.left + 8, by = y_base - 10, bw = len * f.scale;
  svg.open("g", {{"class", "scalebar"}});
  svg.rect(bx, by - 5, bw / 2, 5, {{"fill", kInk}});
  svg.rect(bx + bw / 2, by - 5, bw / 2, 5, {{"fill", "#ffffff"}, {"stroke", kInk}});
  const std::string label =
      len >= 1000 ? formatNumber(len / 1000, len >= 10000 ? 0 : 1) + " km" : formatNumber(len, len < 1 ? 2 : 0) + " m";
  svg.text(bx + bw + 6, by, label, {{"fill", kInk}, {"font-size", "11"}});
  svg.close();
}

/// East and north axes with ticks in metres around the plot area, and a light grid.
void drawAxes(SvgWriter& svg, const MapFrame& f) {
  const double x0 = f.left, x1 = f.left + f.pw, y0 = f.top, y1 = f.top + f.ph;
  const Ticks tx = niceTicks(f.cx - f.pw / 2 / f.scale, f.cx + f.pw / 2 / f.scale, 8);
  const Ticks ty = niceTicks(f.cy - f.ph / 2 / f.scale, f.cy + f.ph / 2 / f.scale, 6);
  svg.open("g", {{"class", "grid"}, {"stroke", "#eeeeee"}, {"stroke-width", "1"}});
  for (const double v : tx.values)
    if (f.X(v) >= x0 && f.X(v) <= x1) svg.line(f.X(v), y0, f.X(v), y1);
  for (const double v : ty.values)
    if (f.Y(v) >= y0 && f.Y(v) <= y1) svg.line(x0, f.Y(v), x1, f.Y(v));
  svg.close();
  svg.open("g", {{"class", "ticks"}, {"fill", kInk}, {"font-size", "11"}});
  for (std::size_t i = 0; i < tx.values.size(); ++i)
    if (f.X(tx.values[i]) >= x0 && f.X(tx.values[i]) <= x1)
      svg.text(f.X(tx.values[i]), y1 + 15, tx.labels[i], {{"text-anchor", "middle"}});
  for (std::size_t i = 0; i < ty.values.size(); ++i)
    if (f.Y(ty.values[i]) >= y0 && f.Y(ty.values[i]) <= y1)
      svg.text(x0 - 5, f.Y(ty.values[i]) + 4, ty.labels[i], {{"text-anchor", "end"}});
  svg.close();
  svg.text((x0 + x1) / 2, y1 + 33, "east of home [m]", {{"text-anchor", "middle"}, {"fill", kInk}});
  svg.text(0, 0, "north of home [m]",
           {{"text-anchor", "middle"},
            {"fill", kInk},
            {"transform", "translate(14," + svgNum((y0 + y1) / 2) + ") rotate(-90)"}});
  svg.rect(x0, y0, f.pw, f.ph, {{"fill", "none"}, {"stroke", "#888888"}, {"stroke-width", "1"}});
}

void drawColourBar(SvgWriter& svg, const MapView& m, double x, double top, double bottom, double vlo, double vhi) {
  const double bx = x + 22, bw = 16, b0 = top + 30, b1 = bottom - 30;
  const int n = 48;
  svg.open("g", {{"class", "colourbar"}});
  svg.text(bx - 6, top + 12, m.value_label, {{"fill", kInk}});
  svg.text(bx - 6, top + 26, "[" + m.value_unit + "]", {{"fill", kInk}});
  for (int i = 0; i < n; ++i) {
    const double t0 = static_cast<double>(i) / n;
    svg.rect(bx, b1 - (b1 - b0) * (t0 + 1.0 / n), bw, (b1 - b0) / n + 0.6, {{"fill", valueColour(t0 + 0.5 / n)}});
  }
  svg.rect(bx, b0, bw, b1 - b0, {{"fill", "none"}, {"stroke", "#666666"}});
  const Ticks t = niceTicks(vlo, vhi, 5);
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    if (t.values[i] < vlo - 1e-9 * (vhi - vlo) || t.values[i] > vhi + 1e-9 * (vhi - vlo)) continue;
    const double y = b1 - (t.values[i] - vlo) / (vhi - vlo) * (b1 - b0);
    svg.line(bx + bw, y, bx + bw + 4, y, {{"stroke", kInk}});
    svg.text(bx + bw + 7, y + 4, t.labels[i], {{"fill", kInk}, {"font-size", "11"}});
  }
  svg.close();
}

void drawPath(SvgWriter& svg, const MapView& m, const MapFrame& f, double vlo, double vhi) {
  svg.open("g", {{"class", "path"},
                 {"fill", "none"},
                 {"stroke-width", "2.6"},
                 {"stroke-linecap", "round"},
                 {"stroke-linejoin", "round"}});
  for (const auto& l : m.path) {
    std::vector<std::pair<double, double>> pts;
    for (const auto& p : l.points) {
      if (std::isfinite(p.x()) && std::isfinite(p.y())) pts.push_back({f.X(p.x()), f.Y(p.y())});
    }
    if (pts.size() < 2) continue;
    Attrs a = {{"points", svgPoints(pts)},
               {"stroke", l.colour.empty() ? valueColour((l.value - vlo) / (vhi - vlo)) : l.colour}};
    if (!l.dash.empty()) {
      a.push_back({"stroke-dasharray", l.dash});
    } else if (l.dashed) {
      a.push_back({"stroke-dasharray", "6 4"});
    }
    svg.open("polyline", a);
    if (!l.tooltip.empty()) svg.title(l.tooltip);
    svg.close();
  }
  svg.close();
}

void drawAreas(SvgWriter& svg, const MapView& m, const MapFrame& f) {
  auto ringData = [&](const geometry::Ring& r) {
    std::string d;
    for (std::size_t i = 0; i < r.size(); ++i)
      d += (i ? "L" : "M") + svgNum(f.X(r[i].x())) + " " + svgNum(f.Y(r[i].y()));
    return d + "Z";
  };
  for (const auto& a : m.areas) {
    std::string d = ringData(a.outer);
    for (const auto& h : a.holes) d += ringData(h);
    svg.open("path",
             {{"d", d}, {"fill", "#e8eef3"}, {"fill-rule", "evenodd"}, {"stroke", "#4d4d4d"}, {"stroke-width", "1.4"}});
    svg.title("survey area: " + formatNumber(geometry::area(a) / 1e4, 3) + " ha, " + std::to_string(a.holes.size()) +
              " hole(s)");
    svg.close();
  }
  for (const auto& z : m.no_fly) {
    svg.open("path", {{"d", ringData(z)},
                      {"fill", "#D55E00"},
                      {"fill-opacity", "0.22"},
                      {"stroke", "#D55E00"},
                      {"stroke-width", "1.4"},
                      {"stroke-dasharray", "5 3"}});
    svg.title("no-fly zone");
    svg.close();
  }
}

}  // namespace

std::string renderSvg(const MapView& m) {
  Range xr, yr, vr;
  auto addPt = [&](const geometry::Point& p) {
    xr.add(p.x(), false);
    yr.add(p.y(), false);
  };
  for (const auto& a : m.areas) {
    for (const auto& p : a.outer) addPt(p);
    for (const auto& h : a.holes)
      for (const auto& p : h) addPt(p);
  }
  for (const auto& z : m.no_fly)
    for (const auto& p : z) addPt(p);
  for (const auto& l : m.path) {
    for (const auto& p : l.points) addPt(p);
    if (l.colour.empty()) vr.add(l.value, false);
  }
  for (const auto& k : m.markers) addPt(k.position);
  if (xr.empty() || yr.empty()) throw std::invalid_argument("map '" + m.title + "': nothing to draw");
  const bool colourBar = needsColourBar(m);
  if (colourBar && (m.value_label.empty() || m.value_unit.empty())) {
    throw std::invalid_argument("map '" + m.title + "': the path colour needs value_label and value_unit");
  }
  std::vector<LegendItem> items;
  for (const auto& e : m.legend) items.push_back({e.name, e.colour, e.dash, LegendKind::Line});
  MapFrame f;
  f.top = m.title.empty() ? 12.0 : 32.0;
  f.left = m.axes ? 62.0 : 12.0;
  const double bottom = m.axes ? 46.0 : 12.0, right = colourBar ? 110.0 : (m.axes ? 18.0 : 12.0);
  const auto rows = legendRows(items, m.width - f.left - right);
  const double height = m.height + kLegendRow * static_cast<double>(rows.size()) + (rows.empty() ? 0.0 : 6.0);
  f.pw = m.width - f.left - right;
  f.ph = m.height - f.top - bottom;
  if (f.pw < 50 || f.ph < 50) throw std::invalid_argument("map '" + m.title + "': figure too small");
  const double dx = std::max(xr.hi - xr.lo, 1.0), dy = std::max(yr.hi - yr.lo, 1.0);
  f.scale = 0.94 * std::min(f.pw / dx, f.ph / dy);
  f.cx = (xr.lo + xr.hi) / 2;
  f.cy = (yr.lo + yr.hi) / 2;

  SvgWriter svg(m.width, height);
  svg.rect(0, 0, m.width, height, {{"fill", "#ffffff"}});
  if (!m.title.empty()) svg.text(f.left, 20, m.title, {{"font-size", "14"}, {"font-weight", "bold"}, {"fill", kInk}});
  if (m.axes) drawAxes(svg, f);
  drawAreas(svg, m, f);
  const double vlo = vr.empty() ? 0.0 : vr.lo, vhi = vr.empty() ? 1.0 : (vr.hi > vr.lo ? vr.hi : vr.lo + 1.0);
  drawPath(svg, m, f, vlo, vhi);
  drawMarkers(svg, m, f);
  // North arrow (top left of the map area).
  const double nx = f.left + (m.axes ? 16.0 : 14.0), ny = f.top + (m.axes ? 6.0 : 4.0);
  svg.open("g", {{"class", "north"}, {"fill", kInk}});
  svg.leaf("polygon", {{"points", svgPoints({{nx, ny}, {nx - 6, ny + 16}, {nx, ny + 12}, {nx + 6, ny + 16}})}});
  svg.text(nx, ny + 29, "N", {{"text-anchor", "middle"}, {"font-weight", "bold"}});
  svg.close();
  if (!m.axes) drawScaleBar(svg, f, m.height - bottom);
  if (colourBar) drawColourBar(svg, m, m.width - right, f.top, m.height - bottom, vlo, vhi);
  drawLegend(svg, rows, f.left, m.height - 4);
  return svg.str();
}

}  // namespace wattswath::report
