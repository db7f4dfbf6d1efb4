// Keeping clear: rings inflated by a margin (every point within the margin inside, nothing much
// farther), areas minus rings, and the margin checker's exact distances for lines, arcs and points.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry_fixtures.hpp"
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/clearance.hpp"

using namespace wattswath::geometry;
using wattswath::test::rectangle;

namespace {

PathLeg line(Point a, Point b) {
  PathLeg l;
  l.start = a;
  l.end = b;
  return l;
}

/// The arc around `c` of radius `r` from angle `a0` [rad] turning by `turn` [rad] (CCW > 0).
PathLeg arc(Point c, double r, double a0, double turn) {
  PathLeg l;
  l.kind = PrimitiveKind::Arc;
  l.center = c;
  l.radius = r;
  l.turn_angle = turn;
  l.start = c + r * Point(std::cos(a0), std::sin(a0));
  l.end = c + r * Point(std::cos(a0 + turn), std::sin(a0 + turn));
  return l;
}

CoveragePath pathOf(const std::vector<PathLeg>& legs) {
  CoveragePath p;
  p.legs = legs;
  return p;
}

/// Distance from `p` to the boundary of `ring` [m].
double toBoundary(const Ring& ring, const Point& p) {
  double d = 1e300;
  for (size_t i = 0; i < ring.size(); ++i) d = std::min(d, distanceToSegment(p, ring[i], ring[(i + 1) % ring.size()]));
  return d;
}

}  // namespace

TEST(Clearance, InflatedSquareHoldsTheMarginAndLittleMore) {
  const Ring square = rectangle(0, 0, 10, 10);
  const auto grown = inflateRings({square}, 2.0);
  ASSERT_EQ(grown.size(), 1u);
  EXPECT_GT(signedArea(grown[0]), 0.0);  // counter-clockwise
  // Every point within 2 m of the square is inside (points at 1.999 m all round it).
  for (int k = 0; k < 360; ++k) {
    const double t = 2.0 * M_PI * k / 360.0;
    const Point dir(std::cos(t), std::sin(t));
    const Point corner(dir.x() >= 0 ? 10 : 0, dir.y() >= 0 ? 10 : 0);
    EXPECT_TRUE(insideRing(grown[0], corner + 1.999 * dir)) << k;
    EXPECT_TRUE(insideRing(grown[0], Point(5, 5) + Point(dir.x() > 0 ? 6.999 : -6.999, 0)));
  }
  // No vertex farther than 2 / cos(pi / 16) from the square, none nearer than 2.
  for (const auto& v : grown[0]) {
    EXPECT_GE(toBoundary(square, v), 2.0 - 1e-9);
    EXPECT_LE(toBoundary(square, v), 2.0 / std::cos(M_PI / kInflateSides) + 1e-9);
  }
  // Square + four 2 m strips + a 16-gon of inradius 2 (16 * 4 * tan(pi / 16)).
  EXPECT_NEAR(signedArea(grown[0]), 100.0 + 80.0 + 64.0 * std::tan(M_PI / 16.0), 1e-6);
}

TEST(Clearance, OverlappingInflatedRingsMergeAndBadInputIsRefused) {
  const auto two = inflateRings({rectangle(0, 0, 10, 10), rectangle(13, 0, 10, 10)}, 2.0);
  EXPECT_EQ(two.size(), 1u);  // 3 m apart, each grown by 2 m
  EXPECT_EQ(inflateRings({rectangle(0, 0, 10, 10), rectangle(15, 0, 10, 10)}, 2.0).size(), 2u);
  EXPECT_THROW(inflateRings({rectangle(0, 0, 10, 10)}, 0.0), std::invalid_argument);
  const Ring bowtie = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  try {
    inflateRings({rectangle(0, 0, 1, 1), bowtie}, 1.0);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ring 1"), std::string::npos) << e.what();
  }
}

TEST(Clearance, SubtractingRingsNotchesTheBoundaryOrMakesHoles) {
  const Ring area = rectangle(0, 0, 100, 100);
  const auto notched = subtractRings(area, {rectangle(90, 40, 20, 20)});  // crosses the east edge
  ASSERT_EQ(notched.size(), 1u);
  EXPECT_TRUE(notched[0].holes.empty());
  EXPECT_NEAR(wattswath::geometry::area(notched[0]), 10000.0 - 200.0, 1e-9);
  const auto holed = subtractRings(area, {rectangle(40, 40, 10, 10), rectangle(45, 45, 10, 10)});  // overlapping
  ASSERT_EQ(holed.size(), 1u);
  ASSERT_EQ(holed[0].holes.size(), 1u);
  EXPECT_NEAR(wattswath::geometry::area(holed[0]), 10000.0 - 175.0, 1e-9);
  EXPECT_EQ(subtractRings(area, {rectangle(49, -10, 2, 120)}).size(), 2u);  // cut in two
}

