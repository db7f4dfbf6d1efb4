#include "wattswath/mission/scurve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wattswath::mission {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct State {
  double acc = 0.0, vel = 0.0, pos = 0.0;
};

// State after `tau` [s] of a segment of `kind` (0 constant jerk, 1 rising raised-cosine jerk, 2
// falling) with (peak) jerk `jerk` and ramp time `tj`, from `s`. Our own integrals of
// j(t) = J/2 (1 -+ cos(pi t / tj)).
State advance(int kind, double tau, double jerk, double tj, const State& s) {
  State r;
  const double base_v = s.vel + s.acc * tau;
  const double base_p = s.pos + s.vel * tau + 0.5 * s.acc * tau * tau;
  if (kind == 0 || tj <= 0.0) {
    const double j = kind == 0 ? jerk : 0.0;
    r.acc = s.acc + j * tau;
    r.vel = base_v + 0.5 * j * tau * tau;
    r.pos = base_p + j * tau * tau * tau / 6.0;
    return r;
  }
  const double k = tj / kPi, h = 0.5 * jerk, sn = std::sin(tau / k), cs = std::cos(tau / k);
  const double sign = kind == 1 ? -1.0 : 1.0;  // rising: 1 - cos; falling: 1 + cos
  r.acc = s.acc + h * (tau + sign * k * sn);
  r.vel = base_v + h * (0.5 * tau * tau - sign * k * k * (cs - 1.0));
  r.pos = base_p + h * (tau * tau * tau / 6.0 + sign * (k * k * tau - k * k * k * sn));
  return r;
}

// State at the end of a whole speed change `c` from `s` (sign +1 speeds up, -1 slows down).
State runChange(const SpeedChange& c, double sign, State s) {
  const double j = sign * c.jerk;
  s = advance(1, c.tj, j, c.tj, s);
  s = advance(0, c.t2, j, c.tj, s);
  s = advance(2, c.tj, j, c.tj, s);
  s = advance(0, c.t4, 0.0, c.tj, s);
  s = advance(1, c.tj, -j, c.tj, s);
  s = advance(0, c.t2, -j, c.tj, s);
  s = advance(2, c.tj, -j, c.tj, s);
  return s;
}

// Largest x in [lo, hi] with ok(x) true, given ok(lo) (bisection; ok is monotone).
template <class F>
double largestFeasible(double lo, double hi, F ok) {
  if (ok(hi)) return hi;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (ok(mid) ? lo : hi) = mid;
  }
  return lo;
}

void checkLimit(const char* name, double v) {
  if (!(v > 0.0 && std::isfinite(v))) {
    throw std::invalid_argument(std::string("SCurveLimits.") + name + " = " + std::to_string(v) +
                                ", expected a positive finite value");
  }
}

}  // namespace

SpeedChangeExtent extentOf(const SpeedChange& c, double v0) {
  State s;
  s.vel = v0;
  const State e = runChange(c, 1.0, s);
  return {e.pos, e.vel - v0, 4.0 * c.tj + 2.0 * c.t2 + c.t4};
}

