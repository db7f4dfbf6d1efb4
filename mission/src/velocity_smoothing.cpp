// PX4's VelocitySmoothing (src/lib/motion_planning/VelocitySmoothing.cpp) in our own words: the
// phase durations of the quickest jerk-limited velocity change and its evaluation.
#include "velocity_smoothing.hpp"

#include <algorithm>
#include <cmath>

namespace wattswath::mission::detail {
namespace {

constexpr double kEps = 1.1920929e-07;  // FLT_EPSILON, PX4's threshold

int signOf(double x) { return (0.0 < x) - (x < 0.0); }

// T1 shortened so that the acceleration a0 + j T1 stays within +-a_max.
double saturateT1(double a0, double j, double t1, double a_max) {
  const double a_end = a0 + j * t1;
  if (a_end > a_max) return (a_max - a0) / j;
  if (a_end < -a_max) return (-a_max - a0) / j;
  return t1;
}

// The first of the two roots (T1, T3 = a0 / j + T1) that are both non-negative, else 0.
double pickT1(double plus, double minus, double a0, double j) {
  if (plus >= 0.0 && a0 / j + plus >= 0.0) return plus;
  if (minus >= 0.0 && a0 / j + minus >= 0.0) return minus;
  return 0.0;
}

// Jerk phase [s] of the quickest change of velocity by dv from acceleration a0 with jerk j (signed).
double quickestT1(double a0, double dv, double j, double a_max) {
  const double delta = 2.0 * a0 * a0 + 4.0 * j * dv;
  if (delta < 0.0) return 0.0;
  const double s = std::sqrt(delta);
  const double t1 = pickT1((-a0 + 0.5 * s) / j, (-a0 - 0.5 * s) / j, a0, j);
  return std::max(saturateT1(a0, j, t1, a_max), 0.0);
}

// Jerk phase [s] of the change of velocity by dv that lasts `total` [s].
double timedT1(double total, double a0, double dv, double j, double a_max) {
  const double b = j * total - a0;
  const double delta = total * total * j * j + 2.0 * total * a0 * j - a0 * a0 - 4.0 * j * dv;
  if (delta < 0.0) return 0.0;
  const double s = std::sqrt(delta), inv = 1.0 / (-2.0 * j);
  const double plus = std::max((-b + s) * inv, 0.0), minus = std::max((-b - s) * inv, 0.0);
  double t1 = 0.0;
  if (a0 / j + plus >= 0.0 && plus + a0 / j + plus <= total) t1 = plus;
  else if (a0 / j + minus >= 0.0 && minus + a0 / j + minus <= total) t1 = minus;
  return saturateT1(a0, j, t1, a_max);
}

// Constant-acceleration phase [s] after T1 and before T3 that completes the change dv.
double middleT2(double t1, double t3, double a0, double dv, double j) {
  const double den = a0 + j * t1;
  if (std::abs(den) <= kEps) return 0.0;
  return std::max((-0.5 * t1 * t1 * j - t1 * t3 * j - t1 * a0 + 0.5 * t3 * t3 * j - t3 * a0 + dv) / den, 0.0);
}

}  // namespace

int JerkLimitedAxis::direction() const {
  // The velocity reached if the acceleration were brought to zero now at full jerk.
  double v_zero_acc = v_;
  if (std::abs(a_) > kEps) {
    const double j = -signOf(a_) * max_jerk_, t = -a_ / j;
    v_zero_acc = v_ + a_ * t + 0.5 * j * t * t;
  }
  const int d = signOf(v_sp_ - v_zero_acc);
  return d != 0 ? d : signOf(a_);
}

void JerkLimitedAxis::plan(double v_sp) {
  v_sp_ = std::clamp(v_sp, -max_vel_, max_vel_);
  local_ = 0.0;
  x0_ = x_, v0_ = v_, a0_ = a_;
  dir_ = direction();
  const double j = dir_ * max_jerk_, dv = v_sp_ - v_;
  if (std::abs(j) <= kEps) {
    t1_ = t2_ = t3_ = 0.0;
    return;
  }
  t1_ = quickestT1(a_, dv, j, max_accel_);
  t3_ = std::max(a_ / j + t1_, 0.0);
  t2_ = middleT2(t1_, t3_, a_, dv, j);
}

void JerkLimitedAxis::planInTime(double total_s) {
  const double j = dir_ * max_jerk_, dv = v_sp_ - v0_;
  if (std::abs(j) <= kEps) {
    t1_ = t2_ = t3_ = 0.0;
    return;
  }
  t1_ = timedT1(total_s, a0_, dv, j, max_accel_);
  t3_ = std::max(a0_ / j + t1_, 0.0);
  t2_ = std::max(total_s - t1_ - t3_, 0.0);
}

void JerkLimitedAxis::advance(double dt) {
  local_ += dt;
  double t = local_;
  double a = a0_, v = v0_, x = x0_;
  // Constant jerk j for time s from (a, v, x).
  const auto run = [&](double j, double s) {
    x += v * s + 0.5 * a * s * s + j * s * s * s / 6.0;
    v += a * s + 0.5 * j * s * s;
    a += j * s;
  };
  const double s1 = std::min(t, t1_);
  run(dir_ * max_jerk_, s1);
  t -= s1;
  if (t > 0.0) {
    const double s2 = std::min(t, t2_);
    run(0.0, s2);
    t -= s2;
  }
  if (t > 0.0) {
    const double s3 = std::min(t, t3_);
    run(-dir_ * max_jerk_, s3);
    t -= s3;
  }
  if (t > 0.0) {
    a = 0.0;
    run(0.0, t);
  }
  x_ = x, v_ = v, a_ = a;
}

void synchronise(std::array<JerkLimitedAxis, 3>& axes) {
  std::size_t longest = 0;
  double total = 0.0;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (axes[i].totalTime() > total) total = axes[i].totalTime(), longest = i;
  }
  if (total <= kEps) return;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (i != longest && axes[i].totalTime() < total) axes[i].planInTime(total);
  }
}

}  // namespace wattswath::mission::detail
