#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/mission/files.hpp"

#include <filesystem>
#include <iomanip>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <boost/math/distributions/fisher_f.hpp>
#include <nlohmann/json.hpp>

#include "median.hpp"
#include "minimise.hpp"
#include "waypoint_passage.hpp"
#include "number_text.hpp"
#include "wattswath/calibration/replay.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/energy/candidate_effects.hpp"

namespace wattswath::calibration {
namespace {

using detail::gridThenBrent;
using detail::nelderMead;
using detail::num;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Power [W] of a log sample: the logged power, else voltage x current, else NaN.
double samplePower(const logs::LogSample& s) {
  if (std::isfinite(s.power)) return s.power;
  if (std::isfinite(s.voltage) && std::isfinite(s.current)) return s.voltage * s.current;
  return kNaN;
}

// One parameter a calibration fits: its name, range and the unit it is written in.
struct FreeParameter {
  std::string name;
  double lo, hi;
  const char* unit;
};

std::vector<FreeParameter> freeParameters(mission::AutopilotFamily f) {
  using F = mission::AutopilotFamily;
  switch (f) {
    case F::ArduCopterLeash:
      return {{"WPNAV_ACCEL", 50, 500, "cm/s/s"}, {"WPNAV_SPEED_UP", 50, 500, "cm/s"}, {"WPNAV_SPEED_DN", 30, 400, "cm/s"},
              {"POS_XY_P", 0.3, 3.0, "1/s"}, {"VEL_XY_P", 0.3, 6.0, "1/s"}};
    case F::ArduCopterSCurve:
      return {{"WPNAV_ACCEL", 50, 500, "cm/s/s"}, {"WPNAV_JERK", 0.3, 20, "m/s/s/s"},
              {"WPNAV_SPEED_UP", 50, 500, "cm/s"}, {"WPNAV_SPEED_DN", 30, 400, "cm/s"}};
    case F::PX4:
      return {{"MPC_ACC_HOR", 0.5, 10, "m/s/s"}, {"MPC_JERK_AUTO", 0.5, 40, "m/s/s/s"},
              {"MPC_TKO_SPEED", 0.3, 5, "m/s"}, {"MPC_Z_V_AUTO_DN", 0.5, 4, "m/s"}};
  }
  return {};
}

// The measured side of a flight, computed once, in the log's frame.
struct Prepared {
  const MissionFlight* flight;
  mission::Mission mission;  // the mission with its home where the vehicle took off (see prepare)
  std::vector<mission::NavStep> steps;
  std::vector<Eigen::Vector3d> waypoints;
  Eigen::Vector2d offset;
  Eigen::Vector2d launch = Eigen::Vector2d::Zero();  // [m] take-off point, east/north of the mission's home
  FlightTimes measured;
  std::string match_problem;                            // FlightComparison::match_problem
  std::vector<double> t;                                // [s] the log's times from its first sample
  std::vector<Eigen::Vector3d> track, velocity;         // [m], [m/s] in the mission's frame from the take-off point
};

// Why `f`'s log may not be of its mission: fewer than half of the mission's legs found with both
// ends in the log (a log of another mission matches a few by chance), or the track laid onto the
// waypoints at the alignment's search limit (kAlignSearchM; logs with a geodetic origin are placed
// by it, not searched); empty when neither.
std::string matchProblem(const MissionFlight& f, const Prepared& p) {
  const std::size_t legs = p.measured.leg_s.size();
  const auto matched = static_cast<std::size_t>(
      std::count_if(p.measured.leg_s.begin(), p.measured.leg_s.end(), [](double x) { return std::isfinite(x); }));
  if (legs >= 2 && 2 * matched < legs) {
    return "only " + std::to_string(matched) + " of the mission's " + std::to_string(legs) +
           " legs were found flown in the log (both ends passed within the acceptance distance): is this the log of "
           "this mission? Its times and energies would compare two different flights";
  }
  if (!f.log.has_geodetic_origin && p.offset.cwiseAbs().maxCoeff() >= kAlignSearchM - 0.5) {
    return "the log's track fits the mission's waypoints only at the " + detail::num(kAlignSearchM, 3) +
           " m limit of the alignment search (offset " + detail::num(p.offset.x(), 3) + ", " + detail::num(p.offset.y(), 3) +
           " m): is this the log of this mission, flown where the file says?";
  }
  return "";
}

Prepared prepare(const MissionFlight& f) {
  Prepared p;
  p.flight = &f;
  p.mission = missionFromLaunch(f, &p.offset, &p.launch);
  std::vector<double> power;
  for (const auto& s : f.log.samples) {
    // The log's frame, moved so that its first sample (the take-off point) is the origin.
    p.track.push_back(s.position - Eigen::Vector3d(f.log.samples.front().position.x(), f.log.samples.front().position.y(), 0.0));
    p.velocity.push_back(s.velocity);
    p.t.push_back(s.t - f.log.samples.front().t);
    power.push_back(samplePower(s));
  }
  p.steps = mission::sequenceMission(p.mission);
  p.waypoints = flownWaypoints(p.steps);
  p.measured = flightTimes(p.t, p.track, power, p.waypoints);
  if (!(p.measured.energy_j > 0.0)) {
    throw std::invalid_argument(f.name + ": the log has no usable power (voltage x current): it cannot be compared");
  }
  p.match_problem = matchProblem(f, p);
  return p;
}

// The predicted side: times (and energy when `model` is given) of the predicted trajectory.
FlightTimes predictedTimes(const mission::FlownMission& flown, const std::vector<double>& piece_energy,
                           const std::vector<Eigen::Vector3d>& waypoints) {
  std::vector<double> t, power;
  std::vector<Eigen::Vector3d> pos;
  for (std::size_t i = 0; i < flown.samples.size(); ++i) {
    t.push_back(flown.samples[i].t);
    pos.push_back(flown.samples[i].position);
    const double dt = i > 0 ? flown.samples[i].t - flown.samples[i - 1].t : 0.0;
    power.push_back(i > 0 && i - 1 < piece_energy.size() && dt > 0.0 ? piece_energy[i - 1] / dt : (i == 0 ? 0.0 : kNaN));
  }
  return flightTimes(t, pos, power, waypoints);
}

double relErr(double pred, double meas) { return meas != 0.0 ? (pred - meas) / meas : 0.0; }

FlightComparison compare(const Prepared& p, const FlightTimes& pred) {
  FlightComparison c;
  c.name = p.flight->name;
  c.measured = p.measured;
  c.predicted = pred;
  c.offset = p.offset;
  c.launch = p.launch;
  c.time_error_pct = 100.0 * relErr(pred.total_s, p.measured.total_s);
  c.energy_error_pct = 100.0 * relErr(pred.energy_j, p.measured.energy_j);
  double sum = 0.0;
  for (std::size_t k = 0; k < std::min(pred.leg_s.size(), p.measured.leg_s.size()); ++k) {
    if (std::isfinite(pred.leg_s[k]) && std::isfinite(p.measured.leg_s[k]) && p.measured.leg_s[k] > 0.0) {
      sum += std::abs(relErr(pred.leg_s[k], p.measured.leg_s[k]));
      ++c.legs_matched;
    }
  }
  c.leg_time_mape_pct = c.legs_matched > 0 ? 100.0 * sum / c.legs_matched : kNaN;
  std::vector<double> ratios;
  for (std::size_t k = 0; k < std::min(pred.leg_peak_mps.size(), p.measured.leg_peak_mps.size()); ++k)
    if (std::isfinite(p.measured.leg_peak_mps[k]) && std::isfinite(pred.leg_peak_mps[k]) && pred.leg_peak_mps[k] >= 1.0)
      ratios.push_back(p.measured.leg_peak_mps[k] / pred.leg_peak_mps[k]);
  c.leg_peak_ratio = detail::median(ratios);  // NaN without a leg
  c.match_problem = p.match_problem;
  return c;
}

// Squared relative time errors of a prediction: total, take-off, return and the legs (as a group).
double timeCost(const FlightTimes& m, const FlightTimes& p) {
  auto sq = [](double x) { return std::isfinite(x) ? x * x : 1.0; };
  double legs = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < std::min(m.leg_s.size(), p.leg_s.size()); ++k) {
    if (std::isfinite(m.leg_s[k]) && m.leg_s[k] > 0.0) {
      legs += std::isfinite(p.leg_s[k]) ? sq(relErr(p.leg_s[k], m.leg_s[k])) : 1.0;
      ++n;
    }
  }
  return sq(relErr(p.total_s, m.total_s)) + sq(relErr(p.takeoff_s, m.takeoff_s)) + sq(relErr(p.return_s, m.return_s)) +
         (n > 0 ? legs / n : 0.0);
}

// The number of terms of timeCost: the finite total, take-off and return times and the matched legs.
int timeTerms(const FlightTimes& m) {
  int n = 0;
  for (double x : {m.total_s, m.takeoff_s, m.return_s}) n += std::isfinite(x) ? 1 : 0;
  for (double x : m.leg_s) n += std::isfinite(x) && x > 0.0 ? 1 : 0;
  return n;
}

}  // namespace

