// libFuzzer target: the waypoint path reader of `simulate --path` on arbitrary bytes. Any
// std::exception is an accepted answer; a crash, a sanitizer report, or an accepted path with
// fewer than two waypoints or a coordinate that is not finite and within tol::kLogMaxMagnitude is
// a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

#include "wattswath/logs/log_io.hpp"
#include "wattswath/logs/tolerances.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto w = wattswath::logs::parseWaypointPath(text, "fuzz.txt");
    if (w.size() < 2) std::abort();
    for (const auto& p : w)
      if (!p.allFinite() || p.cwiseAbs().maxCoeff() > wattswath::logs::tol::kLogMaxMagnitude) std::abort();
  } catch (const std::exception&) {
  }
  return 0;
}
