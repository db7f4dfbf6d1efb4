// Fitting an energy model's coefficients to measured power (Ceres Levenberg-Marquardt within the
// coefficients' bounds; their covariance from the Jacobian, coefficient_covariance.cpp). Ceres is private to this file.
#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "coefficient_covariance.hpp"
#include "excitation.hpp"
#include "time_series.hpp"
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

// Residuals model power - measured power, for coefficients in per-effect parameter blocks, with
// the Jacobian by central differences of Ceres's own step (max(sqrt(eps), 1e-6 |x|)) taken on the
// one effect a coefficient belongs to: the other effects' power does not change, so each column
// costs two evaluations of one effect instead of two of the whole model (numeric differentiation
// of the whole model spent 2k + 1 model evaluations per Jacobian).
class PowerCost final : public ceres::CostFunction {
 public:
  PowerCost(const EnergyModel& model, std::vector<int> block_of_effect, const Points* pts,
            const std::vector<std::vector<double>>& block_values)
      : model_(model), block_of_(std::move(block_of_effect)), pts_(pts) {
    for (const auto& v : block_values) mutable_parameter_block_sizes()->push_back(static_cast<int>(v.size()));
    set_num_residuals(static_cast<int>(pts->state.size()));
  }

  bool Evaluate(double const* const* params, double* residuals, double** jacobians) const override {
    setParams(model_, params);
    const auto& e = model_.effects();
    const size_t n = pts_->state.size();
    std::fill(residuals, residuals + n, 0.0);
    for (const auto& eff : e)  // summed effect by effect in the model's order, as EnergyModel::power does
      for (size_t i = 0; i < n; ++i) residuals[i] += eff->power(*pts_->state[i]);
    for (size_t i = 0; i < n; ++i) residuals[i] -= pts_->measured[i];
    if (!jacobians) return true;
    std::vector<double> plus(n);
    for (size_t k = 0; k < e.size(); ++k) {
      const int b = block_of_[k];
      if (b < 0 || !jacobians[b]) continue;
      const size_t m = e[k]->coefficients().size();
      std::vector<double> x(params[b], params[b] + m);
      for (size_t j = 0; j < m; ++j) {
        const double delta = std::max(std::sqrt(std::numeric_limits<double>::epsilon()), 1e-6 * std::abs(x[j]));
        std::vector<double> moved = x;
        moved[j] = x[j] + delta;
        e[k]->setCoefficientValues(moved);
        for (size_t i = 0; i < n; ++i) plus[i] = e[k]->power(*pts_->state[i]);
        moved[j] = x[j] - delta;
        e[k]->setCoefficientValues(moved);
        for (size_t i = 0; i < n; ++i) jacobians[b][i * m + j] = (plus[i] - e[k]->power(*pts_->state[i])) / (2.0 * delta);
      }
      e[k]->setCoefficientValues(x);
    }
    return true;
  }

  // Sets the coefficients of `m` from the parameter blocks.
  void setParams(EnergyModel& m, double const* const* params) const {
    const auto& e = m.effects();
    for (size_t k = 0; k < e.size(); ++k) {
      if (block_of_[k] < 0) continue;
      const size_t n = e[k]->coefficients().size();
      e[k]->setCoefficientValues(std::vector<double>(params[block_of_[k]], params[block_of_[k]] + n));
    }
  }

 private:
  mutable EnergyModel model_;
  std::vector<int> block_of_;  // -1 when the effect has no coefficients
  const Points* pts_;
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
  detail::validate(s.excitation);
}

// Why each coefficient (effect by effect, in order) cannot be determined by the excitation of
// `pts` (empty: it can), in words.
std::vector<std::vector<std::string>> heldCoefficients(const EnergyModel& m, const Points& pts, const ExcitationSettings& s) {
  std::vector<std::vector<std::string>> held;
  for (const auto& e : m.effects()) {
    held.emplace_back();
    for (const auto& c : e->coefficients()) {
      const auto x = detail::excitationOf(e->name(), c.name, pts.state, s);
      held.back().push_back(x.enough() ? std::string()
                                       : std::to_string(x.excited) + " of " + std::to_string(x.airborne) +
                                             " airborne samples " + x.what + " (" + std::to_string(x.required) +
                                             " needed): " + x.why);
    }
  }
  return held;
}

