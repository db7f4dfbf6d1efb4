// libFuzzer target: the vehicle JSON reader on arbitrary bytes. Any std::exception is an accepted
// answer; a crash, a sanitizer report or a broken round trip (an accepted vehicle that does not
// read back identically from vehicleToJson) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

#include "wattswath/energy/vehicle.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace en = wattswath::energy;
  const std::string text(reinterpret_cast<const char*>(data), size);
  en::Vehicle v;
  try {
    v = en::parseVehicle(text, "fuzz.json");
  } catch (const std::exception&) {
    return 0;
  }
  const en::Vehicle back = en::parseVehicle(en::vehicleToJson(v), "roundtrip.json");  // must not throw
  if (back.mass_kg != v.mass_kg || back.rotor_count != v.rotor_count || back.disk_area_m2 != v.disk_area_m2 ||
      back.battery.has_value() != v.battery.has_value() || !(en::marinsHoverPowerW(v) > 0.0)) {
    std::abort();
  }
  return 0;
}
