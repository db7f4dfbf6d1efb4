// The airframe a vehicle file describes (predict.hpp airframeOfVehicle).
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "wattswath/mission/predict.hpp"

namespace wattswath::mission {

Airframe airframeOfVehicle(const energy::Vehicle& v, const std::string& source) {
  Airframe a = airframeOf(v.drag_area_m2, v.mass_kg, v.air_density_kgpm3);
  const auto it = v.extensions.find("airframe");
  if (it == v.extensions.end()) return a;
  const auto j = nlohmann::json::parse(it->second);
  const std::string where = source + ": extensions.airframe";
  if (!j.is_object()) throw std::invalid_argument(where + " = " + it->second + ", expected an object");
  auto number = [&](const char* key, double lo, double hi, double& out) {
    if (!j.contains(key)) return;
    const auto& x = j[key];
    if (!x.is_number() || !(x.get<double>() >= lo && x.get<double>() <= hi)) {
      throw std::invalid_argument(where + "." + key + " = " + x.dump() + ", expected a number in " + std::to_string(lo) +
                                  ".." + std::to_string(hi));
    }
    out = x.get<double>();
  };
  number("drag_linear_per_s", 0.0, 10.0, a.drag_linear_per_s);
  number("drag_quadratic_per_m", 0.0, 1.0, a.drag_quadratic_per_m);
  double response = 0.0;
  if (j.contains("response_s")) {
    number("response_s", 0.0, 2.0, response);
    a.response_s = response;
  }
  return a;
}

}  // namespace wattswath::mission
