#pragma once
// Internal to calibration/src: numbers in the notes and descriptions of fit.cpp, diagnose.cpp and
// simulate.cpp.
#include <cstdio>
#include <string>

namespace wattswath::calibration::detail {

/// `v` written with `digits` significant digits (printf %g).
inline std::string num(double v, int digits = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace wattswath::calibration::detail
