// Verification: flying a candidate, checking its coverage exactly (geometry's CGAL checker) and
// taking arcs back where it would fall under 99 %; which candidate is the better plan; and the
// public coverage and plan checks.
#include "verification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::planner {
namespace detail {
namespace {

using geometry::Point;
using geometry::Ring;

// A ring without consecutive repeated vertices: CGAL's Boolean operations need simple polygons,
// and the planner itself tolerates repeats (PlannerDegenerate.DuplicateAndCollinearVerticesArePlanned).
Ring withoutRepeats(const Ring& ring) {
  Ring out;
  for (const auto& p : ring)
    if (out.empty() || (p - out.back()).norm() > 1e-9 * std::max(1.0, p.norm())) out.push_back(p);
  while (out.size() > 1 && (out.front() - out.back()).norm() <= 1e-9 * std::max(1.0, out.front().norm())) out.pop_back();
  return out;
}

// `route` flown, its path labelled with the pattern and sweep angle [rad] it came from.
FlownPath flyLabelled(RouteScorer& scorer, const Route& route, double angle, const std::string& pattern) {
  FlownPath f = scorer.fly(route);
  f.path.pattern = pattern;
  f.path.sweep_angle = angle;
  return f;
}

// Whether the two paths sweep the same swaths: the same legs, every field equal (what coverageOf reads).
bool sameLegs(const geometry::CoveragePath& a, const geometry::CoveragePath& b) {
  return std::equal(a.legs.begin(), a.legs.end(), b.legs.begin(), b.legs.end(),
                    [](const geometry::PathLeg& x, const geometry::PathLeg& y) {
                      return x.kind == y.kind && x.role == y.role && x.start == y.start && x.end == y.end &&
                             x.center == y.center && x.radius == y.radius && x.turn_angle == y.turn_angle &&
                             x.heading_start == y.heading_start && x.heading_end == y.heading_end;
                    });
}

}  // namespace

std::vector<geometry::PolygonWithHoles> freeRegions(const SurveyProblem& pr) {
  geometry::PolygonWithHoles area;
  area.outer = withoutRepeats(pr.area.outer);
  for (const auto& h : pr.area.holes) {
    Ring r = withoutRepeats(h);
    if (r.size() >= 3) area.holes.push_back(std::move(r));
  }
  geometry::SurveyArea free;
  free.regions = {area};
  if (!pr.no_fly.empty()) {
    geometry::NoFlyZones zones;
    zones.source = "SurveyProblem.no_fly";
    for (const auto& z : pr.no_fly) {
      Ring r = withoutRepeats(z);
      if (r.size() < 3) continue;
      if (geometry::signedArea(r) < 0) std::reverse(r.begin(), r.end());
      zones.zones.push_back(std::move(r));
    }
    geometry::subtractNoFlyZones(free, zones);
  }
  return free.regions;
}

double coverageOf(const std::vector<geometry::PolygonWithHoles>& regions, double footprint,
                  const geometry::CoveragePath& path) {
  double required = 0.0, covered = 0.0;
  for (const auto& region : regions) {
    const auto r = geometry::checkCoverage(region, {path}, footprint);
    required += r.required_area;
    covered += r.covered_area;
  }
  return required > 0.0 ? 100.0 * covered / required : 100.0;
}

PlanCandidate flyUnverified(RouteScorer& scorer, const AngleResult& a, const std::string& pattern) {
  PlanCandidate c;
  if (!std::isfinite(a.score) || a.route.points.size() < 2) return c;
  c.flown = flyLabelled(scorer, a.route, a.angle, pattern);
  c.pattern = pattern;
  c.sweep_angle_deg = pattern == "spiral" ? 0.0 : normDeg(a.angle);
  c.cells = a.cells;
  c.coverage_pct = std::numeric_limits<double>::quiet_NaN();
  c.valid = true;
  return c;
}

void verify(const std::vector<geometry::PolygonWithHoles>& free, double footprint, RouteScorer& scorer,
            const AngleResult& a, PlanCandidate& c) {
  if (!c.valid) return;
  c.coverage_pct = coverageOf(free, footprint, c.flown.path);
  if (c.coverage_pct >= kMinCoveragePct) return;
  Route route = a.route;
  for (double scale : {0.5, 0.25, 0.0}) {
    for (size_t i = 0; i < route.max_tangent.size(); ++i) route.max_tangent[i] = scale * a.route.max_tangent[i];
    c.flown = flyLabelled(scorer, route, a.angle, c.pattern);
    c.coverage_pct = coverageOf(free, footprint, c.flown.path);
    if (c.coverage_pct >= kMinCoveragePct) return;
  }
}

PlanCandidate finish(const std::vector<geometry::PolygonWithHoles>& free, double footprint, RouteScorer& scorer,
                     const AngleResult& a, const std::string& pattern, const std::vector<const PlanCandidate*>& checked) {
  PlanCandidate c = flyUnverified(scorer, a, pattern);
  // The shortest path is often the plan itself: its coverage is known (verify() would stop at the
  // first check, which keeps kMinCoveragePct), and the exact check is a third of a small field's search.
  for (const PlanCandidate* k : checked)
    if (c.valid && k && k->valid && k->coverage_pct >= kMinCoveragePct && sameLegs(c.flown.path, k->flown.path)) {
      c.coverage_pct = k->coverage_pct;
      return c;
    }
  verify(free, footprint, scorer, a, c);
  return c;
}

bool better(const PlanCandidate& c, const PlanCandidate& plan) {
  if (!c.valid) return false;
  if (!plan.valid) return true;
  const bool covers = c.coverage_pct >= kMinCoveragePct, plan_covers = plan.coverage_pct >= kMinCoveragePct;
  if (covers != plan_covers) return covers;
  if (covers) return c.flown.energy < plan.flown.energy;
  if (std::abs(c.coverage_pct - plan.coverage_pct) > 1e-9) return c.coverage_pct > plan.coverage_pct;
  return c.flown.energy < plan.flown.energy;
}

}  // namespace detail

