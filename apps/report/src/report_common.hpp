#pragma once
// Internal to apps/report/src: what the plan, mission, validation, turn and speed reports share.
#include <algorithm>
#include <string>
#include <vector>

#include "wattswath/report/charts.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report::detail {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;  // [deg] per radian

/// Energy [J] written in kJ with 3 decimals.
inline std::string kJ(double joules) { return formatNumber(joules / 1000.0, 3); }

/// The usable-charge figure of a predicted flight, drawn the same in the plan and mission reports:
/// usable charge left [%] (as the autopilot counts it) against `time` [min], the reserve line when
/// `b.reserve_pct` is known, and the cut-off marked when the battery reaches it in flight.
LineChart usableChargeChart(const BatteryTrace& b, const Axis& time);

/// The caption of usableChargeChart's figure.
std::string usableChargeCaption(const BatteryTrace& b);

/// "battery cut-off m:ss": the label of the line marking the cut-off on the time plots.
std::string cutoffLabel(double seconds);

/// Adds the facts table to `r` unless there are none.
inline void addFacts(HtmlReport& r, const Facts& f) {
  if (!f.empty()) r.facts(f);
}

/// Waypoint dots with their numbers; items at the same place share one dot ("3, 27").
inline void addWaypointMarkers(MapView& m, const std::vector<MissionMark>& items) {
  struct Spot {
    geometry::Point p;
    std::string label;
  };
  std::vector<Spot> spots;
  for (const auto& it : items) {
    if (!it.position || it.seq < 0) continue;
    auto same =
        std::find_if(spots.begin(), spots.end(), [&](const Spot& s) { return (s.p - *it.position).norm() < 1.0; });
    if (same == spots.end()) {
      spots.push_back({*it.position, std::to_string(it.seq)});
    } else {
      same->label += ", " + std::to_string(it.seq);
    }
  }
  for (const auto& s : spots) {
    MapMarker k{s.p, s.label, MapMarker::Shape::Circle, "#222222"};
    k.size = 3.0;
    m.markers.push_back(k);
  }
}

}  // namespace wattswath::report::detail
