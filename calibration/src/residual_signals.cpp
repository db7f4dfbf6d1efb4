// The residual against a library of signals (issue 18): which signals carry what the model misses,
// with tests whose sample size is the effective one of two autocorrelated series.
#include "wattswath/calibration/residual_signals.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <Eigen/Dense>

#include "time_series.hpp"

namespace wattswath::calibration {
namespace {

struct Signal {
  std::string name, unit;
  std::vector<double> x;
};

// Signals of one log appended to `out` (in signalNames() order); current squared only when the
// log has a current, or a voltage to divide the power by.
void appendSignals(const PreparedLog& L, const std::vector<double>& model, std::vector<Signal>& out) {
  const size_t n = L.states.size();
  auto col = [&](size_t k) -> std::vector<double>& { return out[k].x; };
  double drawn_total = 0.0;
  for (size_t i = 0; i < n; ++i) drawn_total += L.weight[i] * L.measured[i];
  size_t first = 0;
  while (first + 1 < n && !L.states[first].airborne) ++first;
  double drawn = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const auto& s = L.states[i];
    drawn += L.weight[i] * L.measured[i];
    const size_t a = i > 0 ? i - 1 : i, b = i + 1 < n ? i + 1 : i;
    const double dt = L.states[b].t - L.states[a].t;
    const double hs = s.velocity.head<2>().norm();
    // The current the model draws at the logged voltage: the logged current carries the measured
    // power's own noise, which the residual shares, so it would correlate with any residual.
    const bool has_v = i < L.voltage.size() && std::isfinite(L.voltage[i]) && L.voltage[i] > 0.0;
    const double amps = has_v ? model[i] / L.voltage[i] : std::nan("");
    col(0).push_back(s.t - L.states[first].t);
    col(1).push_back(drawn_total > 0.0 ? 1.0 - drawn / drawn_total : 1.0);
    col(2).push_back(amps * amps);
    col(3).push_back(model[i] * model[i]);
    col(4).push_back(dt > 0.0 ? (model[b] - model[a]) / dt : 0.0);
    col(5).push_back(L.position[i].z());
    col(6).push_back(L.position[i].z() - L.position[first].z());
    col(7).push_back(hs);
    col(8).push_back(hs * hs);
    col(9).push_back(s.acceleration.norm());
    col(10).push_back(s.velocity.z());
    col(11).push_back(std::abs(s.yaw_rate));
    col(12).push_back(s.heading);
  }
}

// Quantile bins of `x` that never split equal values; each bin's indices.
std::vector<std::vector<size_t>> quantileBins(const std::vector<double>& x, int bins) {
  std::vector<size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return x[a] < x[b]; });
  std::vector<std::vector<size_t>> out;
  const size_t target = std::max<size_t>(1, x.size() / static_cast<size_t>(bins));
  for (size_t k = 0; k < order.size();) {
    out.emplace_back();
    size_t j = k;
    while (j < order.size() && (out.back().size() < target || x[order[j]] == x[order[j - 1]])) out.back().push_back(order[j++]);
    k = j;
  }
  return out;
}

// Share of the variance of `r` explained by the bin means of `x` (correlation ratio eta^2), with the bins.
double binnedShare(const std::vector<double>& x, const std::vector<double>& r, int bins, std::vector<SignatureBin>& out,
                   int& dof) {
  const double m = std::accumulate(r.begin(), r.end(), 0.0) / r.size();
  double total = 0.0, between = 0.0;
  for (double v : r) total += (v - m) * (v - m);
  const auto idx = quantileBins(x, bins);
  for (const auto& b : idx) {
    double s = 0.0;
    for (size_t i : b) s += r[i];
    const double mb = s / b.size();
    between += b.size() * (mb - m) * (mb - m);
    out.push_back({x[b.front()], x[b.back()], static_cast<int>(b.size()), mb});
  }
  dof = std::max(1, static_cast<int>(idx.size()) - 1);
  return total > 0.0 ? between / total : 0.0;
}

// Linear share: r^2 (for heading the multiple R^2 on cos and sin) and the slope.
double linearShare(const Signal& s, const std::vector<double>& r, double& slope, int& dof) {
  if (s.name != "heading") {
    const double c = detail::correlation(s.x, r);
    const double mx = std::accumulate(s.x.begin(), s.x.end(), 0.0) / s.x.size();
    const double mr = std::accumulate(r.begin(), r.end(), 0.0) / r.size();
    double sxx = 0.0, sxr = 0.0;
    for (size_t i = 0; i < r.size(); ++i) {
      sxx += (s.x[i] - mx) * (s.x[i] - mx);
      sxr += (s.x[i] - mx) * (r[i] - mr);
    }
    slope = sxx > 0.0 ? sxr / sxx : 0.0;
    dof = 1;
    return c * c;
  }
  std::vector<double> cs(s.x.size()), sn(s.x.size());
  for (size_t i = 0; i < s.x.size(); ++i) {
    cs[i] = std::cos(s.x[i]);
    sn[i] = std::sin(s.x[i]);
  }
  const double rc = detail::correlation(cs, r), rs = detail::correlation(sn, r), rcs = detail::correlation(cs, sn);
  slope = 0.0;
  dof = 2;
  return std::abs(rcs) < 0.999 ? std::max(0.0, (rc * rc + rs * rs - 2 * rc * rs * rcs) / (1 - rcs * rcs)) : rc * rc;
}

