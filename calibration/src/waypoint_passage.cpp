// When a track passes a waypoint (waypoint_passage.hpp). A vehicle stopping at a waypoint sits
// within a metre of it for seconds: its closest sample is anywhere in that stop, up to a second
// either side of it in a 1 Hz log, while the prediction's closest sample is where the simulated
// vehicle settles. The middle of the dwell, with the entry and exit interpolated between samples,
// is the same event for both; for a vehicle flying through it is the closest approach.
#include "waypoint_passage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wattswath::calibration::detail {
namespace {

// [m] Closest distance from `w` to the segment between samples a and b.
double segmentDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& w) {
  const Eigen::Vector3d u = b - a, r = w - a;
  const double len2 = u.squaredNorm();
  const double s = len2 > 1e-12 ? std::clamp(r.dot(u) / len2, 0.0, 1.0) : 0.0;
  return (r - s * u).norm();
}

// [s] When the track, straight between samples i and i + 1, crosses the sphere of `radius` around
// `w`: the first crossing (`entering`) or the last one.
double crossing(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos, long i, const Eigen::Vector3d& w,
                double radius, bool entering) {
  const Eigen::Vector3d u = pos[i + 1] - pos[i], r = pos[i] - w;
  const double a = u.squaredNorm(), b = 2.0 * r.dot(u), c = r.squaredNorm() - radius * radius;
  double s = entering ? 0.0 : 1.0;  // no real root: the samples straddle the sphere only by rounding
  if (a > 1e-12 && b * b - 4.0 * a * c >= 0.0) {
    const double q = std::sqrt(b * b - 4.0 * a * c);
    s = std::clamp(entering ? (-b - q) / (2.0 * a) : (-b + q) / (2.0 * a), 0.0, 1.0);
  }
  return t[i] + s * (t[i + 1] - t[i]);
}

}  // namespace

Passage waypointPassage(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pos, const Eigen::Vector3d& w,
                        std::size_t from, double match_m) {
  Passage p;
  const long n = static_cast<long>(t.size()), first = static_cast<long>(from);
  // The closest sample in three dimensions: a vehicle landing, or taking off, below a waypoint
  // (one over home) is not at it.
  double best = 1e300, best_h = 1e300;  // [m] the closest sample's distance, and its horizontal part
  long at = first, last = n - 1;
  for (long i = first; i < n; ++i) {
    const double di = (pos[i] - w).norm();
    if (di < best) best = di, best_h = (pos[i] - w).head<2>().norm(), at = i;
    if (best_h < match_m && di > best + 10.0) {
      last = i;
      break;
    }
  }
  if (!(best_h <= match_m)) return p;
  p.index = at;
  p.closest_m = best_h;
  // The dwell in three dimensions, so a take-off climb below a waypoint is not counted as at it;
  // distances only for the samples the walk out of the dwell visits.
  auto d = [&](long i) { return (pos[i] - w).norm(); };
  double closest = d(at);
  for (long j = std::max(first, at - 1); j < std::min(at + 1, n - 1); ++j)
    closest = std::min(closest, segmentDistance(pos[j], pos[j + 1], w));
  const double radius = closest + kDwellMargin;
  long a = at, b = at;
  while (a > first && d(a - 1) <= radius) --a;
  while (b < last && d(b + 1) <= radius) ++b;
  if (a == first || b == n - 1) {  // the dwell's start or end is not in the track: the closest sample
    p.t = t[at];
    return p;
  }
  p.t = 0.5 * (crossing(t, pos, a - 1, w, radius, true) + crossing(t, pos, b, w, radius, false));
  return p;
}

double interpolateAt(const std::vector<double>& t, const std::vector<double>& y, double at) {
  if (t.empty() || !std::isfinite(at)) return std::numeric_limits<double>::quiet_NaN();
  if (at <= t.front()) return y.front();
  if (at >= t.back()) return y.back();
  const std::size_t j = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
  const std::size_t i = j - 1;
  const double f = t[j] > t[i] ? (at - t[i]) / (t[j] - t[i]) : 0.0;
  return y[i] + f * (y[j] - y[i]);
}

}  // namespace wattswath::calibration::detail
