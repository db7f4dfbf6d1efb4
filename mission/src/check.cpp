// Checks of a mission read from a file (commands, frames, fields, distance from home, DO_JUMP) and
// the unrolling of its DO_JUMP loops in ArduPilot's order (AP_Mission::get_next_cmd).
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "files_internal.hpp"
#include "wattswath/geometry/frame.hpp"

namespace wattswath::mission {
namespace detail {

void fail(const std::string& where, const std::string& what) { throw MissionError(where + ": " + what); }

std::string numberText(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string withoutBom(const std::string& text) {
  return text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text;
}

void checkText(const std::string& text, const std::string& source) {
  const auto starts = [&](const char* bom, std::size_t n) { return text.size() >= n && text.compare(0, n, bom, n) == 0; };
  const bool utf32 = starts("\xFF\xFE\x00\x00", 4) || starts("\x00\x00\xFE\xFF", 4);
  const bool utf16 = !utf32 && (starts("\xFF\xFE", 2) || starts("\xFE\xFF", 2) ||
                                (text.size() >= 4 && (text[0] == '\0' || text[1] == '\0') && (text[2] == '\0' || text[3] == '\0')));
  if (utf16 || utf32) {
    fail(source, std::string("the file is ") + (utf32 ? "UTF-32" : "UTF-16") +
                     " text, expected UTF-8 or ASCII (save it as UTF-8: Notepad's \"UTF-8\", iconv -f UTF-16 -t UTF-8)");
  }
  const std::size_t nul = text.find('\0');
  if (nul == std::string::npos) return;
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n'));
  const std::size_t start = text.rfind('\n', nul);
  const std::size_t column = nul - (start == std::string::npos ? 0 : start + 1) + 1;
  fail(source + ":" + std::to_string(line), "a NUL byte at column " + std::to_string(column) +
                                                ", expected text (the file may be binary, truncated or damaged)");
}

std::string printable(const std::string& s, std::size_t most) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < most; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    } else {
      out += s[i];
    }
  }
  if (s.size() > most) out += "...";
  return out;
}

void checkHomePoint(const geometry::GeoPoint& p, const std::string& where) {
  if (!(std::isfinite(p.lat_deg) && p.lat_deg >= -90.0 && p.lat_deg <= 90.0))
    fail(where, "home latitude = " + numberText(p.lat_deg) + ", expected a latitude in [-90, 90] deg");
  if (!(std::isfinite(p.lon_deg) && p.lon_deg >= -180.0 && p.lon_deg <= 180.0))
    fail(where, "home longitude = " + numberText(p.lon_deg) + ", expected a longitude in [-180, 180] deg");
  if (!std::isfinite(p.alt_m)) fail(where, "home altitude = " + numberText(p.alt_m) + ", expected a finite altitude [m AMSL]");
}

}  // namespace detail

