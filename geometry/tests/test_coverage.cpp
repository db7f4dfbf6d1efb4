// Coverage geometry: swath spacing, corners, boustrophedon and spiral candidates, and the checkers.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry_fixtures.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/coverage.hpp"
#include "wattswath/geometry/route.hpp"
#include "wattswath/geometry/swath.hpp"

namespace g = wattswath::geometry;
using wattswath::test::randomArea;
using wattswath::test::rectangle;
using wattswath::test::reversed;

namespace {

constexpr double kDeg = M_PI / 180.0;
// Issue 4 asked every candidate to cover >= 99 % outside the holes; since issue 22 a sweep line ends
// on the boundary (no flown point outside the area), so at a sweep angle oblique to an edge the
// wedges between one line's end and the next line's are left: 96.3 % is the worst of these tests.
// The planner chooses angles and line counts that keep 99 % (test_planner_coverage).
constexpr double kMinCoverage = 0.96;

/// Every path is valid, stays inside the area and out of its holes, and together they cover the
/// area; returns the covered fraction.
double expectValid(const g::PolygonWithHoles& area, const std::vector<g::CoveragePath>& paths, double spacing,
                   const std::string& what) {
  for (const auto& p : paths) {
    const auto problems = g::checkPath(p, area);
    EXPECT_TRUE(problems.empty()) << what << " cell " << p.cell << ": " << (problems.empty() ? "" : problems.front());
    const auto inside = g::checkContainment(area, p, false);
    EXPECT_LE(inside.outside_m, 0.0) << what << " cell " << p.cell << ": outside the area, " << inside.max_depth_m << " m deep";
    EXPECT_LE(inside.in_holes_m, 0.0) << what << " cell " << p.cell << ": in a hole";
  }
  const auto report = g::checkCoverage(area, paths, spacing);
  EXPECT_GE(report.fraction(), kMinCoverage) << what;
  return report.fraction();
}

g::PolygonWithHoles squareWithHole() {
  g::PolygonWithHoles a;
  a.outer = rectangle(0, 0, 200, 150);
  a.holes.push_back(reversed(rectangle(70, 50, 50, 40)));
  return a;
}

}  // namespace

TEST(SwathSpacing, ESpiralCameraGivesAbout21_45m) {
  g::CameraSettings c;
  c.altitude = 10.0;
  c.fov = 100.0 * kDeg;
  c.side_overlap = 0.10;
  // Issue 4 / data README: 10 m, 100 deg, 10 % -> about 21.45 m between passes.
  EXPECT_NEAR(g::swathSpacing(c), 21.45, 0.01);
  EXPECT_NEAR(g::footprintWidth(c), 23.835, 0.001);
}

TEST(SwathSpacing, SensorAndFocalLength) {
  g::CameraSettings c;
  c.altitude = 50.0;
  c.sensor_width = 0.0132;
  c.focal_length = 0.0088;
  c.side_overlap = 0.2;
  EXPECT_NEAR(g::footprintWidth(c), 75.0, 1e-9);
  EXPECT_NEAR(g::swathSpacing(c), 60.0, 1e-9);
}

TEST(SwathSpacing, RejectsBadSettings) {
  g::CameraSettings c;
  c.fov = 100.0 * kDeg;
  c.side_overlap = 1.0;
  EXPECT_THROW(g::swathSpacing(c), std::invalid_argument);
  c.side_overlap = 0.1;
  c.altitude = -1.0;
  EXPECT_THROW(g::swathSpacing(c), std::invalid_argument);
  c.altitude = 10.0;
  c.fov = 0.0;
  EXPECT_THROW(g::swathSpacing(c), std::invalid_argument);  // neither fov nor sensor
}

