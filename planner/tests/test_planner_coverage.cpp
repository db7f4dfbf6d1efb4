// The planner: valid plans (continuity, coverage >= 99 %, no no-fly entry), never worse than a
// baseline, above the lower bound; speeds and corners optimal for their geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/path_profile.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/speed.hpp"
#include "test_util.hpp"

using namespace wattswath;
using namespace wattswath::planner;
using geometry::LegRole;
using geometry::Point;
using geometry::Ring;

namespace {
energy::Vehicle iris() { return energy::loadVehicle(test::sourcePath("data/vehicles/iris.json")); }

void expectValid(const SurveyProblem& pr, const PlanResult& r) {
  ASSERT_TRUE(r.plan.valid);
  EXPECT_TRUE(checkPlan(pr, r.plan.flown.path).empty()) << checkPlan(pr, r.plan.flown.path).front();
  EXPECT_GE(r.plan.coverage_pct, 99.0);
  // Independent oracle: geometry's exact coverage checker (CGAL Booleans of the swaths), with the
  // no-fly zones (all inside the area in these tests) as holes.
  geometry::PolygonWithHoles free_area = pr.area;
  for (auto z : pr.no_fly) {
    if (geometry::signedArea(z) > 0) std::reverse(z.begin(), z.end());
    free_area.holes.push_back(z);
  }
  const double exact = geometry::checkCoverage(free_area, {r.plan.flown.path}, pr.footprint).fraction();
  EXPECT_GE(exact, 0.99);
  // The planner reports geometry's exact figure (it once used its own sample-grid estimate).
  EXPECT_NEAR(r.plan.coverage_pct, 100.0 * exact, 1e-6);
  // Never dearer than a baseline that keeps coverage too (one that misses 99 % cannot be the plan).
  for (const PlanCandidate* c : {&r.shortest_path, &r.ground_station_default}) {
    if (c->valid && c->coverage_pct >= 99.0) {
      EXPECT_LE(r.plan.flown.energy, c->flown.energy + 1e-6);
    }
  }
  if (r.best_spiral && r.best_spiral->coverage_pct >= 99.0) {
    EXPECT_LE(r.plan.flown.energy, r.best_spiral->flown.energy + 1e-6);
  }
  // Issue 22: no flown point outside the area or inside a hole or no-fly zone, from the first sweep
  // to the last (home may lie outside), within geometry::tol::kContainment (1 mm) of the boundary.
  const auto inside = planContainment(pr, r.plan.flown.path);
  EXPECT_LE(inside.outside_m, 0.0) << "outside the area, up to " << inside.max_depth_m << " m";
  EXPECT_LE(inside.in_holes_m, 0.0) << "in a hole or no-fly zone, up to " << inside.max_depth_m << " m";
  EXPECT_GT(r.lower_bound_j, 0.0);
  EXPECT_LT(r.lower_bound_j, r.plan.flown.energy);
  // A bound for every flight that keeps coverage, the baselines too.
  for (const PlanCandidate* c : {&r.shortest_path, &r.ground_station_default}) {
    if (c->valid && c->coverage_pct >= 99.0) {
      EXPECT_LT(r.lower_bound_j, c->flown.energy);
    }
  }
  if (r.best_spiral && r.best_spiral->coverage_pct >= 99.0) {
    EXPECT_LT(r.lower_bound_j, r.best_spiral->flown.energy);
  }
  // Speeds: every leg within the vehicle limit; junctions continuous.
  const auto& sp = r.plan.flown.speeds;
  ASSERT_EQ(sp.junction.size(), r.plan.flown.path.legs.size() + 1);
  for (double v : sp.cruise) EXPECT_LE(v, 16.0 + 1e-9);
  EXPECT_EQ(sp.junction.front(), 0.0);
  EXPECT_EQ(sp.junction.back(), 0.0);
}

// An L of two arms, 400 m x 80 m along east and 80 m x 400 m along north; 20 m spacing.
SurveyProblem lShape() {
  SurveyProblem p;
  p.area.outer = {{0, 0}, {400, 0}, {400, 80}, {80, 80}, {80, 400}, {0, 400}};
  p.spacing = p.footprint = 20.0;
  p.home = {-10, -10};
  return p;
}

// The E-Spiral rectangle of Marins et al. (about 252 m x 118 m), spacing 21.45 m (10 m altitude,
// 100 deg field of view, 10 % overlap) as in ../shared/data/README.md.
SurveyProblem rectangle() {
  SurveyProblem p;
  p.area.outer = {{0, 0}, {252, 0}, {252, 118}, {0, 118}};
  p.spacing = 21.45;
  p.footprint = 21.45 / 0.9;
  p.home = {-5, -5};
  return p;
}
}  // namespace

