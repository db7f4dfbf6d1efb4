// Fitting an energy model's coefficients to measured power (Ceres Levenberg-Marquardt within the
// coefficients' bounds, covariance for their uncertainties). Ceres is private to this file.
#include <ceres/ceres.h>
#include <ceres/covariance.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "number_text.hpp"
#include "wattswath/calibration/diagnose.hpp"

namespace wattswath::calibration {
using namespace energy;  // the physics this library compares with measurements
using detail::num;
namespace {

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

}  // namespace wattswath::calibration