// The columns a signal is cleared of: a constant and the model's sensitivities, with their QR.
struct Basis {
  Eigen::MatrixXd X;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
};

// `x` minus its least-squares fit by the columns of `b`.
std::vector<double> partialOut(const Basis& b, const std::vector<double>& x) {
  const Eigen::Map<const Eigen::VectorXd> v(x.data(), static_cast<Eigen::Index>(x.size()));
  const Eigen::VectorXd rest = v - b.X * b.qr.solve(v);
  return std::vector<double>(rest.data(), rest.data() + rest.size());
}

// `partial`: the signal cleared of the model's columns (added-variable test), or null.
ResidualSignature test(const Signal& s, const std::vector<double>& r, const SignatureSettings& set,
                       const Signal* partial = nullptr, const std::vector<double>* r_partial = nullptr) {
  ResidualSignature g;
  g.signal = s.name;
  g.unit = s.unit;
  const Signal& ls = partial ? *partial : s;
  const std::vector<double>& lr = r_partial ? *r_partial : r;
  g.effective_samples = detail::pairEffectiveSize(ls.x, lr);
  int dof_lin = 1, dof_bin = 1;
  const double lin = linearShare(ls, lr, g.slope, dof_lin);
  const double bin = binnedShare(s.x, r, set.bins, g.bins, dof_bin);
  const double n = g.effective_samples;
  const double lin_strength = lin - dof_lin / n, bin_strength = bin - dof_bin / n;
  const bool linear = lin_strength >= bin_strength;
  g.form = linear ? "linear" : "binned";
  g.strength = std::max(0.0, linear ? lin_strength : bin_strength);
  g.statistic = n * (linear ? lin : bin);
  g.threshold = detail::chiSquareQuantile(linear ? dof_lin : dof_bin, set.p_value);
  g.significant = g.statistic > g.threshold && g.strength >= set.min_strength;
  // Sign of the relation: slope, or whether the upper half of the bins sits above the lower half.
  bool rises = g.slope > 0.0;
  if (!linear && g.bins.size() >= 2) {
    const size_t h = g.bins.size() / 2;
    double lo = 0.0, hi = 0.0;
    for (size_t k = 0; k < g.bins.size(); ++k) (k < h ? lo : hi) += g.bins[k].residual_w / (k < h ? h : g.bins.size() - h);
    rises = hi > lo;
  }
  g.sentence = signatureSentence(s.name, rises);
  return g;
}

void validate(const SignatureSettings& s) {
  auto bad = [](const std::string& f, double v, const std::string& range) {
    throw std::invalid_argument("SignatureSettings." + f + " = " + std::to_string(v) + ", expected " + range);
  };
  if (s.bins < 3 || s.bins > 50) bad("bins", s.bins, "3..50");
  if (!(s.p_value >= 1e-12 && s.p_value <= 0.1)) bad("p_value", s.p_value, "1e-12..0.1");
  if (!(s.min_strength >= 0.0 && s.min_strength <= 1.0)) bad("min_strength", s.min_strength, "0..1");
  if (!(s.same_correlation >= 0.0 && s.same_correlation <= 1.0)) bad("same_correlation", s.same_correlation, "0..1");
}
}  // namespace

const std::vector<std::string>& signalNames() {
  static const std::vector<std::string> n = {"time",     "state_of_charge", "current_squared", "power_squared", "power_rate",
                                             "altitude", "height",          "speed",           "speed_squared", "acceleration",
                                             "climb_rate", "yaw_rate",      "heading"};
  return n;
}

