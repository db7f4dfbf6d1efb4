#include "wattswath/geometry/coverage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/ring.hpp>

#include "cgal_ops.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/tolerances.hpp"

namespace wattswath::geometry {
namespace {

constexpr double kSpiralSimplify = 0.02;  // [-] of the spacing: outline detail dropped before the straight skeleton

// `ring` with the vertices Douglas-Peucker (Boost.Geometry) finds within `tolerance` [m] of the
// simplified outline dropped: a field edge traced by GPS has hundreds of vertices the laps, a
// spacing apart, cannot follow, and the straight skeleton's cost grows faster than its vertices.
Ring simplifiedRing(const Ring& ring, double tolerance) {
  namespace bg = boost::geometry;
  using BgPoint = bg::model::d2::point_xy<double>;
  using BgRing = bg::model::ring<BgPoint, false, false>;  // counter-clockwise, open
  BgRing in, out;
  for (const auto& p : ring) in.push_back(BgPoint(p.x(), p.y()));
  bg::simplify(in, out, tolerance);
  if (out.size() < 3 || out.size() == in.size()) return ring;
  Ring r;
  for (const auto& p : out) {
    const Point q(p.x(), p.y());
    if (r.empty() || (q - r.back()).norm() > tol::kPosition) r.push_back(q);
  }
  while (r.size() > 1 && (r.front() - r.back()).norm() <= tol::kPosition) r.pop_back();  // simplify may close it
  return r.size() >= 3 ? r : ring;
}

constexpr double kWallTol = 1e-9;  // [m] sweep-frame x values closer than this are the same wall
// A corner gets a spike when it lies this many times farther than the footprint's half-diagonal
// (corners under about 69 deg); nearly right corners lose only a negligible sliver without one.
constexpr double kSpikeFactor = 1.25;
// Spiral waypoints turning less than this [rad] and this close to the straight line past them
// [fraction of the spacing] are dropped.
constexpr double kKinkAngle = 2.0 * M_PI / 180.0;
constexpr double kKinkOffset = 0.02;

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

void validateRing(const Ring& r, const std::string& what) {
  if (r.size() < 3) throw std::invalid_argument(what + ": " + std::to_string(r.size()) + " vertices, expected at least 3");
  for (size_t i = 0; i < r.size(); ++i) {
    if (!r[i].allFinite()) throw std::invalid_argument(what + ": vertex " + std::to_string(i) + " is not finite");
  }
  if (std::abs(signedArea(r)) <= 0.0) throw std::invalid_argument(what + ": zero area, expected a polygon with area");
}

void validateArea(const PolygonWithHoles& area) {
  validateRing(area.outer, "area outer boundary");
  for (size_t h = 0; h < area.holes.size(); ++h) validateRing(area.holes[h], "area hole " + std::to_string(h));
}

void validateSpacing(double spacing) {
  if (!(std::isfinite(spacing) && spacing > 0.0)) {
    std::ostringstream os;
    os << "coverage: spacing " << spacing << " m, expected a finite value > 0";
    throw std::invalid_argument(os.str());
  }
}

Ring ccw(Ring r) {
  if (signedArea(r) < 0.0) std::reverse(r.begin(), r.end());
  return r;
}

/// Removes repeated and collinear vertices of a closed ring.
Ring cleanRing(const Ring& in) {
  Ring r;
  for (const auto& p : in) {
    if (r.empty() || (p - r.back()).norm() > tol::kPosition) r.push_back(p);
  }
  while (r.size() > 1 && (r.front() - r.back()).norm() <= tol::kPosition) r.pop_back();
  bool changed = true;
  while (changed && r.size() >= 3) {
    changed = false;
    for (size_t i = 0; i < r.size() && r.size() >= 3; ++i) {
      const Point& a = r[(i + r.size() - 1) % r.size()];
      const Point& b = r[i];
      const Point& c = r[(i + 1) % r.size()];
      if (std::abs(cross(b - a, c - b)) <= tol::kPosition * ((b - a).norm() + (c - b).norm())) {
        r.erase(r.begin() + static_cast<long>(i));
        changed = true;
        break;
      }
    }
  }
  return r;
}

/// Splits a convex piece with vertical walls into its lower and upper chains.
SweepPiece toSweepPiece(const Ring& piece) {
  const Ring r = ccw(piece);
  const size_t n = r.size();
  double xl = std::numeric_limits<double>::infinity(), xr = -xl;
  for (const auto& p : r) {
    xl = std::min(xl, p.x());
    xr = std::max(xr, p.x());
  }
  auto pick = [&](double x, bool lowest) {
    size_t best = n;
    for (size_t i = 0; i < n; ++i) {
      if (std::abs(r[i].x() - x) > kWallTol) continue;
      if (best == n || (lowest ? r[i].y() < r[best].y() : r[i].y() > r[best].y())) best = i;
    }
    return best;
  };
  const size_t l_lo = pick(xl, true), l_hi = pick(xl, false), r_lo = pick(xr, true), r_hi = pick(xr, false);
  SweepPiece s;
  s.x_left = xl;
  s.x_right = xr;
  for (size_t i = l_lo;; i = (i + 1) % n) {  // CCW from bottom-left to bottom-right is the lower chain
    s.lower.push_back(r[i]);
    if (i == r_lo) break;
  }
  for (size_t i = r_hi;; i = (i + 1) % n) {  // CCW from top-right to top-left is the upper chain
    s.upper.push_back(r[i]);
    if (i == l_hi) break;
  }
  std::reverse(s.upper.begin(), s.upper.end());
  return s;
}

double chainAt(const std::vector<Point>& chain, double x) {
  if (x <= chain.front().x()) return chain.front().y();
  for (size_t i = 1; i < chain.size(); ++i) {
    if (x <= chain[i].x()) {
      const double dx = chain[i].x() - chain[i - 1].x();
      if (dx <= kWallTol) return chain[i].y();
      return chain[i - 1].y() + (chain[i].y() - chain[i - 1].y()) * (x - chain[i - 1].x()) / dx;
    }
  }
  return chain.back().y();
}

/// A cell in the sweep frame: lower / upper boundary as functions of x.
struct SweepCell {
  const std::vector<SweepPiece>& pieces;