// Puts back the values `start` gave the held coefficients (the initialisers may have moved them).
void restoreHeld(EnergyModel& m, const EnergyModel& start, const std::vector<std::vector<std::string>>& held) {
  for (size_t k = 0; k < m.effects().size(); ++k) {
    auto v = m.effects()[k]->coefficients();
    std::vector<double> vals;
    for (size_t c = 0; c < v.size(); ++c) {
      vals.push_back(held[k][c].empty() ? v[c].value : start.effects()[k]->coefficients()[c].value);
    }
    if (!vals.empty()) m.effects()[k]->setCoefficientValues(vals);
  }
}

// The Ceres problem of a fit: one parameter block per effect with coefficients, bounded, the
// held coefficients constant.
struct Blocks {
  std::vector<std::vector<double>> values;
  std::vector<int> block_of;  // per effect; -1 when the effect has no coefficients
  std::vector<double*> ptrs;
  bool any_free = false;
};

Blocks makeBlocks(const EnergyModel& m, const std::vector<std::vector<std::string>>& held) {
  Blocks b;
  const auto& effects = m.effects();
  b.block_of.assign(effects.size(), -1);
  for (size_t k = 0; k < effects.size(); ++k) {
    if (effects[k]->coefficients().empty()) continue;
    b.block_of[k] = static_cast<int>(b.values.size());
    std::vector<double> v;
    for (const auto& c : effects[k]->coefficients()) v.push_back(std::clamp(c.value, c.lower, c.upper));
    b.values.push_back(v);
    for (const auto& h : held[k]) b.any_free = b.any_free || h.empty();
  }
  for (auto& v : b.values) b.ptrs.push_back(v.data());
  return b;
}

// Fits the free coefficients of `out.model` to `pts`; returns the final cost.
double solve(FitResult& out, Blocks& b, const std::vector<std::vector<std::string>>& held, const Points& pts,
             const FitSettings& s, ceres::Problem& problem) {
  const auto& effects = out.model.effects();
  auto* cost = new PowerCost(out.model, b.block_of, &pts, b.values);
  problem.AddResidualBlock(cost, s.huber_w > 0.0 ? new ceres::HuberLoss(s.huber_w) : nullptr, b.ptrs);
  for (size_t k = 0; k < effects.size(); ++k) {
    if (b.block_of[k] < 0) continue;
    double* p = b.ptrs[b.block_of[k]];
    const auto& cs = effects[k]->coefficients();
    std::vector<int> fixed;
    for (size_t c = 0; c < cs.size(); ++c) {
      if (!held[k][c].empty()) fixed.push_back(static_cast<int>(c));
      problem.SetParameterLowerBound(p, static_cast<int>(c), cs[c].lower);
      problem.SetParameterUpperBound(p, static_cast<int>(c), cs[c].upper);
    }
    if (fixed.size() == cs.size()) {
      problem.SetParameterBlockConstant(p);
    } else if (!fixed.empty()) {
      problem.SetManifold(p, new ceres::SubsetManifold(static_cast<int>(cs.size()), fixed));
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
  if (b.any_free) ceres::Solve(opt, &problem, &summary);
  cost->setParams(out.model, b.ptrs.data());
  double cost_value = 0.0;
  for (size_t i = 0; i < pts.state.size(); ++i) {
    const double r = out.model.power(*pts.state[i]) - pts.measured[i];
    cost_value += 0.5 * r * r;
  }
  return b.any_free ? summary.final_cost : cost_value;
}

// The coefficients of `out.model` as FittedCoefficients (sigma NaN), the held ones not determined.
void listCoefficients(FitResult& out, const std::vector<std::vector<std::string>>& held) {
  const auto& effects = out.model.effects();
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
      if (!held[k][c].empty()) {
        f.determined = false;
        f.fitted = false;
        f.why_not_determined = held[k][c] + "; kept at " + num(f.value) + " " + f.unit +
                               ", its starting value (from the vehicle's physics for the model's own effects)";
        out.notes.push_back(f.effect + "." + f.name + " is not determined by the data: " + f.why_not_determined);
      } else {
        const double span = std::max(1e-12, 1e-6 * (cs[c].upper - cs[c].lower));
        f.at_bound = f.value <= cs[c].lower + span || f.value >= cs[c].upper - span;
      }
      out.coefficients.push_back(f);
    }
  }
}