namespace {
using detail::fail;
using detail::numberText;

constexpr int kMaxJumpRepeat = 1000;  // DO_JUMP repeat counts accepted, [0, kMaxJumpRepeat]

/// "WHERE: NAV_WAYPOINT FIELD = VALUE, expected EXPECTED"; in a .plan (`plan`) NaN is written as
/// "null (unset)", the JSON null it was read from.
[[noreturn]] void badField(const MissionItem& it, const std::string& field, double v, const std::string& expected, bool plan = false) {
  fail(it.where, commandName(it.command) + " " + field + " = " + (plan && std::isnan(v) ? "null (unset)" : numberText(v)) +
                     ", expected " + expected);
}

void atLeastZero(const MissionItem& it, double v, const std::string& field, const std::string& what, bool plan) {
  if (!(std::isfinite(v) && v >= 0.0)) badField(it, field, v, what, plan);
}

void checkFrame(const MissionItem& it) {
  const int f = it.frame;
  const bool global = f == 0 || f == 3 || f == 10 || f == 5 || f == 6 || f == 11;
  if (isPositional(it.command) && !global) {
    fail(it.where, commandName(it.command) + " frame = " + std::to_string(f) +
                       ", expected a global frame for a position: 0 (absolute), 3 (relative to home), 10 (terrain) "
                       "or their _INT variants 5, 6, 11 (ArduPilot refuses any other with MAV_MISSION_UNSUPPORTED_FRAME)");
  }
  if (!global && f != 2) {
    fail(it.where, commandName(it.command) + " frame = " + std::to_string(f) +
                       ", expected a mission frame: 0, 3, 10 (or 5, 6, 11), or 2 for a command without a position");
  }
}

void checkPosition(const MissionItem& it, bool plan) {
  if (!isPositional(it.command)) return;
  // Take-off and land may leave lat/lon empty (NaN in a .plan) or 0, 0: "where the vehicle is".
  const bool inPlace = it.command == static_cast<int>(Command::NavTakeoff) || it.command == static_cast<int>(Command::NavLand);
  const bool unset = std::isnan(it.lat_deg) && std::isnan(it.lon_deg);
  if (!(inPlace && unset)) {
    if (!(std::isfinite(it.lat_deg) && it.lat_deg >= -90.0 && it.lat_deg <= 90.0))
      badField(it, "latitude", it.lat_deg, "a latitude in [-90, 90] deg", plan);
    if (!(std::isfinite(it.lon_deg) && it.lon_deg >= -180.0 && it.lon_deg <= 180.0))
      badField(it, "longitude", it.lon_deg, "a longitude in [-180, 180] deg", plan);
  }
  if (it.command != static_cast<int>(Command::NavLand) && !std::isfinite(it.alt_m))
    badField(it, "altitude", it.alt_m, "a finite altitude [m]", plan);
}

void checkSpeed(const MissionItem& it, bool plan) {
  const double type = it.param[0], v = it.param[1];
  if (!(type == 0.0 || type == 1.0 || type == 2.0 || type == 3.0))
    badField(it, "param1 (speed type)", type, "0 (airspeed), 1 (ground speed), 2 (climb) or 3 (descent)", plan);
  if (isSpeedSentinel(v)) return;  // MAVLink: no change, or back to the default
  if (!(std::isfinite(v) && v > 0.0)) {
    badField(it, "param2 (speed)", v, "a speed > 0 m/s, -1 for no change or -2 for the default speed", plan);
  }
}

void checkJump(const MissionItem& it, bool plan = false) {
  const double target = it.param[0], repeat = it.param[1];
  if (!(std::isfinite(target) && target >= 1.0 && target == std::floor(target) && target <= 65535.0))
    badField(it, "param1 (target item)", target, "an item number >= 1", plan);
  if (repeat == -1.0)
    badField(it, "param2 (repeat count)", repeat, "a repeat count in [0, 1000] (-1 repeats forever: the mission never ends)", plan);
  if (!(std::isfinite(repeat) && repeat >= 0.0 && repeat <= kMaxJumpRepeat && repeat == std::floor(repeat)))
    badField(it, "param2 (repeat count)", repeat, "a whole repeat count in [0, 1000]", plan);
}

// ArduPilot's AP_Mission keeps a LOITER_TURNS' turns and radius as whole numbers in one byte each
// (radii above 255 m divided by 10, and not in every version): more than 255 turns, or a radius
// below 1 m (0: a turn on the spot, whose behaviour changes between versions) or above 255 m, is
// refused rather than flown by a guess.
void checkLoiterTurns(const MissionItem& it, bool plan) {
  const double turns = it.param[0], radius = it.param[2];
  if (!(std::isfinite(turns) && turns >= 0.0 && turns < 256.0))
    badField(it, "param1 (turns)", turns, "a number of turns in [0, 255] (ArduPilot keeps whole turns in one byte)", plan);
  if (!(std::isfinite(radius) && std::abs(radius) >= 1.0 && std::abs(radius) < 256.0))
    badField(it, "param3 (radius)", radius,
             "a radius of 1 to 255 m, negative for counter-clockwise (0, a turn on the spot, and radii above 255 m, "
             "which ArduPilot stores divided by 10, are not modelled)", plan);
}

void checkParams(const MissionItem& it, bool plan) {
  switch (static_cast<Command>(it.command)) {
    case Command::NavWaypoint:
    case Command::NavSplineWaypoint:
      return atLeastZero(it, it.param[0], "param1 (hold time)", "a hold time >= 0 s", plan);
    case Command::NavLoiterTime:
      return atLeastZero(it, it.param[0], "param1 (loiter time)", "a time >= 0 s", plan);
    case Command::NavLoiterTurns:
      return checkLoiterTurns(it, plan);
    case Command::NavDelay:
      return atLeastZero(it, it.param[0], "param1 (delay)", "a delay >= 0 s (time-of-day delays, param1 = -1, are not supported)", plan);
    case Command::ConditionDelay:
      return atLeastZero(it, it.param[0], "param1 (delay)", "a delay >= 0 s", plan);
    case Command::ConditionYaw:
      if (!std::isfinite(it.param[0])) badField(it, "param1 (angle)", it.param[0], "a heading [deg]", plan);
      return;
    case Command::DoChangeSpeed:
      return checkSpeed(it, plan);
    case Command::DoSetCamTriggDist:
      return atLeastZero(it, it.param[0], "param1 (distance)", "a trigger distance >= 0 m", plan);
    case Command::DoJump:
      return checkJump(it, plan);
    default:
      return;
  }
}

/// Which items the autopilot can reach from the first: each item leads to the next, a DO_JUMP also
/// to its target (the first item numbered that or later), and a NAV_RETURN_TO_LAUNCH, NAV_LAND or
/// NAV_LOITER_UNLIM ends the mission (AP_Mission stops there unless MIS_OPTIONS continues after a
/// landing; a loiter without limit is never complete).
std::vector<bool> reachableItems(const Mission& m) {
  const std::size_t n = m.items.size();
  std::vector<bool> seen(n, false);
  std::vector<std::size_t> todo{0};
  while (!todo.empty()) {
    const std::size_t k = todo.back();
    todo.pop_back();
    if (k >= n || seen[k]) continue;
    seen[k] = true;
    const MissionItem& it = m.items[k];
    const auto cmd = static_cast<Command>(it.command);
    if (cmd == Command::NavReturnToLaunch || cmd == Command::NavLand || cmd == Command::NavLoiterUnlimited) continue;
    todo.push_back(k + 1);
    if (cmd != Command::DoJump || !std::isfinite(it.param[0]) || it.param[1] == 0.0) continue;
    for (std::size_t t = 0; t < n; ++t) {
      if (m.items[t].seq >= it.param[0]) {
        todo.push_back(t);
        break;
      }
    }
  }
  return seen;
}

/// Rejects, or drops with --lenient, the items whose command is not supported. A navigation command
/// moves the vehicle, so it is never skipped; an item the mission never reaches (after its landing
/// or return) is kept unread, as the autopilot never runs it.
void checkCommands(Mission& m, const ReadOptions& o) {
  if (m.items.empty()) fail(m.source, "no mission items, expected at least one");
  const std::vector<bool> reached = reachableItems(m);
  std::vector<MissionItem> kept;
  for (std::size_t k = 0; k < m.items.size(); ++k) {
    MissionItem& it = m.items[k];
    if (isSupportedCommand(it.command) || !reached[k]) {
      kept.push_back(std::move(it));
      continue;
    }
    const std::string what = "command = " + std::to_string(it.command) + " (" + commandName(it.command) +
                             "), expected a supported command (docs/missions.md)";
    if (isNavCommand(it.command)) {
      fail(it.where, what + "; a navigation command moves the vehicle, so the prediction cannot leave it out (not even "
                            "with " + o.lenient_option + "): remove it or replace it with the waypoints it flies");
    }
    if (!o.lenient) fail(it.where, what + "; use " + o.lenient_option + " to skip it");
    m.warnings.push_back(it.where + ": " + what + "; skipped (" + o.lenient_option + ")");
  }
  if (kept.empty())
    fail(m.source, "all " + std::to_string(m.items.size()) + " items have unsupported commands (skipped with " + o.lenient_option + "), "
                   "expected at least one supported item");
  m.items = std::move(kept);
}

// A file without a home (a .waypoints home row or a .plan plannedHomePosition at 0, 0): the first
// position is home, and the warning says to give the launch point (predict --launch) unless given.
void checkHome(Mission& m, const ReadOptions& o) {
  if (m.home_known) return detail::checkHomePoint(m.home, m.source);
  for (const auto& it : m.items) {
    if (!hasPosition(it)) continue;
    m.home = {it.lat_deg, it.lon_deg, 0.0};
    m.warnings.push_back(m.source + ": no home position; the first position (" + it.where + ") is used as home, at altitude 0 m" +
                         (o.distances_from ? std::string()
                                           : ": the autopilot sets home where the vehicle arms, so give that point with "
                                             "predict --launch LAT,LON (or LAT,LON,ALT) for the return and the distances "
                                             "from home to be right"));
    return;
  }
}

void checkDistances(const Mission& m, const ReadOptions& o) {
  bool any = false;
  for (const auto& it : m.items) any = any || hasPosition(it);
  if (!any) return;
  const geometry::GeoPoint from = o.distances_from.value_or(m.home);
  const geometry::LocalFrame frame(from);
  const std::string what = o.distances_from ? "the launch point (" : "home (";
  for (const auto& it : m.items) {
    if (!hasPosition(it)) continue;
    const double d = frame.toLocal(it.lat_deg, it.lon_deg).norm();
    if (d > o.max_distance_m) {
      fail(it.where, commandName(it.command) + " at (" + numberText(it.lat_deg) + ", " + numberText(it.lon_deg) +
                         ") is " + numberText(std::round(d) / 1000.0) + " km from " + what + numberText(from.lat_deg) +
                         ", " + numberText(from.lon_deg) + "), expected at most " + numberText(o.max_distance_m / 1000.0) +
                         " km (ReadOptions::max_distance_m)" +
                         (o.distances_from ? "" : "; when the file's home is a placeholder, give where the vehicle will "
                                                  "arm (predict --launch LAT,LON): the autopilot sets home there"));
    }
  }
}

void validateOptions(const ReadOptions& o) {
  if (!(o.max_distance_m > 0.0 && o.max_distance_m <= 2e7))
    throw std::invalid_argument("ReadOptions::max_distance_m = " + numberText(o.max_distance_m) + ", expected (0, 2e7] m");
  if (!(o.max_unrolled_items >= 1 && o.max_unrolled_items <= 100000000))
    throw std::invalid_argument("ReadOptions::max_unrolled_items = " + std::to_string(o.max_unrolled_items) +
                                ", expected [1, 1e8]");
}

/// Index in m.items where a jump to item `target` lands: the first item numbered `target` or later
/// (later when lenient reading dropped the target itself).
std::size_t jumpIndex(const Mission& m, const MissionItem& jump) {
  const double target = jump.param[0];
  for (std::size_t k = 0; k < m.items.size(); ++k)
    if (m.items[k].seq >= target) return k;
  badField(jump, "param1 (target item)", target,
           "an item of the mission (the last is " + std::to_string(m.items.empty() ? 0 : m.items.back().seq) + ")");
}

[[noreturn]] void tooLong(const Mission& m, std::size_t last_jump, std::size_t limit) {
  const std::string most = ", expected at most " + std::to_string(limit) + " (ReadOptions::max_unrolled_items)";
  if (last_jump >= m.items.size()) fail(m.source, "the mission has more than " + std::to_string(limit) + " items" + most);
  const MissionItem& j = m.items[last_jump];
  fail(j.where, "DO_JUMP to item " + numberText(j.param[0]) + " repeated " + numberText(j.param[1]) +
                    " times: the loops unroll to more than " + std::to_string(limit) + " items" + most +
                    "; lower the repeat counts");
}

}  // namespace

