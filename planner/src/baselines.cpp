// What the plan is measured against: the shortest path and the ground-station default (scored by
// the same model in the same run), and the physical lower bound.
#include "baselines.hpp"

#include <algorithm>
#include <cmath>

#include "angle_search.hpp"
#include "verification.hpp"
#include "wattswath/energy/marins.hpp"
#include "wattswath/geometry/check.hpp"

namespace wattswath::planner::detail {

using geometry::Point;

PlanCandidate shortestPathBaseline(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                   RouteScorer& scorer, const StopTable& stop, const PlannerSettings& ps,
                                   const std::vector<geometry::PolygonWithHoles>& free, int* count,
                                   const std::vector<const PlanCandidate*>& checked) {
  const AngleResult shortest = searchAngles(ctx, model, ss, stop, Objective::Length, ps, count).front();
  return finish(free, ctx.problem->footprint, scorer, shortest, "boustrophedon", checked);
}

PlanCandidate groundStationBaseline(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                    const StopTable& stop, const PlannerSettings& ps,
                                    const std::vector<geometry::PolygonWithHoles>& free, int* count,
                                    const std::vector<const PlanCandidate*>& checked) {
  const auto& outer = ctx.problem->area.outer;
  size_t longest = 0;
  for (size_t i = 0; i < outer.size(); ++i)
    if ((outer[(i + 1) % outer.size()] - outer[i]).norm() > (outer[(longest + 1) % outer.size()] - outer[longest]).norm())
      longest = i;
  const Point e = outer[(longest + 1) % outer.size()] - outer[longest];
  SpeedSettings gs = ss;
  gs.fixed_speed = std::min(ps.ground_station_speed, ss.max_speed);
  gs.corners = CornerStrategy::Sharp;
  RouteScorer gs_scorer(model, gs);
  const AngleResult gsr = evaluateAngle(ctx, std::atan2(e.y(), e.x()), gs_scorer, stop, Objective::Length, ps.exact_max_cells);
  PlanCandidate c = finish(free, ctx.problem->footprint, gs_scorer, gsr, "boustrophedon", checked);
  ++*count;
  return c;
}

double lowerBound(const SurveyProblem& problem, const energy::EnergyModel& model, const SpeedSettings& ss,
                  RouteScorer& scorer, const PlannerSettings& ps) {
  // The swath length the coverage needs at the best energy per metre, plus the way from home to
  // the area and back; turns counted at zero (an arc can cost as little per metre). A path of
  // length L sweeps its square footprint w over at most L w + w^2 of ground (counted with
  // multiplicity); the requested spacing s asks every point to be seen w / s times (side overlap),
  // so L >= A / s - w (with s = w: A / w - w, the plain coverage bound). Sweeps pay at least the best
  // energy per metre under the camera cap, the way to and from the area at least the best at all.
  const auto& outer = problem.area.outer;
  const double cap = ps.camera_max_speed > 0 ? std::min(ps.camera_max_speed, ss.max_speed) : ss.max_speed;
  double free_area = geometry::area(problem.area);
  for (const auto& z : problem.no_fly) free_area -= std::abs(geometry::signedArea(z));  // may overlap the outside: bound stays a bound
  free_area = std::max(free_area, 0.0);
  double approach = kInf;
  if (geometry::insideRing(outer, problem.home)) approach = 0.0;
  for (size_t i = 0; i < outer.size(); ++i)
    approach = std::min(approach, geometry::distanceToSegment(problem.home, outer[i], outer[(i + 1) % outer.size()]));
  const double swath = std::max(0.0, free_area / problem.spacing - problem.footprint);
  const double sweep_e = model.minEnergyPerMetre(cap);  // [J/m]; a search of its own (about 0.6 ms), done once when no cap
  const double any_e = cap == ss.max_speed ? sweep_e : model.minEnergyPerMetre(ss.max_speed);
  double bound = sweep_e * swath + any_e * 2.0 * approach;
  // Every flight also starts and ends at rest. When power depends on speed alone (Marins' effects:
  // hover, kinetic, drag), a flight of length L from rest to rest costs at least the best single
  // stop-to-stop leg of length L: along the path, speed is at most the accelerate-cruise-brake
  // envelope at the vehicle's limits, energy per metre falls with speed up to the best speed, the
  // kinetic term pays at least the peak speed up and down, and turns and stops only add. That
  // least energy grows with L, so the shortest possible flight bounds every flight.
  if (energy::MarinsClosedForm::forLegsOf(model, ss.limits) && swath + 2.0 * approach > 0.0) {
    bound = std::max(bound, scorer.legEnergy(swath + 2.0 * approach, 0.0, 0.0, ss.max_speed));
  }
  return bound;
}

}  // namespace wattswath::planner::detail
