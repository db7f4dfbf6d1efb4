#pragma once
// Internal to apps/report/src: what the plan, validation, turn and speed reports share.
#include <string>

#include "wattswath/report/charts.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report::detail {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;  // [deg] per radian

/// Energy [J] written in kJ with 3 decimals.
inline std::string kJ(double joules) { return formatNumber(joules / 1000.0, 3); }

/// Adds the facts table to `r` unless there are none.
inline void addFacts(HtmlReport& r, const Facts& f) {
  if (!f.empty()) r.facts(f);
}

}  // namespace wattswath::report::detail
