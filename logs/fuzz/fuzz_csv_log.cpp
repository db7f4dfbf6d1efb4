// libFuzzer target: the canonical CSV flight-log reader on arbitrary bytes. Any std::exception is
// an accepted answer; a crash, a sanitizer report, an accepted log with a non-finite sample, or a
// broken round trip (writeCsvLog output that does not read back with the same samples) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

#include "wattswath/logs/log_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  wattswath::logs::FlightLog log;
  try {
    log = wattswath::logs::parseCsvLog(text, "fuzz.csv");
  } catch (const std::exception&) {
    return 0;
  }
  for (const auto& s : log.samples) {
    if (!std::isfinite(s.t) || !s.position.allFinite() || !s.velocity.allFinite() || !s.acceleration.allFinite() ||
        !std::isfinite(s.power)) {
      std::abort();
    }
  }
  const wattswath::logs::FlightLog back = wattswath::logs::parseCsvLog(wattswath::logs::writeCsvLog(log), "roundtrip.csv");  // must not throw
  if (back.samples.size() != log.samples.size()) std::abort();
  for (size_t i = 0; i < log.samples.size(); ++i) {
    if (back.samples[i].t != log.samples[i].t || back.samples[i].power != log.samples[i].power) std::abort();
  }
  return 0;
}
