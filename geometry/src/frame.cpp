#include "wattswath/geometry/frame.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LocalCartesian.hpp>

namespace wattswath::geometry {

struct LocalFrame::Impl {
  GeographicLib::LocalCartesian lc;
};

void validateGeoPoint(const GeoPoint& p, const std::string& where) {
  std::ostringstream msg;
  msg.precision(12);
  if (!std::isfinite(p.lat_deg) || !std::isfinite(p.lon_deg) || !std::isfinite(p.alt_m)) {
    msg << where << ": non-finite coordinate (lat " << p.lat_deg << ", lon " << p.lon_deg << ", alt " << p.alt_m
        << "); expected finite numbers";
    throw std::invalid_argument(msg.str());
  }
  if (p.lat_deg < -90.0 || p.lat_deg > 90.0) {
    msg << where << ": latitude " << p.lat_deg << " deg is outside [-90, 90] (lon/lat swapped?)";
    throw std::invalid_argument(msg.str());
  }
  if (p.lon_deg < -180.0 || p.lon_deg > 180.0) {
    msg << where << ": longitude " << p.lon_deg << " deg is outside [-180, 180]";
    throw std::invalid_argument(msg.str());
  }
}

LocalFrame::LocalFrame(const GeoPoint& origin) : origin_(origin) {
  validateGeoPoint(origin, "frame origin");
  impl_ = std::make_shared<const Impl>(Impl{GeographicLib::LocalCartesian(origin.lat_deg, origin.lon_deg, origin.alt_m)});
}

double geodesicDistance(const GeoPoint& a, const GeoPoint& b) {
  double s12 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(a.lat_deg, a.lon_deg, b.lat_deg, b.lon_deg, s12);
  return s12;
}

Point LocalFrame::toLocal(double lat_deg, double lon_deg) const {
  double x = 0, y = 0, z = 0;
  impl_->lc.Forward(lat_deg, lon_deg, origin_.alt_m, x, y, z);
  return {x, y};
}

Eigen::Vector3d LocalFrame::toLocal3(const GeoPoint& p) const {
  double x = 0, y = 0, z = 0;
  impl_->lc.Forward(p.lat_deg, p.lon_deg, p.alt_m, x, y, z);
  return {x, y, z};
}

GeoPoint LocalFrame::toGeodetic(const Point& p) const {
  // Find z such that the point (x, y, z) lies at the origin's ellipsoid height: h(z) has slope ~1
  // (the local up is nearly the ellipsoid normal), so a few fixed-point steps converge to 1e-12 m.
  double z = 0.0, lat = 0, lon = 0, h = 0;
  for (int i = 0; i < 8; ++i) {
    impl_->lc.Reverse(p.x(), p.y(), z, lat, lon, h);
    const double dh = h - origin_.alt_m;
    if (std::abs(dh) < 1e-12) break;
    z -= dh;
  }
  return {lat, lon, origin_.alt_m};
}

GeoPoint LocalFrame::toGeodetic3(const Eigen::Vector3d& p) const {
  GeoPoint g;
  impl_->lc.Reverse(p.x(), p.y(), p.z(), g.lat_deg, g.lon_deg, g.alt_m);
  return g;
}

}  // namespace wattswath::geometry
