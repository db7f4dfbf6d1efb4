#include "wattswath/geometry/route.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/tolerances.hpp"

namespace wattswath::geometry {

void Route::append(const Route& other, LegRole join_role) {
  if (other.points.empty()) return;
  if (!points.empty() && (points.back() - other.points.front()).norm() > tol::kPosition) {
    roles.push_back(join_role);
    points.push_back(other.points.front());
  } else if (points.empty()) {
    points.push_back(other.points.front());
  }
  points.insert(points.end(), other.points.begin() + 1, other.points.end());
  roles.insert(roles.end(), other.roles.begin(), other.roles.end());
}

double Route::length() const {
  double l = 0.0;
  for (size_t i = 1; i < points.size(); ++i) l += (points[i] - points[i - 1]).norm();
  return l;
}

double tangentWithin(double turn, double margin) {
  const double h = 0.5 * std::abs(turn);
  if (h < 1e-9 || margin <= 0.0) return 0.0;
  return margin * std::tan(h) / (1.0 / std::cos(h) - 1.0);
}

namespace {

double headingOf(const Point& d) { return std::atan2(d.y(), d.x()); }

/// Signed angle from heading a to heading b in (-pi, pi].
double turnAngle(double a, double b) {
  double d = std::remainder(b - a, 2.0 * M_PI);
  if (d <= -M_PI) d += 2.0 * M_PI;
  return d;
}

PathLeg lineLeg(const Point& a, const Point& b, LegRole role, double alt) {
  PathLeg l;
  l.kind = PrimitiveKind::Line;
  l.role = role;
  l.start = a;
  l.end = b;
  l.heading_start = l.heading_end = headingOf(b - a);
  l.altitude = alt;
  return l;
}

/// Whether the arc of radius r rounding the corner at b (entered from a) (turn angle `turn`) enters a
/// hole or leaves the outer boundary.
bool arcEntersHole(const PolygonWithHoles& keep_out, const Point& a, const Point& b, double r,
                   double turn) {
  // Since issue 22 an arc must not leave the outer boundary either (at a corner inside the area:
  // a transit from a home outside is not held to it).
  const bool keep_inside = !keep_out.outer.empty() && (insideRing(keep_out.outer, b) ||
                                                       distanceToRing(keep_out.outer, b) <= tol::kContainment);
  if (keep_out.holes.empty() && !keep_inside) return false;
  const Point din = (b - a).normalized();
  const double t = r * std::tan(0.5 * std::abs(turn));
  const Point start = b - t * din;
  const Point normal = turn > 0 ? Point(-din.y(), din.x()) : Point(din.y(), -din.x());
  const Point center = start + r * normal;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(turn) / tol::kArcChord)));
  Point prev = start;
  for (int k = 1; k <= n; ++k) {
    const double phi = turn * k / n;
    const Point rel = start - center;
    const Point q = center + Point(std::cos(phi) * rel.x() - std::sin(phi) * rel.y(),
                                   std::sin(phi) * rel.x() + std::cos(phi) * rel.y());
    if (segmentEntersHole(keep_out, prev, q) || (keep_inside && segmentLeavesArea(keep_out, prev, q))) return true;
    prev = q;
  }
  return false;
}

}  // namespace

