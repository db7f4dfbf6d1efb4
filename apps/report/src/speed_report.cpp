// The optimal-speed report: optimal cruise speed against leg length (Marins et al. Fig. 3) and
// leg energy against speed.
#include <algorithm>
#include <cmath>
#include <limits>

#include "report_common.hpp"
#include "wattswath/report/charts.hpp"
#include "wattswath/report/reports.hpp"
#include "wattswath/report/svg.hpp"

namespace wattswath::report {

using namespace detail;

HtmlReport speedReport(const SpeedReportData& d) {
  HtmlReport r(d.title);
  addFacts(r, d.facts);
  if (!d.curves.empty()) {
    LineChart c;
    c.title = "Optimal cruise speed against leg length";
    c.x = {"leg length", "m"};
    c.y = {"optimal cruise speed", "m/s"};
    c.y.include_zero = true;
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (std::size_t i = 0; i < d.curves.size(); ++i) {
      Series s(d.curves[i].name, d.curves[i].distance, d.curves[i].speed);
      s.dash = seriesDash(i);
      c.series.push_back(s);
      for (const double x : d.curves[i].distance) {
        if (x > 0.0) lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
    }
    c.x.log = lo > 0.0 && hi / lo > 50.0;
    if (d.v_max) {
      Series v("speed limit", {lo, hi}, {*d.v_max, *d.v_max});
      v.colour = "#666666";
      v.dash = "2 3";
      v.width = 1.2;
      if (std::isfinite(lo)) c.series.push_back(v);
    }
    r.heading("Optimal speed (Marins et al. Fig. 3)");
    r.figure({"vopt-distance", renderSvg(c), "The speed that minimises the energy of a leg flown " + d.leg_ends + ", for model variants."});
    Table t{"Optimal cruise speed [m/s]", {"model variant", "leg length [m]", "v_opt [m/s]"}, {}, {false, true, true}, true};
    for (const auto& k : d.curves) {
      for (std::size_t i = 0; i < k.distance.size() && i < k.speed.size(); ++i) {
        t.rows.push_back({k.name, formatNumber(k.distance[i], 1), formatNumber(k.speed[i], 3)});
      }
    }
    r.table(t);
  }
  if (!d.legs.empty()) {
    LineChart c;
    c.title = "Energy per metre against cruise speed";
    c.x = {"cruise speed", "m/s"};
    c.y = {"leg energy / leg length", "J/m"};
    for (std::size_t i = 0; i < d.legs.size(); ++i) {
      const auto& l = d.legs[i];
      Series s;
      s.name = formatNumber(l.distance, 0) + " m leg";
      s.dash = seriesDash(i);
      for (std::size_t k = 0; k < l.speed.size() && k < l.energy.size(); ++k) {
        s.x.push_back(l.speed[k]);
        s.y.push_back(l.distance > 0 ? l.energy[k] / l.distance : std::numeric_limits<double>::quiet_NaN());
      }
      c.series.push_back(s);
      if (l.distance > 0) c.markers.push_back({l.best_speed, l.best_energy / l.distance, formatNumber(l.best_speed, 2) + " m/s", seriesColour(i)});
    }
    double best = 0.0;
    for (const auto& l : d.legs) {
      if (l.distance > 0) best = std::max(best, l.best_energy / l.distance);
    }
    if (best > 0.0) {  // the slow end grows without bound (hover time): show the region around the optima
      c.y.min = 0.0;
      c.y.max = 2.5 * best;
    }
    r.heading("Leg energy against speed");
    r.figure({"vopt-energy", renderSvg(c), "Rings mark the optimal cruise speed of each leg length."});
  }
  return r;
}

}  // namespace wattswath::report
