// `plan --sorties`: the plan split into battery-sized sorties, each checked by the flight model.
#include "plan_sorties.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <regex>
#include <stdexcept>

#include "cli.hpp"
#include "plan_fleet.hpp"
#include "plan_flight.hpp"
#include "predict_spread.hpp"
#include "wattswath/report/svg.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/planned_mission.hpp"
#include "wattswath/planner/battery_use.hpp"
#include "wattswath/planner/sorties.hpp"

namespace wattswath::apps {
namespace {

namespace pl = wattswath::planner;

struct FlownSortie {
  pl::Sortie sortie;
  pl::PlanMission mission;
  mission::MissionPrediction prediction;
};

// Every sortie of `split` written and flown; `fits` false when one does not keep the reserve with
// the energy margin (FlightScoring::settings.energy_margin; predict's "Fits", not "too close to call").
std::vector<FlownSortie> flySorties(const pl::SortieSplit& split, const pl::FlightScoring& s, bool& fits) {
  std::vector<FlownSortie> out;
  fits = true;
  for (const auto& so : split.sorties) {
    FlownSortie f{so, pl::missionFromPlan(so.flown, *s.problem, *s.frame, s.home_altitude_amsl_m, s.mission), {}};
    f.prediction = pl::flyWrittenMission(f.mission, s, "sortie mission.plan");
    fits = fits && f.prediction.battery.fits_with_margin;
    out.push_back(std::move(f));
  }
  return out;
}

double total(const std::vector<FlownSortie>& v) {
  double e = 0.0;
  for (const auto& f : v) e += f.prediction.total.energy_j;
  return e;
}

double totalTime(const std::vector<FlownSortie>& v) {
  double t = 0.0;
  for (const auto& f : v) t += f.prediction.total.time_s;
  return t;
}

int parseCount(const std::string& text) {
  if (text == "auto") return 0;
  try {
    std::size_t used = 0;
    const int n = std::stoi(text, &used);
    if (used == text.size() && n >= 1 && n <= 1000) return n;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument("--sorties '" + text + "': expected 'auto' or a count 1..1000");
}

std::string name(std::size_t k, const char* ext) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "sortie_%02zu.%s", k + 1, ext);
  return buf;
}

}  // namespace

// The closed-form budget corrected by flights: the usable energy as predict's battery model
// discharges it, from the sorties of a first split at `ss.budget_j` (energy / (1 - usable left),
// their median). Unchanged when that split fails or no sortie used the battery.
double flownBudget(const pl::PlanCandidate& plan, const pl::FlightScoring& scoring, pl::RouteScorer& scorer,
                   const pl::SortieSettings& ss, double reserve_pct) {
  std::vector<FlownSortie> flown;
  bool fits = false;
  try {
    flown = flySorties(pl::splitIntoSorties(plan.flown, *scoring.problem, scorer, ss), scoring, fits);
  } catch (const std::runtime_error&) {
    return ss.budget_j;
  }
  std::vector<double> usable_j;
  for (const auto& f : flown)
    if (f.prediction.battery.usable_left_end < 0.95) usable_j.push_back(f.prediction.total.energy_j / (1.0 - f.prediction.battery.usable_left_end));
  if (usable_j.empty()) return ss.budget_j;
  std::nth_element(usable_j.begin(), usable_j.begin() + usable_j.size() / 2, usable_j.end());
  return usable_j[usable_j.size() / 2] * (1.0 - reserve_pct / 100.0) / (1.0 + scoring.settings.energy_margin);
}

