// `wattswath reproduce`, section 10: Marins, Cabreira & Ferreira (2018), the closed-form energy model.
// Every number of the paper the model can compute, ours beside it, and where they part, why.
#include <cmath>
#include <string>
#include <vector>

#include "marins_paper.hpp"
#include "reproduce.hpp"
#include "wattswath/energy/marins.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/optimal_speed.hpp"
#include "wattswath/energy/turns.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::apps {
namespace {

namespace en = wattswath::energy;
namespace mp = wattswath::apps::marins;

std::string n(double x, int digits = 4) { return reproNumber(x, digits); }

std::string pct(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%+.1f %%", x);
  return b;
}

/// A 3 x 4 Markdown table in Table V's layout; `cell(i, j)` gives the text of row i, column j.
template <class Cell>
std::string table5Markdown(const std::string& title, Cell cell) {
  std::string md = "| " + title + " | beta = 30 deg | beta = 45 deg | beta = 60 deg | beta = 90 deg |\n|---|---:|---:|---:|---:|\n";
  for (int i = 0; i < 3; ++i) {
    md += "| " + n(mp::kTable5Distance[i]) + " m |";
    for (int j = 0; j < 4; ++j) md += " " + cell(i, j) + " |";
    md += "\n";
  }
  return md;
}

ReproSection reproduceMarins(const ReproContext& ctx) {
  ReproSection out;
  const std::string vehicle_file = "data/vehicles/iris.json";
  const en::Vehicle v = en::loadVehicle(ctx.source_dir + "/" + vehicle_file);
  const en::MarinsClosedForm paper = en::MarinsClosedForm::fromVehicle(v, en::DragIntegration::PaperCruiseSpeed);
  const en::MarinsClosedForm exact = en::MarinsClosedForm::fromVehicle(v, en::DragIntegration::Exact);
  const double w = v.max_yaw_rate_radps;
  const en::ProfileLimits lim{v.max_acceleration_mps2, v.max_acceleration_mps2};
  nlohmann::json& J = out.json["marins"];
  std::string& md = out.markdown;

  md += "## Marins, Cabreira & Ferreira (2018): closed-form energy model\n\n"
        "Vehicle `" + vehicle_file + "` (the paper's IRIS: m 1.3 kg, A 0.2027 m^2, eta 0.90 x 0.65, C_D A 0.01547 m^2, "
        "a 1 m/s^2, omega_max 2.1 rad/s, rho 1.2928 kg/m^3, g 9.81 m/s^2). *Ours* is the paper's own equations "
        "evaluated without intermediate rounding; our default model (exact drag integral, numerical optimum) is "
        "shown separately. Where the paper's number does not follow from its equations we say what it must have "
        "used instead; those inferred values are never used by the model.\n\n";

  // ------------------------------------------------------------------ hover
  const double p0 = en::marinsRotorPowerW(v), ph = en::marinsHoverPowerW(v), pi = en::idealHoverPowerW(v);
  en::Vehicle g98 = v;
  g98.gravity_mps2 = 9.80;
  const double p0_g98 = en::marinsRotorPowerW(g98);
  const double v2 = std::sqrt(2.0 * v.weightN() / (v.air_density_kgpm3 * v.disk_area_m2));
  nlohmann::json hover = nlohmann::json::array();
  hover.push_back(reproRow("P0, rotor power to hover (Eq. 4)", mp::kP0, p0, "W",
                           "the paper's 125.6 W is Eq. 4 with g = 9.80 (" + n(p0_g98, 5) + " W), not its stated 9.81"));
  hover.push_back(reproRow("P_hov = P0 / (0.90 x 0.65) (Eq. 5)", mp::kPHover, ph, "W", "carries the g = 9.80 of P0"));
  hover.push_back(reproRow(
      "v2, far-wake velocity (Eq. 3)", mp::kV2, v2, "m/s",
      "Eq. 3 with the stated m, rho, A gives " + n(v2) + " m/s; 10.24 m/s needs m g / (rho A) " +
          pct(100.0 * (mp::kV2 * mp::kV2 / (v2 * v2) - 1.0)) +
          " larger (e.g. m = " + n(v.mass_kg * mp::kV2 * mp::kV2 / (v2 * v2), 3) +
          " kg); it only feeds the advance-ratio estimate of eta_prop, no energy"));
  J["hover"] = hover;
  J["ideal_momentum_w"] = pi;
  J["eq4_over_ideal"] = p0 / pi;
  md += "### Hover power (Eq. 1-5) and ideal momentum theory\n\n" + reproMarkdownTable(hover) + "\n";
  md += "Ideal momentum theory gives T^1.5 / sqrt(2 rho A) = " + n(pi) + " W for the same vehicle; Eq. 4 is exactly " +
        n(p0 / pi, 4) +
        " times that. The factor is exactly 2 because Eq. 4 multiplies the thrust by the far-wake "
        "velocity v2 (P = F v2) although the air passes the disk at v3 = v2 / 2 (the paper's own Eq. 2 uses "
        "v3 = (v1 + v2)/2 for the mass flow); the ideal induced power is T v3. What absorbs the factor is the "
        "efficiency chain: read against momentum theory, P_hov = P_ideal x 2 / (0.90 x 0.65) means an "
        "effective rotor figure of merit of 0.65 / 2 = 0.33, and the number that actually validates it is the "
        "measured hover power of Di Franco & Buttazzo, " + n(mp::kMeasuredHover) + " W (Sec. IV-A), which P_hov "
        "matches within " + pct(100.0 * (ph / mp::kMeasuredHover - 1.0)) +
        ". With ideal momentum theory and the same efficiencies the model would predict " + n(pi / v.totalEfficiency()) +
        " W, half the measurement. We keep Eq. 4 as published (the `hover` effect's coefficient is P_hov); a fit "
        "to logs re-estimates it anyway.\n\n";

  // ------------------------------------------------------------------ optimal velocity
  const double v600 = paper.eq10OptimalSpeed(600.0), v1200 = paper.eq10OptimalSpeed(1200.0);
  // The distance at which Eq. 10 gives the paper's 16.2 m/s (bisection: v_opt grows with d).
  double lo = 600.0, hi = 1200.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (paper.eq10OptimalSpeed(mid) < mp::kVopt1200 ? lo : hi) = mid;
  }
  const double d_for_162 = 0.5 * (lo + hi);
  const en::MarinsClosedForm paper98 = en::MarinsClosedForm::fromVehicle(g98, en::DragIntegration::PaperCruiseSpeed);
  nlohmann::json vopt = nlohmann::json::array();
  vopt.push_back(reproRow("v_opt at 600 m (Eq. 10)", mp::kVopt600, v600, "m/s"));
  vopt.push_back(reproRow(
      "v_opt at 1,200 m (Eq. 10)", mp::kVopt1200, v1200, "m/s",
      "Eq. 10's real root at 1,200 m is " + n(v1200) + " m/s (" + n(paper98.eq10OptimalSpeed(1200.0)) +
          " with g = 9.80); 16.2 m/s is the root at d = " + n(d_for_162) +
          " m, so the paper's value was probably read off its Fig. 3 curve"));
  J["optimal_velocity"] = vopt;
  md += "### Optimal velocity (Eq. 10, Fig. 3)\n\n" + reproMarkdownTable(vopt) + "\n";