TEST(Speed, LegOptimumBeatsAGridOfCruiseSpeeds) {
  const auto v = iris();
  const auto model = energy::marinsModel(v);
  RouteScorer s(model, SpeedSettings::fromVehicle(v));
  for (double L : {10.0, 50.0, 100.0, 200.0, 600.0}) {
    const double e = s.legEnergy(L, 0.0, 0.0, 16.0);
    for (double c = 0.5; c <= 16.0; c += 0.25)
      EXPECT_LE(e, model.energy(energy::buildLegProfile(L, 0.0, c, 0.0, {1.0, 1.0})) + 1e-6) << L << " " << c;
  }
  EXPECT_TRUE(std::isinf(s.legEnergy(1.0, 0.0, 10.0, 16.0)));  // cannot reach 10 m/s in 1 m
}

TEST(Speed, ClosedFormScorerEqualsTheGenericModel) {
  // With Marins' effects only the scorer optimises legs over the inlined closed form; a zero climb
  // effect (nothing on level legs) forces the generic optimiser: legs and routes must agree.
  const auto v = iris();
  const auto marins = energy::marinsModel(v);
  auto generic = marins;
  generic.add(energy::ClimbEffect(0.0, 0.0));
  const auto settings = SpeedSettings::fromVehicle(v);
  RouteScorer fast(marins, settings), slow(generic, settings);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> len(0.5, 800.0), spd(0.0, 16.0);
  int finite = 0;
  for (int i = 0; i < 600; ++i) {
    const double d = len(rng), vi = spd(rng), vo = spd(rng), cap = 1.0 + spd(rng);
    const double a = fast.legEnergy(d, vi, vo, cap), b = slow.legEnergy(d, vi, vo, cap);
    if (!std::isfinite(b)) {
      EXPECT_FALSE(std::isfinite(a)) << d << " " << vi << " " << vo << " " << cap;
      continue;
    }
    ++finite;
    EXPECT_NEAR(a, b, 1e-7 * b) << d << " " << vi << " " << vo << " " << cap;
    // The optimum is flat: speeds agree to about the square root of the energies' agreement.
    EXPECT_NEAR(fast.legCruise(d, vi, vo, cap), slow.legCruise(d, vi, vo, cap), 2e-3) << d << " " << vi << " " << vo << " " << cap;
  }
  EXPECT_GT(finite, 300);
  for (int k = 0; k < 20; ++k) {  // seeded random routes with arcs allowed at every corner
    Route r;
    r.points = {{0, 0}};
    r.max_tangent = {0};
    std::uniform_real_distribution<double> xy(-300.0, 300.0), tan(0.0, 30.0);
    for (int j = 0; j < 8; ++j) r.add({xy(rng), xy(rng)}, j % 2 ? LegRole::Sweep : LegRole::Transit, j == 7 ? 0.0 : tan(rng));
    const double a = fast.energy(r), b = slow.energy(r);
    EXPECT_NEAR(a, b, 1e-6 * b) << k;
  }
}

TEST(Speed, AutoCornersCostNoMoreThanEitherStrategy) {
  const auto v = iris();
  const auto model = energy::marinsModel(v);
  Route r;
  r.points = {{0, 0}};
  r.max_tangent = {0};
  // A boustrophedon with 20 m spacing and 10 m run-out at each line end.
  for (int k = 0; k < 6; ++k) {
    const double y = 20.0 * k;
    const bool right = k % 2 == 0;
    r.add({right ? -10.0 : 210.0, y}, LegRole::Transit, 10.0);
    r.add({right ? 210.0 : -10.0, y}, LegRole::Sweep, 10.0);
  }
  r.add({0, 0}, LegRole::Transit, 0.0);
  auto settings = SpeedSettings::fromVehicle(v);
  double e[3];
  int i = 0;
  for (auto cs : {CornerStrategy::Sharp, CornerStrategy::Rounded, CornerStrategy::Auto}) {
    settings.corners = cs;
    RouteScorer s(model, settings);
    const auto f = s.fly(r);
    EXPECT_NEAR(f.energy, s.energy(r), 1e-6 * f.energy);
    e[i++] = f.energy;
    if (cs == CornerStrategy::Sharp) {
      EXPECT_EQ(f.rounded_corners, 0);
    }
    if (cs == CornerStrategy::Rounded) {
      EXPECT_GT(f.rounded_corners, 0);
    }
  }
  EXPECT_LE(e[2], e[0] + 1e-9);
  EXPECT_LE(e[2], e[1] + 1e-9);
  EXPECT_LT(e[1], e[0]);  // on long sweeps a rounded U-turn at speed beats two stops
}

