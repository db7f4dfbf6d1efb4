#include "wattswath/geometry/swath.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wattswath::geometry {
namespace {

[[noreturn]] void bad(const std::string& field, double value, const std::string& expected) {
  std::ostringstream os;
  os << "camera: " << field << " = " << value << ", expected " << expected;
  throw std::invalid_argument(os.str());
}

}  // namespace

double footprintWidth(const CameraSettings& c) {
  if (!(std::isfinite(c.altitude) && c.altitude > 0.0)) bad("altitude [m]", c.altitude, "a finite value > 0");
  if (c.fov != 0.0) {
    if (!(std::isfinite(c.fov) && c.fov > 0.0 && c.fov < M_PI)) bad("fov [rad]", c.fov, "a value in (0, pi)");
    return 2.0 * c.altitude * std::tan(0.5 * c.fov);
  }
  if (!(std::isfinite(c.sensor_width) && c.sensor_width > 0.0))
    bad("sensor_width [m]", c.sensor_width, "a finite value > 0 (or set fov)");
  if (!(std::isfinite(c.focal_length) && c.focal_length > 0.0))
    bad("focal_length [m]", c.focal_length, "a finite value > 0 (or set fov)");
  return c.altitude * c.sensor_width / c.focal_length;
}

double swathSpacing(const CameraSettings& c) {
  if (!(std::isfinite(c.side_overlap) && c.side_overlap >= 0.0 && c.side_overlap < 1.0))
    bad("side_overlap", c.side_overlap, "a fraction in [0, 1)");
  return footprintWidth(c) * (1.0 - c.side_overlap);
}

}  // namespace wattswath::geometry
