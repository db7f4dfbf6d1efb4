// The measured side of a mission flight: where the mission's home lies in the log's frame, and the
// times, energies and speeds of its phases and legs between waypoint passages
// (mission_calibration.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "waypoint_passage.hpp"
#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/geometry/frame.hpp"

namespace wattswath::calibration {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Mean horizontal distance of the waypoints to the nearest track point, the track shifted by -d.
double alignmentCost(const std::vector<Eigen::Vector3d>& track, const std::vector<Eigen::Vector3d>& wps,
                     const Eigen::Vector2d& d) {
  double sum = 0.0;
  for (const auto& w : wps) {
    double best = 1e300;
    for (const auto& p : track) best = std::min(best, (p.head<2>() - d - w.head<2>()).squaredNorm());
    sum += std::sqrt(best);
  }
  return wps.empty() ? 0.0 : sum / static_cast<double>(wps.size());
}

}  // namespace

Eigen::Vector2d alignTrack(const std::vector<Eigen::Vector3d>& track, const std::vector<Eigen::Vector3d>& waypoints,
                           double search_m) {
  std::vector<Eigen::Vector3d> thin;
  const std::size_t step = std::max<std::size_t>(1, track.size() / 1500);
  for (std::size_t i = 0; i < track.size(); i += step) thin.push_back(track[i]);
  Eigen::Vector2d best = Eigen::Vector2d::Zero();
  double best_cost = alignmentCost(thin, waypoints, best);
  for (double grid : {2.0, 0.5, 0.1}) {
    const double span = grid == 2.0 ? search_m : grid * 4.0;
    const Eigen::Vector2d centre = best;
    for (double dx = -span; dx <= span + 1e-9; dx += grid)
      for (double dy = -span; dy <= span + 1e-9; dy += grid) {
        const Eigen::Vector2d d = centre + Eigen::Vector2d(dx, dy);
        const double c = alignmentCost(thin, waypoints, d);
        if (c < best_cost) best_cost = c, best = d;
      }
  }
  return best;
}

namespace {

// Horizontal speed [m/s] at each sample over the 1 s from it (the last second: back to 1 s before),
// so a 1 Hz log and a 10 Hz prediction are smoothed alike.
std::vector<double> windowSpeeds(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos) {
  std::vector<double> v(t.size(), kNaN);
  std::size_t j = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    j = std::max(j, i);
    while (j + 1 < t.size() && t[j] < t[i] + 1.0 - 1e-9) ++j;
    std::size_t a = i, b = j;
    if (t[b] - t[a] < 1.0 - 1e-9) {  // the log's last second: look back instead
      a = i;
      while (a > 0 && t[b] - t[a] < 1.0 - 1e-9) --a;
    }
    if (t[b] > t[a]) v[i] = (pos[b] - pos[a]).head<2>().norm() / (t[b] - t[a]);
  }
  return v;
}

}  // namespace