// The fewest sorties (or `ss.count`) each of which, flown by the autopilot model, lands with the
// reserve with the energy margin, and among those the least closed-form energy: the planner asks
// the flight model which runs of pieces fly (pl::splitIntoFlownSorties), starting from the
// closed-form budget `ss.budget_j` (flownBudget's).
std::vector<FlownSortie> flownSplit(const pl::PlanCandidate& plan, const pl::FlightScoring& scoring, pl::RouteScorer& scorer,
                                    const pl::SortieSettings& ss, bool& fits) {
  fits = false;
  if (ss.budget_j <= ss.overhead_j) return {};
  const pl::SortieCheck flies = [&](const pl::Sortie& so) {
    const auto m = pl::missionFromPlan(so.flown, *scoring.problem, *scoring.frame, scoring.home_altitude_amsl_m, scoring.mission);
    return pl::flyWrittenMission(m, scoring, "sortie mission.plan").battery.fits_with_margin;
  };
  try {
    return flySorties(pl::splitIntoFlownSorties(plan.flown, *scoring.problem, scorer, ss, flies), scoring, fits);
  } catch (const std::runtime_error&) {
    return {};
  }
}

// The closed-form split (`ss.naive`: the naive one) at which every sortie, flown by the autopilot
// model, lands with the reserve: from the budget `ss.budget_j` (flownBudget's), the pieces of a
// sortie that lands below the reserve weighted up until every one keeps it.
std::vector<FlownSortie> repairedSplit(const pl::PlanCandidate& plan, const pl::FlightScoring& scoring, pl::RouteScorer& scorer,
                                       pl::SortieSettings ss, double reserve_pct, bool& fits) {
  std::vector<FlownSortie> flown;
  fits = false;
  for (int attempt = 0; attempt < 30; ++attempt) {
    if (ss.budget_j <= ss.overhead_j) break;
    try {
      flown = flySorties(pl::splitIntoSorties(plan.flown, *scoring.problem, scorer, ss), scoring, fits);
    } catch (const std::runtime_error&) {
      fits = false;
      break;  // no split at this budget: none with heavier pieces
    }
    if (fits) break;
    // Where a sortie lands below the reserve (the battery drains faster at high power than its
    // energy says), its pieces weigh more in the next split.
    if (ss.piece_weight.empty()) ss.piece_weight.assign(static_cast<std::size_t>(flown.back().sortie.last_sweep + 1), 1.0);
    for (const auto& f : flown) {
      const double left = f.prediction.battery.usable_left_end_with_margin, reserve = reserve_pct / 100.0;
      if (f.prediction.battery.fits_with_margin) continue;
      const double factor = 1.02 + std::max(0.0, reserve - left) / std::max(1.0 - reserve, 0.1);
      for (int p = f.sortie.first_sweep; p <= f.sortie.last_sweep; ++p) ss.piece_weight[static_cast<std::size_t>(p)] *= factor;
    }
  }
  return flown;
}

// The better of the flown split and the repaired closed-form one, each flown: the fewest sorties
// that all land with the reserve, then the least flown energy. The flown split takes a run to fly
// when a longer one from the same piece does, which a run ending far from home can belie; the
// repaired split then may fit with fewer.
std::vector<FlownSortie> bestSplit(const pl::PlanCandidate& plan, const pl::FlightScoring& scoring, pl::RouteScorer& scorer,
                                   pl::SortieSettings ss, double reserve_pct, bool& fits) {
  ss.budget_j = flownBudget(plan, scoring, scorer, ss, reserve_pct);
  bool flown_fits = false, repaired_fits = false;
  std::vector<FlownSortie> flown = flownSplit(plan, scoring, scorer, ss, flown_fits);
  std::vector<FlownSortie> repaired = repairedSplit(plan, scoring, scorer, ss, reserve_pct, repaired_fits);
  fits = flown_fits || repaired_fits;
  if (!repaired_fits) return flown;
  if (!flown_fits) return repaired;
  const bool repaired_better = repaired.size() < flown.size() || (repaired.size() == flown.size() && total(repaired) < total(flown));
  return repaired_better ? repaired : flown;
}

