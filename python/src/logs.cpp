// Python bindings of the logs library: canonical CSV, ArduPilot DataFlash and PX4 ULog flight logs
// read into one FlightLog whose samples are NumPy arrays.
#include <limits>

#include "bindings.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/logs/log_io.hpp"

namespace wattswath::python {
namespace {

namespace lg = logs;

// One column of the samples as a NumPy array.
template <class F>
py::array_t<double> column(const lg::FlightLog& log, const F& f) {
  return arrayOf(log.samples.size(), [&](std::size_t i) { return f(log.samples[i]); });
}

lg::FlightLog readLog(const std::string& path, double from_s, double to_s, bool airborne_only, bool lenient) {
  lg::LogReadOptions o;
  o.from_s = from_s;
  o.to_s = to_s;
  o.airborne_only = airborne_only;
  o.lenient = lenient;
  return lg::readFlightLog(path, o);
}

py::list eventList(const lg::FlightLog& log) {
  py::list out;
  for (const auto& e : log.events) out.append(py::dict(py::arg("t") = e.t, py::arg("kind") = e.kind, py::arg("text") = e.text));
  return out;
}

void bindSampleArrays(py::class_<lg::FlightLog>& c) {
  c.def_property_readonly("t", [](const lg::FlightLog& l) { return column(l, [](const auto& s) { return s.t; }); },
                          "Sample times [s], increasing.")
      .def_property_readonly("position", [](const lg::FlightLog& l) {
            return rowsOf<3>(l.samples.size(), [&](std::size_t i) { return l.samples[i].position; });
          }, "Positions, N x 3, local ENU [m] (z up).")
      .def_property_readonly("velocity", [](const lg::FlightLog& l) {
            return rowsOf<3>(l.samples.size(), [&](std::size_t i) { return l.samples[i].velocity; });
          }, "Ground velocities, N x 3, ENU [m/s].")
      .def_property_readonly("acceleration", [](const lg::FlightLog& l) {
            return rowsOf<3>(l.samples.size(), [&](std::size_t i) { return l.samples[i].acceleration; });
          }, "Accelerations, N x 3, ENU, gravity removed [m/s^2].")
      .def_property_readonly("yaw", [](const lg::FlightLog& l) { return column(l, [](const auto& s) { return s.yaw; }); },
                             "ENU heading [rad] (NaN where not logged).")
      .def_property_readonly("voltage", [](const lg::FlightLog& l) { return column(l, [](const auto& s) { return s.voltage; }); },
                             "Battery voltage [V] (NaN where not logged).")
      .def_property_readonly("current", [](const lg::FlightLog& l) { return column(l, [](const auto& s) { return s.current; }); },
                             "Battery current [A] (NaN where not logged).")
      .def_property_readonly("power", [](const lg::FlightLog& l) { return column(l, [](const auto& s) { return s.power; }); },
                             "Electrical power drawn [W].")
      .def_property_readonly("mass", [](const lg::FlightLog& l) { return column(l, [](const auto& s) { return s.mass; }); },
                             "Vehicle mass [kg] (NaN where not logged).");
}

}  // namespace

void bindLogs(py::module_& m) {
  py::class_<lg::FlightLog> c(m, "FlightLog", "A flight log: samples as NumPy arrays (SI units, local ENU frame).");
  c.def_readonly("source", &lg::FlightLog::source, "File the log was read from.")
      .def_readonly("format", &lg::FlightLog::format, "'csv', 'dataflash', 'ulog' or 'simulated'.")
      .def_readonly("metadata", &lg::FlightLog::metadata, "Metadata: the file's '# key: value' lines and reader facts.")
      .def_readonly("velocity_derived", &lg::FlightLog::velocity_derived, "Velocities were derived from positions.")
      .def_readonly("acceleration_derived", &lg::FlightLog::acceleration_derived,
                    "Accelerations were derived from velocities.")
      .def_property_readonly("airborne", [](const lg::FlightLog& l) {
            py::list out;
            for (const auto& w : l.airborne) out.append(py::make_tuple(w.begin, w.end));
            return out;
          }, "Airborne windows found by the reader, a list of (begin, end) [s].")
      .def_property_readonly("events", &eventList, "Modes, events and mission items: dicts t [s], kind, text.")
      .def_property_readonly("duration", &lg::FlightLog::duration, "First to last sample [s].")
      .def("to_csv", &lg::writeCsvLog, "The log as canonical CSV text (../shared/formats/flight-log-csv.md).")
      .def("__len__", [](const lg::FlightLog& l) { return l.samples.size(); }, "Number of samples.")
      .def("__repr__", [](const lg::FlightLog& l) {
        return "<wattswath.FlightLog '" + l.source + "' (" + l.format + "), " + std::to_string(l.samples.size()) +
               " samples>";
      });
  bindSampleArrays(c);
  const double inf = std::numeric_limits<double>::infinity();
  m.def("read_log", &readLog, py::arg("path"), py::arg("from_s") = -inf, py::arg("to_s") = inf,
        py::arg("airborne_only") = false, py::arg("lenient") = false,
        "Reads a flight log of any supported format (canonical CSV, DataFlash .bin, ULog .ulg, by content), "
        "keeping samples in [from_s, to_s] [s]; lenient skips corrupt parts of binary logs (listed in "
        "metadata['warnings']). RuntimeError names the file, line and column.");
  m.def("parse_csv_log", [](const std::string& text, const std::string& source) { return lg::parseCsvLog(text, source); },
        py::arg("text"), py::arg("source") = "<string>",
        "Parses canonical CSV text into a FlightLog; `source` names it in error messages.");
  m.def("read_waypoint_path", [](const std::string& path) {
          const auto w = lg::readWaypointPath(path);
          return rowsOf<3>(w.size(), [&](std::size_t i) { return w[i]; });
        }, py::arg("path"), "A waypoint path file ('x y z' [m] per line) as an N x 3 array.");
}

}  // namespace wattswath::python