  double x0() const { return pieces.front().x_left; }
  double x1() const { return pieces.back().x_right; }
  /// Lowest (upper=false) or highest (upper=true) boundary value at x over the pieces touching x.
  double at(double x, bool upper) const {
    double v = upper ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    for (const auto& p : pieces) {
      if (x < p.x_left - kWallTol || x > p.x_right + kWallTol) continue;
      const double y = chainAt(upper ? p.upper : p.lower, x);
      v = upper ? std::max(v, y) : std::min(v, y);
    }
    return v;
  }
  /// Boundary vertices strictly between a and b (in the order from a to b).
  std::vector<Point> chainBetween(double a, double b, bool upper) const {
    std::vector<Point> out;
    const double lo = std::min(a, b), hi = std::max(a, b);
    for (const auto& p : pieces) {
      for (const auto& q : upper ? p.upper : p.lower) {
        if (q.x() > lo + kWallTol && q.x() < hi - kWallTol) out.push_back(q);
      }
    }
    std::sort(out.begin(), out.end(), [&](const Point& u, const Point& v) {
      return a < b ? u.x() < v.x() : u.x() > v.x();
    });
    return out;
  }
};

/// Distance along the ray from `o` in unit direction `u` to the first crossing of `ring` (inf if none).
double rayToRing(const Ring& ring, const Point& o, const Point& u) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point& a = ring[i];
    const Point ab = ring[(i + 1) % ring.size()] - a;
    const double den = cross(u, ab);
    if (std::abs(den) <= 1e-15) continue;
    const double t = cross(a - o, ab) / den, w = cross(a - o, u) / den;
    if (t > tol::kPosition && w >= 0.0 && w <= 1.0) best = std::min(best, t);
  }
  return best;
}