namespace {

// The sortie's flight as the separation check and the map read it: horizontal positions in the
// area's local frame (the prediction's are from home).
pl::Track trackOf(const mission::MissionPrediction& p, const geometry::Point& home) {
  pl::Track t;
  for (const auto& smp : p.flight.samples) t.push_back({smp.t, home + smp.position.head<2>(), smp.airborne});
  return t;
}

// The report's row of a flown sortie (its track every ~1 s for the map).
report::PlanSortie viewOf(const FlownSortie& f, const pl::Track& track, const std::string& name, const std::string& file, bool camera) {
  report::PlanSortie v;
  v.name = name;
  v.file = file;
  for (std::size_t i = 0; i < track.size(); i += 10) v.track.push_back(track[i].p);
  if (!track.empty()) v.track.push_back(track.back().p);
  v.energy_j = f.prediction.total.energy_j;
  v.time_s = f.prediction.total.time_s;
  v.soc_landing_pct = 100.0 * f.prediction.battery.usable_left_end;
  v.photos = camera ? f.mission.photos : -1;
  return v;
}

std::string fleetName(int vehicle, int order, const char* ext) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "vehicle_%d_sortie_%02d.%s", vehicle + 1, order + 1, ext);
  return buf;
}

// Writes the sorties' missions and fills the per-sortie JSON and report rows (fleet: `fleet`).
void writeSorties(const std::vector<FlownSortie>& flown, const std::vector<pl::Track>& tracks, const pl::FleetSchedule* fleet,
                  bool camera, const std::filesystem::path& dir, const SortieRequest& req, nlohmann::json& list,
                  SortieOutcome& out) {
  auto& view = out.view;
  for (std::size_t k = 0; k < flown.size(); ++k) {
    const auto& f = flown[k];
    const pl::ScheduledSortie* sc = fleet ? &fleet->sorties[k] : nullptr;
    const std::string plan = sc ? fleetName(sc->vehicle, sc->order, "plan") : name(k, "plan");
    const std::string wpl = sc ? fleetName(sc->vehicle, sc->order, "waypoints") : name(k, "waypoints");
    // As plan's other files: never over an input, over an existing file only with --force.
    for (const auto& file : {plan, wpl}) checkWritable((dir / file).string(), req.force, req.inputs);
    writeTextFileAtomic((dir / plan).string(), mission::toQgcPlan(f.mission.mission));
    writeTextFileAtomic((dir / wpl).string(), mission::toQgcWpl(f.mission.mission));
    out.files.push_back(plan);
    out.files.push_back(wpl);
    const double e = f.prediction.total.energy_j;
    nlohmann::json row = {{"file", plan}, {"energy_j", e}, {"energy_wh", e / 3600.0}, {"time_s", f.prediction.total.time_s},
                          {"usable_left_pct", 100.0 * f.prediction.battery.usable_left_end}, {"fits", f.prediction.battery.fits},
                          {"usable_left_with_margin_pct", 100.0 * f.prediction.battery.usable_left_end_with_margin},
                          {"fits_with_margin", f.prediction.battery.fits_with_margin},
                          {"photos", camera ? nlohmann::json(f.mission.photos) : nlohmann::json(nullptr)},
                          {"first_sweep", f.sortie.first_sweep + 1}, {"last_sweep", f.sortie.last_sweep + 1}};
    std::string label = "sortie " + std::to_string(k + 1);
    if (sc) {
      row["vehicle"] = sc->vehicle + 1;
      row["vehicle_sortie"] = sc->order + 1;
      row["start_s"] = sc->start_s;
      row["end_s"] = sc->end_s;
      row["delay_s"] = sc->delay_s;
      label = "vehicle " + std::to_string(sc->vehicle + 1) + ", sortie " + std::to_string(sc->order + 1);
    }
    list.push_back(row);
    view.sorties.push_back(viewOf(f, tracks[k], label, plan, camera));
    if (sc) {
      view.sorties.back().vehicle = sc->vehicle + 1;
      view.sorties.back().start_s = sc->start_s;
      view.sorties.back().delay_s = sc->delay_s;
    }
  }
}

}  // namespace

