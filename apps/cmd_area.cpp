// `wattswath area info`: read, validate and describe a survey area.
#include <iostream>
#include <memory>

#include "cli.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::apps {
namespace geo = wattswath::geometry;

namespace {

nlohmann::json areaInfoJson(const geo::SurveyArea& a) {
  size_t vertices = 0, holes = 0;
  for (const auto& r : a.regions) {
    vertices += r.outer.size();
    holes += r.holes.size();
    for (const auto& h : r.holes) vertices += h.size();
  }
  const geo::Point lo = a.bboxMin(), hi = a.bboxMax();
  nlohmann::json bbox = {{"min_x_m", lo.x()}, {"min_y_m", lo.y()}, {"max_x_m", hi.x()}, {"max_y_m", hi.y()},
                         {"width_m", hi.x() - lo.x()}, {"height_m", hi.y() - lo.y()}};
  nlohmann::json origin = nullptr;
  if (a.frame) {
    const auto& o = a.frame->origin();
    origin = {{"lat_deg", o.lat_deg}, {"lon_deg", o.lon_deg}, {"alt_m", o.alt_m}};
    const geo::GeoPoint sw = a.frame->toGeodetic(lo), ne = a.frame->toGeodetic(hi);
    bbox["south_deg"] = sw.lat_deg;
    bbox["west_deg"] = sw.lon_deg;
    bbox["north_deg"] = ne.lat_deg;
    bbox["east_deg"] = ne.lon_deg;
  }
  nlohmann::json home = nullptr;
  if (a.home) home = {{"x_m", a.home->x()}, {"y_m", a.home->y()}};
  return {{"source", a.source},
          {"regions", a.regions.size()},
          {"vertices", vertices},
          {"holes", holes},
          {"no_fly_zones", a.no_fly.size()},
          {"area_m2", a.area()},
          {"perimeter_m", a.perimeter()},
          {"bbox", bbox},
          {"origin", origin},
          {"home", home},
          {"repairs", a.repairs}};
}

void registerAreaInfo(CLI::App& area) {
  struct Opts {
    std::string path;
    std::vector<std::string> no_fly;
    std::string wkt_units = "lonlat", layer, where;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = area.add_subcommand("info", "Read, validate and describe a survey area (GeoJSON, KML, WKT, QGC .waypoints / .plan, Mission Planner .poly, any GDAL vector format)");
  cmd->add_option("AREA", o->path, "survey area file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--no-fly", o->no_fly, "extra no-fly zone file(s), subtracted from the area")->check(CLI::ExistingFile);
  cmd->add_option("--wkt-units", o->wkt_units, "WKT coordinates: lonlat (degrees) or metres")
      ->check(CLI::IsMember({"lonlat", "metres"}));
  addAreaSelectOptions(cmd, o->layer, o->where);
  addJsonFlag(cmd, o->json);
  cmd->callback([o]() {
    geo::ReadOptions ro;
    ro.layer = o->layer;
    ro.where = o->where;
    ro.no_fly_files = o->no_fly;
    ro.wkt_units = o->wkt_units == "metres" ? geo::WktUnits::Metres : geo::WktUnits::LonLatDegrees;
    const geo::SurveyArea a = geo::readSurveyArea(o->path, ro);
    const nlohmann::json j = areaInfoJson(a);
    if (o->json) {
      printJson(j);
      return;
    }
    std::cout << "area:       " << a.source << "\n"
              << "regions:    " << a.regions.size() << " (" << j["holes"] << " holes, " << j["vertices"] << " vertices)\n"
              << "area:       " << a.area() << " m^2\n"
              << "perimeter:  " << a.perimeter() << " m\n"
              << "bbox:       " << j["bbox"]["width_m"] << " m x " << j["bbox"]["height_m"] << " m\n";
    if (a.frame) std::cout << "origin:     " << a.frame->origin().lat_deg << ", " << a.frame->origin().lon_deg << "\n";
    for (const auto& r : a.repairs) std::cout << "repair:     " << r << "\n";
  });
}

}  // namespace

void registerAreaCommands(CLI::App& app) {
  auto* area = app.add_subcommand("area", "Survey areas: read, validate, describe");
  area->require_subcommand(1);
  registerAreaInfo(*area);
}

}  // namespace wattswath::apps