/// A lap with an out-and-back spike along the outward bisector of every acute corner whose
/// bisector meets `reference` farther than kSpikeFactor * margin * sqrt(2): the spike ends `margin` short of it,
/// so the footprint reaches into the corner.
Ring withSpikes(const Ring& lap, const Ring& reference, double margin) {
  Ring out;
  const size_t n = lap.size();
  for (size_t i = 0; i < n; ++i) {
    const Point& prev = lap[(i + n - 1) % n];
    const Point& v = lap[i];
    const Point& next = lap[(i + 1) % n];
    out.push_back(v);
    const Point din = v - prev, dout = next - v;
    if (cross(din, dout) <= 0.0 || din.dot(dout) >= 0.0) continue;  // reflex or not acute
    const Point outward = (din.normalized() - dout.normalized()).normalized();
    const double g = rayToRing(reference, v, outward);
    if (!std::isfinite(g) || g <= kSpikeFactor * margin * std::sqrt(2.0)) continue;
    out.push_back(v + (g - margin) * outward);
    out.push_back(v);
  }
  return out;
}

bool polylineSafe(const PolygonWithHoles& area, const std::vector<Point>& pts, double angle) {
  for (size_t i = 1; i < pts.size(); ++i) {
    const Point a = fromSweepFrame(pts[i - 1], angle), b = fromSweepFrame(pts[i], angle);
    if (segmentEntersHole(area, a, b) || segmentLeavesArea(area, a, b)) return false;
  }
  return true;
}

}  // namespace

Point toSweepFrame(const Point& p, double sweep_angle) {
  const double phi = 0.5 * M_PI - sweep_angle;
  const double c = std::cos(phi), s = std::sin(phi);
  return Point(c * p.x() - s * p.y(), s * p.x() + c * p.y());
}

Point fromSweepFrame(const Point& p, double sweep_angle) {
  const double phi = sweep_angle - 0.5 * M_PI;
  const double c = std::cos(phi), s = std::sin(phi);
  return Point(c * p.x() - s * p.y(), s * p.x() + c * p.y());
}

BoustrophedonDecomposition decomposeBoustrophedon(const PolygonWithHoles& area, double sweep_angle) {
  validateArea(area);
  if (!std::isfinite(sweep_angle)) throw std::invalid_argument("boustrophedon: sweep angle is not finite");
  PolygonWithHoles rotated;
  for (const auto& p : area.outer) rotated.outer.push_back(toSweepFrame(p, sweep_angle));
  for (const auto& h : area.holes) {
    rotated.holes.emplace_back();
    for (const auto& p : h) rotated.holes.back().push_back(toSweepFrame(p, sweep_angle));
  }
  std::vector<SweepPiece> pieces;
  for (const auto& region : detail::regularizedRegions(rotated)) {
    for (const auto& ring : detail::verticalDecomposition(region)) {
      if (ring.size() < 3) continue;
      SweepPiece p = toSweepPiece(ring);
      if (p.x_right - p.x_left > tol::kSliver) pieces.push_back(std::move(p));
    }
  }
  std::sort(pieces.begin(), pieces.end(), [](const SweepPiece& a, const SweepPiece& b) {
    return a.x_left < b.x_left || (a.x_left == b.x_left && a.lower.front().y() < b.lower.front().y());
  });
  const size_t n = pieces.size();
  std::vector<std::vector<size_t>> right(n), left(n);
  for (size_t a = 0; a < n; ++a) {
    const double x = pieces[a].x_right;
    const double a_lo = pieces[a].lower.back().y(), a_hi = pieces[a].upper.back().y();
    auto it = std::lower_bound(pieces.begin(), pieces.end(), x - kWallTol,
                               [](const SweepPiece& p, double v) { return p.x_left < v; });
    for (; it != pieces.end() && it->x_left <= x + kWallTol; ++it) {
      const size_t b = static_cast<size_t>(it - pieces.begin());
      const double overlap = std::min(a_hi, it->upper.front().y()) - std::max(a_lo, it->lower.front().y());
      if (overlap > tol::kSliver) {
        right[a].push_back(b);
        left[b].push_back(a);
      }
    }
  }
  BoustrophedonDecomposition d;
  d.sweep_angle = sweep_angle;
  for (size_t start = 0; start < n; ++start) {
    const bool continues = left[start].size() == 1 && right[left[start][0]].size() == 1;
    if (continues) continue;  // not the first piece of its cell
    BoustrophedonCell cell;
    size_t cur = start;
    while (true) {
      cell.pieces.push_back(pieces[cur]);
      if (right[cur].size() != 1 || left[right[cur][0]].size() != 1) break;
      cur = right[cur][0];
    }
    Ring outline;
    for (const auto& p : cell.pieces) outline.insert(outline.end(), p.lower.begin(), p.lower.end());
    for (auto p = cell.pieces.rbegin(); p != cell.pieces.rend(); ++p) outline.insert(outline.end(), p->upper.rbegin(), p->upper.rend());
    for (auto& q : outline) q = fromSweepFrame(q, sweep_angle);
    cell.boundary = ccw(cleanRing(outline));
    d.cells.push_back(std::move(cell));
  }
  return d;
}

