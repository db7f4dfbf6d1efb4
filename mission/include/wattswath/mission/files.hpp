#pragma once
/// @file files.hpp
/// Mission files in and out: QGroundControl `.plan` (JSON) and QGC WPL 110 `.waypoints` (Mission
/// Planner, pymavlink, QGroundControl) read into the item model of mission.hpp, checked, and
/// written back. What each reader accepts is listed in docs/missions.md.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "wattswath/mission/mission.hpp"

namespace wattswath::mission {

/// A mission file that cannot be read: the message names the file, the line (`.waypoints`) or
/// item (`.plan`), the field, the value and what was expected.
class MissionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// [-] Most items a written mission may hold after its home: MAVLink's MISSION_COUNT.count and
/// item seq are 16-bit (65,535 at most) and ArduPilot uploads home as item 0.
inline constexpr std::size_t kMaxMissionItems = 65534;

/// Throws std::invalid_argument when `items` (the items after home) exceed kMaxMissionItems,
/// naming the count, the limit and what to change. Every mission writer calls it before writing.
void checkMissionItemCount(std::size_t items);

/// Largest mission file read [B] (read whole; a 65,534-item `.plan` is about 30 MB).
inline constexpr long long kMaxMissionFileBytes = 64LL * 1024 * 1024;

/// How missions are read and checked.
struct ReadOptions {
  bool lenient = false;                      ///< an unsupported command becomes a warning and its item is dropped
  std::string lenient_option = "--lenient";  ///< the option that sets `lenient`, as messages name it
  double max_distance_m = 50000.0;           ///< [m] farthest a positional item may be from home, (0, 2e7]
  std::size_t max_unrolled_items = 100000;   ///< most items the DO_JUMP loops may unroll to, [1, 1e8]
  /// [deg] when set, where the vehicle will arm: positional items are checked against it instead of
  /// the file's home (ArduPilot and PX4 set home where they arm, so a file's home may be a placeholder)
  std::optional<geometry::GeoPoint> distances_from;
};

/// Reads a mission file: `.plan` (QGroundControl JSON) or `.waypoints` / `.txt` (QGC WPL 110),
/// chosen by the extension and the content (which must agree when both are known). Throws
/// MissionError when the file cannot be opened or read or is over kMaxMissionFileBytes, or as
/// parseQgcPlan / parseQgcWpl.
Mission readMission(const std::string& path, const ReadOptions& o = {});

/// Parses QGroundControl `.plan` text (fileType "Plan", version 1, mission version 2) by QGC's own
/// loading rules: SimpleItems, and the stored items of "survey" (version 4, 5) and "CorridorScan"
/// complex items; DO_JUMP targets given as doJumpId become item seqs. `source` names the text in
/// messages and Mission::source. Throws MissionError naming the item for anything it cannot load,
/// and as checkMission.
Mission parseQgcPlan(const std::string& text, const std::string& source, const ReadOptions& o = {});

/// Parses QGC WPL 110 text: 12 tab- or space-separated columns, row 0 is home, CR LF, a UTF-8 byte
/// order mark, '#' comment lines and decimal commas in tab-separated lines accepted. `source` names
/// the text in messages. Throws MissionError naming the line for anything it cannot load, and as
/// checkMission.
Mission parseQgcWpl(const std::string& text, const std::string& source, const ReadOptions& o = {});

/// Checks a mission as the readers do (and applies their lenient drops): supported commands,
/// frames, finite and in-range fields, speeds, hold times, distance from home, DO_JUMP targets,
/// repeat counts and the unrolled length. Sets the home from the first position when it is not
/// known. Throws MissionError naming the item, the field, the value and what was expected.
void checkMission(Mission& m, const ReadOptions& o = {});

/// The items in the order the autopilot executes them, DO_JUMP loops unrolled (ArduPilot: a jump
/// with repeat count n is taken n times, each DO_JUMP keeps its own count for the whole mission;
/// the DO_JUMP items themselves are left out). Throws MissionError for a missing target, a repeat
/// count of -1 (forever) or outside [0, 1000], or more than o.max_unrolled_items items.
std::vector<MissionItem> unrollJumps(const Mission& m, const ReadOptions& o = {});

/// `.plan` JSON text of `m` (QGroundControl's layout: SimpleItems with doJumpId = seq, items
/// renumbered 1..n in order, empty geoFence and rallyPoints). The home is written as given.
std::string toQgcPlan(const Mission& m);

/// QGC WPL 110 text of `m` (tab separated, row 0 home at its altitude AMSL, numbers written
/// exactly: they read back to the same doubles; items renumbered 1..n in order).
std::string toQgcWpl(const Mission& m);

}  // namespace wattswath::mission
