// The plan report's sorties section: each sortie on the map in its own colour and dash pattern,
// a table per sortie, the price of splitting against one unlimited-battery flight, the fleet.
#include <algorithm>
#include <cmath>
#include <map>

#include "report_common.hpp"

namespace wattswath::report {

using namespace detail;

namespace {

std::string Wh(double joules) { return formatNumber(joules / 3600.0, 1); }

void sortieMap(HtmlReport& r, const PlanReportData& d, const PlanSorties& s) {
  MapView m;
  m.title = "Sorties, each in its own colour and dash pattern";
  m.areas = d.areas;
  m.no_fly = d.no_fly;
  for (std::size_t k = 0; k < s.sorties.size(); ++k) {
    const auto& so = s.sorties[k];
    if (so.track.size() < 2) continue;
    MapPolyline p;
    p.points = so.track;
    p.colour = seriesColour(k);
    p.dash = seriesDash(k);
    p.tooltip = so.name + " (" + so.file + "): " + kJ(so.energy_j) + " kJ, " + formatMinSec(so.time_s) + " min:s, lands with " +
                formatNumber(so.soc_landing_pct, 0) + " %";
    m.path.push_back(std::move(p));
    m.legend.push_back({so.name, seriesColour(k), seriesDash(k)});
  }
  if (d.home) m.markers.push_back({*d.home, "home: every sortie's take-off and landing", MapMarker::Shape::Square, "#000000"});
  if (m.path.empty() && m.areas.empty()) {
    r.paragraph("No sortie has a track to draw.");
    return;
  }
  r.figure({"plan-sorties-map", renderSvg(m),
            "Map in local metres (east right, north up): each sortie as the autopilot model flies its own mission file, "
            "from take-off to landing at home; hover a track for its sortie" +
                std::string(d.no_fly.empty() ? "" : "; red dashed areas are no-fly zones") + "."});
}

void sortieTable(HtmlReport& r, const PlanSorties& s) {
  const bool fleet = s.vehicles > 0;
  Table t{"Sorties (each flown by the autopilot model from its own mission file, take-off command to landing)",
          {"sortie", "mission file", "energy [kJ]", "energy [Wh]", "time [min:s]", "state of charge at landing [% of usable]", "photos"},
          {},
          {false, false, true, true, true, true, true},
          false};
  if (fleet) {
    t.header.insert(t.header.begin() + 1, {"vehicle", "take-off at [min:s]", "delay for separation [s]"});
    t.numeric.insert(t.numeric.begin() + 1, {true, true, true});
  }
  double e = 0.0, time = 0.0;
  int photos = 0;
  bool camera = false;
  for (const auto& so : s.sorties) {
    std::vector<std::string> row = {so.name, so.file, kJ(so.energy_j), Wh(so.energy_j), formatMinSec(so.time_s),
                                    formatNumber(so.soc_landing_pct, 1), so.photos >= 0 ? std::to_string(so.photos) : "-"};
    if (fleet)
      row.insert(row.begin() + 1, {std::to_string(so.vehicle), formatMinSec(so.start_s), formatNumber(so.delay_s, 0)});
    t.rows.push_back(row);
    e += so.energy_j;
    time += so.time_s;
    camera = camera || so.photos >= 0;
    photos += std::max(so.photos, 0);
  }
  std::vector<std::string> total = {"all " + std::to_string(s.sorties.size()) + " sorties", "", kJ(e), Wh(e), formatMinSec(time), "",
                                    camera ? std::to_string(photos) : "-"};
  if (fleet) total.insert(total.begin() + 1, {"", "", ""});
  t.rows.push_back(total);
  r.table(t);
  Table p{"Price of splitting: the sorties against one idealised flight with an unlimited battery",
          {"flight", "energy [kJ]", "energy [Wh]", "time in the air [min:s]", "energy above the one flight [%]"},
          {},
          {false, true, true, true, true},
          false};
  const double base = s.single_energy_j;
  p.rows.push_back({"one flight (" + s.single_base + ")", kJ(base), Wh(base), formatMinSec(s.single_time_s), "0.0"});
  p.rows.push_back({std::to_string(s.sorties.size()) + " sorties, each landing with " + formatNumber(s.reserve_pct, 0) + " % reserve", kJ(e),
                    Wh(e), formatMinSec(time), base > 0.0 ? formatNumber(100.0 * (e / base - 1.0), 1) : "-"});
  r.table(p);
}

// The fleet's timeline: each sortie a bar from its take-off to its landing at its vehicle's
// height, in the sortie's colour and dash pattern as on the map.
void fleetTimeline(HtmlReport& r, const PlanSorties& s) {
  LineChart c;
  c.title = "Fleet timeline: each sortie from take-off to landing";
  c.x = {"time since the first take-off", "min"};
  c.y = {"vehicle", "1"};
  c.y.min = 0.5;
  c.y.max = s.vehicles + 0.5;
  c.x.min = 0.0;
  c.height = 160.0 + 40.0 * s.vehicles;
  for (std::size_t k = 0; k < s.sorties.size(); ++k) {
    const auto& so = s.sorties[k];
    Series b(so.name, {so.start_s / 60.0, (so.start_s + so.time_s) / 60.0}, {double(so.vehicle), double(so.vehicle)});
    b.colour = seriesColour(k);
    b.dash = seriesDash(k);
    b.width = 6.0;
    c.series.push_back(std::move(b));
  }
  r.figure({"plan-fleet-timeline", renderSvg(c),
            "When each vehicle flies (makespan " + formatMinSec(s.makespan_s) + " min:s); the gaps are battery swaps (" +
                formatNumber(s.swap_time_s, 0) + " s) and delays that keep the separation."});
}

void fleetSchedule(HtmlReport& r, const PlanSorties& s) {
  fleetTimeline(r, s);
  struct Busy {
    int sorties = 0;
    double first = 1e300, last = 0.0, air = 0.0;
  };
  std::map<int, Busy> by;
  for (const auto& so : s.sorties) {
    auto& b = by[so.vehicle];
    ++b.sorties;
    b.first = std::min(b.first, so.start_s);
    b.last = std::max(b.last, so.start_s + so.time_s);
    b.air += so.time_s;
  }
  Table t{"Fleet schedule: " + std::to_string(s.vehicles) + " vehicles flying at once, makespan " + formatMinSec(s.makespan_s) + " min:s",
          {"vehicle", "sorties", "first take-off [min:s]", "last landing [min:s]", "in the air [min:s]", "battery swaps [min:s]"},
          {},
          {true, true, true, true, true, true},
          false};
  for (const auto& [v, b] : by)
    t.rows.push_back({std::to_string(v), std::to_string(b.sorties), formatMinSec(b.first), formatMinSec(b.last), formatMinSec(b.air),
                      formatMinSec(s.swap_time_s * (b.sorties - 1))});
  r.table(t);
  const std::string found = std::isfinite(s.min_separation_m) ? formatNumber(s.min_separation_m, 1) + " m" : "no two vehicles airborne at once";
  r.paragraph("Separation: any two airborne vehicles keep at least " + formatNumber(s.separation_m, 1) +
              " m horizontally, checked on the trajectories the autopilot model flies (every sortie's samples at its "
              "scheduled time, vehicles on the ground not counted); a sortie that would come closer starts later. "
              "Smallest separation found: " + found + ". Vehicles take off " + formatNumber(s.launch_interval_s, 0) +
              " s apart; a battery swap takes " + formatNumber(s.swap_time_s, 0) + " s.");
}

}  // namespace

void addPlanSorties(HtmlReport& r, const PlanReportData& d) {
  if (!d.sorties) return;
  const auto& s = *d.sorties;
  r.heading(s.vehicles > 0 ? "Sorties and fleet" : "Sorties");
  sortieMap(r, d, s);
  sortieTable(r, s);
  if (s.vehicles > 0) fleetSchedule(r, s);
}

}  // namespace wattswath::report
