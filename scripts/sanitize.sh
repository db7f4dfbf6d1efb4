#!/usr/bin/env bash
# Builds the test suite with address and undefined-behaviour sanitizers (-DWATTSWATH_SANITIZE=ON)
# into build-asan/ and runs it. SANITIZE_TESTS picks the test programs (default: the fast subset
# that exercises every reader through the CLI and the library; "all" builds and runs every test).
set -euo pipefail
cd "$(dirname "$0")/.."
default_tests="test_bad_inputs test_robustness_regressions test_output_safety test_log_io test_energy_core test_numerical_guards"
tests="${SANITIZE_TESTS:-$default_tests}"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DWATTSWATH_SANITIZE=ON -DWATTSWATH_BUILD_BENCHMARKS=OFF -DWATTSWATH_BUILD_EXAMPLES=OFF >/dev/null
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
if [[ "$tests" == "all" ]]; then
  cmake --build build-asan -j2
  ctest --test-dir build-asan --output-on-failure -j2
  exit 0
fi
read -r -a list <<< "$tests"
cmake --build build-asan -j2 --target wattswath "${list[@]}"
for t in "${list[@]}"; do
  echo "sanitize: $t"
  "build-asan/bin/$t" --gtest_brief=1
done
echo "sanitize: ${#list[@]} test programs passed under address and undefined-behaviour sanitizers"
