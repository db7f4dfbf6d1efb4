#pragma once
/// @file camera.hpp
/// Photos of a survey: a nadir camera as users give it (fields of view, or sensor, focal length and
/// image size), where its photos fall at an altitude (footprints, line spacing from the side
/// overlap, trigger distance from the frontal overlap, ground sampling distance), computed as
/// QGroundControl's CameraCalc computes them, and how many photos a stretch of sweep takes.

namespace wattswath::planner {

/// A nadir camera in landscape orientation: the image width lies across track.
struct Camera {
  double fov_across_rad = 0.0;  ///< [rad] field of view across track, (0, pi)
  double fov_along_rad = 0.0;   ///< [rad] field of view along track, (0, pi)
  int image_width_px = 0;       ///< [px] image width (across track); 0: unknown, no ground sampling distance

  /// A camera from its sensor width and height [mm], focal length [mm] and image size [px] (0: not
  /// given). As QGC's CameraCalc: the footprint across track is altitude x sensor width / focal length;
  /// along track, image height x GSD when the image size is given (square pixels), else altitude x
  /// sensor height / focal length. Throws std::invalid_argument naming the value when not positive.
  static Camera fromSensor(double sensor_width_mm, double sensor_height_mm, double focal_length_mm,
                           int image_width_px = 0, int image_height_px = 0);
  /// Throws std::invalid_argument naming the field and value when a field of view is outside (0, pi)
  /// or the image width is negative.
  void validate() const;
};

/// Where a camera's photos fall at one altitude with given overlaps.
struct PhotoGeometry {
  double footprint_across_m = 0.0;   ///< [m] footprint width across track: 2 h tan(fov_across / 2)
  double footprint_along_m = 0.0;    ///< [m] footprint length along track: 2 h tan(fov_along / 2)
  double line_spacing_m = 0.0;       ///< [m] distance between sweep lines: across footprint x (1 - side overlap)
  double trigger_distance_m = 0.0;   ///< [m] distance between photos on a sweep: along footprint x (1 - frontal overlap)
  double gsd_m = 0.0;                ///< [m/px] ground sampling distance: across footprint / image width (0: unknown)
};

/// The photos of `camera` at `altitude_m` [m] above flat ground with `side_overlap` and
/// `frontal_overlap` [-] in [0, 1) (QGC CameraCalc::_recalcTriggerDistance: AdjustedFootprintSide
/// and AdjustedFootprintFrontal). Throws std::invalid_argument naming the value out of range.
PhotoGeometry photoGeometry(const Camera& camera, double altitude_m, double side_overlap, double frontal_overlap);

/// [-] Photos taken along `length_m` [m] of sweep by distance triggering every `trigger_distance_m`
/// [m] switched on with one photo at once and off with one more (DO_SET_CAM_TRIGG_DIST param3 1, as
/// QGC writes it): at 0, d, 2d, ... and at the end, ceil(L / d) + 1. (QGC's own estimate, ceil(L / d)
/// per transect, leaves out one of the two ends.) 0 when `trigger_distance_m` is not positive.
int photosAlong(double length_m, double trigger_distance_m);

}  // namespace wattswath::planner
