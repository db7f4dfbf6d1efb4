// The airframe's drag from an ArduPilot log's attitude and EKF velocity, and its response from the
// position controller's target and achieved acceleration (airframe.hpp).
#include "wattswath/logs/airframe.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <boost/math/tools/minima.hpp>

#include "binary_read.hpp"
#include "wattswath/logs/dataflash.hpp"

namespace wattswath::logs {
namespace {

constexpr double kG = 9.80665;  // [m/s^2]

struct Series {
  std::vector<double> t, n, e;  // [s], north and east velocity [m/s]
  std::string source;
};

// EKF (or position controller) velocity, first core only.
Series velocity(const dataflash::Log& L) {
  for (const char* name : {"XKF1", "NKF1", "EKF1", "PSCN"}) {
    const std::string m = name;
    if (m == "PSCN" ? !(L.has("PSCN", "VN") && L.has("PSCE", "VE")) : !(L.has(m, "VN") && L.has(m, "VE"))) continue;
    Series s;
    s.source = m;
    const auto t = L.times(m);
    const auto n = L.column(m, "VN");
    const auto e = m == "PSCN" ? L.column("PSCE", "VE") : L.column(m, "VE");
    const auto core = L.has(m, "C") ? L.column(m, "C") : std::vector<double>(t.size(), 0.0);
    for (std::size_t i = 0; i < t.size() && i < n.size() && i < e.size(); ++i) {
      if (core[i] != 0.0) continue;
      if (!s.t.empty() && t[i] <= s.t.back()) continue;
      s.t.push_back(t[i]);
      s.n.push_back(n[i]);
      s.e.push_back(e[i]);
    }
    if (s.t.size() >= 10) return s;
  }
  return {};
}

// Linear interpolation of (tx, x) at t, held at the ends (tx increasing).
double interp(const std::vector<double>& tx, const std::vector<double>& x, double t) {
  const auto it = std::lower_bound(tx.begin(), tx.end(), t);
  if (it == tx.begin()) return x.front();
  if (it == tx.end()) return x.back();
  const std::size_t i = static_cast<std::size_t>(it - tx.begin());
  const double w = (t - tx[i - 1]) / std::max(tx[i] - tx[i - 1], 1e-9);
  return x[i - 1] + w * (x[i] - x[i - 1]);
}

// Non-negative least squares of y = c1 s + c2 s^2.
void fit(const std::vector<double>& s, const std::vector<double>& y, double& c1, double& c2) {
  double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double x1 = s[i], x2 = s[i] * s[i];
    a11 += x1 * x1;
    a12 += x1 * x2;
    a22 += x2 * x2;
    b1 += x1 * y[i];
    b2 += x2 * y[i];
  }
  const double det = a11 * a22 - a12 * a12;
  c1 = det > 0 ? (b1 * a22 - b2 * a12) / det : -1.0;
  c2 = det > 0 ? (a11 * b2 - a12 * b1) / det : -1.0;
  if (c1 < 0.0 || c2 < 0.0) {  // one term alone, the better of the two
    const double q1 = std::max(0.0, b1 / a11), q2 = std::max(0.0, b2 / a22);
    const double r1 = q1 * q1 * a11 - 2 * q1 * b1, r2 = q2 * q2 * a22 - 2 * q2 * b2;
    c1 = r1 <= r2 ? q1 : 0.0;
    c2 = r1 <= r2 ? 0.0 : q2;
  }
}

dataflash::Log readDataflash(const std::string& path, const LogReadOptions& options) {
  auto bytes = binary::readFileBytes(path, options.max_file_bytes);
  if (bytes.size() < 2 || bytes[0] != 0xA3 || bytes[1] != 0x95) {
    throw std::runtime_error(path + ": not an ArduPilot DataFlash (.bin) log; the airframe (drag and response) is identified from "
                                    "DataFlash logs only (PX4 ULog: not supported yet)");
  }
  return dataflash::Log::parseAcceptingCutEnd(std::move(bytes), path, options.lenient);
}

// One axis of the response fit: target and achieved acceleration [m/s^2] at the sample times.
struct AccelAxis {
  std::vector<double> target, achieved;
};

// Sum of squared errors of a first-order lag `tau` [s] from target to achieved over the samples
// `t` [s], simulated in 5 ms steps with the target interpolated, restarted after gaps over 0.5 s.
double lagError(const std::vector<double>& t, const AccelAxis& a, double tau) {
  constexpr double kStep = 0.005, kGap = 0.5;
  double sse = 0.0, x = a.achieved.front();
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] - t[i - 1] > kGap) {
      x = a.achieved[i];
      continue;
    }
    const int n = std::max(1, static_cast<int>(std::lround((t[i] - t[i - 1]) / kStep)));
    const double alpha = 1.0 - std::exp(-(t[i] - t[i - 1]) / n / tau);
    for (int k = 0; k < n; ++k) {
      const double w = static_cast<double>(k) / n;  // the target at the step's start
      x += (a.target[i - 1] + w * (a.target[i] - a.target[i - 1]) - x) * alpha;
    }
    sse += (x - a.achieved[i]) * (x - a.achieved[i]);
  }
  return sse;
}

