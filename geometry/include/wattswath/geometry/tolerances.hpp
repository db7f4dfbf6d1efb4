#pragma once
/// @file tolerances.hpp
/// Named numerical tolerances of the geometry module, in one place (README: "Precision").

namespace wattswath::geometry::tol {

inline constexpr double kPosition = 1e-6;   ///< [m] points closer than this are the same point
inline constexpr double kAngle = 1e-9;      ///< [rad] headings closer than this are the same heading
inline constexpr double kHoleDepth = 1e-6;  ///< [m] a path this close to a hole's boundary does not enter it
inline constexpr double kArcChord = 0.05;   ///< [rad] hole checks split arcs into chords of at most this angle
inline constexpr double kSwathArcChord = 0.3927;  ///< [rad] swaths of arcs: one rectangle per chord of at most this angle (pi/8)
inline constexpr double kCheckPosition = 1e-6;  ///< [m] checkPath: largest gap allowed between legs
inline constexpr double kCheckAngle = 1e-6;     ///< [rad] checkPath: largest heading jump allowed between legs
inline constexpr double kContainment = 1e-3;  ///< [m] checkContainment: a path this close to the boundary is on it, not beyond
inline constexpr double kSliver = 1e-6;     ///< [m] cells or walls narrower than this are dropped as slivers

}  // namespace wattswath::geometry::tol
