#pragma once
// Internal: numbers in error messages, with enough digits to show the offending value.
#include <sstream>
#include <stdexcept>
#include <string>

namespace wattswath::energy::detail {

/// `x` with 10 significant digits.
inline std::string formatNumber(double x) {
  std::ostringstream os;
  os.precision(10);
  os << x;
  return os.str();
}

/// Throws std::invalid_argument "<owner>.<field> = <value>, expected lo..hi" unless lo <= value <= hi
/// (NaN fails): the one range check of the settings structs' validate() functions.
inline void checkSettingRange(const char* owner, const char* field, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi)) {
    throw std::invalid_argument(std::string(owner) + "." + field + " = " + formatNumber(value) + ", expected " +
                                formatNumber(lo) + ".." + formatNumber(hi));
  }
}

}  // namespace wattswath::energy::detail
