#include "wattswath/mission/predict.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "files_internal.hpp"
#include "flight_internal.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/planned_mission.hpp"

namespace wattswath::mission {
namespace {

// The discharge of `profile` with its power scaled by `scale` (Hwang et al., 1 s steps).
energy::EnduranceResult discharge(const energy::Battery& b, std::vector<energy::PowerStep> profile, double scale) {
  for (auto& step : profile) step.power_w *= scale;
  energy::DischargeSettings ds;
  ds.dt_s = 1.0;
  return energy::simulateProfile(b, profile, ds);
}

// The charge left is counted as the autopilot counts it (energy::countedUsableLeft: drawn against
// the usable capacity, as BATT_CAPACITY's remaining % and ground stations show it), not Hwang's
// Peukert residual, which drops as the motors start and rises back when they stop; the cut-off
// check keeps the Peukert law. This is that charge at the end of the flight, 0 at the cut-off.
double usableLeft(const energy::Battery& b, const energy::EnduranceResult& r) {
  return r.series.empty() ? 0.0 : energy::countedUsableLeft(b, r.series.back());
}

// One plain sentence on the reserve, with and without the margin for the prediction's error. Its
// first words match the JSON's fits / fits_with_margin ("Does not fit", "Too close to call", "Fits").
// A flight that ends in the air (no RTL or LAND) is judged where it ends, and says so.
// `margin_depleted`: with the margin's extra energy the battery reaches its cut-off.
std::string verdictText(const BatteryPrediction& out, double endurance_s, bool margin_depleted) {
  std::ostringstream v;
  v.precision(3);
  const double margin_pct = 100.0 * out.energy_margin;
  const std::string lands = out.ends_in_air ? "ends the mission in the air (return and landing not counted) with" : "lands with";
  std::ostringstream wm;
  wm.precision(3);
  wm << " with " << margin_pct << " % more energy";
  const std::string with_margin = wm.str();
  if (out.depleted) {
    v << "Does not fit: the battery reaches its cut-off " << endurance_s << " s into the flight.";
  } else if (!out.fits) {
    v << "Does not fit the reserve: " << lands << " " << 100.0 * out.usable_left_end << " % of the usable charge, below the "
      << 100.0 * out.reserve_fraction << " % reserve";
    if (out.energy_margin <= 0.0) v << ".";
    else if (margin_depleted) v << ";" << with_margin << " (the prediction's error margin, --energy-margin) the battery reaches its cut-off.";
    else v << ";" << with_margin << " (the prediction's error margin, --energy-margin) " << 100.0 * out.usable_left_end_with_margin << " %.";
  } else if (out.energy_margin <= 0.0) {
    v << "Fits: " << lands << " " << 100.0 * out.usable_left_end << " % of the usable charge (reserve "
      << 100.0 * out.reserve_fraction << " %).";
  } else if (!out.fits_with_margin) {
    v << "Too close to call: as predicted it " << lands << " " << 100.0 * out.usable_left_end
      << " % of the usable charge (reserve " << 100.0 * out.reserve_fraction << " %), but" << with_margin
      << " (the prediction's error margin, --energy-margin) ";
    if (margin_depleted) v << "the battery reaches its cut-off";
    else v << "only " << 100.0 * out.usable_left_end_with_margin << " %";
    v << ". Shorten the mission, or calibrate the model on your own logs (wattswath calibrate).";
  } else {
    v << "Fits: " << lands << " " << 100.0 * out.usable_left_end << " % of the usable charge (reserve "
      << 100.0 * out.reserve_fraction << " %), " << 100.0 * out.usable_left_end_with_margin << " %" << with_margin
      << " for the prediction's error.";
  }
  return v.str();
}

void batteryAlong(const energy::Battery& b, const std::vector<energy::PowerStep>& profile, double reserve, double margin,
                  bool ends_in_air, BatteryPrediction& out) {
  const energy::EnduranceResult r = discharge(b, profile, 1.0);
  out.known = true;
  out.ends_in_air = ends_in_air;
  out.reserve_fraction = reserve;
  for (const auto& smp : r.series) {
    out.t_s.push_back(smp.t);
    out.usable_left.push_back(energy::countedUsableLeft(b, smp));
    out.voltage_v.push_back(smp.voltage_v);
  }
  out.depleted = r.depleted;
  out.depleted_at_s = r.depleted ? r.endurance_s : 0.0;
  out.usable_left_end = usableLeft(b, r);
  out.fits = !r.depleted && out.usable_left_end >= reserve;
  out.energy_margin = margin;
  const energy::EnduranceResult rm = margin > 0.0 ? discharge(b, profile, 1.0 + margin) : r;
  out.usable_left_end_with_margin = usableLeft(b, rm);
  out.fits_with_margin = !rm.depleted && out.usable_left_end_with_margin >= reserve;
  out.verdict = verdictText(out, r.endurance_s, rm.depleted);
}

// [m] Distance of `p` from the segment from `a` to `b`.
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double len2 = d.squaredNorm();
  const double u = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + u * d)).norm();
}