AirframeDragEstimate dragOf(const dataflash::Log& L, const LogReadOptions& options) {
  AirframeDragEstimate out;
  const Series v = velocity(L);
  if (v.t.empty() || !L.has("ATT", "Roll") || !L.has("ATT", "Pitch") || !L.has("ATT", "Yaw")) {
    out.reason = "the log has no ATT attitude or no EKF velocity (XKF1, NKF1, EKF1 or PSCN/PSCE)";
    return out;
  }
  out.velocity_source = v.source;
  const auto ta = L.times("ATT");
  auto rad = [&](const char* c) {
    auto x = L.column("ATT", c);
    for (double& d : x) d *= M_PI / 180.0;
    return x;
  };
  const auto roll = rad("Roll"), pitch = rad("Pitch");
  auto yaw = rad("Yaw");
  for (std::size_t i = 1; i < yaw.size(); ++i) yaw[i] = yaw[i - 1] + std::remainder(yaw[i] - yaw[i - 1], 2 * M_PI);
  std::vector<double> speeds, drag;
  for (std::size_t i = 1; i + 1 < v.t.size(); ++i) {
    const double t = v.t[i], speed = std::hypot(v.n[i], v.e[i]);
    if (t < options.from_s || t > options.to_s || speed < 1.0 || t < ta.front() || t > ta.back()) continue;
    const double r = interp(ta, roll, t), p = interp(ta, pitch, t), y = interp(ta, yaw, t);
    const double zd = std::cos(p) * std::cos(r);
    if (zd < 0.3) continue;  // beyond 70 degrees of lean: not flight the model describes
    const double an = -kG * (std::cos(y) * std::sin(p) * std::cos(r) + std::sin(y) * std::sin(r)) / zd;
    const double ae = -kG * (std::sin(y) * std::sin(p) * std::cos(r) - std::cos(y) * std::sin(r)) / zd;
    const double h = v.t[i + 1] - v.t[i - 1];
    if (!(h > 0.0 && h < 1.0)) continue;
    const double dn = (v.n[i + 1] - v.n[i - 1]) / h, de = (v.e[i + 1] - v.e[i - 1]) / h;
    speeds.push_back(speed);
    drag.push_back(((an - dn) * v.n[i] + (ae - de) * v.e[i]) / speed);
  }
  out.samples = speeds.size();
  out.speed_max_mps = speeds.empty() ? 0.0 : *std::max_element(speeds.begin(), speeds.end());
  if (out.samples < 100 || out.speed_max_mps < 3.0) {
    out.reason = std::to_string(out.samples) + " samples above 1 m/s, fastest " + std::to_string(out.speed_max_mps) +
                 " m/s; at least 100 reaching 3 m/s are needed";
    return out;
  }
  fit(speeds, drag, out.drag_linear_per_s, out.drag_quadratic_per_m);
  double mean = 0, ss = 0, sr = 0;
  for (double d : drag) mean += d / drag.size();
  for (std::size_t i = 0; i < drag.size(); ++i) {
    const double pred = out.drag_linear_per_s * speeds[i] + out.drag_quadratic_per_m * speeds[i] * speeds[i];
    ss += (drag[i] - mean) * (drag[i] - mean);
    sr += (drag[i] - pred) * (drag[i] - pred);
  }
  out.r2 = ss > 0 ? 1.0 - sr / ss : 0.0;
  out.rms_mps2 = std::sqrt(sr / drag.size());
  out.determined = out.r2 >= 0.8;
  if (!out.determined) out.reason = "the fit explains only " + std::to_string(out.r2 * 100.0) + " % of the drag's variance (wind or manual flying?)";
  return out;
}

