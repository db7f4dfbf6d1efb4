#pragma once
// What `predict` takes beyond the mission and the vehicle: where the vehicle will arm (--launch)
// and the wind it will fly in (--wind), parsed with errors that name the option.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "wattswath/mission/flight.hpp"
#include "wattswath/mission/mission.hpp"

namespace wattswath::apps {

/// Where the vehicle will arm (--launch LAT,LON[,ALT]): the autopilot sets home there.
struct Launch {
  double from_home_m = 0.0;         ///< [m] horizontal distance from the file's home
  std::optional<double> alt_m;      ///< [m] the launch point's altitude, as the file's home's (AMSL)
  double alt_change_m = 0.0;        ///< [m] the launch altitude minus the file's home altitude
  int absolute_items = 0;           ///< items whose heights are absolute (they move with the home's): absoluteItems
};

/// How many items of `m` whose height is flown (the take-off and the steps flown to, from the
/// sequenced `steps`) give it above sea level (MAV_FRAME_GLOBAL), so it moves with the home's altitude.
int absoluteItems(const mission::Mission& m, const std::vector<mission::NavStep>& steps);

/// The point of --launch ("LAT,LON[,ALT]") [deg], its altitude left 0; throws std::invalid_argument
/// naming --launch for a malformed value.
geometry::GeoPoint launchPoint(const std::string& launch);

/// Moves `m`'s home to `launch` ("LAT,LON" [deg], optionally ",ALT" [m, the file's home's reference]):
/// the autopilot sets home where the vehicle arms and returns there; heights given relative to
/// home stay above the new home, absolute ones are measured from its altitude. Throws
/// std::invalid_argument naming --launch for a malformed or implausible value.
Launch moveHomeTo(mission::Mission& m, const std::string& launch);

/// The launch in words.
std::string launchText(const Launch& l);

/// Directions `predict --wind SPEED` (any direction) flies: every 45 degrees.
constexpr int kWindDirections = 8;

/// The wind of --wind SPEED,FROM: SPEED [m/s] blowing from the compass bearing FROM [deg], as a
/// forecast or METAR gives it; or SPEED alone when the direction is not known (predict only).
struct Wind {
  double speed_mps = 0.0;  ///< [m/s] 0..40
  double from_deg = 0.0;   ///< [deg] compass bearing it blows from, 0..360 (0 north, 90 east)
  /// SPEED alone: the direction is not known, and from_deg is the dearest of kWindDirections
  bool any_direction = false;
  /// [m/s] where the air moves to, east and north (PredictSettings::wind)
  Eigen::Vector2d air() const;
  /// The wind and what the prediction does with it, in words.
  std::string text() const;
};

/// The JSON of `wind`: {speed_mps, from_deg, east_mps, north_mps, text}, null in still air.
nlohmann::json windJson(const std::optional<Wind>& wind);

/// Parses --wind SPEED,FROM, or SPEED alone when `any_direction_allowed`; throws
/// std::invalid_argument naming --wind for a malformed or implausible value.
Wind parseWind(const std::string& text, bool any_direction_allowed = false);

/// parseWind of an option's value, std::nullopt (still air) when it was not given (empty).
std::optional<Wind> windOption(const std::string& text, bool any_direction_allowed = false);

}  // namespace wattswath::apps