TEST(Corners, SharpCornersTurnInPlace) {
  g::Route r;
  r.points = {{0, 0}, {100, 0}, {100, 50}, {0, 50}};
  r.roles = {g::LegRole::Sweep, g::LegRole::Turn, g::LegRole::Sweep};
  const auto p = g::shapeCorners(r, {});
  ASSERT_EQ(p.legs.size(), 5u);
  EXPECT_EQ(p.legs[1].kind, g::PrimitiveKind::TurnInPlace);
  EXPECT_NEAR(p.legs[1].turn_angle, M_PI / 2, 1e-12);
  EXPECT_EQ(p.turnCount(), 2);
  EXPECT_NEAR(p.length(), 250.0, 1e-9);
  EXPECT_TRUE(g::checkPath(p, {}).empty());
}

TEST(Corners, RoundedCornersShortenLegsByTheTangentLength) {
  g::Route r;
  r.points = {{0, 0}, {100, 0}, {100, 50}, {0, 50}};
  r.roles = {g::LegRole::Sweep, g::LegRole::Turn, g::LegRole::Sweep};
  g::CornerSettings c;
  c.style = g::CornerStyle::Rounded;
  c.radius = 4.4 / 2.1;  // v / omega_max
  const auto p = g::shapeCorners(r, c);
  ASSERT_EQ(p.legs.size(), 5u);
  EXPECT_EQ(p.legs[1].kind, g::PrimitiveKind::Arc);
  EXPECT_NEAR(p.legs[0].length(), 100.0 - c.radius, 1e-9);
  EXPECT_NEAR(p.legs[2].length(), 50.0 - 2 * c.radius, 1e-9);
  EXPECT_NEAR(p.length(), 250.0 - 4 * c.radius + 2 * (M_PI / 2) * c.radius, 1e-9);
  EXPECT_TRUE(g::checkPath(p, {}).empty());
}

TEST(Corners, RadiusShrinksOnShortSegmentsAndReversalsStaySharp) {
  g::Route r;
  r.points = {{0, 0}, {100, 0}, {100, 4}, {0, 4}, {50, 4}};
  r.roles.assign(4, g::LegRole::Sweep);
  g::CornerSettings c;
  c.style = g::CornerStyle::Rounded;
  c.radius = 10.0;
  const auto p = g::shapeCorners(r, c);
  EXPECT_TRUE(g::checkPath(p, {}).empty());
  int arcs = 0, spins = 0;
  for (const auto& l : p.legs) {
    if (l.kind == g::PrimitiveKind::Arc) {
      ++arcs;
      EXPECT_NEAR(l.radius, 2.0, 1e-9);  // half of the 4 m segment at each end
    }
    if (l.kind == g::PrimitiveKind::TurnInPlace) ++spins;
  }
  EXPECT_EQ(arcs, 2);
  EXPECT_EQ(spins, 1);  // the 180 deg reversal
}

TEST(Corners, MismatchedRolesThrow) {
  g::Route r;
  r.points = {{0, 0}, {1, 0}};
  EXPECT_THROW(g::shapeCorners(r, {}), std::invalid_argument);
}

TEST(PathChecker, ReportsGapsHeadingJumpsAndHoleEntries) {
  g::PolygonWithHoles area = squareWithHole();
  g::Route r;
  r.points = {{10, 70}, {190, 70}};  // straight through the hole
  r.roles = {g::LegRole::Sweep};
  auto p = g::shapeCorners(r, {});
  auto problems = g::checkPath(p, area);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("enters a hole"), std::string::npos);
  r.points = {{10, 50}, {190, 50}};  // along the hole's edge: allowed
  EXPECT_TRUE(g::checkPath(g::shapeCorners(r, {}), area).empty());
  p.legs.push_back(p.legs[0]);  // same leg again: a gap back to the start
  problems = g::checkPath(p, {});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("gap"), std::string::npos);
  p.legs.pop_back();
  g::PathLeg turn = p.legs[0];
  turn.kind = g::PrimitiveKind::Line;
  turn.start = p.legs[0].end;
  turn.end = turn.start + g::Point(0, 10);
  turn.heading_start = turn.heading_end = M_PI / 2;
  p.legs.push_back(turn);
  problems = g::checkPath(p, {});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("heading jumps"), std::string::npos);
}

