#include "wattswath/planner/planner.hpp"

namespace wattswath::planner {

const char* version() { return "0.1.0"; }

}  // namespace wattswath::planner