  const en::EnergyModel def_model = [&] {
    en::EnergyModel m = en::marinsModel(v, en::DragIntegration::Exact);
    m.remove("yaw_rate");
    return m;
  }();
  md += "Fig. 3 as numbers: Eq. 10's root for the full model and the two variants of Eq. 11, and our default "
        "model's optimum (exact drag integral, `optimalCruiseSpeed`, no speed limit). Speeds in m/s.\n\n"
        "| d [m] | Eq. 10 full | without kinetic | without drag | default model (exact drag) |\n"
        "|---:|---:|---:|---:|---:|\n";
  nlohmann::json curve = nlohmann::json::array();
  for (double d : {25.0, 50.0, 100.0, 150.0, 300.0, 600.0, 1200.0, 2400.0, 5000.0, 10000.0}) {
    const double full = paper.eq10OptimalSpeed(d), nk = paper.eq10OptimalSpeed(d, {false, true}),
                 nd = paper.eq10OptimalSpeed(d, {true, false});
    const double ex = en::optimalCruiseSpeed(def_model, d, 0.0, 0.0, lim, 1e3).speed;
    curve.push_back({{"distance_m", d}, {"full", full}, {"without_kinetic", nk}, {"without_drag", nd}, {"default_exact", ex}});
    md += "| " + n(d) + " | " + n(full) + " | " + n(nk) + " | " + n(nd) + " | " + n(ex) + " |\n";
  }
  J["fig3_curve"] = curve;
  md += "\nAs d grows, Eq. 10 tends to (P0 / (rho C_D A))^(1/3) = " + n(paper.longLegOptimalSpeed()) +
        " m/s (the paper's \"limit\"). As the paper concludes, leaving out the kinetic term moves v_opt by a few "
        "per cent at 600 m (" + pct(100.0 * (paper.eq10OptimalSpeed(600.0, {false, true}) / v600 - 1.0)) +
        ") and less on longer legs, while leaving out drag is badly wrong (" +
        pct(100.0 * (paper.eq10OptimalSpeed(600.0, {true, false}) / v600 - 1.0)) +
        " at 600 m, unbounded as d grows). The exact drag integral charges the accelerating and braking ramps "
        "their true, lower speed, so its optimum is higher than Eq. 10's (table; discussed below).\n\n";

