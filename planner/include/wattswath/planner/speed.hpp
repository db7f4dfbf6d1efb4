#pragma once
/// @file speed.hpp
/// Speeds and corners for a route (a polyline with a role per segment): every corner is either a
/// sharp stop with a turn in place or a rounded arc flown at a reduced speed, and every straight
/// piece flies at the cruise speed minimising its energy given its entry and exit speeds
/// (optimal-velocity segment splitting; Marins et al. Eq. 6-9 per leg). The corner choices are
/// made jointly by dynamic programming over the corners, so the whole path's energy is minimal
/// for the chosen geometry.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wattswath/energy/marins.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/path_profile.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/path.hpp"

namespace wattswath::planner {

/// How corners are flown.
enum class CornerStrategy {
  Sharp,    ///< stop and turn in place at every corner
  Rounded,  ///< an arc wherever one fits, else a stop
  Auto      ///< per corner, whichever costs less energy
};

/// Parses "sharp", "rounded" or "auto"; throws std::invalid_argument naming the value otherwise.
CornerStrategy cornerStrategyFromString(const std::string& s);
/// Lower-case name of a strategy.
const char* toString(CornerStrategy s);

/// A route: vertices, the role of each segment, and how far an arc may cut into the segments at
/// each vertex without losing coverage or nearing an obstacle.
struct Route {
  std::vector<geometry::Point> points;     ///< [m] vertices in flight order (at least 2)
  std::vector<geometry::LegRole> roles;    ///< role of segment i (points[i] to points[i+1])
  std::vector<double> max_tangent;         ///< [m] per vertex: largest tangent length of an arc there (0: stop only)

  /// Appends point `p` reached by a segment of role `role`; `tangent_at_p` as in max_tangent.
  void add(const geometry::Point& p, geometry::LegRole role, double tangent_at_p);
  /// Total polyline length [m].
  double length() const;
};

/// Speed and corner settings.
struct SpeedSettings {
  double max_speed = 16.0;            ///< [m/s] vehicle maximum, (0, 200]
  double camera_max_speed = 0.0;      ///< [m/s] cap on sweep legs from the camera (0: none)
  double fixed_speed = 0.0;           ///< [m/s] fly every leg at this cruise speed (0: optimise), for baselines
  double lateral_acceleration = 1.0;  ///< [m/s^2] centripetal limit on arcs, v^2 / r <= this, (0, 100]
  energy::ProfileLimits limits;       ///< [m/s^2] acceleration and braking
  double yaw_rate = 2.1;              ///< [rad/s] yaw rate of turns in place, (0, 100]
  double altitude = 10.0;             ///< [m] flight height above home written into the legs
  CornerStrategy corners = CornerStrategy::Auto;  ///< corner strategy
  bool arc_chains = true;             ///< also offer arcs at chain speeds (runs of close corners flown without
                                      ///< stopping; 6 options per corner instead of 2: slower to score)

  /// Settings from a vehicle (maximum speed, acceleration, yaw rate).
  static SpeedSettings fromVehicle(const energy::Vehicle& v);
  /// Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

/// A route flown: the geometric path with its speeds, and the energy and time of each leg.
struct FlownPath {
  geometry::CoveragePath path;     ///< legs: lines, arcs, turns in place
  energy::SpeedPlan speeds;        ///< cruise per leg, speed at each junction
  std::vector<double> leg_energy;  ///< [J] per leg
  std::vector<double> leg_time;    ///< [s] per leg
  double energy = 0.0;             ///< [J] total
  double time = 0.0;               ///< [s] total
  double length = 0.0;             ///< [m] total flown distance
  int sharp_corners = 0;           ///< corners flown as stop + turn in place
  int rounded_corners = 0;         ///< corners flown as arcs
};

/// Fast energy-only evaluation of a route [J] (what flyRoute().energy returns; infinite when no
/// feasible speeds exist). Caches leg optima internally; not thread-safe, use one per thread.
class RouteScorer {
 public:
  /// Scorer with `model` and `settings` (validated; throws std::invalid_argument).
  RouteScorer(const energy::EnergyModel& model, const SpeedSettings& settings);
  /// Minimum energy of `route` over speeds and corner choices [J].
  double energy(const Route& route);
  /// The full flown path (legs, speeds, energies) of `route`.
  FlownPath fly(const Route& route);
  /// Minimum energy of a straight leg of `length` [m] entered at `v_in`, left at `v_out`,
  /// cruising at most at `cap` [m/s] [J]; infinite when the speed change does not fit.
  double legEnergy(double length, double v_in, double v_out, double cap);
  /// The cruise speed achieving legEnergy [m/s].
  double legCruise(double length, double v_in, double v_out, double cap);
  /// Energy of a turn in place by `angle` [rad] [J].
  double turnEnergy(double angle) const;
  /// The settings.
  const SpeedSettings& settings() const { return settings_; }
  /// The model.
  const energy::EnergyModel& model() const { return model_; }

 private:
  struct Solved;
  Solved solve(const Route& route);
  double optimise(double length, double v_in, double v_out, double cap, double* cruise);
  energy::EnergyModel model_;
  SpeedSettings settings_;
  std::optional<energy::MarinsClosedForm> closed_;  // the inlined leg energy when the model is Marins' own
  struct Cache;
  std::shared_ptr<Cache> cache_;
};

}  // namespace wattswath::planner