std::vector<ResidualSignature> residualSignatures(const std::vector<PreparedLog>& logs,
                                                  const std::vector<std::vector<double>>& modelled,
                                                  const SignatureSettings& set,
                                                  const std::vector<std::vector<double>>& model_columns) {
  validate(set);
  if (logs.size() != modelled.size()) throw std::invalid_argument("residualSignatures: one modelled series per log expected");
  static const char* units[] = {"s", "-", "A^2", "W^2", "W/s", "m", "m", "m/s", "m^2/s^2", "m/s^2", "m/s", "rad/s", "rad"};
  std::vector<Signal> sig;
  for (size_t k = 0; k < signalNames().size(); ++k) sig.push_back({signalNames()[k], units[k], {}});
  std::vector<double> r;
  for (size_t j = 0; j < logs.size(); ++j) {
    if (modelled[j].size() != logs[j].states.size())
      throw std::invalid_argument("residualSignatures: modelled power of " + logs[j].source + " has the wrong length");
    appendSignals(logs[j], modelled[j], sig);
    for (size_t i = 0; i < logs[j].states.size(); ++i) r.push_back(logs[j].measured[i] - modelled[j][i]);
  }
  // The added-variable basis: a constant and the model's sensitivity columns (those that vary).
  std::vector<const std::vector<double>*> cols;
  for (const auto& c : model_columns) {
    if (c.size() != r.size()) throw std::invalid_argument("residualSignatures: a model column has the wrong length");
    if (std::all_of(c.begin(), c.end(), [](double v) { return std::isfinite(v); })) cols.push_back(&c);
  }
  const bool partial = !cols.empty() && r.size() > 10 * (cols.size() + 1);
  Basis basis;
  std::vector<double> r_partial;
  if (partial) {
    basis.X.resize(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(cols.size() + 1));
    basis.X.col(0).setOnes();
    for (size_t k = 0; k < cols.size(); ++k)
      basis.X.col(static_cast<Eigen::Index>(k + 1)) = Eigen::Map<const Eigen::VectorXd>(cols[k]->data(), basis.X.rows());
    basis.qr.compute(basis.X);
    r_partial = partialOut(basis, r);
  }
  std::vector<ResidualSignature> out;
  std::vector<const Signal*> used;
  for (const auto& s : sig) {
    const bool usable = std::all_of(s.x.begin(), s.x.end(), [](double v) { return std::isfinite(v); });
    if (!usable || r.size() < 10) continue;  // e.g. current squared without current or voltage
    if (partial && s.name != "heading") {  // heading's cos/sin test keeps the raw signal
      const Signal ps{s.name, s.unit, partialOut(basis, s.x)};
      out.push_back(test(s, r, set, &ps, &r_partial));
    } else {
      out.push_back(test(s, r, set));
    }
    used.push_back(&s);
  }
  std::vector<size_t> order(out.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (out[a].significant != out[b].significant) return out[a].significant;
    return out[a].strength > out[b].strength + 1e-12;
  });
  // Merge signals these data cannot tell apart into the one ranked first.
  std::vector<ResidualSignature> merged;
  std::vector<bool> taken(out.size(), false);
  for (size_t a : order) {
    if (taken[a]) continue;
    taken[a] = true;
    ResidualSignature g = out[a];
    for (size_t b : order) {
      if (taken[b] || std::abs(detail::correlation(used[a]->x, used[b]->x)) <= set.same_correlation) continue;
      taken[b] = true;
      g.same_as.push_back(out[b].signal);
    }
    if (!g.same_as.empty()) {
      std::string names;
      for (const auto& n : g.same_as) names += (names.empty() ? "" : ", ") + n;
      g.sentence += " (in these data the same signature as " + names + ")";
    }
    merged.push_back(std::move(g));
  }
  return merged;
}

std::string signalLabel(const std::string& signal) {
  if (signal == "state_of_charge") return "share of this log's energy still to be drawn";
  std::string label = signal;
  std::replace(label.begin(), label.end(), '_', ' ');
  return label;
}

std::string signatureSentence(const std::string& signal, bool rises) {
  const std::string dir = rises ? "rises" : "falls";
  if (signal == "time")
    return std::string(rises ? "grows" : "shrinks") +
           " with time since take-off: motor or ESC heating, battery sag, or a slow change of the vehicle or sensor";
  if (signal == "state_of_charge")  // 1 - energy drawn / the log's energy: this log's progress, not the pack's charge
    return "follows the share of this log's energy still to be drawn (1 at its start, 0 at its end; not the pack's "
           "state of charge, which the log does not give): battery sag as the pack empties if the flight began on a "
           "full pack, or anything else that changes steadily through the flight";
  if (signal == "current_squared")
    return dir + " with current squared: resistive loss in the battery, wiring or ESCs (I^2 R)";
  if (signal == "power_squared")
    return dir + " with power squared: resistive loss at nearly constant voltage, or efficiency changing with load";
  if (signal == "power_rate")
    return "follows the rate of change of power: the power measurement lags the load (current-sensor or logging "
           "filter), or the motors respond late";
  if (signal == "altitude")
    return dir + " with altitude: air density falling with height (rotor power grows as 1/sqrt(rho)), or temperature";
  if (signal == "height")
    return dir + " with height above take-off: ground effect near the ground (less power within about a rotor "
                 "diameter), or air density";
  if (signal == "speed" || signal == "speed_squared")
    return dir + " with horizontal speed: drag, translational lift or wind in a form the model's effects lack";
  if (signal == "acceleration")
    return dir + " with acceleration: effective mass, load-dependent efficiency, or tilt changes";
  if (signal == "climb_rate")
    return dir + " with climb rate: climb efficiency, or descent through the rotors' own wake (vortex ring)";
  if (signal == "yaw_rate") return dir + " with yaw rate: the torque difference that yaws the vehicle";
  if (signal == "heading") return "depends on heading: wind, or a heading-dependent sensor error";
  throw std::invalid_argument("signatureSentence: unknown signal '" + signal + "'");
}

}  // namespace wattswath::calibration
