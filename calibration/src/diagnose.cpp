// Diagnosing an energy model against logs: cross-validated ranking of candidate effects, the error
// staircase, the description of fitted effects, and fit-and-compare on training and test logs.
#include "wattswath/calibration/diagnose.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "number_text.hpp"

namespace wattswath::calibration {
using namespace energy;  // the physics this library compares with measurements
using detail::num;
namespace {

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

// Held-out predictions of `start` refitted fold by fold.
struct Folds {
  std::vector<std::vector<SampleSet>> train;
  std::vector<std::vector<SampleSet>> test;
  std::string label;
};

Folds makeFolds(const std::vector<PreparedLog>& logs, const DiagnoseSettings& s) {
  Folds f;
  if (logs.size() >= 2) {
    f.label = "leave-one-flight-out (" + std::to_string(logs.size()) + " flights)";
    for (size_t k = 0; k < logs.size(); ++k) {
      std::vector<SampleSet> tr, te;
      for (size_t j = 0; j < logs.size(); ++j) (j == k ? te : tr).push_back({&logs[j], {}});
      f.train.push_back(tr);
      f.test.push_back(te);
    }
    return f;
  }
  const PreparedLog& L = logs.at(0);
  const int blocks = s.folds * s.blocks_per_fold;
  f.label = std::to_string(s.folds) + "-fold interleaved time blocks (" + std::to_string(blocks) + " blocks)";
  const double t0 = L.states.front().t, t1 = L.states.back().t;
  f.train.assign(s.folds, {SampleSet{&L, {}}});
  f.test.assign(s.folds, {SampleSet{&L, {}}});
  for (size_t i = 0; i < L.states.size(); ++i) {
    const int b = std::min(blocks - 1, static_cast<int>((L.states[i].t - t0) / (t1 - t0) * blocks));
    const int fold = b % s.folds;
    for (int k = 0; k < s.folds; ++k) (k == fold ? f.test : f.train)[k][0].index.push_back(static_cast<int>(i));
  }
  return f;
}

// Cross-validated metrics of `start` and the held-out predictions per log.
ErrorMetrics crossValidate(const EnergyModel& start, const std::vector<PreparedLog>& logs, const Folds& folds,
                           const FitSettings& fs) {
  std::vector<std::vector<double>> pred(logs.size());
  for (size_t j = 0; j < logs.size(); ++j) pred[j].assign(logs[j].states.size(), 0.0);
  for (size_t k = 0; k < folds.train.size(); ++k) {
    const FitResult fr = fitModel(start, folds.train[k], fs);
    for (const auto& set : folds.test[k]) {
      const size_t j = static_cast<size_t>(set.log - logs.data());
      if (set.index.empty()) {
        pred[j] = modelPower(fr.model, *set.log);
      } else {
        for (int i : set.index) pred[j][i] = fr.model.power(set.log->states[i]);
      }
    }
  }
  std::vector<LogReplay> rep;
  for (size_t j = 0; j < logs.size(); ++j) rep.push_back(assembleReplay(logs[j], pred[j]));
  return errorMetrics(rep);
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

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const size_t n = a.size();
  if (n < 3) return 0.0;
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n, mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < n; ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
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
      return "wind not determined: with drag area " + pm(a) +
             " m^2 the air speed hardly changes the modelled power, so these data say nothing about the wind";
    }
    const double sig = std::isfinite(e.sigma) && std::isfinite(n.sigma) ? std::hypot(e.sigma, n.sigma) / std::sqrt(2.0)
                                                                        : std::numeric_limits<double>::quiet_NaN();
    return "wind " + pm(speed, sig, 2) + " m/s towards " + num(std::round(bearing), 3) +
           " deg (compass bearing the air moves to), drag area " + pm(a) + " m^2";
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
         (x.fitted ? " (its value is arbitrary)" : " (not fitted: kept at its starting value)");
  }
  return s;
}

