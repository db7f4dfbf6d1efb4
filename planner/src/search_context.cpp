// What the stages of the coverage search share: the stop-to-stop table, angles, workers, and the
// route helpers (moves around obstacles, cell zigzags, cost estimates, the area with its zones).
#include "search_context.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

#include "wattswath/geometry/check.hpp"

namespace wattswath::planner::detail {
namespace {

using geometry::LegRole;
using geometry::Point;
using geometry::Ring;
constexpr int kStopTableSize = 64;  // samples of the stop-to-stop leg energy table (log spaced)

}  // namespace

StopTable makeStopTable(RouteScorer& scorer, double max_len) {
  StopTable t;
  const double lo = 0.5, hi = std::max(max_len, 10.0);
  for (int i = 0; i < kStopTableSize; ++i) {
    const double L = lo * std::pow(hi / lo, static_cast<double>(i) / (kStopTableSize - 1));
    t.len.push_back(L);
    t.e.push_back(scorer.legEnergy(L, 0.0, 0.0, scorer.settings().max_speed));
  }
  return t;
}

// Rounded to 1e-9 deg: the search steps whole and tenth degrees in radians, and 66 deg should read
// 66, not 65.99999999999999.
double normDeg(double rad) {
  double d = std::fmod(rad / kDeg, 180.0);
  if (d < 0) d += 180.0;
  d = std::round(d * 1e9) / 1e9;
  return d >= 180.0 ? 0.0 : d;
}

void onWorkers(int workers, const std::function<void(int)>& work) {
  std::vector<std::thread> pool;
  std::exception_ptr error;
  std::mutex m;
  for (int t = 0; t < workers; ++t)
    pool.emplace_back([&, t]() {
      try {
        work(t);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        error = std::current_exception();
      }
    });
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

void moveTo(const Context& ctx, Route& r, const Point& to, LegRole role, double tangent_at_to) {
  const Point from = r.points.back();
  if (ctx.router->clear(from, to)) {
    // A move between two points of the area that would cut across a bay of the outer boundary
    // goes over its reflex corners instead (when that way is clear of the obstacles too).
    if (ctx.inside.outer.empty() || !geometry::segmentLeavesArea(ctx.inside, from, to)) {
      r.add(to, role, tangent_at_to);
      return;
    }
    const auto inside = geometry::safeRoute(ctx.inside, from, to);
    bool clear = true;
    for (size_t i = 1; i < inside.size() && clear; ++i) clear = ctx.router->clear(inside[i - 1], inside[i]);
    if (clear) {
      for (size_t i = 1; i + 1 < inside.size(); ++i) r.add(inside[i], LegRole::Transit, 0.0);
      r.add(to, role, tangent_at_to);
      return;
    }
  }
  const auto path = ctx.router->route(from, to);
  for (size_t i = 1; i + 1 < path.size(); ++i) r.add(path[i], LegRole::Transit, 0.5 * ctx.clearance);
  r.add(to, role, tangent_at_to);
}

void appendVia(const Context& ctx, Route& r, const Route& next) {
  moveTo(ctx, r, next.points.front(), LegRole::Transit, next.max_tangent.front());
  for (size_t i = 1; i < next.points.size(); ++i) r.add(next.points[i], next.roles[i - 1], next.max_tangent[i]);
}

Route reversed(const Route& r) {
  Route o;
  o.points.assign(r.points.rbegin(), r.points.rend());
  o.roles.assign(r.roles.rbegin(), r.roles.rend());
  o.max_tangent.assign(r.max_tangent.rbegin(), r.max_tangent.rend());
  return o;
}

std::vector<geometry::SweepLineCell> sweepCells(const Context& ctx, double angle, double* first_y) {
  geometry::SweepLineSettings s;
  s.spacing = ctx.problem->spacing;
  s.clearance = ctx.clearance;
  s.run_out = ctx.run_out;
  s.fewer_lines = ctx.fewer_lines;
  const auto lines = geometry::sweepLines(ctx.problem->area.outer, ctx.obstacles, angle, s);
  *first_y = lines.first_y;
  return geometry::sweepLineCells(lines.lines);
}

Route cellRoute(const Context& ctx, const geometry::SweepLineCell& cell, double angle, double first_y, bool from_top,
                bool start_right) {
  Route r;
  for (const auto& pass : geometry::sweepPasses(cell, angle, first_y, ctx.problem->spacing, from_top, start_right)) {
    if (r.points.empty()) {
      r.points.push_back(pass.start);
      r.max_tangent.push_back(0.0);
    } else {
      // The connector between two lines is the turn between them (role Turn, as geometry's
      // boustrophedon labels it): its footprint covers the wedges a slanted boundary leaves
      // beyond the lines' ends, which end on the boundary since issue 22.
      moveTo(ctx, r, pass.start, LegRole::Turn, pass.start_run_out + ctx.turn_room);
    }
    r.add(pass.end, LegRole::Sweep, pass.end_run_out + ctx.turn_room);
  }
  return r;
}

double polylineCost(const std::vector<Point>& pts, Objective obj, const StopTable& stop, const RouteScorer& scorer) {
  double c = 0.0;
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const double L = (pts[i + 1] - pts[i]).norm();
    c += obj == Objective::Length ? L : stop.eval(L);
    if (obj == Objective::Energy && i + 2 < pts.size()) {
      const Point u = pts[i + 1] - pts[i], v = pts[i + 2] - pts[i + 1];
      c += scorer.turnEnergy(std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v)));
    }
  }
  return c;
}

double stopEstimate(const Route& r, const StopTable& stop, const RouteScorer& scorer) {
  return polylineCost(r.points, Objective::Energy, stop, scorer);
}

std::optional<geometry::PolygonWithHoles> areaWithZones(const SurveyProblem& pr, std::string* why) {
  geometry::PolygonWithHoles area = pr.area;
  for (const auto& z : pr.no_fly) {
    const bool inside = std::all_of(z.begin(), z.end(), [&](const Point& p) { return geometry::insideRing(pr.area.outer, p); });
    const bool is_hole = std::any_of(pr.area.holes.begin(), pr.area.holes.end(), [&](const Ring& h) {
      return h.size() == z.size() && std::all_of(z.begin(), z.end(), [&](const Point& p) {
               return std::any_of(h.begin(), h.end(), [&](const Point& q) { return (p - q).norm() < 1e-6; });
             });
    });
    if (is_hole) continue;
    if (!inside) {
      *why = "a no-fly zone (grown by the no-fly margin) crosses the area boundary: this search needs the zones "
             "inside the area, as holes, and was not run (the one-angle sweeps go around the zone)";
      return std::nullopt;
    }
    Ring h = z;
    if (geometry::signedArea(h) > 0) std::reverse(h.begin(), h.end());
    area.holes.push_back(h);
  }
  return area;
}

}  // namespace wattswath::planner::detail