// Jacobian of the residuals (rows) in the free coefficients (columns, in out.coefficients'
// order), with Ceres's Huber correction sqrt(rho') on rows beyond the loss scale.
Eigen::MatrixXd freeJacobian(const FitResult& out, const Blocks& b, const Points& pts, const std::vector<size_t>& free,
                             double huber_w) {
  PowerCost cost(out.model, b.block_of, &pts, b.values);
  const size_t n = pts.state.size();
  std::vector<double> residuals(n);
  std::vector<std::vector<double>> jac(b.ptrs.size());
  std::vector<double*> jp;
  for (size_t k = 0; k < b.ptrs.size(); ++k) {
    jac[k].resize(n * b.values[k].size());
    jp.push_back(jac[k].data());
  }
  std::vector<const double*> params(b.ptrs.begin(), b.ptrs.end());
  cost.Evaluate(params.data(), residuals.data(), jp.data());
  struct Ref {
    size_t block, idx;
  };
  std::vector<Ref> refs;
  const auto& effects = out.model.effects();
  for (size_t k = 0; k < effects.size(); ++k)
    for (size_t c = 0; c < effects[k]->coefficients().size(); ++c) refs.push_back({static_cast<size_t>(b.block_of[k]), c});
  Eigen::MatrixXd j(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(free.size()));
  for (size_t col = 0; col < free.size(); ++col) {
    const Ref r = refs[free[col]];
    const size_t m = b.values[r.block].size();
    for (size_t i = 0; i < n; ++i) j(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(col)) = jac[r.block][i * m + r.idx];
  }
  if (huber_w > 0.0) {
    for (size_t i = 0; i < n; ++i) {
      const double a = std::abs(residuals[i]);
      if (a > huber_w) j.row(static_cast<Eigen::Index>(i)) *= std::sqrt(huber_w / a);
    }
  }
  return j;
}

// Formal uncertainty of the free coefficients: covariance of the linearised problem times the
// residual variance; a free coefficient the data do not constrain, alone or only in a combination
// with others, is marked not determined, and strongly correlated pairs are noted.
void addUncertainty(FitResult& out, const Blocks& b, const Points& pts, double huber_w, double final_cost) {
  std::vector<size_t> free;
  for (size_t i = 0; i < out.coefficients.size(); ++i)
    if (out.coefficients[i].determined) free.push_back(i);  // the others are held by their excitation
  if (free.empty()) return;
  const size_t n = pts.state.size(), p = free.size();
  // Correlated residuals carry n / tau independent samples' worth of information (issue 18).
  const double s2 = n > p ? 2.0 * final_cost / static_cast<double>(n - p) * out.autocorrelation_time : 0.0;
  const auto cov = detail::coefficientCovariance(freeJacobian(out, b, pts, free, huber_w), s2);
  auto label = [&](size_t i) { return out.coefficients[i].effect + "." + out.coefficients[i].name; };
  for (size_t k = 0; k < p; ++k) {
    auto& c = out.coefficients[free[k]];
    if (cov.determined[k]) {
      c.sigma = std::sqrt(cov.covariance(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)));
      continue;
    }
    c.determined = false;
    if (cov.tied_to[k].empty()) {
      c.why_not_determined = "the modelled power does not change with it at the fitted values; its value " + num(c.value) +
                             " " + c.unit + " is arbitrary";
    } else {
      std::string others;
      for (int o : cov.tied_to[k]) {
        const std::string name = label(free[static_cast<size_t>(o)]);
        if (others.find(name) == std::string::npos) others += (others.empty() ? "" : ", ") + name;
      }
      c.why_not_determined = "the data fix only its combination with " + others + "; its value " + num(c.value) + " " +
                             c.unit + " is one of many that fit as well";
    }
    out.notes.push_back(label(free[k]) + " is not determined by the data (" + c.why_not_determined + ")");
  }
  for (size_t a = 0; a < p; ++a) {
    for (size_t bb = a + 1; bb < p; ++bb) {
      if (!cov.determined[a] || !cov.determined[bb]) continue;
      const auto ia = static_cast<Eigen::Index>(a), ib = static_cast<Eigen::Index>(bb);
      const double va = cov.covariance(ia, ia), vb = cov.covariance(ib, ib);
      if (!(va > 0 && vb > 0)) continue;
      const double r = cov.covariance(ia, ib) / std::sqrt(va * vb);
      if (std::abs(r) > 0.95) {
        out.notes.push_back(label(free[a]) + " and " + label(free[bb]) + " are correlated (r = " + num(r, 3) +
                            "): the data constrain mainly a combination of them");
      }
    }
  }
}

