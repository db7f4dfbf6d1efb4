# `cmake --install build --prefix P`: the seven libraries' public headers (include/wattswath/...),
# the static libraries and the CMake package wattswath (lib/cmake/wattswath/) with the namespaced
# targets wattswath::io, ::geometry, ::energy, ::logs, ::mission, ::calibration and ::planner, the same
# names as the in-tree ALIAS targets (EXPORT_NAME in each library's CMakeLists.txt); also the
# `wattswath` command line (bin/). A consumer: find_package(wattswath) and link wattswath::planner
# (examples/consumer/ is one, built by the test install_consumer). The heavy dependencies stay
# PRIVATE, but static libraries need them at link time, so wattswathConfig.cmake finds them again
# (find_dependency) and recreates the wrapper targets wattswath::ompl and wattswath::geographiclib.
include(CMakePackageConfigHelpers)

set(WATTSWATH_LIBRARIES io geometry energy logs mission calibration planner)
set(WATTSWATH_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/wattswath)

foreach(library IN LISTS WATTSWATH_LIBRARIES)
  install(TARGETS wattswath_${library} EXPORT wattswathTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${CMAKE_SOURCE_DIR}/${library}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
install(TARGETS wattswath RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(EXPORT wattswathTargets NAMESPACE wattswath:: DESTINATION ${WATTSWATH_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/wattswathConfig.cmake.in
  ${CMAKE_BINARY_DIR}/wattswathConfig.cmake INSTALL_DESTINATION ${WATTSWATH_INSTALL_CMAKEDIR})
# 0.x: a minor version may break the interface, so only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/wattswathConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES
  ${CMAKE_BINARY_DIR}/wattswathConfig.cmake
  ${CMAKE_BINARY_DIR}/wattswathConfigVersion.cmake
  ${CMAKE_SOURCE_DIR}/cmake/WattswathDependencyTargets.cmake
  DESTINATION ${WATTSWATH_INSTALL_CMAKEDIR})
