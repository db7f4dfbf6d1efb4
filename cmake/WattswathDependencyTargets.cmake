# Imported targets for the two dependencies whose Debian packages give variables only, so that
# planner/ (OMPL), geometry/ and logs/ (GeographicLib) link them PRIVATE like any other and the
# installed package names targets, not this machine's library paths. Included after
# find_package(ompl CONFIG) and find_package(GeographicLib) by the top-level CMakeLists.txt and by
# the installed wattswathConfig.cmake.

# An INTERFACE IMPORTED target `target` with these include directories and libraries (once).
function(wattswath_variables_target target include_dirs libraries)
  if(NOT TARGET ${target})
    add_library(${target} INTERFACE IMPORTED)
    set_target_properties(${target} PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${include_dirs}" INTERFACE_LINK_LIBRARIES "${libraries}")
  endif()
endfunction()

# Debian's OMPL 1.5.2 ships omplConfig.cmake with OMPL_INCLUDE_DIRS and OMPL_LIBRARIES only.
wattswath_variables_target(wattswath::ompl "${OMPL_INCLUDE_DIRS}" "${OMPL_LIBRARIES}")
# Debian's GeographicLib 1.52 ships FindGeographicLib.cmake (in /usr/share/cmake/geographiclib).
wattswath_variables_target(wattswath::geographiclib "${GeographicLib_INCLUDE_DIRS}" "${GeographicLib_LIBRARIES}")