TEST(Speed, CameraLimitCapsSweepLegsOnly) {
  const auto v = iris();
  auto settings = SpeedSettings::fromVehicle(v);
  settings.camera_max_speed = 4.0;
  RouteScorer s(energy::marinsModel(v), settings);
  Route r;
  r.points = {{0, 0}};
  r.max_tangent = {0};
  r.add({500, 0}, LegRole::Transit, 0);
  r.add({500, 500}, LegRole::Sweep, 0);
  const auto f = s.fly(r);
  for (size_t i = 0; i < f.path.legs.size(); ++i)
    if (f.path.legs[i].role == LegRole::Sweep) {
      EXPECT_LE(f.speeds.cruise[i], 4.0 + 1e-9);
    }
  EXPECT_GT(f.speeds.cruise.front(), 4.0);
}

TEST(Speed, ArcChainsFlyARoundLapWithoutStopping) {
  // Two laps of a 24-gon of radius 140 m (36.5 m edges, 15 deg corners): every widest arc takes
  // half of each edge, so arcs meet with no straight between them. With arcs at chain speeds the
  // laps are flown without a stop; without them every corner is a stop.
  const auto v = iris();
  const auto model = energy::marinsModel(v);
  Route r;
  for (int i = 0; i <= 48; ++i) {
    const Point p(140.0 * std::cos(2 * M_PI * i / 24), 140.0 * std::sin(2 * M_PI * i / 24));
    if (i == 0) {
      r.points.push_back(p);
      r.max_tangent.push_back(0.0);
    } else {
      r.add(p, LegRole::Sweep, i == 48 ? 0.0 : 30.0);
    }
  }
  SpeedSettings with = SpeedSettings::fromVehicle(v), without = with;
  without.arc_chains = false;
  RouteScorer a(model, with), b(model, without);
  const auto fa = a.fly(r), fb = b.fly(r);
  EXPECT_EQ(fa.sharp_corners, 0);
  EXPECT_EQ(fa.rounded_corners, 47);
  EXPECT_GT(fb.sharp_corners, 40);
  EXPECT_LT(fa.energy, 0.6 * fb.energy) << fa.energy << " vs " << fb.energy;
  EXPECT_NEAR(a.energy(r), fa.energy, 1e-6 * fa.energy);
  // Continuity: a junction speed is the end speed of one leg and the start of the next.
  for (double s : fa.speeds.junction) EXPECT_TRUE(std::isfinite(s));
  EXPECT_TRUE(geometry::checkPath(fa.path, geometry::PolygonWithHoles{}).empty());
}