// A warning when spline waypoints take the flight well off the straight lines between waypoints
// (what a ground station's mission distance counts): how far, before which item, and how much
// longer the curves are.
std::string splineSwing(const Mission& m, const std::vector<NavStep>& steps, const FlownMission& f) {
  double worst = 0.0, curves = 0.0, chords = 0.0;
  int worst_item = -1;
  Eigen::Vector3d from = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const NavStep& st = steps[k];
    if (st.kind == NavStep::Kind::SplineWaypoint && st.has_position) {
      chords += (st.target - from).norm();
      const FlightSample* prev = nullptr;
      for (const FlightSample& s : f.samples) {
        if (s.step != static_cast<int>(k)) continue;
        const double d = distanceToSegment(s.position, from, st.target);
        if (d > worst) worst = d, worst_item = st.item;
        if (prev) curves += (s.position - prev->position).norm();
        prev = &s;
      }
    }
    if (st.kind == NavStep::Kind::Takeoff) from = {from.x(), from.y(), st.target.z()};
    else if (st.has_position && (isFlownTo(st) || st.kind == NavStep::Kind::Land)) from = st.target;
  }
  if (worst < 1.0 || worst_item < 0) return {};
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(1);
  os << m.items[worst_item].where << ": spline waypoints: the flight swings up to " << worst
     << " m off the straight line between waypoints (the most on the way to this item) and its curves are about " << std::max(0.0, curves - chords)
     << " m longer than the straight lines a ground station's mission distance counts: check the curves against obstacles "
        "and no-fly zones (--report draws them)";
  return os.str();
}

// `model` with its drag taken at air speed in `wind` [m/s] (the wind effect, which replaces
// parasitic_drag with the same drag area); what it cannot take is said in `notes`.
energy::EnergyModel inWind(const energy::EnergyModel& model, const energy::Vehicle& v, const Eigen::Vector2d& wind,
                           std::vector<std::string>& notes) {
  energy::EnergyModel out = energy::withWind(model, v, wind.x(), wind.y());
  if (!out.has("wind")) {
    notes.push_back("the energy model has no drag effect (parasitic_drag or wind): the wind changes how the vehicle flies, "
                    "not the power it draws");
  }
  if (out.has("translational_lift")) {
    notes.push_back("translational lift is taken at ground speed: in wind the rotors see the air speed, which the model "
                    "does not use there");
  }
  return out;
}

// PX4's MissionBase::on_active moves past a reached item only when its autocontinue is set; at the
// first item without it the vehicle holds until the pilot moves it on. The mission up to that item
// (it included) when one is not the last, with `note` saying so; nullopt when every item continues.
std::optional<Mission> px4StopsAt(const Mission& m, std::string& note) {
  const auto stop = std::find_if(m.items.begin(), m.items.end(), [](const MissionItem& it) { return !it.autocontinue; });
  if (stop == m.items.end()) return std::nullopt;
  const auto after = static_cast<std::size_t>(std::distance(stop, m.items.end())) - 1;
  note = stop->where + ": autoContinue is false: PX4 stops at this item and waits for the pilot (MissionBase::on_active "
         "moves on only when it is set), so the prediction ends there, in the air" +
         (after > 0 ? "; the " + std::to_string(after) + " item(s) after it are not flown" : std::string()) +
         " (QGC .plan \"autoContinue\", the 12th .waypoints column)";
  if (after == 0) return std::nullopt;
  Mission cut = m;
  cut.items.erase(cut.items.begin() + std::distance(m.items.begin(), stop) + 1, cut.items.end());
  return cut;
}

