// The coverage planner's orchestrator: checks the problem, then runs the stages (angle_search,
// cell_plan, spiral_plan, baselines; each candidate assembled by assemble and verified by
// verification) and keeps the least-energy plan that keeps coverage.
#include "wattswath/planner/coverage.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <sstream>
#include <stdexcept>

#include "angle_search.hpp"
#include "baselines.hpp"
#include "cell_plan.hpp"
#include "search_context.hpp"
#include "spiral_plan.hpp"
#include "verification.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/planner/order.hpp"
#include "wattswath/planner/transit.hpp"

namespace wattswath::planner {

using namespace detail;  // the stages

namespace {

// Throws std::invalid_argument when home is inside an obstacle of `router` or a no-fly zone covers
// the whole area (nothing to cover: an error, not an empty plan).
void checkFlyable(const SurveyProblem& problem, const TransitRouter& router) {
  if (router.blocked(problem.home)) throw std::invalid_argument("home is inside a hole or no-fly zone");
  for (size_t i = 0; i < problem.no_fly.size(); ++i) {
    const auto& z = problem.no_fly[i];
    const bool area_inside = std::all_of(problem.area.outer.begin(), problem.area.outer.end(),
                                         [&](const geometry::Point& p) { return geometry::insideRing(z, p); });
    const bool zone_reaches_in = std::any_of(z.begin(), z.end(), [&](const geometry::Point& p) {
      return geometry::insideRing(problem.area.outer, p);
    });
    if (area_inside && !zone_reaches_in) {
      throw std::invalid_argument("SurveyProblem.no_fly[" + std::to_string(i) +
                                  "] covers the whole area; expected a zone leaving part of the area to fly");
    }
  }
}

// The search context of `problem` (outer boundary counter-clockwise); the router is set by the caller.
Context contextOf(const SurveyProblem& problem, const PlannerSettings& ps) {
  Context ctx;
  ctx.problem = &problem;
  ctx.obstacles = problem.area.holes;
  ctx.obstacles.insert(ctx.obstacles.end(), problem.no_fly.begin(), problem.no_fly.end());
  ctx.clearance = ps.clearance;
  ctx.run_out = ps.overshoot;  // 0 by default: the lines end on the boundary (issue 22)
  ctx.turn_room = 0.5 * problem.spacing;
  ctx.inside.outer = problem.area.outer;
  ctx.inside.holes = ctx.obstacles;
  ctx.overlap_margin = 0.5 * (problem.footprint - problem.spacing);
  return ctx;
}

// Speeds and corners of the plan: the vehicle's limits, the camera cap, the altitude, the strategy.
SpeedSettings speedSettingsOf(const energy::Vehicle& vehicle, const SurveyProblem& problem, const PlannerSettings& ps) {
  SpeedSettings ss = SpeedSettings::fromVehicle(vehicle);
  ss.camera_max_speed = ps.camera_max_speed;
  ss.altitude = problem.altitude;
  ss.corners = ps.corners;
  return ss;
}

// The stop-to-stop table for legs up to four times the farthest vertex from home.
StopTable stopTableOf(const SurveyProblem& problem, RouteScorer& scorer) {
  double diag = 0.0;
  for (const auto& p : problem.area.outer) diag = std::max(diag, (p - problem.home).norm());
  return makeStopTable(scorer, 4.0 * diag);
}

// Whether the counter-clockwise `ring` turns left (or goes straight) at every vertex.
bool convex(const geometry::Ring& ring) {
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const geometry::Point u = ring[(i + 1) % n] - ring[i], v = ring[(i + 2) % n] - ring[(i + 1) % n];
    if (u.x() * v.y() - u.y() * v.x() < 0.0) return false;
  }
  return true;
}

std::string deg(double d) {
  std::ostringstream os;
  os << d;
  return os.str();
}

// The plan is the least-energy candidate of all scored, baselines included (so it never costs
// more than one that keeps coverage).
void chooseAmongBaselines(PlanResult& res) {
  for (const PlanCandidate* c : {&res.shortest_path, &res.ground_station_default}) {
    if (better(*c, res.plan)) {
      res.plan = *c;
      res.notes.push_back("a baseline geometry was cheaper than the searched ones and is used as the plan");
    }
  }
  if (res.best_spiral && better(*res.best_spiral, res.plan)) res.plan = *res.best_spiral;
  if (!res.plan.valid) throw std::runtime_error("plan: no coverage path found (area narrower than the clearance?)");
}

}  // namespace

