#!/usr/bin/env bash
# Builds the libFuzzer targets with clang into build-fuzz/ and runs each for a bounded time
# (FUZZ_SECONDS, default 60) from the seed corpus in fuzz/corpus/<reader>/, plus, when present,
# the real logs of ../shared/data/autopilot-logs. New corpus entries go to build-fuzz/corpus/
# (never into the source tree). Exits non-zero when a target finds a crash.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-60}"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWATTSWATH_FUZZ=ON \
  -DWATTSWATH_BUILD_TESTS=OFF -DWATTSWATH_BUILD_BENCHMARKS=OFF -DWATTSWATH_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build-fuzz -j2 --target fuzz_dataflash fuzz_ulog
shared="../shared/data/autopilot-logs"
for reader in dataflash ulog; do
  work="build-fuzz/corpus/$reader"
  mkdir -p "$work" "build-fuzz/artifacts/$reader"
  cp -n fuzz/corpus/"$reader"/* "$work"/ 2>/dev/null || true
  ext=bin; [[ "$reader" == ulog ]] && ext=ulg
  # Seeds from the real logs: their first 64 kB (definitions and the first data), kept small.
  if [[ -d "$shared" ]]; then
    for f in "$shared"/*."$ext"; do head -c 65536 "$f" > "$work/real_$(basename "$f")"; done
  fi
  echo "fuzz: $reader for ${seconds} s"
  "build-fuzz/bin/fuzz_$reader" "$work" -max_total_time="$seconds" -max_len=131072 -rss_limit_mb=2048 \
    -artifact_prefix="build-fuzz/artifacts/$reader/" -print_final_stats=1
done
