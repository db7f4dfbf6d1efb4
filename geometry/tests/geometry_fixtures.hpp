#pragma once
// Polygons for the geometry tests, built in code (no files needed).
#include <cmath>
#include <random>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::test {

using geometry::Point;
using geometry::PolygonWithHoles;
using geometry::Ring;

/// Axis-aligned rectangle [x0, x0 + w] x [y0, y0 + h], counter-clockwise.
inline Ring rectangle(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}

/// The same ring clockwise (a hole).
inline Ring reversed(Ring r) { return Ring(r.rbegin(), r.rend()); }

/// A star-shaped polygon around `c` with `n` vertices at radii in [r_min, r_max] and up to
/// `holes` small square holes that keep clear of each other and of the boundary.
inline PolygonWithHoles randomArea(std::mt19937& rng, const Point& c, double r_min, double r_max, int n, int holes) {
  std::uniform_real_distribution<double> ur(r_min, r_max), uj(-0.3, 0.3), u01(0.0, 1.0);
  PolygonWithHoles a;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * (i + 0.5 + uj(rng)) / n;
    const double r = ur(rng);
    a.outer.push_back(c + r * Point(std::cos(t), std::sin(t)));
  }
  std::vector<std::pair<Point, double>> placed;
  for (int k = 0, tries = 0; k < holes && tries < 200; ++tries) {
    const double half = r_min * (0.06 + 0.08 * u01(rng));
    const double rr = (r_min * 0.85 - 1.5 * half) * std::sqrt(u01(rng));
    const double t = 2.0 * M_PI * u01(rng);
    const Point p = c + rr * Point(std::cos(t), std::sin(t));
    bool clear = true;
    for (const auto& [q, h] : placed) clear = clear && (p - q).norm() > 1.6 * (h + half) + 5.0;
    if (!clear) continue;
    placed.push_back({p, half});
    const double rot = u01(rng);
    Ring hole;
    for (int j = 0; j < 4; ++j) {
      const double a4 = rot + M_PI / 2 * j;
      hole.push_back(p + half * std::sqrt(2.0) * Point(std::cos(a4), std::sin(a4)));
    }
    a.holes.push_back(reversed(hole));
    ++k;
  }
  return a;
}

}  // namespace wattswath::test
