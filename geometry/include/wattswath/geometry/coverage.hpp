#pragma once
/// @file coverage.hpp
/// Coverage candidates over a survey area: boustrophedon cell decomposition with back-and-forth
/// sweep lines at any angle, and inward-offset spirals (CGAL does the polygon work privately).

#include <vector>

#include "wattswath/geometry/path.hpp"
#include "wattswath/geometry/route.hpp"

namespace wattswath::geometry {

/// One x-monotone piece of a cell in the sweep frame (sweep lines vertical): between x_left and
/// x_right a vertical line meets the piece in one interval, from `lower` to `upper`.
struct SweepPiece {
  double x_left = 0.0;        ///< [m] left wall, sweep frame
  double x_right = 0.0;       ///< [m] right wall, sweep frame
  std::vector<Point> lower;   ///< [m] lower boundary, polyline with increasing x from x_left to x_right
  std::vector<Point> upper;   ///< [m] upper boundary, polyline with increasing x from x_left to x_right
};

/// A boustrophedon cell: any sweep line meets it in one interval.
struct BoustrophedonCell {
  Ring boundary;                   ///< [m] cell outline in the ENU frame, counter-clockwise
  std::vector<SweepPiece> pieces;  ///< [m] the cell in the sweep frame, pieces ordered by x
};

/// A boustrophedon cell decomposition of an area for one sweep direction.
struct BoustrophedonDecomposition {
  double sweep_angle = 0.0;              ///< [rad] direction of the sweep lines (0 = east, CCW)
  std::vector<BoustrophedonCell> cells;  ///< cells, ordered by their left wall in the sweep frame
};

/// Maps a point from the ENU frame to the sweep frame of `sweep_angle` [rad], where the sweep
/// lines are vertical (rotation by pi/2 - sweep_angle).
Point toSweepFrame(const Point& p, double sweep_angle);
/// Maps a point from the sweep frame of `sweep_angle` [rad] back to the ENU frame.
Point fromSweepFrame(const Point& p, double sweep_angle);

/// Boustrophedon cell decomposition (Choset) of `area` for sweep lines along `sweep_angle` [rad]:
/// CGAL's vertical decomposition in the sweep frame, then pieces merged wherever the sweep line's
/// connectivity does not change. Throws std::invalid_argument on an invalid polygon (< 3 vertices,
/// non-finite coordinates, zero area).
BoustrophedonDecomposition decomposeBoustrophedon(const PolygonWithHoles& area, double sweep_angle);

/// Partition of a simple polygon (no holes) into convex pieces, counter-clockwise: CGAL's optimal
/// convex partition (fewest pieces; Greene's dynamic programme) up to 24 vertices, Hertel-Mehlhorn
/// (at most four times the fewest) beyond; a convex ring is returned as it is. Repeated and
/// collinear vertices are dropped first. Throws std::invalid_argument for a ring with fewer than 3
/// distinct vertices, a non-finite vertex or a ring that crosses itself.
std::vector<Ring> convexPartition(const Ring& polygon);

/// Corner of a cell where the boustrophedon starts, in the sweep frame (left = first line at the
/// smallest sweep-frame x, bottom = first line flown upwards).
enum class StartCorner { BottomLeft, BottomRight, TopLeft, TopRight };

/// Settings for boustrophedon candidates.
struct BoustrophedonSettings {
  double spacing = 20.0;                      ///< [m] distance between passes, > 0
  double sweep_angle = 0.0;                   ///< [rad] direction of the sweep lines, any value (mod pi)
  StartCorner start = StartCorner::BottomLeft;  ///< where each cell's route starts
};

/// Route over one cell: sweep lines spaced at most `spacing` apart (evenly, inset half a spacing
/// from the walls), alternating direction, ending on the cell's boundary (no flown point leaves the
/// area), joined by connectors straight where that stays in the area and out of its holes, else
/// along the cell boundary (role Turn). `area` is the area the cell came from.
Route boustrophedonRoute(const PolygonWithHoles& area, const BoustrophedonDecomposition& decomposition,
                         int cell, const BoustrophedonSettings& settings);

/// One path per cell (CoveragePath::cell set) with `corners` shaped; `altitude` [m] on every leg.
std::vector<CoveragePath> boustrophedonPaths(const PolygonWithHoles& area, const BoustrophedonSettings& settings,
                                             const CornerSettings& corners, double altitude = 0.0);

/// A spiral cell: the laps (inward offsets) of one region, outermost first.
struct SpiralCell {
  std::vector<Ring> laps;       ///< [m] offset rings, counter-clockwise, outermost first; an acute
                                ///< corner may carry an out-and-back spike (v, tip, v) toward the
                                ///< corner outside it so the footprint reaches into the corner
  std::vector<double> offsets;  ///< [m] inward offset of each lap from the piece boundary
};

/// Settings for spiral candidates.
struct SpiralSettings {
  double spacing = 20.0;     ///< [m] distance between laps, > 0
  int start_vertex = 0;      ///< index of the first lap's vertex where the spiral starts (taken
                             ///< modulo that lap's vertex count; laps are as CGAL orders them)
  bool clockwise = false;    ///< fly the laps clockwise instead of counter-clockwise
  double split_angle = 0.0;  ///< [rad] sweep angle of the boustrophedon decomposition that cuts an
                             ///< area with holes into hole-free pieces before offsetting
};

/// Spiral decomposition: areas with holes are first cut into hole-free boustrophedon cells (at
/// `split_angle`); each piece's outline is simplified (Douglas-Peucker, Boost.Geometry, to 2 % of
/// the spacing; kept as it is where that would make it cross itself), offset inwards by spacing/2,
/// 3 spacing/2, ... (CGAL straight skeleton) and each chain of offsets that does not split is one cell. Where an offset splits
/// (narrow necks), each part starts a new cell. Where a part would vanish with its deepest point t
/// more than half a spacing inside the last lap, the next lap is put at t - spacing/4 instead, so
/// no point stays more than half a spacing from a lap. Pieces thinner than a spacing get one lap
/// at half their depth.
std::vector<SpiralCell> decomposeSpiral(const PolygonWithHoles& area, double spacing, double split_angle = 0.0);

/// One continuous spiral route through the laps of `cell`: each lap is flown from its start
/// vertex around to one spacing before that vertex, then straight to the next lap's vertex
/// nearest that point (all segments role Sweep).
Route spiralRoute(const SpiralCell& cell, const SpiralSettings& settings);

/// One path per spiral cell (CoveragePath::cell set) with `corners` shaped; `altitude` [m] on every leg.
std::vector<CoveragePath> spiralPaths(const PolygonWithHoles& area, const SpiralSettings& settings,
                                      const CornerSettings& corners, double altitude = 0.0);

/// Joins per-cell routes in the given order with transits (role Transit) that go around holes
/// (shortest route over hole vertices, see safeRoute()).
Route joinRoutes(const PolygonWithHoles& area, const std::vector<Route>& routes);

}  // namespace wattswath::geometry
