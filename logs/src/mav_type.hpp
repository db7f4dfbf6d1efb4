#pragma once
// Private helper of the log readers: names of MAVLink MAV_TYPE values (PX4 vehicle_status.system_type).
#include <map>
#include <string>

namespace wattswath::logs {

/// Name of MAV_TYPE `t`, e.g. "quadrotor", or "MAV_TYPE <t>" when not listed.
inline std::string mavTypeName(int t) {
  static const std::map<int, std::string> names = {{1, "fixed wing"}, {2, "quadrotor"}, {3, "coaxial"},
      {4, "helicopter"}, {10, "ground rover"}, {13, "hexarotor"}, {14, "octorotor"}, {15, "tricopter"},
      {19, "VTOL tailsitter duorotor"}, {20, "VTOL tailsitter quadrotor"}, {21, "VTOL tiltrotor"}, {22, "VTOL"}};
  auto it = names.find(t);
  return it == names.end() ? "MAV_TYPE " + std::to_string(t) : it->second;
}

}  // namespace wattswath::logs
