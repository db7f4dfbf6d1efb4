#pragma once
/// @file frame.hpp
/// The local East-North-Up frame in which all geometry is done: geodetic lat/lon/alt in and out
/// through GeographicLib::LocalCartesian (kept private in geometry/src/frame.cpp).

#include <memory>
#include <string>

#include <Eigen/Core>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::geometry {

/// A geodetic position on the WGS84 ellipsoid.
struct GeoPoint {
  double lat_deg = 0.0;  ///< [deg] latitude, [-90, 90]
  double lon_deg = 0.0;  ///< [deg] longitude, [-180, 180]
  double alt_m = 0.0;    ///< [m] height above the WGS84 ellipsoid (or as given by the file)
};

/// Throws std::invalid_argument naming `where` unless lat is in [-90, 90], lon in [-180, 180] and
/// both (and alt) are finite.
void validateGeoPoint(const GeoPoint& p, const std::string& where);

/// [m] The WGS84 geodesic distance between `a` and `b` (GeographicLib), heights ignored.
double geodesicDistance(const GeoPoint& a, const GeoPoint& b);

/// A local tangent-plane frame: x east, y north, z up [m], origin at a geodetic point.
/// Wraps GeographicLib::LocalCartesian (exact ellipsoidal geodetic <-> ECEF <-> ENU transform).
/// 2D use: toLocal() drops z; toGeodetic() returns the point at the origin's ellipsoid height whose
/// ENU x, y are the given ones (solved by iterating on z), so lat/lon -> x, y -> lat/lon is exact
/// to better than 1e-9 m at any distance. Copies share the (immutable) GeographicLib object.
class LocalFrame {
 public:
  /// Frame at `origin`; throws std::invalid_argument if it is out of range or not finite.
  explicit LocalFrame(const GeoPoint& origin);

  /// The origin of the frame.
  const GeoPoint& origin() const { return origin_; }

  /// ENU x (east), y (north) [m] of a geodetic point (altitude ignored: taken at the origin's height).
  Point toLocal(double lat_deg, double lon_deg) const;
  /// ENU x, y, z [m] of a geodetic point including its altitude.
  Eigen::Vector3d toLocal3(const GeoPoint& p) const;
  /// Geodetic point at the origin's height whose ENU x, y are `p` [m]; alt_m = origin alt.
  GeoPoint toGeodetic(const Point& p) const;
  /// Geodetic point of an ENU position x, y, z [m] (exact inverse of toLocal3).
  GeoPoint toGeodetic3(const Eigen::Vector3d& p) const;

 private:
  struct Impl;
  GeoPoint origin_;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace wattswath::geometry
