#pragma once
// Internal: numbers in error messages, with enough digits to show the offending value.
#include <sstream>
#include <string>

namespace wattswath::energy::detail {

/// `x` with 10 significant digits.
inline std::string formatNumber(double x) {
  std::ostringstream os;
  os.precision(10);
  os << x;
  return os.str();
}

}  // namespace wattswath::energy::detail
