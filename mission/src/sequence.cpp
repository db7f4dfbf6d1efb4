// The mission as the autopilot executes it: DO commands applied where AP_Mission runs them (a DO
// command between two navigation items takes effect when the first is complete, so it governs
// the leg into the second), DO_JUMP unrolled, positions in the local ENU frame of home.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

#include "wattswath/mission/flight.hpp"

namespace wattswath::mission {
namespace {

// Altitude above home [m] of an item in its frame.
double altitudeAboveHome(const MissionItem& it, const Mission& m) {
  switch (it.frame) {
    case 0:
    case 5: return it.alt_m - m.home.alt_m;  // MAV_FRAME_GLOBAL(_INT): above mean sea level
    case 3:
    case 6:                                   // relative to home
    case 10:
    case 11: return it.alt_m;                 // above terrain: flat terrain at home's height assumed
    default: break;
  }
  throw std::invalid_argument(it.where + ": " + commandName(it.command) + " in MAV_FRAME " + std::to_string(it.frame) +
                              ", expected 0/5 (absolute), 3/6 (relative) or 10/11 (terrain)");
}

bool hasLatLon(const MissionItem& it) {
  return std::isfinite(it.lat_deg) && std::isfinite(it.lon_deg) && !(it.lat_deg == 0.0 && it.lon_deg == 0.0);
}

// The kind of step navigation item `it` becomes, as far as the waypoint controller is concerned:
// a LAND without a position descends at once (no waypoint), so it counts as a delay here.
NavStep::Kind kindOf(const MissionItem& it) {
  switch (static_cast<Command>(it.command)) {
    case Command::NavTakeoff: return NavStep::Kind::Takeoff;
    case Command::NavSplineWaypoint: return NavStep::Kind::SplineWaypoint;
    case Command::NavLoiterTime: return NavStep::Kind::LoiterTime;
    case Command::NavLoiterTurns: return NavStep::Kind::LoiterTurns;
    case Command::NavDelay: return NavStep::Kind::Delay;
    case Command::NavReturnToLaunch: return NavStep::Kind::ReturnToLaunch;
    case Command::NavLand: return hasLatLon(it) ? NavStep::Kind::Land : NavStep::Kind::Delay;
    default: return NavStep::Kind::Waypoint;
  }
}

struct Sequencer {
  Sequencer(const Mission& mission, std::vector<std::string>* w) : m(mission), frame(mission.home), warnings(w) {}
  const Mission& m;
  geometry::LocalFrame frame;
  std::vector<std::string>* warnings;
  std::vector<NavStep> steps;
  double speed_xy = 0.0, speed_up = 0.0, speed_down = 0.0;
  // PX4's rule (Navigator's VEHICLE_CMD_DO_CHANGE_SPEED): param2 > 0 is the cruise speed whatever
  // the speed type in param1, anything else returns to the default.
  double speed_xy_px4 = 0.0;
  // ArduCopter 4.1-4.4 (ArduPilot issue 21080): after a take-off or a circle the waypoint controller
  // is idle, and the next wp_start re-initialises it at the default speeds. Of the DO items before
  // that waypoint, AP_Mission runs the first as the previous navigation item completes (before
  // wp_start: its speed change is lost) and the others one per loop after the waypoint started.
  double speed_xy_41 = 0.0, speed_up_41 = 0.0, speed_down_41 = 0.0;
  bool controller_idle = true;  // no waypoint flown since the take-off or the last circle
  int section_dos = 0;          // DO items since the last navigation item
  struct Pending {
    int type;
    double v;
    bool kept;  // run after the waypoint started: not the first DO item of the last section
  };
  std::vector<Pending> pending;  // speed changes while the controller is idle

  bool section_waits = false;  // a CONDITION_DELAY or CONDITION_DISTANCE since the last navigation item

  // A DO (or CONDITION) item run: counts it in its section.
  void doItem(const MissionItem& it) {
    ++section_dos;
    if (it.command == static_cast<int>(Command::ConditionDelay) || it.command == static_cast<int>(Command::ConditionDistance))
      section_waits = true;
  }

  // The speeds of the 4.1-4.4 rule: `type` 2 climb, 3 descent, else horizontal.
  void set41(int type, double v) {
    if (type == 2) speed_up_41 = v;
    else if (type == 3) speed_down_41 = v;
    else speed_xy_41 = v;
  }

  // Navigation item of kind `kind` starts: a waypoint after an idle controller restarts it at the
  // defaults and keeps only the changes run after it started.
  void navStarts(NavStep::Kind kind) {
    const bool restarts = kind == NavStep::Kind::Waypoint || kind == NavStep::Kind::SplineWaypoint ||
                          kind == NavStep::Kind::LoiterTime || kind == NavStep::Kind::Land;
    if (controller_idle && restarts) {
      speed_xy_41 = speed_up_41 = speed_down_41 = 0.0;
      for (const Pending& c : pending)
        if (c.kept) set41(c.type, c.v);
      pending.clear();
      controller_idle = false;
    } else {
      for (Pending& c : pending) c.kept = false;  // run before a later restart: lost
    }
    if (kind == NavStep::Kind::Takeoff || kind == NavStep::Kind::LoiterTurns) controller_idle = true;
    section_dos = 0;
    section_waits = false;
  }