// A note when the `.plan` says it was written for another firmware (firmwareType) or for a vehicle
// that is not a multicopter (vehicleType) than the one predicted: QGroundControl writes a mission
// for the firmware and vehicle it was connected to or set for, and the prediction flies it as the
// vehicle file's autopilot does. Files that do not say (WPL, firmwareType 0) get no note.
void writtenForNotes(const Mission& m, const AutopilotConfig& a, std::vector<std::string>& notes) {
  const bool px4 = a.family == AutopilotFamily::PX4;
  const bool for_px4 = m.firmware_type == static_cast<int>(Firmware::PX4);
  const char* written = m.firmware_type == static_cast<int>(Firmware::ArduPilot) ? "ArduPilot" : for_px4 ? "PX4" : nullptr;
  if (written != nullptr && for_px4 != px4) {
    notes.push_back(m.source + ": the .plan was written for " + written + " (firmwareType " +
                    std::to_string(m.firmware_type) + ") and is predicted as the vehicle's " + a.firmware + " " +
                    a.version + " flies it; items the firmwares read differently (speeds, take-off, loiter and "
                    "landing items) follow " + a.firmware);
  }
  static const int multicopter[] = {0, 2, 3, 4, 13, 14, 15, 29, 35};  // MAV_TYPE: generic and rotary wings
  if (std::find(std::begin(multicopter), std::end(multicopter), m.vehicle_type) != std::end(multicopter)) return;
  const int t = m.vehicle_type;
  const std::string kind = t == 1                 ? "a fixed-wing aircraft"
                           : (t >= 19 && t <= 25) ? "a VTOL aircraft"
                           : (t == 10 || t == 11) ? "a rover or boat"
                           : t == 12              ? "a submarine"
                                                  : "a vehicle that is not a multicopter";
  notes.push_back(m.source + ": the .plan was written for " + kind + " (vehicleType " + std::to_string(t) +
                  "); it is predicted as the vehicle file's multicopter flies it");
}

// A note when DO_CHANGE_SPEED asks for more horizontal speed than the vehicle file's max_speed_mps:
// the autopilots take it (ArduCopter's AC_WPNav::set_speed_xy has no upper bound; PX4 caps at
// MPC_XY_VEL_MAX), so it is flown, and the note says how fast the flight went.
std::string fasterThanVehicle(const Mission& m, const energy::Vehicle& v, const FlownMission& f) {
  int count = 0;
  double most = 0.0;
  std::string first;
  for (const MissionItem& it : m.items) {
    const bool horizontal = it.param[0] == 0.0 || it.param[0] == 1.0;
    if (it.command != static_cast<int>(Command::DoChangeSpeed) || !horizontal || !(it.param[1] > v.max_speed_mps)) continue;
    if (count++ == 0) first = it.where;
    most = std::max(most, it.param[1]);
  }
  if (count == 0) return {};
  double flown = 0.0;
  for (const FlightSample& s : f.samples) flown = std::max(flown, std::hypot(s.velocity.x(), s.velocity.y()));
  std::ostringstream os;
  os.precision(3);
  os << first << ": DO_CHANGE_SPEED asks for up to " << most << " m/s (" << count << " item(s)), above the vehicle file's "
     << "max_speed_mps " << v.max_speed_mps << " m/s; the autopilot takes the speed, so the prediction flies it, as fast "
     << "as the airframe allows: up to " << flown << " m/s over the ground. Check the vehicle can fly that fast";
  return os.str();
}

// The MAV_CMD numbers PX4's mission feasibility check accepts (FeasibilityChecker::
// checkMissionItemValidity, PX4 main of 2025, 1.15 era): a mission holding any other is rejected
// whole ("Mission rejected: item N: unsupported cmd: C"). Older versions' lists differ.
bool px4Accepts(int command) {
  static const int accepted[] = {0,    16,   17,   19,   20,  21,  22,  31,   84,   85,   93,   4501, 42600, 211,
                                 177,  178,  179,  189,  2003, 203, 2000, 2001, 2500, 2501, 200,  204,  205,   1000,
                                 1001, 187,  201,  195,  196,  197, 206, 260, 214,  530,  531,  532,  3000};
  return std::find(std::begin(accepted), std::end(accepted), command) != std::end(accepted);
}

