#pragma once
// Internal to planner/src: what every stage of the coverage search shares (the problem's fixed
// context, the objective, the stop-to-stop energy table, an assembled candidate) and the route
// helpers the stages build their candidates with. The stages: angle_search, spiral_plan,
// cell_plan, assemble (order and transits), verification; coverage.cpp runs them.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "wattswath/geometry/polygon.hpp"
#include "wattswath/geometry/sweep_lines.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/speed.hpp"
#include "wattswath/planner/transit.hpp"

namespace wattswath::planner::detail {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDeg = M_PI / 180.0;  // [rad] per degree

/// Everything fixed for one problem: obstacles, router; rotated copies per angle are made on demand.
struct Context {
  const SurveyProblem* problem = nullptr;  ///< the problem, outer boundary counter-clockwise
  std::vector<geometry::Ring> obstacles;   ///< holes + no-fly zones
  const TransitRouter* router = nullptr;   ///< transits around the obstacles
  double clearance = 2.0;                  ///< [m] distance kept from the obstacles
  double run_out = 0.0;                    ///< [m] extension of sweep lines beyond the boundary
  double turn_room = 0.0;                  ///< [m] how far an arc at a line's end may cut back into the line
                                           ///< (and its connector): the turn happens inside the area
  int fewer_lines = 0;                     ///< sweep lines dropped below the full-coverage count (SweepLineSettings)
  geometry::PolygonWithHoles inside;       ///< the outer boundary with the obstacles as holes: where moves stay
  double overlap_margin = 0.0;             ///< [m] (footprint - spacing) / 2
};

/// What a search minimises.
enum class Objective { Energy, Length };

/// Stop-to-stop straight-leg energy as a function of length, tabulated for transit costs.
struct StopTable {
  std::vector<double> len;  ///< [m] leg lengths, increasing (log spaced)
  std::vector<double> e;    ///< [J] energy of a stop-to-stop leg of each length
  /// Energy of a stop-to-stop leg of length `L` [m], interpolated (linear beyond the ends) [J].
  double eval(double L) const {
    if (L <= 0.0) return 0.0;
    if (L <= len.front()) return e.front() * L / len.front();
    if (L >= len.back()) return e.back() + (e.back() - e[e.size() - 2]) / (len.back() - len[len.size() - 2]) * (L - len.back());
    const size_t i = std::upper_bound(len.begin(), len.end(), L) - len.begin();
    const double f = (L - len[i - 1]) / (len[i] - len[i - 1]);
    return e[i - 1] + f * (e[i] - e[i - 1]);
  }
};

/// The table for legs up to `max_len` [m] (at least 10 m) at the scorer's maximum speed.
StopTable makeStopTable(RouteScorer& scorer, double max_len);

/// A fully assembled candidate for one sweep angle.
struct AngleResult {
  double angle = 0.0;       ///< [rad] sweep angle (spirals: the angle that split the area)
  double score = kInf;      ///< [J] or [m]: energy or length, by objective
  Route route;              ///< home to home
  int cells = 0;            ///< cells covered
  std::vector<int> chosen;  ///< candidate chosen per visited cell, in flight order (index into the input candidates)
};

/// Sweep direction in [0, 180) [deg] of `rad` [rad], rounded to 1e-9 deg.
double normDeg(double rad);

/// Runs `work(t)` for t = 0 .. workers - 1 on `workers` threads; rethrows an exception one threw.
void onWorkers(int workers, const std::function<void(int)>& work);

/// Appends a straight move from the route's last point to `to` (role `role`, `tangent_at_to` [m]
/// as in Route::max_tangent), detouring around obstacles.
void moveTo(const Context& ctx, Route& r, const geometry::Point& to, geometry::LegRole role, double tangent_at_to);

/// Appends `next` to `r`, joined by a transit from r's end to next's start (around obstacles).
void appendVia(const Context& ctx, Route& r, const Route& next);

/// Reverse of a route (same energy: the model charges acceleration and braking alike).
Route reversed(const Route& r);

/// The boustrophedon cells of the sweep lines of `ctx` at `angle` [rad]; `first_y` [m] receives
/// the line-frame y of line 0.
std::vector<geometry::SweepLineCell> sweepCells(const Context& ctx, double angle, double* first_y);

/// Route of one cell: start at the first (or last) row, at its left (or right) end; zigzag.
Route cellRoute(const Context& ctx, const geometry::SweepLineCell& cell, double angle, double first_y, bool from_top,
                bool start_right);

/// Cost of the polyline `pts` by `obj`: length [m], or stop-to-stop legs and turns in place [J].
double polylineCost(const std::vector<geometry::Point>& pts, Objective obj, const StopTable& stop,
                    const RouteScorer& scorer);

/// Quick estimate of a route's energy for ranking within a cell: every segment a stop-to-stop leg
/// (tabulated), every corner a stop and a turn in place [J]. An upper bound of the exact energy of
/// the sharp-corner route; the ranking it gives is refined by exact scoring of the few best.
double stopEstimate(const Route& r, const StopTable& stop, const RouteScorer& scorer);

/// The area with every no-fly zone inside it as a hole (zones already holes are skipped); nullopt
/// with `why` set when a zone crosses the boundary (`plan` subtracts such zones from the area first).
std::optional<geometry::PolygonWithHoles> areaWithZones(const SurveyProblem& pr, std::string* why);

}  // namespace wattswath::planner::detail
