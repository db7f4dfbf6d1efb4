#pragma once
/// @file bindings.hpp
/// The pybind11 module `wattswath`: one bind function per library (each in its own source file),
/// and the conversions from the libraries' value types to NumPy arrays and Python dicts.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "wattswath/energy/model.hpp"

namespace wattswath::python {

namespace py = pybind11;

/// Adds vehicles, effects, energy models, legs, optimal speeds and turns (energy library).
void bindEnergy(py::module_& m);
/// Adds survey areas and their reader (geometry library).
void bindGeometry(py::module_& m);
/// Adds flight logs and their readers (logs library).
void bindLogs(py::module_& m);
/// Adds measurement checks, replay, residuals, diagnosis, fits and simulated logs (calibration library).
void bindCalibration(py::module_& m);
/// Adds mission files and mission prediction (mission library).
void bindMission(py::module_& m);
/// Adds mission calibration: flight behaviour and energy fitted to logged flights of known missions.
void bindMissionCalibration(py::module_& m);
/// Adds the coverage planner (planner library).
void bindPlanner(py::module_& m);

/// A 1-D NumPy array copied from `v`.
py::array_t<double> toArray(const std::vector<double>& v);
/// A 1-D NumPy array of `n` values `f(i)` of type T (double: [unit of f]; int for indices).
template <class T = double, class F>
py::array_t<T> arrayOf(std::size_t n, const F& f) {
  py::array_t<T> a(static_cast<py::ssize_t>(n));
  auto w = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < n; ++i) w(static_cast<py::ssize_t>(i)) = f(i);
  return a;
}
/// An N x `Cols` NumPy array whose row i is `f(i)` (an Eigen vector of size Cols).
template <int Cols, class F>
py::array_t<double> rowsOf(std::size_t n, const F& f) {
  py::array_t<double> a({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(Cols)});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Matrix<double, Cols, 1> r = f(i);
    for (int c = 0; c < Cols; ++c) w(static_cast<py::ssize_t>(i), c) = r[c];
  }
  return a;
}
/// The rows of an N x 3 array-like as points [m]; throws ValueError naming `what` on another shape.
std::vector<Eigen::Vector3d> toPoints3(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
                                       const std::string& what);
/// {effect: {phase: J}} and totals of a breakdown as a dict: energy_j, time_s, length_m,
/// by_effect {name: J}, by_phase {phase: J}.
py::dict breakdownDict(const energy::Breakdown& b);

}  // namespace wattswath::python
