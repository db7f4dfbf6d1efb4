// Keeping clear: the problem with its no-fly zones grown by the margin (geometry's inflateRings and
// subtractRings), and the inclusion fence around the area and the flown path.
#include "wattswath/planner/margin.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/clearance.hpp"

namespace wattswath::planner {
namespace {

namespace geo = wattswath::geometry;

/// [m] Largest gap between the points of a path sampled for how far it strays outside the area.
constexpr double kSampleStep = 1.0;

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

/// Throws std::invalid_argument naming `what` unless `v` is finite and at least (or above) zero.
void checkMargin(double v, bool zero_ok, const std::string& what) {
  if (!std::isfinite(v) || v < 0.0 || (!zero_ok && v == 0.0))
    throw std::invalid_argument(what + " = " + std::to_string(v) + " m, expected " + (zero_ok ? ">= 0" : "> 0"));
}

/// Throws std::invalid_argument when `home` [m] lies inside a zone or within `margin` [m] of one.
void checkHome(const geo::Point& home, const std::vector<geo::Ring>& zones, double margin) {
  geo::PathLeg at;
  at.kind = geo::PrimitiveKind::TurnInPlace;
  at.start = at.end = home;
  for (size_t z = 0; z < zones.size(); ++z) {
    const double edge = geo::distanceToRing(at, zones[z]);
    if (geo::insideRing(zones[z], home) && edge > 0.01)
      throw std::invalid_argument("home is inside no-fly zone " + std::to_string(z) + " (counted from 0 in the order the "
                                  "zones were given), " + metres(edge) + " m from its edge: move home (--home)");
    const double d = geo::insideRing(zones[z], home) ? 0.0 : edge;
    if (d < margin)
      throw std::invalid_argument("home is " + metres(d) + " m from no-fly zone " + std::to_string(z) +
                                  " (counted from 0 in the order the zones were given), within the no-fly margin of " +
                                  metres(margin) + " m: move home (--home) or lower --no-fly-margin");
  }
}

/// How far `p` [m] lies outside `ring` (0 inside).
double outsideBy(const geo::Ring& ring, const geo::Point& p) {
  if (geo::insideRing(ring, p)) return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < ring.size(); ++i) d = std::min(d, geo::distanceToSegment(p, ring[i], ring[(i + 1) % ring.size()]));
  return d;
}

/// Points of `leg` at most kSampleStep apart along it, both ends included.
std::vector<geo::Point> samples(const geo::PathLeg& leg) {
  const int n = std::max(1, static_cast<int>(std::ceil(leg.length() / kSampleStep)));
  std::vector<geo::Point> pts;
  const double a0 = std::atan2(leg.start.y() - leg.center.y(), leg.start.x() - leg.center.x());
  for (int k = 0; k <= n; ++k) {
    const double f = static_cast<double>(k) / n;
    if (leg.kind == geo::PrimitiveKind::Arc)
      pts.push_back(leg.center + leg.radius * geo::Point(std::cos(a0 + f * leg.turn_angle), std::sin(a0 + f * leg.turn_angle)));
    else
      pts.push_back(leg.start + f * (leg.end - leg.start));
  }
  return pts;
}

/// The ring of largest area among `rings` (empty when there is none).
geo::Ring largest(const std::vector<geo::Ring>& rings) {
  geo::Ring best;
  double best_area = -1.0;
  for (const auto& r : rings)
    if (std::abs(geo::signedArea(r)) > best_area) {
      best_area = std::abs(geo::signedArea(r));
      best = r;
    }
  return best;
}

}  // namespace

std::vector<geo::Ring> noFlyZones(const SurveyProblem& problem) {
  std::vector<geo::Ring> zones = problem.area.holes;
  zones.insert(zones.end(), problem.no_fly.begin(), problem.no_fly.end());
  return zones;
}

SurveyProblem withNoFlyMargin(const SurveyProblem& problem, double margin_m, std::vector<std::string>* notes) {
  checkMargin(margin_m, true, "no-fly margin");
  const auto zones = noFlyZones(problem);
  if (margin_m == 0.0 || zones.empty()) return problem;
  checkHome(problem.home, zones, margin_m);
  std::vector<geo::Ring> grown;
  try {
    grown = geo::inflateRings(zones, margin_m + kMarginPad);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("no-fly zones (holes first, then the extra zones): ") + e.what());
  }
  auto parts = geo::subtractRings(problem.area.outer, grown);
  if (parts.empty())
    throw std::invalid_argument("the no-fly margin of " + metres(margin_m) +
                                " m around the no-fly zones leaves nothing of the area to cover; lower --no-fly-margin");
  std::sort(parts.begin(), parts.end(),
            [](const geo::PolygonWithHoles& a, const geo::PolygonWithHoles& b) { return geo::area(a) > geo::area(b); });
  SurveyProblem out = problem;
  out.area = parts.front();
  out.no_fly = grown;
  if (parts.size() > 1 && notes) {
    double left = 0.0;
    for (size_t i = 1; i < parts.size(); ++i) left += geo::area(parts[i]);
    notes->push_back("WARNING: the no-fly margin of " + metres(margin_m) + " m cuts the area into " + std::to_string(parts.size()) +
                     " parts; the largest is covered, " + metres(left) + " m^2 in the others is NOT (plan them from "
                     "their own area file, or lower --no-fly-margin)");
  }
  return out;
}

InclusionFence inclusionFence(const SurveyProblem& problem, const geo::CoveragePath& path, double margin_m) {
  checkMargin(margin_m, false, "inclusion fence margin");
  const geo::Ring& outer = problem.area.outer;
  double out_by = outsideBy(outer, problem.home);
  for (const auto& leg : path.legs)
    for (const auto& p : samples(leg)) out_by = std::max(out_by, outsideBy(outer, p));
  // Samples at most kSampleStep apart: no flown point is more than half a step beyond the farthest.
  double d = margin_m + out_by + 0.5 * kSampleStep;
  for (int attempt = 0; attempt < 8; ++attempt, d += margin_m) {
    InclusionFence f{largest(geo::inflateRings({outer}, d)), d};
    if (!f.ring.empty() && geo::fenceViolations(path, f.ring, margin_m).empty() && geo::insideRing(f.ring, problem.home))
      return f;
  }
  throw std::runtime_error("inclusion fence: no fence within " + metres(d) + " m of the area keeps the path " +
                           metres(margin_m) + " m inside it");
}

}  // namespace wattswath::planner