TEST(Clearance, DistancesOfLinesArcsAndPointsAreExact) {
  const Ring box = rectangle(12, -1, 2, 2);
  EXPECT_NEAR(distanceToRing(line({0, 4}, {20, 4}), box), 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(distanceToRing(line({0, 0}, {20, 0}), box), 0.0);  // crosses
  PathLeg here = line({10, 0}, {10, 0});
  here.kind = PrimitiveKind::TurnInPlace;
  EXPECT_NEAR(distanceToRing(here, box), 2.0, 1e-12);
  // Quarter arc of radius 10 from east to north: nearest to the box at its start.
  const PathLeg quarter = arc({0, 0}, 10, 0.0, M_PI / 2);
  EXPECT_NEAR(distanceToRing(quarter, box), 2.0, 1e-12);
  // An edge across the 45 deg radial at radius 12: the arc's middle is 2 m from it.
  const Point u(std::cos(M_PI / 4), std::sin(M_PI / 4)), n(-u.y(), u.x());
  const Ring wedge = {12.0 * u - 3.0 * n, 20.0 * u, 12.0 * u + 3.0 * n};
  EXPECT_NEAR(distanceToRing(quarter, wedge), 2.0, 1e-12);
  // The same arc flown clockwise (north to east), and an arc that crosses the edge.
  EXPECT_NEAR(distanceToRing(arc({0, 0}, 10, M_PI / 2, -M_PI / 2), wedge), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(distanceToRing(arc({0, 0}, 13, 0.0, M_PI / 2), wedge), 0.0);
  // The other half of the circle is far from the wedge: the radial through the foot is off the arc.
  EXPECT_NEAR(distanceToRing(arc({0, 0}, 10, M_PI, M_PI / 2), wedge), (Point(-10, 0) - (12.0 * u + 3.0 * n)).norm(),
              1e-12);
}

TEST(Clearance, MarginViolationsNameTheLegTheZoneAndTheDistance) {
  const auto path = pathOf({line({0, 5}, {30, 5}), arc({30, 10}, 5, -M_PI / 2, M_PI), line({30, 15}, {0, 15})});
  const std::vector<Ring> zones = {rectangle(10, 7, 5, 6), rectangle(36, 8, 4, 4), rectangle(100, 100, 1, 1)};
  const auto v = marginViolations(path, zones, 2.5);
  // Line 0 is 2 m below zone 0, the arc 1 m from zone 1, line 2 is 2 m above zone 0.
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].leg, 0);
  EXPECT_EQ(v[0].zone, 0);
  EXPECT_NEAR(v[0].distance_m, 2.0, 1e-12);
  EXPECT_EQ(v[1].leg, 1);
  EXPECT_EQ(v[1].zone, 1);
  EXPECT_NEAR(v[1].distance_m, 1.0, 1e-12);
  EXPECT_EQ(v[2].leg, 2);
  EXPECT_TRUE(marginViolations(path, zones, 1.0).empty());
  // A leg wholly inside a zone is at distance 0.
  const auto inside = marginViolations(pathOf({line({11, 9}, {12, 9})}), zones, 0.5);
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_DOUBLE_EQ(inside[0].distance_m, 0.0);
}

TEST(Clearance, FenceViolationsAreLegsOutsideOrTooNearTheEdge) {
  const auto path = pathOf({line({5, 5}, {95, 5}), line({95, 5}, {95, 99}), line({95, 99}, {120, 99})});
  const Ring fence = rectangle(0, 0, 100, 100);
  const auto v = fenceViolations(path, fence, 2.0);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].leg, 1);
  EXPECT_NEAR(v[0].distance_m, 1.0, 1e-12);
  EXPECT_EQ(v[1].leg, 2);
  EXPECT_DOUBLE_EQ(v[1].distance_m, 0.0);  // leaves the fence
  EXPECT_TRUE(fenceViolations(pathOf({line({5, 5}, {95, 5})}), fence, 4.9).empty());
}