// A note naming the items PX4's feasibility check would reject the mission for.
std::string px4Rejects(const Mission& m) {
  int count = 0;
  std::string first;
  for (const MissionItem& it : m.items) {
    if (px4Accepts(it.command)) continue;
    if (count++ == 0) first = it.where + " (" + commandName(it.command) + ")";
  }
  if (count == 0) return {};
  return first + ": " + std::to_string(count) + " item(s) with commands PX4's mission feasibility check does not list "
         "(FeasibilityChecker::checkMissionItemValidity as of 1.15): such a PX4 rejects the whole mission (\"Mission "
         "rejected: item N: unsupported cmd\"); older versions' lists differ. The prediction flies it as if accepted";
}

// The frames PX4 takes an item in at upload (MavlinkMissionManager::parse_mavlink_mission_item): a
// position only in MAV_FRAME_GLOBAL (0) or GLOBAL_RELATIVE_ALT (3), or their _INT variants (5, 6) in
// an INT upload, as QGroundControl's is; a command without a position only in MAV_FRAME_MISSION (2),
// except the region of interest at a location (DO_SET_ROI_LOCATION, DO_SET_ROI), read in a global
// frame. Another frame is answered MAV_MISSION_UNSUPPORTED_FRAME (10, 11: terrain), a known frame
// with a command it does not take there MAV_MISSION_UNSUPPORTED, and nothing of the upload is kept.
// Empty when PX4 takes `it`, else what it answers and why.
std::string px4FrameRefusal(const MissionItem& it) {
  const int f = it.frame;
  const bool global = f == 0 || f == 3 || f == 5 || f == 6;
  const bool roi = it.command == 195 || it.command == static_cast<int>(Command::DoSetRoi);  // DO_SET_ROI_LOCATION, DO_SET_ROI
  const std::string frame = " in MAV_FRAME " + std::to_string(f);
  if (!global && f != 2) {
    return frame + ": PX4 refuses the upload (MavlinkMissionManager::parse_mavlink_mission_item answers "
           "MAV_MISSION_UNSUPPORTED_FRAME and keeps no item): it takes frames 0 and 3 (5 and 6 in an INT upload) for a "
           "position, and 2 (MAV_FRAME_MISSION) for a command without one" +
           (f == 10 || f == 11 ? std::string("; it has no terrain frame, so write the altitude relative to home (frame 3)") : "");
  }
  if (isPositional(it.command) && !global) {
    return frame + ": PX4 refuses the upload (parse_mavlink_mission_item answers MAV_MISSION_UNSUPPORTED): it takes a "
           "positional command only in frame 0 or 3 (5 or 6 in an INT upload); write the item in frame 3 for a PX4 vehicle";
  }
  if (!isPositional(it.command) && !roi && global) {
    return frame + ": PX4 refuses the upload (parse_mavlink_mission_item answers MAV_MISSION_UNSUPPORTED): it takes a "
           "command without a position only in MAV_FRAME_MISSION (2), where QGroundControl writes it (Mission Planner "
           "often writes frame 3); write the item in frame 2 for a PX4 vehicle";
  }
  return {};
}

// Notes on the take-off and landing rules of PX4's feasibility check (FeasibilityChecker::
// checkTakeoff and checkMissionItemValidity, 1.15): a take-off at or below home, a take-off after an
// item with a position, and a mission that starts with a landing are each rejected.
void px4TakeoffRules(const Mission& m, std::vector<std::string>& notes) {
  const std::string then = ": PX4 rejects such a mission (FeasibilityChecker, 1.15); the prediction flies it as if accepted";
  bool positioned = false;
  for (std::size_t k = 0; k < m.items.size(); ++k) {
    const MissionItem& it = m.items[k];
    if (k == 0 && it.command == static_cast<int>(Command::NavLand)) notes.push_back(it.where + ": the mission starts with a landing" + then);
    if (it.command == static_cast<int>(Command::NavTakeoff)) {
      const double above = detail::altitudeAboveHome(it, m);
      if (!(above > 0.0)) notes.push_back(it.where + ": NAV_TAKEOFF at or below home's altitude (" + detail::numberText(above) + " m)" + then);
      if (positioned) notes.push_back(it.where + ": NAV_TAKEOFF after an item with a position" + then);
    } else if (isNavCommand(it.command) && it.command != static_cast<int>(Command::NavDelay)) {
      positioned = true;
    }
  }
}

