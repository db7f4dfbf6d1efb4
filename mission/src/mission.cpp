// The mission item model: command names and classes, frames, and equality.
#include "wattswath/mission/mission.hpp"

#include <cmath>
#include <stdexcept>

namespace wattswath::mission {
namespace {

struct CommandInfo {
  int number;
  const char* name;
  bool supported;
};

// MAV_CMD numbers and names of common.xml; `supported`: accepted by the readers.
constexpr CommandInfo kCommands[] = {
    {16, "NAV_WAYPOINT", true},
    {17, "NAV_LOITER_UNLIM", true},
    {18, "NAV_LOITER_TURNS", true},
    {19, "NAV_LOITER_TIME", true},
    {20, "NAV_RETURN_TO_LAUNCH", true},
    {21, "NAV_LAND", true},
    {22, "NAV_TAKEOFF", true},
    {30, "NAV_CONTINUE_AND_CHANGE_ALT", false},
    {31, "NAV_LOITER_TO_ALT", false},
    {36, "NAV_ARC_WAYPOINT", false},
    {42, "NAV_SCRIPT_TIME", false},
    {43, "NAV_ATTITUDE_TIME", false},
    {82, "NAV_SPLINE_WAYPOINT", true},
    {83, "NAV_ALTITUDE_WAIT", false},
    {84, "NAV_VTOL_TAKEOFF", false},
    {85, "NAV_VTOL_LAND", false},
    {92, "NAV_GUIDED_ENABLE", false},
    {93, "NAV_DELAY", true},
    {94, "NAV_PAYLOAD_PLACE", false},
    {112, "CONDITION_DELAY", true},
    {113, "CONDITION_CHANGE_ALT", false},
    {114, "CONDITION_DISTANCE", true},
    {115, "CONDITION_YAW", true},
    {176, "DO_SET_MODE", false},
    {177, "DO_JUMP", true},
    {178, "DO_CHANGE_SPEED", true},
    {179, "DO_SET_HOME", false},
    {180, "DO_SET_PARAMETER", false},
    {181, "DO_SET_RELAY", true},
    {182, "DO_REPEAT_RELAY", true},
    {183, "DO_SET_SERVO", true},
    {184, "DO_REPEAT_SERVO", true},
    {189, "DO_LAND_START", true},
    {193, "DO_PAUSE_CONTINUE", false},
    {195, "DO_SET_ROI_LOCATION", true},
    {196, "DO_SET_ROI_WPNEXT_OFFSET", true},
    {197, "DO_SET_ROI_NONE", true},
    {198, "DO_SET_ROI_SYSID", true},
    {200, "DO_CONTROL_VIDEO", true},
    {201, "DO_SET_ROI", true},
    {202, "DO_DIGICAM_CONFIGURE", true},
    {203, "DO_DIGICAM_CONTROL", true},
    {204, "DO_MOUNT_CONFIGURE", true},
    {205, "DO_MOUNT_CONTROL", true},
    {206, "DO_SET_CAM_TRIGG_DIST", true},
    {207, "DO_FENCE_ENABLE", true},
    {208, "DO_PARACHUTE", false},
    {211, "DO_GRIPPER", false},
    {214, "DO_SET_CAM_TRIGG_INTERVAL", true},
    {215, "DO_SET_RESUME_REPEAT_DIST", true},
    {216, "DO_SPRAYER", false},
    {217, "DO_SEND_SCRIPT_MESSAGE", false},
    {218, "DO_AUX_FUNCTION", true},
    {222, "DO_GUIDED_LIMITS", false},
    {223, "DO_ENGINE_CONTROL", false},
    {224, "DO_SET_MISSION_CURRENT", false},
    {530, "SET_CAMERA_MODE", true},
    {531, "SET_CAMERA_ZOOM", true},
    {532, "SET_CAMERA_FOCUS", true},
    {1000, "DO_GIMBAL_MANAGER_PITCHYAW", true},
    {1001, "DO_GIMBAL_MANAGER_CONFIGURE", true},
    {2000, "IMAGE_START_CAPTURE", true},
    {2001, "IMAGE_STOP_CAPTURE", true},
    {2500, "VIDEO_START_CAPTURE", true},
    {2501, "VIDEO_STOP_CAPTURE", true},
    {3000, "DO_VTOL_TRANSITION", false},
    {42600, "DO_WINCH", false},
};

const CommandInfo* find(int command) {
  for (const auto& c : kCommands)
    if (c.number == command) return &c;
  return nullptr;
}

bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

}  // namespace

std::string commandName(int command) {
  const CommandInfo* c = find(command);
  return c ? std::string(c->name) : "MAV_CMD " + std::to_string(command);
}

bool isNavCommand(int command) {
  // MAV_CMD_NAV_* are numbered below MAV_CMD_NAV_LAST (95); DO_* and CONDITION_* above.
  return command >= 16 && command < 95;
}

bool isSupportedCommand(int command) {
  const CommandInfo* c = find(command);
  return c && c->supported;
}

bool isPositional(int command) {
  switch (static_cast<Command>(command)) {
    case Command::NavTakeoff:
    case Command::NavWaypoint:
    case Command::NavSplineWaypoint:
    case Command::NavLoiterTime:
    case Command::NavLoiterTurns:
    case Command::NavLoiterUnlimited:
    case Command::NavLand:
      return true;
    default:
      return false;
  }
}

bool hasPosition(const MissionItem& item) {
  return isPositional(item.command) && std::isfinite(item.lat_deg) && std::isfinite(item.lon_deg) &&
         !(item.lat_deg == 0.0 && item.lon_deg == 0.0);
}

AltitudeFrame altitudeFrame(int frame) {
  switch (frame) {
    case 0: case 5: return AltitudeFrame::Absolute;
    case 2: return AltitudeFrame::Mission;
    case 3: case 6: return AltitudeFrame::Relative;
    case 10: case 11: return AltitudeFrame::Terrain;
    default:
      throw std::invalid_argument("MAV_FRAME " + std::to_string(frame) +
                                  " is not a mission frame (expected 0, 2, 3, 5, 6, 10 or 11)");
  }
}

bool operator==(const MissionItem& a, const MissionItem& b) {
  for (int k = 0; k < 4; ++k)
    if (!same(a.param[k], b.param[k])) return false;
  return a.seq == b.seq && a.command == b.command && a.frame == b.frame && same(a.lat_deg, b.lat_deg) &&
         same(a.lon_deg, b.lon_deg) && same(a.alt_m, b.alt_m) && a.autocontinue == b.autocontinue;
}

bool operator!=(const MissionItem& a, const MissionItem& b) { return !(a == b); }

bool operator==(const Mission& a, const Mission& b) {
  return same(a.home.lat_deg, b.home.lat_deg) && same(a.home.lon_deg, b.home.lon_deg) &&
         same(a.home.alt_m, b.home.alt_m) && a.home_known == b.home_known && a.items == b.items &&
         same(a.plan_cruise_speed_mps, b.plan_cruise_speed_mps) &&
         same(a.plan_hover_speed_mps, b.plan_hover_speed_mps) && a.firmware_type == b.firmware_type &&
         a.vehicle_type == b.vehicle_type;
}

bool operator!=(const Mission& a, const Mission& b) { return !(a == b); }

}  // namespace wattswath::mission
