#pragma once
// Shared helper in logs::detail (not part of the logs API): derivative of a local quadratic
// least-squares fit (Savitzky-Golay smoothing generalised to uneven time steps). Used by
// logs/src/log_io.cpp (velocities and accelerations of a CSV log) and calibration/src/replay.cpp
// (yaw rate); a public header so calibration can include it, hence installed with logs' include/.
#include <algorithm>

#include <Eigen/Dense>

namespace wattswath::logs::detail {

/// d/dt at sample i of a parabola fitted to (time(k), value(k)) over 2 * half + 1 samples centred
/// on i (shifted inwards at the ends; a line when only 2 samples exist). `n` is the sample count.
template <class Time, class Value>
double localSlope(int n, int i, int half, Time time, Value value) {
  const int w = std::min(2 * half + 1, n);
  const int lo = std::clamp(i - w / 2, 0, n - w);
  const int hi = lo + w;  // exclusive
  const double t0 = time(i);
  // Times scaled by the window span keep the normal equations well conditioned at any rate.
  const double span = std::max(time(hi - 1) - time(lo), 1e-12);
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int k = lo; k < hi; ++k) {
    const double u = (time(k) - t0) / span;
    const Eigen::Vector3d phi(1.0, u, w >= 3 ? u * u : 0.0);
    N += phi * phi.transpose();
    b += phi * value(k);
  }
  if (w < 3) N(2, 2) = 1.0;
  return N.ldlt().solve(b)(1) / span;
}

}  // namespace wattswath::logs::detail