TEST(PathChecker, SafeRouteGoesAroundHoles) {
  const auto area = squareWithHole();
  const auto route = g::safeRoute(area, {10, 70}, {190, 70});
  ASSERT_GE(route.size(), 3u);
  for (size_t i = 1; i < route.size(); ++i) EXPECT_FALSE(g::segmentEntersHole(area, route[i - 1], route[i]));
  double len = 0;
  for (size_t i = 1; i < route.size(); ++i) len += (route[i] - route[i - 1]).norm();
  EXPECT_NEAR(len, std::hypot(60, 20) + 50 + std::hypot(70, 20), 1e-6);  // over the bottom corners
}

TEST(CoverageChecker, CountsOnlyTheAreaOutsideHoles) {
  const auto area = squareWithHole();
  g::Route r;
  r.points = {{0, 10}, {200, 10}};
  r.roles = {g::LegRole::Sweep};
  const auto report = g::checkCoverage(area, {g::shapeCorners(r, {})}, 20.0);
  EXPECT_NEAR(report.required_area, 200 * 150 - 50 * 40, 1e-6);
  EXPECT_NEAR(report.covered_area, 200 * 20, 1e-6);
}

TEST(CoverageChecker, RefusesANonSimpleAreaInEveryBuild) {
  // CGAL checks simplicity only as a precondition, compiled out in Release: the checker must say so
  // itself rather than return the "area" of a repeated vertex or a bow-tie.
  g::Route r;
  r.points = {{0, 10}, {200, 10}};
  r.roles = {g::LegRole::Sweep};
  const auto path = g::shapeCorners(r, {});
  g::PolygonWithHoles repeated;
  repeated.outer = {{0, 0}, {200, 0}, {200, 0}, {200, 150}, {0, 150}};
  EXPECT_THROW(g::checkCoverage(repeated, {path}, 20.0), std::invalid_argument);
  g::PolygonWithHoles bow_tie;
  bow_tie.outer = {{0, 0}, {200, 150}, {200, 0}, {0, 150}};
  EXPECT_THROW(g::checkCoverage(bow_tie, {path}, 20.0), std::invalid_argument);
  auto bad_hole = squareWithHole();
  bad_hole.holes.front().push_back(bad_hole.holes.front().back());
  EXPECT_THROW(g::checkCoverage(bad_hole, {path}, 20.0), std::invalid_argument);
}

TEST(Boustrophedon, RectangleIsOneCellAtEverySweepAngle) {
  g::PolygonWithHoles area;
  area.outer = rectangle(0, 0, 252, 118);
  for (int deg = 0; deg <= 180; deg += 15) {
    g::BoustrophedonSettings s;
    s.spacing = 21.45;
    s.sweep_angle = deg * kDeg;
    const auto paths = g::boustrophedonPaths(area, s, {});
    ASSERT_EQ(paths.size(), 1u) << deg;
    expectValid(area, paths, s.spacing, "rectangle at " + std::to_string(deg) + " deg");
  }
}

TEST(Boustrophedon, LinesRunAlongTheSweepAngleAndAlternate) {
  g::PolygonWithHoles area;
  area.outer = rectangle(0, 0, 100, 60);
  g::BoustrophedonSettings s;
  s.spacing = 20.0;
  s.sweep_angle = 0.0;  // lines along east
  const auto d = g::decomposeBoustrophedon(area, s.sweep_angle);
  ASSERT_EQ(d.cells.size(), 1u);
  const auto r = g::boustrophedonRoute(area, d, 0, s);
  std::vector<double> headings;
  for (size_t i = 0; i + 1 < r.points.size(); ++i) {
    if (r.roles[i] != g::LegRole::Sweep) continue;
    const g::Point v = r.points[i + 1] - r.points[i];
    EXPECT_NEAR(v.y(), 0.0, 1e-9);
    headings.push_back(v.x());
    EXPECT_NEAR(std::abs(v.x()), 100.0, 1e-9);
  }
  ASSERT_EQ(headings.size(), 3u);  // 60 m / 20 m
  EXPECT_LT(headings[0] * headings[1], 0.0);
  EXPECT_LT(headings[1] * headings[2], 0.0);
  for (auto corner : {g::StartCorner::BottomLeft, g::StartCorner::BottomRight, g::StartCorner::TopLeft,
                      g::StartCorner::TopRight}) {
    s.start = corner;
    const auto rr = g::boustrophedonRoute(area, d, 0, s);
    EXPECT_NEAR(rr.length(), r.length(), 1e-9);
  }
}