void SurveyProblem::validate() const {
  if (area.outer.size() < 3)
    throw std::invalid_argument("SurveyProblem.area: outer boundary has " + std::to_string(area.outer.size()) +
                                " vertices (at least 3 expected)");
  if (std::abs(geometry::signedArea(area.outer)) <= 0.0)
    throw std::invalid_argument("SurveyProblem.area: outer boundary has zero area");
  for (const auto& p : area.outer)
    if (!p.allFinite()) throw std::invalid_argument("SurveyProblem.area: a vertex is not finite");
  if (!(spacing > 0.0 && spacing <= 1000.0))
    throw std::invalid_argument("SurveyProblem.spacing = " + std::to_string(spacing) + " m is outside (0, 1000]");
  if (!(footprint >= spacing && footprint <= 10000.0))
    throw std::invalid_argument("SurveyProblem.footprint = " + std::to_string(footprint) + " m must be >= spacing (" +
                                std::to_string(spacing) + " m) and <= 10000");
  if (!(altitude > 0.0 && altitude <= 1000.0))
    throw std::invalid_argument("SurveyProblem.altitude = " + std::to_string(altitude) + " m is outside (0, 1000]");
  if (!home.allFinite()) throw std::invalid_argument("SurveyProblem.home is not finite");
  for (size_t i = 0; i < no_fly.size(); ++i)
    if (no_fly[i].size() < 3)
      throw std::invalid_argument("SurveyProblem.no_fly[" + std::to_string(i) + "] has " +
                                  std::to_string(no_fly[i].size()) + " vertices (at least 3 expected)");
}

void PlannerSettings::validate() const {
  auto bad = [](const std::string& f, double v, const std::string& range) {
    throw std::invalid_argument("PlannerSettings." + f + " = " + std::to_string(v) + " is outside " + range);
  };
  if (!(camera_max_speed >= 0.0 && camera_max_speed <= 200.0)) bad("camera_max_speed", camera_max_speed, "[0, 200]");
  if (!(coarse_step_deg > 0.0 && coarse_step_deg <= 90.0)) bad("coarse_step_deg", coarse_step_deg, "(0, 90]");
  if (!(fine_step_deg > 0.0 && fine_step_deg <= coarse_step_deg)) bad("fine_step_deg", fine_step_deg, "(0, coarse_step_deg]");
  if (threads < 1 || threads > 64) bad("threads", threads, "[1, 64]");
  if (!(ground_station_speed > 0.0 && ground_station_speed <= 200.0))
    bad("ground_station_speed", ground_station_speed, "(0, 200]");
  if (!(clearance > 0.0 && clearance <= 100.0)) bad("clearance", clearance, "(0, 100]");
  if (!(overshoot >= 0.0 && overshoot <= 100.0)) bad("overshoot", overshoot, "[0, 100]");
  if (exact_max_cells < 0 || exact_max_cells > kGtspExactMaxClusters) bad("exact_max_cells", exact_max_cells, "[0, 12]");
}