CoveragePath shapeCorners(const Route& route, const CornerSettings& corners, double altitude,
                          const PolygonWithHoles& keep_out) {
  if (route.points.empty()) return {};
  if (route.roles.size() + 1 != route.points.size()) {
    throw std::invalid_argument("shapeCorners: route has " + std::to_string(route.points.size()) + " points but " +
                                std::to_string(route.roles.size()) + " roles (expected points - 1)");
  }
  if (!(corners.radius >= 0.0) || !std::isfinite(corners.radius)) {
    throw std::invalid_argument("shapeCorners: corner radius " + std::to_string(corners.radius) +
                                " m, expected a finite value >= 0");
  }
  for (size_t i = 0; i < route.points.size(); ++i) {
    if (!route.points[i].allFinite())
      throw std::invalid_argument("shapeCorners: waypoint " + std::to_string(i) + " is not finite");
  }
  // Drop zero-length segments and merge collinear same-direction segments of the same role.
  std::vector<Point> pts{route.points.front()};
  std::vector<LegRole> roles;
  for (size_t i = 1; i < route.points.size(); ++i) {
    const Point& p = route.points[i];
    if ((p - pts.back()).norm() <= tol::kPosition) continue;
    if (pts.size() >= 2 && roles.back() == route.roles[i - 1]) {
      const Point d0 = pts.back() - pts[pts.size() - 2], d1 = p - pts.back();
      const double cross = d0.x() * d1.y() - d0.y() * d1.x();
      if (std::abs(cross) <= tol::kPosition * (d0.norm() + d1.norm()) && d0.dot(d1) > 0.0) {
        pts.back() = p;
        continue;
      }
    }
    pts.push_back(p);
    roles.push_back(route.roles[i - 1]);
  }
  CoveragePath path;
  const size_t nseg = roles.size();
  if (nseg == 0) return path;
  // Corner i sits at pts[i] between segment i-1 and segment i (i = 1 .. nseg-1).
  std::vector<double> angle(nseg + 1, 0.0), radius(nseg + 1, 0.0), cut(nseg + 1, 0.0);
  std::vector<double> len(nseg);
  for (size_t s = 0; s < nseg; ++s) len[s] = (pts[s + 1] - pts[s]).norm();
  for (size_t i = 1; i < nseg; ++i) {
    angle[i] = turnAngle(headingOf(pts[i] - pts[i - 1]), headingOf(pts[i + 1] - pts[i]));
    if (corners.style != CornerStyle::Rounded || corners.radius <= 0.0 ||
        std::abs(angle[i]) > corners.max_rounded_angle || std::abs(angle[i]) <= tol::kAngle)
      continue;
    const double t = std::tan(0.5 * std::abs(angle[i]));
    const double avail_in = i == 1 ? len[i - 1] : 0.5 * len[i - 1];
    const double avail_out = i + 1 == nseg ? len[i] : 0.5 * len[i];
    double r = std::min(corners.radius, std::min(avail_in, avail_out) / t);
    for (int attempt = 0; attempt < 3 && r > 0.0; ++attempt, r *= 0.5) {
      if (!arcEntersHole(keep_out, pts[i - 1], pts[i], r, angle[i])) break;
      if (attempt == 2) r = 0.0;
    }
    radius[i] = r;
    cut[i] = radius[i] * t;
  }
  Point cursor = pts[0];
  for (size_t s = 0; s < nseg; ++s) {
    const Point dir = (pts[s + 1] - pts[s]) / len[s];
    const Point seg_end = pts[s + 1] - cut[s + 1] * dir;
    if ((seg_end - cursor).norm() > tol::kPosition) path.legs.push_back(lineLeg(cursor, seg_end, roles[s], altitude));
    cursor = seg_end;
    const size_t c = s + 1;  // corner at the end of segment s
    if (c >= nseg || std::abs(angle[c]) <= tol::kAngle) continue;
    const double h0 = headingOf(dir), h1 = headingOf(pts[c + 1] - pts[c]);
    PathLeg leg;
    leg.role = LegRole::Turn;
    leg.altitude = altitude;
    leg.heading_start = h0;
    leg.heading_end = h0 + angle[c];
    leg.turn_angle = angle[c];
    leg.start = cursor;
    if (radius[c] > tol::kPosition) {
      const Point out_dir(std::cos(h1), std::sin(h1));
      const Point normal = angle[c] > 0 ? Point(-dir.y(), dir.x()) : Point(dir.y(), -dir.x());
      leg.kind = PrimitiveKind::Arc;
      leg.radius = radius[c];
      leg.center = cursor + radius[c] * normal;
      leg.end = pts[c] + cut[c] * out_dir;
    } else {
      leg.kind = PrimitiveKind::TurnInPlace;
      leg.end = cursor;
    }
    path.legs.push_back(leg);
    cursor = leg.end;
  }
  return path;
}

}  // namespace wattswath::geometry
