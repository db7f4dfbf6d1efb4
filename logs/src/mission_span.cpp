// The part of an autopilot log that flew a mission: from the switch into the mission mode to the
// landing (autopilot_log.hpp, missionSpan).
#include <cstdio>
#include <limits>
#include <string>

#include "wattswath/logs/autopilot_log.hpp"

namespace wattswath::logs {
namespace {

// True for the mode in which an autopilot flies its mission, as the readers name it: ArduPilot
// "AUTO (3)", PX4 "AUTO_MISSION (3)" or "AUTO_TAKEOFF (17)".
bool missionMode(const std::string& text) {
  return text.rfind("AUTO (", 0) == 0 || text.rfind("AUTO_MISSION", 0) == 0 || text.rfind("AUTO_TAKEOFF", 0) == 0;
}

constexpr double kLandCompleteWithin = 5.0;  // [s] LAND_COMPLETE after the airborne window's end, at most

std::string at(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f s", t);
  return b;
}

}  // namespace

std::optional<MissionSpan> missionSpan(const FlightLog& log) {
  if (log.format != "dataflash" && log.format != "ulog") return std::nullopt;
  const LogEvent* start = nullptr;
  for (const auto& e : log.events) {
    if (e.kind == "mode" && missionMode(e.text)) {
      start = &e;
      break;
    }
  }
  if (start == nullptr) return std::nullopt;
  MissionSpan s;
  s.from_s = start->t;
  s.from_what = "the switch to " + start->text + " at " + at(start->t);
  s.liftoff_s = std::numeric_limits<double>::quiet_NaN();
  bool found = false;
  for (const auto& w : log.airborne) {
    if (w.end <= start->t) continue;
    if (!found) {
      if (w.begin < start->t) s.started_airborne = true;
      else s.liftoff_s = w.begin;
    }
    found = true;
    s.to_s = w.end;
  }
  if (!found) return std::nullopt;
  s.to_what = "the landing at " + at(s.to_s);
  // ArduCopter: the airborne window ends at the first landed event, LAND_COMPLETE_MAYBE; the
  // landing a prediction counts (its land detector) is LAND_COMPLETE, logged after it.
  for (const auto& e : log.events) {
    if (e.kind == "event" && e.text == "EV 18 LAND_COMPLETE" && e.t >= s.to_s && e.t <= s.to_s + kLandCompleteWithin) {
      s.to_what = "LAND_COMPLETE at " + at(e.t);
      s.to_s = e.t;
      break;
    }
  }
  return s;
}

MissionCut cutToMission(FlightLog& log) {
  MissionCut c;
  if (log.format != "dataflash" && log.format != "ulog") return c;
  if (log.metadata.count("window") != 0) return c;  // already cut where the user asked
  const std::string other = " (--from / --to / --airborne choose another part)";
  if (const auto span = missionSpan(log)) {
    LogReadOptions cut;
    cut.from_s = span->from_s;
    cut.to_s = span->to_s;
    applyTimeWindow(log, cut);
    c.from_s = span->from_s;
    c.to_s = span->to_s;
    c.source = span->started_airborne ? "mission mode, started in the air" : "mission mode to landing";
    c.note = log.source + ": compared from " + span->from_what + " to " + span->to_what +
             (span->started_airborne ? "; the mission was started in the air, so the predicted take-off climb is not in this part" : "") +
             other;
  } else if (!log.airborne.empty()) {
    c.from_s = log.airborne.front().begin;
    c.to_s = log.airborne.back().end;
    LogReadOptions cut;
    cut.airborne_only = true;
    applyTimeWindow(log, cut);
    c.source = "airborne part";
    c.note = log.source + ": no switch into the mission mode (AUTO / AUTO_MISSION) is logged: compared over the airborne part, " +
             log.metadata["window"] + ", so a fitted take-off delay counts from lift-off" + other;
  } else {
    c.from_s = log.samples.front().t;
    c.to_s = log.samples.back().t;
    c.source = "whole log";
    c.note = log.source + ": neither a switch into the mission mode nor an airborne part is logged: the whole log is compared, as "
                          "if it began with the take-off command" + other;
  }
  return c;
}

}  // namespace wattswath::logs
