// The held-out validation and the greedy search of diagnose() with its stopping rule (issue 18).
#include "diagnose_search.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "number_text.hpp"
#include "time_series.hpp"

namespace wattswath::calibration::detail {
using namespace energy;  // the physics this library compares with measurements

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
  // Contiguous blocks: a held-out block is predicted from the flight before and after it, so an
  // effect that switches at a time (a payload release) is estimated on the training part.
  // With 2 folds each held-out half would hide from its training half whatever happens in it: the
  // log is cut into 4 quarters instead and each fold holds out two that are not adjacent (1 and 3,
  // 2 and 4), so each training half spans the whole flight.
  const PreparedLog& L = logs.at(0);
  const int blocks = s.folds == 2 ? 4 : s.folds;
  f.label = s.folds == 2 ? "2 folds of alternate quarters (contiguous time blocks)"
                         : std::to_string(s.folds) + " contiguous time blocks";
  const double t0 = L.states.front().t, t1 = L.states.back().t;
  f.train.assign(s.folds, {SampleSet{&L, {}}});
  f.test.assign(s.folds, {SampleSet{&L, {}}});
  for (size_t i = 0; i < L.states.size(); ++i) {
    const double u = t1 > t0 ? (L.states[i].t - t0) / (t1 - t0) : 0.0;
    const int fold = std::min(blocks - 1, static_cast<int>(u * blocks)) % s.folds;
    for (int k = 0; k < s.folds; ++k) (k == fold ? f.test : f.train)[k][0].index.push_back(static_cast<int>(i));
  }
  return f;
}

Evaluation evaluate(const EnergyModel& start, const std::vector<std::string>& added, const std::vector<PreparedLog>& logs,
                    const Folds& folds, const FitSettings& fs) {
  Evaluation e;
  e.added = added;
  e.start = start;
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
  for (size_t j = 0; j < logs.size(); ++j) {
    rep.push_back(assembleReplay(logs[j], pred[j]));
    for (size_t i = 0; i < pred[j].size(); ++i) e.heldout_residual.push_back(pred[j][i] - logs[j].measured[i]);
  }
  e.heldout = errorMetrics(rep);
  std::vector<SampleSet> all;
  for (const auto& l : logs) all.push_back({&l, {}});
  e.full = fitModel(start, all, fs);
  return e;
}

double likelihoodRatio(const Evaluation& base, const Evaluation& better, double* n_eff) {
  const auto& r = better.heldout_residual;
  double a = 0.0, b = 0.0;
  for (size_t i = 0; i < r.size(); ++i) {
    a += base.heldout_residual[i] * base.heldout_residual[i];
    b += r[i] * r[i];
  }
  const double n = static_cast<double>(r.size()) / autocorrelationTime(r);
  if (n_eff) *n_eff = n;
  return a > 0.0 && b > 0.0 ? n * std::log(a / b) : 0.0;
}

EnergyModel withEffects(const EnergyModel& model, const std::vector<std::string>& added, const Vehicle& v,
                        const std::vector<std::shared_ptr<const energy::Effect>>& extra) {
  EnergyModel m = model;
  for (const auto& n : added) {
    const auto user = std::find_if(extra.begin(), extra.end(), [&](const auto& e) { return e && e->name() == n; });
    if (user != extra.end()) {
      m.add((*user)->clone());
    } else {
      m = withCandidate(m, n, v);
    }
  }
  return m;
}

