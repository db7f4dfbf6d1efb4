// libFuzzer target: the mission readers (QGroundControl .plan and QGC WPL 110) on arbitrary bytes,
// strict and lenient. Any std::exception is an accepted answer; a crash, a sanitizer report, an
// accepted mission with a position out of range, DO_JUMP loops that do not unroll, or a broken
// round trip (the writer's output that does not read back to the same mission) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

#include "wattswath/mission/files.hpp"

namespace {
using namespace wattswath::mission;

/// What the readers guarantee of a mission they accept.
void checkAccepted(const Mission& m, const ReadOptions& o) {
  if (m.items.empty()) std::abort();
  for (const auto& it : m.items) {
    if (!hasPosition(it)) continue;
    if (!(std::fabs(it.lat_deg) <= 90.0 && std::fabs(it.lon_deg) <= 180.0)) std::abort();
  }
  if (unrollJumps(m, o).size() > o.max_unrolled_items) std::abort();  // must not throw either
}

/// Writing and reading back gives the same mission (exactly when the items are numbered 1..n,
/// as the writers renumber them; a .waypoints file carries no plan speeds, firmware or vehicle).
void checkRoundTrip(const Mission& m, bool plan, const ReadOptions& o) {
  Mission expect = m;
  if (!plan) {
    expect.plan_cruise_speed_mps = expect.plan_hover_speed_mps = 0.0;
    expect.firmware_type = expect.vehicle_type = 0;
  }
  const Mission back = plan ? parseQgcPlan(toQgcPlan(m), "roundtrip.plan", o)
                            : parseQgcWpl(toQgcWpl(m), "roundtrip.waypoints", o);  // must not throw
  bool numbered = true;
  for (std::size_t k = 0; k < m.items.size(); ++k) numbered = numbered && m.items[k].seq == static_cast<int>(k) + 1;
  if (back.items.size() != m.items.size() || (numbered && back != expect)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (bool lenient : {false, true}) {
    ReadOptions o;
    o.lenient = lenient;
    for (bool plan : {true, false}) {
      Mission m;
      try {
        m = plan ? parseQgcPlan(text, "fuzz.plan", o) : parseQgcWpl(text, "fuzz.waypoints", o);
      } catch (const std::exception&) {
        continue;
      }
      checkAccepted(m, o);
      checkRoundTrip(m, plan, o);
    }
  }
  return 0;
}
