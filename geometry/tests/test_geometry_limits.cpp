// Issue 20, areas at scale: thousands of holes were validated pair by pair (2,025 holes: 18 s)
// and the transit router checked every visibility edge of a wiggly boundary eagerly (a
// 2,000-vertex field planned for 8 minutes). This program runs under a 60 s watchdog.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include "ring_index.hpp"  // geometry/src: the index is internal, tested against the plain loops here
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace {

namespace geo = wattswath::geometry;
using geo::Point;

geo::Ring square(double x, double y, double side) {
  return {Point(x, y), Point(x + side, y), Point(x + side, y + side), Point(x, y + side)};
}

TEST(AreaLimits, ThousandsOfHolesAreValidatedBySweepNotPairs) {
  // 4,900 holes: every pair compared exactly was 1.2e7 CGAL polygon intersections (minutes);
  // boxes swept first leave none to compare here.
  geo::PolygonWithHoles p;
  p.outer = square(0, 0, 2000);
  for (int i = 0; i < 70; ++i)
    for (int j = 0; j < 70; ++j) p.holes.push_back(square(50 + 27.0 * i, 50 + 27.0 * j, 3));
  EXPECT_NO_THROW(geo::validatePolygon(p, "grid.geojson"));
  EXPECT_EQ(p.holes.size(), 4900u);
  // Two overlapping holes among them are still found, and named.
  p.holes.push_back(square(51, 51, 3));
  try {
    geo::validatePolygon(p, "grid.geojson");
    FAIL() << "overlapping holes accepted";
  } catch (const geo::SurveyAreaError& e) {
    EXPECT_NE(std::string(e.what()).find("grid.geojson: hole 4900: overlaps hole 0"), std::string::npos) << e.what();
  }
}

/// The shortest route by the definition: Dijkstra over every visibility edge, checked eagerly.
double shortestByDefinition(const geo::PolygonWithHoles& area, const std::vector<Point>& nodes) {
  const size_t n = nodes.size();
  auto blocked = [&](const Point& p, const Point& q) {
    return geo::segmentEntersHole(area, p, q) || geo::segmentLeavesArea(area, p, q);
  };
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<bool> done(n, false);
  dist[0] = 0.0;
  for (;;) {
    size_t u = n;
    for (size_t v = 0; v < n; ++v)
      if (!done[v] && (u == n || dist[v] < dist[u])) u = v;
    if (u == n || !std::isfinite(dist[u])) break;
    done[u] = true;
    for (size_t v = 0; v < n; ++v)
      if (!done[v] && !blocked(nodes[u], nodes[v])) dist[v] = std::min(dist[v], dist[u] + (nodes[v] - nodes[u]).norm());
  }
  return dist[1];
}

TEST(RouteLimits, TheLazyRouterFindsTheShortestRouteOnAWigglyBoundary) {
  // A 400-vertex star (every other vertex reflex) with two square holes; routes between random
  // inside points (fixed seed) against eager Dijkstra over the same nodes.
  geo::PolygonWithHoles area;
  const int N = 400;
  for (int i = 0; i < N; ++i) {
    const double r = (i % 2 ? 300.0 : 285.0), a = 2.0 * M_PI * i / N;
    area.outer.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  area.holes = {square(-80, -30, 60), square(40, 20, 50)};
  for (auto& h : area.holes) std::reverse(h.begin(), h.end());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ang(0.0, 2.0 * M_PI), rad(0.0, 270.0);
  int routed_around = 0;
  for (int k = 0; k < 30; ++k) {
    Point a, b;
    do a = Point(rad(rng) * std::cos(ang(rng)), rad(rng) * std::sin(ang(rng)));
    while (geo::insideRing(area.holes[0], a) || geo::insideRing(area.holes[1], a));
    do b = Point(rad(rng) * std::cos(ang(rng)), rad(rng) * std::sin(ang(rng)));
    while (geo::insideRing(area.holes[0], b) || geo::insideRing(area.holes[1], b));
    const auto route = geo::safeRoute(area, a, b);
    double len = 0.0;
    for (size_t i = 1; i < route.size(); ++i) {
      len += (route[i] - route[i - 1]).norm();
      EXPECT_FALSE(geo::segmentEntersHole(area, route[i - 1], route[i]));
      EXPECT_FALSE(geo::segmentLeavesArea(area, route[i - 1], route[i]));
    }
    routed_around += route.size() > 2;
    std::vector<Point> nodes{a, b};
    for (const auto& h : area.holes) nodes.insert(nodes.end(), h.begin(), h.end());
    for (size_t i = 0; i < area.outer.size(); ++i) {
      const Point& p = area.outer[(i + area.outer.size() - 1) % area.outer.size()];
      const Point& q = area.outer[i];
      const Point& r = area.outer[(i + 1) % area.outer.size()];
      if ((q - p).x() * (r - q).y() - (q - p).y() * (r - q).x() < 0.0) nodes.push_back(q);
    }
    EXPECT_NEAR(len, shortestByDefinition(area, nodes), 1e-6) << "route " << k;
  }
  EXPECT_GE(routed_around, 8);  // most pairs need to go around a hole or the star's points
}

TEST(RouteLimits, TheRingIndexAnswersAsThePlainLoops) {
  // The R-tree of a large ring's edges (ring_index.hpp) must give the plain loops' answers: inside,
  // near, and whether a segment leaves the ring. A wiggly 3,000-vertex ring, random points and
  // segments (fixed seed), many on or near the boundary.
  geo::PolygonWithHoles area;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  const int N = 3000;
  for (int i = 0; i < N; ++i) {
    const double a = 2.0 * M_PI * i / N, r = 300.0 + 20.0 * std::sin(7.0 * a) + 3.0 * std::sin(97.0 * a) + 1.5 * jitter(rng);
    area.outer.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  const geo::detail::RingIndex index(area.outer);
  std::uniform_real_distribution<double> coord(-340.0, 340.0), pick(0.0, N - 1.0), off(-2.0, 2.0);
  auto randomPoint = [&](int k) {
    if (k % 3) return Point(coord(rng), coord(rng));
    const Point& v = area.outer[static_cast<size_t>(pick(rng))];  // near a vertex: the hard cases
    return Point(v.x() + off(rng), v.y() + off(rng));
  };
  int inside = 0, near = 0, leaves = 0;
  for (int k = 0; k < 3000; ++k) {
    const Point p = randomPoint(k), q = randomPoint(k + 1);
    ASSERT_EQ(index.inside(p), geo::insideRing(area.outer, p)) << p.transpose();
    ASSERT_EQ(index.near(p, 1.0), geo::distanceToRing(area.outer, p) <= 1.0) << p.transpose();
    ASSERT_EQ(geo::detail::segmentLeavesRing(index, p, q), geo::segmentLeavesArea(area, p, q))
        << p.transpose() << " -> " << q.transpose();
    inside += index.inside(p);
    near += index.near(p, 1.0);
    leaves += geo::segmentLeavesArea(area, p, q);
  }
  // Every kind of answer occurred.
  EXPECT_GT(inside, 300);
  EXPECT_GT(near, 100);
  EXPECT_GT(leaves, 300);
  EXPECT_GT(3000 - leaves, 300);
}

}  // namespace

TEST(RouteLimits, TheHoleIndexAnswersAsThePlainLoopAndRoutesAroundHundredsOfHoles) {
  // 400 holes (a jittered 20 x 20 grid of rotated 12 m squares, fixed seed) in a 1 km field: the
  // holes' R-tree (ring_index.hpp) must say whether a segment enters a hole exactly as the plain
  // loop over every hole does (segments at random and grazing hole corners), and a route across
  // the field must go around every hole.
  geo::PolygonWithHoles area;
  area.outer = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> jitter(-8.0, 8.0), rot(0.0, M_PI / 2);
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      const Point c(50.0 + 47.0 * i + jitter(rng), 50.0 + 47.0 * j + jitter(rng));
      const double r = rot(rng);
      geo::Ring h;
      for (int k = 0; k < 4; ++k) {
        const double t = r - 0.5 * M_PI * k;  // clockwise, as holes are stored
        h.push_back(c + 8.5 * Point(std::cos(t), std::sin(t)));
      }
      area.holes.push_back(h);
    }
  }
  const geo::detail::HoleIndex index(area.holes);
  std::uniform_real_distribution<double> coord(0.0, 1000.0), off(-0.5, 0.5), len(-60.0, 60.0);
  int entered = 0;
  for (int k = 0; k < 4000; ++k) {
    Point a(coord(rng), coord(rng));
    if (k % 2) {  // from near a hole corner: the hard cases
      const auto& h = area.holes[static_cast<size_t>(k) % area.holes.size()];
      a = h[static_cast<size_t>(k / 2) % 4] + Point(off(rng), off(rng));
    }
    const Point b = a + Point(len(rng), len(rng));
    const bool plain = geo::segmentEntersHole(area, a, b);
    ASSERT_EQ(index.segmentEnters(a, b), plain) << "segment " << k << ": (" << a.transpose() << ") -> (" << b.transpose() << ")";
    entered += plain;
  }
  EXPECT_GT(entered, 400);  // the test exercises both answers
  EXPECT_LT(entered, 3600);
  const auto route = geo::safeRoute(area, Point(5, 5), Point(995, 995));
  ASSERT_GE(route.size(), 3u);
  for (size_t i = 1; i < route.size(); ++i) EXPECT_FALSE(geo::segmentEntersHole(area, route[i - 1], route[i]));
}
