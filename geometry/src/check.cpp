#include "wattswath/geometry/check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <sstream>

#include "cgal_ops.hpp"
#include "ring_index.hpp"
#include "wattswath/geometry/tolerances.hpp"

namespace wattswath::geometry {
namespace {

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

double angleGap(double a, double b) { return std::abs(std::remainder(a - b, 2.0 * M_PI)); }

Point rotate(const Point& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Point(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

/// Points along a leg: its ends for a line, chord ends for an arc, one point for a turn in place.
std::vector<Point> legPolyline(const PathLeg& leg, double chord = tol::kArcChord) {
  if (leg.kind != PrimitiveKind::Arc) return {leg.start, leg.end};
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(leg.turn_angle) / chord)));
  std::vector<Point> pts;
  for (int i = 0; i <= n; ++i) pts.push_back(leg.center + rotate(leg.start - leg.center, leg.turn_angle * i / n));
  return pts;
}

Ring rectangle(const Point& a, const Point& b, double spacing) {
  const double h = 0.5 * spacing;
  Point d = b - a;
  const double len = d.norm();
  d = len > 0.0 ? Point(d / len) : Point(1.0, 0.0);
  const Point nrm(-d.y(), d.x());
  const Point p0 = a - h * d, p1 = b + h * d;
  return {p0 - h * nrm, p1 - h * nrm, p1 + h * nrm, p0 + h * nrm};
}

std::string legName(size_t i) { return "leg " + std::to_string(i); }

}  // namespace

double distanceToSegment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

bool insideRing(const Ring& ring, const Point& p, double margin) {
  bool inside = false;
  const size_t n = ring.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  if (!inside || margin <= 0.0) return inside;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    if (distanceToSegment(p, ring[j], ring[i]) <= margin) return false;
  }
  return true;
}

double distanceToRing(const Ring& ring, const Point& p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < ring.size(); ++i) best = std::min(best, distanceToSegment(p, ring[i], ring[(i + 1) % ring.size()]));
  return best;
}

namespace detail {

bool segmentEntersRing(const Ring& hole, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double len2 = ab.squaredNorm();
  std::vector<double> ts{0.0, 1.0};
  const size_t n = hole.size();
  for (size_t i = 0; i < n; ++i) {
    const Point& c = hole[i];
    const Point& d = hole[(i + 1) % n];
    const Point cd = d - c;
    const double den = cross(ab, cd);
    if (std::abs(den) > 1e-12 * std::sqrt(len2 * cd.squaredNorm())) {
      const double t = cross(c - a, cd) / den, u = cross(c - a, ab) / den;
      if (t > 0.0 && t < 1.0 && u >= -1e-12 && u <= 1.0 + 1e-12) ts.push_back(t);
    } else if (len2 > 0.0) {  // parallel: split at the projections of the edge ends
      for (const Point& q : {c, d}) {
        const double t = (q - a).dot(ab) / len2;
        if (t > 0.0 && t < 1.0) ts.push_back(t);
      }
    }
  }
  std::sort(ts.begin(), ts.end());
  for (size_t k = 0; k + 1 < ts.size(); ++k) {
    if (ts[k + 1] - ts[k] <= 0.0 && len2 > 0.0) continue;
    const Point m = a + 0.5 * (ts[k] + ts[k + 1]) * ab;
    if (insideRing(hole, m, tol::kHoleDepth)) return true;
  }
  return false;
}

}  // namespace detail

bool segmentEntersHole(const PolygonWithHoles& area, const Point& a, const Point& b) {
  // A hole whose bounding box the segment's misses cannot be entered (its inside lies in the box);
  // the box costs comparisons where the exact test costs an allocation and cross products.
  const Point lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  for (const auto& hole : area.holes) {
    bool apart = !hole.empty();
    for (int axis = 0; axis < 2 && apart; ++axis) {
      double h_lo = hole.front()[axis], h_hi = h_lo;
      for (const auto& v : hole) h_lo = std::min(h_lo, v[axis]), h_hi = std::max(h_hi, v[axis]);
      apart = h_hi < lo[axis] || h_lo > hi[axis];
    }
    if (!apart && detail::segmentEntersRing(hole, a, b)) return true;
  }
  return false;
}