// The response of the airframe's acceleration to the position controller's target.
ResponseEstimate estimateResponse(const dataflash::Log& L, const LogReadOptions& options) {
  ResponseEstimate out;
  if (!(L.has("PSCN", "TAN") && L.has("PSCN", "AN") && L.has("PSCE", "TAE") && L.has("PSCE", "AE"))) {
    out.reason = "the log has no PSCN/PSCE target and achieved acceleration (ArduCopter logs them from 4.5 on)";
    return out;
  }
  const auto tn = L.times("PSCN");
  const auto tan_ = L.column("PSCN", "TAN"), an = L.column("PSCN", "AN"), tae = L.column("PSCE", "TAE"), ae = L.column("PSCE", "AE");
  std::vector<double> t;
  AccelAxis north, east;
  for (std::size_t i = 0; i < tn.size() && i < tae.size() && i < ae.size(); ++i) {
    if (tn[i] < options.from_s || tn[i] > options.to_s || (!t.empty() && tn[i] <= t.back())) continue;
    t.push_back(tn[i]);
    north.target.push_back(tan_[i]);
    north.achieved.push_back(an[i]);
    east.target.push_back(tae[i]);
    east.achieved.push_back(ae[i]);
  }
  out.samples = 2 * t.size();
  if (t.size() < 150) {
    out.reason = std::to_string(out.samples) + " samples of target and achieved acceleration; at least 300 are needed";
    return out;
  }
  const auto sse = [&](double tau) { return lagError(t, north, tau) + lagError(t, east, tau); };
  // Brent's minimisation of the lag over 0.02-1 s (Boost.Math), to about 1e-8 s.
  std::uintmax_t iterations = 100;
  out.response_s = boost::math::tools::brent_find_minima(sse, 0.02, 1.0, std::numeric_limits<double>::digits / 2, iterations).first;
  double mean = 0.0, sst = 0.0;
  for (const auto* axis : {&north, &east})
    for (double x : axis->achieved) mean += x / out.samples;
  for (const auto* axis : {&north, &east})
    for (double x : axis->achieved) sst += (x - mean) * (x - mean);
  out.r2 = sst > 0.0 ? 1.0 - sse(out.response_s) / sst : 0.0;
  out.determined = out.r2 >= 0.8 && out.response_s < 0.99;
  if (!out.determined) {
    out.reason = "a first-order lag explains only " + std::to_string(out.r2 * 100.0) + " % of the achieved acceleration's variance";
  }
  return out;
}

}  // namespace

AirframeDragEstimate estimateAirframeDrag(const std::string& path, const LogReadOptions& options) {
  return dragOf(readDataflash(path, options), options);
}

AirframeEstimate estimateAirframe(const std::string& path, const LogReadOptions& options) {
  const auto L = readDataflash(path, options);
  return {dragOf(L, options), estimateResponse(L, options)};
}

}  // namespace wattswath::logs
