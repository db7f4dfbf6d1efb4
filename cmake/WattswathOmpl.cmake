# Debian's OMPL 1.5.2 ships omplConfig.cmake with variables only (no ompl::ompl target).
# Wrap them in an imported target so planner/ can link it PRIVATE like any other.
find_package(ompl REQUIRED CONFIG)
if(NOT TARGET wattswath::ompl)
  add_library(wattswath::ompl INTERFACE IMPORTED)
  set_target_properties(wattswath::ompl PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OMPL_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${OMPL_LIBRARIES}")
endif()
