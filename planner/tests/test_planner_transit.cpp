// Transits around no-fly zones: exact shortest paths that never enter an obstacle.
#include <gtest/gtest.h>

#include <random>

#include "wattswath/planner/transit.hpp"

using namespace wattswath::planner;
using wattswath::geometry::Point;
using wattswath::geometry::Ring;

namespace {
Ring square(double cx, double cy, double h) { return {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}}; }
double length(const std::vector<Point>& p) {
  double s = 0;
  for (size_t i = 0; i + 1 < p.size(); ++i) s += (p[i + 1] - p[i]).norm();
  return s;
}
}  // namespace

TEST(Transit, StraightWhenClear) {
  TransitRouter r({square(50, 50, 10)});
  const auto p = r.route({0, 0}, {100, 0});
  ASSERT_EQ(p.size(), 2u);
}

TEST(Transit, GoesAroundASquareOnTheShortestSide) {
  const double c = 1.0;
  TransitRouter r({square(0, 0, 10)}, TransitSettings{c});
  const auto p = r.route({-30, 0}, {30, 0});
  // Around two pushed-out corners (10 + c, +-(10 + c)): 2 * |(-30,0)-(-11,11)| + 22.
  const double expected = 2.0 * Point(19.0, 11.0).norm() + 22.0;
  EXPECT_NEAR(length(p), expected, 1e-9);
  for (size_t i = 0; i + 1 < p.size(); ++i) EXPECT_FALSE(segmentEntersRing(p[i], p[i + 1], square(0, 0, 10)));
}

TEST(Transit, NeverEntersRandomObstacles) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-100.0, 100.0), h(3.0, 12.0);
  std::vector<Ring> obs;
  for (int i = 0; i < 10; ++i) {
    const Ring s = square(u(rng), u(rng), h(rng));
    bool overlap = false;
    for (const auto& o : obs)
      overlap = overlap || (std::abs(o[0].x() - s[0].x()) < 30 && std::abs(o[0].y() - s[0].y()) < 30);
    if (!overlap) obs.push_back(s);
  }
  TransitRouter r(obs);
  int routed = 0;
  for (int k = 0; k < 200; ++k) {
    const Point a(u(rng) * 1.3, u(rng) * 1.3), b(u(rng) * 1.3, u(rng) * 1.3);
    if (r.blocked(a) || r.blocked(b)) {
      EXPECT_THROW(r.route(a, b), std::runtime_error);
      continue;
    }
    const auto p = r.route(a, b);
    routed += p.size() > 2;
    EXPECT_GE(length(p), (b - a).norm() - 1e-9);
    for (size_t i = 0; i + 1 < p.size(); ++i)
      for (const auto& o : obs) EXPECT_FALSE(segmentEntersRing(p[i], p[i + 1], o)) << "query " << k;
  }
  EXPECT_GT(routed, 10);
}

TEST(Transit, SegmentTestsSeeDiagonalsAndEdges) {
  const Ring s = square(0, 0, 10);
  EXPECT_TRUE(segmentEntersRing({-10, -10}, {10, 10}, s));   // the diagonal, vertex to vertex
  EXPECT_FALSE(segmentEntersRing({-10, -10}, {10, -10}, s)); // along an edge
  EXPECT_FALSE(segmentEntersRing({-20, 10}, {20, 10}, s));   // touching the top edge
  EXPECT_THROW(TransitRouter({{{0, 0}, {1, 0}}}), std::invalid_argument);
}

TEST(Transit, RouteAllMatchesPairwiseRoutes) {
  TransitRouter r({square(0, 0, 10), square(40, 5, 8), square(-30, 30, 6)});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-60.0, 60.0);
  std::vector<Point> pts;
  while (pts.size() < 25) {
    const Point p(u(rng), u(rng));
    if (!r.blocked(p)) pts.push_back(p);
  }
  const auto all = r.routeAll(pts);
  ASSERT_EQ(all.size(), pts.size() * pts.size());
  for (size_t i = 0; i < pts.size(); ++i)
    for (size_t j = i + 1; j < pts.size(); ++j)
      EXPECT_NEAR(length(all[i * pts.size() + j]), length(r.route(pts[i], pts[j])), 1e-9) << i << " " << j;
}
