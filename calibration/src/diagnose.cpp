// Diagnosing an energy model against logs: cross-validated ranking of candidate effects, the error
// staircase, the description of fitted effects, and fit-and-compare on training and test logs.
#include "wattswath/calibration/diagnose.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "diagnose_search.hpp"
#include "number_text.hpp"
#include "time_series.hpp"

namespace wattswath::calibration {
using namespace energy;  // the physics this library compares with measurements
using detail::num;
namespace {

// A residual within this factor of the white noise, carrying no tested signal, is explained.
constexpr double kExplainedRatio = 1.5;

std::string pm(double v, double sigma, int digits = 3) {
  std::string s = num(v, digits);
  if (std::isfinite(sigma)) s += " +- " + num(sigma, 2);
  return s;
}

// Value of a fitted coefficient times `scale`, with its uncertainty when it is determined.
std::string pm(const FittedCoefficient& c, double scale = 1.0, int digits = 3) {
  if (!c.determined) return num(c.value * scale, digits);  // describeEffect says why after the description
  return pm(c.value * scale, c.sigma * scale, digits);
}

std::vector<SampleSet> allOf(const std::vector<PreparedLog>& logs) {
  std::vector<SampleSet> d;
  for (const auto& l : logs) d.push_back({&l, {}});
  return d;
}

std::vector<LogReplay> replayAll(const EnergyModel& m, const std::vector<PreparedLog>& logs) {
  std::vector<LogReplay> r;
  for (const auto& l : logs) r.push_back(replay(m, l));
  return r;
}

}  // namespace

namespace {
// describeEffect() without what is not determined.
std::string describeValues(const std::string& effect, const std::vector<FittedCoefficient>& c) {
  auto get = [&](const std::string& n) -> const FittedCoefficient& {
    for (const auto& x : c)
      if (x.effect == effect && x.name == n) return x;
    throw std::out_of_range("describeEffect: no coefficient " + effect + "." + n);
  };
  if (effect == "parasitic_drag") {
    const auto& a = get("drag_area");
    return "drag area " + pm(a) + " m^2";
  }
  if (effect == "wind") {
    const auto &e = get("wind_east"), &n = get("wind_north"), &a = get("drag_area");
    const double speed = std::hypot(e.value, n.value);
    const double bearing = std::fmod(std::atan2(e.value, n.value) * 180.0 / M_PI + 360.0, 360.0);
    if (!e.fitted || !n.fitted) return "wind not determined: these data have too little fast flight to show it";
    if (!e.determined || !n.determined) {
      return "wind not determined: these data do not separate it from the drag and the hover power (the notes say "
             "why), drag area " + pm(a) + " m^2";
    }
    const double sig = std::isfinite(e.sigma) && std::isfinite(n.sigma) ? std::hypot(e.sigma, n.sigma) / std::sqrt(2.0)
                                                                        : std::numeric_limits<double>::quiet_NaN();
    const double from = std::fmod(std::round(bearing) + 180.0, 360.0);
    return "wind " + pm(speed, sig, 2) + " m/s from " + num(from, 3) + " deg (towards " + num(std::round(bearing), 3) +
           " deg; as replay --wind and predict --wind take it: " + num(speed, 2) + "," + num(from, 3) + "), drag area " +
           pm(a) + " m^2";
  }
  if (effect == "translational_lift") {
    const auto &p = get("induced_power"), &v = get("induced_velocity");
    const double at8 = p.value * (TranslationalLiftEffect::inducedRatio(8.0, v.value) - 1.0);
    return "induced power " + pm(p) + " W at hover, falling with forward speed on a scale of v_h = " +
           pm(v) + " m/s (" + num(at8, 3) + " W at 8 m/s)";
  }
  if (effect == "climb") {
    const auto &u = get("climb_mass"), &d = get("descent_mass");
    return "climbing costs " + pm(u, 9.81) + " W per m/s (m/eta = " + pm(u) + " kg), descending saves " + pm(d, 9.81) +
           " W per m/s";
  }
  if (effect == "load_efficiency") {
    const auto& k = get("efficiency_slope");
    return "efficiency changes by " + pm(k, 100.0) + " % per unit of load factor";
  }
  if (effect == "yaw_rate") {
    const auto& k = get("yaw_power");
    return "yawing costs " + pm(k) + " W per rad/s";
  }
  if (effect == "payload_mass") {
    const auto &m = get("payload_mass"), &t = get("release_time");
    return "payload " + pm(m) + " kg released at t = " + pm(t, 1.0, 4) + " s";
  }
  std::string s;
  for (const auto& x : c) {
    if (x.effect != effect) continue;
    s += (s.empty() ? "" : ", ") + x.name + " " + pm(x) + " " + x.unit;
  }
  return s;
}
}  // namespace

std::string describeEffect(const std::string& effect, const std::vector<FittedCoefficient>& c) {
  std::string s = describeValues(effect, c);
  for (const auto& x : c) {
    if (x.effect != effect || x.determined) continue;
    s += "; " + x.name + " NOT DETERMINED by the data" +
         (x.fitted ? (x.at_bound ? " (at its physical bound: not a measurement)" : " (its value is not a measurement: the note says why)")
                   : " (not fitted: kept at its starting value)");
  }
  return s;
}

namespace {
void checkSettings(const DiagnoseSettings& s) {
  auto bad = [](const std::string& f, double v, const std::string& range) {
    throw std::invalid_argument("DiagnoseSettings." + f + " = " + num(v) + ", expected " + range);
  };
  if (s.folds < 2 || s.folds > 10) bad("folds", s.folds, "2..10");
  if (!(s.p_value >= 1e-9 && s.p_value <= 0.1)) bad("p_value", s.p_value, "1e-9..0.1");
  if (!(s.min_excess_share >= 0.0 && s.min_excess_share <= 1.0)) bad("min_excess_share", s.min_excess_share, "0..1");
  if (s.max_effects < 1 || s.max_effects > 10) bad("max_effects", s.max_effects, "1..10");
}

// Residual of `m` on every log, concatenated [W] (modelled - measured), and the modelled power per log.
std::vector<double> residualOf(const EnergyModel& m, const std::vector<PreparedLog>& logs,
                               std::vector<std::vector<double>>* power = nullptr) {
  std::vector<double> r;
  for (const auto& l : logs) {
    const auto p = modelPower(m, l);
    for (size_t i = 0; i < p.size(); ++i) r.push_back(p[i] - l.measured[i]);
    if (power) power->push_back(p);
  }
  return r;
}

// The fitted model's sensitivity to each of its coefficients over every log, concatenated
// [W per coefficient unit]: forward differences of 1e-4 of the value (or of 1e-6 near 0), stepped
// back when the step would leave the coefficient's bounds. `power`: m's power per log, already
// computed by the caller.
std::vector<std::vector<double>> modelColumns(const EnergyModel& m, const std::vector<PreparedLog>& logs,
                                              const std::vector<std::vector<double>>& power) {
  std::vector<double> base;
  for (const auto& p : power) base.insert(base.end(), p.begin(), p.end());
  std::vector<std::vector<double>> cols;
  for (const auto& name : m.effectNames()) {
    const auto& coeffs = m.effect(name).coefficients();
    for (size_t k = 0; k < coeffs.size(); ++k) {
      EnergyModel moved = m;
      std::vector<double> v;
      for (const auto& c : coeffs) v.push_back(c.value);
      double h = std::max(1e-4 * std::abs(v[k]), 1e-6);
      if (v[k] + h > coeffs[k].upper) h = -h;
      v[k] += h;
      moved.effect(name).setCoefficientValues(v);
      std::vector<double> col;
      for (const auto& l : logs) {
        const auto p = modelPower(moved, l);
        col.insert(col.end(), p.begin(), p.end());
      }
      for (size_t i = 0; i < col.size(); ++i) col[i] = (col[i] - base[i]) / h;
      cols.push_back(std::move(col));
    }
  }
  return cols;
}

double rmsOf(const std::vector<double>& r) {
  double s = 0.0;
  for (double x : r) s += x * x;
  return r.empty() ? 0.0 : std::sqrt(s / r.size());
}

/// [-] samples below which a diagnosis gives no verdict.
constexpr double kMinDiagnosisSamples = 30.0;

// The candidates none of whose coefficients these data could fit (they lack the excitation each
// needs), listed in d.untested and returned in words ("wind (0 of 278 ...) and ..."); empty when
// every candidate was tested.
std::string untestedText(Diagnosis& d) {
  std::vector<std::pair<std::string, std::string>> by_lack;  // (what the data lack, effects), in order
  for (const auto& c : d.candidates) {
    if (c.coefficients.empty()) continue;
    bool any_fitted = false;
    for (const auto& k : c.coefficients) any_fitted = any_fitted || k.fitted;
    if (any_fitted) continue;
    std::string why = c.coefficients.front().why_not_determined;
    if (const auto cut = why.find("; kept at"); cut != std::string::npos) why.erase(cut);
    d.untested.push_back(c.effect + ": " + why);
    const std::string lack = why.substr(0, why.find(": "));  // "0 of 278 airborne samples faster than ..."
    auto it = std::find_if(by_lack.begin(), by_lack.end(), [&](const auto& x) { return x.first == lack; });
    if (it == by_lack.end()) by_lack.push_back({lack, c.effect});
    else it->second += ", " + c.effect;
  }
  std::string text;
  for (const auto& [lack, effects] : by_lack) text += (text.empty() ? "" : "; ") + effects + " (" + lack + ")";
  return text;
}

// The verdict from the found effects and the structure the final residual keeps: a significant
// signature, or a variance above the white noise's by more than about 4 standard errors of the
// noise estimate (6 / sqrt(n) relative: the median-difference estimate has about 1.5 / sqrt(n)).
void conclude(Diagnosis& d) {
  std::vector<const ResidualSignature*> sig;
  for (const auto& g : d.signatures)
    if (g.significant) sig.push_back(&g);
  size_t n = 0;
  for (const auto& p : d.final_power) n += p.size();
  // Too little data to test anything: no verdict (5 samples read "nothing is missing" with no signal
  // tested). (The residual's correlation time is no guide here: a missing effect lengthens it.)
  if (d.signatures.empty() || static_cast<double>(n) < kMinDiagnosisSamples) {
    d.verdict = "cannot_tell";
    d.conclusion = "The data cannot tell: " + std::to_string(n) + " airborne samples" +
                   (d.signatures.empty() ? std::string(", and no signal of the residual could be tested")
                                         : ", fewer than the " + num(kMinDiagnosisSamples, 2) + " needed to test the residual's signals") +
                   "; give longer logs, or more of them." +
                   (d.found.empty() ? std::string()
                                    : " (The search kept " + std::to_string(d.found.size()) +
                                          " effect(s), listed under found, which so few samples cannot confirm.)");
    return;
  }
  const double ratio = d.noise_w > 0.0 ? d.final_rmse_w / d.noise_w : 1.0;
  const bool excess = ratio * ratio - 1.0 > 6.0 / std::sqrt(std::max<double>(1.0, static_cast<double>(n)));
  const std::string noise = "residual " + num(d.final_rmse_w, 3) + " W against a white noise of " + num(d.noise_w, 3) +
                            " W (" + num(ratio, 3) + "x)";
  std::string found;
  for (const auto& f : d.found) found += (found.empty() ? "" : " and ") + f.effect;
  const std::string untested = untestedText(d);
  if (sig.empty() && !excess && ratio <= kExplainedRatio && d.found.empty() && !untested.empty()) {
    d.verdict = "cannot_tell";
    d.conclusion = "The data cannot tell: no candidate they can test improves the held-out error significantly and the "
                   "residual carries none of the tested signals (" + noise + "), but they cannot test " + untested +
                   ". Give a log that flies what those need.";
    return;
  }
  if (sig.empty() && !excess && ratio <= kExplainedRatio) {
    d.verdict = d.found.empty() ? "nothing_missing" : "missing_effect";
    d.conclusion = d.found.empty() ? "Nothing is missing: no candidate improves the held-out error significantly and "
                                     "the residual carries none of the tested signals (" + noise + ")."
                                   : "Missing: " + found + ". With it the residual carries none of the tested signals (" +
                                         noise + ")." + (untested.empty() ? "" : " These data cannot test " + untested + ".");
    return;
  }
  d.verdict = "unexplained";
  d.conclusion = (d.found.empty() ? std::string("No known candidate explains the residual")
                                  : "Found " + found + ", but a structure remains that no candidate explains") +
                 " (" + noise + ", correlated in time).";
  if (sig.empty()) {
    // Leads only where a signal carries a visible share of the residual (the three strongest were
    // cited at 0 % of its variance).
    for (size_t k = 0; k < d.signatures.size() && sig.size() < 3; ++k)
      if (d.signatures[k].strength >= kMinLeadStrength) sig.push_back(&d.signatures[k]);
    d.conclusion += sig.empty() ? " No tested signal carries as much as " + num(100.0 * kMinLeadStrength, 2) +
                                      " % of it: sensor noise correlated in time, or an effect none of the tested "
                                      "signals follows."
                                : " No single tested signal carries it significantly; the strongest are listed as leads.";
  }
  std::vector<std::string> said;  // speed and speed squared share a sentence: say it once
  for (size_t k = 0; k < sig.size() && said.size() < 3; ++k) {
    if (std::find(said.begin(), said.end(), sig[k]->sentence) != said.end()) continue;
    d.conclusion += std::string(said.empty() ? " It " : " It also ") + sig[k]->sentence + " (" + sig[k]->signal + ", " +
                    num(100.0 * sig[k]->strength, 2) + " % of its variance).";
    said.push_back(sig[k]->sentence);
  }
}
}  // namespace

Diagnosis diagnose(const EnergyModel& model, const Vehicle& v, const std::vector<PreparedLog>& logs,
                   const DiagnoseSettings& s) {
  if (logs.empty()) throw std::invalid_argument("diagnose: no logs");
  checkSettings(s);
  Diagnosis d;
  const detail::Folds folds = detail::makeFolds(logs, s);
  d.validation = folds.label;
  d.physics_replay = replayAll(model, logs);
  d.physics = errorMetrics(d.physics_replay);
  d.residuals = residualTables(d.physics_replay);
  const detail::Evaluation base = detail::evaluate(model, {}, logs, folds, s.fit);
  d.baseline = base.heldout;
  std::string own;
  for (const auto& e : model.effectNames()) own += (own.empty() ? "" : ",") + e;
  const StaircaseStep physics{"vehicle physics (no fit)", d.physics}, refit{"refit " + own, d.baseline};
  const auto base_res = residualOf(base.full.model, logs);
  d.noise_w = detail::whiteNoiseSigma(base_res);
  d.autocorrelation_time = detail::autocorrelationTime(base_res);
  const detail::Evaluation fin = detail::searchEffects(model, v, logs, folds, s, d.noise_w, base, d);
  d.staircase.insert(d.staircase.begin(), {physics, refit});
  d.final_heldout = fin.heldout;
  d.final_rmse_w = rmsOf(residualOf(fin.full.model, logs, &d.final_power));
  d.final_effects = fin.full.model.effectNames();
  d.signatures = residualSignatures(logs, d.final_power, s.signatures, modelColumns(fin.full.model, logs, d.final_power));
  conclude(d);
  return d;
}

FitReport fitAndCompare(const EnergyModel& model, const std::vector<PreparedLog>& train,
                        const std::vector<PreparedLog>& test, const FitSettings& s) {
  if (train.empty()) throw std::invalid_argument("fitAndCompare: no training logs");
  FitReport r;
  r.fit = fitModel(model, allOf(train), s);
  r.train_before = errorMetrics(replayAll(model, train));
  r.train_replay = replayAll(r.fit.model, train);
  r.train_after = errorMetrics(r.train_replay);
  if (!test.empty()) {
    r.test_before = errorMetrics(replayAll(model, test));
    r.test_replay = replayAll(r.fit.model, test);
    r.test_after = errorMetrics(r.test_replay);
  }
  return r;
}

}  // namespace wattswath::calibration