FlightTimes flightTimes(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos,
                        const std::vector<double>& power, const std::vector<Eigen::Vector3d>& waypoints, double match_m) {
  FlightTimes ft;
  if (t.size() < 2) return ft;
  ft.total_s = t.back() - t.front();
  const double top = waypoints.empty() ? pos.back().z() : 0.9 * waypoints.front().z();
  ft.takeoff_s = kNaN;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (pos[i].z() >= top) {
      ft.takeoff_s = t[i] - t.front();
      break;
    }
  std::vector<double> cum_e(t.size(), 0.0), cum_s(t.size(), 0.0);
  for (std::size_t i = 1; i < t.size(); ++i) {
    const bool ok = std::isfinite(power[i]) && std::isfinite(power[i - 1]);
    cum_e[i] = cum_e[i - 1] + (ok ? 0.5 * (power[i] + power[i - 1]) * (t[i] - t[i - 1]) : 0.0);
    cum_s[i] = cum_s[i - 1] + (pos[i] - pos[i - 1]).norm();
  }
  std::vector<long> at_index;  // the sample closest to each passage (-1: unmatched)
  std::size_t from = 0;
  for (const auto& w : waypoints) {
    const detail::Passage pass = detail::waypointPassage(t, pos, w, from, match_m);
    at_index.push_back(pass.index);
    ft.passage_s.push_back(pass.index >= 0 ? pass.t - t.front() : kNaN);
    if (pass.index >= 0) from = static_cast<std::size_t>(pass.index);
  }
  double first = kNaN, last = kNaN;
  for (std::size_t k = 0; k < ft.passage_s.size(); ++k) {
    if (std::isfinite(ft.passage_s[k])) {
      if (!std::isfinite(first)) first = ft.passage_s[k];
      last = ft.passage_s[k];
    }
    if (k > 0) {
      ft.leg_s.push_back(ft.passage_s[k] - ft.passage_s[k - 1]);
      const bool both = at_index[k] >= 0 && at_index[k - 1] >= 0;
      const double t0 = t.front() + ft.passage_s[k - 1], t1 = t.front() + ft.passage_s[k];
      ft.leg_energy_j.push_back(both ? detail::interpolateAt(t, cum_e, t1) - detail::interpolateAt(t, cum_e, t0) : kNaN);
      ft.leg_speed_mps.push_back(both && ft.leg_s.back() > 0.0
                                     ? (detail::interpolateAt(t, cum_s, t1) - detail::interpolateAt(t, cum_s, t0)) / ft.leg_s.back()
                                     : kNaN);
    }
  }
  ft.mission_s = std::isfinite(first) ? last - first : kNaN;
  ft.return_s = std::isfinite(last) ? ft.total_s - last : kNaN;
  // Peak speed per leg and time spent slow between the first and last passage.
  const std::vector<double> speed = windowSpeeds(t, pos);
  for (std::size_t k = 1; k < at_index.size(); ++k) {
    double peak = kNaN;
    if (at_index[k] >= 0 && at_index[k - 1] >= 0) {
      peak = 0.0;
      for (long i = at_index[k - 1]; i <= at_index[k]; ++i)
        if (std::isfinite(speed[static_cast<std::size_t>(i)])) peak = std::max(peak, speed[static_cast<std::size_t>(i)]);
    }
    ft.leg_peak_mps.push_back(peak);
  }
  ft.slow_s = std::isfinite(first) && last > first ? 0.0 : kNaN;  // not measured over one passage
  for (std::size_t i = 1; i < t.size() && std::isfinite(first); ++i) {
    const double tm = t[i] - t.front();
    if (tm > first && tm <= last && std::isfinite(speed[i - 1]) && speed[i - 1] < 1.0) ft.slow_s += t[i] - t[i - 1];
  }
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (!std::isfinite(power[i]) || !std::isfinite(power[i - 1])) continue;
    const double e = 0.5 * (power[i] + power[i - 1]) * (t[i] - t[i - 1]);
    ft.energy_j += e;
    const double tm = t[i] - t.front();
    if (std::isfinite(first) && tm > first && tm <= last) ft.mission_energy_j += e;
  }
  return ft;
}

std::vector<Eigen::Vector3d> flownWaypoints(const std::vector<mission::NavStep>& steps) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& s : steps)
    if (mission::isFlownTo(s) && s.has_position)
      out.push_back(s.target);
  return out;
}

mission::Mission missionFromLaunch(const MissionFlight& f, Eigen::Vector2d* offset, Eigen::Vector2d* launch) {
  std::vector<Eigen::Vector3d> track;
  for (const auto& s : f.log.samples) track.push_back(s.position);
  Eigen::Vector2d d;
  if (f.log.has_geodetic_origin) {
    // The log's frame has a geodetic origin (an autopilot's EKF origin, or lat/lon columns): the
    // mission's home row is placed in it exactly, not by laying the track onto the waypoints.
    const geometry::LocalFrame frame(geometry::GeoPoint{f.log.origin_lat_deg, f.log.origin_lon_deg, f.log.origin_alt_m});
    d = frame.toLocal(f.mission.home.lat_deg, f.mission.home.lon_deg);
  } else {
    d = alignTrack(track, flownWaypoints(mission::sequenceMission(f.mission)));
  }
  const Eigen::Vector2d at = track.empty() ? Eigen::Vector2d::Zero() : Eigen::Vector2d(track.front().head<2>() - d);
  if (offset) *offset = d;
  if (launch) *launch = at;
  return missionLaunchedAt(f.mission, at);
}

mission::Mission missionLaunchedAt(const mission::Mission& m, const Eigen::Vector2d& launch) {
  mission::Mission out = m;
  const geometry::GeoPoint g = geometry::LocalFrame(m.home).toGeodetic(geometry::Point(launch.x(), launch.y()));
  out.home.lat_deg = g.lat_deg;
  out.home.lon_deg = g.lon_deg;
  return out;
}

}  // namespace wattswath::calibration