TEST(Speed, RandomRoutesFlyAndEveryLegReprofiles) {
  // Property (fixed seed): random polylines with short and long segments and random arc room fly
  // without an error, fly() costs what energy() says, and every flown leg rebuilds from its own
  // speeds (what the plan report does): the edge cases of legs just long enough for their speed
  // change once threw in both places.
  const auto path_profile_limits = [](const energy::Vehicle& v) {
    return energy::ProfileLimits{v.max_acceleration_mps2, v.max_acceleration_mps2};
  };
  for (const auto& v : {iris(), energy::loadVehicle(test::sourcePath("data/vehicles/hwang-hexacopter.json"))}) {
    const auto model = energy::marinsModel(v);
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    RouteScorer scorer(model, SpeedSettings::fromVehicle(v));
    for (int trial = 0; trial < 150; ++trial) {
      Route r;
      Point p(0, 0);
      r.points.push_back(p);
      r.max_tangent.push_back(0.0);
      double heading = 0.0;
      const int n = 3 + trial % 9;
      for (int k = 0; k < n; ++k) {
        heading += (u(rng) - 0.5) * 2.0 * M_PI * (trial % 3 == 0 ? 0.15 : 0.9);
        p += (2.0 + 60.0 * u(rng) * u(rng)) * Point(std::cos(heading), std::sin(heading));
        r.add(p, k % 4 == 3 ? LegRole::Transit : LegRole::Sweep, k + 1 == n ? 0.0 : 30.0 * u(rng));
      }
      SCOPED_TRACE("trial " + std::to_string(trial));
      FlownPath f;
      ASSERT_NO_THROW(f = scorer.fly(r));
      ASSERT_TRUE(std::isfinite(f.energy));
      EXPECT_NEAR(scorer.energy(r), f.energy, 1e-6 * f.energy);
      for (size_t i = 0; i < f.path.legs.size(); ++i) {
        geometry::CoveragePath one;
        one.legs = {f.path.legs[i]};
        const energy::SpeedPlan sp{{f.speeds.cruise[i]}, {f.speeds.junction[i], f.speeds.junction[i + 1]}};
        EXPECT_NO_THROW(energy::profileFromPath(one, sp, path_profile_limits(v), v.max_yaw_rate_radps)) << "leg " << i;
      }
    }
  }
}

TEST(Planner, RectangleOfMarinsEtAl) {
  const auto v = iris();
  const auto pr = rectangle();
  const auto r = planCoverage(pr, v, energy::marinsModel(v));
  expectValid(pr, r);
  ASSERT_TRUE(r.best_spiral.has_value());
  EXPECT_GE(r.best_spiral->coverage_pct, 99.0);
  EXPECT_TRUE(checkPlan(pr, r.best_spiral->flown.path).empty());
  // The plan is cheaper than what a ground station flies by default.
  EXPECT_LT(r.plan.flown.energy, 0.95 * r.ground_station_default.flown.energy);
}

TEST(Planner, LowerBoundCountsTheStartAndStopEveryFlightMakes) {
  // Rectangle 252 m x 118 m, home 5 m off a corner: the swath length is A / s - w; a flight from
  // rest to rest over it costs at least the best stop-to-stop leg of that length (Marins' effects).
  const auto v = iris();
  const auto model = energy::marinsModel(v);
  const auto pr = rectangle();
  PlannerSettings ps;
  ps.per_cell = false;
  const auto r = planCoverage(pr, v, model, ps);
  const double approach = std::sqrt(50.0);  // home (-5, -5) to the corner (0, 0)
  const double swath = 252.0 * 118.0 / pr.spacing - pr.footprint;
  const double per_metre = model.minEnergyPerMetre(16.0) * (swath + 2.0 * approach);
  RouteScorer scorer(model, SpeedSettings::fromVehicle(v));
  const double rest_to_rest = scorer.legEnergy(swath + 2.0 * approach, 0.0, 0.0, 16.0);
  // At least the kinetic energy of reaching 10 m/s and braking from it (the best cruise over 1.3 km
  // is near 14.6 m/s), on top of the per-metre part.
  EXPECT_GT(rest_to_rest, per_metre + model.effect("kinetic").coefficient("effective_mass") * 10.0 * 10.0);
  EXPECT_NEAR(r.lower_bound_j, rest_to_rest, 1e-6 * rest_to_rest);
  EXPECT_LT(r.lower_bound_j, r.plan.flown.energy);
  // With an effect whose power depends on more than speed (here a climb term) only the per-metre
  // part is claimed.
  auto climb = model;
  climb.add(energy::ClimbEffect(0.0, 0.0));
  const auto rc = planCoverage(pr, v, climb, ps);
  EXPECT_NEAR(rc.lower_bound_j, per_metre, 1e-6 * per_metre);
}

TEST(Planner, CornerStrategiesKeepCoverage) {
  const auto v = iris();
  const auto pr = rectangle();
  for (auto cs : {CornerStrategy::Sharp, CornerStrategy::Rounded}) {
    PlannerSettings ps;
    ps.corners = cs;
    const auto r = planCoverage(pr, v, energy::marinsModel(v), ps);
    expectValid(pr, r);
  }
}