  void warn(const std::string& w) {
    if (warnings) warnings->push_back(w);
  }

  Eigen::Vector3d position(const MissionItem& it) const {
    const geometry::Point p = frame.toLocal(it.lat_deg, it.lon_deg);
    return {p.x(), p.y(), altitudeAboveHome(it, m)};
  }

  void changeSpeed(const MissionItem& it) {
    const double v = it.param[1];
    const int type = static_cast<int>(it.param[0]);
    if (v == -1.0) speed_xy_px4 = 0.0;  // PX4: reset_cruising_speed()
    if (v == -1.0 || std::isnan(v)) return;  // ArduPilot: "no change"
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument(it.where + ": DO_CHANGE_SPEED speed (param2) = " + std::to_string(v) +
                                  " m/s, expected > 0 (or -1 for no change)");
    }
    speed_xy_px4 = v;
    if (type == 2) speed_up = v;
    else if (type == 3) speed_down = v;
    else speed_xy = v;
    set41(type, v);
    if (controller_idle) pending.push_back({type, v, section_dos > 0});
    if (section_waits) {
      warn(it.where + ": DO_CHANGE_SPEED after a CONDITION_DELAY or CONDITION_DISTANCE: ArduPilot runs it only once "
           "that condition is met, and drops it if the next waypoint is reached first; the prediction applies it "
           "from the next waypoint on, as if the condition were met at once");
    }
  }

  NavStep step(NavStep::Kind kind, int index) const {
    NavStep s;
    s.kind = kind;
    s.item = index;
    if (index >= 0 && index < static_cast<int>(m.items.size())) s.where = m.items[index].where;
    s.speed_xy = speed_xy;
    s.speed_xy_px4 = speed_xy_px4;
    s.speed_up = speed_up;
    s.speed_down = speed_down;
    s.speed_xy_41 = speed_xy_41;
    s.speed_up_41 = speed_up_41;
    s.speed_down_41 = speed_down_41;
    return s;
  }

  // Adds the step of navigation item `index`; returns false when the mission ends there.
  bool nav(int index) {
    const MissionItem& it = m.items[index];
    switch (static_cast<Command>(it.command)) {
      case Command::NavTakeoff: {
        NavStep s = step(NavStep::Kind::Takeoff, index);
        s.target = {0.0, 0.0, altitudeAboveHome(it, m)};
        steps.push_back(s);
        return true;
      }
      case Command::NavWaypoint:
      case Command::NavSplineWaypoint:
      case Command::NavLoiterTime: {
        const bool loiter = it.command == static_cast<int>(Command::NavLoiterTime);
        NavStep s = step(loiter ? NavStep::Kind::LoiterTime
                                : (it.command == static_cast<int>(Command::NavSplineWaypoint) ? NavStep::Kind::SplineWaypoint
                                                                                               : NavStep::Kind::Waypoint),
                         index);
        s.has_position = hasLatLon(it);
        if (s.has_position) s.target = position(it);
        else s.target.z() = altitudeAboveHome(it, m);
        s.alt_given = it.alt_m != 0.0;
        s.hold_s = std::isfinite(it.param[0]) ? std::max(0.0, it.param[0]) : 0.0;
        if (!loiter && std::isfinite(it.param[1])) s.accept_radius_m = std::max(0.0, it.param[1]);
        steps.push_back(s);
        return true;
      }
      case Command::NavLoiterTurns: {
        // AP_Mission (mavlink_int_to_mission_cmd) keeps min(255, param1) turns and |param3| metres
        // as whole numbers (the conversions truncate); param3 < 0 circles counter-clockwise.
        NavStep s = step(NavStep::Kind::LoiterTurns, index);
        s.has_position = hasLatLon(it);
        if (s.has_position) s.target = position(it);
        else s.target.z() = altitudeAboveHome(it, m);
        s.alt_given = it.alt_m != 0.0;
        s.loiter_turns = std::floor(std::min(255.0, std::max(0.0, it.param[0])));
        s.loiter_radius_m = std::floor(std::abs(it.param[2]));
        s.loiter_ccw = it.param[2] < 0.0;
        steps.push_back(s);
        return true;
      }
      case Command::NavDelay: {
        NavStep s = step(NavStep::Kind::Delay, index);
        s.has_position = false;
        s.hold_s = std::isfinite(it.param[0]) ? std::max(0.0, it.param[0]) : 0.0;
        if (!(s.hold_s > 0.0)) {
          // ModeAuto::do_nav_delay: a delay that is not positive waits until the time of day in
          // param2-4 (hour, minute, second UTC), AP::rtc().get_time_utc.
          const auto part = [&](int i) { return std::isfinite(it.param[i]) ? static_cast<int>(std::clamp(it.param[i], -1.0, 99.0)) : 0; };
          char when[16];
          std::snprintf(when, sizeof when, "%02d:%02d:%02d", part(1), part(2), part(3));
          warn(it.where + ": NAV_DELAY of 0 s: ArduPilot takes a delay that is not positive as a wait until the time of day " +
               "in param2-4 (" + when + " UTC), up to a day, which the prediction cannot know; PX4 waits 0 s; the " +
               "prediction takes no delay");
        }
        steps.push_back(s);
        return true;
      }
      case Command::NavReturnToLaunch:
        steps.push_back(step(NavStep::Kind::ReturnToLaunch, index));
        return false;
      case Command::NavLand: {
        NavStep s = step(NavStep::Kind::Land, index);
        s.has_position = hasLatLon(it);
        if (s.has_position) s.target = position(it);
        steps.push_back(s);
        return false;
      }
      default: break;
    }
    throw std::invalid_argument(it.where + ": " + commandName(it.command) +
                                " cannot be flown by the flight model (supported: NAV_TAKEOFF, NAV_WAYPOINT, "
                                "NAV_SPLINE_WAYPOINT, NAV_LOITER_TIME, NAV_LOITER_TURNS, NAV_DELAY, NAV_RETURN_TO_LAUNCH, "
                                "NAV_LAND)");
  }
};

}  // namespace

