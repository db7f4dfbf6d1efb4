// Photos of a survey: footprints, line spacing, trigger distance and GSD as QGroundControl's
// CameraCalc computes them, and the photo count of a stretch of sweep.
#include "wattswath/planner/camera.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace wattswath::planner {
namespace {

void requirePositive(double v, const std::string& what) {
  if (!(std::isfinite(v) && v > 0.0))
    throw std::invalid_argument("camera: " + what + " = " + std::to_string(v) + ", expected > 0");
}

void requireFraction(double v, const std::string& what) {
  if (!(v >= 0.0 && v < 1.0))
    throw std::invalid_argument("camera: " + what + " = " + std::to_string(v) + ", expected a fraction in [0, 1)");
}

}  // namespace

Camera Camera::fromSensor(double sensor_width_mm, double sensor_height_mm, double focal_length_mm, int image_width_px,
                          int image_height_px) {
  requirePositive(sensor_width_mm, "sensor width [mm]");
  requirePositive(sensor_height_mm, "sensor height [mm]");
  requirePositive(focal_length_mm, "focal length [mm]");
  if (image_width_px < 0 || image_height_px < 0)
    throw std::invalid_argument("camera: image size " + std::to_string(image_width_px) + " x " +
                                std::to_string(image_height_px) + " px, expected positive (or 0: not given)");
  Camera c;
  c.fov_across_rad = 2.0 * std::atan(sensor_width_mm / (2.0 * focal_length_mm));
  // QGC: frontal footprint = image height x GSD, GSD = h x sensor width / (image width x focal length).
  const double along_mm = image_width_px > 0 && image_height_px > 0
                              ? sensor_width_mm * image_height_px / image_width_px
                              : sensor_height_mm;
  c.fov_along_rad = 2.0 * std::atan(along_mm / (2.0 * focal_length_mm));
  c.image_width_px = image_width_px;
  return c;
}

void Camera::validate() const {
  if (!(fov_across_rad > 0.0 && fov_across_rad < M_PI))
    throw std::invalid_argument("camera: field of view across track = " + std::to_string(fov_across_rad * 180.0 / M_PI) +
                                " deg, expected (0, 180)");
  if (!(fov_along_rad > 0.0 && fov_along_rad < M_PI))
    throw std::invalid_argument("camera: field of view along track = " + std::to_string(fov_along_rad * 180.0 / M_PI) +
                                " deg, expected (0, 180)");
  if (image_width_px < 0)
    throw std::invalid_argument("camera: image width = " + std::to_string(image_width_px) + " px, expected >= 0");
}

PhotoGeometry photoGeometry(const Camera& camera, double altitude_m, double side_overlap, double frontal_overlap) {
  camera.validate();
  requirePositive(altitude_m, "altitude [m]");
  requireFraction(side_overlap, "side overlap");
  requireFraction(frontal_overlap, "frontal overlap");
  PhotoGeometry g;
  g.footprint_across_m = 2.0 * altitude_m * std::tan(0.5 * camera.fov_across_rad);
  g.footprint_along_m = 2.0 * altitude_m * std::tan(0.5 * camera.fov_along_rad);
  g.line_spacing_m = g.footprint_across_m * (1.0 - side_overlap);
  g.trigger_distance_m = g.footprint_along_m * (1.0 - frontal_overlap);
  g.gsd_m = camera.image_width_px > 0 ? g.footprint_across_m / camera.image_width_px : 0.0;
  return g;
}

int photosAlong(double length_m, double trigger_distance_m) {
  if (!(trigger_distance_m > 0.0) || !(length_m >= 0.0)) return 0;
  // A hair under a whole number of trigger distances is that number (no extra photo for rounding).
  return static_cast<int>(std::ceil(length_m / trigger_distance_m - 1e-9)) + 1;
}

}  // namespace wattswath::planner
