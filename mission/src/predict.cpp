#include "wattswath/mission/predict.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wattswath::mission {
namespace {

void batteryAlong(const energy::Battery& b, const FlightPieces& fp, const std::vector<double>& e, double reserve,
                  BatteryPrediction& out) {
  std::vector<energy::PowerStep> profile;
  profile.reserve(fp.pieces.size());
  for (std::size_t i = 0; i < fp.pieces.size(); ++i) {
    const double d = fp.pieces[i].duration;
    profile.push_back({d, d > 0.0 ? std::max(0.0, e[i] / d) : 0.0});
  }
  energy::DischargeSettings ds;
  ds.dt_s = 1.0;
  const energy::EnduranceResult r = energy::simulateProfile(b, profile, ds);
  out.known = true;
  out.reserve_fraction = reserve;
  for (const auto& smp : r.series) {
    out.t_s.push_back(smp.t);
    out.usable_left.push_back(std::min(smp.usable_left, 1.0));
    out.voltage_v.push_back(smp.voltage_v);
  }
  out.depleted = r.depleted;
  out.depleted_at_s = r.depleted ? r.endurance_s : 0.0;
  const double left = (r.final_residual_ah - energy::cutoffResidualAh(b)) / (b.pack.usable_fraction * b.capacityAh());
  out.usable_left_end = r.depleted ? 0.0 : std::min(left, 1.0);
  out.fits = !r.depleted && out.usable_left_end >= reserve;
  std::ostringstream v;
  v.precision(3);
  if (r.depleted) {
    v << "Does not fit: the battery reaches its cut-off " << r.endurance_s << " s into the flight.";
  } else if (!out.fits) {
    v << "Fits, but lands with " << 100.0 * out.usable_left_end << " % of the usable charge, below the "
      << 100.0 * reserve << " % reserve.";
  } else {
    v << "Fits: lands with " << 100.0 * out.usable_left_end << " % of the usable charge (reserve " << 100.0 * reserve
      << " %).";
  }
  out.verdict = v.str();
}

}  // namespace

MissionPrediction predictMission(const Mission& m, const energy::Vehicle& v, const energy::EnergyModel& model,
                                 const AutopilotConfig& autopilot, const PredictSettings& s) {
  if (!(s.reserve_fraction >= 0.0 && s.reserve_fraction <= 0.9)) {
    throw std::invalid_argument("reserve fraction " + std::to_string(s.reserve_fraction) + ", expected 0..0.9");
  }
  MissionPrediction p;
  p.warnings = m.warnings;
  const std::vector<NavStep> steps = sequenceMission(m, &p.warnings);
  FlightSettings fs = s.flight;
  if (s.airframe_from_vehicle) fs.airframe = airframeOfVehicle(v, v.name);
  p.flight = flyMission(steps, autopilot, fs);
  p.pieces = toPieces(p.flight);
  p.breakdown = model.emptyBreakdown();
  p.piece_energy_j.resize(p.pieces.pieces.size());
  p.items.resize(steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    ItemPrediction& it = p.items[k];
    it.step = static_cast<int>(k);
    it.item = steps[k].item;
    it.seq = it.item >= 0 ? m.items[it.item].seq : -1;
    it.command = it.item >= 0 ? commandName(m.items[it.item].command) : "NAV_TAKEOFF (assumed)";
    it.reached_s = p.flight.events[k].reached_s;
    it.completed_s = p.flight.events[k].completed_s;
  }
  for (std::size_t i = 0; i < p.pieces.pieces.size(); ++i) {
    const std::vector<energy::Piece> one{p.pieces.pieces[i]};
    model.accumulate(one, p.breakdown);
    const double e = model.energy(one);
    p.piece_energy_j[i] = e;
    const energy::Piece& pc = p.pieces.pieces[i];
    for (Totals* t : {&p.total, &p.phases[static_cast<int>(p.pieces.phase[i])],
                      &p.items[std::clamp(p.pieces.step[i], 0, static_cast<int>(steps.size()) - 1)].totals}) {
      t->energy_j += e;
      t->time_s += pc.duration;
      t->distance_m += pc.length;
    }
  }
  p.breakdown.time = p.total.time_s;
  p.breakdown.length = p.total.distance_m;
  for (const std::string& n : p.flight.notes) p.warnings.push_back(n);
  if (v.battery) batteryAlong(*v.battery, p.pieces, p.piece_energy_j, s.reserve_fraction, p.battery);
  return p;
}

}  // namespace wattswath::mission
