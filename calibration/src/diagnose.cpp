#include "wattswath/calibration/diagnose.hpp"

#include <ceres/ceres.h>
#include <ceres/covariance.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <stdexcept>

namespace wattswath::calibration {
using namespace energy;  // the physics this library compares with measurements
namespace {

std::string num(double v, int digits = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string pm(double v, double sigma, int digits = 3) {
  std::string s = num(v, digits);
  if (std::isfinite(sigma)) s += " +- " + num(sigma, 2);
  return s;
}

// Value of a fitted coefficient times `scale`, with its uncertainty, or "(not determined)".
std::string pm(const FittedCoefficient& c, double scale = 1.0, int digits = 3) {
  if (!c.determined) return num(c.value * scale, digits) + " (not determined by the data)";
  return pm(c.value * scale, c.sigma * scale, digits);
}

// Flattened training data: pointers to motion states and the measured power.
struct Points {
  std::vector<const MotionState*> state;
  std::vector<double> measured;
};

Points gather(const std::vector<SampleSet>& data, int max_samples) {
  size_t total = 0;
  for (const auto& d : data) total += d.index.empty() ? d.log->states.size() : d.index.size();
  const size_t stride = total > static_cast<size_t>(max_samples) ? (total + max_samples - 1) / max_samples : 1;
  Points p;
  size_t k = 0;
  for (const auto& d : data) {
    const size_t n = d.index.empty() ? d.log->states.size() : d.index.size();
    for (size_t j = 0; j < n; ++j, ++k) {
      if (k % stride) continue;
      const int i = d.index.empty() ? static_cast<int>(j) : d.index[j];
      p.state.push_back(&d.log->states[i]);
      p.measured.push_back(d.log->measured[i]);
    }
  }
  return p;
}

// Residuals model power - measured power, for coefficients in per-effect parameter blocks.
struct PowerResiduals {
  mutable EnergyModel model;
  std::vector<int> block_of_effect;  // -1 when the effect has no coefficients
  const Points* pts;

  bool operator()(double const* const* params, double* residuals) const {
    setParams(model, params);
    for (size_t i = 0; i < pts->state.size(); ++i) residuals[i] = model.power(*pts->state[i]) - pts->measured[i];
    return true;
  }
  void setParams(EnergyModel& m, double const* const* params) const {
    const auto& e = m.effects();
    for (size_t k = 0; k < e.size(); ++k) {
      if (block_of_effect[k] < 0) continue;
      const size_t n = e[k]->coefficients().size();
      e[k]->setCoefficientValues(std::vector<double>(params[block_of_effect[k]], params[block_of_effect[k]] + n));
    }
  }
};

// Release time of a payload by a change-point scan: the split of the time-sorted residuals that
// best explains them as a higher mean before than after (two-sample mean difference, O(n)).
void initPayload(EnergyModel& m, const Points& pts) {
  if (!m.has("payload_mass")) return;
  Effect& pe = m.effect("payload_mass");
  if (pe.coefficient("payload_mass") != 0.0) return;
  std::vector<std::pair<double, double>> r;  // (t, measured - model)
  for (size_t i = 0; i < pts.state.size(); ++i) {
    r.emplace_back(pts.state[i]->t, pts.measured[i] - m.power(*pts.state[i]));
  }
  std::sort(r.begin(), r.end());
  const size_t n = r.size();
  if (n < 4) return;
  const double total = std::accumulate(r.begin(), r.end(), 0.0, [](double a, const auto& x) { return a + x.second; });
  double before = 0.0, best = -1.0;
  size_t best_k = 0;
  for (size_t k = 1; k + 1 < n; ++k) {
    before += r[k - 1].second;
    const double mb = before / k, ma = (total - before) / (n - k);
    if (mb <= ma) continue;
    const double score = static_cast<double>(k) * (n - k) / n * (mb - ma) * (mb - ma);
    if (score > best) {
      best = score;
      best_k = k;
    }
  }
  if (best < 0.0) return;
  const double tr = 0.5 * (r[best_k - 1].first + r[best_k].first);
  pe.setCoefficientValues({0.005 * pe.coefficients()[0].upper, tr});  // 5 % of the vehicle mass
}

// Translational lift starts neutral (no induced power); give the fit a non-zero start so the
// speed scale has a gradient: a quarter of the mean measured power.
void initTranslationalLift(EnergyModel& m, const Points& pts) {
  if (!m.has("translational_lift")) return;
  Effect& e = m.effect("translational_lift");
  if (e.coefficient("induced_power") != 0.0) return;
  double mean = 0.0;
  for (double p : pts.measured) mean += p / pts.measured.size();
  e.setCoefficientValues({0.25 * std::max(mean, 1.0), e.coefficient("induced_velocity")});
}

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return v.empty() ? 0.0 : std::sqrt(s / v.size());
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

void checkSettings(const FitSettings& s) {
  if (s.max_samples < 100 || s.max_samples > 1000000) {
    throw std::invalid_argument("FitSettings.max_samples = " + std::to_string(s.max_samples) + ", expected 100..1e6");
  }
  if (s.max_iterations < 1 || s.max_iterations > 1000) {
    throw std::invalid_argument("FitSettings.max_iterations = " + std::to_string(s.max_iterations) +
                                ", expected 1..1000");
  }
  if (!(s.huber_w >= 0.0 && s.huber_w <= 1e4)) {
    throw std::invalid_argument("FitSettings.huber_w = " + std::to_string(s.huber_w) + ", expected 0..1e4 W");
  }
}

}  // namespace

FitResult fitModel(const EnergyModel& start, const std::vector<SampleSet>& data, const FitSettings& s) {
  checkSettings(s);
  const Points pts = gather(data, s.max_samples);
  if (pts.state.size() < 3) throw std::invalid_argument("fitModel: fewer than 3 samples to fit");
  FitResult out;
  out.model = start;
  initPayload(out.model, pts);
  initTranslationalLift(out.model, pts);

  const auto& effects = out.model.effects();
  std::vector<std::vector<double>> blocks;
  std::vector<int> block_of(effects.size(), -1);
  for (size_t k = 0; k < effects.size(); ++k) {
    if (effects[k]->coefficients().empty()) continue;
    block_of[k] = static_cast<int>(blocks.size());
    std::vector<double> b;
    for (const auto& c : effects[k]->coefficients()) b.push_back(std::clamp(c.value, c.lower, c.upper));
    blocks.push_back(b);
  }
  auto* functor = new PowerResiduals{out.model, block_of, &pts};
  auto* cost = new ceres::DynamicNumericDiffCostFunction<PowerResiduals, ceres::CENTRAL>(functor);
  std::vector<double*> ptrs;
  for (auto& b : blocks) {
    cost->AddParameterBlock(static_cast<int>(b.size()));
    ptrs.push_back(b.data());
  }
  cost->SetNumResiduals(static_cast<int>(pts.state.size()));
  ceres::Problem problem;
  problem.AddResidualBlock(cost, s.huber_w > 0.0 ? new ceres::HuberLoss(s.huber_w) : nullptr, ptrs);
  for (size_t k = 0; k < effects.size(); ++k) {
    if (block_of[k] < 0) continue;
    const auto& cs = effects[k]->coefficients();
    for (size_t c = 0; c < cs.size(); ++c) {
      problem.SetParameterLowerBound(ptrs[block_of[k]], static_cast<int>(c), cs[c].lower);
      problem.SetParameterUpperBound(ptrs[block_of[k]], static_cast<int>(c), cs[c].upper);
    }
  }
  ceres::Solver::Options opt;
  opt.linear_solver_type = ceres::DENSE_QR;
  opt.max_num_iterations = s.max_iterations;
  opt.logging_type = ceres::SILENT;
  opt.minimizer_progress_to_stdout = false;
  opt.function_tolerance = 1e-10;
  opt.parameter_tolerance = 1e-10;
  ceres::Solver::Summary summary;
  ceres::Solve(opt, &problem, &summary);
  functor->setParams(out.model, ptrs.data());

  std::vector<double> res(pts.state.size());
  for (size_t i = 0; i < res.size(); ++i) res[i] = out.model.power(*pts.state[i]) - pts.measured[i];
  out.train_rmse_w = rms(res);
  out.samples = static_cast<int>(res.size());

  // Formal uncertainty: covariance of the linearised problem times the residual variance.
  size_t p = 0;
  for (const auto& b : blocks) p += b.size();
  const double s2 = res.size() > p ? 2.0 * summary.final_cost / (res.size() - p) : 0.0;
  ceres::Covariance::Options copt;
  copt.algorithm_type = ceres::DENSE_SVD;
  copt.null_space_rank = -1;
  copt.min_reciprocal_condition_number = 1e-14;
  ceres::Covariance cov(copt);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (size_t a = 0; a < ptrs.size(); ++a)
    for (size_t b = a; b < ptrs.size(); ++b) pairs.emplace_back(ptrs[a], ptrs[b]);
  const bool have_cov = !pairs.empty() && cov.Compute(pairs, &problem);
  if (!have_cov && !pairs.empty()) out.notes.push_back("covariance is singular: some coefficients are not determined");
  struct Ref {
    size_t block, idx;
  };
  std::vector<Ref> refs;
  for (size_t k = 0; k < effects.size(); ++k) {
    const auto& cs = effects[k]->coefficients();
    for (size_t c = 0; c < cs.size(); ++c) {
      FittedCoefficient f;
      f.effect = effects[k]->name();
      f.name = cs[c].name;
      f.unit = cs[c].unit;
      f.meaning = cs[c].meaning;
      f.value = cs[c].value;
      f.sigma = std::numeric_limits<double>::quiet_NaN();
      const double span = std::max(1e-12, 1e-6 * (cs[c].upper - cs[c].lower));
      f.at_bound = f.value <= cs[c].lower + span || f.value >= cs[c].upper - span;
      out.coefficients.push_back(f);
      refs.push_back({static_cast<size_t>(block_of[k]), c});
    }
  }
  if (have_cov) {
    auto covAt = [&](const Ref& a, const Ref& b) {
      const size_t na = blocks[a.block].size(), nb = blocks[b.block].size();
      std::vector<double> m(na * nb);
      if (a.block <= b.block) {
        cov.GetCovarianceBlock(ptrs[a.block], ptrs[b.block], m.data());
        return m[a.idx * nb + b.idx];
      }
      cov.GetCovarianceBlock(ptrs[b.block], ptrs[a.block], m.data());
      return m[b.idx * na + a.idx];
    };
    for (size_t i = 0; i < refs.size(); ++i) {
      // DENSE_SVD with null_space_rank -1 is a pseudo-inverse: a coefficient the data do not
      // constrain (its Jacobian column vanishes) comes back with variance 0, which is not "exact"
      // but "unknown".
      const double v = covAt(refs[i], refs[i]);
      auto& c = out.coefficients[i];
      if (v > 0.0) {
        c.sigma = std::sqrt(v * s2);
      } else {
        c.sigma = std::numeric_limits<double>::quiet_NaN();
        c.determined = false;
        out.notes.push_back(c.effect + "." + c.name + " is not determined by the data (the modelled power does not "
                            "change with it at the fitted values); its value " + num(c.value) + " " + c.unit +
                            " is arbitrary");
      }
    }
    for (size_t i = 0; i < refs.size(); ++i) {
      for (size_t j = i + 1; j < refs.size(); ++j) {
        const double vi = covAt(refs[i], refs[i]), vj = covAt(refs[j], refs[j]);
        if (!(vi > 0 && vj > 0)) continue;
        const double r = covAt(refs[i], refs[j]) / std::sqrt(vi * vj);
        if (std::abs(r) > 0.95) {
          out.notes.push_back(out.coefficients[i].effect + "." + out.coefficients[i].name + " and " +
                              out.coefficients[j].effect + "." + out.coefficients[j].name + " are correlated (r = " +
                              num(r, 3) + "): the data constrain mainly a combination of them");
        }
      }
    }
  }
  for (const auto& c : out.coefficients) {
    if (c.at_bound) out.notes.push_back(c.effect + "." + c.name + " stopped at a bound (" + num(c.value) + " " + c.unit + ")");
  }
  return out;
}

std::string describeEffect(const std::string& effect, const std::vector<FittedCoefficient>& c) {
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

FlightLog simulateFlight(const std::vector<Eigen::Vector3d>& wps, const EnergyModel& truth,
                         const SimulationSettings& s) {
  if (wps.size() < 2) throw std::invalid_argument("simulateFlight: need at least 2 waypoints");
  for (size_t k = 0; k < wps.size(); ++k) {
    if (!wps[k].allFinite()) {
      throw std::invalid_argument("simulateFlight: waypoint " + std::to_string(k + 1) + " is not finite, expected x y z in m");
    }
  }
  if (!(s.rate_hz >= 0.1 && s.rate_hz <= 1000.0)) {
    throw std::invalid_argument("SimulationSettings.rate_hz = " + std::to_string(s.rate_hz) + ", expected 0.1..1000");
  }
  // Timeline of pieces with their start position and 3-D direction.
  struct Span {
    Piece piece;
    Eigen::Vector3d start, dir;
    double t0;
  };
  std::vector<Span> spans;
  double t = 0.0;
  ProfileLimits lim;
  lim.acceleration = lim.deceleration = s.acceleration;
  double heading = 0.0;
  auto push = [&](const Piece& p, const Eigen::Vector3d& at, const Eigen::Vector3d& dir) {
    spans.push_back({p, at, dir, t});
    t += p.duration;
  };
  push(hover(std::max(s.hover_s, 1e-3)), wps[0], Eigen::Vector3d::Zero());
  for (size_t k = 0; k + 1 < wps.size(); ++k) {
    const Eigen::Vector3d d = wps[k + 1] - wps[k];
    const double len = d.norm();
    if (len < 1e-9) continue;
    const double horiz = d.head<2>().norm();
    if (horiz > 1e-6) {
      const double h = std::atan2(d.y(), d.x());
      const double turn = std::remainder(h - heading, 2.0 * M_PI);
      if (s.yaw_rate > 0.0 && std::abs(turn) > 1e-6) {
        Piece p = turnInPlace(turn, s.yaw_rate, heading);
        p.phase = Phase::Turn;
        push(p, wps[k], Eigen::Vector3d::Zero());
      }
      heading = h;
    }
    const double vc = horiz > std::abs(d.z()) ? s.cruise_speed : s.vertical_speed;
    for (const Piece& p : buildLegProfile(len, 0.0, vc, 0.0, lim, heading, d.z())) push(p, wps[k], d / len);
  }
  // Each piece starts where the previous one ended.
  {
    Eigen::Vector3d pos = wps[0];
    for (auto& sp : spans) {
      sp.start = pos;
      pos += sp.dir * sp.piece.length;
    }
  }
  Piece last = hover(std::max(s.hover_s, 1e-3));
  last.heading = heading;  // hover keeps the last heading (no yaw jump)
  push(last, wps.back(), Eigen::Vector3d::Zero());

  std::mt19937 rng(s.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  FlightLog log;
  log.source = "simulated";
  log.format = "simulated";
  log.metadata["vehicle"] = "simulated";
  log.metadata["sample_rate_hz"] = num(s.rate_hz, 6);
  log.metadata["seed"] = std::to_string(s.seed);
  const double total = t;
  const double dt = 1.0 / s.rate_hz;
  // A waypoint 1e300 m away would otherwise loop for ever filling memory.
  if (!(std::isfinite(total) && total * s.rate_hz < s.max_samples)) {
    throw std::invalid_argument("simulateFlight: the flight lasts " + std::to_string(total) + " s, " +
                                std::to_string(total * s.rate_hz) + " samples at " + std::to_string(s.rate_hz) +
                                " Hz, expected at most " + std::to_string(s.max_samples) +
                                " samples (waypoints too far apart?)");
  }
  size_t k = 0;
  for (double tt = 0.0; tt <= total; tt += dt) {
    while (k + 1 < spans.size() && tt >= spans[k].t0 + spans[k].piece.duration) ++k;
    const Span& sp = spans[k];
    const double tau = std::clamp(tt - sp.t0, 0.0, sp.piece.duration);
    MotionState st = stateAt(sp.piece, tau, sp.t0);
    st.t = tt;
    LogSample x;
    x.t = tt;
    double dist = 0.0;
    if (sp.piece.length > 0.0) {
      const double a = (sp.piece.v_end - sp.piece.v_start) / sp.piece.duration;
      dist = sp.piece.v_start * tau + 0.5 * a * tau * tau;
    }
    x.position = sp.start + sp.dir * dist;
    x.velocity = st.velocity + s.velocity_noise_mps * Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    x.acceleration = st.acceleration;
    x.yaw = st.heading;
    const double p = truth.power(st) + s.power_noise_w * noise(rng);
    x.voltage = s.voltage_start_v + (s.voltage_end_v - s.voltage_start_v) * tt / std::max(total, 1e-9);
    x.power = p;
    x.current = p / x.voltage;
    log.samples.push_back(x);
  }
  return log;
}

}  // namespace wattswath::calibration
