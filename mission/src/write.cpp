// Writers of the item model: QGroundControl `.plan` and QGC WPL 110 `.waypoints`.
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "files_internal.hpp"

namespace wattswath::mission {
namespace {
using detail::numberText;
using nlohmann::json;

/// Throws std::invalid_argument naming the item for an infinite field (NaN is written as "unset").
void checkWritable(const MissionItem& it) {
  const double v[7] = {it.param[0], it.param[1], it.param[2], it.param[3], it.lat_deg, it.lon_deg, it.alt_m};
  for (int k = 0; k < 7; ++k)
    if (std::isinf(v[k]))
      throw std::invalid_argument("mission item " + std::to_string(it.seq) + " (" + commandName(it.command) + "): param" +
                                  std::to_string(k + 1) + " = " + numberText(v[k]) + ", expected a finite number or NaN");
}

/// The items renumbered 1..n in order; each DO_JUMP's target follows its item (the first item
/// numbered at or after the old target, as the readers resolve it).
std::vector<MissionItem> renumbered(const Mission& m) {
  checkMissionItemCount(m.items.size());
  std::vector<MissionItem> out = m.items;
  for (std::size_t k = 0; k < out.size(); ++k) {
    checkWritable(out[k]);
    out[k].seq = static_cast<int>(k) + 1;
    if (out[k].command != static_cast<int>(Command::DoJump)) continue;
    std::size_t j = 0;
    while (j < m.items.size() && m.items[j].seq < m.items[k].param[0]) ++j;
    if (j == m.items.size())
      throw std::invalid_argument("mission item " + std::to_string(m.items[k].seq) + ": DO_JUMP target " +
                                  numberText(m.items[k].param[0]) + " is past the last item");
    out[k].param[0] = static_cast<double>(j + 1);
  }
  return out;
}

json jsonNumber(double v) { return std::isnan(v) ? json(nullptr) : json(v); }

/// A `.plan` speed field: an integer when the value is whole (Mission Planner reads cruiseSpeed and
/// hoverSpeed as int and refuses 5.0), the real otherwise (read back exactly; QGC takes either).
json speedField(double v) {
  if (std::trunc(v) == v && std::abs(v) < 1e9) return json(static_cast<std::int64_t>(v));
  return json(v);
}

/// QGroundControl's AltitudeMode of a frame (1 relative, 2 absolute, 4 terrain frame), 0 for none.
int altitudeMode(int frame) {
  switch (frame) {
    case 3: case 6: return 1;
    case 0: case 5: return 2;
    case 10: case 11: return 4;
    default: return 0;
  }
}

json planItem(const MissionItem& it) {
  json params = json::array();
  for (double p : {it.param[0], it.param[1], it.param[2], it.param[3], it.lat_deg, it.lon_deg, it.alt_m})
    params.push_back(jsonNumber(p));
  json j = {{"autoContinue", it.autocontinue}, {"command", it.command}, {"doJumpId", it.seq},
            {"frame", it.frame},               {"params", params},      {"type", "SimpleItem"}};
  if (isPositional(it.command) && altitudeMode(it.frame) != 0) {
    j["AMSLAltAboveTerrain"] = nullptr;
    j["Altitude"] = jsonNumber(it.alt_m);
    j["AltitudeMode"] = altitudeMode(it.frame);
  }
  return j;
}

}  // namespace

void checkMissionItemCount(std::size_t items) {
  if (items <= kMaxMissionItems) return;
  throw std::invalid_argument("mission: " + std::to_string(items) + " items after home, more than the " +
                              std::to_string(kMaxMissionItems) +
                              " a MAVLink mission can hold (MISSION_COUNT is 16-bit and home is item 0); nothing "
                              "written: widen the line spacing or split the area into several missions");
}

std::string toQgcPlan(const Mission& m) {
  json items = json::array();
  for (const auto& it : renumbered(m)) items.push_back(planItem(it));
  json mission = {{"version", 2},
                  {"firmwareType", m.firmware_type},
                  {"vehicleType", m.vehicle_type},
                  {"plannedHomePosition", {m.home.lat_deg, m.home.lon_deg, m.home.alt_m}},
                  {"items", items}};
  if (!m.home_known) mission["plannedHomePosition"] = {0.0, 0.0, 0.0};
  if (m.plan_cruise_speed_mps > 0.0) mission["cruiseSpeed"] = speedField(m.plan_cruise_speed_mps);
  if (m.plan_hover_speed_mps > 0.0) mission["hoverSpeed"] = speedField(m.plan_hover_speed_mps);
  const json plan = {{"fileType", "Plan"},
                     {"version", 1},
                     {"groundStation", "wattswath"},
                     {"mission", mission},
                     {"geoFence", {{"version", 2}, {"circles", json::array()}, {"polygons", json::array()}}},
                     {"rallyPoints", {{"version", 2}, {"points", json::array()}}}};
  return plan.dump(4) + "\n";
}

std::string toQgcWpl(const Mission& m) {
  std::ostringstream o;
  o << "QGC WPL 110\n";
  const bool home = m.home_known;
  o << "0\t1\t0\t16\t0\t0\t0\t0\t" << numberText(home ? m.home.lat_deg : 0.0) << "\t"
    << numberText(home ? m.home.lon_deg : 0.0) << "\t" << numberText(home ? m.home.alt_m : 0.0) << "\t1\n";
  for (const auto& it : renumbered(m)) {
    o << it.seq << "\t0\t" << it.frame << "\t" << it.command;
    // NaN ("unchanged", e.g. a yaw) as Mission Planner writes it (.NET's NaN symbol, which QGroundControl's
    // QString::toDouble also reads); 0 would be a yaw of north for PX4.
    for (double p : {it.param[0], it.param[1], it.param[2], it.param[3], it.lat_deg, it.lon_deg, it.alt_m})
      o << "\t" << (std::isnan(p) ? std::string("NaN") : numberText(p));
    o << "\t" << (it.autocontinue ? 1 : 0) << "\n";
  }
  return o.str();
}

}  // namespace wattswath::mission
