// What `diagnose` prints, as JSON and in words (issue 18).
#include "diagnose_output.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "cli.hpp"
#include "log_json.hpp"

namespace wattswath::apps {
using nlohmann::json;

namespace {
json candidateJson(const calibration::CandidateResult& c) {
  json coeffs = json::object(), sig = json::object(), units = json::object();
  for (const auto& x : c.coefficients) {
    coeffs[x.name] = x.value;
    sig[x.name] = std::isfinite(x.sigma) ? json(x.sigma) : json(nullptr);
    units[x.name] = x.unit;
  }
  return {{"effect", c.effect},
          {"rmse_w", c.rmse_w},
          {"improvement_pct", c.improvement_pct},
          {"energy_error_pct", c.energy_error_pct},
          {"leg_energy_mape_pct", c.leg_energy_mape_pct},
          {"coefficients", coeffs},
          {"uncertainty", sig},
          {"units", units},
          {"identifiability", identifiabilityJson(c.coefficients)[c.effect]},
          {"summary", c.summary},
          {"indistinct_from", c.indistinct_from},
          {"notes", c.notes},
          {"significance", {{"test", "held-out likelihood ratio on effective samples"},
                            {"statistic", c.lr_statistic},
                            {"threshold", c.lr_threshold},
                            {"effective_samples", c.effective_samples}}},
          {"excess_share", c.excess_share},
          {"kept", c.kept},
          {"why_not_kept", c.why_not_kept}};
}

json signatureJson(const calibration::ResidualSignature& g) {
  json bins = json::array();
  for (const auto& b : g.bins) bins.push_back({{"lo", b.lo}, {"hi", b.hi}, {"count", b.count}, {"residual_w", b.residual_w}});
  return {{"signal", g.signal},
          {"unit", g.unit},
          {"strength", g.strength},
          {"form", g.form},
          {"slope", g.slope},
          {"statistic", g.statistic},
          {"threshold", g.threshold},
          {"effective_samples", g.effective_samples},
          {"significant", g.significant},
          {"same_as", g.same_as},
          {"sentence", g.sentence},
          {"bins", bins}};
}
}  // namespace

json diagnosisJson(const calibration::Diagnosis& d) {
  json cands = json::array(), found = json::array(), sigs = json::array(), tested = json::array(), stair = json::array();
  for (const auto& c : d.candidates) cands.push_back(candidateJson(c));
  for (const auto& c : d.found) found.push_back(candidateJson(c));
  bool any = false;
  for (const auto& g : d.signatures) any = any || g.significant;
  for (size_t k = 0; k < d.signatures.size(); ++k) {
    const auto& g = d.signatures[k];
    tested.push_back(signatureJson(g));
    // With no significant signal, the three strongest are given as leads (significant: false).
    if (d.verdict == "unexplained" && (g.significant || (!any && k < 3 && g.strength >= calibration::kMinLeadStrength)))
      sigs.push_back(signatureJson(g));
  }
  for (const auto& st : d.staircase) {
    stair.push_back({{"label", st.label},
                     {"rmse_w", st.metrics.rmse_w},
                     {"energy_error_pct", st.metrics.energy_error_pct},
                     {"leg_energy_mape_pct", st.metrics.leg_energy_mape_pct}});
  }
  json fin = metricsJson(d.final_heldout);
  fin["in_sample_rmse_w"] = d.final_rmse_w;
  fin["noise_ratio"] = d.noise_w > 0.0 ? d.final_rmse_w / d.noise_w : 1.0;
  return {{"verdict", d.verdict},
          {"conclusion", d.conclusion},
          {"found", found},
          {"signatures", sigs},
          {"signals_tested", tested},
          {"noise_w", d.noise_w},
          {"autocorrelation_time", d.autocorrelation_time},
          {"final", fin},
          {"search", d.search},
          {"candidates", cands},
          {"staircase", stair},
          {"final_effects", d.final_effects},
          {"untested", d.untested}};
}

void printDiagnosis(const calibration::Diagnosis& d) {
  std::cout << "verdict: " << d.verdict << "\n  " << d.conclusion << "\n";
  for (const auto& f : d.found) {
    std::cout << "found: " << f.effect << " - " << f.summary << " (held-out " << fixedText(f.rmse_w, 1)
              << " W, likelihood ratio " << fixedText(f.lr_statistic, 1) << " > " << fixedText(f.lr_threshold, 1) << ")\n";
  }
  if (!d.found.empty()) {
    std::string set;
    for (const auto& e : d.final_effects) set += (set.empty() ? "" : ",") + e;
    std::cout << "to fit the model with what was found: wattswath fit --effects " << set << " ..."
              << (std::find(d.final_effects.begin(), d.final_effects.end(), "wind") != d.final_effects.end()
                      ? " (wind replaces parasitic_drag: it is drag at air speed)"
                      : "")
              << "\n";
  }
  if (d.verdict == "unexplained") {
    std::cout << "the residual (measured - modelled) carries:\n";
    bool any = false;
    for (const auto& g : d.signatures) any = any || g.significant;
    for (size_t k = 0; k < d.signatures.size(); ++k) {
      const auto& g = d.signatures[k];
      if (!g.significant && (any || k >= 3 || g.strength < calibration::kMinLeadStrength)) continue;
      std::cout << "  " << g.signal << " (" << fixedText(100.0 * g.strength, 1) << " % of its variance, " << g.form
                << (g.significant ? "" : ", not significant: a lead") << "): " << g.sentence << "\n";
    }
  }
  std::cout << "white noise " << fixedText(d.noise_w, 1) << " W, residual correlated over "
            << fixedText(d.autocorrelation_time, 1) << " samples\n";
  std::cout << "search:\n";
  for (const auto& x : d.search) std::cout << "  " << x << "\n";
  std::cout << "candidates of the first round, best first (held-out RMSE after adding the effect):\n";
  for (const auto& c : d.candidates) {
    std::cout << "  " << c.effect << ": " << fixedText(c.rmse_w, 1) << " W (" << fixedText(c.improvement_pct, 1)
              << " %, likelihood ratio " << fixedText(c.lr_statistic, 1) << ") - " << c.summary << (c.kept ? "" : " [not kept: " + c.why_not_kept + "]") << "\n";
    if (!c.indistinct_from.empty()) {
      std::cout << "    cannot be told apart from:";
      for (const auto& n : c.indistinct_from) std::cout << " " << n;
      std::cout << "\n";
    }
  }
}

}  // namespace wattswath::apps
