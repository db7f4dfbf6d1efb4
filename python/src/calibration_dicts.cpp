// The calibration library's results converted to Python dicts (calibration_dicts.hpp).
#include "calibration_dicts.hpp"

namespace wattswath::python {

namespace cal = calibration;

py::dict compareDict(const cal::EnergyCompare& c) {
  return py::dict(py::arg("measured_j") = c.measured_j, py::arg("modelled_j") = c.modelled_j,
                  py::arg("time_s") = c.time_s, py::arg("error_pct") = c.errorPct());
}

py::dict metricsDict(const cal::ErrorMetrics& e) {
  py::dict phases;
  for (int p = 0; p < energy::kPhaseCount; ++p) {
    const cal::PhaseError& pe = e.phases[p];
    if (pe.samples == 0) continue;
    phases[energy::toString(static_cast<energy::Phase>(p))] =
        py::dict(py::arg("samples") = pe.samples, py::arg("rmse_w") = pe.rmse_w,
                 py::arg("measured_mean_w") = pe.measured_mean_w, py::arg("modelled_mean_w") = pe.modelled_mean_w,
                 py::arg("energy_error_pct") = pe.energy_error_pct);
  }
  return py::dict(py::arg("samples") = e.samples, py::arg("rmse_w") = e.rmse_w,
                  py::arg("energy_error_pct") = e.energy_error_pct,
                  py::arg("leg_energy_mape_pct") = e.leg_energy_mape_pct, py::arg("phases") = phases);
}

py::dict residualTablesDict(const std::vector<cal::ResidualTable>& tables) {
  py::dict out;
  for (const auto& t : tables) {
    const auto& b = t.bins;
    py::dict d;
    d["unit"] = t.unit;
    d["lo"] = arrayOf(b.size(), [&](std::size_t i) { return b[i].lo; });
    d["hi"] = arrayOf(b.size(), [&](std::size_t i) { return b[i].hi; });
    d["count"] = arrayOf<int>(b.size(), [&](std::size_t i) { return b[i].count; });
    d["measured_mean_w"] = arrayOf(b.size(), [&](std::size_t i) { return b[i].measured_mean_w; });
    d["modelled_mean_w"] = arrayOf(b.size(), [&](std::size_t i) { return b[i].modelled_mean_w; });
    d["residual_w"] = arrayOf(b.size(), [&](std::size_t i) { return b[i].residualW(); });
    out[py::str(t.quantity)] = d;
  }
  return out;
}

py::list fittedList(const std::vector<cal::FittedCoefficient>& c) {
  py::list out;
  for (const auto& f : c)
    out.append(py::dict(py::arg("effect") = f.effect, py::arg("name") = f.name, py::arg("unit") = f.unit,
                        py::arg("meaning") = f.meaning, py::arg("value") = f.value, py::arg("sigma") = f.sigma,
                        py::arg("at_bound") = f.at_bound, py::arg("determined") = f.determined,
                        py::arg("fitted") = f.fitted, py::arg("why_not_determined") = f.why_not_determined));
  return out;
}

py::dict diagnosisDict(const cal::Diagnosis& d) {
  py::list candidates;
  for (const auto& c : d.candidates)
    candidates.append(py::dict(py::arg("effect") = c.effect, py::arg("rmse_w") = c.rmse_w,
                               py::arg("improvement_pct") = c.improvement_pct,
                               py::arg("energy_error_pct") = c.energy_error_pct,
                               py::arg("leg_energy_mape_pct") = c.leg_energy_mape_pct,
                               py::arg("coefficients") = fittedList(c.coefficients), py::arg("summary") = c.summary,
                               py::arg("indistinct_from") = c.indistinct_from, py::arg("notes") = c.notes));
  py::list staircase;
  for (const auto& s : d.staircase) staircase.append(py::make_tuple(s.label, metricsDict(s.metrics)));
  py::dict out;
  out["validation"] = d.validation;
  out["physics"] = metricsDict(d.physics);
  out["baseline"] = metricsDict(d.baseline);
  out["candidates"] = candidates;
  out["staircase"] = staircase;
  out["physics_replay"] = d.physics_replay;
  out["residuals"] = residualTablesDict(d.residuals);
  return out;
}

py::dict fitReportDict(const cal::FitReport& r) {
  py::dict out;
  out["model"] = r.fit.model;
  out["coefficients"] = fittedList(r.fit.coefficients);
  out["samples"] = r.fit.samples;
  out["notes"] = r.fit.notes;
  out["train_before"] = metricsDict(r.train_before);
  out["train_after"] = metricsDict(r.train_after);
  out["test_before"] = metricsDict(r.test_before);
  out["test_after"] = metricsDict(r.test_after);
  out["train_replay"] = r.train_replay;
  out["test_replay"] = r.test_replay;
  return out;
}

}  // namespace wattswath::python
