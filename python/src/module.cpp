// The Python module `wattswath`: the libraries' public API for scripts and notebooks. Each
// library's part is bound in its own file (energy.cpp, geometry.cpp, logs.cpp, calibration.cpp,
// mission.cpp, mission_calibration.cpp, planner.cpp); the library exceptions reach Python as ValueError
// (std::invalid_argument), IndexError (std::out_of_range) and RuntimeError (the readers' errors,
// which name the file, line and field).
#include "bindings.hpp"

namespace wattswath::python {

py::array_t<double> toArray(const std::vector<double>& v) {
  return arrayOf(v.size(), [&](std::size_t i) { return v[i]; });
}

std::vector<Eigen::Vector3d> toPoints3(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
                                       const std::string& what) {
  if (a.ndim() != 2 || a.shape(1) != 3) {
    std::string shape;
    for (py::ssize_t d = 0; d < a.ndim(); ++d) shape += (d ? " x " : "") + std::to_string(a.shape(d));
    throw std::invalid_argument(what + ": expected an N x 3 array of x, y, z [m], got shape (" + shape + ")");
  }
  const auto r = a.unchecked<2>();
  std::vector<Eigen::Vector3d> out;
  out.reserve(static_cast<std::size_t>(a.shape(0)));
  for (py::ssize_t i = 0; i < a.shape(0); ++i) out.emplace_back(r(i, 0), r(i, 1), r(i, 2));
  return out;
}

py::dict breakdownDict(const energy::Breakdown& b) {
  py::dict by_effect, by_phase;
  for (const auto& name : b.effects) by_effect[py::str(name)] = b.byEffect(name);
  for (int p = 0; p < energy::kPhaseCount; ++p) {
    const auto phase = static_cast<energy::Phase>(p);
    if (b.byPhase(phase) != 0.0) by_phase[energy::toString(phase)] = b.byPhase(phase);
  }
  py::dict d;
  d["energy_j"] = b.total();
  d["time_s"] = b.time;
  d["length_m"] = b.length;
  d["by_effect"] = by_effect;
  d["by_phase"] = by_phase;
  return d;
}

}  // namespace wattswath::python

PYBIND11_MODULE(wattswath, m) {
  namespace wp = wattswath::python;
  m.doc() =
      "wattswath: minimum-energy coverage planning for multirotor drones, a physical energy model "
      "and its check against flight logs. SI units throughout (m, s, J, W, rad); arrays are NumPy.";
  m.attr("__version__") = "0.1.0";
  wp::bindEnergy(m);
  wp::bindGeometry(m);
  wp::bindLogs(m);
  wp::bindCalibration(m);
  wp::bindMission(m);
  wp::bindMissionCalibration(m);
  wp::bindPlanner(m);
}