void checkMission(Mission& m, const ReadOptions& o) {
  validateOptions(o);
  checkCommands(m, o);
  for (const auto& it : m.items) {
    checkFrame(it);
    checkPosition(it, m.format == "plan");
    checkParams(it, m.format == "plan");
  }
  checkHome(m, o);
  checkDistances(m, o);
  unrollJumps(m, o);
}

std::vector<MissionItem> unrollJumps(const Mission& m, const ReadOptions& o) {
  validateOptions(o);
  const std::size_t n = m.items.size();
  std::vector<std::size_t> target(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    if (m.items[k].command != static_cast<int>(Command::DoJump)) continue;
    checkJump(m.items[k]);
    target[k] = jumpIndex(m, m.items[k]);
  }
  std::vector<int> runs(n, 0);
  std::vector<MissionItem> out;
  std::size_t last_jump = n;  // the DO_JUMP taken last, named when the loops grow too long
  for (std::size_t k = 0; k < n;) {
    const MissionItem& it = m.items[k];
    if (it.command != static_cast<int>(Command::DoJump)) {
      out.push_back(it);
      ++k;
    } else if (runs[k] < static_cast<int>(it.param[1])) {
      ++runs[k];
      last_jump = k;
      k = target[k];
    } else {
      ++k;
    }
    if (out.size() > o.max_unrolled_items) tooLong(m, last_jump, o.max_unrolled_items);
  }
  return out;
}

}  // namespace wattswath::mission
