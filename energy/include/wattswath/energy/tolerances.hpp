#pragma once
/// @file tolerances.hpp
/// Named numerical tolerances of the energy module, in one place (README: "Precision").

namespace wattswath::energy::tol {

inline constexpr double kLength = 1e-9;   ///< [m] pieces shorter than this are dropped
inline constexpr double kSpeed = 1e-9;    ///< [m/s] speeds closer than this are equal
inline constexpr double kRoot = 1e-12;    ///< [m/s] bracket width at which root finders stop
inline constexpr double kEnergyRel = 1e-9;  ///< [-] relative agreement of closed forms and quadrature
}  // namespace wattswath::energy::tol
