#pragma once
// Internal to calibration/src: the median of the mission comparisons (mission_calibration.cpp) and
// of the tracking error (tracking_error.cpp); the upper median of the logged power (replay.cpp,
// measurement_check.cpp).
#include <algorithm>
#include <limits>
#include <vector>

namespace wattswath::calibration::detail {

/// The median of `v`: the mean of the two middle values for an even count; NaN when empty.
inline double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

/// The upper median of `v`: the middle value, the upper of the two middle ones for an even count;
/// NaN when empty.
inline double upperMedian(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace wattswath::calibration::detail
