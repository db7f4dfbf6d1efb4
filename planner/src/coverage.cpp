#include "wattswath/planner/coverage.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "wattswath/energy/marins.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/coverage.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/planner/order.hpp"
#include "wattswath/planner/transit.hpp"

namespace wattswath::planner {
namespace {

using geometry::LegRole;
using geometry::Point;
using geometry::Ring;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDeg = M_PI / 180.0;
constexpr int kStopTableSize = 64;       // samples of the stop-to-stop leg energy table (log spaced)
constexpr int kMaxSpiralStarts = 32;         // start vertices tried per spiral cell (evenly spread)
constexpr size_t kMaxSpiralKeep = 6;
constexpr size_t kFinishBest = 8;            // best-ranked angles flown in full before choosing
constexpr size_t kMaxConvexPieces = 6;       // a cell is cut into convex pieces only when there are at most this many
// [-] of the spacing: how far a spiral's rounded corner may cut inside its vertex beyond the
// footprint overlap (the outer lap's footprint covers most of the sliver; finish() checks coverage
// and takes arcs back where the plan would fall under 99 %).
constexpr double kSpiralCornerCut = 0.1;
constexpr size_t kMaxSpiralOrderCandidates = 8;  // cheapest spiral starts per cell the whole-area spiral orders
constexpr double kKeepWithin = 1.10;         // a cell keeps alternatives costing at most this times its best            // best-ranked angles flown in full before choosing         // cheapest spiral candidates a cell keeps for the order search
constexpr double kMaxRoundedTurn = 3.0;      // [rad] sharper corners (a spiral's out-and-back spikes) are stops
constexpr double kMinCoveragePct = 99.0;     // [%] coverage a plan must keep (issue 5: >= 99 %)

// A free interval of one sweep line, in the rotated frame (x along the line).
struct Interval {
  double x0 = 0.0, x1 = 0.0;      // [m] covered part
  double ext0 = 0.0, ext1 = 0.0;  // [m] run-out beyond each end that an arc may cut into
};

// A boustrophedon cell: intervals on consecutive sweep lines.
struct Cell {
  int first_line = 0;
  std::vector<Interval> rows;
};

// Everything fixed for one problem: obstacles, router, rotated copies per angle are made on demand.
struct Context {
  const SurveyProblem* problem = nullptr;
  std::vector<Ring> obstacles;  // holes + no-fly zones
  const TransitRouter* router = nullptr;
  double clearance = 2.0;
  double run_out = 0.0;  // [m] extension of sweep lines beyond the boundary
  double overlap_margin = 0.0;  // [m] (footprint - spacing) / 2
};

Point rot(const Point& p, double c, double s) { return {c * p.x() + s * p.y(), -s * p.x() + c * p.y()}; }
Point unrot(const Point& p, double c, double s) { return {c * p.x() - s * p.y(), s * p.x() + c * p.y()}; }

// Sweep direction in [0, 180) [deg], rounded to 1e-9 deg: the search steps whole and tenth degrees
// in radians, and 66 deg should read 66, not 65.99999999999999.
double normDeg(double rad) {
  double d = std::fmod(rad / kDeg, 180.0);
  if (d < 0) d += 180.0;
  d = std::round(d * 1e9) / 1e9;
  return d >= 180.0 ? 0.0 : d;
}

// Largest tangent of an arc at a corner of deflection `theta` that stays within `margin` of the vertex.
double tangentWithin(double theta, double margin) {
  const double h = 0.5 * std::abs(theta);
  if (h < 1e-9 || margin <= 0.0) return 0.0;
  return margin * std::tan(h) / (1.0 / std::cos(h) - 1.0);
}

// x of the crossings of horizontal line y with `ring` (half-open rule).
void crossings(const Ring& ring, double y, std::vector<double>& xs) {
  const size_t n = ring.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if ((a.y() > y) != (b.y() > y)) xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
  }
}

std::vector<std::pair<double, double>> pairsOf(std::vector<double> xs) {
  std::sort(xs.begin(), xs.end());
  std::vector<std::pair<double, double>> out;
  for (size_t i = 0; i + 1 < xs.size(); i += 2) out.emplace_back(xs[i], xs[i + 1]);
  return out;
}

// Sweep lines at `angle`: free intervals per line (area minus obstacles), ends marked.
std::vector<std::vector<Interval>> sweepLines(const Context& ctx, double angle, double* first_y) {
  const double c = std::cos(angle), s = std::sin(angle);
  const auto& pr = *ctx.problem;
  Ring outer;
  for (const auto& p : pr.area.outer) outer.push_back(rot(p, c, s));
  std::vector<Ring> obst;
  for (const auto& r : ctx.obstacles) {
    Ring q;
    for (const auto& p : r) q.push_back(rot(p, c, s));
    obst.push_back(q);
  }
  double ymin = kInf, ymax = -kInf;
  for (const auto& p : outer) {
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
  }
  const double d = pr.spacing;
  const double half_band = 0.5 * pr.footprint * (1.0 - 1e-9);  // [m] half width of a line's footprint
  const int nlines = std::max(1, static_cast<int>(std::ceil((ymax - ymin) / d - 1e-9)));
  const double y0 = ymin + 0.5 * ((ymax - ymin) - (nlines - 1) * d);
  *first_y = y0;
  std::vector<std::vector<Interval>> lines(nlines);
  for (int k = 0; k < nlines; ++k) {
    const double y = y0 + k * d;
    std::vector<double> xs;
    crossings(outer, y, xs);
    auto area = pairsOf(xs);
    // Stretch each interval to the extent of the area inside the line's footprint band: an edge
    // nearly parallel to the line leaves a long thin wedge the centre line alone would miss. The
    // extent is reached at the band's edges or at a vertex inside the band.
    std::vector<double> probes{y - half_band, y + half_band};
    for (const auto& p : outer)
      if (std::abs(p.y() - y) < half_band) probes.push_back(p.y());
    for (double yp : probes) {
      std::vector<double> px;
      crossings(outer, yp, px);
      for (const auto& b : pairsOf(px))
        for (auto& a : area)
          if (b.first < a.second && b.second > a.first) {
            a.first = std::min(a.first, b.first);
            a.second = std::max(a.second, b.second);
          }
    }
    std::vector<std::pair<double, double>> blocked;
    for (const auto& r : obst) {
      std::vector<double> bx;
      crossings(r, y, bx);
      for (auto& b : pairsOf(bx)) blocked.emplace_back(b.first - ctx.clearance, b.second + ctx.clearance);
    }
    std::sort(blocked.begin(), blocked.end());
    for (const auto& a : area) {
      // Subtract the blocked intervals; ends at the outer boundary get the run-out, clipped by blocks.
      double x = a.first;
      bool at_boundary = true;
      auto emit = [&](double x_end, bool end_boundary) {
        if (x_end - x <= 1e-6) return;
        Interval iv;
        iv.x0 = x;
        iv.x1 = x_end;
        if (at_boundary) {
          double lim = x - ctx.run_out;
          for (const auto& b : blocked)
            if (b.second <= x + 1e-9 && b.second > lim) lim = b.second;
          iv.ext0 = x - lim;
          iv.x0 = x;
        }
        if (end_boundary) {
          double lim = x_end + ctx.run_out;
          for (const auto& b : blocked)
            if (b.first >= x_end - 1e-9 && b.first < lim) lim = b.first;
          iv.ext1 = lim - x_end;
        }
        lines[k].push_back(iv);
      };
      for (const auto& b : blocked) {
        if (b.second <= x || b.first >= a.second) continue;
        if (b.first > x) emit(b.first, false);
        x = std::max(x, b.second);
        at_boundary = false;
      }
      emit(a.second, true);
    }
  }
  return lines;
}

// Groups the intervals of consecutive lines into cells (one-to-one overlaps stay in one cell).
std::vector<Cell> cellsOf(const std::vector<std::vector<Interval>>& lines) {
  std::vector<Cell> cells;
  std::vector<int> prev_cell;  // cell of each interval on the previous line
  for (size_t k = 0; k < lines.size(); ++k) {
    std::vector<int> cur(lines[k].size(), -1);
    for (size_t j = 0; j < lines[k].size(); ++j) {
      const auto& iv = lines[k][j];
      int match = -1, count = 0;
      if (k > 0) {
        for (size_t i = 0; i < lines[k - 1].size(); ++i) {
          const auto& p = lines[k - 1][i];
          if (std::min(p.x1, iv.x1) - std::max(p.x0, iv.x0) > 0.0) {
            match = static_cast<int>(i);
            ++count;
          }
        }
      }
      bool joined = false;
      if (count == 1) {
        int back = 0;  // how many intervals of this line overlap the matched one
        const auto& p = lines[k - 1][match];
        for (const auto& o : lines[k])
          if (std::min(p.x1, o.x1) - std::max(p.x0, o.x0) > 0.0) ++back;
        const int c = prev_cell[match];
        if (back == 1 && c >= 0 && cells[c].first_line + static_cast<int>(cells[c].rows.size()) == static_cast<int>(k)) {
          cells[c].rows.push_back(iv);
          cur[j] = c;
          joined = true;
        }
      }
      if (!joined) {
        cells.push_back({static_cast<int>(k), {iv}});
        cur[j] = static_cast<int>(cells.size()) - 1;
      }
    }
    prev_cell = cur;
  }
  return cells;
}

// Appends a straight move from the route's last point to `to`, detouring around obstacles.
void moveTo(const Context& ctx, Route& r, const Point& to, LegRole role, double tangent_at_to) {
  const Point from = r.points.back();
  if (ctx.router->clear(from, to)) {
    r.add(to, role, tangent_at_to);
    return;
  }
  const auto path = ctx.router->route(from, to);
  for (size_t i = 1; i + 1 < path.size(); ++i) r.add(path[i], LegRole::Transit, 0.5 * ctx.clearance);
  r.add(to, role, tangent_at_to);
}

// Route of one cell: start at the first (or last) row, at its left (or right) end; zigzag.
Route cellRoute(const Context& ctx, const Cell& cell, double angle, double first_y, bool from_top, bool start_right) {
  const double c = std::cos(angle), s = std::sin(angle);
  const int n = static_cast<int>(cell.rows.size());
  Route r;
  bool right = start_right;
  for (int i = 0; i < n; ++i) {
    const int row = from_top ? n - 1 - i : i;
    const auto& iv = cell.rows[row];
    const double y = first_y + (cell.first_line + row) * ctx.problem->spacing;
    const double xa = right ? iv.x1 + iv.ext1 : iv.x0 - iv.ext0;
    const double xb = right ? iv.x0 - iv.ext0 : iv.x1 + iv.ext1;
    const double ta = right ? iv.ext1 : iv.ext0, tb = right ? iv.ext0 : iv.ext1;
    const Point a = unrot(Point(xa, y), c, s), b = unrot(Point(xb, y), c, s);
    if (r.points.empty()) {
      r.points.push_back(a);
      r.max_tangent.push_back(0.0);
    } else {
      moveTo(ctx, r, a, LegRole::Transit, ta);
    }
    r.add(b, LegRole::Sweep, tb);
    right = !right;
  }
  return r;
}

// Reverse of a route (same energy: the model charges acceleration and braking alike).
Route reversed(const Route& r) {
  Route o;
  o.points.assign(r.points.rbegin(), r.points.rend());
  o.roles.assign(r.roles.rbegin(), r.roles.rend());
  o.max_tangent.assign(r.max_tangent.rbegin(), r.max_tangent.rend());
  return o;
}

// Stop-to-stop straight-leg energy as a function of length, tabulated for transit costs.
struct StopTable {
  std::vector<double> len, e;
  double eval(double L) const {
    if (L <= 0.0) return 0.0;
    if (L <= len.front()) return e.front() * L / len.front();
    if (L >= len.back()) return e.back() + (e.back() - e[e.size() - 2]) / (len.back() - len[len.size() - 2]) * (L - len.back());
    const size_t i = std::upper_bound(len.begin(), len.end(), L) - len.begin();
    const double f = (L - len[i - 1]) / (len[i] - len[i - 1]);
    return e[i - 1] + f * (e[i] - e[i - 1]);
  }
};

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

enum class Objective { Energy, Length };

// A fully assembled candidate for one sweep angle.
struct AngleResult {
  double angle = 0.0;
  double score = kInf;  // energy or length, by objective
  Route route;
  int cells = 0;
  std::vector<int> chosen;  // candidate chosen per visited cell, in flight order (index into the input candidates)
};

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

AngleResult assemble(const Context& ctx, std::vector<Route> cand, GtspInstance g, AngleResult res, RouteScorer& scorer,
                     const StopTable& stop, Objective obj, int exact_max_cells, bool also_length_order = true);

// Boustrophedon at one angle: cells, 4 candidates each, ordered by GTSP, assembled home to home.
AngleResult evaluateAngle(const Context& ctx, double angle, RouteScorer& scorer, const StopTable& stop, Objective obj,
                          int exact_max_cells, bool also_length_order = false) {
  AngleResult res;
  res.angle = angle;
  double first_y = 0.0;
  const auto cells = cellsOf(sweepLines(ctx, angle, &first_y));
  if (cells.empty()) return res;
  std::vector<Route> cand;
  GtspInstance g;
  int cluster = 0;
  for (size_t ci = 0; ci < cells.size(); ++ci) {
    bool any = false;
    for (int top = 0; top < 2; ++top) {
      for (bool right : {false, true}) {
        const Route r = cellRoute(ctx, cells[ci], angle, first_y, top == 1, right);
        if (r.points.size() < 2) continue;  // a sliver without length
        const double cost = obj == Objective::Length ? r.length() : scorer.energy(r);
        if (!std::isfinite(cost)) continue;
        cand.push_back(r);
        g.cluster.push_back(cluster);
        g.cost.push_back(cost);
        any = true;
      }
    }
    cluster += any;
  }
  if (cand.empty()) return res;
  res.cells = cluster;
  return assemble(ctx, std::move(cand), std::move(g), res, scorer, stop, obj, exact_max_cells, also_length_order);
}

// Orders per-cell candidates (`g.cluster` / `g.cost` filled, one route each in `cand`) by GTSP
// and joins them from home back to home with transits; fills res.route and res.score.
AngleResult assemble(const Context& ctx, std::vector<Route> cand, GtspInstance g, AngleResult res, RouteScorer& scorer,
                     const StopTable& stop, Objective obj, int exact_max_cells, bool also_length_order) {
  // Each candidate reversed is also a candidate (same internal cost, swapped ends), unless a
  // candidate of the cell already runs between the same two ends (the reverse of a zigzag from one
  // corner is usually the zigzag from its end corner): the order search then has half the nodes.
  const size_t base = cand.size();
  std::vector<int> origin(base);
  for (size_t i = 0; i < base; ++i) origin[i] = static_cast<int>(i);
  for (size_t i = 0; i < base; ++i) {
    const Point& from = cand[i].points.back();
    const Point& to = cand[i].points.front();
    bool same_ends = false;
    for (size_t k = 0; k < base && !same_ends; ++k)
      same_ends = g.cluster[k] == g.cluster[i] && cand[k].points.front() == from && cand[k].points.back() == to &&
                  g.cost[k] <= g.cost[i];
    if (same_ends) continue;
    cand.push_back(reversed(cand[i]));
    origin.push_back(static_cast<int>(i));
    g.cluster.push_back(g.cluster[i]);
    g.cost.push_back(g.cost[i]);
  }
  const int n = static_cast<int>(cand.size());
  // Transit costs between the distinct end points only (a candidate and its reverse share both
  // ends, and the start corners of a cell share theirs): symmetric, computed once per pair.
  std::vector<Point> ends{ctx.problem->home};
  auto indexOf = [&ends](const Point& p) {
    for (size_t k = 0; k < ends.size(); ++k)
      if (ends[k] == p) return static_cast<int>(k);
    ends.push_back(p);
    return static_cast<int>(ends.size()) - 1;
  };
  std::vector<int> entry(n + 1, 0), exit(n + 1, 0);  // index n (depot) is home, end 0
  for (int i = 0; i < n; ++i) {
    entry[i] = indexOf(cand[i].points.front());
    exit[i] = indexOf(cand[i].points.back());
  }
  const int m = static_cast<int>(ends.size());
  const auto routes = ctx.router->routeAll(ends);
  // The order search works on estimates (candidates flown alone from rest to rest, transits
  // stop to stop), so for the energy objective the order that is shortest is also built and the
  // one whose joined route really costs less energy is kept.
  std::vector<Objective> orders{obj};
  if (obj == Objective::Energy && also_length_order) orders.push_back(Objective::Length);
  for (Objective order : orders) {
    Eigen::MatrixXd between = Eigen::MatrixXd::Zero(m, m);
    for (int p = 0; p < m; ++p)
      for (int q = p + 1; q < m; ++q)
        between(p, q) = between(q, p) = polylineCost(routes[static_cast<size_t>(p) * m + q], order, stop, scorer);
    GtspInstance go = g;
    if (order != obj)
      for (int i = 0; i < n; ++i) go.cost[static_cast<size_t>(i)] = cand[static_cast<size_t>(i)].length();
    go.transit = Eigen::MatrixXd::Zero(n + 1, n + 1);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        if (i != j || i == n) go.transit(i, j) = between(exit[i], entry[j]);
    const GtspTour tour = solveGtsp(go, exact_max_cells);
    Route full;
    std::vector<int> chosen;
    full.points.push_back(ctx.problem->home);
    full.max_tangent.push_back(0.0);
    for (int node : tour.nodes) {
      chosen.push_back(origin[static_cast<size_t>(node)]);
      const Route& r = cand[node];
      moveTo(ctx, full, r.points.front(), LegRole::Transit, r.max_tangent.front());
      for (size_t i = 1; i < r.points.size(); ++i) full.add(r.points[i], r.roles[i - 1], r.max_tangent[i]);
    }
    moveTo(ctx, full, ctx.problem->home, LegRole::Transit, 0.0);
    const double score = obj == Objective::Length ? full.length() : scorer.energy(full);
    if (score < res.score) {
      res.score = score;
      res.route = std::move(full);
      res.chosen = std::move(chosen);
    }
  }
  return res;
}

// Evaluates `angles` on `threads` workers, each with its own scorer.
std::vector<AngleResult> evaluateAngles(const Context& ctx, const std::vector<double>& angles,
                                        const energy::EnergyModel& model, const SpeedSettings& ss,
                                        const StopTable& stop, Objective obj, int threads, int exact_max_cells) {
  std::vector<AngleResult> out(angles.size());
  std::vector<std::thread> pool;
  std::exception_ptr error;
  std::mutex m;
  const int nt = std::max(1, std::min<int>(threads, static_cast<int>(angles.size())));
  for (int t = 0; t < nt; ++t) {
    pool.emplace_back([&, t]() {
      try {
        // The scan ranks angles of boustrophedon routes, whose corners are far apart: arcs at chain
        // speeds change little there, and scoring without them is several times faster.
        SpeedSettings scan = ss;
        scan.arc_chains = false;
        RouteScorer scorer(model, scan);
        for (size_t i = t; i < angles.size(); i += nt)
          out[i] = evaluateAngle(ctx, angles[i], scorer, stop, obj, exact_max_cells);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        error = std::current_exception();
      }
    });
  }
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
  return out;
}

// Coarse grid over [0, 180) then a fine grid around the best coarse angles.
// Every evaluated angle (coarse and refined), best score first.
std::vector<AngleResult> searchAngles(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                      const StopTable& stop, Objective obj, const PlannerSettings& ps, int* count,
                                      std::vector<AngleScore>* scan = nullptr) {
  std::vector<double> coarse;
  for (double a = 0.0; a < 180.0 - 1e-9; a += ps.coarse_step_deg) coarse.push_back(a * kDeg);
  auto res = evaluateAngles(ctx, coarse, model, ss, stop, obj, ps.threads, ps.exact_max_cells);
  *count += static_cast<int>(res.size());
  std::sort(res.begin(), res.end(), [](const auto& a, const auto& b) { return a.score < b.score; });
  std::vector<double> fine;
  for (size_t k = 0; k < std::min<size_t>(2, res.size()); ++k) {
    if (!std::isfinite(res[k].score)) continue;
    for (double da = -ps.coarse_step_deg + ps.fine_step_deg; da < ps.coarse_step_deg - 1e-9; da += ps.fine_step_deg)
      if (std::abs(da) > 1e-9) fine.push_back(res[k].angle + da * kDeg);
  }
  auto more = evaluateAngles(ctx, fine, model, ss, stop, obj, ps.threads, ps.exact_max_cells);
  *count += static_cast<int>(more.size());
  if (scan) {
    for (const auto* list : {&res, &more})
      for (const auto& r : *list) scan->push_back({normDeg(r.angle), r.score});
    std::sort(scan->begin(), scan->end(), [](const auto& a, const auto& b) { return a.sweep_angle_deg < b.sweep_angle_deg; });
  }
  for (auto& r : more) res.push_back(std::move(r));
  std::stable_sort(res.begin(), res.end(), [](const auto& a, const auto& b) { return a.score < b.score; });
  return res;
}

// Quick estimate of a route's energy for ranking within a cell: every segment a stop-to-stop leg
// (tabulated), every corner a stop and a turn in place [J]. An upper bound of the exact energy of
// the sharp-corner route; the ranking it gives is refined by exact scoring of the few best.
double stopEstimate(const Route& r, const StopTable& stop, const RouteScorer& scorer) {
  return polylineCost(r.points, Objective::Energy, stop, scorer);
}

// The area with every no-fly zone inside it as a hole (zones already holes are skipped); nullopt
// with `why` set when a zone crosses the boundary (`plan` subtracts such zones from the area first).
std::optional<geometry::PolygonWithHoles> areaWithZones(const SurveyProblem& pr, std::string* why) {
  geometry::PolygonWithHoles area = pr.area;
  for (const auto& z : pr.no_fly) {
    const bool inside = std::all_of(z.begin(), z.end(), [&](const Point& p) { return insideRing(p, pr.area.outer); });
    const bool is_hole = std::any_of(pr.area.holes.begin(), pr.area.holes.end(), [&](const Ring& h) {
      return h.size() == z.size() && std::all_of(z.begin(), z.end(), [&](const Point& p) {
               return std::any_of(h.begin(), h.end(), [&](const Point& q) { return (p - q).norm() < 1e-6; });
             });
    });
    if (is_hole) continue;
    if (!inside) {
      *why = "a no-fly zone crosses the area boundary (subtract it from the area first, as `plan` does)";
      return std::nullopt;
    }
    Ring h = z;
    if (geometry::signedArea(h) > 0) std::reverse(h.begin(), h.end());
    area.holes.push_back(h);
  }
  return area;
}

// One spiral cell flown from `start` (a vertex of its first lap) in direction `cw`, as a planner
// route: all segments Sweep, arcs allowed at corners within the footprint overlap, none at the
// out-and-back spikes.
Route spiralCellRoute(const Context& ctx, const geometry::SpiralCell& cell, int start, bool cw, double split_angle) {
  geometry::SpiralSettings st;
  st.spacing = ctx.problem->spacing;
  st.start_vertex = start;
  st.clockwise = cw;
  st.split_angle = split_angle;
  const auto gr = geometry::spiralRoute(cell, st);
  Route r;
  for (size_t k = 0; k < gr.points.size(); ++k) {
    if (!r.points.empty() && (gr.points[k] - r.points.back()).norm() < 1e-9) continue;
    if (r.points.empty()) {
      r.points.push_back(gr.points[k]);
      r.max_tangent.push_back(0.0);
      continue;
    }
    r.add(gr.points[k], LegRole::Sweep, 0.0);
  }
  for (size_t k = 1; k + 1 < r.points.size(); ++k) {
    const Point u = r.points[k] - r.points[k - 1], v = r.points[k + 1] - r.points[k];
    const double th = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
    r.max_tangent[k] = std::abs(th) < kMaxRoundedTurn
                           ? tangentWithin(th, ctx.overlap_margin + kSpiralCornerCut * ctx.problem->spacing)
                           : 0.0;
  }
  return r;
}

// Start vertices tried on a spiral cell: every vertex of its first lap, at most kMaxSpiralStarts
// evenly spread.
std::vector<int> spiralStarts(const geometry::SpiralCell& cell) {
  std::vector<int> out;
  if (cell.laps.empty() || cell.laps.front().empty()) return out;
  const int m = static_cast<int>(cell.laps.front().size());
  const int step = std::max(1, m / kMaxSpiralStarts);
  for (int start = 0; start < m; start += step) out.push_back(start);
  return out;
}

// Spiral plan: geometry's straight-skeleton spirals (an area with holes is first cut into hole-free
// boustrophedon pieces at `split_angle`; narrow necks split laps into further cells). Candidates of
// each spiral cell: every start vertex of its first lap (at most kMaxSpiralStarts, evenly spread),
// both directions; then GTSP order and transits as for boustrophedon.
std::optional<AngleResult> spiralPlan(const Context& ctx, RouteScorer& scorer, const StopTable& stop, Objective obj,
                                      int exact_max_cells, double split_angle, int* count, std::string* why) {
  const auto& pr = *ctx.problem;
  const auto area = areaWithZones(pr, why);
  if (!area) {
    *why = "no spiral: " + *why;
    return std::nullopt;
  }
  std::vector<geometry::SpiralCell> cells;
  try {
    cells = geometry::decomposeSpiral(*area, pr.spacing, split_angle);
  } catch (const std::exception& e) {
    *why = std::string("no spiral: ") + e.what();
    return std::nullopt;
  }
  std::vector<Route> cand;
  GtspInstance g;
  int cluster = 0;
  for (const auto& cell : cells) {
    // Every start vertex and direction ranked by the quick estimate (or length); the best few are
    // scored exactly and go to the order search (each candidate kept multiplies its work).
    std::vector<std::pair<double, Route>> ranked;
    for (int start : spiralStarts(cell))
      for (bool cw : {false, true}) {
        Route r = spiralCellRoute(ctx, cell, start, cw, split_angle);
        if (r.points.size() < 2) continue;
        ++*count;
        const double estimate = obj == Objective::Length ? r.length() : stopEstimate(r, stop, scorer);
        if (std::isfinite(estimate)) ranked.emplace_back(estimate, std::move(r));
      }
    std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    if (ranked.size() > kMaxSpiralOrderCandidates) ranked.resize(kMaxSpiralOrderCandidates);
    bool any = false;
    for (auto& [estimate, r] : ranked) {
      const double cost = obj == Objective::Length ? estimate : scorer.energy(r);
      if (!std::isfinite(cost)) continue;
      cand.push_back(std::move(r));
      g.cluster.push_back(cluster);
      g.cost.push_back(cost);
      any = true;
    }
    cluster += any;
  }
  if (cand.empty()) {
    *why = "no spiral: the area is narrower than one swath";
    return std::nullopt;
  }
  AngleResult res;
  res.angle = split_angle;
  res.cells = cluster;
  return assemble(ctx, std::move(cand), std::move(g), res, scorer, stop, obj, exact_max_cells);
}

// A per-cell candidate of the mixed search.
struct CellCandidate {
  Route route;
  double cost = kInf;  // [J] energy of the route alone
  bool spiral = false;
  double angle = 0.0;  // [rad] sweep angle (boustrophedon)
};

// Boustrophedon route over the single cell of `cctx` at `angle`, first row at the top or bottom,
// first pass starting at the right or left. Where the cell is not monotone at this angle its sweep
// intervals form several sub-cells: they are flown in line order (from the top when `top`), each
// from the corner nearest the previous one's exit.
Route sweepCellRoute(const Context& cctx, double angle, bool top, bool right) {
  double first_y = 0.0;
  auto sub = cellsOf(sweepLines(cctx, angle, &first_y));
  if (sub.empty()) return {};
  std::stable_sort(sub.begin(), sub.end(), [top](const Cell& a, const Cell& b) {
    return top ? a.first_line > b.first_line : a.first_line < b.first_line;
  });
  Route r = cellRoute(cctx, sub.front(), angle, first_y, top, right);
  for (size_t k = 1; k < sub.size(); ++k) {
    Route best;
    double best_d = kInf;
    for (int t = 0; t < 2; ++t)
      for (bool rt : {false, true}) {
        Route c = cellRoute(cctx, sub[k], angle, first_y, t == 1, rt);
        if (c.points.empty()) continue;
        const double d = (c.points.front() - r.points.back()).norm();
        if (d < best_d) {
          best_d = d;
          best = std::move(c);
        }
      }
    if (best.points.empty()) continue;
    if (r.points.empty()) {
      r = std::move(best);
      continue;
    }
    moveTo(cctx, r, best.points.front(), LegRole::Transit, best.max_tangent.front());
    for (size_t i = 1; i < best.points.size(); ++i) r.add(best.points[i], best.roles[i - 1], best.max_tangent[i]);
  }
  return r;
}


// Candidates of one boustrophedon cell (ring `boundary`, no holes inside): boustrophedon at every
// coarse angle, refined around the cell's best (ranked by stopEstimate), then scored exactly with
// each start corner at the best angle and at the decomposition's angle; and the straight-skeleton
// spiral from every start vertex both ways (ranked by stopEstimate, the kMaxSpiralKeep best scored
// exactly). `count` counts the routes scored.
std::vector<CellCandidate> cellCandidates(const Context& ctx, const Ring& boundary, double decomposition_angle,
                                          const PlannerSettings& ps, RouteScorer& scorer, const StopTable& stop,
                                          int* count) {
  SurveyProblem cell_problem = *ctx.problem;
  cell_problem.area = geometry::PolygonWithHoles{boundary, {}};
  Context cctx = ctx;
  cctx.problem = &cell_problem;
  std::vector<CellCandidate> out;
  auto corners = [&](double angle) {
    for (int top = 0; top < 2; ++top)
      for (bool right : {false, true}) {
        CellCandidate c;
        c.route = sweepCellRoute(cctx, angle, top == 1, right);
        c.angle = angle;
        if (c.route.points.size() < 2) continue;
        c.cost = scorer.energy(c.route);
        ++*count;
        if (std::isfinite(c.cost)) out.push_back(std::move(c));
      }
  };
  // Boustrophedon: the angle ranked by the estimate (one start corner), coarse then refined.
  double best_angle = decomposition_angle, best_estimate = kInf;
  auto consider = [&](double a) {
    const Route r = sweepCellRoute(cctx, a, false, false);
    ++*count;
    if (r.points.size() < 2) return;
    const double e = stopEstimate(r, stop, scorer);
    if (e < best_estimate) {
      best_estimate = e;
      best_angle = a;
    }
  };
  for (double a = 0.0; a < 180.0 - 1e-9; a += ps.coarse_step_deg) consider(a * kDeg);
  const double coarse_best = best_angle;
  for (double da = -ps.coarse_step_deg + ps.fine_step_deg; da < ps.coarse_step_deg - 1e-9; da += ps.fine_step_deg)
    if (std::abs(da) > 1e-9) consider(coarse_best + da * kDeg);
  corners(best_angle);
  if (std::abs(normDeg(best_angle) - normDeg(decomposition_angle)) > 1e-6) {
    // The decomposition's angle too (its corners line up with the neighbouring cells'), unless
    // clearly dearer: every candidate kept multiplies the order search's work.
    double best_cost = kInf;
    for (const auto& c : out) best_cost = std::min(best_cost, c.cost);
    const size_t before = out.size();
    corners(decomposition_angle);
    double alt = kInf;
    for (size_t i = before; i < out.size(); ++i) alt = std::min(alt, out[i].cost);
    if (alt > kKeepWithin * best_cost) out.resize(before);
  }
  if (!ps.spirals) return out;
  // Spirals of the cell (necks split it into several spiral cells: flown one after the other, each
  // from its first-lap vertex nearest the previous exit).
  std::vector<geometry::SpiralCell> spirals;
  try {
    spirals = geometry::decomposeSpiral(cell_problem.area, cell_problem.spacing, decomposition_angle);
  } catch (const std::exception&) {
    spirals.clear();  // no spiral for this cell; its boustrophedon candidates remain
  }
  spirals.erase(std::remove_if(spirals.begin(), spirals.end(),
                               [](const geometry::SpiralCell& c) { return c.laps.empty() || c.laps.front().empty(); }),
                spirals.end());
  if (spirals.empty()) return out;
  std::vector<std::pair<double, CellCandidate>> ranked;
  for (int start : spiralStarts(spirals.front()))
    for (bool cw : {false, true}) {
      CellCandidate c;
      c.spiral = true;
      c.route = spiralCellRoute(cctx, spirals.front(), start, cw, decomposition_angle);
      for (size_t k = 1; k < spirals.size() && c.route.points.size() >= 2; ++k) {
        const Ring& lap = spirals[k].laps.front();
        int nearest = 0;
        for (size_t v = 1; v < lap.size(); ++v)
          if ((lap[v] - c.route.points.back()).norm() < (lap[nearest] - c.route.points.back()).norm())
            nearest = static_cast<int>(v);
        const Route next = spiralCellRoute(cctx, spirals[k], nearest, cw, decomposition_angle);
        if (next.points.size() < 2) continue;
        moveTo(cctx, c.route, next.points.front(), LegRole::Transit, 0.0);
        for (size_t i = 1; i < next.points.size(); ++i) c.route.add(next.points[i], next.roles[i - 1], next.max_tangent[i]);
      }
      ++*count;
      if (c.route.points.size() < 2) continue;
      const double e = stopEstimate(c.route, stop, scorer);
      ranked.emplace_back(e, std::move(c));
    }
  std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (ranked.size() > kMaxSpiralKeep) ranked.resize(kMaxSpiralKeep);
  double best_cost = kInf;
  for (const auto& c : out) best_cost = std::min(best_cost, c.cost);
  for (auto& [e, c] : ranked) {
    c.cost = scorer.energy(c.route);
    ++*count;
    if (std::isfinite(c.cost) && c.cost <= kKeepWithin * best_cost) out.push_back(std::move(c));
  }
  return out;
}

// Per-cell search on two partitions of the area: (a) geometry's boustrophedon cells at `angle`
// (holes and inner no-fly zones cut them), (b) those cells cut further into convex pieces
// (geometry::convexPartition), so that e.g. the two arms of an L can take different sweep angles.
// Candidates of every distinct piece come from cellCandidates() (pieces spread over `ps.threads`
// workers); per partition one GTSP picks a candidate per piece and the order; the cheaper partition
// is returned. `info` receives, per visited piece in flight order, what was chosen.
std::optional<AngleResult> perCellPlan(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                       RouteScorer& scorer, const StopTable& stop, const PlannerSettings& ps,
                                       double angle, int* count, std::vector<CellPlan>* info, std::string* why) {
  const auto& pr = *ctx.problem;
  const auto area = areaWithZones(pr, why);
  if (!area) return std::nullopt;
  geometry::BoustrophedonDecomposition dec;
  try {
    dec = geometry::decomposeBoustrophedon(*area, angle);
  } catch (const std::exception& e) {
    *why = e.what();
    return std::nullopt;
  }
  if (dec.cells.empty()) {
    *why = "the decomposition has no cells";
    return std::nullopt;
  }
  std::vector<Ring> pieces;                      // distinct pieces of both partitions
  std::vector<std::vector<int>> partitions(2);   // piece indices of (a) and (b)
  for (const auto& cell : dec.cells) {
    const int id = static_cast<int>(pieces.size());
    pieces.push_back(cell.boundary);
    partitions[0].push_back(id);
    std::vector<Ring> parts;
    try {
      parts = geometry::convexPartition(cell.boundary);
    } catch (const std::exception&) {
      parts.clear();  // not partitioned: the cell stays whole in (b)
    }
    if (parts.size() <= 1 || parts.size() > kMaxConvexPieces) {
      // Convex already, or an outline of many small bends (a wavy field edge): pieces that small
      // only add transits and turns, so the cell stays whole.
      partitions[1].push_back(id);
      continue;
    }
    for (auto& part : parts) {
      partitions[1].push_back(static_cast<int>(pieces.size()));
      pieces.push_back(std::move(part));
    }
  }
  const size_t n = pieces.size();
  std::vector<std::vector<CellCandidate>> per(n);
  std::vector<int> counts(n, 0);
  std::exception_ptr error;
  std::mutex m;
  std::vector<std::thread> pool;
  const int nt = std::max(1, std::min<int>(ps.threads, static_cast<int>(n)));
  for (int t = 0; t < nt; ++t)
    pool.emplace_back([&, t]() {
      try {
        RouteScorer local(model, ss);
        for (size_t i = t; i < n; i += nt) per[i] = cellCandidates(ctx, pieces[i], angle, ps, local, stop, &counts[i]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        error = std::current_exception();
      }
    });
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
  for (int c : counts) *count += c;

  std::optional<AngleResult> best;
  for (size_t v = 0; v < partitions.size(); ++v) {
    if (v == 1 && partitions[1] == partitions[0]) break;  // every cell already convex
    std::vector<Route> cand;
    std::vector<const CellCandidate*> meta;
    std::vector<int> piece_of;
    GtspInstance g;
    int cluster = 0;
    for (int id : partitions[v]) {
      if (per[static_cast<size_t>(id)].empty()) continue;  // a sliver with no sweep line
      for (const auto& c : per[static_cast<size_t>(id)]) {
        cand.push_back(c.route);
        meta.push_back(&c);
        piece_of.push_back(id);
        g.cluster.push_back(cluster);
        g.cost.push_back(c.cost);
      }
      ++cluster;
    }
    if (cand.empty()) continue;
    AngleResult res;
    res.angle = angle;
    res.cells = cluster;
    res = assemble(ctx, std::move(cand), std::move(g), res, scorer, stop, Objective::Energy, ps.exact_max_cells,
                   cluster <= ps.exact_max_cells);
    if (best && best->score <= res.score) continue;
    info->clear();
    for (int k : res.chosen) {
      const CellCandidate& c = *meta[static_cast<size_t>(k)];
      const Ring& piece = pieces[static_cast<size_t>(piece_of[static_cast<size_t>(k)])];
      info->push_back({c.spiral ? "spiral" : "boustrophedon", c.spiral ? 0.0 : normDeg(c.angle), c.cost,
                       std::abs(geometry::signedArea(piece))});
    }
    best = std::move(res);
  }
  if (!best) *why = "no cell has a candidate route";
  return best;
}

// A ring without consecutive repeated vertices: CGAL's Boolean operations need simple polygons,
// and the planner itself tolerates repeats (PlannerDegenerate.DuplicateAndCollinearVerticesArePlanned).
Ring withoutRepeats(const Ring& ring) {
  Ring out;
  for (const auto& p : ring)
    if (out.empty() || (p - out.back()).norm() > 1e-9 * std::max(1.0, p.norm())) out.push_back(p);
  while (out.size() > 1 && (out.front() - out.back()).norm() <= 1e-9 * std::max(1.0, out.front().norm())) out.pop_back();
  return out;
}

// The area minus its holes and no-fly zones (subtracted with CGAL as `plan` does; a zone partly
// outside is clipped): what the coverage must reach.
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

// Coverage of `path` over `regions` [%], exact, by geometry's own checker: the swaths (a square
// footprint `footprint` wide along every sweep line and arc) united with CGAL Boolean operations.
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

// Flies the route of `a` with its widest arcs; coverage_pct is NaN until verify() has run.
// `route` flown, its path labelled with the pattern and sweep angle [rad] it came from.
FlownPath flyLabelled(RouteScorer& scorer, const Route& route, double angle, const std::string& pattern) {
  FlownPath f = scorer.fly(route);
  f.path.pattern = pattern;
  f.path.sweep_angle = angle;
  return f;
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

// Checks the coverage of `c` (flown from `a` by flyUnverified). Rounded corners must keep it: when
// the arcs leave more than kMinCoveragePct uncovered, the same route is flown with the arcs allowed
// to cut in less (halving), down to stops everywhere.
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
                     const AngleResult& a, const std::string& pattern) {
  PlanCandidate c = flyUnverified(scorer, a, pattern);
  verify(free, footprint, scorer, a, c);
  return c;
}

// Whether candidate `c` should replace `plan`: keeping coverage (>= kMinCoveragePct) first, then
// less energy; between candidates that both miss it, more coverage first.
bool better(const PlanCandidate& c, const PlanCandidate& plan) {
  if (!c.valid) return false;
  if (!plan.valid) return true;
  const bool covers = c.coverage_pct >= kMinCoveragePct, plan_covers = plan.coverage_pct >= kMinCoveragePct;
  if (covers != plan_covers) return covers;
  if (covers) return c.flown.energy < plan.flown.energy;
  if (std::abs(c.coverage_pct - plan.coverage_pct) > 1e-9) return c.coverage_pct > plan.coverage_pct;
  return c.flown.energy < plan.flown.energy;
}

double distanceToSegment(const Point& p, const Point& a, const Point& b) {
  const Point d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + d * t)).norm();
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
  if (exact_max_cells < 0 || exact_max_cells > kGtspExactMaxClusters) bad("exact_max_cells", exact_max_cells, "[0, 12]");
}