std::vector<Point> safeRoute(const PolygonWithHoles& area, const Point& a, const Point& b) {
  const bool stay_inside = insideRing(area.outer, a) || distanceToRing(area.outer, a) <= tol::kContainment;
  const bool b_inside = insideRing(area.outer, b) || distanceToRing(area.outer, b) <= tol::kContainment;
  // A large outer ring is indexed once for the many visibility checks (each answer as the plain loop's).
  std::optional<detail::RingIndex> outer;
  if (stay_inside && b_inside && area.outer.size() >= detail::kMinIndexedVertices) outer.emplace(area.outer);
  auto leaves = [&](const Point& p, const Point& q) {
    return outer ? detail::segmentLeavesRing(*outer, p, q) : segmentLeavesArea(area, p, q);
  };
  // Many holes are indexed by box likewise.
  std::optional<detail::HoleIndex> holes;
  if (area.holes.size() >= detail::kMinIndexedHoles) holes.emplace(area.holes);
  auto blocked = [&](const Point& p, const Point& q) {
    const bool enters = holes ? holes->segmentEnters(p, q) : segmentEntersHole(area, p, q);
    return enters || (stay_inside && b_inside && leaves(p, q));
  };
  if (!blocked(a, b)) return {a, b};
  std::vector<Point> nodes{a, b};
  if (stay_inside && b_inside) {
    const double orient = signedArea(area.outer) >= 0.0 ? 1.0 : -1.0;
    const size_t n = area.outer.size();
    for (size_t i = 0; i < n; ++i) {  // reflex corners of the outer boundary
      const Point& p = area.outer[(i + n - 1) % n];
      const Point& q = area.outer[i];
      if (orient * cross(q - p, area.outer[(i + 1) % n] - q) < 0.0) nodes.push_back(q);
    }
  }
  for (const auto& h : area.holes) {
    const double orient = signedArea(h) >= 0.0 ? 1.0 : -1.0;
    const size_t n = h.size();
    for (size_t i = 0; i < n; ++i) {  // only convex corners of a hole can be on a shortest path
      const Point& p = h[(i + n - 1) % n];
      const Point& q = h[i];
      const Point& r = h[(i + 1) % n];
      if (orient * cross(q - p, r - q) > 0.0) nodes.push_back(q);
    }
  }
  // A* over the visibility graph of the nodes (Euclidean distance to b: consistent), with lazy
  // edge checks: an edge is checked when its far node is taken from the queue, not when it is
  // offered, so a nearly straight route on a boundary of thousands of reflex corners checks a few
  // edges instead of every pair (a 2,000-vertex field took 8 minutes to plan).
  const size_t n = nodes.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<size_t> prev(n, n);
  std::vector<bool> done(n, false), checked(n, false);
  auto h = [&](size_t v) { return (nodes[v] - nodes[1]).norm(); };
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  dist[0] = 0.0;
  checked[0] = true;
  queue.push({h(0), 0});
  while (!queue.empty()) {
    const auto [f, u] = queue.top();
    queue.pop();
    if (done[u] || f != dist[u] + h(u)) continue;  // settled, or a stale entry (pushed as exactly dist + h)
    if (!checked[u]) {
      // Offered by a parent not yet checked: if that parent cannot see it, take the best settled
      // node that can (or drop it until a newly settled node offers it again).
      checked[u] = true;
      if (blocked(nodes[prev[u]], nodes[u])) {
        dist[u] = std::numeric_limits<double>::infinity();
        prev[u] = n;
        for (size_t v = 0; v < n; ++v) {
          const double nd = dist[v] + (nodes[u] - nodes[v]).norm();
          if (done[v] && nd < dist[u] && !blocked(nodes[v], nodes[u])) {
            dist[u] = nd;
            prev[u] = v;
          }
        }
        if (prev[u] != n) queue.push({dist[u] + h(u), u});
        continue;
      }
    }
    done[u] = true;
    if (u == 1) break;
    for (size_t v = 0; v < n; ++v) {
      if (done[v]) continue;
      const double nd = dist[u] + (nodes[v] - nodes[u]).norm();
      if (nd < dist[v]) {
        dist[v] = nd;
        prev[v] = u;
        checked[v] = false;
        queue.push({nd + h(v), v});
      }
    }
  }
  if (prev[1] == n) return {a, b};
  std::vector<Point> out;
  for (size_t v = 1; v != n; v = prev[v]) out.push_back(nodes[v]);
  std::reverse(out.begin(), out.end());
  return out;
}