TEST(Boustrophedon, HoleSplitsIntoCellsAndIsNeverEntered) {
  const auto area = squareWithHole();
  for (int deg = 0; deg <= 180; deg += 10) {
    g::BoustrophedonSettings s;
    s.spacing = 15.0;
    s.sweep_angle = deg * kDeg;
    const auto d = g::decomposeBoustrophedon(area, s.sweep_angle);
    EXPECT_GE(d.cells.size(), 3u) << deg;
    g::CornerSettings c;
    c.style = deg % 20 == 0 ? g::CornerStyle::Rounded : g::CornerStyle::Sharp;
    c.radius = 3.0;
    expectValid(area, g::boustrophedonPaths(area, s, c), s.spacing, "hole at " + std::to_string(deg) + " deg");
  }
}

TEST(Degenerate, CollinearRunsSliversTouchingHolesNecksAndU) {
  std::vector<std::pair<std::string, g::PolygonWithHoles>> cases;
  g::PolygonWithHoles collinear;  // many collinear vertices along every side
  for (int i = 0; i < 10; ++i) collinear.outer.push_back({i * 20.0, 0});
  for (int i = 0; i < 5; ++i) collinear.outer.push_back({200, i * 20.0});
  for (int i = 10; i > 0; --i) collinear.outer.push_back({i * 20.0, 100});
  for (int i = 5; i > 0; --i) collinear.outer.push_back({0, i * 20.0});
  cases.push_back({"collinear runs", collinear});
  g::PolygonWithHoles sliver;
  sliver.outer = {{0, 0}, {300, 0}, {300, 0.5}, {0, 40}};
  cases.push_back({"sliver", sliver});
  g::PolygonWithHoles touching;  // hole sharing part of the bottom edge, hole touching a corner point
  touching.outer = rectangle(0, 0, 200, 120);
  touching.holes.push_back(reversed(rectangle(40, 0, 30, 30)));
  touching.holes.push_back(reversed({{150, 80}, {200, 120}, {140, 100}}));
  cases.push_back({"holes touching the boundary", touching});
  g::PolygonWithHoles neck;  // two squares joined by a 3 m neck
  neck.outer = {{0, 0}, {100, 0}, {100, 48.5}, {160, 48.5}, {160, 0}, {260, 0},
                {260, 100}, {160, 100}, {160, 51.5}, {100, 51.5}, {100, 100}, {0, 100}};
  cases.push_back({"thin neck", neck});
  g::PolygonWithHoles u;
  u.outer = {{0, 0}, {150, 0}, {150, 120}, {110, 120}, {110, 30}, {40, 30}, {40, 120}, {0, 120}};
  cases.push_back({"concave U", u});
  for (const auto& [name, area] : cases) {
    for (int deg : {0, 37, 90, 135}) {
      g::BoustrophedonSettings s;
      s.spacing = 12.0;
      s.sweep_angle = deg * kDeg;
      expectValid(area, g::boustrophedonPaths(area, s, {}), s.spacing, name + " boustrophedon " + std::to_string(deg));
    }
    g::SpiralSettings sp;
    sp.spacing = 12.0;
    expectValid(area, g::spiralPaths(area, sp, {}), sp.spacing, name + " spiral");
  }
}

