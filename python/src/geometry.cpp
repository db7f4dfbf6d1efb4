// Python bindings of the geometry library: survey areas read from GeoJSON, KML, WKT and QGC
// .waypoints files, projected to the local East-North-Up frame [m].
#include "bindings.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::python {
namespace {

namespace geo = geometry;

py::array_t<double> ringArray(const geo::Ring& r) {
  return rowsOf<2>(r.size(), [&](std::size_t i) { return r[i]; });
}

py::list ringList(const std::vector<geo::Ring>& rings) {
  py::list out;
  for (const auto& r : rings) out.append(ringArray(r));
  return out;
}

geo::OriginChoice originChoice(const std::string& s) {
  if (s == "bbox") return geo::OriginChoice::BoundingBoxCenter;
  if (s == "first_vertex") return geo::OriginChoice::FirstVertex;
  if (s == "home") return geo::OriginChoice::Home;
  throw std::invalid_argument("origin = '" + s + "': expected 'bbox', 'first_vertex' or 'home'");
}

geo::SurveyArea readArea(const std::string& path, const std::vector<std::string>& no_fly, const std::string& origin) {
  geo::ReadOptions o;
  o.no_fly_files = no_fly;
  o.origin_choice = originChoice(origin);
  return geo::readSurveyArea(path, o);
}

}  // namespace

void bindGeometry(py::module_& m) {
  py::class_<geo::SurveyArea>(m, "SurveyArea",
                              "A validated survey area in the local ENU frame [m] (x east, y north).")
      .def_readonly("source", &geo::SurveyArea::source, "File the area was read from.")
      .def_readonly("repairs", &geo::SurveyArea::repairs, "What was repaired or clipped, one note each.")
      .def_property_readonly("area_m2", &geo::SurveyArea::area, "Flyable area of all regions [m^2].")
      .def_property_readonly("perimeter_m", &geo::SurveyArea::perimeter, "Length of all boundaries and holes [m].")
      .def_property_readonly("region_count", [](const geo::SurveyArea& a) { return a.regions.size(); },
                             "Number of separate flyable parts.")
      .def_property_readonly("outer", [](const geo::SurveyArea& a) { return ringArray(a.polygon().outer); },
                             "Outer boundary of the single region, N x 2 [m], counter-clockwise "
                             "(RuntimeError when the area has several parts).")
      .def_property_readonly("holes", [](const geo::SurveyArea& a) { return ringList(a.polygon().holes); },
                             "Holes of the single region (no-fly zones inside it), a list of N x 2 arrays [m].")
      .def_property_readonly("no_fly", [](const geo::SurveyArea& a) { return ringList(a.no_fly); },
                             "Extra no-fly zones as read, a list of N x 2 arrays [m].")
      .def_property_readonly("home", [](const geo::SurveyArea& a) -> py::object {
            if (!a.home) return py::none();
            return py::make_tuple(a.home->x(), a.home->y());
          }, "Home (launch) point (x, y) [m], or None when the file has none.")
      .def_property_readonly("origin", [](const geo::SurveyArea& a) -> py::object {
            if (!a.frame) return py::none();
            const geo::GeoPoint o = a.frame->origin();
            return py::make_tuple(o.lat_deg, o.lon_deg, o.alt_m);
          }, "The local frame's origin (lat [deg], lon [deg], alt [m]), or None for metric input.")
      .def("to_geodetic", [](const geo::SurveyArea& a, double x, double y) {
            if (!a.frame) throw std::invalid_argument(a.source + ": the area has no geodetic frame (metric input)");
            const geo::GeoPoint g = a.frame->toGeodetic(geo::Point(x, y));
            return py::make_tuple(g.lat_deg, g.lon_deg);
          }, py::arg("x"), py::arg("y"), "Local point [m] to (lat, lon) [deg].")
      .def("__repr__", [](const geo::SurveyArea& a) {
        return "<wattswath.SurveyArea '" + a.source + "', " + std::to_string(a.area()) + " m^2>";
      });
  m.def("read_area", &readArea, py::arg("path"), py::arg("no_fly") = std::vector<std::string>{},
        py::arg("origin") = "bbox",
        "Reads, projects, validates and repairs a survey area (.geojson, .kml, .wkt, .waypoints), subtracting "
        "the no-fly zone files; origin 'bbox', 'first_vertex' or 'home'. RuntimeError names the file and vertex.");
}

}  // namespace wattswath::python
