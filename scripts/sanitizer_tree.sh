# Sourced by scripts/fuzz.sh and scripts/sanitize.sh: both use the one clang tree build-fuzz/,
# configured identically, with address and undefined-behaviour sanitizers on every target
# (WATTSWATH_FUZZ implies WATTSWATH_SANITIZE), so the energy and geometry libraries are compiled
# once for the fuzz targets and the sanitizer tests. -O1 with line tables only: fast enough to
# fuzz, symbolized stack traces, and a much cheaper cold build of the CGAL/OMPL code than -O2 -g.
configure_sanitizer_tree() {
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DWATTSWATH_FUZZ=ON -DWATTSWATH_SANITIZE=ON \
    -DWATTSWATH_BUILD_TESTS=ON -DWATTSWATH_BUILD_BENCHMARKS=OFF -DWATTSWATH_BUILD_EXAMPLES=OFF >/dev/null
}
