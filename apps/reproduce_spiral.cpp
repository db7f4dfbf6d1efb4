// Reproduction section 20: the spiral-coverage 47 kJ case of Marins, Cabreira & Ferreira, Section
// V-A, Tables III and IV, end to end from the E-Spiral rectangle file.
#include <cmath>
#include <filesystem>
#include <sstream>

#include "reproduce.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/path_profile.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/coverage.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/geometry/swath.hpp"
#include "spiral_case.hpp"

namespace wattswath::apps {
namespace {

namespace en = wattswath::energy;
namespace g = wattswath::geometry;

/// One row of Table III / IV: hover, kinetic, drag energy of one part [J].
struct PaperRow {
  const char* part;
  double hover, kinetic, drag;
};

// Marins et al. Table III (modelled, a = 1 m/s^2, 8 m/s, 4.4 m/s curves): total 46,603 J.
constexpr PaperRow kTable3[] = {{"accelerate", 8560, 506, 131},
                                {"cruise", 27286, 0, 1096},
                                {"brake", 6848, 434, 128},
                                {"curves", 1601, 0, 13}};
// Marins et al. Table IV (corrected: a about 1.2 m/s^2, slower legs): total 47,556 J; measured 47,329 J.
constexpr PaperRow kTable4[] = {{"accelerate", 7472, 499, 97},
                                {"cruise", 29902, 0, 1122},
                                {"brake", 6313, 445, 96},
                                {"curves", 1601, 0, 9}};
constexpr double kTable3Total = 46603.0;
constexpr double kTable4Total = 47556.0;
constexpr double kMeasured = 47329.0;
constexpr double kTolerancePct = 3.0;  // [%] Table III's total, ours against the paper's

const en::Phase kParts[] = {en::Phase::Accelerate, en::Phase::Cruise, en::Phase::Brake, en::Phase::Turn};

nlohmann::json breakdownJson(const en::Breakdown& b) {
  nlohmann::json parts = nlohmann::json::object();
  const char* names[] = {"accelerate", "cruise", "brake", "curves"};
  for (int i = 0; i < 4; ++i) {
    parts[names[i]] = {{"hover_j", b.at("hover", kParts[i])},
                       {"kinetic_j", b.at("kinetic", kParts[i])},
                       {"drag_j", b.at("parasitic_drag", kParts[i])}};
  }
  return {{"hover_j", b.byEffect("hover")},
          {"kinetic_j", b.byEffect("kinetic")},
          {"drag_j", b.byEffect("parasitic_drag")},
          {"by_part", parts}};
}

std::string table(const en::Breakdown& b, const PaperRow (&paper)[4], double paper_total) {
  std::ostringstream md;
  md.setf(std::ios::fixed);
  md.precision(0);
  md << "| part | hover paper | hover ours | kinetic paper | kinetic ours | drag paper | drag ours |\n"
     << "|---|---:|---:|---:|---:|---:|---:|\n";
  double ph = 0, pk = 0, pd = 0;
  for (int i = 0; i < 4; ++i) {
    md << "| " << paper[i].part << " | " << paper[i].hover << " | " << b.at("hover", kParts[i]) << " | "
       << paper[i].kinetic << " | " << b.at("kinetic", kParts[i]) << " | " << paper[i].drag << " | "
       << b.at("parasitic_drag", kParts[i]) << " |\n";
    ph += paper[i].hover;
    pk += paper[i].kinetic;
    pd += paper[i].drag;
  }
  md << "| **total by component** | " << ph << " | " << b.byEffect("hover") << " | " << pk << " | "
     << b.byEffect("kinetic") << " | " << pd << " | " << b.byEffect("parasitic_drag") << " |\n";
  md << "| **total** | " << paper_total << " | " << b.total() << " | | | | |\n\n";
  return md.str();
}

ReproSection reproduceSpiral(const ReproContext& ctx) {
  ReproSection s;
  const std::string area_file = ctx.shared_data + "/espiral/area__rectangle.waypoints";
  std::ostringstream md;
  md << "## Spiral coverage case (Marins et al. Section V-A, Tables III and IV)\n\n";
  if (!std::filesystem::exists(area_file)) {
    md << "Skipped: " << area_file << " not found (the reference data is not beside the checkout).\n";
    s.markdown = md.str();
    s.json["spiral_case"] = {{"skipped", "reference data not found"}};
    return s;
  }
  const auto vehicle = en::loadVehicle(ctx.source_dir + "/data/vehicles/iris.json");
  const auto area = g::readSurveyArea(area_file);
  const SpiralCaseSettings paper_settings = SpiralCaseSettings::table3(vehicle);
  const SpiralCaseResult ours = runSpiralCase(area.polygon(), vehicle, paper_settings);
  const SpiralCaseSettings corrected_settings = SpiralCaseSettings::table4(vehicle);
  const SpiralCaseResult corrected = runSpiralCase(area.polygon(), vehicle, corrected_settings);

  nlohmann::json j = {{"energy_j", ours.breakdown.total()},
                      {"time_s", ours.breakdown.time},
                      {"length_m", ours.path.length()},
                      {"legs", ours.path.legs.size()},
                      {"breakdown", breakdownJson(ours.breakdown)},
                      {"spacing_m", ours.spacing},
                      {"laps", ours.laps},
                      {"corner_radius_m", paper_settings.corner_radius},
                      {"rows",
                       {reproRow("total energy, Table III", kTable3Total, ours.breakdown.total(), "J"),
                        reproRow("total energy, Table IV (corrected)", kTable4Total, corrected.breakdown.total(), "J"),
                        reproRow("measured flight vs corrected", kMeasured, corrected.breakdown.total(), "J")}},
                      {"corrected",
                       {{"energy_j", corrected.breakdown.total()},
                        {"time_s", corrected.breakdown.time},
                        {"breakdown", breakdownJson(corrected.breakdown)}}}};
  s.json["spiral_case"] = j;

  md.setf(std::ios::fixed);
  md.precision(1);
  md << "Area: `espiral/area__rectangle.waypoints` (" << area.polygon().outer.size()
     << " vertices, " << area.area() << " m^2). E-Spiral camera: 10 m altitude, 100 deg field of view, "
     << "10 % side overlap, so passes are " << ours.spacing << " m apart (2 h tan(fov/2) (1 - overlap)).\n\n"
     << "**Path reconstruction.** The paper does not give the path; we rebuild it: inward offsets of the "
     << "rectangle at spacing/2, 3 spacing/2, ... (CGAL straight skeleton) give " << ours.laps
     << " laps, joined into one spiral that starts at a corner on a long side, flies each lap counter-"
     << "clockwise and leaves it one spacing before its start for the next lap. Corners are arcs of "
     << "radius v_corner / omega_max = " << paper_settings.corner_radius << " m. That gives "
     << ours.path.legs.size() << " legs (" << ours.path.legs.size() - ours.path.turnCount() << " straights, "
     << ours.path.turnCount() << " curves), " << ours.path.length()
     << " m, " << ours.pieces << " constant-acceleration pieces; the paper's \"45 small parts (straights "
     << "and curves)\" is not defined closely enough to match exactly. The spiral covers "
     << 100.0 * ours.coverage << " % of the rectangle.\n\n"
     << "**Table III** (a = 1 m/s^2, 8 m/s cruise, 4.4 m/s = 55 % of cruise in the curves, start and end "
     << "at rest, IRIS parameters of Section IV, energies in J):\n\n"
     << table(ours.breakdown, kTable3, kTable3Total);
  const double diff3 = 100.0 * (ours.breakdown.total() - kTable3Total) / kTable3Total;
  const bool within = std::abs(diff3) <= kTolerancePct;
  s.json["spiral_case"]["tolerance_pct"] = kTolerancePct;
  s.json["spiral_case"]["within_tolerance"] = within;
  // The hover rows are time x P_hov: the paper's rows in seconds of our hover power.
  const en::Breakdown& b = ours.breakdown;
  const double p_hov = b.byEffect("hover") / b.time;
  const double paper_hover = kTable3[0].hover + kTable3[1].hover + kTable3[2].hover + kTable3[3].hover;
  md.precision(2);
  md << "Ours " << b.total() << " J vs the paper's 46,603 J: " << diff3 << " %, "
     << (within ? "within" : "OUTSIDE") << " the tolerance of " << static_cast<int>(kTolerancePct) << " %; time " << b.time
     << " s. Differences: our accelerate and "
     << "brake rows are equal, as they must be with equal a and the same speeds at both ends of every "
     << "straight (start and end at rest); the paper's brake row is 20 % below its accelerate row, "
     << "which its stated settings do not explain. ";
  md.precision(1);
  md << "In time at our hover power (" << p_hov << " W) the paper's hover column is "
     << paper_hover / p_hov - b.time << " s longer than ours in all, so its path (E-Spiral's own, not published) "
     << "was at most a few seconds longer than our reconstruction; but its cruise row is "
     << (kTable3[1].hover - b.at("hover", en::Phase::Cruise)) / p_hov << " s longer and its brake row "
     << (b.at("hover", en::Phase::Brake) - kTable3[2].hover) / p_hov
     << " s shorter than ours: most of the cruise difference is time the paper books as cruise and we book as "
        "braking, which its settings do not explain either. Drag is integrated exactly over each piece (the "
        "paper's Eq. 9 uses the cruise speed for the whole leg).\n\n";
  md.precision(1);
  md << "**Table IV** (corrected: a = " << corrected_settings.acceleration << " m/s^2, curves at "
     << corrected_settings.corner_speed << " m/s, cruise " << corrected_settings.cruise_speed << " m/s on legs of "
     << corrected_settings.long_leg << " m or more and " << corrected_settings.short_leg_speed
     << " m/s on shorter ones, the paper's \"below 7 m/s on very short paths\", \"at 4 m/s or less in turns\" "
     << "and \"mean acceleration 1.2 m/s^2\"; the paper gives no exact speeds):\n\n"
     << table(corrected.breakdown, kTable4, kTable4Total);
  md.precision(2);
  md << "Ours " << corrected.breakdown.total() << " J vs Table IV's 47,556 J ("
     << 100.0 * (corrected.breakdown.total() - kTable4Total) / kTable4Total << " %) and the measured 47,329 J ("
     << 100.0 * (corrected.breakdown.total() - kMeasured) / kMeasured << " %).\n";
  s.markdown = md.str();
  return s;
}

const bool kRegistered = registerReproSection(20, "spiral_case", &reproduceSpiral);

}  // namespace
}  // namespace wattswath::apps
