// Sweep lines over an area with obstacles, their cells and the zigzag passes over a cell (moved
// from the planner: the straight-line geometry of its boustrophedon routes).
#include "wattswath/geometry/sweep_lines.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace wattswath::geometry {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Point rot(const Point& p, double c, double s) { return {c * p.x() + s * p.y(), -s * p.x() + c * p.y()}; }
Point unrot(const Point& p, double c, double s) { return {c * p.x() - s * p.y(), s * p.x() + c * p.y()}; }

// x of the crossings of horizontal line y with `ring` (half-open rule).
void crossings(const Ring& ring, double y, std::vector<double>& xs) {
  const size_t n = ring.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if ((a.y() > y) != (b.y() > y)) xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
  }
}

std::vector<std::pair<double, double>> pairsOf(std::vector<double> xs) {
  std::sort(xs.begin(), xs.end());
  std::vector<std::pair<double, double>> out;
  for (size_t i = 0; i + 1 < xs.size(); i += 2) out.emplace_back(xs[i], xs[i + 1]);
  return out;
}

// The area's intervals on line y: where the line itself meets the area. (They were once stretched
// to the area inside the line's footprint band, which put the ends of lines along a slanted edge
// outside the area: issue 22.)
std::vector<std::pair<double, double>> areaIntervals(const Ring& outer, double y) {
  std::vector<double> xs;
  crossings(outer, y, xs);
  return pairsOf(xs);
}

// Appends to `line` the free intervals of `area` minus the sorted `blocked` intervals; ends at the
// outer boundary get the run-out, clipped by blocks.
void subtractBlocked(const std::pair<double, double>& a, const std::vector<std::pair<double, double>>& blocked,
                     double run_out, std::vector<SweepInterval>& line) {
  double x = a.first;
  bool at_boundary = true;
  auto emit = [&](double x_end, bool end_boundary) {
    if (x_end - x <= 1e-6) return;
    SweepInterval iv;
    iv.x0 = x;
    iv.x1 = x_end;
    if (at_boundary) {
      double lim = x - run_out;
      for (const auto& b : blocked)
        if (b.second <= x + 1e-9 && b.second > lim) lim = b.second;
      iv.ext0 = x - lim;
      iv.x0 = x;
    }
    if (end_boundary) {
      double lim = x_end + run_out;
      for (const auto& b : blocked)
        if (b.first >= x_end - 1e-9 && b.first < lim) lim = b.first;
      iv.ext1 = lim - x_end;
    }
    line.push_back(iv);
  };
  for (const auto& b : blocked) {
    if (b.second <= x || b.first >= a.second) continue;
    if (b.first > x) emit(b.first, false);
    x = std::max(x, b.second);
    at_boundary = false;
  }
  emit(a.second, true);
}

}  // namespace

SweepLines sweepLines(const Ring& area_outer, const std::vector<Ring>& obstacles, double angle,
                      const SweepLineSettings& settings) {
  const double c = std::cos(angle), s = std::sin(angle);
  Ring outer;
  for (const auto& p : area_outer) outer.push_back(rot(p, c, s));
  std::vector<Ring> obst;
  for (const auto& r : obstacles) {
    Ring q;
    for (const auto& p : r) q.push_back(rot(p, c, s));
    obst.push_back(q);
  }
  double ymin = kInf, ymax = -kInf;
  for (const auto& p : outer) {
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
  }
  const double d = settings.spacing;
  const int full = static_cast<int>(std::ceil((ymax - ymin) / d - 1e-9));  // lines the full coverage needs
  const int nlines = std::max(1, full - std::max(0, settings.fewer_lines));
  const double y0 = ymin + 0.5 * ((ymax - ymin) - (nlines - 1) * d);
  SweepLines out;
  out.first_y = y0;
  out.lines.resize(nlines);
  for (int k = 0; k < nlines; ++k) {
    const double y = y0 + k * d;
    const auto area = areaIntervals(outer, y);
    std::vector<std::pair<double, double>> blocked;
    for (const auto& r : obst) {
      std::vector<double> bx;
      crossings(r, y, bx);
      for (auto& b : pairsOf(bx)) blocked.emplace_back(b.first - settings.clearance, b.second + settings.clearance);
    }
    std::sort(blocked.begin(), blocked.end());
    for (const auto& a : area) subtractBlocked(a, blocked, settings.run_out, out.lines[k]);
  }
  return out;
}

std::vector<SweepLineCell> sweepLineCells(const std::vector<std::vector<SweepInterval>>& lines) {
  std::vector<SweepLineCell> cells;
  std::vector<int> prev_cell;  // cell of each interval on the previous line
  for (size_t k = 0; k < lines.size(); ++k) {
    std::vector<int> cur(lines[k].size(), -1);
    for (size_t j = 0; j < lines[k].size(); ++j) {
      const auto& iv = lines[k][j];
      int match = -1, count = 0;
      if (k > 0) {
        for (size_t i = 0; i < lines[k - 1].size(); ++i) {
          const auto& p = lines[k - 1][i];
          if (std::min(p.x1, iv.x1) - std::max(p.x0, iv.x0) > 0.0) {
            match = static_cast<int>(i);
            ++count;
          }
        }
      }
      bool joined = false;
      if (count == 1) {
        int back = 0;  // how many intervals of this line overlap the matched one
        const auto& p = lines[k - 1][match];
        for (const auto& o : lines[k])
          if (std::min(p.x1, o.x1) - std::max(p.x0, o.x0) > 0.0) ++back;
        const int c = prev_cell[match];
        if (back == 1 && c >= 0 && cells[c].first_line + static_cast<int>(cells[c].rows.size()) == static_cast<int>(k)) {
          cells[c].rows.push_back(iv);
          cur[j] = c;
          joined = true;
        }
      }
      if (!joined) {
        cells.push_back({static_cast<int>(k), {iv}});
        cur[j] = static_cast<int>(cells.size()) - 1;
      }
    }
    prev_cell = cur;
  }
  return cells;
}

std::vector<SweepPass> sweepPasses(const SweepLineCell& cell, double angle, double first_y, double spacing,
                                   bool from_top, bool start_right) {
  const double c = std::cos(angle), s = std::sin(angle);
  const int n = static_cast<int>(cell.rows.size());
  std::vector<SweepPass> passes;
  bool right = start_right;
  for (int i = 0; i < n; ++i) {
    const int row = from_top ? n - 1 - i : i;
    const auto& iv = cell.rows[row];
    const double y = first_y + (cell.first_line + row) * spacing;
    const double xa = right ? iv.x1 + iv.ext1 : iv.x0 - iv.ext0;
    const double xb = right ? iv.x0 - iv.ext0 : iv.x1 + iv.ext1;
    const double ta = right ? iv.ext1 : iv.ext0, tb = right ? iv.ext0 : iv.ext1;
    passes.push_back({unrot(Point(xa, y), c, s), unrot(Point(xb, y), c, s), ta, tb});
    right = !right;
  }
  return passes;
}

}  // namespace wattswath::geometry