double coveragePercent(const SurveyProblem& pr, const geometry::CoveragePath& path) {
  return coverageOf(freeRegions(pr), pr.footprint, path);
}

std::vector<std::string> checkPlan(const SurveyProblem& pr, const geometry::CoveragePath& path) {
  // Continuity, headings, arcs and holes: geometry's path checker; then the no-fly zones.
  std::vector<std::string> problems = geometry::checkPath(path, pr.area);
  const std::vector<Ring>& obstacles = pr.no_fly;
  for (size_t i = 0; i < path.legs.size(); ++i) {
    const auto& leg = path.legs[i];
    std::vector<Point> pts{leg.start, leg.end};
    if (leg.kind == geometry::PrimitiveKind::Arc) {
      pts.clear();
      const double a0 = std::atan2(leg.start.y() - leg.center.y(), leg.start.x() - leg.center.x());
      for (int k = 0; k <= 16; ++k) {
        const double a = a0 + leg.turn_angle * k / 16.0;
        pts.push_back(leg.center + leg.radius * Point(std::cos(a), std::sin(a)));
      }
    }
    for (size_t k = 0; k + 1 < pts.size(); ++k)
      for (size_t o = 0; o < obstacles.size(); ++o)
        if (segmentEntersRing(pts[k], pts[k + 1], obstacles[o]) || insideRing(pts[k], obstacles[o]))
          problems.push_back("leg " + std::to_string(i) + " enters " +
                             "no-fly zone " + std::to_string(o));
  }
  return problems;
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
  Context ctx;
  ctx.problem = &problem;
  ctx.obstacles = problem.area.holes;
  ctx.obstacles.insert(ctx.obstacles.end(), problem.no_fly.begin(), problem.no_fly.end());
  ctx.clearance = ps.clearance;
  ctx.run_out = 0.5 * problem.spacing;
  ctx.overlap_margin = 0.5 * (problem.footprint - problem.spacing);
  TransitRouter router(ctx.obstacles, TransitSettings{ps.clearance});
  if (router.blocked(problem.home)) throw std::invalid_argument("home is inside a hole or no-fly zone");
  // A no-fly zone over the whole area leaves nothing to cover: an error, not an empty plan.
  for (size_t i = 0; i < problem.no_fly.size(); ++i) {
    const auto& z = problem.no_fly[i];
    const bool area_inside = std::all_of(problem.area.outer.begin(), problem.area.outer.end(),
                                         [&](const geometry::Point& p) { return insideRing(p, z); });
    const bool zone_reaches_in = std::any_of(z.begin(), z.end(), [&](const geometry::Point& p) {
      return insideRing(p, problem.area.outer);
    });
    if (area_inside && !zone_reaches_in) {
      throw std::invalid_argument("SurveyProblem.no_fly[" + std::to_string(i) +
                                  "] covers the whole area; expected a zone leaving part of the area to fly");
    }
  }
  ctx.router = &router;

  SpeedSettings ss = SpeedSettings::fromVehicle(vehicle);
  ss.camera_max_speed = ps.camera_max_speed;
  ss.altitude = problem.altitude;
  ss.corners = ps.corners;
  RouteScorer scorer(model, ss);
  double diag = 0.0;
  for (const auto& p : problem.area.outer) diag = std::max(diag, (p - problem.home).norm());
  const StopTable stop = makeStopTable(scorer, 4.0 * diag);

  PlanResult res;
  const auto free = freeRegions(problem);  // what the coverage checks measure against
  auto deg = [](double d) {
    std::ostringstream os;
    os << d;
    return os.str();
  };
  say("plan: searching sweep angles (coarse " + deg(ps.coarse_step_deg) + " deg, fine " + deg(ps.fine_step_deg) +
      " deg) on " + std::to_string(ps.threads) + " threads");
  const auto ranked = searchAngles(ctx, model, ss, stop, Objective::Energy, ps, &res.candidates, &res.sweep_scan);
  const AngleResult& best = ranked.front();
  // The search ranks angles by the order search's estimate; the few best are flown in full (with
  // the coverage check, which may take arcs back) and the cheapest that keeps coverage is kept.
  // Re-assembled with the shortest order as a second choice (see assemble()), on ps.threads workers.
  size_t finals = 0;
  while (finals < std::min(kFinishBest, ranked.size()) && std::isfinite(ranked[finals].score)) ++finals;
  std::vector<PlanCandidate> finished(finals);
  std::vector<AngleResult> flown_from(finals);
  {
    std::vector<std::thread> pool;
    std::exception_ptr error;
    std::mutex m;
    const int nt = std::max(1, std::min<int>(ps.threads, static_cast<int>(finals)));
    for (int t = 0; t < nt; ++t)
      pool.emplace_back([&, t]() {
        try {
          RouteScorer local(model, ss);
          for (size_t k = t; k < finals; k += nt) {
            const AngleResult both =
                evaluateAngle(ctx, ranked[k].angle, local, stop, Objective::Energy, ps.exact_max_cells, true);
            flown_from[k] = both.score < ranked[k].score ? both : ranked[k];
            finished[k] = flyUnverified(local, flown_from[k], "boustrophedon");
          }
        } catch (...) {
          std::lock_guard<std::mutex> lock(m);
          error = std::current_exception();
        }
      });
    for (auto& th : pool) th.join();
    if (error) std::rethrow_exception(error);
  }
  // The exact coverage check (CGAL Booleans) costs as much as flying a route, so the finalists are
  // checked lazily, cheapest first: once one keeps coverage, a finalist whose widest-arc energy is
  // already higher cannot win (narrower arcs only take its energy up, not down).
  std::vector<size_t> by_energy(finals);
  for (size_t k = 0; k < finals; ++k) by_energy[k] = k;
  std::sort(by_energy.begin(), by_energy.end(),
            [&](size_t a, size_t b) { return finished[a].flown.energy < finished[b].flown.energy; });
  for (size_t k : by_energy) {
    auto& c = finished[k];
    if (!c.valid) continue;
    if (res.plan.valid && res.plan.coverage_pct >= kMinCoveragePct && c.flown.energy >= res.plan.flown.energy) break;
    verify(free, problem.footprint, scorer, flown_from[k], c);
    if (better(c, res.plan)) res.plan = std::move(c);
  }
  const double plan_angle = res.plan.valid ? res.plan.flown.path.sweep_angle : best.angle;  // [rad]
  // (c) The best spiral needs only the plan's angle (to cut an area with holes into pieces): with a
  // second thread it runs beside the per-cell search and the baselines. It has its own scorer in
  // every case, so its numbers do not depend on the number of threads.
  std::string spiral_why;
  int spiral_count = 0;
  std::optional<PlanCandidate> spiral_plan;
  auto spiral_stage = [&ctx, &model, &ss, &stop, &ps, &free, &problem, plan_angle, &spiral_count, &spiral_why,
                       &spiral_plan]() {
    RouteScorer local(model, ss);
    const auto s = spiralPlan(ctx, local, stop, Objective::Energy, ps.exact_max_cells, plan_angle, &spiral_count, &spiral_why);
    if (s && std::isfinite(s->score)) {
      spiral_plan = finish(free, problem.footprint, local, *s, "spiral");
    } else if (spiral_why.empty()) {
      spiral_why = "no spiral: no start vertex gave a flyable route";
    }
  };
  std::future<void> spiral_job;  // destroyed (joined) before anything the stage refers to
  if (ps.spirals && ps.threads > 1) spiral_job = std::async(std::launch::async, spiral_stage);
  if (ps.per_cell && std::isfinite(best.score)) {
    say("plan: per-cell search (each cell's own sweep angle or spiral)");
    std::vector<CellPlan> info;
    std::string why;
    const auto mixed = perCellPlan(ctx, model, ss, scorer, stop, ps, plan_angle, &res.candidates, &info, &why);
    if (!mixed) {
      res.notes.push_back("per-cell search skipped: " + why);
    } else {
      const bool all_spiral = std::all_of(info.begin(), info.end(), [](const CellPlan& c) { return c.pattern == "spiral"; });
      const bool any_spiral = std::any_of(info.begin(), info.end(), [](const CellPlan& c) { return c.pattern == "spiral"; });
      PlanCandidate c = finish(free, problem.footprint, scorer, *mixed, all_spiral ? "spiral" : any_spiral ? "mixed" : "boustrophedon");
      // The reported angle: the largest boustrophedon cell's.
      double largest = -1.0;
      for (const auto& cp : info)
        if (cp.pattern == "boustrophedon" && cp.area_m2 > largest) {
          largest = cp.area_m2;
          c.sweep_angle_deg = cp.sweep_angle_deg;
        }
      if (all_spiral) c.sweep_angle_deg = 0.0;
      c.cell_plans = std::move(info);
      res.per_cell = c;
      if (better(c, res.plan)) res.plan = std::move(c);
    }
  }

  say("plan: baselines");
  // (a) shortest path: length objective for angle and order, flown with our speeds.
  const AngleResult shortest = searchAngles(ctx, model, ss, stop, Objective::Length, ps, &res.candidates).front();
  res.shortest_path = finish(free, problem.footprint, scorer, shortest, "boustrophedon");
  // (b) ground-station default: parallel to the longest edge, one constant speed, stop at corners.
  const auto& outer = problem.area.outer;
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
  res.ground_station_default = finish(free, problem.footprint, gs_scorer, gsr, "boustrophedon");
  ++res.candidates;
  // (c) best spiral (started above when there is a second thread).
  say("plan: spirals");
  if (!ps.spirals) {
    res.notes.push_back("spirals were not searched (straight parallel lines only)");
  } else {
    if (spiral_job.valid()) {
      spiral_job.get();  // rethrows what the stage threw
    } else {
      spiral_stage();
    }
    res.candidates += spiral_count;
    if (spiral_plan) {
      res.best_spiral = std::move(*spiral_plan);
    } else {
      res.notes.push_back(spiral_why);
    }
  }
  // The plan is the least-energy candidate of all scored, baselines included (so it never costs
  // more than one that keeps coverage).
  for (const PlanCandidate* c : {&res.shortest_path, &res.ground_station_default}) {
    if (better(*c, res.plan)) {
      res.plan = *c;
      res.notes.push_back("a baseline geometry was cheaper than the searched ones and is used as the plan");
    }
  }
  if (res.best_spiral && better(*res.best_spiral, res.plan)) res.plan = *res.best_spiral;
  if (!res.plan.valid) throw std::runtime_error("plan: no coverage path found (area narrower than the clearance?)");

  // Lower bound: the swath length the coverage needs at the best energy per metre, plus the way from
  // home to the area and back; turns counted at zero (an arc can cost as little per metre). A path
  // of length L sweeps its square footprint w over at most L w + w^2 of ground (counted with
  // multiplicity); the requested spacing s asks every point to be seen w / s times (side overlap),
  // so L >= A / s - w (with s = w: A / w - w, the plain coverage bound). Sweeps pay at least the best
  // energy per metre under the camera cap, the way to and from the area at least the best at all.
  const double cap = ps.camera_max_speed > 0 ? std::min(ps.camera_max_speed, ss.max_speed) : ss.max_speed;
  double free_area = geometry::area(problem.area);
  for (const auto& z : problem.no_fly) free_area -= std::abs(geometry::signedArea(z));  // may overlap the outside: bound stays a bound
  free_area = std::max(free_area, 0.0);
  double approach = kInf;
  if (insideRing(problem.home, problem.area.outer)) approach = 0.0;
  for (size_t i = 0; i < outer.size(); ++i)
    approach = std::min(approach, distanceToSegment(problem.home, outer[i], outer[(i + 1) % outer.size()]));
  const double swath = std::max(0.0, free_area / problem.spacing - problem.footprint);
  res.lower_bound_j = model.minEnergyPerMetre(cap) * swath + model.minEnergyPerMetre(ss.max_speed) * 2.0 * approach;
  // Every flight also starts and ends at rest. When power depends on speed alone (Marins' effects:
  // hover, kinetic, drag), a flight of length L from rest to rest costs at least the best single
  // stop-to-stop leg of length L: along the path, speed is at most the accelerate-cruise-brake
  // envelope at the vehicle's limits, energy per metre falls with speed up to the best speed, the
  // kinetic term pays at least the peak speed up and down, and turns and stops only add. That
  // least energy grows with L, so the shortest possible flight bounds every flight.
  if (energy::MarinsClosedForm::forLegsOf(model, ss.limits) && swath + 2.0 * approach > 0.0) {
    res.lower_bound_j = std::max(res.lower_bound_j, scorer.legEnergy(swath + 2.0 * approach, 0.0, 0.0, ss.max_speed));
  }
  if (vehicle.battery) {
    res.battery = predictBatteryUse(res.plan.flown, *vehicle.battery);
    if (!res.battery->fits) res.notes.push_back(res.battery->warning);
  }
  say("plan: done, " + std::to_string(res.candidates) + " candidates scored");
  return res;
}

}  // namespace wattswath::planner