const char* toString(FlightPhase p) {
  switch (p) {
    case FlightPhase::Takeoff: return "takeoff";
    case FlightPhase::Mission: return "mission";
    case FlightPhase::Return: return "return";
    case FlightPhase::Landing: return "landing";
  }
  return "unknown";
}

bool isFlownTo(const NavStep& s) {
  return s.kind == NavStep::Kind::Waypoint || s.kind == NavStep::Kind::SplineWaypoint || s.kind == NavStep::Kind::LoiterTime;
}

std::vector<NavStep> sequenceMission(const Mission& m, std::vector<std::string>* warnings, std::size_t max_steps) {
  Sequencer q(m, warnings);
  std::map<int, int> seq_to_index, jumps_done;
  for (std::size_t i = 0; i < m.items.size(); ++i) seq_to_index[m.items[i].seq] = static_cast<int>(i);
  int i = 0;
  bool ended = false;
  std::size_t visited = 0;
  while (i < static_cast<int>(m.items.size()) && !ended) {
    if (++visited > max_steps) {
      throw std::invalid_argument(m.source + ": the mission runs more than " + std::to_string(max_steps) +
                                  " items with its DO_JUMPs unrolled; expected a bounded mission");
    }
    const MissionItem& it = m.items[i];
    if (it.command == static_cast<int>(Command::DoJump)) {
      const int target = static_cast<int>(it.param[0]), repeat = static_cast<int>(it.param[1]);
      auto to = seq_to_index.find(target);
      if (to == seq_to_index.end()) {
        throw std::invalid_argument(it.where + ": DO_JUMP to item " + std::to_string(target) + ", which does not exist");
      }
      if (repeat < 0) throw std::invalid_argument(it.where + ": DO_JUMP repeats forever (param2 = -1); expected a count");
      if (jumps_done[i] < repeat) {
        ++jumps_done[i];
        i = to->second;
        continue;
      }
      ++i;
      continue;
    }
    if (it.command == static_cast<int>(Command::DoChangeSpeed)) q.changeSpeed(it);
    if (isNavCommand(it.command)) {
      q.navStarts(kindOf(it));
      ended = !q.nav(i);
    } else {
      q.doItem(it);
    }
    ++i;
  }
  if (ended && i < static_cast<int>(m.items.size())) {
    q.warn(m.items[i].where + ": items after " + commandName(q.steps.back().item >= 0 ? m.items[q.steps.back().item].command : 0) +
           " are never flown (" + std::to_string(m.items.size() - i) + " ignored)");
  }
  if (q.steps.empty()) throw std::invalid_argument(m.source + ": the mission has no navigation item to fly");
  if (q.steps.front().kind != NavStep::Kind::Takeoff) {
    const double z = q.steps.front().has_position ? q.steps.front().target.z() : 10.0;
    NavStep t = q.steps.front();
    t.kind = NavStep::Kind::Takeoff;
    t.target = {0.0, 0.0, z};
    t.hold_s = 0.0;
    t.item = -1;
    q.steps.insert(q.steps.begin(), t);
    q.warn(m.source + ": no NAV_TAKEOFF first: a vertical take-off to " + std::to_string(z) + " m is assumed");
  }
  const NavStep::Kind last = q.steps.back().kind;
  if (last != NavStep::Kind::ReturnToLaunch && last != NavStep::Kind::Land) {
    q.warn(m.source + ": the mission does not end with NAV_RETURN_TO_LAUNCH or NAV_LAND: the vehicle hovers at the "
           "last item and the prediction ends there, in the air");
  }
  return q.steps;
}

}  // namespace wattswath::mission