TEST(Planner, SeededRandomAreasWithHolesAreValid) {
  const auto v = iris();
  const auto model = energy::marinsModel(v);
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 4; ++trial) {
    SurveyProblem pr;
    // A star-shaped outer ring of 7-10 vertices around (200, 200), radius 120-200 m.
    const int nv = 7 + trial % 4;
    for (int i = 0; i < nv; ++i) {
      const double a = 2.0 * M_PI * (i + 0.3 * u(rng)) / nv, rad = 120.0 + 80.0 * u(rng);
      pr.area.outer.push_back({200 + rad * std::cos(a), 200 + rad * std::sin(a)});
    }
    // One hole and one no-fly zone inside, small squares away from each other.
    const double h = 10.0 + 10.0 * u(rng);
    pr.area.holes.push_back({{150 - h, 170 - h}, {150 - h, 170 + h}, {150 + h, 170 + h}, {150 + h, 170 - h}});
    pr.no_fly.push_back({{250, 230}, {275, 235}, {262, 262}});
    pr.spacing = 20.0;
    pr.footprint = 22.0;
    pr.home = {200, 20};
    PlannerSettings ps;
    ps.coarse_step_deg = 30.0;
    ps.fine_step_deg = 5.0;
    const auto r = planCoverage(pr, v, model, ps);
    SCOPED_TRACE("trial " + std::to_string(trial));
    expectValid(pr, r);
  }
}

TEST(Planner, PerCellSearchSweepsEachArmOfAnLAlongItself) {
  // An L of two long arms, 400 m x 80 m along east and 80 m x 400 m along north: one sweep angle
  // for both flies one of the arms across, in many 80 m lines; per cell, each arm along its length.
  const auto v = iris();
  const auto model = energy::marinsModel(v);
  const SurveyProblem pr = lShape();
  // Straight parallel lines only (spirals off, as photogrammetry often asks): a spiral around the
  // L is cheaper still (see SpiralCompetesPerCellOnTheL), but here the arms' own angles are what
  // the per-cell search must find.
  PlannerSettings one, per;
  one.per_cell = false;
  one.spirals = per.spirals = false;
  const auto r1 = planCoverage(pr, v, model, one);
  const auto r = planCoverage(pr, v, model, per);
  expectValid(pr, r);
  expectValid(pr, r1);
  EXPECT_TRUE(r1.plan.cell_plans.empty());
  // The per-cell plan wins here, with the arms swept near 0 deg and near 90 deg.
  ASSERT_GE(r.plan.cell_plans.size(), 2u);
  EXPECT_LT(r.plan.flown.energy, r1.plan.flown.energy);
  double one_angle = std::numeric_limits<double>::infinity();
  for (const auto& a : r1.sweep_scan) one_angle = std::min(one_angle, a.energy_j);
  EXPECT_LT(r.plan.flown.energy, 0.8 * one_angle) << r.plan.flown.energy << " vs " << one_angle;
  bool along_east = false, along_north = false;
  double cell_area = 0.0;
  for (const auto& c : r.plan.cell_plans) {
    cell_area += c.area_m2;
    EXPECT_GT(c.energy_j, 0.0);
    if (c.pattern != "boustrophedon") continue;
    along_east |= c.sweep_angle_deg < 10.0 || c.sweep_angle_deg > 170.0;
    along_north |= std::abs(c.sweep_angle_deg - 90.0) < 10.0;
  }
  EXPECT_TRUE(along_east && along_north);
  EXPECT_NEAR(cell_area, geometry::area(pr.area), 1e-6 * geometry::area(pr.area));  // the cells tile the area
}

TEST(Planner, SpiralCompetesPerCellOnTheL) {
  // The same L with spirals allowed: the per-cell search and the whole-area spiral compete, and the
  // plan is never dearer than the per-cell plan, the whole-area spiral or the straight-lines-only
  // plan. (Until issue 22 a spiral won here; since the lines end on the boundary and turn inside
  // on arcs, sweeping the arms along their lengths is cheaper.)
  const auto v = iris();
  const auto model = energy::marinsModel(v);
  const SurveyProblem pr = lShape();
  const auto r = planCoverage(pr, v, model);
  PlannerSettings lines;
  lines.spirals = false;
  const auto r_lines = planCoverage(pr, v, model, lines);
  expectValid(pr, r);
  ASSERT_TRUE(r.per_cell.has_value());
  EXPECT_LE(r.plan.flown.energy, r.per_cell->flown.energy + 1e-6);
  ASSERT_TRUE(r.best_spiral.has_value());
  EXPECT_LE(r.plan.flown.energy, r.best_spiral->flown.energy + 1e-6);
  EXPECT_LE(r.plan.flown.energy, r_lines.plan.flown.energy + 1e-6);
  EXPECT_FALSE(r_lines.best_spiral.has_value());
  EXPECT_NE(r_lines.plan.pattern, "spiral");
}