// A fitted coefficient the data do not narrow is marked not determined, with the reason: one that
// stopped at a physical bound (its value is the bound and its +- the curvature of a fit that wanted
// to go past it, not a measurement); a magnitude (lower bound >= 0) whose uncertainty is as large as
// its value (the data do not tell it from none); a signed one (a wind component) whose uncertainty
// spans a quarter of its physical range. The covariance alone only drops directions that are
// numerically flat: a wind of 15 +- 1e3 m/s and a hover power of 204 +- 1.5e3 W passed.
void markUnresolved(FitResult& out) {
  size_t i = 0;
  for (const auto& e : out.model.effects()) {
    for (const auto& cf : e->coefficients()) {
      auto& c = out.coefficients[i++];
      if (!c.fitted || !c.determined) continue;
      std::string why;
      if (c.at_bound) {
        why = "it stopped at its physical bound, " + num(c.value) + " " + c.unit +
              ": the data push it past the bound, so the value is the bound, not a measurement";
        c.sigma = std::numeric_limits<double>::quiet_NaN();
      } else if (std::isfinite(c.sigma) && cf.lower >= 0.0 && c.sigma >= std::abs(c.value)) {
        why = "its uncertainty +- " + num(c.sigma, 2) + " " + c.unit + " is as large as its value " + num(c.value) +
              ": the data do not tell it from none";
      } else if (std::isfinite(c.sigma) && cf.lower < 0.0 && c.sigma > 0.25 * (cf.upper - cf.lower)) {
        why = "its uncertainty +- " + num(c.sigma, 2) + " " + c.unit + " spans more than a quarter of its physical range [" +
              num(cf.lower) + ", " + num(cf.upper) + "] " + c.unit;
      }
      if (why.empty()) continue;
      c.determined = false;
      c.why_not_determined = why;
      out.notes.push_back(c.effect + "." + c.name + " is not determined by the data (" + why + ")");
    }
  }
}

}  // namespace

FitResult fitModel(const EnergyModel& start, const std::vector<SampleSet>& data, const FitSettings& s) {
  checkSettings(s);
  const Points pts = gather(data, s.max_samples);
  if (pts.state.size() < 3) throw std::invalid_argument("fitModel: fewer than 3 samples to fit");
  FitResult out;
  out.model = start;
  const auto held = heldCoefficients(start, pts, s.excitation);
  initPayload(out.model, pts);
  initTranslationalLift(out.model, pts);
  restoreHeld(out.model, start, held);
  Blocks b = makeBlocks(out.model, held);
  ceres::Problem problem;
  const double final_cost = solve(out, b, held, pts, s, problem);

  std::vector<double> res(pts.state.size());
  for (size_t i = 0; i < res.size(); ++i) res[i] = out.model.power(*pts.state[i]) - pts.measured[i];
  out.train_rmse_w = rms(res);
  out.samples = static_cast<int>(res.size());
  out.autocorrelation_time = detail::autocorrelationTime(res);
  listCoefficients(out, held);
  if (b.any_free) addUncertainty(out, b, pts, s.huber_w, final_cost);
  for (const auto& c : out.coefficients) {
    if (c.at_bound && !c.determined) out.notes.push_back(c.effect + "." + c.name + " stopped at a bound (" + num(c.value) + " " + c.unit + ")");
  }
  markUnresolved(out);
  return out;
}

}  // namespace wattswath::calibration
