// A fleet flying the sorties of one split at once (fleet.hpp).
#include "wattswath/planner/fleet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace wattswath::planner {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void check(const FleetSettings& s) {
  auto bad = [](const std::string& field, double v, const std::string& expected) {
    throw std::invalid_argument("FleetSettings." + field + " = " + std::to_string(v) + ", expected " + expected);
  };
  if (s.vehicles < 1 || s.vehicles > 100) bad("vehicles", s.vehicles, "1..100");
  if (!(s.swap_time_s >= 0.0 && s.swap_time_s <= 86400.0)) bad("swap_time_s", s.swap_time_s, "0..86400 s");
  if (!(s.launch_interval_s >= 0.0 && s.launch_interval_s <= 86400.0)) bad("launch_interval_s", s.launch_interval_s, "0..86400 s");
  if (!(s.separation_m >= 0.0 && s.separation_m <= 1e4)) bad("separation_m", s.separation_m, "0..10000 m");
  if (!(s.check_dt_s >= 0.01 && s.check_dt_s <= 5.0)) bad("check_dt_s", s.check_dt_s, "0.01..5 s");
  if (!(s.delay_step_s >= 0.1 && s.delay_step_s <= 600.0)) bad("delay_step_s", s.delay_step_s, "0.1..600 s");
}

// Where a sortie is at `tau` [s] after its take-off command (false: not airborne then); the
// cursor only moves forward, so calls must come in time order.
struct Cursor {
  const Track* track = nullptr;
  std::size_t i = 0;

  bool at(double tau, geometry::Point& p) {
    const Track& tr = *track;
    if (tau < tr.front().t || tau > tr.back().t) return false;
    while (i + 1 < tr.size() && tr[i + 1].t < tau) ++i;
    const TrackSample& a = tr[i];
    const TrackSample& b = tr[std::min(i + 1, tr.size() - 1)];
    if (!a.airborne || !b.airborne) return false;
    const double f = b.t > a.t ? std::clamp((tau - a.t) / (b.t - a.t), 0.0, 1.0) : 0.0;
    p = a.p + (b.p - a.p) * f;
    return true;
  }
};

// Least distance between two points moving linearly from (a0, b0) to (a1, b1) over one step.
double closestApproach(const geometry::Point& a0, const geometry::Point& a1, const geometry::Point& b0, const geometry::Point& b1) {
  const geometry::Point d0 = a0 - b0, dd = (a1 - b1) - d0;
  const double den = dd.squaredNorm();
  const double u = den > 0.0 ? std::clamp(-d0.dot(dd) / den, 0.0, 1.0) : 0.0;
  return (d0 + dd * u).norm();
}

// Vehicle and order of every sortie from the first sortie of each vehicle's run.
void assign(const std::vector<int>& runs, std::size_t n, std::vector<int>& vehicle, std::vector<int>& order) {
  vehicle.assign(n, 0);
  order.assign(n, 0);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::size_t end = k + 1 < runs.size() ? static_cast<std::size_t>(runs[k + 1]) : n;
    for (std::size_t i = static_cast<std::size_t>(runs[k]); i < end; ++i) {
      vehicle[i] = static_cast<int>(k);
      order[i] = static_cast<int>(i) - runs[k];
    }
  }
}

}  // namespace

