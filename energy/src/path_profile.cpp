#include "wattswath/energy/path_profile.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "wattswath/energy/tolerances.hpp"

namespace wattswath::energy {
namespace {

std::string legError(size_t i, const std::string& what) {
  return "profileFromPath: leg " + std::to_string(i) + ": " + what;
}

}  // namespace

std::vector<Piece> profileFromPath(const geometry::CoveragePath& path, const SpeedPlan& plan,
                                   const ProfileLimits& limits, double yaw_rate) {
  const size_t n = path.legs.size();
  if (plan.cruise.size() != n || plan.junction.size() != n + 1) {
    std::ostringstream os;
    os << "profileFromPath: plan has " << plan.cruise.size() << " cruise and " << plan.junction.size()
       << " junction speeds for " << n << " legs (expected " << n << " and " << n + 1 << ")";
    throw std::invalid_argument(os.str());
  }
  std::vector<Piece> out;
  for (size_t i = 0; i < n; ++i) {
    const auto& leg = path.legs[i];
    const double v0 = plan.junction[i], v1 = plan.junction[i + 1], vc = plan.cruise[i];
    const double slack = 2.0 * tol::kSpeed * std::max(1.0, std::max(v0, v1));
    switch (leg.kind) {
      case geometry::PrimitiveKind::Line: {
        try {
          const auto pieces = buildLegProfile(leg.length(), v0, vc, v1, limits, leg.heading_start);
          out.insert(out.end(), pieces.begin(), pieces.end());
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument(legError(i, e.what()));
        }
        break;
      }
      case geometry::PrimitiveKind::Arc: {
        if (std::abs(v0 - vc) > slack || std::abs(v1 - vc) > slack) {
          std::ostringstream os;
          os << "an arc is flown at constant speed, but entry " << v0 << ", cruise " << vc << " and exit " << v1
             << " m/s differ";
          throw std::invalid_argument(legError(i, os.str()));
        }
        try {
          out.push_back(arc(leg.radius, leg.turn_angle, vc, leg.heading_start));
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument(legError(i, e.what()));
        }
        break;
      }
      case geometry::PrimitiveKind::TurnInPlace: {
        if (std::abs(v0) > slack || std::abs(v1) > slack) {
          std::ostringstream os;
          os << "a turn in place starts and ends at rest, but entry is " << v0 << " and exit " << v1 << " m/s";
          throw std::invalid_argument(legError(i, os.str()));
        }
        try {
          out.push_back(turnInPlace(leg.turn_angle, yaw_rate, leg.heading_start));
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument(legError(i, e.what()));
        }
        break;
      }
    }
  }
  return out;
}

}  // namespace wattswath::energy
