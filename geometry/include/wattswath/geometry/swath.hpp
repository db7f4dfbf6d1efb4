#pragma once
/// @file swath.hpp
/// Swath spacing (distance between adjacent passes) from a downward-looking camera.

namespace wattswath::geometry {

/// A nadir camera flown at constant height. Give either the field of view or the sensor width and
/// focal length (the field of view wins when both are set).
struct CameraSettings {
  double altitude = 10.0;      ///< [m] height above ground, > 0
  double fov = 0.0;            ///< [rad] full field of view across track, in (0, pi); 0 = use sensor
  double sensor_width = 0.0;   ///< [m] sensor width across track, > 0 when fov is 0
  double focal_length = 0.0;   ///< [m] lens focal length, > 0 when fov is 0
  double side_overlap = 0.1;   ///< [-] fraction of the footprint shared by adjacent passes, in [0, 1)
};

/// Ground footprint width across track, 2 h tan(fov / 2) or h * sensor / focal [m].
/// Throws std::invalid_argument naming the field when a setting is out of range.
double footprintWidth(const CameraSettings& camera);

/// Distance between adjacent passes, footprint * (1 - overlap) [m]
/// (E-Spiral: 10 m, 100 deg, 10 % -> 21.45 m).
double swathSpacing(const CameraSettings& camera);

}  // namespace wattswath::geometry