std::vector<int> fleetRuns(const std::vector<double>& d, const FleetSettings& s) {
  check(s);
  const int n = static_cast<int>(d.size());
  if (n == 0) throw std::invalid_argument("fleetRuns: no sorties");
  std::vector<double> prefix(d.size() + 1, 0.0);
  for (int i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + d[i];
  const int kmax = std::min(s.vehicles, n);
  // best[k][j]: least makespan of sorties 0..j-1 flown by vehicles 0..k-1, each with a run.
  std::vector<std::vector<double>> best(kmax + 1, std::vector<double>(n + 1, kInf));
  std::vector<std::vector<int>> from(kmax + 1, std::vector<int>(n + 1, -1));
  best[0][0] = 0.0;
  for (int k = 1; k <= kmax; ++k)
    for (int j = k; j <= n; ++j)
      for (int a = k - 1; a < j; ++a) {
        const double load = (k - 1) * s.launch_interval_s + prefix[j] - prefix[a] + s.swap_time_s * (j - a - 1);
        const double m = std::max(best[k - 1][a], load);
        if (m < best[k][j]) {
          best[k][j] = m;
          from[k][j] = a;
        }
      }
  int used = 1;
  for (int k = 2; k <= kmax; ++k)
    if (best[k][n] < best[used][n] - 1e-9) used = k;
  std::vector<int> runs;
  for (int k = used, j = n; k > 0; j = from[k][j], --k) runs.insert(runs.begin(), from[k][j]);
  return runs;
}

double minSeparation(const std::vector<Track>& tracks, const std::vector<int>& vehicle, const std::vector<double>& start_s,
                     double dt, double separation_m, int* conflict_sortie) {
  if (conflict_sortie) *conflict_sortie = -1;
  double t0 = kInf, t1 = -kInf;
  std::vector<Cursor> cur;
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    cur.push_back({&tracks[i], 0});
    t0 = std::min(t0, start_s[i] + tracks[i].front().t);
    t1 = std::max(t1, start_s[i] + tracks[i].back().t);
  }
  struct Active {
    std::size_t sortie;
    geometry::Point a, b;
  };
  double least = kInf;
  std::vector<Active> act;
  const auto steps = static_cast<long>(std::ceil((t1 - t0) / dt));
  for (long k = 0; k < steps; ++k) {
    const double ta = t0 + dt * static_cast<double>(k), tb = std::min(ta + dt, t1);
    act.clear();
    for (std::size_t i = 0; i < tracks.size(); ++i) {
      geometry::Point a, b;
      if (cur[i].at(ta - start_s[i], a) && cur[i].at(tb - start_s[i], b)) act.push_back({i, a, b});
    }
    for (std::size_t x = 0; x < act.size(); ++x)
      for (std::size_t y = x + 1; y < act.size(); ++y) {
        if (vehicle[act[x].sortie] == vehicle[act[y].sortie]) continue;
        const double dist = closestApproach(act[x].a, act[x].b, act[y].a, act[y].b);
        least = std::min(least, dist);
        if (conflict_sortie && dist < separation_m) {
          const std::size_t i = act[x].sortie, j = act[y].sortie;
          *conflict_sortie = static_cast<int>(start_s[j] > start_s[i] || (start_s[j] == start_s[i] && j > i) ? j : i);
          return least;
        }
      }
  }
  return least;
}

FleetSchedule scheduleFleet(const std::vector<Track>& tracks, const FleetSettings& s) {
  check(s);
  std::vector<double> dur;
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    if (tracks[i].empty()) throw std::invalid_argument("scheduleFleet: sortie " + std::to_string(i + 1) + " has no samples");
    dur.push_back(tracks[i].back().t);
  }
  std::vector<int> vehicle, order;
  assign(fleetRuns(dur, s), tracks.size(), vehicle, order);
  FleetSchedule out;
  out.sorties.resize(tracks.size());
  std::vector<double> start(tracks.size(), 0.0);
  auto timetable = [&]() {
    for (std::size_t i = 0; i < tracks.size(); ++i) {
      auto& so = out.sorties[i];
      so.vehicle = vehicle[i];
      so.order = order[i];
      const double ready = order[i] == 0 ? vehicle[i] * s.launch_interval_s : out.sorties[i - 1].end_s + s.swap_time_s;
      so.start_s = start[i] = ready + so.delay_s;
      so.end_s = so.start_s + dur[i];
    }
  };
  for (;;) {
    timetable();
    int conflict = -1;
    out.min_separation_m = minSeparation(tracks, vehicle, start, s.check_dt_s, s.separation_m, &conflict);
    if (conflict < 0) break;
    if (++out.delays > s.max_delays)
      throw std::runtime_error("the fleet's vehicles still come within " + std::to_string(s.separation_m) + " m of each other after " +
                               std::to_string(s.max_delays) + " delays of " + std::to_string(s.delay_step_s) + " s");
    out.sorties[static_cast<std::size_t>(conflict)].delay_s += s.delay_step_s;
  }
  out.makespan_s = 0.0;
  for (const auto& so : out.sorties) out.makespan_s = std::max(out.makespan_s, so.end_s);
  return out;
}

}  // namespace wattswath::planner