TEST(Planner, SweepScanHasEveryAngleSearched) {
  const auto v = iris();
  const auto pr = rectangle();
  PlannerSettings ps;
  ps.per_cell = false;
  ps.spirals = false;  // the scan is of boustrophedon angles (a whole-area spiral wins this rectangle)
  const auto r = planCoverage(pr, v, energy::marinsModel(v), ps);
  // 18 coarse angles (10 deg) and 2 x 18 refined ones (1 deg) around the two best.
  EXPECT_EQ(r.sweep_scan.size(), 18u + 36u);
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < r.sweep_scan.size(); ++i) {
    EXPECT_GE(r.sweep_scan[i].sweep_angle_deg, 0.0);
    EXPECT_LT(r.sweep_scan[i].sweep_angle_deg, 180.0);
    if (i > 0) {
      EXPECT_GE(r.sweep_scan[i].sweep_angle_deg, r.sweep_scan[i - 1].sweep_angle_deg);
    }
    best = std::min(best, r.sweep_scan[i].energy_j);
  }
  // The scan scores routes with the widest arcs at their largest speeds only; the plan, flown with
  // arcs at chain speeds too, costs at most the best scanned angle.
  ASSERT_EQ(r.plan.pattern, "boustrophedon");
  EXPECT_LE(r.plan.flown.energy, best * (1 + 1e-9));
  EXPECT_GT(r.plan.flown.energy, 0.9 * best);
}

TEST(Planner, NeverDearerThanABaselineOnSeededRandomAreas) {
  // Random star-shaped areas of 4-15 vertices with 0-3 square holes, spacing 10-30 m, footprint up
  // to 20 % wider, each corner strategy: the plan keeps coverage, passes the checkers and costs no
  // more than any baseline. (Seeds 18, 25 and 32 once gave plans dearer than a baseline that
  // covered 99.6 % instead of 100 %.)
  const auto v = iris();
  const auto model = energy::marinsModel(v);
  for (int seed : {0, 5, 7, 11, 18, 25, 32, 41}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    SurveyProblem pr;
    const int nv = 4 + seed % 12;
    for (int i = 0; i < nv; ++i) {
      const double a = 2 * M_PI * (i + 0.4 * u(rng)) / nv, r = 80 + 150 * u(rng);
      pr.area.outer.push_back({r * std::cos(a), r * std::sin(a)});
    }
    for (int h = 0; h < seed % 4; ++h) {
      const double cx = -60 + 120 * u(rng), cy = -60 + 120 * u(rng), s = 5 + 10 * u(rng);
      pr.area.holes.push_back({{cx - s, cy - s}, {cx - s, cy + s}, {cx + s, cy + s}, {cx + s, cy - s}});
    }
    pr.spacing = 10 + 20 * u(rng);
    pr.footprint = pr.spacing * (1 + 0.2 * u(rng));
    pr.home = {-300, -300};
    PlannerSettings ps;
    ps.corners = seed % 3 == 0 ? CornerStrategy::Sharp : seed % 3 == 1 ? CornerStrategy::Rounded : CornerStrategy::Auto;
    SCOPED_TRACE("seed " + std::to_string(seed));
    expectValid(pr, planCoverage(pr, v, model, ps));
  }
}

TEST(Planner, BadInputGivesClearErrors) {
  const auto v = iris();
  auto pr = rectangle();
  pr.spacing = -1;
  try {
    planCoverage(pr, v, energy::marinsModel(v));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("spacing"), std::string::npos);
  }
  pr = rectangle();
  pr.no_fly.push_back({{-10, -10}, {0, -10}, {0, 0}, {-10, 0}});  // home inside
  EXPECT_THROW(planCoverage(pr, v, energy::marinsModel(v)), std::invalid_argument);
  EXPECT_THROW(cornerStrategyFromString("smooth"), std::invalid_argument);
}
