#include "spiral_case.hpp"

#include <cmath>
#include <stdexcept>

#include "wattswath/energy/path_profile.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/coverage.hpp"
#include "wattswath/geometry/swath.hpp"

namespace wattswath::apps {

namespace en = wattswath::energy;
namespace g = wattswath::geometry;

SpiralCaseSettings SpiralCaseSettings::table3(const en::Vehicle& v) {
  SpiralCaseSettings s;
  s.acceleration = v.max_acceleration_mps2;
  s.yaw_rate = v.max_yaw_rate_radps;
  s.corner_radius = s.corner_speed / s.yaw_rate;
  return s;
}

SpiralCaseSettings SpiralCaseSettings::table4(const en::Vehicle& v) {
  SpiralCaseSettings s = table3(v);
  s.acceleration = 1.2;     // "the mean value during the whole coverage is 1.2 m/s^2"
  s.corner_speed = 4.0;     // "when it turns, most of the times it does that at 4 m/s or less"
  s.short_leg_speed = 7.0;  // "for some very short paths, it flies below 7 m/s"
  s.long_leg = 100.0;       // our reading of "very short": the legs under 100 m (the short sides)
  s.corner_radius = s.corner_speed / s.yaw_rate;  // v / omega_max: the same curve time as Table III,
                                                  // as Table IV's unchanged 1,601 J of curve hover shows
  return s;
}

SpiralCaseResult runSpiralCase(const g::PolygonWithHoles& area, const en::Vehicle& vehicle,
                               const SpiralCaseSettings& settings) {
  SpiralCaseResult r;
  g::CameraSettings camera;
  camera.altitude = 10.0;
  camera.fov = 100.0 * M_PI / 180.0;
  camera.side_overlap = 0.10;
  r.spacing = g::swathSpacing(camera);
  const auto cells = g::decomposeSpiral(area, r.spacing);
  if (cells.size() != 1) {
    throw std::runtime_error("spiral case: the area gives " + std::to_string(cells.size()) +
                             " spiral cells, expected one (a rectangle)");
  }
  const auto& lap0 = cells[0].laps[0];
  g::SpiralSettings sp;
  sp.spacing = r.spacing;
  double longest = -1.0;
  for (size_t i = 0; i < lap0.size(); ++i) {  // start at the corner that begins a long side
    const double len = (lap0[(i + 1) % lap0.size()] - lap0[i]).norm();
    if (len > longest + 1e-9) {
      longest = len;
      sp.start_vertex = static_cast<int>(i);
    }
  }
  g::CornerSettings corners;
  corners.style = g::CornerStyle::Rounded;
  corners.radius = settings.corner_radius;
  r.path = g::shapeCorners(g::spiralRoute(cells[0], sp), corners, camera.altitude, area);
  r.path.pattern = "spiral";
  r.path.cell = 0;
  r.laps = static_cast<int>(cells[0].laps.size());
  r.coverage = g::checkCoverage(area, {r.path}, r.spacing).fraction();

  const size_t n = r.path.legs.size();
  en::SpeedPlan plan;
  plan.cruise.resize(n);
  plan.junction.assign(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const auto& leg = r.path.legs[i];
    if (leg.kind == g::PrimitiveKind::Arc) {
      plan.cruise[i] = settings.corner_speed;
      plan.junction[i] = plan.junction[i + 1] = settings.corner_speed;
    } else {
      plan.cruise[i] = leg.length() >= settings.long_leg ? settings.cruise_speed : settings.short_leg_speed;
    }
  }
  en::ProfileLimits limits;
  limits.acceleration = limits.deceleration = settings.acceleration;
  const auto pieces = en::profileFromPath(r.path, plan, limits, settings.yaw_rate);
  r.pieces = static_cast<int>(pieces.size());
  r.breakdown = en::marinsModel(vehicle).evaluate(pieces);
  return r;
}

}  // namespace wattswath::apps