Diagnosis diagnose(const EnergyModel& model, const Vehicle& v, const std::vector<PreparedLog>& logs,
                   const DiagnoseSettings& s) {
  if (logs.empty()) throw std::invalid_argument("diagnose: no logs");
  if (s.folds < 2 || s.folds > 10) throw std::invalid_argument("DiagnoseSettings.folds = " + std::to_string(s.folds) + ", expected 2..10");
  if (s.blocks_per_fold < 1 || s.blocks_per_fold > 50) {
    throw std::invalid_argument("DiagnoseSettings.blocks_per_fold = " + std::to_string(s.blocks_per_fold) +
                                ", expected 1..50");
  }
  Diagnosis d;
  const Folds folds = makeFolds(logs, s);
  d.validation = folds.label;
  d.physics_replay = replayAll(model, logs);
  d.physics = errorMetrics(d.physics_replay);
  d.residuals = residualTables(d.physics_replay);
  d.baseline = crossValidate(model, logs, folds, s.fit);
  d.staircase.push_back({"vehicle physics (no fit)", d.physics});
  d.staircase.push_back({"refit " + [&] {
                           std::string n;
                           for (const auto& e : model.effectNames()) n += (n.empty() ? "" : ",") + e;
                           return n;
                         }(),
                         d.baseline});

  const auto all = allOf(logs);
  const FitResult base_fit = fitModel(model, all, s.fit);
  std::vector<double> base_power;
  for (const auto& l : logs) {
    const auto p = modelPower(base_fit.model, l);
    base_power.insert(base_power.end(), p.begin(), p.end());
  }
  std::vector<std::string> names = s.candidates;
  if (names.empty()) {
    for (const auto& n : knownEffectNames()) {
      if (model.has(n) || (n == "parasitic_drag" && model.has("wind"))) continue;
      names.push_back(n);
    }
  }
  std::vector<std::vector<double>> contribution;
  for (const auto& name : names) {
    if (model.has(name)) continue;
    const EnergyModel m = withCandidate(model, name, v);
    CandidateResult c;
    c.effect = name;
    const ErrorMetrics cv = crossValidate(m, logs, folds, s.fit);
    c.rmse_w = cv.rmse_w;
    c.energy_error_pct = cv.energy_error_pct;
    c.leg_energy_mape_pct = cv.leg_energy_mape_pct;
    c.improvement_pct = d.baseline.rmse_w > 0 ? 100.0 * (d.baseline.rmse_w - cv.rmse_w) / d.baseline.rmse_w : 0.0;
    const FitResult full = fitModel(m, all, s.fit);
    for (const auto& fc : full.coefficients)
      if (fc.effect == name) c.coefficients.push_back(fc);
    c.summary = describeEffect(name, full.coefficients);
    c.notes = full.notes;
    std::vector<double> contrib;
    size_t k = 0;
    for (const auto& l : logs) {
      const auto p = modelPower(full.model, l);
      for (double x : p) contrib.push_back(x - base_power[k++]);
    }
    contribution.push_back(std::move(contrib));
    d.candidates.push_back(std::move(c));
  }
  // Effects whose fitted power contributions are nearly proportional cannot be told apart.
  for (size_t i = 0; i < d.candidates.size(); ++i) {
    for (size_t j = i + 1; j < d.candidates.size(); ++j) {
      if (d.candidates[i].improvement_pct < 0.5 || d.candidates[j].improvement_pct < 0.5) continue;
      if (correlation(contribution[i], contribution[j]) > s.indistinct_correlation) {
        d.candidates[i].indistinct_from.push_back(d.candidates[j].effect);
        d.candidates[j].indistinct_from.push_back(d.candidates[i].effect);
      }
    }
  }
  std::stable_sort(d.candidates.begin(), d.candidates.end(),
                   [](const CandidateResult& a, const CandidateResult& b) { return a.improvement_pct > b.improvement_pct; });
  if (!d.candidates.empty()) {
    ErrorMetrics best;
    best.rmse_w = d.candidates[0].rmse_w;
    best.energy_error_pct = d.candidates[0].energy_error_pct;
    best.leg_energy_mape_pct = d.candidates[0].leg_energy_mape_pct;
    d.staircase.push_back({"+ " + d.candidates[0].effect, best});
  }
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
