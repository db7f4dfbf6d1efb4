// How far a logged vehicle sat off the legs it was flying (mission::FlightSettings::tracking_error):
// the median horizontal and vertical distance of its cruise samples from the nearest leg.
#include <algorithm>
#include <cmath>

#include "median.hpp"
#include "wattswath/calibration/mission_calibration.hpp"

namespace wattswath::calibration {
namespace {

using detail::median;

// Horizontal and vertical distance of `p` from the leg a-b, the leg found by horizontal distance.
void legDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double& horizontal,
                 double& vertical) {
  const Eigen::Vector2d d = (b - a).head<2>();
  const double s = std::clamp((p - a).head<2>().dot(d) / d.squaredNorm(), 0.0, 1.0);
  const Eigen::Vector3d q = a + s * (b - a);
  horizontal = (p - q).head<2>().norm();
  vertical = std::abs(p.z() - q.z());
}

}  // namespace

void addCruiseTrackingErrors(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos,
                             const std::vector<Eigen::Vector3d>& vel, const std::vector<Eigen::Vector3d>& waypoints,
                             double from_s, double to_s, std::vector<double>& horizontal, std::vector<double>& vertical) {
  constexpr double kAwayFromWaypoint = 10.0;  // [m] corners are flown by the model itself
  constexpr double kMinSpeed = 1.5;           // [m/s] hovering and turning samples are not cruise
  for (std::size_t i = 0; i < pos.size() && i < t.size() && i < vel.size(); ++i) {
    if (!(t[i] >= from_s && t[i] <= to_s) || vel[i].head<2>().norm() < kMinSpeed) continue;
    bool near_waypoint = false;
    for (const auto& w : waypoints) near_waypoint = near_waypoint || (pos[i] - w).head<2>().norm() < kAwayFromWaypoint;
    if (near_waypoint) continue;
    double best_h = 1e300, best_v = 0.0;
    for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
      if ((waypoints[k + 1] - waypoints[k]).head<2>().norm() < 1.0) continue;  // vertical legs: take-off, landing
      double h = 0.0, v = 0.0;
      legDistance(pos[i], waypoints[k], waypoints[k + 1], h, v);
      if (h < best_h) best_h = h, best_v = v;
    }
    if (best_h < 1e300) {
      horizontal.push_back(best_h);
      vertical.push_back(best_v);
    }
  }
}

TrackingMeasurement measureTrackingError(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos,
                                         const std::vector<Eigen::Vector3d>& vel,
                                         const std::vector<Eigen::Vector3d>& waypoints, double from_s, double to_s) {
  std::vector<double> h, v;
  addCruiseTrackingErrors(t, pos, vel, waypoints, from_s, to_s, h, v);
  return trackingFromErrors(h, v);
}

TrackingMeasurement trackingFromErrors(const std::vector<double>& horizontal, const std::vector<double>& vertical) {
  TrackingMeasurement m;
  m.samples = static_cast<int>(std::min(horizontal.size(), vertical.size()));
  m.measured = m.samples >= TrackingMeasurement::kMinSamples;
  if (m.measured) m.error = {median(horizontal), median(vertical)};
  return m;
}

}  // namespace wattswath::calibration