SpeedChange planSpeedChange(double v0, double vmax, double distance, const SCurveLimits& lim) {
  SpeedChange c;
  if (!(vmax > v0) || !(distance > 0.0)) return c;
  double tj = lim.jerk * kPi / (2.0 * lim.snap);
  double jerk = lim.jerk, accel = lim.accel;
  const double a_reach = std::min({accel, (vmax - v0) / (2.0 * tj), (distance - 4.0 * v0 * tj) / (4.0 * tj * tj)});
  if (!(a_reach > 0.0)) return c;
  auto fits = [&](const SpeedChange& x) {
    const SpeedChangeExtent e = extentOf(x, v0);
    return e.distance <= distance * (1.0 + 1e-12) && v0 + e.speed_gain <= vmax * (1.0 + 1e-12);
  };
  if (a_reach < jerk * tj) {
    // The jerk ramps alone reach more than the acceleration that fits: shorten them.
    if (v0 == 0.0) {
      tj = std::min({tj, std::pow(distance * kPi / (8.0 * lim.snap), 0.25), std::cbrt(vmax * kPi / (4.0 * lim.snap)),
                     std::sqrt(accel * kPi / (2.0 * lim.snap))});
      jerk = 2.0 * lim.snap * tj / kPi;
    } else {
      jerk = a_reach / tj;
    }
    c.jerk = jerk;
    c.tj = tj;
    accel = jerk * tj;
    const double t4_speed = std::max(0.0, (vmax - v0) / accel - 2.0 * tj);
    c.t4 = largestFeasible(0.0, t4_speed, [&](double t4) {
      SpeedChange x = c;
      x.t4 = t4;
      return fits(x);
    });
    return c;
  }
  c.jerk = jerk;
  c.tj = tj;
  // Full jerk: find the largest acceleration (with no constant-acceleration time) that fits, then
  // the constant-acceleration time.
  auto withAccel = [&](double a, double t4) {
    SpeedChange x = c;
    x.t2 = std::max(0.0, a / jerk - tj);
    x.t4 = t4;
    return x;
  };
  const double a = largestFeasible(jerk * tj, accel, [&](double a_try) { return fits(withAccel(a_try, 0.0)); });
  if (a < accel) return withAccel(a, 0.0);
  const double t4_speed = std::max(0.0, (vmax - v0 - accel * tj - accel * accel / jerk) / accel);
  const double t4 = largestFeasible(0.0, t4_speed, [&](double t4_try) { return fits(withAccel(accel, t4_try)); });
  return withAccel(accel, t4);
}

void SCurveProfile::push(int& i, Kind kind, double duration, double jerk) {
  const State prev{end_acc_[i - 1], end_vel_[i - 1], end_pos_[i - 1]};
  const double tj = duration;
  const int k = kind == Kind::ConstJerk ? 0 : (kind == Kind::IncrJerk ? 1 : 2);
  const State s = duration > 0.0 ? advance(k, duration, jerk, tj, prev) : prev;
  kind_[i] = kind;
  jerk_[i] = jerk;
  end_time_[i] = end_time_[i - 1] + std::max(duration, 0.0);
  end_acc_[i] = s.acc;
  end_vel_[i] = s.vel;
  end_pos_[i] = s.pos;
  ++i;
}

void SCurveProfile::pushJerkRamp(int& i, double tj, double jerk, double t_const) {
  push(i, Kind::IncrJerk, tj, jerk);
  push(i, Kind::ConstJerk, t_const, jerk);
  push(i, Kind::DecrJerk, tj, jerk);
}

void SCurveProfile::pushPhase(int& i, double tj, double jerk, double t2, double t4) {
  pushJerkRamp(i, tj, jerk, t2);
  push(i, Kind::ConstJerk, t4, 0.0);
  pushJerkRamp(i, tj, -jerk, t2);
}

SCurveProfile SCurveProfile::restToRest(double length, const SCurveLimits& limits) { return between(length, 0.0, 0.0, limits); }

SCurveProfile SCurveProfile::between(double length, double origin_speed, double destination_speed, const SCurveLimits& limits) {
  checkLimit("speed", limits.speed);
  checkLimit("accel", limits.accel);
  checkLimit("jerk", limits.jerk);
  checkLimit("snap", limits.snap);
  if (!(length >= 0.0) || !std::isfinite(length)) {
    throw std::invalid_argument("S-curve leg length " + std::to_string(length) + " m, expected a finite value >= 0");
  }
  if (!(origin_speed >= 0.0 && destination_speed >= 0.0 && std::isfinite(origin_speed) && std::isfinite(destination_speed))) {
    throw std::invalid_argument("S-curve end speeds " + std::to_string(origin_speed) + " and " + std::to_string(destination_speed) +
                                " m/s, expected finite values >= 0");
  }
  SCurveProfile p;
  p.length_ = length;
  p.limits_ = limits;
  if (length == 0.0) return p;
  // The rest-to-rest peak speed Vm (SCurve::calculate_track), then each end's speed change from its
  // own speed (at most Vm) to Vm within half the leg (set_origin_speed_max / set_destination_speed_max).
  const SpeedChange rest = planSpeedChange(0.0, limits.speed, 0.5 * length, limits);
  const double vm = extentOf(rest, 0.0).speed_gain;
  const double v0 = std::min(origin_speed, vm), v1 = std::min(destination_speed, vm);
  const SpeedChange up = v0 > 0.0 ? planSpeedChange(v0, vm, 0.5 * length, limits) : rest;
  const SpeedChange down = v1 > 0.0 ? planSpeedChange(v1, vm, 0.5 * length, limits) : rest;
  p.end_vel_[0] = v0;
  int i = 1;
  p.pushPhase(i, up.tj, up.jerk, up.t2, up.t4);
  p.end_acc_[kAccelEnd] = 0.0;  // rounding of the ramps
  p.hold(kAccelEnd + 1, kSpeedChangeEnd, kAccelEnd);
  i = kSpeedChangeEnd + 1;
  const double v = p.end_vel_[kAccelEnd];
  const double down_distance = extentOf(down, v1).distance;
  const double cruise = v > 0.0 ? std::max(0.0, (length - p.end_pos_[kAccelEnd] - down_distance) / v) : 0.0;
  p.push(i, Kind::ConstJerk, cruise, 0.0);
  p.pushPhase(i, down.tj, -down.jerk, down.t2, down.t4);
  p.end_acc_[kSegments - 1] = 0.0;
  p.end_vel_[kSegments - 1] = v1;
  return p;
}