// [m] Above this height above home a note asks to check the altitude: 120 m (400 ft) is the usual
// ceiling of open-category drone flight (EU 2019/947, US 14 CFR 107.51).
constexpr double kHighAboveHome = 120.0;

// The heights of the items flown to (waypoints, loiters), checked against home: an item below
// home's height is flown into the ground, an error naming it (a note with `lenient`; PX4's
// FeasibilityChecker::checkIfBelowHomeAltitude warns "Waypoint N below home" and flies it, ArduPilot
// flies it without a word); an item more than kHighAboveHome above home is noted, as is, for PX4,
// an altitude of 0 (PX4 flies to it as written, down to home's height; ArduPilot reads it as the
// previous target's altitude, noted in the flight). Take-off and landing items have their own rules.
void checkHeights(const Mission& m, const AutopilotConfig& a, bool lenient, std::vector<std::string>& notes) {
  const bool px4 = a.family == AutopilotFamily::PX4;
  int high = 0;
  std::string high_first;
  double highest = 0.0;
  for (const MissionItem& it : m.items) {
    const auto cmd = static_cast<Command>(it.command);
    if (!isPositional(it.command) || cmd == Command::NavTakeoff || cmd == Command::NavLand) continue;
    // ArduPilot reads an altitude of 0 as the previous target's (ModeAuto::loc_from_cmd), in any frame.
    if (it.alt_m == 0.0 && !px4) continue;
    const double above = detail::altitudeAboveHome(it, m);
    const std::string height = commandName(it.command) + " at " + detail::numberText(above) + " m above home (altitude " +
                               detail::numberText(it.alt_m) + " m in MAV_FRAME " + std::to_string(it.frame) +
                               (it.frame == 0 || it.frame == 5 ? ", home at " + detail::numberText(m.home.alt_m) + " m" : "") + ")";
    if (above < 0.0) {
      const std::string what = it.where + ": " + height + ", expected at or above home's height: the vehicle would fly "
                               "into the ground (PX4's mission check warns \"Waypoint below home\" and flies it, "
                               "ArduPilot flies it without a word)";
      if (!lenient) throw MissionError(what + "; correct the altitude or its frame, or use --lenient to predict it as written");
      notes.push_back(what + "; predicted as written (--lenient)");
    } else if (px4 && it.alt_m == 0.0 && it.frame != 0 && it.frame != 5) {
      notes.push_back(it.where + ": " + commandName(it.command) + " at altitude 0 above home: PX4 flies to it as written, "
                      "down to home's height (FeasibilityChecker does not warn, as it is not below home), where ArduPilot "
                      "keeps the previous target's altitude; the prediction flies it as PX4 does");
    }
    if (above > kHighAboveHome) {
      if (high++ == 0) high_first = it.where + ": " + height;
      highest = std::max(highest, above);
    }
  }
  if (high > 0) {
    notes.push_back(high_first + ": " + std::to_string(high) + " item(s) more than " + detail::numberText(kHighAboveHome) +
                    " m above home, up to " + detail::numberText(std::round(highest)) + " m: above the usual ceiling of "
                    "open-category drone flight (120 m); check the altitudes, their frame (0: above sea level) and home's "
                    "altitude");
  }
}

// The note on a take-off the prediction added (the mission does not start with one), as the
// vehicle's autopilot starts such a mission on the ground: ArduCopter refuses it ("Auto: Missing
// Takeoff Cmd", ModeAuto::init), so the prediction assumes it started in the air; PX4 takes off
// vertically to the first item's altitude (Mission::do_need_vertical_takeoff, at least
// MIS_TAKEOFF_ALT above the ground) unless MIS_TKO_LAND_REQ asks for a take-off item.
std::string assumedTakeoffNote(const Mission& m, const NavStep& takeoff, const AutopilotConfig& a) {
  const std::string climb = "a vertical climb to " + detail::num(takeoff.target.z()) + " m" +
                            (takeoff.alt_given ? " (the first item's altitude)" : " (a default: the first item gives no altitude to climb to)");
  if (a.family == AutopilotFamily::PX4) {
    return m.source + ": no NAV_TAKEOFF first: PX4 starts such a mission on the ground with a vertical take-off to the first "
           "item's altitude, at least MIS_TAKEOFF_ALT above the ground (Mission::do_need_vertical_takeoff), unless "
           "MIS_TKO_LAND_REQ requires a take-off item (\"Mission rejected: Takeoff waypoint required\"); the prediction "
           "starts with " + climb;
  }
  return m.source + ": no NAV_TAKEOFF first: ArduCopter will not start such a mission on the ground (\"Auto: Missing "
         "Takeoff Cmd\", ModeAuto::init); the prediction assumes it is started in the air after " + climb;
}

}  // namespace