TEST(Spiral, RectangleLapsAreOneContinuousSpiral) {
  g::PolygonWithHoles area;
  area.outer = rectangle(0, 0, 252, 118);
  const double s = 21.45;
  const auto cells = g::decomposeSpiral(area, s);
  ASSERT_EQ(cells.size(), 1u);
  ASSERT_EQ(cells[0].laps.size(), 3u);  // offsets 10.7, 32.2, 53.6 m; half-width 59 m
  EXPECT_NEAR(cells[0].offsets[2], 2.5 * s, 1e-9);
  for (bool cw : {false, true}) {
    for (int start = 0; start < 4; ++start) {
      g::SpiralSettings sp;
      sp.spacing = s;
      sp.clockwise = cw;
      sp.start_vertex = start;
      g::CornerSettings c;
      c.style = g::CornerStyle::Rounded;
      c.radius = 4.4 / 2.1;
      const auto paths = g::spiralPaths(area, sp, c);
      ASSERT_EQ(paths.size(), 1u);
      EXPECT_GE(paths[0].turnCount(), 10);  // 11 straights and 10 curves from a long side,
      EXPECT_LE(paths[0].turnCount(), 11);  // one more of each from a short side
      expectValid(area, paths, s, "rectangle spiral");
    }
  }
}

TEST(Spiral, TracedOutlineIsSimplifiedBeforeTheSkeleton) {
  // A field edge traced with 512 vertices (a wavy disc, 500 m across): the laps follow an outline
  // simplified to 2 % of the spacing (Douglas-Peucker), not every trace point, and still cover it.
  g::PolygonWithHoles area;
  for (int i = 0; i < 512; ++i) {
    const double t = 2 * M_PI * i / 512, r = 250 * (1 + 0.08 * std::sin(5 * t));
    area.outer.push_back({250 + r * std::cos(t), 250 + r * std::sin(t)});
  }
  const auto cells = g::decomposeSpiral(area, 30.0);
  ASSERT_EQ(cells.size(), 1u);
  for (const auto& lap : cells[0].laps) EXPECT_LT(lap.size(), 100u);  // 512 before simplification
  g::SpiralSettings sp;
  sp.spacing = 30.0;
  expectValid(area, g::spiralPaths(area, sp, {}), sp.spacing, "traced outline spiral");
}

TEST(Spiral, NeckSplitsIntoSeparateCells) {
  g::PolygonWithHoles neck;  // two 100 m squares joined by a 20 m wide, 60 m long corridor
  neck.outer = {{0, 0}, {100, 0}, {100, 40}, {160, 40}, {160, 0}, {260, 0},
                {260, 100}, {160, 100}, {160, 60}, {100, 60}, {100, 100}, {0, 100}};
  const auto cells = g::decomposeSpiral(neck, 8.0);
  EXPECT_GE(cells.size(), 3u);  // the shared outer laps, then each square
  g::SpiralSettings sp;
  sp.spacing = 8.0;
  expectValid(neck, g::spiralPaths(neck, sp, {}), sp.spacing, "neck spiral");
}

TEST(Spiral, AreaWithHoleIsCutIntoHoleFreeCells) {
  const auto area = squareWithHole();
  g::SpiralSettings sp;
  sp.spacing = 15.0;
  const auto paths = g::spiralPaths(area, sp, {});
  EXPECT_GE(paths.size(), 3u);
  expectValid(area, paths, sp.spacing, "spiral with hole");
}

TEST(RandomAreas, CheckerHoldsUnderFixedSeeds) {
  std::mt19937 rng(20240401);
  std::uniform_real_distribution<double> angle(0.0, M_PI);
  for (int k = 0; k < 12; ++k) {
    const auto area = randomArea(rng, {500.0 * k, -300.0}, 120.0, 220.0, 10 + k, k % 4);
    g::BoustrophedonSettings s;
    s.spacing = 18.0;
    s.sweep_angle = angle(rng);
    s.start = static_cast<g::StartCorner>(k % 4);
    g::CornerSettings c;
    c.style = k % 2 ? g::CornerStyle::Rounded : g::CornerStyle::Sharp;
    c.radius = 4.0;
    expectValid(area, g::boustrophedonPaths(area, s, c), s.spacing, "random boustrophedon " + std::to_string(k));
    g::SpiralSettings sp;
    sp.spacing = 18.0;
    sp.split_angle = s.sweep_angle;
    sp.start_vertex = k;
    sp.clockwise = k % 3 == 0;
    expectValid(area, g::spiralPaths(area, sp, c), sp.spacing, "random spiral " + std::to_string(k));
  }
}

