#!/usr/bin/env bash
# Builds test programs with address and undefined-behaviour sanitizers into build-fuzz/, the clang
# tree of the fuzz targets (scripts/sanitizer_tree.sh: the libraries are compiled once for both),
# and runs them. SANITIZE_TESTS picks the test programs (default: the fast subset that exercises
# every reader through the CLI and the library, the output safety and the degenerate geometry of
# the planner; "all" builds and runs every test). Any sanitizer report aborts the program.
set -euo pipefail
cd "$(dirname "$0")/.."
default_tests="test_io test_bad_inputs test_robustness_regressions test_output_safety test_log_io test_energy_core
  test_numerical_guards test_geoio test_mission test_flight test_mission_calibration test_planner_degenerate test_planner"
tests="${SANITIZE_TESTS:-$default_tests}"
source scripts/sanitizer_tree.sh
configure_sanitizer_tree
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
if [[ "$tests" == "all" ]]; then
  cmake --build build-fuzz -j2
  ctest --test-dir build-fuzz --output-on-failure -j2
  exit 0
fi
read -r -a list <<< "$(echo $tests)"
cmake --build build-fuzz -j2 --target wattswath "${list[@]}"
for t in "${list[@]}"; do
  echo "sanitize: $t"
  "build-fuzz/bin/$t" --gtest_brief=1
done
echo "sanitize: ${#list[@]} test programs passed under address and undefined-behaviour sanitizers"