Route boustrophedonRoute(const PolygonWithHoles& area, const BoustrophedonDecomposition& d, int cell_index,
                         const BoustrophedonSettings& settings) {
  validateSpacing(settings.spacing);
  if (cell_index < 0 || cell_index >= static_cast<int>(d.cells.size())) {
    throw std::invalid_argument("boustrophedon: cell " + std::to_string(cell_index) + " out of range (0.." +
                                std::to_string(d.cells.size()) + ")");
  }
  const SweepCell cell{d.cells[static_cast<size_t>(cell_index)].pieces};
  const double s = settings.spacing, angle = d.sweep_angle;
  const double x0 = cell.x0(), width = cell.x1() - x0;
  const int n = std::max(1, static_cast<int>(std::ceil(width / s - 1e-9)));
  const bool from_left = settings.start == StartCorner::BottomLeft || settings.start == StartCorner::TopLeft;
  const bool first_up = settings.start == StartCorner::BottomLeft || settings.start == StartCorner::BottomRight;

  struct Line {
    double x, lo, hi;  // [m] sweep-frame x and the ends on the cell boundary
  };
  std::vector<Line> lines;
  for (int k = 0; k < n; ++k) {
    // The line ends on the cell's boundary: stretching it to reach a slanted boundary's corner
    // put its ends outside the area (issue 22); the coverage figure says what that costs.
    const double x = x0 + ((from_left ? k : n - 1 - k) + 0.5) * width / n;
    lines.push_back({x, cell.at(x, false), cell.at(x, true)});
  }
  Route r;
  auto add = [&](const Point& p, LegRole role) {
    if (r.points.empty()) {
      r.points.push_back(p);
      return;
    }
    r.roles.push_back(role);
    r.points.push_back(p);
  };
  for (size_t k = 0; k < lines.size(); ++k) {
    const Line& l = lines[k];
    const bool up = (k % 2 == 0) == first_up;
    const Point a(l.x, up ? l.lo : l.hi), b(l.x, up ? l.hi : l.lo);
    if (k > 0) {  // connector from the previous line's end: straight, else along the cell boundary
      const Line& p = lines[k - 1];
      const bool top = !up;  // previous line went up, so we are at the top
      const Point prev_end(p.x, top ? p.hi : p.lo);
      std::vector<Point> via{prev_end};
      const auto chain = cell.chainBetween(p.x, l.x, top);
      via.insert(via.end(), chain.begin(), chain.end());
      via.push_back(a);
      const std::vector<Point> straight{prev_end, a};
      const auto& chosen = polylineSafe(area, straight, angle) ? straight : via;
      for (size_t j = 1; j < chosen.size(); ++j) add(fromSweepFrame(chosen[j], angle), LegRole::Turn);
      add(fromSweepFrame(b, angle), LegRole::Sweep);
    } else {
      add(fromSweepFrame(a, angle), LegRole::Sweep);
      add(fromSweepFrame(b, angle), LegRole::Sweep);
    }
  }
  return r;
}

