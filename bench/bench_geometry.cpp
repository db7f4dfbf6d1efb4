// Geometry benchmarks: boustrophedon decomposition and candidate generation (boustrophedon at one
// angle, all cells, and spiral) for the real IRIS survey area with its no-fly zone and for a
// synthetic 100 ha field with 10 holes. Baseline in the same run: the same 100 ha field without
// holes; and reading the bundled area files. Route checks on a 1,200-vertex star: the plain loops
// (Baseline) against the ring's R-tree; segments against 400 holes: every hole, a box check
// first, the holes' R-tree. Run: build/bin/bench_geometry (docs/performance.md, section "Geometry").
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>

#include "ring_index.hpp"  // geometry/src: the internal index, against the plain loops
#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/coverage.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace g = wattswath::geometry;

namespace {

constexpr double kSpacing = 21.45;  // [m] E-Spiral camera (10 m, 100 deg, 10 %)

/// 1000 m x 1000 m field (100 ha) with `holes` square holes of 40 m on a jittered grid (seed 7).
g::PolygonWithHoles field(int holes) {
  g::PolygonWithHoles a;
  a.outer = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-60.0, 60.0), rot(0.0, M_PI / 2);
  for (int k = 0; k < holes; ++k) {
    const g::Point c(150.0 + 175.0 * (k % 5) + jitter(rng), 300.0 + 400.0 * (k / 5) + jitter(rng));
    const double r = 20.0 * std::sqrt(2.0), t0 = rot(rng);
    g::Ring h;
    for (int j = 3; j >= 0; --j) h.push_back(c + r * g::Point(std::cos(t0 + j * M_PI / 2), std::sin(t0 + j * M_PI / 2)));
    a.holes.push_back(h);
  }
  return a;
}

const g::PolygonWithHoles& irisArea() {
  static const g::PolygonWithHoles area = [] {
    // data/areas/iris_area.geojson: the real IRIS+ flight area with its no-fly zone as a hole.
    return g::readSurveyArea(std::string(WATTSWATH_SOURCE_DIR) + "/data/areas/iris_area.geojson").polygon();
  }();
  return area;
}

void decompose(benchmark::State& st, const g::PolygonWithHoles& area) {
  for (auto _ : st) {
    auto d = g::decomposeBoustrophedon(area, 30.0 * M_PI / 180.0);
    benchmark::DoNotOptimize(d);
  }
}

void candidates(benchmark::State& st, const g::PolygonWithHoles& area) {
  g::BoustrophedonSettings bs;
  bs.spacing = kSpacing;
  bs.sweep_angle = 30.0 * M_PI / 180.0;
  g::SpiralSettings sp;
  sp.spacing = kSpacing;
  for (auto _ : st) {
    auto b = g::boustrophedonPaths(area, bs, {});
    auto s = g::spiralPaths(area, sp, {});
    benchmark::DoNotOptimize(b);
    benchmark::DoNotOptimize(s);
  }
}

void coverageCheck(benchmark::State& st, const g::PolygonWithHoles& area) {
  g::BoustrophedonSettings bs;
  bs.spacing = kSpacing;
  const auto paths = g::boustrophedonPaths(area, bs, {});
  for (auto _ : st) benchmark::DoNotOptimize(g::checkCoverage(area, paths, kSpacing));
}

}  // namespace

void BM_Decompose_Field100ha_NoHoles_Baseline(benchmark::State& st) { decompose(st, field(0)); }
void BM_Decompose_Field100ha_10Holes(benchmark::State& st) { decompose(st, field(10)); }
void BM_Candidates_Field100ha_NoHoles_Baseline(benchmark::State& st) { candidates(st, field(0)); }
void BM_Candidates_Field100ha_10Holes(benchmark::State& st) { candidates(st, field(10)); }
void BM_CoverageCheck_Field100ha_10Holes(benchmark::State& st) { coverageCheck(st, field(10)); }

BENCHMARK(BM_Decompose_Field100ha_NoHoles_Baseline)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Decompose_Field100ha_10Holes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Candidates_Field100ha_NoHoles_Baseline)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Candidates_Field100ha_10Holes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CoverageCheck_Field100ha_10Holes)->Unit(benchmark::kMillisecond);