FlightComparison compareFlight(const MissionFlight& f, const energy::Vehicle& v, const energy::EnergyModel& model,
                               const mission::AutopilotConfig& autopilot, const mission::PredictSettings& settings) {
  const Prepared p = prepare(f);
  const mission::MissionPrediction pred = mission::predictMission(p.mission, v, model, autopilot, settings);
  return compare(p, predictedTimes(pred.flight, pred.piece_energy_j, p.waypoints));
}

namespace {

// Each flight's own value of the acceleration parameter `acc` (the others as in `x`), into
// `r.per_flight`, and whether the flights agree: a flight determines its value when its misfit at the
// joint value exceeds its own minimum by more than `share` of it (else it fits the joint value as
// well); the flights agree unless two that determine their values want values more than 25 %
// apart. Says so in `r.fitted` and `r.notes`.
template <class Cost>
void checkAgreement(const std::vector<Prepared>& prepared, const FreeParameter& acc, const std::vector<double>& x,
                    Cost flightCost, double share, CalibrationResult& r) {
  r.acceleration_parameter = acc.name;
  double lo = 1e300, hi = -1e300;
  int determined = 0;
  std::ostringstream each, wanted;
  for (const auto& p : prepared) {
    std::vector<double> xf = x;
    xf[0] = gridThenBrent([&](double u) { xf[0] = u; return flightCost(xf, p); }, 45, 15);
    FlightAcceleration fa;
    fa.flight = std::filesystem::path(p.flight->name).filename().string();
    fa.value = acc.lo + xf[0] * (acc.hi - acc.lo);
    fa.misfit_alone = flightCost(xf, p);
    fa.misfit_joint = flightCost(x, p);
    fa.determined = fa.misfit_joint > (1.0 + share) * fa.misfit_alone;
    if (fa.determined) {
      lo = std::min(lo, fa.value), hi = std::max(hi, fa.value);
      wanted << (determined ? ", " : "") << fa.flight << " " << num(fa.value);
      ++determined;
    }
    each << (r.per_flight.empty() ? "" : ", ") << fa.flight << " " << num(fa.value)
         << (fa.determined ? "" : " (not determined by it: it fits the joint value within " + num(100.0 * share) + " %)");
    r.per_flight.push_back(fa);
  }
  const double joint = acc.lo + x[0] * (acc.hi - acc.lo);
  const bool kept = std::find(r.kept_at_start.begin(), r.kept_at_start.end(), acc.name) != r.kept_at_start.end();
  const std::string together = kept ? "together: kept at its starting value " + num(joint) + ", which the flights together fit as well"
                                    : "together " + num(joint);
  r.fitted.push_back(acc.name + " of each flight alone: " + each.str() + " " + acc.unit + " (" + together + ")");
  r.flights_agree = determined < 2 || hi <= 1.25 * lo;
  if (!r.flights_agree) {
    r.notes.push_back("the flights do not agree on " + acc.name + ": each alone wants " + wanted.str() + " " + acc.unit +
                      " (" + together + "). One set of parameters does not describe them all: the model lacks a "
                      "behaviour they differ in, or the setting changed between flights; the logs cannot tell which, and "
                      "a prediction of another flight may be off by this spread");
  }
}

// The flights' tracking error, pooled over their cruise samples (measured, not fitted), into `r`.
void measureTracking(const std::vector<Prepared>& prepared, CalibrationResult& r) {
  std::vector<double> h, v;
  std::ostringstream each;
  for (const auto& p : prepared) {
    const auto& passage = p.measured.passage_s;
    double from = kNaN, to = kNaN;
    for (double x : passage)
      if (std::isfinite(x)) to = x, from = std::isfinite(from) ? from : x;
    std::vector<double> hf, vf;
    if (std::isfinite(from)) addCruiseTrackingErrors(p.t, p.track, p.velocity, p.waypoints, from, to, hf, vf);
    const TrackingMeasurement m = trackingFromErrors(hf, vf);
    each << (each.tellp() > 0 ? ", " : "") << std::filesystem::path(p.flight->name).filename().string() << " "
         << (m.measured ? num(m.error.horizontal_m) + " / " + num(m.error.vertical_m) + " m" : "too few samples");
    h.insert(h.end(), hf.begin(), hf.end());
    v.insert(v.end(), vf.begin(), vf.end());
  }
  r.tracking = trackingFromErrors(h, v);
  if (r.tracking.measured) {
    r.fitted.push_back("tracking error (measured, not fitted): " + num(r.tracking.error.horizontal_m) + " m horizontal, " +
                       num(r.tracking.error.vertical_m) + " m vertical, the median of " + std::to_string(r.tracking.samples) +
                       " cruise samples (each flight: " + each.str() + ")");
  } else {
    r.notes.push_back("the logs have " + std::to_string(r.tracking.samples) + " cruise samples (at least " +
                      std::to_string(TrackingMeasurement::kMinSamples) + " needed): how far the vehicle sits off its line "
                      "is not measured and taken as 0");
  }
}

// The behaviour fit's problem: the flights' time misfit as a function of the free parameters and
// the take-off delay, normalised to [0, 1] (the delay last), and of the behaviour variant (bit 0: a
// stop at every waypoint; bit 1: DO_CHANGE_SPEED one waypoint late).
struct BehaviourProblem {
  static constexpr double kMaxDelay = 10.0;  // [s] the take-off delay at x = 1
  const std::vector<Prepared>& prepared;
  const mission::AutopilotConfig& autopilot;
  const std::vector<FreeParameter>& free;
  mission::Airframe airframe;  // once, not per evaluation
  double sim_dt;               // [s]
  mission::TrackingError tracking;