namespace {

bool inModel(const EnergyModel& m, const std::string& n) { return m.has(n) || (n == "parasitic_drag" && m.has("wind")); }

size_t coefficientCount(const EnergyModel& m, const std::string& n) {
  return m.has(n) ? m.effect(n).coefficients().size() : 0;
}

// Why a fitted candidate is not a finding (empty: it may be): a coefficient at a bound, or a
// payload "released" outside the logs.
std::string boundProblem(const std::string& name, const FitResult& full, const std::vector<PreparedLog>& logs) {
  // A part of the effect fitted to zero (climb's descent_mass: climbing costs, descending does not)
  // while another part is measured away from its bounds: the effect is that other part alone.
  bool measured_part = false;
  for (const auto& c : full.coefficients) measured_part = measured_part || (c.effect == name && c.determined && !c.at_bound);
  for (const auto& c : full.coefficients) {
    if (c.effect != name) continue;
    if (c.at_bound && measured_part && c.value == 0.0 && (c.name == "descent_mass" || c.name == "climb_mass")) continue;
    if (c.at_bound) {
      return c.name + " stopped at its bound (" + num(c.value) + " " + c.unit +
             "): the candidate's form does not fit what is missing";
    }
    // An effect whose size is within 3 sigma of none is not a finding (sigma allows for the
    // residual's autocorrelation, fitModel).
    if ((c.name == "payload_mass" || c.name == "yaw_power") && c.determined && std::isfinite(c.sigma) &&
        c.value < 3.0 * c.sigma) {
      return c.name + " " + num(c.value) + " +- " + num(c.sigma, 2) + " " + c.unit + " is within 3 sigma of none";
    }
    if (c.name == "release_time") {
      double t0 = logs.front().states.front().t, t1 = logs.front().states.back().t;
      for (const auto& l : logs) t0 = std::min(t0, l.states.front().t), t1 = std::max(t1, l.states.back().t);
      if (c.value < t0 || c.value > t1) {
        return "the payload would be released at t = " + num(c.value) + " s, outside the log (" + num(t0) + " to " +
               num(t1) + " s): it stands in for a drift, not a release";
      }
    }
  }
  return "";
}

CandidateResult score(const Evaluation& cur, const Evaluation& ev, const std::string& name, double noise_w,
                      const std::vector<PreparedLog>& logs, const DiagnoseSettings& s) {
  CandidateResult c;
  c.effect = name;
  c.rmse_w = ev.heldout.rmse_w;
  c.energy_error_pct = ev.heldout.energy_error_pct;
  c.leg_energy_mape_pct = ev.heldout.leg_energy_mape_pct;
  const double before = cur.heldout.rmse_w;
  c.improvement_pct = before > 0 ? 100.0 * (before - c.rmse_w) / before : 0.0;
  for (const auto& fc : ev.full.coefficients)
    if (fc.effect == name) c.coefficients.push_back(fc);
  c.summary = describeEffect(name, ev.full.coefficients);
  c.notes = ev.full.notes;
  c.lr_statistic = likelihoodRatio(cur, ev, &c.effective_samples);
  const auto added = static_cast<int>(std::max<size_t>(1, coefficientCount(ev.start, name) - coefficientCount(cur.start, name)));
  c.lr_threshold = chiSquareQuantile(added, s.p_value);
  const double excess = before * before - noise_w * noise_w;
  c.excess_share = excess > 0.0 ? (before * before - c.rmse_w * c.rmse_w) / excess : 0.0;
  const std::string bound = boundProblem(name, ev.full, logs);
  if (c.lr_statistic <= c.lr_threshold) {
    c.why_not_kept = "held-out improvement not significant (likelihood ratio " + num(c.lr_statistic, 3) + " on " +
                     num(c.effective_samples, 3) + " effective samples, " + num(c.lr_threshold, 3) + " needed)";
  } else if (c.excess_share < s.min_excess_share) {
    c.why_not_kept = "removes only " + num(100.0 * c.excess_share, 2) + " % of the held-out variance above the noise (" +
                     num(100.0 * s.min_excess_share, 2) + " % needed): a stand-in for part of something else";
  } else if (!bound.empty()) {
    c.why_not_kept = bound;
  } else {
    c.kept = true;
  }
  return c;
}

// Marks candidates of the first round whose fitted power contributions are nearly proportional.
void markIndistinct(std::vector<CandidateResult>& cs, const std::vector<Evaluation>& evs, const Evaluation& base,
                    const std::vector<PreparedLog>& logs, double limit) {
  std::vector<double> base_p;
  for (const auto& l : logs) {
    const auto p = modelPower(base.full.model, l);
    base_p.insert(base_p.end(), p.begin(), p.end());
  }
  std::vector<std::vector<double>> contrib;
  for (const auto& e : evs) {
    std::vector<double> c;
    for (const auto& l : logs) {
      const auto p = modelPower(e.full.model, l);
      c.insert(c.end(), p.begin(), p.end());
    }
    for (size_t i = 0; i < c.size(); ++i) c[i] -= base_p[i];
    contrib.push_back(std::move(c));
  }
  for (size_t i = 0; i < cs.size(); ++i) {
    for (size_t j = i + 1; j < cs.size(); ++j) {
      if (cs[i].improvement_pct < 0.5 || cs[j].improvement_pct < 0.5) continue;
      if (correlation(contrib[i], contrib[j]) > limit) {
        cs[i].indistinct_from.push_back(cs[j].effect);
        cs[j].indistinct_from.push_back(cs[i].effect);
      }
    }
  }
}

std::string percent(double share) { return num(100.0 * share, 3) + " %"; }
}  // namespace