// Segment k as given: its kind, (peak) jerk and its state at its end.
void SCurveProfile::set(int k, Kind kind, double jerk, double time, double acc, double vel, double pos) {
  kind_[k] = kind;
  jerk_[k] = jerk;
  end_time_[k] = time;
  end_acc_[k] = acc;
  end_vel_[k] = vel;
  end_pos_[k] = pos;
}

// Segments first..last empty, at the time, speed and position segment `ref` ends with.
void SCurveProfile::hold(int first, int last, int ref) {
  for (int k = first; k <= last; ++k) set(k, Kind::ConstJerk, 0.0, end_time_[ref], 0.0, end_vel_[ref], end_pos_[ref]);
}

// Lengthens the cruise so that the leg ends at its length (SCurve's "t15").
void SCurveProfile::stretchCruise() {
  end_acc_[kDecelEnd] = 0.0;
  end_vel_[kDecelEnd] = std::max(0.0, end_vel_[kDecelEnd]);
  const double dp = std::max(0.0, length_ - end_pos_[kDecelEnd]);
  const double v = end_vel_[kConst];
  if (!(v > 0.0)) return;
  for (int k = kConst; k <= kDecelEnd; ++k) {
    end_time_[k] += dp / v;
    end_pos_[k] += dp;
  }
}

// In the speed change: it becomes the acceleration phase, leaving room for another change.
void SCurveProfile::restartAfterSpeedChange() {
  set(0, Kind::ConstJerk, 0.0, end_time_[kAccelEnd], end_acc_[kAccelEnd], end_vel_[kAccelEnd], end_pos_[kAccelEnd]);
  for (int k = 1; k <= kAccelEnd; ++k) {
    const int from = k + (kSpeedChangeEnd - kAccelEnd);
    set(k, kind_[from], jerk_[from], end_time_[from], end_acc_[from], end_vel_[from], end_pos_[from]);
  }
  hold(kAccelEnd + 1, kSpeedChangeEnd, kAccelEnd);
}

// In the cruise: the acceleration and speed-change phases become the cruise flown so far.
void SCurveProfile::restartInCruise(double time) {
  const TrackState now = at(time);
  hold(0, 0, kSpeedChangeEnd);
  for (int k = 1; k <= kSpeedChangeEnd; ++k) set(k, Kind::ConstJerk, 0.0, time, 0.0, now.vel, now.pos);
}

// A slower speed before the constant acceleration has ended: the acceleration is re-planned to
// the new speed, or to the slowest that cutting that segment short still allows.
void SCurveProfile::shortenAcceleration(double time) {
  const double v_min =
      end_vel_[kAccelEnd] - end_acc_[kAccelMax] * (end_time_[kAccelMax] - std::max(time, end_time_[kAccelMax - 1]));
  const double v_target = std::max(v_min, limits_.speed);
  const SpeedChange up = planSpeedChange(end_vel_[0], v_target, 0.5 * length_, limits_);
  int i = 1;
  pushPhase(i, up.tj, up.jerk, up.t2, up.t4);
  end_acc_[kAccelEnd] = 0.0;
  hold(kAccelEnd + 1, kConst, kAccelEnd);
  const SpeedChange down = planSpeedChange(0.0, v_target, 0.5 * length_, limits_);
  i = kConst + 1;
  pushPhase(i, down.tj, -down.jerk, down.t2, down.t4);
  stretchCruise();
}