double coveragePercent(const SurveyProblem& pr, const geometry::CoveragePath& path) {
  return detail::coverageOf(detail::freeRegions(pr), pr.footprint, path);
}

std::vector<std::string> checkPlan(const SurveyProblem& pr, const geometry::CoveragePath& path) {
  // Continuity, headings, arcs and holes: geometry's path checker; then the no-fly zones.
  std::vector<std::string> problems = geometry::checkPath(path, pr.area);
  const std::vector<geometry::Ring>& obstacles = pr.no_fly;
  for (size_t i = 0; i < path.legs.size(); ++i) {
    const auto& leg = path.legs[i];
    std::vector<geometry::Point> pts{leg.start, leg.end};
    if (leg.kind == geometry::PrimitiveKind::Arc) {
      pts.clear();
      const double a0 = std::atan2(leg.start.y() - leg.center.y(), leg.start.x() - leg.center.x());
      for (int k = 0; k <= 16; ++k) {
        const double a = a0 + leg.turn_angle * k / 16.0;
        pts.push_back(leg.center + leg.radius * geometry::Point(std::cos(a), std::sin(a)));
      }
    }
    for (size_t k = 0; k + 1 < pts.size(); ++k)
      for (size_t o = 0; o < obstacles.size(); ++o)
        if (segmentEntersRing(pts[k], pts[k + 1], obstacles[o]) || geometry::insideRing(obstacles[o], pts[k]))
          problems.push_back("leg " + std::to_string(i) + " enters " +
                             "no-fly zone " + std::to_string(o));
  }
  return problems;
}

geometry::ContainmentReport planContainment(const SurveyProblem& pr, const geometry::CoveragePath& path) {
  geometry::PolygonWithHoles area = pr.area;
  area.holes.insert(area.holes.end(), pr.no_fly.begin(), pr.no_fly.end());
  return geometry::checkContainment(area, path);
}

}  // namespace wattswath::planner