TEST(JoinRoutes, TransitsAvoidHoles) {
  const auto area = squareWithHole();
  g::BoustrophedonSettings s;
  s.spacing = 15.0;
  const auto d = g::decomposeBoustrophedon(area, s.sweep_angle);
  std::vector<g::Route> routes;
  for (size_t c = 0; c < d.cells.size(); ++c) routes.push_back(g::boustrophedonRoute(area, d, static_cast<int>(c), s));
  const auto joined = g::shapeCorners(g::joinRoutes(area, routes), {});
  EXPECT_TRUE(g::checkPath(joined, area).empty());
  EXPECT_GE(g::checkCoverage(area, {joined}, s.spacing).fraction(), kMinCoverage);
}

TEST(ConvexPartition, SplitsAnLIntoTwoConvexPiecesOfTheSameArea) {
  const g::Ring l = {{0, 0}, {400, 0}, {400, 80}, {80, 80}, {80, 400}, {0, 400}};
  const auto parts = g::convexPartition(l);
  ASSERT_EQ(parts.size(), 2u);  // optimal: one cut at the reflex vertex
  double sum = 0.0;
  for (const auto& p : parts) {
    EXPECT_GT(g::signedArea(p), 0.0);  // counter-clockwise
    // Convex: every turn to the left.
    for (size_t i = 0; i < p.size(); ++i) {
      const g::Point u = p[(i + 1) % p.size()] - p[i], v = p[(i + 2) % p.size()] - p[(i + 1) % p.size()];
      EXPECT_GE(u.x() * v.y() - u.y() * v.x(), -1e-9);
    }
    sum += g::signedArea(p);
  }
  EXPECT_NEAR(sum, g::signedArea(l), 1e-9);
}

TEST(ConvexPartition, ConvexClockwiseAndCollinearInputs) {
  // A clockwise square with a collinear and a repeated vertex: one counter-clockwise piece of 4.
  const g::Ring sq = {{0, 0}, {0, 10}, {10, 10}, {10, 5}, {10, 5}, {10, 0}};
  const auto parts = g::convexPartition(sq);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].size(), 4u);
  EXPECT_NEAR(g::signedArea(parts[0]), 100.0, 1e-9);
  // A random star-shaped ring: pieces tile it.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.3, 1.0);
  g::Ring star;
  for (int i = 0; i < 30; ++i) {
    const double a = 2 * M_PI * i / 30, r = 100 * u(rng);
    star.push_back({r * std::cos(a), r * std::sin(a)});
  }
  double sum = 0.0;
  for (const auto& p : g::convexPartition(star)) sum += g::signedArea(p);  // 30 vertices: Hertel-Mehlhorn
  EXPECT_NEAR(sum, g::signedArea(star), 1e-6);
}

