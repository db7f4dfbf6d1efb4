// The mission as the autopilot executes it: DO commands applied where AP_Mission runs them (a DO
// command between two navigation items takes effect when the first is complete, so it governs
// the leg into the second), DO_JUMP unrolled, positions in the local ENU frame of home.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "flight_internal.hpp"
#include "wattswath/mission/flight.hpp"

namespace wattswath::mission {
namespace {
using detail::altitudeAboveHome;


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
  // ArduCopter 3.x's rule (Copter::do_change_speed up to 3.6): any speed > 0 is the horizontal speed,
  // whatever the type; the type check came with ArduPilot PR 9535 (October 2018, in 4.0).
  double speed_xy_3x = 0.0;
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
  int aux_noted = 0;           // DO_AUX_FUNCTION items run (the first is noted)
  std::set<int> terrain_items;  // positional items flown with altitudes above terrain (frame 10 or 11)
  std::string terrain_first;    // the first of them, for the note

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
    // PX4 resets its cruise speed on any speed <= 0 (reset_cruising_speed()); ArduCopter's
    // ModeAuto::do_change_speed acts only on a speed > 0, so -1 (no change) and -2 (the default:
    // MAVLink's meaning) leave its speed as it was.
    if (isSpeedSentinel(v)) speed_xy_px4 = 0.0;
    if (v == -2.0) {
      warn(it.where + ": DO_CHANGE_SPEED -2 (the default speed): PX4 returns to its default cruise speed; ArduCopter acts "
           "only on a speed > 0 and keeps the speed it has");
    }
    if (isSpeedSentinel(v) || std::isnan(v)) return;
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument(it.where + ": DO_CHANGE_SPEED speed (param2) = " + std::to_string(v) +
                                  " m/s, expected > 0 (or -1 for no change, -2 for the default speed)");
    }
    speed_xy_px4 = v;
    speed_xy_3x = v;
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
    s.speed_xy_3x = speed_xy_3x;
    s.speed_up = speed_up;
    s.speed_down = speed_down;
    s.speed_xy_41 = speed_xy_41;
    s.speed_up_41 = speed_up_41;
    s.speed_down_41 = speed_down_41;
    return s;
  }

  // The step of kind `kind` for positional item `index`: its position, or only its altitude when
  // latitude and longitude are 0 ("here"), and whether its altitude was given.
  NavStep placed(NavStep::Kind kind, int index) const {
    const MissionItem& it = m.items[index];
    NavStep s = step(kind, index);
    s.has_position = hasLatLon(it);
    if (s.has_position) s.target = position(it);
    else s.target.z() = altitudeAboveHome(it, m);
    s.alt_given = it.alt_m != 0.0;
    return s;
  }

  // Adds the step of navigation item `index`; returns false when the mission ends there.
  bool nav(int index) {
    const MissionItem& it = m.items[index];
    switch (static_cast<Command>(it.command)) {
      case Command::NavTakeoff: {
        NavStep s = step(NavStep::Kind::Takeoff, index);
        s.target = {0.0, 0.0, altitudeAboveHome(it, m)};
        if (hasLatLon(it)) s.takeoff_xy = position(it).head<2>();
        steps.push_back(s);
        return true;
      }
      case Command::NavWaypoint:
      case Command::NavSplineWaypoint:
      case Command::NavLoiterTime: {
        const bool loiter = it.command == static_cast<int>(Command::NavLoiterTime);
        NavStep s = placed(loiter ? NavStep::Kind::LoiterTime
                                  : (it.command == static_cast<int>(Command::NavSplineWaypoint) ? NavStep::Kind::SplineWaypoint
                                                                                                 : NavStep::Kind::Waypoint),
                           index);
        s.hold_s = std::isfinite(it.param[0]) ? std::max(0.0, it.param[0]) : 0.0;
        if (!loiter && std::isfinite(it.param[1])) s.accept_radius_m = std::max(0.0, it.param[1]);
        steps.push_back(s);
        return true;
      }
      case Command::NavLoiterTurns: {
        // AP_Mission (mavlink_int_to_mission_cmd) keeps min(255, param1) turns and |param3| metres
        // as whole numbers (the conversions truncate); param3 < 0 circles counter-clockwise.
        NavStep s = placed(NavStep::Kind::LoiterTurns, index);
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
      case Command::NavLoiterUnlimited: {
        // ModeAuto::do_loiter_unlimited: a stop at the position (the next item is never started),
        // then a loiter until the pilot or a ground station ends it: the flight ends there, in the air.
        NavStep s = placed(NavStep::Kind::Waypoint, index);
        steps.push_back(s);
        warn(it.where + ": NAV_LOITER_UNLIM: the autopilot loiters there until the pilot or a ground station ends it; "
             "the prediction ends on arrival, in the air, and counts no loiter time");
        return false;
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
                                "NAV_SPLINE_WAYPOINT, NAV_LOITER_TIME, NAV_LOITER_TURNS, NAV_LOITER_UNLIM, NAV_DELAY, "
                                "NAV_RETURN_TO_LAUNCH, NAV_LAND)");
  }
};

// The warning for the items after the navigation item `last` that ends the mission, `i` the first.
std::string neverFlown(const Mission& m, int i, const NavStep& last) {
  const std::string what = last.item >= 0 ? commandName(m.items[last.item].command) : "the mission's end";
  std::string w = m.items[i].where + ": items after " + what + " are never flown (" +
                  std::to_string(m.items.size() - i) + " ignored)";
  for (std::size_t k = i; k < m.items.size(); ++k) {
    if (m.items[k].command != static_cast<int>(Command::NavTakeoff)) continue;
    w += "; ArduPilot flies on to the take-off at " + m.items[k].where +
         " only when MIS_OPTIONS asks it to continue after a landing, which the prediction does not model";
    break;
  }
  return w;
}

// NAV_DELAY items before the take-off: AP_Mission::is_takeoff_next skips them when it checks that
// the mission starts with a take-off, and ModeAuto waits them out on the ground, armed at idle
// (nav_delay_run: make_safe_ground_handling). They leave the flight; its times count from the
// take-off, as they count from the throttle-up.
void groundDelays(Sequencer& q) {
  std::size_t n = 0;
  double wait = 0.0;
  while (n < q.steps.size() && q.steps[n].kind == NavStep::Kind::Delay && q.steps[n].item >= 0 &&
         q.m.items[q.steps[n].item].command == static_cast<int>(Command::NavDelay)) {
    wait += q.steps[n].hold_s;
    ++n;
  }
  if (n == 0 || n == q.steps.size() || q.steps[n].kind != NavStep::Kind::Takeoff) return;
  q.warn(q.steps.front().where + ": NAV_DELAY of " + detail::num(wait) + " s before the take-off: ArduCopter waits it out "
         "on the ground, armed at idle, then takes off (AP_Mission::is_takeoff_next skips delays); the prediction starts at "
         "the take-off and leaves the wait out of its time and energy");
  q.steps.erase(q.steps.begin(), q.steps.begin() + static_cast<std::ptrdiff_t>(n));
}

// A mission that does not start with a take-off: a vertical climb to the first item's altitude
// (10 m when it gives none: a landing, a return, an item without an altitude) is put before it, as
// an added step (item -1) whose alt_given says whether the altitude is the first item's. The note
// depends on the autopilot, so predictMission gives it (assumedTakeoffNote).
void assumeTakeoff(Sequencer& q) {
  const NavStep& first = q.steps.front();
  const bool positioned = first.kind != NavStep::Kind::Delay && first.kind != NavStep::Kind::Land &&
                          first.kind != NavStep::Kind::ReturnToLaunch;
  const bool from_item = positioned && (first.has_position || first.alt_given) && first.target.z() > 0.0;
  NavStep t = first;
  t.kind = NavStep::Kind::Takeoff;
  t.target = {0.0, 0.0, from_item ? first.target.z() : 10.0};
  t.alt_given = from_item;
  t.hold_s = 0.0;
  t.item = -1;
  t.where.clear();
  q.steps.insert(q.steps.begin(), t);
}
}  // namespace