  // ------------------------------------------------------------------ strategies at 600 m, 45 deg
  const mp::Procedure eqs{false, ph, ph};
  const double p_turn = mp::impliedTurnPower(w), p_round = mp::impliedRoundedHoverPower();
  const mp::Procedure inferred{true, p_turn, p_turn};
  const auto s = mp::strategies(paper, w, 600.0, 45.0, eqs);
  const auto si = mp::strategies(paper, w, 600.0, 45.0, inferred);
  // Alternatives tried for the unexplained one-leg energy.
  const double leg_236 = (600.0 / v600 + v600 / paper.accel) * p_turn + paper.m_eff * v600 * v600 +
                         600.0 * paper.k_drag * v600 * v600;
  const double leg_225 = (600.0 / v600 + v600 / paper.accel) * mp::kMeasuredHover + paper.m_eff * v600 * v600 +
                         600.0 * paper.k_drag * v600 * v600;
  const double leg_149 = paper.eq9Energy(600.0, mp::kVopt600);
  const double R162 = mp::kVopt1200 / w;
  const double L2_162 = 1200.0 + en::roundedExtraLength(R162, M_PI / 4.0);
  const double L2_162_rad = 1200.0 + 2.0 * R162 * (1.0 + std::cos(45.0)) / std::sin(45.0) + R162 * (M_PI + M_PI / 4.0);
  const double drag_printed = s.l2 * 0.5 * paper.rho_cda * s.v2 * s.v2;  // Eq. 16 as printed: no 1/eta
  const double drag_paper_inputs = mp::kL2 * paper.k_drag * mp::kVopt1200 * mp::kVopt1200;
  const double drag_rho_cda = mp::kL2 * paper.rho_cda * mp::kVopt1200 * mp::kVopt1200;
  const double drag_factor = mp::kDrag2 / (mp::kL2 * 0.5 * paper.rho_cda * mp::kVopt1200 * mp::kVopt1200);
  nlohmann::json st = nlohmann::json::array();
  st.push_back(reproRow("Strategy 1: v_opt at 600 m (Eq. 10)", mp::kVopt600, s.v1, "m/s"));
  st.push_back(reproRow(
      "Strategy 1: one 600 m leg (Eq. 9)", mp::kLeg600, s.leg, "J",
      "Eq. 9 gives " + n(s.leg) + " J (" + n(leg_149) + " J at the rounded 14.9 m/s). Not identified: the 236.2 W "
          "hover power that explains the turn gives " + n(leg_236) + " J (" + pct(100.0 * (leg_236 / mp::kLeg600 - 1)) +
          "), the measured 225 W gives " + n(leg_225) + " J (" + pct(100.0 * (leg_225 / mp::kLeg600 - 1)) + ")"));
  st.push_back(reproRow("Strategy 1: turn in place, 135 deg (Eq. 14)", mp::kTurn45, s.turn, "J",
                        "265 J is (pi - beta)/omega_max = " + n((M_PI - M_PI / 4.0) / w) + " s at " + n(p_turn) +
                            " W = " + n(p_turn / mp::kPHover, 4) +
                            " x the paper's P_hov: a hover power 10 % above its own Eq. 5"));
  st.push_back(reproRow("Strategy 1 total (Eq. 12)", mp::kTotal1, s.total1, "J", "the leg and turn differences above"));
  st.push_back(reproRow("Strategy 2: v_opt at L2 ~ 1,200 m (Eq. 10)", mp::kVopt1200, s.v2, "m/s",
                        "see the optimal-velocity table: 16.2 m/s is Eq. 10 at " + n(d_for_162) + " m"));
  st.push_back(reproRow("Strategy 2: radius R = v / omega_max", mp::kRadius, s.radius, "m",
                        "follows v_opt; with the paper's 16.2 m/s, R = " + n(R162) + " m"));
  st.push_back(reproRow(
      "Strategy 2: path length L2 (Eq. 15)", mp::kL2, s.l2, "m",
      "with the paper's R, Eq. 15 gives " + n(L2_162) + " m; its 1,258 m (" + n(L2_162_rad) +
          ") results only when cos and sin are given 45 as radians (a spreadsheet COS(45)): 2R(1 + cos)/sin = " +
          n(2 * R162 * (1 + std::cos(45.0)) / std::sin(45.0)) + " m instead of " +
          n(2 * R162 * (1 + std::cos(M_PI / 4)) / std::sin(M_PI / 4)) + " m"));
  st.push_back(reproRow("Strategy 2: flight time L2 / v", mp::kTime2, s.time2, "s", "\"about 78 s\""));
  st.push_back(reproRow("Strategy 2: hover term (Eq. 16)", mp::kHover2, s.hover2, "J",
                        "18,337 J is 1,258 m / 16.2 m/s = " + n(mp::kL2 / mp::kVopt1200) + " s at " + n(p_round) +
                            " W: the same 1.10 x P_hov as the turn"));
  st.push_back(reproRow(
      "Strategy 2: drag term (Eq. 16)", mp::kDrag2, s.drag2, "J",
      "ours divides by eta as Eq. 9 does (Eq. 16 says it is Eq. 9 without the ramps); Eq. 16 as printed, without "
      "1/eta, gives " + n(drag_printed) + " J. Even with the paper's own L2 and v (" + n(drag_paper_inputs) +
          " J) 6,750 J needs " + n(drag_factor, 3) + " x rho/2 C_D A L2 v^2, i.e. about rho C_D A without the 1/2 of "
          "Eq. 8 (" + n(drag_rho_cda) + " J, " + pct(100.0 * (drag_rho_cda / mp::kDrag2 - 1)) + "); not identified"));
  st.push_back(reproRow("Strategy 2 total (Eq. 16)", mp::kTotal2, s.total2, "J", "the hover and drag terms above"));
  st.push_back(reproRow("Saving of strategy 2", 100.0 * (mp::kTotal1 - mp::kTotal2) / mp::kTotal1, s.saving, "%",
                        "the differences above; Table V below shows the pattern over d and beta"));
  J["strategies_600m_45deg"] = st;
  J["implied_turn_power_w"] = p_turn;
  J["implied_rounded_hover_power_w"] = p_round;
  md += "### Turn strategies at 600 m, beta = 45 deg (Sec. V-B, Eq. 12-16)\n\n" + reproMarkdownTable(st) + "\n";
  md += "Two deviations are certain because the paper's numbers reproduce within 0.1 % with them: the turn and "
        "Strategy 2's hover term both use " + n(p_turn) + " W (" + n(p_round) + " W) instead of P_hov = 214.7 W, and "
        "Eq. 15's cos and sin were evaluated at 45 *radians*. With both and the paper's 16.2 m/s, L2 = " +
        n(L2_162_rad) + " m, the turn costs " + n(si.turn) + " J and the hover term " +
        n(L2_162_rad / mp::kVopt1200 * p_turn) + " J. The one-leg energy and the drag term remain unexplained.\n\n";

