#!/usr/bin/env bash
# Builds the libFuzzer targets with clang into build-fuzz/ (scripts/sanitizer_tree.sh) and runs
# each for a bounded time (FUZZ_SECONDS each, default 20; FUZZ_TARGETS to pick some) from its
# seeds: fuzz/corpus/<name>/ when present plus the files listed below (bundled examples and the
# malformed-input corpus) and, for the autopilot readers, the first 64 kB of the real logs in
# ../shared/data/autopilot-logs.
# New corpus entries go to build-fuzz/corpus/ (never into the source tree); a crashing input is
# saved in build-fuzz/artifacts/<target>/. Exits non-zero when a target finds a crash.
# The mutation sequence is seeded (FUZZ_SEED, default 1) so that a CI finding can be replayed; how
# far it gets in FUZZ_SECONDS still depends on the machine's speed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-20}"

# target -> seed files (globs relative to the checkout)
declare -A seeds=(
  [fuzz_vehicle_json]="data/vehicles/*.json tests/data/good/*.json tests/data/bad/vehicle_*.json"
  [fuzz_csv_log]="tests/data/good/*.csv tests/data/bad/*.csv"
  [fuzz_area]="data/areas/* tests/data/bad/*.geojson tests/data/bad/*.kml tests/data/bad/*.wkt tests/data/bad/*.waypoints"
  [fuzz_dataflash]="tests/data/bad/*.bin"
  [fuzz_ulog]="tests/data/bad/*.ulg"
)
# target -> extension of the real logs in ../shared/data/autopilot-logs
declare -A real_logs=([fuzz_dataflash]=bin [fuzz_ulog]=ulg)
all_targets=(fuzz_vehicle_json fuzz_csv_log fuzz_area fuzz_dataflash fuzz_ulog)
shared="../shared/data/autopilot-logs"
read -r -a targets <<< "${FUZZ_TARGETS:-${all_targets[*]}}"

source scripts/sanitizer_tree.sh
configure_sanitizer_tree
cmake --build build-fuzz -j2 --target "${targets[@]}"

for t in "${targets[@]}"; do
  work="build-fuzz/corpus/$t"
  mkdir -p "$work" "build-fuzz/artifacts/$t"
  name="${t#fuzz_}"
  if [[ -d "fuzz/corpus/$name" ]]; then cp -n fuzz/corpus/"$name"/* "$work"/ 2>/dev/null || true; fi
  for f in ${seeds[$t]:-}; do
    [[ -f "$f" ]] && cp -n "$f" "$work/seed_$(basename "$f")"
  done
  # Seeds from the real logs: their first 64 kB (definitions and the first data), kept small.
  if [[ -n "${real_logs[$t]:-}" && -d "$shared" ]]; then
    for f in "$shared"/*."${real_logs[$t]}"; do head -c 65536 "$f" > "$work/real_$(basename "$f")"; done
  fi
  echo "fuzz: $t for ${seconds} s from $(ls "$work" | wc -l) inputs"
  status=0
  "build-fuzz/bin/$t" "$work" -seed="${FUZZ_SEED:-1}" -max_total_time="$seconds" -max_len=131072 -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="build-fuzz/artifacts/$t/" -print_final_stats=1 > "build-fuzz/$t.log" 2>&1 || status=$?
  grep -E "^(stat::|Done|==[0-9]+==|SUMMARY)" "build-fuzz/$t.log" | head -n 20 || true
  if ((status != 0)); then
    tail -n 60 "build-fuzz/$t.log" >&2
    echo "fuzz: $t FAILED (exit $status); reproduce with build-fuzz/bin/$t build-fuzz/artifacts/$t/<file>" >&2
    exit "$status"
  fi
done
echo "fuzz: all ${#targets[@]} targets ran ${seconds} s each without a finding"