namespace detail {

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

}  // namespace detail

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
    if (it.command == static_cast<int>(Command::DoAuxFunction) && q.aux_noted++ == 0) {
      q.warn(it.where + ": DO_AUX_FUNCTION " + detail::num(it.param[0]) + " runs an auxiliary switch function, which can "
             "be anything from a relay to a mode change; the prediction assumes it does not change the flight");
    }
    if (isPositional(it.command) && (it.frame == 10 || it.frame == 11)) {
      if (q.terrain_items.empty()) q.terrain_first = it.where;
      q.terrain_items.insert(i);  // an item a DO_JUMP repeats counts once
    }
    if (isNavCommand(it.command)) {
      q.navStarts(kindOf(it));
      ended = !q.nav(i);
    } else {
      q.doItem(it);
    }
    ++i;
  }
  if (ended && i < static_cast<int>(m.items.size())) q.warn(neverFlown(m, i, q.steps.back()));
  if (!q.terrain_items.empty()) {
    q.warn(q.terrain_first + ": " + std::to_string(q.terrain_items.size()) + " item(s) give altitudes above terrain (MAV_FRAME 10/11); "
           "without terrain data the prediction flies them over flat ground at home's height, as heights above home");
  }
  if (q.steps.empty()) throw std::invalid_argument(m.source + ": the mission has no navigation item to fly");
  groundDelays(q);
  if (q.steps.front().kind != NavStep::Kind::Takeoff) assumeTakeoff(q);
  else if (q.steps.front().target.z() < 1.0) {
    q.warn(q.steps.front().where + ": NAV_TAKEOFF to " + detail::num(q.steps.front().target.z()) +
           " m above home: ArduCopter climbs at least 1 m above where it lifts off (ModeAuto::takeoff_start), and so does "
           "the prediction");
  }
  const NavStep::Kind last = q.steps.back().kind;
  const bool loiters = q.steps.back().item >= 0 &&
                       m.items[q.steps.back().item].command == static_cast<int>(Command::NavLoiterUnlimited);
  if (last != NavStep::Kind::ReturnToLaunch && last != NavStep::Kind::Land && !loiters) {
    q.warn(m.source + ": the mission does not end with NAV_RETURN_TO_LAUNCH or NAV_LAND: the vehicle hovers at the "
           "last item and the prediction ends there, in the air");
  }
  return q.steps;
}

}  // namespace wattswath::mission