  // ------------------------------------------------------------------ Table V
  md += "### Table V: energy reduction of Strategy 2 [%]\n\n";
  nlohmann::json t5 = nlohmann::json::array();
  double worst_eqs = 0.0, worst_inf = 0.0;
  double ours_eqs[3][4], ours_inf[3][4], ours_def[3][4], ours_rest[3][4];
  for (int i = 0; i < 3; ++i) {
    const double d = mp::kTable5Distance[i];
    for (int j = 0; j < 4; ++j) {
      const double b = mp::kTable5Angle[j];
      ours_eqs[i][j] = mp::strategies(paper, w, d, b, eqs).saving;
      ours_inf[i][j] = mp::strategies(paper, w, d, b, inferred).saving;
      en::TurnSettings ts;
      ours_def[i][j] = en::compareTurnStrategies(en::marinsModel(v), d, b * M_PI / 180.0, lim, w, 1e3, ts).saving_pct;
      ts.rounded_from_rest = true;
      ours_rest[i][j] = en::compareTurnStrategies(en::marinsModel(v), d, b * M_PI / 180.0, lim, w, 1e3, ts).saving_pct;
      worst_eqs = std::max(worst_eqs, std::abs(ours_eqs[i][j] - mp::kTable5[i][j]));
      worst_inf = std::max(worst_inf, std::abs(ours_inf[i][j] - mp::kTable5[i][j]));
      const std::string q = "Table V, " + n(d) + " m, beta = " + n(b) + " deg";
      t5.push_back(reproRow(q, mp::kTable5[i][j], ours_eqs[i][j], "%",
                            "paper's procedure as inferred: " + n(ours_inf[i][j], 3) +
                                " %; the paper's equations grow steadily with beta, the paper's numbers do not"));
    }
  }
  J["table5"] = t5;
  J["table5_inferred_procedure"] = ours_inf;
  J["table5_default_model"] = ours_def;
  J["table5_default_model_from_rest"] = ours_rest;
  auto diffCell = [](double ours, double paper_v) {
    char b[48];
    std::snprintf(b, sizeof b, "%.1f (%+.1f)", ours, ours - paper_v);
    return std::string(b);
  };
  auto one = [](double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f", x);
    return std::string(b);
  };
  double rest_lo = 1e9, rest_hi = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      rest_lo = std::min(rest_lo, ours_rest[i][j] / ours_def[i][j]);
      rest_hi = std::max(rest_hi, ours_rest[i][j] / ours_def[i][j]);
    }
  md += table5Markdown("paper", [&](int i, int j) { return one(mp::kTable5[i][j]); }) + "\n";
  md += table5Markdown("ours: paper's equations (diff, points)", [&](int i, int j) {
          return diffCell(ours_eqs[i][j], mp::kTable5[i][j]);
        }) + "\n";
  md += table5Markdown("paper's procedure as inferred (diff, points)", [&](int i, int j) {
          return diffCell(ours_inf[i][j], mp::kTable5[i][j]);
        }) + "\n";
  md += table5Markdown("default model, Eq. 16 (constant speed)", [&](int i, int j) { return one(ours_def[i][j]); }) + "\n";
  md += table5Markdown("default model, rounded path from rest", [&](int i, int j) { return one(ours_rest[i][j]); }) + "\n";
  std::string trig_rad, trig_deg;
  for (int j = 0; j < 4; ++j) {
    const double b = mp::kTable5Angle[j], br = b * M_PI / 180.0;
    trig_rad += (j ? ", " : "") + n((1.0 + std::cos(b)) / std::sin(b), 3);
    trig_deg += (j ? ", " : "") + n((1.0 + std::cos(br)) / std::sin(br), 3);
  }
  md += "The paper's own equations (Eq. 9, 10, 14, 15, 16 with 1/eta on drag) differ from Table V by up to " +
        n(worst_eqs, 2) +
        " points, and in shape: with Eq. 15 in radians the saving grows steadily with beta (a wider corner "
        "makes the loop shorter, cot(beta/2)), while Table V goes 30 > 60 > 90 > 45 deg. That zig-zag is the "
        "signature of cos/sin evaluated at beta read as radians: (1 + cos b)/sin b at b = 30, 45, 60, 90 is " +
        trig_rad + " in radians instead of " + trig_deg + ", which orders the savings 30 > 60 > 90 > 45 deg as in "
        "Table V; "
        "with it and the 236.2 W hover power of the turn and Strategy 2, the "
        "procedure reproduces every cell within " + n(worst_inf, 2) +
        " points, the rest being the unexplained leg and drag numbers. Our default model flies each strategy at "
        "its own optimal speed with the exact drag integral. Eq. 16 flies Strategy 2 at constant speed from start "
        "to end while Strategy 1 starts and ends at rest; charging Strategy 2 the same start and stop (last "
        "table, `wattswath turns --from-rest`) cuts the saving to " + n(100.0 * rest_lo, 2) + "-" +
        n(100.0 * rest_hi, 2) + " % of it, which is the fair comparison for a corner between two legs that both "
        "begin and end at rest.\n\n";

  // ------------------------------------------------------------------ drag integration
  md += "### Drag integration: exact (default) vs Eq. 9\n\n"
        "Eq. 9 charges drag at the cruise speed over the whole leg; the exact integral (our default, "
        "`--drag exact`) charges the ramps their true speed: on a stop-to-stop trapezoid it is lower by "
        "rho/2 C_D A v^4 / (2 a eta).\n\n"
        "| d [m] | v [m/s] (Eq. 10) | E Eq. 9 [J] | E exact [J] | diff | v_opt exact [m/s] |\n|---:|---:|---:|---:|---:|---:|\n";
  nlohmann::json dj = nlohmann::json::array();
  for (double d : {100.0, 300.0, 600.0, 1200.0, 5000.0}) {
    const double vv = paper.eq10OptimalSpeed(d);
    const double ep = paper.legEnergy(d, 0.0, vv, 0.0), ee = exact.legEnergy(d, 0.0, vv, 0.0);
    const double vx = en::optimalCruiseSpeed(def_model, d, 0.0, 0.0, lim, 1e3).speed;
    dj.push_back({{"distance_m", d}, {"speed_mps", vv}, {"paper_j", ep}, {"exact_j", ee}, {"v_opt_exact_mps", vx}});
    md += "| " + n(d) + " | " + n(vv) + " | " + n(ep) + " | " + n(ee) + " | " + pct(100.0 * (ee / ep - 1.0)) + " | " +
          n(vx) + " |\n";
  }
  J["drag_integration"] = dj;
  const auto best600 = en::optimalCruiseSpeed(def_model, 600.0, 0.0, 0.0, lim, 1e3);
  J["exact_vs_paper_600m_pct"] = 100.0 * (exact.legEnergy(600.0, 0.0, v600, 0.0) / paper.legEnergy(600.0, 0.0, v600, 0.0) - 1.0);
  md += "\nThe energies differ by at most a few per cent (" +
        pct(J["exact_vs_paper_600m_pct"].get<double>()) +
        " at 600 m, the ramps' drag). Because the energy is flat near its minimum, the optimal speed moves more (" +
        n(v600) + " -> " + n(best600.speed) + " m/s at 600 m) while the exact energy at the two speeds differs by " +
        pct(100.0 * (best600.energy / exact.legEnergy(600.0, 0.0, v600, 0.0) - 1.0)) + ".\n";
  return out;
}

const bool kRegistered = registerReproSection(10, "marins", &reproduceMarins);

}  // namespace
}  // namespace wattswath::apps
