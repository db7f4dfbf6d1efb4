# wattswath_test(name SOURCES ... LIBS ...): one GoogleTest program, registered with ctest (label
# "unit"). Each library keeps its tests beside it (<library>/tests/); the command-line and
# cross-library tests, the shared test helpers (tests/*.hpp) and the test data (tests/data/) live in
# the top-level tests/. Tests that read ../shared/data are registered only when it exists
# (WATTSWATH_HAVE_SHARED_DATA; CI has it beside the checkout).
find_package(GTest REQUIRED)
include(GoogleTest)

set(WATTSWATH_HAVE_SHARED_DATA OFF)
if(EXISTS "${WATTSWATH_SHARED_DATA_DIR}/README.md")
  set(WATTSWATH_HAVE_SHARED_DATA ON)
else()
  message(STATUS "wattswath: ${WATTSWATH_SHARED_DATA_DIR} not found; tests on the reference data are skipped")
endif()

# TIMEOUT s: a hang watchdog for each of the program's tests (regression tests of inputs that used
# to spin or run in quadratic time); none by default.
function(wattswath_test name)
  cmake_parse_arguments(T "" "TIMEOUT" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  target_include_directories(${name} PRIVATE ${CMAKE_SOURCE_DIR}/tests)
  target_compile_definitions(${name} PRIVATE
    WATTSWATH_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    WATTSWATH_SHARED_DATA_DIR="${WATTSWATH_SHARED_DATA_DIR}"
    WATTSWATH_BINARY="$<TARGET_FILE:wattswath>")
  wattswath_warnings(${name})
  if(T_TIMEOUT)
    gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS unit TIMEOUT ${T_TIMEOUT})
  else()
    gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS unit)
  endif()
endfunction()