PlanResult planCoverage(const SurveyProblem& pr, const energy::Vehicle& vehicle, const energy::EnergyModel& model,
                        const PlannerSettings& ps, const ProgressFn& progress) {
  pr.validate();
  ps.validate();
  auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };
  SurveyProblem problem = pr;
  if (geometry::signedArea(problem.area.outer) < 0) std::reverse(problem.area.outer.begin(), problem.area.outer.end());
  Context ctx = contextOf(problem, ps);
  TransitRouter router(ctx.obstacles, TransitSettings{ps.clearance});
  checkFlyable(problem, router);
  ctx.router = &router;
  const SpeedSettings ss = speedSettingsOf(vehicle, problem, ps);
  RouteScorer scorer(model, ss);
  const StopTable stop = stopTableOf(problem, scorer);

  PlanResult res;
  const auto free = freeRegions(problem);  // what the coverage checks measure against
  say("plan: searching sweep angles (coarse " + deg(ps.coarse_step_deg) + " deg, fine " + deg(ps.fine_step_deg) +
      " deg) on " + std::to_string(ps.threads) + " threads");
  const auto ranked = searchAngles(ctx, model, ss, stop, Objective::Energy, ps, &res.candidates, &res.sweep_scan);
  const AngleResult& best = ranked.front();
  LineCountNeighbour neighbour;
  res.plan = bestAnglePlan(ctx, ranked, model, ss, scorer, stop, ps, free, &neighbour);
  if (neighbour.lines_delta != 0) res.line_count_neighbour = neighbour;
  const double plan_angle = res.plan.valid ? res.plan.flown.path.sweep_angle : best.angle;  // [rad]
  // (c) The best spiral needs only the plan's angle (to cut an area with holes into pieces): with a
  // second thread it runs beside the per-cell search and the baselines.
  auto spiral_stage = [&]() { return spiralStage(ctx, model, ss, stop, ps, free, plan_angle); };
  std::future<SpiralStage> spiral_job;  // destroyed (joined) before anything the stage refers to
  if (ps.spirals && ps.threads > 1) spiral_job = std::async(std::launch::async, spiral_stage);
  // A convex outline without obstacles is one piece: the per-cell search's choices for it (its own
  // angle, a spiral) are the one-angle search's and the spiral stage's, so it is skipped.
  const bool one_cell = ctx.obstacles.empty() && convex(problem.area.outer);
  if (ps.per_cell && one_cell) res.notes.push_back("per-cell search skipped: a convex area without obstacles is one piece");
  if (ps.per_cell && !one_cell && std::isfinite(best.score)) {
    say("plan: per-cell search (each cell's own sweep angle or spiral)");
    std::string why;
    auto c = perCellCandidate(ctx, model, ss, scorer, stop, ps, free, plan_angle, &res.candidates, &why);
    if (!c) {
      res.notes.push_back("per-cell search skipped: " + why);
    } else {
      res.per_cell = *c;
      if (better(*c, res.plan)) res.plan = std::move(*c);
    }
  }

  say("plan: baselines");
  res.shortest_path = shortestPathBaseline(ctx, model, ss, scorer, stop, ps, free, &res.candidates, {&res.plan});
  res.ground_station_default =
      groundStationBaseline(ctx, model, ss, stop, ps, free, &res.candidates, {&res.plan, &res.shortest_path});
  // (c) best spiral (started above when there is a second thread).
  say("plan: spirals");
  if (!ps.spirals) {
    res.notes.push_back("spirals were not searched (straight parallel lines only)");
  } else {
    SpiralStage spiral = spiral_job.valid() ? spiral_job.get() : spiral_stage();  // get() rethrows what the stage threw
    res.candidates += spiral.count;
    if (spiral.plan) {
      res.best_spiral = std::move(*spiral.plan);
    } else {
      res.notes.push_back(spiral.why);
    }
  }
  chooseAmongBaselines(res);
  res.lower_bound_j = lowerBound(problem, model, ss, scorer, ps);
  if (vehicle.battery) {
    res.battery = predictBatteryUse(res.plan.flown, *vehicle.battery);
    if (!res.battery->fits) res.notes.push_back(res.battery->warning);
  }
  say("plan: done, " + std::to_string(res.candidates) + " candidates scored");
  return res;
}

}  // namespace wattswath::planner