// The speed change from the acceleration's end speed to the new speed limit, within half the
// cruise, when the cruise is long enough (SCurve::set_speed_max's rule). ArduPilot writes the jerk
// time as min(powf(x, 1/3), tj): the integer 1/3 is 0, so the first term is 1 s and the rule is
// 12 min(1 s, tj); we keep what the autopilot computes.
void SCurveProfile::planSpeedChangeSegments() {
  hold(kAccelEnd + 1, kSpeedChangeEnd, kAccelEnd);
  const double v = end_vel_[kAccelEnd];
  if (limits_.speed == v || !(v > 0.0)) return;
  const double cruise = end_pos_[kConst] - end_pos_[kAccelEnd];
  const double jerk_time = std::min(1.0, limits_.jerk * kPi / (2.0 * limits_.snap));
  SpeedChange c;
  double sign = 1.0;
  if (limits_.speed < v && jerk_time * 12.0 < cruise / v) {
    c = planSpeedChange(limits_.speed, v, 0.5 * cruise, limits_);
    sign = -1.0;
  } else if (limits_.speed > v && cruise / (jerk_time * 12.0) > v) {
    c = planSpeedChange(v, std::min(limits_.speed, cruise / (jerk_time * 12.0)), 0.5 * cruise, limits_);
  }
  if (c.jerk == 0.0) return;
  int i = kAccelEnd + 1;
  pushPhase(i, c.tj, sign * c.jerk, c.t2, c.t4);
  end_acc_[kSpeedChangeEnd] = 0.0;
}

// The braking from the cruise to `end_speed` [m/s] within what is left of the leg.
void SCurveProfile::planDeceleration(double end_speed) {
  int i = kConst;
  push(i, Kind::ConstJerk, 0.0, 0.0);
  const double v = end_vel_[kConst];
  if (end_speed < v) {
    const SpeedChange c = planSpeedChange(end_speed, v, length_ - end_pos_[kConst], limits_);
    pushPhase(i, c.tj, -c.jerk, c.t2, c.t4);
  } else {
    hold(kConst + 1, kDecelEnd, kConst);
  }
  stretchCruise();
}

void SCurveProfile::setSpeedMax(double time, double speed) {
  if (length_ == 0.0 || !(speed > 0.0) || !std::isfinite(speed) || speed == limits_.speed) return;
  limits_.speed = speed;
  if (time >= end_time_[kConst]) return;
  const double end_speed = std::min(speed, end_vel_[kDecelEnd]);
  if (!(time > 0.0)) {
    *this = between(length_, std::min(speed, end_vel_[0]), end_speed, limits_);
    return;
  }
  if (time >= end_time_[kAccelEnd] && time <= end_time_[kSpeedChangeEnd]) {
    restartAfterSpeedChange();
  } else if (time > end_time_[kSpeedChangeEnd]) {
    restartInCruise(time);
  }
  if (time <= end_time_[kAccelMax] && end_time_[kAccelMax] > end_time_[kAccelMax - 1] && speed < end_vel_[kAccelEnd] &&
      end_acc_[kAccelMax] > 0.0) {
    shortenAcceleration(time);
  }
  planSpeedChangeSegments();
  planDeceleration(std::min(end_speed, end_vel_[kSpeedChangeEnd]));
}

TrackState SCurveProfile::at(double t) const {
  if (!(t > end_time_[0])) return {end_pos_[0], end_vel_[0], end_acc_[0]};
  if (t >= duration()) return {length_, end_vel_[kSegments - 1], 0.0};
  int i = 1;
  while (i < kSegments - 1 && t >= end_time_[i]) ++i;
  const State prev{end_acc_[i - 1], end_vel_[i - 1], end_pos_[i - 1]};
  const double tj = end_time_[i] - end_time_[i - 1];
  const int k = kind_[i] == Kind::ConstJerk ? 0 : (kind_[i] == Kind::IncrJerk ? 1 : 2);
  const State s = advance(k, t - end_time_[i - 1], jerk_[i], tj, prev);
  return {std::min(s.pos, length_), std::max(s.vel, 0.0), s.acc};
}

}  // namespace wattswath::mission
