// What `predict` takes beyond the mission and the vehicle: --launch and --wind (predict_options.hpp).
#include "predict_options.hpp"

#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/files.hpp"

namespace wattswath::apps {
namespace {

// The comma-separated parts of an option's value.
std::vector<std::string> commaParts(const std::string& value) {
  std::vector<std::string> parts;
  for (std::size_t from = 0;;) {
    const auto comma = value.find(',', from);
    parts.push_back(value.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return parts;
}

// `part` of `option`'s `value` as a finite number; else std::invalid_argument naming both and `expected`.
double optionNumber(const std::string& option, const std::string& value, const std::string& part, const std::string& expected) {
  std::size_t used = 0;
  double x = std::nan("");
  try {
    x = std::stod(part, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != part.size() || !std::isfinite(x)) {
    throw std::invalid_argument(option + " '" + value + "': '" + part + "' is not a number; " + expected);
  }
  return x;
}

constexpr const char* kLaunchExpected =
    "expected LAT,LON in degrees or LAT,LON,ALT with ALT in metres as the mission's home altitude, e.g. 43.7157,10.4612 "
    "or 43.7157,10.4612,35.5";

}  // namespace

int absoluteItems(const mission::Mission& m, const std::vector<mission::NavStep>& steps) {
  std::set<int> items;  // an item repeated by DO_JUMP counts once
  for (const auto& st : steps) {
    const bool flies_height = st.kind == mission::NavStep::Kind::Takeoff || st.kind == mission::NavStep::Kind::LoiterTurns ||
                              (mission::isFlownTo(st) && st.has_position);
    if (flies_height && st.item >= 0 && mission::altitudeFrame(m.items[static_cast<std::size_t>(st.item)].frame) == mission::AltitudeFrame::Absolute)
      items.insert(st.item);
  }
  return static_cast<int>(items.size());
}

geometry::GeoPoint launchPoint(const std::string& launch) {
  const std::vector<std::string> parts = commaParts(launch);
  if (parts.size() < 2 || parts.size() > 3) throw std::invalid_argument("--launch '" + launch + "': " + kLaunchExpected);
  auto number = [&](const std::string& text) { return optionNumber("--launch", launch, text, kLaunchExpected); };
  geometry::GeoPoint at{number(parts[0]), number(parts[1]), 0.0};
  geometry::validateGeoPoint(at, "--launch");
  return at;
}

Launch moveHomeTo(mission::Mission& m, const std::string& launch) {
  const std::vector<std::string> parts = commaParts(launch);
  auto number = [&](const std::string& text) { return optionNumber("--launch", launch, text, kLaunchExpected); };
  geometry::GeoPoint at = launchPoint(launch);
  at.alt_m = m.home.alt_m;
  Launch l;
  l.from_home_m = geometry::geodesicDistance(m.home, at);
  if (parts.size() == 3) {
    l.alt_m = number(parts[2]);
    if (!(*l.alt_m >= -500.0 && *l.alt_m <= 9000.0)) {
      throw std::invalid_argument("--launch '" + launch + "': altitude " + parts[2] + " m is outside -500..9000 m");
    }
    l.alt_change_m = *l.alt_m - m.home.alt_m;
    m.home.alt_m = *l.alt_m;
  }
  m.home.lat_deg = at.lat_deg;
  m.home.lon_deg = at.lon_deg;
  m.home_known = true;
  return l;
}

std::string launchText(const Launch& l) {
  std::ostringstream os;
  if (l.from_home_m > 50000.0) {
    os << std::fixed << std::setprecision(0) << l.from_home_m / 1000.0
       << " km from the mission's home, which is taken as a placeholder: the autopilot's home is set where it arms, and "
          "the return flies there";
  } else {
    os << std::fixed << std::setprecision(1) << l.from_home_m
       << " m from the mission's home; the autopilot's home is set there and the return flies to it";
  }
  if (l.alt_m) {
    os << "; " << std::showpos << l.alt_change_m << std::noshowpos << " m from the home's altitude: ";
    if (l.absolute_items > 0) {
      os << l.absolute_items << " item(s) with absolute heights are flown that much lower above the vehicle's home";
    } else {
      os << "every height in the mission is relative to home, so none changes";
    }
  } else if (l.absolute_items > 0) {
    os << "; its altitude is taken as the home's (" << l.absolute_items
       << " item(s) have absolute heights: give --launch LAT,LON,ALT when the ground there is higher or lower)";
  }
  return os.str();
}

Eigen::Vector2d Wind::air() const {
  const double to = (from_deg + 180.0) * M_PI / 180.0;
  return {speed_mps * std::sin(to), speed_mps * std::cos(to)};
}

std::string Wind::text() const {
  static const char* names[] = {"N", "NE", "E", "SE", "S", "SW", "W", "NW"};
  std::ostringstream os;
  os << std::fixed << std::setprecision(1) << speed_mps << " m/s from ";
  if (any_direction) os << "any direction; flown from the dearest of " << kWindDirections << " directions, ";
  os << std::setprecision(0) << from_deg << " deg (" << names[static_cast<int>(std::lround(from_deg / 45.0)) % 8]
     << "): the vehicle flies against its drag at air speed (lean-limited upwind) and the energy model's drag is taken at "
        "air speed; a steady wind, no gusts";
  return os.str();
}

nlohmann::json windJson(const std::optional<Wind>& wind) {
  if (!wind) return nullptr;
  return {{"speed_mps", wind->speed_mps}, {"from_deg", wind->from_deg}, {"any_direction", wind->any_direction},
          {"east_mps", wind->air().x()}, {"north_mps", wind->air().y()}, {"text", wind->text()}};
}

Wind parseWind(const std::string& text, bool any_direction_allowed) {
  const std::string expected = std::string("expected SPEED,FROM: the speed in m/s and the compass bearing in degrees it blows "
                                           "from (0 north, 90 east), e.g. 6,45 for 6 m/s from the north-east") +
                               (any_direction_allowed ? ", or SPEED alone for a wind from any direction"
                                                      : " (SPEED alone, any direction, is for predict)");
  const std::vector<std::string> parts = commaParts(text);
  const bool any = parts.size() == 1 && any_direction_allowed;
  if (parts.size() != 2 && !any) throw std::invalid_argument("--wind '" + text + "': " + expected);
  Wind w{optionNumber("--wind", text, parts[0], expected), any ? 0.0 : optionNumber("--wind", text, parts[1], expected), any};
  if (!(w.speed_mps >= 0.0 && w.speed_mps <= 40.0)) {
    throw std::invalid_argument("--wind '" + text + "': speed " + parts[0] + " m/s is outside 0..40 m/s");
  }
  if (!(w.from_deg >= 0.0 && w.from_deg <= 360.0)) {
    throw std::invalid_argument("--wind '" + text + "': direction " + parts.back() + " deg is outside 0..360");
  }
  return w;
}

std::optional<Wind> windOption(const std::string& text, bool any_direction_allowed) {
  if (text.empty()) return std::nullopt;
  return parseWind(text, any_direction_allowed);
}

}  // namespace wattswath::apps
