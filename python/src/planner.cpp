// Python bindings of the planner: the minimum-energy coverage plan of a survey area (planCoverage),
// its energy, time and path as NumPy arrays, its baselines and its mission as QGroundControl .plan text.
#include <cmath>

#include "bindings.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/mission/planned_mission.hpp"
#include "wattswath/mission/autopilot.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/flight_score.hpp"
#include "wattswath/planner/margin.hpp"
#include "wattswath/planner/mission_from_plan.hpp"

namespace wattswath::python {
namespace {

namespace geo = geometry;
namespace pl = planner;

const char* kindName(geo::PrimitiveKind k) {
  switch (k) {
    case geo::PrimitiveKind::Line: return "line";
    case geo::PrimitiveKind::Arc: return "arc";
    case geo::PrimitiveKind::TurnInPlace: return "turn_in_place";
  }
  return "?";
}

const char* roleName(geo::LegRole r) {
  switch (r) {
    case geo::LegRole::Sweep: return "sweep";
    case geo::LegRole::Turn: return "turn";
    case geo::LegRole::Transit: return "transit";
    case geo::LegRole::Climb: return "climb";
  }
  return "?";
}

// The path as a polyline [m]: each leg's start, arcs sampled at most 10 deg apart, the last end.
py::array_t<double> polyline(const geo::CoveragePath& path) {
  std::vector<geo::Point> pts;
  for (const auto& leg : path.legs) {
    pts.push_back(leg.start);
    if (leg.kind != geo::PrimitiveKind::Arc) continue;
    const geo::Point r0 = leg.start - leg.center;
    const double phi0 = std::atan2(r0.y(), r0.x());
    const int n = std::max(2, static_cast<int>(std::ceil(std::abs(leg.turn_angle) / (M_PI / 18.0))));
    for (int k = 1; k < n; ++k) {
      const double phi = phi0 + leg.turn_angle * k / n;
      pts.emplace_back(leg.center + leg.radius * geo::Point(std::cos(phi), std::sin(phi)));
    }
  }
  if (!path.legs.empty()) pts.push_back(path.legs.back().end);
  return rowsOf<2>(pts.size(), [&](std::size_t i) { return pts[i]; });
}

py::dict legsDict(const pl::FlownPath& f) {
  const auto& legs = f.path.legs;
  std::vector<std::string> kind, role;
  for (const auto& l : legs) {
    kind.emplace_back(kindName(l.kind));
    role.emplace_back(roleName(l.role));
  }
  const auto at = [](const std::vector<double>& v, std::size_t i) { return i < v.size() ? v[i] : std::nan(""); };
  py::dict d;
  d["start"] = rowsOf<2>(legs.size(), [&](std::size_t i) { return legs[i].start; });
  d["end"] = rowsOf<2>(legs.size(), [&](std::size_t i) { return legs[i].end; });
  d["length_m"] = arrayOf(legs.size(), [&](std::size_t i) { return legs[i].length(); });
  d["energy_j"] = arrayOf(legs.size(), [&](std::size_t i) { return at(f.leg_energy, i); });
  d["time_s"] = arrayOf(legs.size(), [&](std::size_t i) { return at(f.leg_time, i); });
  d["cruise_mps"] = arrayOf(legs.size(), [&](std::size_t i) { return at(f.speeds.cruise, i); });
  d["kind"] = kind;
  d["role"] = role;
  return d;
}

py::dict candidateDict(const pl::PlanCandidate& c) {
  return py::dict(py::arg("energy_j") = c.flown.energy, py::arg("time_s") = c.flown.time,
                  py::arg("length_m") = c.flown.length, py::arg("pattern") = c.pattern,
                  py::arg("sweep_angle_deg") = c.sweep_angle_deg, py::arg("cells") = c.cells,
                  py::arg("coverage_pct") = c.coverage_pct, py::arg("sharp_corners") = c.flown.sharp_corners,
                  py::arg("rounded_corners") = c.flown.rounded_corners);
}

pl::SurveyProblem problemOf(const geo::SurveyArea& area, double spacing, double altitude, double footprint) {
  pl::SurveyProblem p;
  p.area = area.polygon();
  p.no_fly = area.no_fly;
  p.home = area.home ? *area.home : p.area.outer.front();
  p.spacing = spacing;
  p.footprint = footprint > 0.0 ? footprint : spacing;
  p.altitude = altitude;
  return p;
}

// The plan's mission as `wattswath plan` writes it: flown by the vehicle's autopilot model as
// `predict` flies it (the vehicle's autopilot object, else ArduCopter 4.5 defaults), in each way it
// can be written (arcs as chords or waypoints; ArduCopter: speed commands a waypoint early), the
// cheapest kept (planner/flight_score.hpp). `problem` is the area as read (no margin); the mission
// gets plan's inclusion fence and its check of the legs between waypoints against the no-fly margin
// (apps/cmd_plan.cpp, flightScoring).
pl::FlightScore flownMission(const pl::PlanResult& r, const pl::SurveyProblem& problem, const geo::LocalFrame& frame,
                             double home_alt_m, const energy::Vehicle& v, const energy::EnergyModel& model,
                             double no_fly_margin, int threads) {
  pl::FlightScoring scoring;
  scoring.problem = &problem;
  scoring.frame = &frame;
  scoring.home_altitude_amsl_m = home_alt_m;
  scoring.mission.rotor_count = v.rotor_count;
  scoring.mission.fence_margin_m = no_fly_margin > 0.0 ? no_fly_margin : pl::kDefaultNoFlyMargin;
  scoring.mission.no_fly_margin_m = no_fly_margin;
  scoring.vehicle = &v;
  scoring.model = &model;
  pl::setAutopilot(scoring, mission::parseAutopilot(v.autopilot_json, v.name));
  scoring.threads = threads;
  std::vector<pl::FlightScore> scores;
  {
    py::gil_scoped_release release;
    scores = pl::scoreByFlight({{"plan", &r.plan}}, scoring);
  }
  return scores[pl::cheapestFlight(scores)];
}

py::dict flightDict(const pl::FlightScore& f) {
  return py::dict(py::arg("label") = f.label, py::arg("energy_j") = f.prediction.total.energy_j,
                  py::arg("time_s") = f.prediction.total.time_s, py::arg("distance_m") = f.prediction.total.distance_m,
                  py::arg("arc_waypoints") = f.arc_waypoints, py::arg("speeds_a_waypoint_early") = f.speeds_a_waypoint_early);
}

py::dict plan(const geo::SurveyArea& area, const energy::Vehicle& v, const energy::EnergyModel& model, double spacing,
              double altitude, double footprint, bool spirals, bool per_cell, double no_fly_margin, int threads) {
  const pl::SurveyProblem problem = problemOf(area, spacing, altitude, footprint);
  // As `wattswath plan --no-fly-margin`: the search covers the area with its no-fly zones grown by
  // the margin (ValueError for a negative margin, or home within it).
  std::vector<std::string> margin_notes;
  const pl::SurveyProblem flown_problem = pl::withNoFlyMargin(problem, no_fly_margin, &margin_notes);
  pl::PlannerSettings s;
  s.spirals = spirals;
  s.per_cell = per_cell;
  s.threads = threads;
  pl::PlanResult r;
  // Other Python threads may run during the search and the flights; they work on copies those
  // threads cannot change.
  const energy::Vehicle vehicle = v;
  const energy::EnergyModel scoring = model;
  {
    py::gil_scoped_release release;
    r = pl::planCoverage(flown_problem, vehicle, scoring, s);
  }
  py::dict d = candidateDict(r.plan);
  d["lower_bound_j"] = r.lower_bound_j;
  d["candidates"] = r.candidates;
  d["path"] = polyline(r.plan.flown.path);
  d["legs"] = legsDict(r.plan.flown);
  d["shortest_path"] = candidateDict(r.shortest_path);
  d["ground_station_default"] = candidateDict(r.ground_station_default);
  d["best_spiral"] = r.best_spiral ? py::object(candidateDict(*r.best_spiral)) : py::object(py::none());
  d["sweep_scan_deg"] = arrayOf(r.sweep_scan.size(), [&](std::size_t i) { return r.sweep_scan[i].sweep_angle_deg; });
  d["sweep_scan_j"] = arrayOf(r.sweep_scan.size(), [&](std::size_t i) { return r.sweep_scan[i].energy_j; });
  margin_notes.insert(margin_notes.end(), r.notes.begin(), r.notes.end());
  d["notes"] = margin_notes;
  if (area.frame) {
    const pl::FlightScore chosen = flownMission(r, problem, *area.frame, area.home_alt_m.value_or(area.frame->origin().alt_m),
                                                vehicle, scoring, no_fly_margin, threads);
    d["qgc_plan"] = mission::toQgcPlan(chosen.mission.mission);
    d["mission_notes"] = chosen.mission.notes;
    d["flight"] = flightDict(chosen);
  } else {
    d["qgc_plan"] = py::none();
    d["flight"] = py::none();
  }
  return d;
}

}  // namespace

void bindPlanner(py::module_& m) {
  m.def("plan", &plan, py::arg("area"), py::arg("vehicle"), py::arg("model"), py::arg("spacing") = 15.0,
        py::arg("altitude") = 10.0, py::arg("footprint") = 0.0, py::arg("spirals") = true, py::arg("per_cell") = true,
        py::arg("no_fly_margin") = pl::kDefaultNoFlyMargin, py::arg("threads") = 2,
        "Plans the minimum-energy coverage of a SurveyArea (single region) with lines `spacing` [m] apart at "
        "`altitude` [m] (footprint [m], default the spacing), every flown point keeping `no_fly_margin` [m] "
        "(default 2, as `wattswath plan --no-fly-margin`; 0: none) from the area's holes and no-fly zones: dict "
        "energy_j, time_s, length_m, pattern, sweep_angle_deg, coverage_pct, path (M x 2 polyline [m]), legs "
        "(per-leg arrays), the baselines shortest_path, ground_station_default, best_spiral, lower_bound_j, notes, "
        "qgc_plan (.plan text, None without a geodetic frame) and flight: the search's plan flown by the vehicle's "
        "autopilot model with `model` in each way it can be written (label, energy_j, time_s, distance_m, "
        "arc_waypoints, speeds_a_waypoint_early; the cheapest way of writing it), None without a geodetic frame. "
        "With the same options (spacing, altitude, no_fly_margin; `model` = marins_model(vehicle) of a vehicle "
        "without a calibration), qgc_plan is the mission.plan `wattswath plan` writes and flight the flight it "
        "prints, whenever plan writes the search's own choice (--json flight.written starts with 'plan'): plan also "
        "flies the per-cell, best-spiral and shortest-path candidates and writes whichever flies cheapest. "
        "ValueError for a negative margin, or home within it of a zone.");
}

}  // namespace wattswath::python