  // Sets the parameters `x` stands for in `ap` and the take-off delay [s].
  void apply(const std::vector<double>& x, mission::AutopilotConfig& ap, double& delay) const {
    for (std::size_t i = 0; i < free.size(); ++i) ap.parameters[free[i].name] = free[i].lo + x[i] * (free[i].hi - free[i].lo);
    delay = x.back() * kMaxDelay;
  }
  // The time misfit of one flight flown with the parameters `x` and the behaviour `variant`.
  double flightCost(const std::vector<double>& x, int variant, const Prepared& p) const {
    mission::AutopilotConfig ap = autopilot;
    mission::FlightSettings fs;
    fs.dt = sim_dt;
    fs.airframe = airframe;
    fs.stop_at_waypoints = variant & 1;
    fs.speed_change_late = variant & 2;
    fs.tracking_error = tracking;
    apply(x, ap, fs.takeoff_delay_s);
    try {
      return timeCost(p.measured, predictedTimes(mission::flyMission(p.steps, ap, fs), {}, p.waypoints));
    } catch (const std::exception&) {
      return 100.0;
    }
  }
  // The time misfit of all flights.
  double cost(const std::vector<double>& x, int variant) const {
    double c = 0.0;
    for (const auto& p : prepared) c += flightCost(x, variant, p);
    return c;
  }
  // The starting point: the autopilot's own values, and a short take-off delay.
  std::vector<double> start() const {
    std::vector<double> x0;
    for (const auto& fp : free) x0.push_back(std::clamp((autopilot.get(fp.name) - fp.lo) / (fp.hi - fp.lo), 0.0, 1.0));
    x0.push_back(0.05);
    return x0;
  }
};

// Fits the behaviour: for each corner and speed-change variant (the autopilot's own rules, a stop at
// every waypoint, speed changes a waypoint late, or both) the parameters by Nelder-Mead; the variant
// with the least time misfit wins. Returns the parameters; sets the variant and its text in `r`.
std::vector<double> fitBehaviour(const BehaviourProblem& bp, int max_evaluations, double share, CalibrationResult& r,
                                 int& chosen) {
  const char* kVariants[4] = {"the autopilot's own rules", "a stop at every waypoint",
                              "DO_CHANGE_SPEED one waypoint late", "a stop at every waypoint and DO_CHANGE_SPEED one waypoint late"};
  const std::vector<double> x0 = bp.start();
  std::vector<std::vector<double>> xs;
  std::vector<double> cost;
  chosen = 0;
  std::ostringstream misfits;
  for (int variant = 0; variant < 4; ++variant) {
    xs.push_back(nelderMead([&](const std::vector<double>& p) { return bp.cost(p, variant); }, x0, max_evaluations));
    cost.push_back(bp.cost(xs.back(), variant));
    misfits << (variant ? "; " : "") << kVariants[variant] << " " << num(cost.back(), 4);
    if (cost.back() < cost[static_cast<std::size_t>(chosen)]) chosen = variant;
  }
  // Variants that fit within `share` of the best cannot be told apart by these flights (all four
  // tie when no waypoint is flown through and no speed changes): the autopilot's own rules stay when
  // they are among them, as a behaviour parameter the flights do not call to change stays.
  const double best = cost[static_cast<std::size_t>(chosen)];
  std::string tied;
  for (int variant = 0; variant < 4; ++variant)
    if (variant != chosen && cost[static_cast<std::size_t>(variant)] <= (1.0 + share) * best)
      tied += (tied.empty() ? "" : ", ") + std::string(kVariants[variant]);
  if (!tied.empty()) {
    if (cost[0] <= (1.0 + share) * best) chosen = 0;
    r.notes.push_back("these flights cannot tell the behaviours apart: " + std::string(kVariants[chosen]) + " and " + tied +
                      " fit their times within " + num(100.0 * share) + " % of each other; " + kVariants[chosen] + " kept");
  }
  r.stop_at_waypoints = chosen & 1;
  r.speed_change_late = chosen & 2;
  r.fitted.push_back(std::string("behaviour: ") + kVariants[chosen] + " (time misfit: " + misfits.str() + ")");
  return xs[static_cast<std::size_t>(chosen)];
}

// The behaviour parameters the flights do not call to change, returned to their starting values one
// at a time: each still fitted parameter is set back with the others re-fitted (Nelder-Mead), and the
// one that raises the time misfit least goes back when that rise is not significant: at most `share`
// of the misfit, or an F statistic rise / (misfit / (n - k)) below the F(1, n - k) quantile at
// 1 - `alpha` (n: the misfit's terms, k: the parameters still fitted and the take-off delay); again
// until none goes back. A parameter the flights do not determine, or whose start they fit as well,
// stays where it was; with n <= k every parameter does. Returns the parameters; lists those set back
// in `r.kept_at_start` and `r.notes`.
std::vector<double> keepUnneededChanges(const BehaviourProblem& bp, std::vector<double> x, int variant, int max_evaluations,
                                        double share, double alpha, CalibrationResult& r) {
  const std::vector<double> x0 = bp.start();
  std::vector<bool> fixed(bp.free.size(), false);
  int n = 0;
  for (const auto& p : bp.prepared) n += timeTerms(p.measured);
  double cost = bp.cost(x, variant);
  for (;;) {
    const int k = 1 + static_cast<int>(std::count(fixed.begin(), fixed.end(), false));  // the open parameters and the delay
    double best_rise = 1e300;
    std::size_t best_i = bp.free.size();
    std::vector<double> best_x;
    for (std::size_t i = 0; i < bp.free.size(); ++i) {
      if (fixed[i]) continue;
      std::vector<std::size_t> open;  // the coordinates still fitted, the take-off delay last
      for (std::size_t j = 0; j < x.size(); ++j)
        if (j == x.size() - 1 || (j != i && !fixed[j])) open.push_back(j);
      std::vector<double> xi = x;
      xi[i] = x0[i];
      auto full = [&](const std::vector<double>& y) {
        std::vector<double> z = xi;
        for (std::size_t q = 0; q < open.size(); ++q) z[open[q]] = y[q];
        return z;
      };
      std::vector<double> y0;
      for (std::size_t j : open) y0.push_back(xi[j]);
      const std::vector<double> xr = full(
          nelderMead([&](const std::vector<double>& v) { return bp.cost(full(v), variant); }, y0, max_evaluations));
      const double rise = bp.cost(xr, variant) - cost;
      if (rise < best_rise) best_rise = rise, best_i = i, best_x = xr;
    }
    if (best_i == bp.free.size()) return x;
    const int dof = n - k;
    std::string why;
    const double pct = 100.0 * std::max(best_rise, 0.0) / std::max(cost, 1e-12);
    if (best_rise <= share * cost) {  // <=: a perfect fit keeps what it need not change
      why = "the time misfit rises by " + num(pct) + " % (at most " + num(100.0 * share) + " %)";
    } else if (alpha > 0.0 && dof <= 0) {
      why = "the flights give " + std::to_string(n) + " time(s) for " + std::to_string(k) +
            " fitted values (with the take-off delay): too few to call for any change";
    } else if (alpha > 0.0) {
      const double f = best_rise / (cost / dof);
      const double crit = boost::math::quantile(boost::math::fisher_f(1.0, dof), 1.0 - alpha);
      if (!(f <= crit)) return x;
      why = "the time misfit rises by " + num(pct) + " %, not significantly (F = " + num(f) + ", below the " +
            num(100.0 * (1.0 - alpha)) + " % point " + num(crit) + " of F(1, " + std::to_string(dof) + "))";
    } else {
      return x;
    }
    fixed[best_i] = true;
    x = best_x;
    cost += std::max(best_rise, 0.0);
    const FreeParameter& fp = bp.free[best_i];
    r.kept_at_start.push_back(fp.name);
    r.notes.push_back(fp.name + " kept at its starting value " + num(fp.lo + x0[best_i] * (fp.hi - fp.lo)) + " " + fp.unit +
                      ": set back there with the others re-fitted, " + why +
                      ", so these flights do not call for a change (they fit as well, or do not determine it)");
  }
}

// Each free parameter before -> after in `r.fitted`; one that ended at the bound of its range is
// said not to be determined by the flights.
void reportBehaviour(const std::vector<FreeParameter>& free, const mission::AutopilotConfig& before, CalibrationResult& r) {
  for (const auto& fp : free) {
    std::string line = fp.name + ": " + num(before.get(fp.name), 4) + " -> " + num(r.autopilot.get(fp.name), 4) + " " + fp.unit;
    const double at = (r.autopilot.get(fp.name) - fp.lo) / (fp.hi - fp.lo);
    if (std::find(r.kept_at_start.begin(), r.kept_at_start.end(), fp.name) != r.kept_at_start.end()) {
      line += " (kept: the flights fit as well with it)";
    } else if (at < 0.01 || at > 0.99) {
      line += " (at the bound of its range: not determined by these flights)";
      r.notes.push_back(fp.name + " ended at the bound of its range [" + num(fp.lo, 4) + ", " + num(fp.hi, 4) + "] " + fp.unit +
                        ": the flights do not determine it");
    }
    r.fitted.push_back(line);
  }
  // The delay is searched in [0, BehaviourProblem::kMaxDelay]; at either end it is not a measurement.
  const double d = r.takeoff_delay_s, max_delay = BehaviourProblem::kMaxDelay;
  std::string line = "take-off delay: " + num(d, 3) + " s from the first sample compared (the take-off command, or lift-off "
                     "when the log does not show it) to lift-off";
  if (d < 0.01 * max_delay || d > 0.99 * max_delay) {
    line += " (at the bound of its range: not determined by these flights)";
    r.notes.push_back("the take-off delay ended at the bound of its range [0, " + num(max_delay, 3) + "] s (" + num(d, 3) +
                      " s): the flights do not determine it");
  }
  r.fitted.push_back(line);
}

// The energy model's coefficients fitted to the logged power on the logged kinematics, into `r`.
void fitEnergy(const std::vector<MissionFlight>& flights, const energy::EnergyModel& model, const FitSettings& settings,
               CalibrationResult& r) {
  std::vector<PreparedLog> logs;
  for (const auto& f : flights) logs.push_back(prepareLog(f.log));
  std::vector<SampleSet> sets;
  for (const auto& l : logs) sets.push_back({&l, {}});
  const FitResult fit = fitModel(model, sets, settings);
  r.model = fit.model;
  for (const auto& c : fit.coefficients) {
    std::string line = c.effect + "." + c.name + ": " + num(c.value, 4) + " " + c.unit;
    if (!c.determined) {  // fitModel marks one at its bound not determined
      line += " (not determined: " + (c.why_not_determined.empty() ? std::string("kept") : c.why_not_determined) + ")";
    } else if (std::isfinite(c.sigma)) {
      line += " +- " + num(c.sigma, 2);
    }
    r.fitted.push_back(line);
    if (c.at_bound) {
      r.notes.push_back(c.effect + "." + c.name + " stopped at its bound (" + num(c.value) + " " + c.unit +
                        "): these logs fit best beyond what the effect allows, so its value is not a measurement of the "
                        "vehicle; the vehicle file stores the bound (refit with more varied flights, or leave the effect "
                        "out with --effects)");
    }
  }
  // The fit's own findings: what the data do not determine and why, correlated pairs.
  for (const auto& n : fit.notes) {
    // Said above, with what it means.
    if (n.find("stopped at a bound") != std::string::npos || n.find("stopped at its physical bound") != std::string::npos) continue;
    if (std::find(r.notes.begin(), r.notes.end(), n) == r.notes.end()) r.notes.push_back(n);
  }
}

// Each flight predicted from its mission with `ap`, `model` and `settings`, compared with its log.
std::vector<FlightComparison> predictAll(const std::vector<Prepared>& prepared, const energy::Vehicle& v,
                                         const energy::EnergyModel& model, const mission::AutopilotConfig& ap,
                                         const mission::PredictSettings& settings) {
  std::vector<FlightComparison> out;
  for (const auto& p : prepared) {
    try {
      const auto pred = mission::predictMission(p.mission, v, model, ap, settings);
      out.push_back(compare(p, predictedTimes(pred.flight, pred.piece_energy_j, p.waypoints)));
    } catch (const mission::MissionError&) {
      throw;  // names its item
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(p.flight->name + ": its mission flown with " + ap.firmware + " " + ap.version + ": " + e.what());
    }
  }
  return out;
}

// The prediction settings a calibration found: take-off delay, corner and speed-change behaviour,
// tracking error.
mission::PredictSettings afterSettings(const CalibrationResult& r) {
  mission::PredictSettings after;
  after.flight.takeoff_delay_s = r.takeoff_delay_s;
  after.flight.stop_at_waypoints = r.stop_at_waypoints;
  after.flight.speed_change_late = r.speed_change_late;
  after.flight.tracking_error = r.tracking.error;
  return after;
}

}  // namespace

