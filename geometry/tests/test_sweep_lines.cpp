// Sweep lines over an area with obstacles, their cells and the zigzag passes over a cell.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry_fixtures.hpp"
#include "wattswath/geometry/sweep_lines.hpp"

namespace g = wattswath::geometry;
using wattswath::test::rectangle;
using wattswath::test::reversed;

namespace {

constexpr double kTol = 1e-9;

// Lines 10 m apart with a 10 m footprint, 2 m from obstacles, 5 m run-out beyond the boundary.
g::SweepLineSettings settings() { return {10.0, 2.0, 5.0}; }

TEST(SweepLines, RectangleHasEvenlySpacedLinesCentredWithRunOut) {
  const auto lines = g::sweepLines(rectangle(0, 0, 100, 50), {}, 0.0, settings());
  ASSERT_EQ(lines.lines.size(), 5u);          // 50 m across at 10 m
  EXPECT_NEAR(lines.first_y, 5.0, kTol);      // half a spacing in from the edge
  for (const auto& line : lines.lines) {
    ASSERT_EQ(line.size(), 1u);
    EXPECT_NEAR(line[0].x0, 0.0, kTol);
    EXPECT_NEAR(line[0].x1, 100.0, kTol);
    EXPECT_NEAR(line[0].ext0, 5.0, kTol);     // run-out at the outer boundary
    EXPECT_NEAR(line[0].ext1, 5.0, kTol);
  }
}

TEST(SweepLines, ObstacleSplitsLinesWithClearanceAndNoRunOutInside) {
  const g::Ring hole = reversed(rectangle(40, 20, 20, 10));  // covers y in (20, 30): the line at y = 25
  const auto lines = g::sweepLines(rectangle(0, 0, 100, 50), {hole}, 0.0, settings());
  ASSERT_EQ(lines.lines.size(), 5u);
  const auto& split = lines.lines[2];
  ASSERT_EQ(split.size(), 2u);
  EXPECT_NEAR(split[0].x1, 38.0, kTol);  // 40 - clearance
  EXPECT_NEAR(split[1].x0, 62.0, kTol);  // 60 + clearance
  EXPECT_NEAR(split[0].ext1, 0.0, kTol);
  EXPECT_NEAR(split[1].ext0, 0.0, kTol);
  EXPECT_NEAR(split[0].ext0, 5.0, kTol);
  EXPECT_NEAR(split[1].ext1, 5.0, kTol);
}

TEST(SweepLines, CellsFollowTheLinesConnectivity) {
  const auto plain = g::sweepLines(rectangle(0, 0, 100, 50), {}, 0.0, settings());
  const auto one = g::sweepLineCells(plain.lines);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].first_line, 0);
  EXPECT_EQ(one[0].rows.size(), 5u);
  // A hole on the middle line: below, left, right and above it are four cells.
  const auto holed = g::sweepLines(rectangle(0, 0, 100, 50), {reversed(rectangle(40, 20, 20, 10))}, 0.0, settings());
  const auto four = g::sweepLineCells(holed.lines);
  ASSERT_EQ(four.size(), 4u);
  EXPECT_EQ(four[0].rows.size(), 2u);
  EXPECT_EQ(four[1].rows.size(), 1u);
  EXPECT_EQ(four[2].rows.size(), 1u);
  EXPECT_EQ(four[3].first_line, 3);
}

TEST(SweepLines, PassesZigzagFromTheChosenCorner) {
  const auto lines = g::sweepLines(rectangle(0, 0, 100, 50), {}, 0.0, settings());
  const auto cell = g::sweepLineCells(lines.lines).front();
  const auto up = g::sweepPasses(cell, 0.0, lines.first_y, 10.0, false, false);
  ASSERT_EQ(up.size(), 5u);
  EXPECT_NEAR((up[0].start - g::Point(-5, 5)).norm(), 0.0, kTol);
  EXPECT_NEAR((up[0].end - g::Point(105, 5)).norm(), 0.0, kTol);
  EXPECT_NEAR((up[1].start - g::Point(105, 15)).norm(), 0.0, kTol);  // back the other way
  EXPECT_NEAR(up[0].start_run_out, 5.0, kTol);
  EXPECT_NEAR(up[0].end_run_out, 5.0, kTol);
  const auto down = g::sweepPasses(cell, 0.0, lines.first_y, 10.0, true, true);
  EXPECT_NEAR((down[0].start - g::Point(105, 45)).norm(), 0.0, kTol);
  EXPECT_NEAR((down[0].end - g::Point(-5, 45)).norm(), 0.0, kTol);
}

TEST(SweepLines, AngleRotatesTheLines) {
  // At 90 deg the lines run north: a 50 m wide, 100 m tall rectangle gets 5 lines along y.
  const double a = M_PI / 2;
  const auto lines = g::sweepLines(rectangle(0, 0, 50, 100), {}, a, settings());
  ASSERT_EQ(lines.lines.size(), 5u);
  const auto cells = g::sweepLineCells(lines.lines);
  ASSERT_EQ(cells.size(), 1u);
  for (const auto& p : g::sweepPasses(cells[0], a, lines.first_y, 10.0, false, false)) {
    EXPECT_NEAR(p.start.x(), p.end.x(), 1e-6);             // each pass runs north or south
    EXPECT_NEAR(std::abs(p.end.y() - p.start.y()), 110.0, 1e-6);  // 100 m plus the run-outs
  }
}

}  // namespace

// The minimum width bounds the sweep lines of any direction (plan's up-front work estimate).
TEST(MinimumWidth, RectangleTriangleAndConcaveRing) {
  using wattswath::geometry::minimumWidth;
  using wattswath::geometry::Point;
  // A 100 x 30 m rectangle, rotated by 30 degrees: 30 m whatever the rotation.
  wattswath::geometry::Ring rect;
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (const Point& p : {Point(0, 0), Point(100, 0), Point(100, 30), Point(0, 30)})
    rect.emplace_back(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  EXPECT_NEAR(minimumWidth(rect), 30.0, 1e-9);
  // A right triangle with legs 30 and 40: the height over the hypotenuse, 24 m.
  EXPECT_NEAR(minimumWidth({Point(0, 0), Point(40, 0), Point(0, 30)}), 24.0, 1e-9);
  // An L (100 x 100 with a 60 x 60 bite): its hull decides, narrowest across the cut corner's
  // edge x + y = 140, at 140 / sqrt 2 from the origin.
  EXPECT_NEAR(minimumWidth({Point(0, 0), Point(100, 0), Point(100, 40), Point(40, 40), Point(40, 100), Point(0, 100)}),
              140.0 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(minimumWidth({Point(0, 0), Point(1, 1)}), 0.0);
}