SortieOutcome planSorties(const pl::PlanCandidate& plan, const PlanFlight& flight, pl::FlightScoring scoring, const std::string& vehicle_path,
                          const SortieRequest& req, const std::filesystem::path& dir) {
  const int count = parseCount(req.sorties);
  if (!(req.reserve_pct >= 0.0 && req.reserve_pct <= 90.0))
    throw std::invalid_argument("--reserve " + std::to_string(req.reserve_pct) + ": expected 0..90 %");
  const auto& v = *scoring.vehicle;
  if (!v.battery) throw std::runtime_error(vehicle_path + ": --sorties needs the vehicle's battery (a 'battery' object)");
  const auto& ph = flight.prediction.phases;
  const double overhead_j = ph[static_cast<int>(mission::FlightPhase::Takeoff)].energy_j + ph[static_cast<int>(mission::FlightPhase::Landing)].energy_j;
  const double single_flight_j = flight.prediction.total.energy_j;
  if (!(req.energy_margin_pct >= 0.0 && req.energy_margin_pct <= 100.0))
    throw std::invalid_argument("--energy-margin " + std::to_string(req.energy_margin_pct) + ": expected 0..100 %");
  PredictionSetup setup = predictionSetup(v, vehicle_path, "", req.reserve_pct);
  setup.settings.energy_margin = req.energy_margin_pct / 100.0;
  setup.settings.wind = scoring.settings.wind;  // this run's (plan --wind)
  // As the whole plan was flown (plan_flight.cpp): a disputed calibration takes the value of its
  // flights of the plan's kind.
  if (const auto choice = kindChoiceOf(calibration::missionKind(flight.prediction.flight.steps, setup.autopilot), setup))
    setup.autopilot.parameters[setup.disputed_parameter] = choice->value;
  scoring = withSetup(scoring, setup);
  pl::RouteScorer scorer(setup.model, pl::SpeedSettings::fromVehicle(v));
  const double usable = pl::predictBatteryUse(plan.flown, *v.battery).usable_energy_j;
  pl::SortieSettings ss;
  ss.count = count;
  ss.overhead_j = overhead_j;
  ss.budget_j = usable * (1.0 - req.reserve_pct / 100.0) / (1.0 + setup.settings.energy_margin);
  // The closed form against the flight model on the whole plan (take-off and landing apart).
  if (plan.flown.energy > 0.0) ss.scale = std::clamp((single_flight_j - overhead_j) / plan.flown.energy, 0.5, 2.0);
  const double budget0 = ss.budget_j;
  bool fits = false;
  const std::vector<FlownSortie> flown = bestSplit(plan, scoring, scorer, ss, req.reserve_pct, fits);
  if (!fits)
    throw std::runtime_error("no split into " + (count ? std::to_string(count) : std::string("sorties")) + " lands every sortie with the " +
                             std::to_string(req.reserve_pct).substr(0, 4) + " % reserve with " + std::to_string(req.energy_margin_pct).substr(0, 4) +
                             " % more energy (--energy-margin; the battery is too small for a single sweep, or --sorties too few)");
  pl::SortieSettings naive = ss;
  naive.naive = true;
  naive.count = 0;
  naive.budget_j = budget0;
  naive.budget_j = flownBudget(plan, scoring, scorer, naive, req.reserve_pct);
  bool naive_fits = false;
  const auto naive_flown = repairedSplit(plan, scoring, scorer, naive, req.reserve_pct, naive_fits);
  std::vector<pl::Track> tracks;
  for (const auto& f : flown) tracks.push_back(trackOf(f.prediction, scoring.problem->home));
  std::optional<pl::FleetSchedule> fleet;
  if (req.vehicles > 0) fleet = pl::scheduleFleet(tracks, fleetSettings(req));
  SortieOutcome out;
  nlohmann::json list = nlohmann::json::array();
  writeSorties(flown, tracks, fleet ? &*fleet : nullptr, scoring.mission.trigger_distance_m > 0.0, dir, req, list, out);
  const double e = total(flown), e_naive = total(naive_flown);
  out.json = {{"count", flown.size()}, {"reserve_pct", req.reserve_pct}, {"energy_margin_pct", req.energy_margin_pct}, {"total_energy_j", e},
              {"total_time_s", totalTime(flown)}, {"single_flight_energy_j", single_flight_j},
              {"single_flight_time_s", flight.prediction.total.time_s},
              {"single_flight", "mission.plan flown in one flight by " + flight.autopilot + " with an unlimited battery"},
              {"price_of_splitting_pct", 100.0 * (e / single_flight_j - 1.0)},
              {"naive", {{"count", naive_flown.size()}, {"total_energy_j", e_naive}, {"all_fit", naive_fits}}},
              {"sorties", list},
              {"fleet", fleet ? fleetJson(*fleet, req, tracks) : nlohmann::json(nullptr)}};
  auto& view = out.view;
  view.single_energy_j = single_flight_j;
  view.single_time_s = flight.prediction.total.time_s;
  view.single_base = "mission.plan flown by " + flight.autopilot + ", unlimited battery";
  view.reserve_pct = req.reserve_pct;
  if (fleet) fillFleetView(*fleet, req, view);
  return out;
}