TEST(ConvexPartition, BadRingsGiveClearErrors) {
  auto expectThrow = [](const g::Ring& r, const std::string& needle) {
    try {
      g::convexPartition(r);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expectThrow({{0, 0}, {1, 0}, {2, 0}}, "at least 3");
  expectThrow({{0, 0}, {10, 10}, {10, 0}, {0, 10}}, "not simple");
  expectThrow({{0, 0}, {NAN, 0}, {0, 1}}, "not finite");
}

TEST(TangentWithin, ArcStaysWithinTheMarginOfItsVertex) {
  for (double turn : {0.2, 1.0, M_PI / 2, 2.5, -1.0}) {
    const double margin = 3.0;
    const double t = g::tangentWithin(turn, margin);
    const double h = 0.5 * std::abs(turn);
    const double r = t / std::tan(h);  // radius of the arc with that tangent length
    EXPECT_NEAR(r * (1.0 / std::cos(h) - 1.0), margin, 1e-9) << turn;  // vertex to arc midpoint
  }
  EXPECT_NEAR(g::tangentWithin(M_PI / 2, 1.0), 1.0 + std::sqrt(2.0), 1e-12);
  EXPECT_EQ(g::tangentWithin(0.0, 3.0), 0.0);  // straight on: no arc
  EXPECT_EQ(g::tangentWithin(1.0, 0.0), 0.0);  // no margin: a stop
}

TEST(DistanceToSegment, NearestPointOnTheSegmentOrAnEnd) {
  const g::Point a(0, 0), b(10, 0);
  EXPECT_NEAR(g::distanceToSegment({5, 3}, a, b), 3.0, 1e-12);
  EXPECT_NEAR(g::distanceToSegment({-3, 4}, a, b), 5.0, 1e-12);  // beyond a
  EXPECT_NEAR(g::distanceToSegment({13, 4}, a, b), 5.0, 1e-12);  // beyond b
  EXPECT_NEAR(g::distanceToSegment({3, 4}, a, a), 5.0, 1e-12);   // a segment without length
}

TEST(ContainmentChecker, MeasuresTheLengthOutsideAndInHolesExactly) {
  const auto area = squareWithHole();  // 200 x 150, hole [70, 120] x [50, 90]
  g::Route r;
  r.points = {{-30, 10}, {230, 10}, {230, 70}, {-10, 70}};  // 30 + 30 m out, 60 m out, 10 + 50 m
  r.roles = {g::LegRole::Sweep, g::LegRole::Sweep, g::LegRole::Sweep};
  const auto rep = g::checkContainment(area, g::shapeCorners(r, {}), false);
  EXPECT_NEAR(rep.outside_m, 30 + 30 + 60 + 30 + 10, 1e-9);
  EXPECT_NEAR(rep.in_holes_m, 50, 1e-9);
  EXPECT_NEAR(rep.max_depth_m, 30, 1e-9);
  // Along the boundary and touching the hole's corner is inside.
  g::Route along;
  along.points = {{0, 0}, {200, 0}, {200, 150}, {120, 90}, {0, 150}};
  along.roles.assign(4, g::LegRole::Sweep);
  EXPECT_EQ(g::checkContainment(area, g::shapeCorners(along, {}), false).total(), 0.0);
  // survey_only leaves out the approach from a home outside and the return.
  g::Route flight;
  flight.points = {{-50, -50}, {10, 10}, {190, 10}, {-50, -50}};
  flight.roles = {g::LegRole::Transit, g::LegRole::Sweep, g::LegRole::Transit};
  EXPECT_EQ(g::checkContainment(area, g::shapeCorners(flight, {})).total(), 0.0);
  EXPECT_GT(g::checkContainment(area, g::shapeCorners(flight, {}), false).outside_m, 100.0);
}

TEST(PathChecker, SafeRouteStaysInsideAConcaveBoundary) {
  g::PolygonWithHoles u;  // a U: the straight line between the arms' tips crosses the bay
  u.outer = {{0, 0}, {300, 0}, {300, 200}, {200, 200}, {200, 60}, {100, 60}, {100, 200}, {0, 200}};
  const auto route = g::safeRoute(u, {50, 190}, {250, 190});
  ASSERT_EQ(route.size(), 4u);  // over the bay's two reflex corners
  double len = 0;
  for (size_t i = 1; i < route.size(); ++i) {
    EXPECT_FALSE(g::segmentLeavesArea(u, route[i - 1], route[i]));
    len += (route[i] - route[i - 1]).norm();
  }
  EXPECT_NEAR(len, 2 * std::hypot(50, 130) + 100, 1e-6);
}