CalibrationResult calibrateMissions(const std::vector<MissionFlight>& flights, const energy::Vehicle& v,
                                    const energy::EnergyModel& model, const mission::AutopilotConfig& autopilot,
                                    const CalibrationSettings& s) {
  if (flights.empty()) throw std::invalid_argument("calibration needs at least one logged flight of a known mission");
  if (!(s.sim_dt >= 0.005 && s.sim_dt <= 0.05)) throw std::invalid_argument("CalibrationSettings.sim_dt out of 0.005..0.05");
  if (!(s.keep_share >= 0.0 && s.keep_share <= 1.0)) {
    throw std::invalid_argument("CalibrationSettings.keep_share = " + std::to_string(s.keep_share) + ", expected 0..1");
  }
  if (!(s.keep_significance >= 0.0 && s.keep_significance <= 0.5)) {
    throw std::invalid_argument("CalibrationSettings.keep_significance = " + std::to_string(s.keep_significance) +
                                ", expected 0..0.5");
  }
  std::vector<Prepared> prepared;
  for (const auto& f : flights) {
    prepared.push_back(prepare(f));
    if (!prepared.back().match_problem.empty()) {
      throw std::invalid_argument(f.name + ": " + prepared.back().match_problem + "; refusing to calibrate on it");
    }
  }
  CalibrationResult r;
  r.autopilot = autopilot;
  r.model = model;
  r.before = predictAll(prepared, v, model, autopilot, {});
  measureTracking(prepared, r);
  for (const auto& p : prepared) r.coverage = combine(r.coverage, missionKind(p.steps, autopilot));
  const std::vector<FreeParameter> free = freeParameters(autopilot.family);
  for (const auto& fp : free) r.behaviour_before[fp.name] = autopilot.get(fp.name);
  const BehaviourProblem bp{prepared, autopilot, free, mission::airframeOfVehicle(v, v.name), s.sim_dt, r.tracking.error};
  int chosen = 0;
  std::vector<double> x = fitBehaviour(bp, s.max_evaluations, s.keep_share, r, chosen);
  if (s.keep_share > 0.0 || s.keep_significance > 0.0)
    x = keepUnneededChanges(bp, x, chosen, s.max_evaluations, s.keep_share, s.keep_significance, r);
  bp.apply(x, r.autopilot, r.takeoff_delay_s);
  reportBehaviour(free, autopilot, r);
  if (prepared.size() >= 2 && !free.empty()) {
    // The other behaviour parameters and the take-off delay held at the joint fit (re-fitted per
    // flight they would absorb the flights' differences; at their starting values, two copies of one
    // flight each gave 90.6 cm/s/s where the joint fit, WPNAV_SPEED_DN moved, gave 83.8).
    const std::vector<double>& base = x;
    checkAgreement(prepared, free.front(), base, [&](const std::vector<double>& xf, const Prepared& p) {
      return bp.flightCost(xf, chosen, p);
    }, s.keep_share, r);
    for (std::size_t i = 0; i < r.per_flight.size() && i < prepared.size(); ++i)
      r.per_flight[i].kind = missionKind(prepared[i].steps, autopilot);
  }
  if (s.fit_energy) fitEnergy(flights, model, s.fit, r);
  r.after = predictAll(prepared, v, r.model, r.autopilot, afterSettings(r));
  return r;
}

}  // namespace wattswath::calibration