std::vector<std::string> staleSortieFiles(const std::filesystem::path& dir, const std::vector<std::string>& written,
                                          const std::vector<std::string>& inputs) {
  static const std::regex names(R"((sortie_[0-9]{2,}|vehicle_[0-9]+_sortie_[0-9]{2,})\.(plan|waypoints))");
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (!std::regex_match(n, names) || std::find(written.begin(), written.end(), n) != written.end()) continue;
    // An input of this run with a sortie's name (an area saved as sortie_01.plan) is never stale.
    const bool input = std::any_of(inputs.begin(), inputs.end(), [&](const std::string& in) {
      std::error_code same_ec;
      return std::filesystem::equivalent(e.path(), in, same_ec);
    });
    if (!input) out.push_back(n);
  }
  std::sort(out.begin(), out.end());
  return out;
}

void printSorties(const nlohmann::json& j) {
  const double e = j["total_energy_j"], one = j["single_flight_energy_j"], en = j["naive"]["total_energy_j"];
  std::printf("sorties: %d, %.1f kJ flown in all (one flight with an unlimited battery: %.1f kJ, +%.1f %%); naive split: %d sorties, %.1f kJ%s\n",
              j["count"].get<int>(), e / 1000.0, one / 1000.0, 100.0 * (e / one - 1.0), j["naive"]["count"].get<int>(), en / 1000.0,
              j["naive"]["all_fit"].get<bool>() ? "" : " (not all keep the reserve)");
  for (const auto& s : j["sorties"]) {
    std::printf("  %s: sweep pieces %d-%d, %.1f kJ (%.1f Wh), %s min:s, lands with %.0f %% of the usable charge",
                s["file"].get<std::string>().c_str(), s["first_sweep"].get<int>(), s["last_sweep"].get<int>(),
                s["energy_j"].get<double>() / 1000.0, s["energy_wh"].get<double>(), report::formatMinSec(s["time_s"].get<double>()).c_str(),
                s["usable_left_pct"].get<double>());
    if (!s["photos"].is_null()) std::printf(", %d photos", s["photos"].get<int>());
    if (s.contains("vehicle"))
      std::printf(", vehicle %d takes off at %s min:s%s", s["vehicle"].get<int>(), report::formatMinSec(s["start_s"].get<double>()).c_str(),
                  s["delay_s"].get<double>() > 0.0 ? (" (" + report::formatMinSec(s["delay_s"].get<double>()) + " later for the separation)").c_str() : "");
    std::printf("\n");
  }
  if (!j["fleet"].is_null()) printFleet(j["fleet"]);
}

}  // namespace wattswath::apps