namespace {
struct Tried {
  std::vector<CandidateResult> results;
  std::vector<Evaluation> evals;
};

struct SearchContext {
  const EnergyModel& model;
  const Vehicle& v;
  const std::vector<PreparedLog>& logs;
  const Folds& folds;
  const DiagnoseSettings& s;
  double noise_w;
};

// Every candidate not in the current model (nor dropped earlier) added to it and evaluated.
Tried tryRound(const SearchContext& c, const Evaluation& cur, const std::vector<std::string>& names,
               const std::set<std::string>& dropped) {
  Tried t;
  for (const auto& n : names) {
    if (inModel(cur.start, n) || dropped.count(n)) continue;
    auto next = cur.added;
    next.push_back(n);
    t.evals.push_back(evaluate(withEffects(c.model, next, c.v, c.s.extra_candidates), next, c.logs, c.folds, c.s.fit));
    t.results.push_back(score(cur, t.evals.back(), n, c.noise_w, c.logs, c.s));
  }
  return t;
}

// The kept candidate with the largest held-out improvement; a kept one with fewer coefficients
// replaces it when the best is not significantly better than it (parsimony: wind that only
// stands in for drag gives way to drag). -1 when none is kept.
int pickBest(const Tried& t, const SearchContext& c) {
  int best = -1;
  for (size_t k = 0; k < t.results.size(); ++k) {
    if (t.results[k].kept && (best < 0 || t.results[k].improvement_pct > t.results[best].improvement_pct)) best = static_cast<int>(k);
  }
  if (best < 0) return best;
  const auto count = [&](size_t k) { return coefficientCount(t.evals[k].start, t.results[k].effect); };
  int simplest = best;
  for (size_t k = 0; k < t.results.size(); ++k) {
    if (!t.results[k].kept || count(k) >= count(simplest)) continue;
    const double lr = likelihoodRatio(t.evals[k], t.evals[best]);
    if (lr <= chiSquareQuantile(static_cast<int>(count(best) - count(k)), c.s.p_value)) simplest = static_cast<int>(k);
  }
  return simplest;
}

// Each earlier kept effect tried without: removed when the model is not significantly worse.
void revisit(const SearchContext& c, Evaluation& cur, std::set<std::string>& dropped, Diagnosis& d) {
  for (size_t k = 0; k + 1 < cur.added.size();) {
    auto without = cur.added;
    const std::string f = without[k];
    without.erase(without.begin() + static_cast<long>(k));
    Evaluation ev = evaluate(withEffects(c.model, without, c.v, c.s.extra_candidates), without, c.logs, c.folds, c.s.fit);
    const double z = likelihoodRatio(ev, cur);
    if (z > chiSquareQuantile(static_cast<int>(std::max<size_t>(1, coefficientCount(cur.start, f))), c.s.p_value)) {
      ++k;
      continue;
    }
    d.search.push_back(f + " is no longer needed once " + cur.added.back() + " is in (likelihood ratio " + num(z, 3) +
                       " for keeping it): removed, it stood in for part of " + cur.added.back());
    d.found.erase(std::remove_if(d.found.begin(), d.found.end(), [&](const CandidateResult& x) { return x.effect == f; }),
                  d.found.end());
    dropped.insert(f);
    cur = std::move(ev);
    d.staircase.push_back({"- " + f, cur.heldout});
  }
}
}  // namespace

Evaluation searchEffects(const EnergyModel& model, const Vehicle& v, const std::vector<PreparedLog>& logs,
                         const Folds& folds, const DiagnoseSettings& s, double noise_w, const Evaluation& base,
                         Diagnosis& d) {
  std::vector<std::string> names = s.candidates;
  if (names.empty()) names = knownEffectNames();
  for (const auto& e : s.extra_candidates)
    if (e && std::find(names.begin(), names.end(), e->name()) == names.end()) names.push_back(e->name());
  const SearchContext c{model, v, logs, folds, s, noise_w};
  Evaluation cur = base;
  std::set<std::string> dropped;
  for (int round = 1; round <= s.max_effects; ++round) {
    Tried t = tryRound(c, cur, names, dropped);
    if (round == 1) {
      markIndistinct(t.results, t.evals, base, logs, s.indistinct_correlation);
      d.candidates = t.results;
      std::stable_sort(d.candidates.begin(), d.candidates.end(),
                       [](const CandidateResult& a, const CandidateResult& b) { return a.improvement_pct > b.improvement_pct; });
    }
    const int best = pickBest(t, c);
    if (best < 0) {
      std::string why = "round " + std::to_string(round) + ": no candidate passes the stopping rule";
      const auto top = std::max_element(t.results.begin(), t.results.end(), [](const auto& a, const auto& b) {
        return a.improvement_pct < b.improvement_pct;
      });
      if (top != t.results.end()) why += " (best " + top->effect + ", " + num(top->improvement_pct, 3) + " %: " + top->why_not_kept + ")";
      d.search.push_back(why);
      break;
    }
    const CandidateResult& r = t.results[best];
    d.search.push_back("round " + std::to_string(round) + ": + " + r.effect + " (held-out RMSE " +
                       num(cur.heldout.rmse_w, 3) + " -> " + num(r.rmse_w, 3) + " W, likelihood ratio " + num(r.lr_statistic, 3) +
                       ", removes " + percent(r.excess_share) + " of the variance above the noise)");
    d.found.push_back(r);
    cur = std::move(t.evals[best]);
    d.staircase.push_back({"+ " + r.effect, cur.heldout});
    revisit(c, cur, dropped, d);
  }
  // The found effects as fitted in the final model.
  for (auto& f : d.found) {
    f.coefficients.clear();
    for (const auto& fc : cur.full.coefficients)
      if (fc.effect == f.effect) f.coefficients.push_back(fc);
    f.summary = describeEffect(f.effect, cur.full.coefficients);
  }
  return cur;
}

}  // namespace wattswath::calibration::detail
