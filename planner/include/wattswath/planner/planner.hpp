#pragma once
/// @file planner.hpp
/// Minimum-energy coverage planning (issue 5). Uses geometry and energy; OMPL and Boost.Graph
/// stay private to planner's .cpp files.

#include "wattswath/energy/model.hpp"
#include "wattswath/geometry/polygon.hpp"

namespace wattswath::planner {

/// Version string of the planner library.
const char* version();

}  // namespace wattswath::planner
