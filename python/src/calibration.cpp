// Python bindings of the calibration library: the measurement check, prepared logs, replay of a
// model on logged kinematics (samples and residuals as NumPy arrays), error metrics, residual
// tables, the diagnosis of missing effects, fits and simulated logs.
#include "bindings.hpp"
#include "calibration_dicts.hpp"
#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/calibration/measurement_check.hpp"
#include "wattswath/calibration/replay.hpp"

namespace wattswath::python {
namespace {

namespace cal = calibration;

// The log checked as the command line checks it (apps/log_inputs.cpp), then segmented.
cal::PreparedLog prepareChecked(const logs::FlightLog& log, const energy::Vehicle& v, bool trust_power,
                                const py::object& waypoints) {
  logs::FlightLog checked = log;
  const cal::MeasurementCheck c = cal::checkMeasurement(checked, v);
  if (!c.position_problem.empty()) throw std::invalid_argument(log.source + ": " + c.position_problem);
  if (!c.power_problem.empty() && !trust_power)
    throw std::invalid_argument(log.source + ": " + c.power_problem +
                                ". Refused: a model compared with this power says nothing; pass trust_power=True "
                                "to use it anyway");
  std::vector<Eigen::Vector3d> w;
  if (!waypoints.is_none()) w = toPoints3(waypoints.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>(), "waypoints");
  return cal::prepareLog(checked, {}, w);
}

py::dict checkDict(const logs::FlightLog& log, const energy::Vehicle& v) {
  logs::FlightLog copy = log;
  const cal::MeasurementCheck c = cal::checkMeasurement(copy, v);
  return py::dict(py::arg("power_problem") = c.power_problem, py::arg("position_problem") = c.position_problem,
                  py::arg("notes") = c.notes, py::arg("airborne_samples") = c.airborne_samples,
                  py::arg("median_power_w") = c.median_power_w, py::arg("median_current_a") = c.median_current_a,
                  py::arg("hover_power_w") = c.hover_power_w,
                  py::arg("cut_at_s") = c.cut ? py::object(py::float_(c.cut_at_s)) : py::object(py::none()));
}

void bindPrepared(py::module_& m) {
  py::class_<cal::PreparedLog>(m, "PreparedLog", "A log made ready for replay: motion states, phases and legs.")
      .def_readonly("source", &cal::PreparedLog::source, "File the log came from.")
      .def_property_readonly("t", [](const cal::PreparedLog& p) {
            return arrayOf(p.states.size(), [&](std::size_t i) { return p.states[i].t; });
          }, "Sample times [s].")
      .def_property_readonly("measured_w", [](const cal::PreparedLog& p) { return toArray(p.measured); },
                             "Measured electrical power per sample [W].")
      .def_property_readonly("weight_s", [](const cal::PreparedLog& p) { return toArray(p.weight); },
                             "Trapezoid weight of each sample [s] (energy = sum(weight * power)).")
      .def_property_readonly("phase", [](const cal::PreparedLog& p) {
            std::vector<std::string> out;
            for (const auto ph : p.phase) out.emplace_back(energy::toString(ph));
            return out;
          }, "Phase name of each sample ('hover', 'cruise', ...).")
      .def_property_readonly("leg", [](const cal::PreparedLog& p) {
            return arrayOf<int>(p.leg.size(), [&](std::size_t i) { return p.leg[i]; });
          }, "Leg index of each sample.")
      .def_property_readonly("leg_count", [](const cal::PreparedLog& p) { return p.legs.size(); }, "Number of legs.")
      .def("__len__", [](const cal::PreparedLog& p) { return p.states.size(); }, "Number of samples.");
}

void bindReplay(py::module_& m) {
  using R = cal::LogReplay;
  const auto col = [](double cal::ReplaySample::*f) {
    return [f](const R& r) { return arrayOf(r.samples.size(), [&](std::size_t i) { return r.samples[i].*f; }); };
  };
  py::class_<R>(m, "Replay", "A model replayed on one log: per-sample arrays and energies per flight, leg and phase.")
      .def_readonly("source", &R::source, "The log's file.")
      .def_property_readonly("t", col(&cal::ReplaySample::t), "Log time of each sample [s].")
      .def_property_readonly("measured_w", col(&cal::ReplaySample::measured_w), "Measured power [W].")
      .def_property_readonly("modelled_w", col(&cal::ReplaySample::modelled_w), "Modelled power [W].")
      .def_property_readonly("residual_w", [](const R& r) {
            return arrayOf(r.samples.size(), [&](std::size_t i) { return r.samples[i].modelled_w - r.samples[i].measured_w; });
          }, "Modelled minus measured power [W].")
      .def_property_readonly("speed", col(&cal::ReplaySample::speed), "Horizontal ground speed [m/s].")
      .def_property_readonly("climb_rate", col(&cal::ReplaySample::climb_rate), "Vertical speed, up positive [m/s].")
      .def_property_readonly("acceleration", col(&cal::ReplaySample::acceleration), "Along-track acceleration [m/s^2].")
      .def_property_readonly("heading", col(&cal::ReplaySample::heading), "ENU track heading [rad].")
      .def_property_readonly("phase", [](const R& r) {
            std::vector<std::string> out;
            for (const auto& s : r.samples) out.emplace_back(energy::toString(s.phase));
            return out;
          }, "Phase name of each sample.")
      .def_property_readonly("leg", [](const R& r) {
            return arrayOf<int>(r.samples.size(), [&](std::size_t i) { return r.samples[i].leg; });
          }, "Leg index of each sample.")
      .def_property_readonly("flight", [](const R& r) { return compareDict(r.flight); },
                             "Whole log: measured_j, modelled_j, time_s, error_pct.")
      .def_property_readonly("legs", [](const R& r) {
            py::list out;
            for (const auto& l : r.legs) out.append(compareDict(l));
            return out;
          }, "Per leg: measured_j, modelled_j, time_s, error_pct.")
      .def_property_readonly("phases", [](const R& r) {
            py::dict out;
            for (int p = 0; p < energy::kPhaseCount; ++p)
              if (r.phases[p].time_s > 0.0) out[energy::toString(static_cast<energy::Phase>(p))] = compareDict(r.phases[p]);
            return out;
          }, "Per phase with samples: measured_j, modelled_j, time_s, error_pct.")
      .def("__len__", [](const R& r) { return r.samples.size(); }, "Number of samples.");
}

cal::FitSettings fitSettings(int max_samples, double huber_w) {
  cal::FitSettings s;
  s.max_samples = max_samples;
  s.huber_w = huber_w;
  return s;
}

py::dict diagnoseDict(const energy::EnergyModel& model, const energy::Vehicle& v,
                      const std::vector<cal::PreparedLog>& logs, const std::vector<std::string>& candidates) {
  cal::DiagnoseSettings s;
  s.candidates = candidates;
  return diagnosisDict(cal::diagnose(model, v, logs, s));
}

void bindFunctions(py::module_& m) {
  m.def("check_measurement", &checkDict, py::arg("log"), py::arg("vehicle"),
        "Is the log a measurement of a flying multirotor? dict power_problem, position_problem (empty: fine), "
        "notes, airborne_samples, median_power_w, hover_power_w, cut_at_s. The log itself is not changed.");
  m.def("prepare_log", &prepareChecked, py::arg("log"), py::arg("vehicle"), py::arg("trust_power") = false,
        py::arg("waypoints") = py::none(),
        "Checks the log against the vehicle (ValueError for an implausible power, unless trust_power, or a "
        "diverged position estimate), cuts a diverged end, then finds phases and legs (ending at `waypoints`, "
        "N x 3 ENU [m], when given).");
  m.def("replay", &cal::replay, py::arg("model"), py::arg("log"), "Replays the model on a PreparedLog.");
  m.def("error_metrics", [](const std::vector<cal::LogReplay>& r) { return metricsDict(cal::errorMetrics(r)); },
        py::arg("replays"),
        "Errors of replays: samples, rmse_w, energy_error_pct, leg_energy_mape_pct, phases {name: {...}}.");
  m.def("residual_tables", [](const std::vector<cal::LogReplay>& r) { return residualTablesDict(cal::residualTables(r)); },
        py::arg("replays"),
        "Residuals binned by speed, climb_rate, acceleration, heading and time: {quantity: {unit, lo, hi, count, "
        "measured_mean_w, modelled_mean_w, residual_w}} with NumPy arrays.");
  m.def("diagnose", &diagnoseDict, py::arg("model"), py::arg("vehicle"), py::arg("logs"),
        py::arg("candidates") = std::vector<std::string>{},
        "Ranks effects not in the model by held-out error reduction (leave-one-flight-out with several logs, "
        "interleaved time blocks with one): dict validation, physics, baseline, candidates (best first).");
  m.def("fit", [](const energy::EnergyModel& model, const std::vector<cal::PreparedLog>& train,
                  const std::vector<cal::PreparedLog>& test, int max_samples, double huber_w) {
          return fitReportDict(cal::fitAndCompare(model, train, test, fitSettings(max_samples, huber_w)));
        }, py::arg("model"), py::arg("train"), py::arg("test") = std::vector<cal::PreparedLog>{},
        py::arg("max_samples") = 4000, py::arg("huber_w") = 0.0,
        "Fits every coefficient of the model on the training logs (Ceres, bounded) and compares before / after: "
        "dict model (the fitted EnergyModel), coefficients, train_before, train_after, test_before, test_after, "
        "train_replay, test_replay, notes.");
  m.def("simulate_flight", [](const py::array_t<double, py::array::c_style | py::array::forcecast>& waypoints,
                              const energy::EnergyModel& truth, double rate_hz, double cruise_speed,
                              double power_noise_w, unsigned seed) {
          cal::SimulationSettings s;
          s.rate_hz = rate_hz;
          s.cruise_speed = cruise_speed;
          s.power_noise_w = power_noise_w;
          s.seed = seed;
          return cal::simulateFlight(toPoints3(waypoints, "waypoints"), truth, s);
        }, py::arg("waypoints"), py::arg("truth"), py::arg("rate_hz") = 10.0, py::arg("cruise_speed") = 8.0,
        py::arg("power_noise_w") = 5.0, py::arg("seed") = 1u,
        "A simulated canonical log of `truth` flown through the N x 3 ENU waypoints [m]: stop, turn, fly each "
        "leg at cruise_speed [m/s]; power noise [W] with a fixed seed.");
}

}  // namespace

void bindCalibration(py::module_& m) {
  bindPrepared(m);
  bindReplay(m);
  bindFunctions(m);
}

}  // namespace wattswath::python