std::vector<Ring> swathPolygons(const CoveragePath& path, double spacing) {
  std::vector<Ring> out;
  for (const auto& leg : path.legs) {
    if (leg.kind == PrimitiveKind::TurnInPlace) continue;
    if (leg.role != LegRole::Sweep && leg.role != LegRole::Turn) continue;
    const auto pts = legPolyline(leg, tol::kSwathArcChord);
    for (size_t i = 1; i < pts.size(); ++i) out.push_back(rectangle(pts[i - 1], pts[i], spacing));
  }
  return out;
}

CoverageReport checkCoverage(const PolygonWithHoles& area, const std::vector<CoveragePath>& paths, double spacing) {
  std::vector<Ring> swaths;
  for (const auto& p : paths) {
    auto s = swathPolygons(p, spacing);
    swaths.insert(swaths.end(), s.begin(), s.end());
  }
  CoverageReport r;
  r.required_area = detail::coveredArea(area, {area.outer});
  r.covered_area = detail::coveredArea(area, swaths);
  return r;
}

std::vector<std::string> checkPath(const CoveragePath& path, const PolygonWithHoles& area) {
  std::vector<std::string> problems;
  auto report = [&](size_t i, const std::string& what) { problems.push_back(legName(i) + ": " + what); };
  for (size_t i = 0; i < path.legs.size(); ++i) {
    const PathLeg& l = path.legs[i];
    if (!l.start.allFinite() || !l.end.allFinite() || !std::isfinite(l.heading_start) ||
        !std::isfinite(l.heading_end) || !std::isfinite(l.turn_angle) || !std::isfinite(l.radius)) {
      report(i, "non-finite value");
      continue;
    }
    const double scale = std::max(1.0, std::max(l.start.norm(), l.end.norm()));
    const double ptol = tol::kCheckPosition * scale;
    switch (l.kind) {
      case PrimitiveKind::Line: {
        const Point d = l.end - l.start;
        if (d.norm() > ptol) {
          const double h = std::atan2(d.y(), d.x());
          if (angleGap(h, l.heading_start) > tol::kCheckAngle || angleGap(h, l.heading_end) > tol::kCheckAngle)
            report(i, "line headings are not along the line");
        }
        break;
      }
      case PrimitiveKind::Arc: {
        if (!(l.radius > 0.0)) {
          report(i, "arc radius is not positive");
          break;
        }
        const double side = l.turn_angle >= 0.0 ? 1.0 : -1.0;
        const Point n0(-std::sin(l.heading_start), std::cos(l.heading_start));
        if ((l.start + side * l.radius * n0 - l.center).norm() > ptol)
          report(i, "arc start heading is not tangent to its circle");
        const Point end = l.center + rotate(l.start - l.center, l.turn_angle);
        if ((end - l.end).norm() > ptol) report(i, "arc end is not where its turn angle leads");
        if (angleGap(l.heading_start + l.turn_angle, l.heading_end) > tol::kCheckAngle)
          report(i, "arc end heading does not match its turn angle");
        break;
      }
      case PrimitiveKind::TurnInPlace: {
        if ((l.end - l.start).norm() > ptol) report(i, "turn in place moves");
        if (angleGap(l.heading_start + l.turn_angle, l.heading_end) > tol::kCheckAngle)
          report(i, "turn in place end heading does not match its turn angle");
        break;
      }
    }
    if (i + 1 < path.legs.size()) {
      const PathLeg& n = path.legs[i + 1];
      if ((n.start - l.end).norm() > ptol) {
        std::ostringstream os;
        os << "gap of " << (n.start - l.end).norm() << " m to the next leg";
        report(i, os.str());
      }
      if (angleGap(n.heading_start, l.heading_end) > tol::kCheckAngle) {
        std::ostringstream os;
        os << "heading jumps by " << angleGap(n.heading_start, l.heading_end) << " rad to the next leg";
        report(i, os.str());
      }
    }
    const auto pts = legPolyline(l);
    bool enters = false;
    if (l.kind == PrimitiveKind::TurnInPlace) {
      for (const auto& h : area.holes) enters = enters || insideRing(h, l.start, tol::kHoleDepth);
    }
    for (size_t k = 1; k < pts.size() && !enters; ++k) enters = segmentEntersHole(area, pts[k - 1], pts[k]);
    if (enters) report(i, "enters a hole");
  }
  return problems;
}

}  // namespace wattswath::geometry
