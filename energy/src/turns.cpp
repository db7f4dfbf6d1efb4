#include "wattswath/energy/turns.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "wattswath/energy/format.hpp"

namespace wattswath::energy {
namespace {

using detail::formatNumber;

void checkCommon(double d, double beta, double yaw_rate) {
  if (!(d > 0.0) || !std::isfinite(d)) {
    throw std::invalid_argument("turn strategies: leg length = " + formatNumber(d) + " m, expected a finite value > 0");
  }
  if (!(beta >= kMinTurnAngle && beta <= M_PI)) {
    throw std::invalid_argument("turn strategies: angle beta = " + formatNumber(beta * 180.0 / M_PI) +
                                " deg, expected an interior angle in [" + formatNumber(kMinTurnAngle * 180.0 / M_PI) +
                                ", 180] deg (below it the legs nearly fold back onto each other and the rounded "
                                "turn's overshoot R cot(beta/2) grows without bound: 1.2 km at 1 deg)");
  }
  if (!(yaw_rate > 0.0) || !std::isfinite(yaw_rate)) {
    throw std::invalid_argument("turn strategies: max yaw rate = " + formatNumber(yaw_rate) + " rad/s, expected > 0");
  }
}

void checkSpeed(const char* what, double v, double v_max) {
  if (!(v > 0.0) || !(v <= v_max) || !std::isfinite(v)) {
    throw std::invalid_argument(std::string("turn strategies: ") + what + " = " + formatNumber(v) + " m/s, expected (0, " +
                                formatNumber(v_max) + "]");
  }
}

}  // namespace

double roundedOvershoot(double radius, double beta) { return radius * std::cos(0.5 * beta) / std::sin(0.5 * beta); }

double roundedExtraLength(double radius, double beta) {
  const double cot_half = std::cos(0.5 * beta) / std::sin(0.5 * beta);  // (1 + cos b) / sin b
  return 2.0 * radius * cot_half + radius * (M_PI + beta);
}

SharpStopTurn sharpStopTurn(const EnergyModel& model, double d, double beta, double speed, const ProfileLimits& lim,
                            double yaw_rate) {
  checkCommon(d, beta, yaw_rate);
  std::vector<Piece> pieces = buildLegProfile(d, 0.0, speed, 0.0, lim);
  SharpStopTurn s;
  s.speed = speed;
  s.leg_energy = model.energy(pieces);
  const Piece turn = turnInPlace(M_PI - beta, yaw_rate);
  s.turn_energy = model.energy({turn});
  pieces.push_back(turn);
  for (const auto& p : buildLegProfile(d, 0.0, speed, 0.0, lim)) pieces.push_back(p);
  s.breakdown = model.evaluate(pieces);
  s.energy = s.breakdown.total();
  s.time = s.breakdown.time;
  return s;
}

RoundedTurn roundedTurn(const EnergyModel& model, double d, double beta, double speed, const ProfileLimits& lim,
                        double yaw_rate, bool from_rest) {
  checkCommon(d, beta, yaw_rate);
  RoundedTurn r;
  r.speed = speed;
  r.radius = speed / yaw_rate;
  r.extra_length = roundedExtraLength(r.radius, beta);
  r.path_length = 2.0 * d + r.extra_length;
  // Each branch is extended by R cot(beta/2) past the vertex; the loop turns (pi + beta) on radius R.
  const double branch = d + roundedOvershoot(r.radius, beta);
  std::vector<Piece> pieces = buildLegProfile(branch, from_rest ? 0.0 : speed, speed, speed, lim);
  pieces.push_back(arc(r.radius, M_PI + beta, speed));
  for (const auto& p : buildLegProfile(branch, speed, speed, from_rest ? 0.0 : speed, lim)) pieces.push_back(p);
  r.breakdown = model.evaluate(pieces);
  r.energy = r.breakdown.total();
  r.time = r.breakdown.time;
  return r;
}

TurnComparison compareTurnStrategies(const EnergyModel& model, double d, double beta, const ProfileLimits& lim,
                                     double yaw_rate, double v_max, const TurnSettings& st) {
  checkCommon(d, beta, yaw_rate);
  if (!(v_max > 0.0) || !std::isfinite(v_max)) {
    throw std::invalid_argument("turn strategies: v_max = " + formatNumber(v_max) + " m/s, expected a finite value > 0");
  }
  TurnComparison c;
  double v1 = 0.0;
  if (st.sharp_speed) {
    v1 = *st.sharp_speed;
    checkSpeed("sharp-stop speed", v1, v_max);
  } else {
    v1 = optimalCruiseSpeed(model, d, 0.0, 0.0, lim, v_max, st.search).speed;
  }
  c.sharp_stop = sharpStopTurn(model, d, beta, v1, lim, yaw_rate);
  double v2 = 0.0;
  if (st.rounded_speed) {
    v2 = *st.rounded_speed;
    checkSpeed("rounded speed", v2, v_max);
  } else {
    auto energyAt = [&](double v) {
      try {
        return roundedTurn(model, d, beta, v, lim, yaw_rate, st.rounded_from_rest).energy;
      } catch (const std::invalid_argument&) {
        return std::numeric_limits<double>::infinity();  // cannot reach v from rest on this branch
      }
    };
    v2 = minimiseOnInterval(energyAt, std::min(st.search.min_speed, 0.5 * v_max), v_max, st.search);
  }
  c.rounded = roundedTurn(model, d, beta, v2, lim, yaw_rate, st.rounded_from_rest);
  c.saving_pct = 100.0 * (c.sharp_stop.energy - c.rounded.energy) / c.sharp_stop.energy;
  return c;
}

}  // namespace wattswath::energy
