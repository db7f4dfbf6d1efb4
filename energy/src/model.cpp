#include "wattswath/energy/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wattswath::energy {

double Breakdown::total() const {
  double s = 0.0;
  for (const auto& row : energy)
    for (double e : row) s += e;
  return s;
}

double Breakdown::byEffect(const std::string& name) const {
  for (size_t i = 0; i < effects.size(); ++i) {
    if (effects[i] == name) {
      double s = 0.0;
      for (double e : energy[i]) s += e;
      return s;
    }
  }
  return 0.0;
}

double Breakdown::byPhase(Phase p) const {
  double s = 0.0;
  for (const auto& row : energy) s += row[static_cast<int>(p)];
  return s;
}

double Breakdown::at(const std::string& name, Phase p) const {
  for (size_t i = 0; i < effects.size(); ++i) {
    if (effects[i] == name) return energy[i][static_cast<int>(p)];
  }
  return 0.0;
}

Breakdown& Breakdown::operator+=(const Breakdown& o) {
  if (o.effects != effects) throw std::invalid_argument("Breakdown::operator+=: effects differ");
  for (size_t i = 0; i < energy.size(); ++i)
    for (int k = 0; k < kPhaseCount; ++k) energy[i][k] += o.energy[i][k];
  time += o.time;
  length += o.length;
  return *this;
}

EnergyModel::EnergyModel(const EnergyModel& other) {
  for (const auto& e : other.effects_) effects_.push_back(e->clone());
}

EnergyModel& EnergyModel::operator=(const EnergyModel& other) {
  if (this != &other) {
    std::vector<std::unique_ptr<Effect>> copy;
    for (const auto& e : other.effects_) copy.push_back(e->clone());
    effects_ = std::move(copy);
  }
  return *this;
}

EnergyModel& EnergyModel::add(std::unique_ptr<Effect> effect) {
  if (!effect) throw std::invalid_argument("EnergyModel::add: null effect");
  if (has(effect->name())) throw std::invalid_argument("EnergyModel::add: effect '" + effect->name() + "' already present");
  effects_.push_back(std::move(effect));
  return *this;
}

EnergyModel& EnergyModel::remove(const std::string& name) {
  effects_.erase(std::remove_if(effects_.begin(), effects_.end(), [&](const auto& e) { return e->name() == name; }),
                 effects_.end());
  return *this;
}

bool EnergyModel::has(const std::string& name) const {
  return std::any_of(effects_.begin(), effects_.end(), [&](const auto& e) { return e->name() == name; });
}

Effect& EnergyModel::effect(const std::string& name) {
  for (auto& e : effects_)
    if (e->name() == name) return *e;
  throw std::out_of_range("energy model has no effect '" + name + "'");
}

const Effect& EnergyModel::effect(const std::string& name) const {
  return const_cast<EnergyModel*>(this)->effect(name);
}

std::vector<std::string> EnergyModel::effectNames() const {
  std::vector<std::string> n;
  for (const auto& e : effects_) n.push_back(e->name());
  return n;
}

double EnergyModel::power(const MotionState& s) const {
  double p = 0.0;
  for (const auto& e : effects_) p += e->power(s);
  return p;
}

double EnergyModel::energy(const std::vector<Piece>& pieces) const {
  double sum = 0.0;
  for (const auto& e : effects_)
    for (const auto& p : pieces) sum += e->energy(p);
  return sum;
}

Breakdown EnergyModel::emptyBreakdown() const {
  Breakdown b;
  b.effects = effectNames();
  b.energy.assign(effects_.size(), std::array<double, kPhaseCount>{});
  return b;
}

void EnergyModel::accumulate(const std::vector<Piece>& pieces, Breakdown& out) const {
  if (out.energy.size() != effects_.size()) throw std::invalid_argument("EnergyModel::accumulate: breakdown shape");
  for (size_t i = 0; i < effects_.size(); ++i)
    for (const auto& p : pieces) out.energy[i][static_cast<int>(p.phase)] += effects_[i]->energy(p);
  for (const auto& p : pieces) {
    out.time += p.duration;
    out.length += p.length;
  }
}

Breakdown EnergyModel::evaluate(const std::vector<Piece>& pieces) const {
  Breakdown b = emptyBreakdown();
  accumulate(pieces, b);
  return b;
}

double EnergyModel::levelPower(double v, double heading) const {
  MotionState s;
  s.velocity = Eigen::Vector3d(v * std::cos(heading), v * std::sin(heading), 0.0);
  s.heading = heading;
  return power(s);
}

double EnergyModel::minEnergyPerMetre(double v_max) const {
  if (!(v_max > 0.0)) throw std::invalid_argument("minEnergyPerMetre: v_max must be > 0");
  double best = std::numeric_limits<double>::infinity();
  const int n = 2000;
  for (int i = 1; i <= n; ++i) {
    const double v = v_max * i / n;
    // The worst heading matters only for heading-dependent effects (wind); check 8 of them.
    for (int h = 0; h < 8; ++h) best = std::min(best, levelPower(v, h * M_PI / 4.0) / v);
  }
  return 0.99 * best;  // 1 % margin for the grid: stays a lower bound for smooth P(v)
}

EnergyModel marinsModel(const Vehicle& v, DragIntegration drag) {
  EnergyModel m;
  m.add(HoverEffect::fromVehicle(v));
  m.add(KineticEffect::fromVehicle(v));
  m.add(ParasiticDragEffect::fromVehicle(v, drag));
  m.add(YawRateEffect(0.0));
  return m;
}

}  // namespace wattswath::energy
