#pragma once
/// @file sweep_lines.hpp
/// Parallel sweep lines over an area with obstacles, the cells their free intervals form, and the
/// zigzag passes over one cell: the straight-line geometry of a boustrophedon route before any
/// transit routing, speed or energy. Works in the line frame of a sweep angle: ENU rotated by
/// -angle, so the lines run along x and are stacked along y.

#include <vector>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::geometry {

/// Spacing, footprint and margins of the sweep lines.
struct SweepLineSettings {
  double spacing = 20.0;    ///< [m] distance between lines, > 0
  double clearance = 2.0;   ///< [m] distance kept from obstacles along a line
  double run_out = 0.0;     ///< [m] extension of an interval beyond the outer boundary (clipped by obstacles)
  int fewer_lines = 0;      ///< lines dropped below ceil(extent / spacing), the full-coverage count (>= 1 line is kept)
};

/// A free interval of one sweep line in the line frame (x along the line) [m].
struct SweepInterval {
  double x0 = 0.0, x1 = 0.0;      ///< [m] covered part
  double ext0 = 0.0, ext1 = 0.0;  ///< [m] run-out beyond each end that an arc may cut into
};

/// The free intervals of every sweep line of an area at one angle.
struct SweepLines {
  double first_y = 0.0;                          ///< [m] line-frame y of line 0; line k lies at first_y + k spacing
  std::vector<std::vector<SweepInterval>> lines;  ///< free intervals per line, by increasing x
};

/// A boustrophedon cell of sweep lines: one interval on each of consecutive lines.
struct SweepLineCell {
  int first_line = 0;               ///< index of the line of rows[0]
  std::vector<SweepInterval> rows;  ///< [m] one interval per line, from first_line on
};

/// One straight pass of a zigzag over a cell, in ENU [m].
struct SweepPass {
  Point start = Point::Zero();  ///< [m] where the pass starts (run-out included)
  Point end = Point::Zero();    ///< [m] where the pass ends (run-out included)
  double start_run_out = 0.0;   ///< [m] run-out at the start that an arc there may cut into
  double end_run_out = 0.0;     ///< [m] run-out at the end that an arc there may cut into
};

/// Sweep lines along `sweep_angle` [rad] over `outer` minus `obstacles` (rings of any orientation):
/// lines `spacing` apart centred on the area's extent (ceil(extent / spacing) - fewer_lines of them),
/// each interval where the line meets the area (so a line ends on the outer boundary), obstacles
/// widened by the clearance, ends at the outer boundary given the run-out (0: none, the default).
SweepLines sweepLines(const Ring& outer, const std::vector<Ring>& obstacles, double sweep_angle,
                      const SweepLineSettings& settings);

/// Groups the intervals of consecutive lines into cells (one-to-one overlaps stay in one cell).
std::vector<SweepLineCell> sweepLineCells(const std::vector<std::vector<SweepInterval>>& lines);

/// Zigzag passes over `cell` of the lines at `sweep_angle` [rad] (line k at first_y + k spacing
/// [m]): from its last row when `from_top`, the first pass from right to left when `start_right`.
std::vector<SweepPass> sweepPasses(const SweepLineCell& cell, double sweep_angle, double first_y, double spacing,
                                   bool from_top, bool start_right);

}  // namespace wattswath::geometry
