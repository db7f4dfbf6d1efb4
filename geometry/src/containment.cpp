// checkContainment: the length of a path outside its area or inside a hole (the test oracle of
// "every flown point inside the survey area and clear of no-fly zones").
#include <algorithm>
#include <cmath>
#include <limits>

#include "ring_index.hpp"
#include "wattswath/geometry/check.hpp"

namespace wattswath::geometry {
namespace {

// Parameters in (0, 1) where segment a-b crosses or touches an edge of `ring`.
void crossingParams(const Point& a, const Point& b, const Ring& ring, std::vector<double>& ts) {
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) detail::edgeCrossing(a, b, ring[i], ring[(i + 1) % n] - ring[i], ts);
}

// Calls piece(t0, t1, middle) for each piece of segment a-b between consecutive parameters of
// `ts` (the crossings, with 0 and 1), in order, until it returns true; returns whether one did.
// Pieces between consecutive crossings are wholly on one side: each is classified at its middle.
template <typename Piece>
bool forEachPiece(const Point& a, const Point& b, std::vector<double>& ts, Piece piece) {
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end(), [](double u, double v) { return v - u <= 1e-12; }), ts.end());
  for (size_t k = 0; k + 1 < ts.size(); ++k) {
    const double t0 = std::clamp(ts[k], 0.0, 1.0), t1 = std::clamp(ts[k + 1], 0.0, 1.0);
    if (t1 - t0 > 0.0 && piece(t0, t1, Point(a + 0.5 * (t0 + t1) * (b - a)))) return true;
  }
  return false;
}

// Adds the parts of segment a-b outside the outer ring or inside a hole to `rep`.
void measureSegment(const Ring& outer, const std::vector<Ring>& holes, const Point& a, const Point& b,
                    double tolerance, ContainmentReport& rep) {
  const double len = (b - a).norm();
  if (len <= 0.0) return;
  std::vector<double> ts{0.0, 1.0};
  crossingParams(a, b, outer, ts);
  for (const auto& h : holes) crossingParams(a, b, h, ts);
  forEachPiece(a, b, ts, [&](double t0, double t1, const Point& m) {
    auto depthTo = [&](const Ring& r) {
      const Point ends[3] = {a + t0 * (b - a), m, a + t1 * (b - a)};
      double dmax = 0.0;
      for (const auto& q : ends) dmax = std::max(dmax, distanceToRing(r, q));
      return dmax;
    };
    if (!insideRing(outer, m) && distanceToRing(outer, m) > tolerance) {
      rep.outside_m += (t1 - t0) * len;
      rep.max_depth_m = std::max(rep.max_depth_m, depthTo(outer));
      return false;
    }
    for (const auto& h : holes) {
      if (insideRing(h, m) && distanceToRing(h, m) > tolerance) {
        rep.in_holes_m += (t1 - t0) * len;
        rep.max_depth_m = std::max(rep.max_depth_m, depthTo(h));
        break;
      }
    }
    return false;
  });
}

}  // namespace

bool segmentLeavesArea(const PolygonWithHoles& area, const Point& a, const Point& b) {
  // As measureSegment on the outer ring, stopping at the first piece outside (a route search asks
  // this for thousands of candidate segments: no lengths or depths needed).
  if ((b - a).norm() <= 0.0) return false;
  std::vector<double> ts{0.0, 1.0};
  crossingParams(a, b, area.outer, ts);
  return forEachPiece(a, b, ts, [&](double, double, const Point& m) {
    return !insideRing(area.outer, m) && distanceToRing(area.outer, m) > tol::kContainment;
  });
}

namespace detail {

bool segmentLeavesRing(const RingIndex& outer, const Point& a, const Point& b) {
  // segmentLeavesArea with the outer ring's questions answered by its index.
  if ((b - a).norm() <= 0.0) return false;
  std::vector<double> ts{0.0, 1.0};
  outer.crossingParams(a, b, ts);
  return forEachPiece(a, b, ts, [&](double, double, const Point& m) {
    return !outer.inside(m) && !outer.near(m, tol::kContainment);
  });
}

}  // namespace detail

ContainmentReport checkContainment(const PolygonWithHoles& area, const CoveragePath& path, bool survey_only,
                                   double tolerance) {
  size_t first = 0, last = path.legs.size();
  if (survey_only) {
    auto isSweep = [](const PathLeg& l) { return l.role == LegRole::Sweep; };
    const auto f = std::find_if(path.legs.begin(), path.legs.end(), isSweep);
    const auto r = std::find_if(path.legs.rbegin(), path.legs.rend(), isSweep);
    first = static_cast<size_t>(f - path.legs.begin());
    last = static_cast<size_t>(path.legs.rend() - r);
  }
  ContainmentReport rep;
  for (size_t i = first; i < last; ++i) {
    const PathLeg& leg = path.legs[i];
    if (leg.kind == PrimitiveKind::TurnInPlace) continue;  // no length; its point ends a line measured
    if (leg.kind == PrimitiveKind::Line) {
      measureSegment(area.outer, area.holes, leg.start, leg.end, tolerance, rep);
      continue;
    }
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(leg.turn_angle) / tol::kArcChord)));
    const double a0 = std::atan2(leg.start.y() - leg.center.y(), leg.start.x() - leg.center.x());
    Point prev = leg.start;
    for (int k = 1; k <= n; ++k) {
      const double a = a0 + leg.turn_angle * k / n;
      const Point q = k == n ? leg.end : Point(leg.center + leg.radius * Point(std::cos(a), std::sin(a)));
      measureSegment(area.outer, area.holes, prev, q, tolerance, rep);
      prev = q;
    }
  }
  return rep;
}

}  // namespace wattswath::geometry