// Transit routes on a 1,200-vertex star (the issue-20 case after repairs): every visibility check
// against the outer ring, as the plain loops answer it (Baseline) and through the ring's R-tree.
g::PolygonWithHoles star() {
  g::PolygonWithHoles a;
  const int n = 1200;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n, r = 300.0 + 20.0 * std::sin(7.0 * t) + (i % 2 ? 2.0 : 0.0);
    a.outer.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return a;
}
std::vector<std::pair<g::Point, g::Point>> chords() {
  std::vector<std::pair<g::Point, g::Point>> c;
  for (int k = 0; k < 64; ++k) {
    const double t = 2.0 * M_PI * k / 64;
    c.push_back({g::Point(270.0 * std::cos(t), 270.0 * std::sin(t)), g::Point(-270.0 * std::cos(t + 0.9), -270.0 * std::sin(t + 0.9))});
  }
  return c;
}
void BM_SegmentLeavesArea_Star1200_Baseline(benchmark::State& st) {
  const auto a = star();
  const auto c = chords();
  for (auto _ : st)
    for (const auto& [p, q] : c) benchmark::DoNotOptimize(g::segmentLeavesArea(a, p, q));
}
void BM_SegmentLeavesArea_Star1200_Indexed(benchmark::State& st) {
  const auto a = star();
  const auto c = chords();
  const g::detail::RingIndex index(a.outer);
  for (auto _ : st)
    for (const auto& [p, q] : c) benchmark::DoNotOptimize(g::detail::segmentLeavesRing(index, p, q));
}
BENCHMARK(BM_SegmentLeavesArea_Star1200_Baseline)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SegmentLeavesArea_Star1200_Indexed)->Unit(benchmark::kMicrosecond);

// Whether segments enter one of 400 holes (a 20 x 20 grid of 12 m squares in a 1 km field; 256
// segments of up to 85 m): every hole tested exactly, as segmentEntersHole did before the boxes
// (Baseline); segmentEntersHole now (a box check first); the holes' R-tree that safeRoute uses.
g::PolygonWithHoles holeGrid() {
  g::PolygonWithHoles a;
  a.outer = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const g::Point c(50.0 + 47.0 * i, 50.0 + 47.0 * j);
      a.holes.push_back({c + g::Point(6, 6), c + g::Point(6, -6), c + g::Point(-6, -6), c + g::Point(-6, 6)});
    }
  return a;
}
std::vector<std::pair<g::Point, g::Point>> shortSegments() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(0.0, 1000.0), len(-60.0, 60.0);
  std::vector<std::pair<g::Point, g::Point>> c;
  for (int k = 0; k < 256; ++k) {
    const g::Point a(coord(rng), coord(rng));
    c.push_back({a, a + g::Point(len(rng), len(rng))});
  }
  return c;
}
void BM_SegmentEntersHole_400Holes_Baseline(benchmark::State& st) {
  const auto a = holeGrid();
  const auto c = shortSegments();
  for (auto _ : st)
    for (const auto& [p, q] : c) {
      bool in = false;
      for (const auto& h : a.holes) in = in || g::detail::segmentEntersRing(h, p, q);
      benchmark::DoNotOptimize(in);
    }
}
void BM_SegmentEntersHole_400Holes_BoxCheck(benchmark::State& st) {
  const auto a = holeGrid();
  const auto c = shortSegments();
  for (auto _ : st)
    for (const auto& [p, q] : c) benchmark::DoNotOptimize(g::segmentEntersHole(a, p, q));
}
void BM_SegmentEntersHole_400Holes_Indexed(benchmark::State& st) {
  const auto a = holeGrid();
  const auto c = shortSegments();
  const g::detail::HoleIndex index(a.holes);
  for (auto _ : st)
    for (const auto& [p, q] : c) benchmark::DoNotOptimize(index.segmentEnters(p, q));
}
void BM_SafeRoute_400Holes(benchmark::State& st) {
  const auto a = holeGrid();
  for (auto _ : st) benchmark::DoNotOptimize(g::safeRoute(a, g::Point(3, 3), g::Point(997, 997)));
}
BENCHMARK(BM_SegmentEntersHole_400Holes_Baseline)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SegmentEntersHole_400Holes_BoxCheck)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SegmentEntersHole_400Holes_Indexed)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SafeRoute_400Holes)->Unit(benchmark::kMillisecond);

void BM_Decompose_IrisArea_NoFly(benchmark::State& st) { decompose(st, irisArea()); }
void BM_Candidates_IrisArea_NoFly(benchmark::State& st) { candidates(st, irisArea()); }
BENCHMARK(BM_Decompose_IrisArea_NoFly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Candidates_IrisArea_NoFly)->Unit(benchmark::kMillisecond);

/// Reading one area file (read, GDAL/OGR parse, projection, CGAL validation, no-fly subtraction).
void readArea(benchmark::State& st, const char* relative) {
  const std::string path = std::string(WATTSWATH_SOURCE_DIR) + "/" + relative;
  for (auto _ : st) benchmark::DoNotOptimize(g::readSurveyArea(path).area());
}
void BM_ReadArea_IrisGeoJson(benchmark::State& st) { readArea(st, "data/areas/iris_area.geojson"); }
void BM_ReadArea_ESpiralGeoJson(benchmark::State& st) { readArea(st, "data/areas/espiral_rectangle.geojson"); }
void BM_ReadArea_FieldKml(benchmark::State& st) { readArea(st, "tests/data/areas/field.kml"); }
void BM_ReadArea_FieldWkt(benchmark::State& st) { readArea(st, "tests/data/areas/field.wkt"); }
BENCHMARK(BM_ReadArea_IrisGeoJson)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReadArea_ESpiralGeoJson)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReadArea_FieldKml)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReadArea_FieldWkt)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