std::vector<CoveragePath> boustrophedonPaths(const PolygonWithHoles& area, const BoustrophedonSettings& settings,
                                             const CornerSettings& corners, double altitude) {
  validateSpacing(settings.spacing);
  const auto d = decomposeBoustrophedon(area, settings.sweep_angle);
  std::vector<CoveragePath> out;
  for (size_t c = 0; c < d.cells.size(); ++c) {
    CoveragePath p = shapeCorners(boustrophedonRoute(area, d, static_cast<int>(c), settings), corners, altitude, area);
    p.pattern = "boustrophedon";
    p.sweep_angle = settings.sweep_angle;
    p.cell = static_cast<int>(c);
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<SpiralCell> decomposeSpiral(const PolygonWithHoles& area, double spacing, double split_angle) {
  validateArea(area);
  validateSpacing(spacing);
  std::vector<Ring> pieces;
  if (area.holes.empty()) {
    pieces.push_back(ccw(area.outer));
  } else {
    for (const auto& c : decomposeBoustrophedon(area, split_angle).cells) pieces.push_back(c.boundary);
  }
  const double s = spacing;
  std::vector<SpiralCell> cells;
  for (auto piece : pieces) {
    // Simplified first; where that makes the outline cross itself, the skeleton of the original.
    const Ring simple = piece.size() > 8 ? simplifiedRing(piece, kSpiralSimplify * s) : piece;
    detail::InwardOffsetter off(simple);
    if (off.ok()) {
      piece = simple;
    } else if (simple.size() != piece.size()) {
      off = detail::InwardOffsetter(piece);
    }
    if (!off.ok()) continue;
    const double depth = off.depth();
    const auto samples = off.depthSamples(0.25 * s);
    if (depth <= tol::kSliver) continue;
    struct Task {
      Ring ring;
      double offset;
      Ring reference;  // ring just outside the task's first lap
      double margin;   // how close a spike must come to the reference's corners
    };
    std::vector<Task> tasks;
    const double first = std::min(0.5 * s, 0.5 * depth);
    for (const auto& r : off.at(first)) tasks.push_back({ccw(r), first, piece, 0.5 * s});
    while (!tasks.empty()) {
      Task task = tasks.back();
      tasks.pop_back();
      SpiralCell cell;
      Ring cur = task.ring, reference = task.reference;
      double d = task.offset, margin = task.margin;
      while (true) {
        cell.laps.push_back(withSpikes(cur, reference, margin));
        cell.offsets.push_back(d);
        auto inside = [&](const std::vector<Ring>& rings) {
          std::vector<Ring> out;
          for (const auto& r : rings) {
            if (insideRing(cur, r.front())) out.push_back(ccw(r));
          }
          return out;
        };
        double next = d + s;
        auto children = inside(off.at(next));
        // Skeleton nodes (the deepest points of each part) that neither this lap nor the children reach.
        double deepest = -1.0;
        for (const auto& [pt, t] : samples) {
          if (t <= d + 0.5 * s + tol::kPosition || t <= deepest || !insideRing(cur, pt)) continue;
          bool reached = false;
          for (const auto& c : children) reached = reached || insideRing(c, pt) || distanceToRing(c, pt) <= 0.5 * std::sqrt(2.0) * s + tol::kPosition;
          if (!reached) deepest = t;
        }
        if (deepest > 0.0) {
          next = deepest - 0.25 * s;
          children = inside(off.at(next));
        }
        if (children.size() == 1) {
          reference = cur;
          margin = s;
          cur = children.front();
          d = next;
          continue;
        }
        for (const auto& c : children) tasks.push_back({c, next, cur, s});
        break;
      }
      cells.push_back(std::move(cell));
    }
  }
  return cells;
}

Route spiralRoute(const SpiralCell& cell, const SpiralSettings& settings) {
  validateSpacing(settings.spacing);
  Route r;
  const double s = settings.spacing;
  Point last;
  for (size_t k = 0; k < cell.laps.size(); ++k) {
    Ring lap = cell.laps[k];
    if (settings.clockwise) std::reverse(lap.begin(), lap.end());
    const size_t n = lap.size();
    if (n < 2) continue;
    size_t j0 = 0;
    if (k == 0) {
      const long m = static_cast<long>(n);
      j0 = static_cast<size_t>(((settings.start_vertex % m) + m) % m);
    } else {
      double best = std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < n; ++j) {
        const double dist = (lap[j] - last).norm();
        if (dist < best) {
          best = dist;
          j0 = j;
        }
      }
    }
    std::vector<Point> pts;
    for (size_t i = 0; i < n; ++i) pts.push_back(lap[(j0 + i) % n]);
    const Point& v0 = pts.front();
    const Point& vl = pts.back();
    const double closing = (vl - v0).norm();
    if (closing > s) pts.push_back(v0 + (vl - v0) * (s / closing));
    for (const auto& p : pts) {
      if (!r.points.empty()) r.roles.push_back(LegRole::Sweep);
      r.points.push_back(p);
    }
    last = r.points.back();
  }
  // Drop waypoints where the spiral only kinks slightly (a lap joining the next one along almost
  // the same line, as on a rectangle that is not exactly rectangular).
  for (size_t i = 1; i + 1 < r.points.size();) {
    const Point a = r.points[i] - r.points[i - 1], b = r.points[i + 1] - r.points[i];
    const double turn = std::atan2(std::abs(cross(a, b)), a.dot(b));
    const Point chord = r.points[i + 1] - r.points[i - 1];
    const double offset = chord.norm() > 0.0 ? std::abs(cross(chord, r.points[i] - r.points[i - 1])) / chord.norm() : 0.0;
    if (turn < kKinkAngle && offset < kKinkOffset * s) {
      r.points.erase(r.points.begin() + static_cast<long>(i));
      r.roles.erase(r.roles.begin() + static_cast<long>(i));
    } else {
      ++i;
    }
  }
  return r;
}

std::vector<CoveragePath> spiralPaths(const PolygonWithHoles& area, const SpiralSettings& settings,
                                      const CornerSettings& corners, double altitude) {
  const auto cells = decomposeSpiral(area, settings.spacing, settings.split_angle);
  std::vector<CoveragePath> out;
  for (size_t c = 0; c < cells.size(); ++c) {
    CoveragePath p = shapeCorners(spiralRoute(cells[c], settings), corners, altitude, area);
    p.pattern = "spiral";
    p.cell = static_cast<int>(c);
    out.push_back(std::move(p));
  }
  return out;
}

Route joinRoutes(const PolygonWithHoles& area, const std::vector<Route>& routes) {
  Route out;
  for (const auto& r : routes) {
    if (r.points.empty()) continue;
    if (!out.points.empty()) {
      const auto via = safeRoute(area, out.points.back(), r.points.front());
      for (size_t i = 1; i + 1 < via.size(); ++i) {
        out.roles.push_back(LegRole::Transit);
        out.points.push_back(via[i]);
      }
    }
    out.append(r, LegRole::Transit);
  }
  return out;
}

}  // namespace wattswath::geometry