std::string missionSizeNote(std::size_t items, const AutopilotConfig& autopilot, const std::string& source) {
  if (autopilot.family != AutopilotFamily::PX4 || items <= kPx4MaxMissionItems) return "";
  return source + ": " + std::to_string(items) + " items: PX4 on flight-controller hardware keeps at most " +
         std::to_string(kPx4MaxMissionItems) + " (navigation.h NUM_MISSIONS_SUPPORTED on NuttX, 2000 before 1.13) and "
         "refuses a longer upload; split the mission (plan --sorties) or fly it in parts";
}

MissionPrediction predictMission(const Mission& given, const energy::Vehicle& v, const energy::EnergyModel& model,
                                 const AutopilotConfig& autopilot, const PredictSettings& s) {
  std::string stop_note;
  const std::optional<Mission> cut = autopilot.family == AutopilotFamily::PX4 ? px4StopsAt(given, stop_note) : std::nullopt;
  const Mission& m = cut ? *cut : given;
  if (!(s.reserve_fraction >= 0.0 && s.reserve_fraction <= 0.9)) {
    throw std::invalid_argument("reserve fraction " + std::to_string(s.reserve_fraction) + ", expected 0..0.9");
  }
  if (!(s.energy_margin >= 0.0 && s.energy_margin <= 1.0)) {
    throw std::invalid_argument("energy margin " + std::to_string(s.energy_margin) + ", expected 0..1");
  }
  std::vector<std::string> frame_notes;  // items PX4 refuses for their frame, predicted with --lenient
  // PX4 has no NAV_SPLINE_WAYPOINT: its mission upload answers MAV_MISSION_UNSUPPORTED and keeps
  // nothing (mavlink_mission.cpp, parse_mavlink_mission_item), so such a mission is never flown.
  if (autopilot.family == AutopilotFamily::PX4) {
    for (const MissionItem& it : m.items) {
      if (it.command == static_cast<int>(Command::NavLoiterTurns)) {
        throw MissionError(it.where + ": NAV_LOITER_TURNS (18) is not modelled for a PX4 vehicle (the mission feasibility "
                           "check of some PX4 versions rejects it as \"not yet supported\", and how the others fly it was not "
                           "read); the ArduCopter models fly it (docs/autopilots.md)");
      }
      if (const std::string r = px4FrameRefusal(it); !r.empty()) {
        const std::string what = it.where + ": " + commandName(it.command) + r;
        if (!s.lenient) throw MissionError(what + ", or use --lenient to predict the mission as if accepted");
        frame_notes.push_back(what + "; predicted as if accepted (--lenient)");
      }
      if (it.command != static_cast<int>(Command::NavSplineWaypoint)) continue;
      throw MissionError(it.where + ": NAV_SPLINE_WAYPOINT (82): PX4 refuses a mission that holds one (the upload is answered "
                         "MAV_MISSION_UNSUPPORTED and no item is kept), so it cannot be flown; write NAV_WAYPOINT (16) for a "
                         "PX4 vehicle");
    }
  }
  MissionPrediction p;
  p.warnings = m.warnings;
  writtenForNotes(m, autopilot, p.warnings);
  if (autopilot.version_assumed) {
    p.warnings.push_back("the vehicle file's autopilot object gives no version: flown as " + autopilot.firmware + " " +
                         autopilot.version + " (the " + toString(autopilot.family) + " model); set autopilot.version, "
                         "since ArduCopter before 4.1 flies the leash model and its parameters differ");
  }
  p.warnings.insert(p.warnings.end(), frame_notes.begin(), frame_notes.end());
  if (!stop_note.empty()) p.warnings.push_back(stop_note);
  if (std::string n = missionSizeNote(given.items.size(), autopilot, m.source); !n.empty()) p.warnings.push_back(std::move(n));
  if (autopilot.family != AutopilotFamily::PX4) {
    for (const MissionItem& it : m.items) {
      if (it.autocontinue) continue;
      p.warnings.push_back(it.where + ": autoContinue is false; ArduPilot does not keep it (AP_Mission stores no such "
                           "flag) and flies on past this item, as predicted");
      break;
    }
  }
  if (autopilot.family == AutopilotFamily::PX4) {
    if (const std::string r = px4Rejects(m); !r.empty()) p.warnings.push_back(r);
    px4TakeoffRules(m, p.warnings);
  }
  checkHeights(m, autopilot, s.lenient, p.warnings);
  const std::vector<NavStep> steps = sequenceMission(m, &p.warnings);
  if (steps.front().item < 0) p.warnings.push_back(assumedTakeoffNote(m, steps.front(), autopilot));
  FlightSettings fs = s.flight;
  if (s.airframe_from_vehicle) fs.airframe = airframeOfVehicle(v, v.name);
  fs.airframe.wind = s.wind;
  const bool windy = s.wind.squaredNorm() > 0.0;
  try {
    p.flight = flyMission(steps, autopilot, fs);
  } catch (const MissionError&) {
    throw;
  } catch (const std::runtime_error& e) {  // the flight ran past FlightSettings::max_time_s
    if (!windy) throw;
    std::ostringstream os;
    os.precision(3);
    os << e.what() << " in a wind of " << s.wind.norm()
       << " m/s: the vehicle probably cannot make way against it (its drag at the lean limit caps its air speed); "
          "check the wind and the vehicle's drag";
    throw std::runtime_error(os.str());
  }
  if (windy && autopilot.family == AutopilotFamily::PX4) {
    p.warnings.push_back("the PX4 model flies its trajectory exactly: the wind changes the power it draws, not its speeds "
                         "or times");
  }
  const energy::EnergyModel windy_model = windy ? inWind(model, v, s.wind, p.warnings) : energy::EnergyModel();
  const energy::EnergyModel& model_used = windy ? windy_model : model;
  if (const std::string swing = splineSwing(m, steps, p.flight); !swing.empty()) p.warnings.push_back(swing);
  if (const std::string fast = fasterThanVehicle(m, v, p.flight); !fast.empty()) p.warnings.push_back(fast);
  p.pieces = toPieces(p.flight);
  p.breakdown = model_used.emptyBreakdown();
  p.piece_energy_j.resize(p.pieces.pieces.size());
  p.items.resize(steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    ItemPrediction& it = p.items[k];
    it.step = static_cast<int>(k);
    it.item = steps[k].item;
    it.seq = it.item >= 0 ? m.items[it.item].seq : -1;
    it.command = it.item >= 0 ? commandName(m.items[it.item].command) : "NAV_TAKEOFF (assumed)";
    it.reached_s = p.flight.events[k].reached_s;
    it.completed_s = p.flight.events[k].completed_s;
  }
  for (std::size_t i = 0; i < p.pieces.pieces.size(); ++i) {
    const std::vector<energy::Piece> one{p.pieces.pieces[i]};
    model_used.accumulate(one, p.breakdown);
    const double e = model_used.energy(one);
    p.piece_energy_j[i] = e;
    const energy::Piece& pc = p.pieces.pieces[i];
    for (Totals* t : {&p.total, &p.phases[static_cast<int>(p.pieces.phase[i])],
                      &p.items[std::clamp(p.pieces.step[i], 0, static_cast<int>(steps.size()) - 1)].totals}) {
      t->energy_j += e;
      t->time_s += pc.duration;
      t->distance_m += pc.length;
    }
  }
  p.breakdown.time = p.total.time_s;
  p.breakdown.length = p.total.distance_m;
  for (const std::string& n : p.flight.notes) p.warnings.push_back(n);
  const bool ends_in_air = !p.flight.samples.empty() && p.flight.samples.back().airborne;
  if (v.battery) batteryAlong(*v.battery, powerProfile(p), s.reserve_fraction, s.energy_margin, ends_in_air, p.battery);
  return p;
}

std::vector<energy::PowerStep> powerProfile(const MissionPrediction& p) {
  std::vector<energy::PowerStep> profile;
  profile.reserve(p.pieces.pieces.size());
  for (std::size_t i = 0; i < p.pieces.pieces.size(); ++i) {
    const double d = p.pieces.pieces[i].duration;
    profile.push_back({d, d > 0.0 ? std::max(0.0, p.piece_energy_j[i] / d) : 0.0});
  }
  return profile;
}

}  // namespace wattswath::mission
