#!/usr/bin/env bash
# Builds the libFuzzer targets with clang into build-fuzz/ (scripts/sanitizer_tree.sh) and runs
# each for a bounded time (FUZZ_SECONDS each, default 20; FUZZ_TARGETS to pick some) from its
# seeds: fuzz/corpus/<name>/ when present plus the files listed below (bundled examples and the
# malformed-input corpus) and, for the autopilot readers, the first 64 kB of the real logs in
# ../shared/data/autopilot-logs.
# New corpus entries go to build-fuzz/corpus/ (never into the source tree); a crashing input is
# saved in build-fuzz/artifacts/<target>/. Exits non-zero when a target finds a crash.
# The mutation sequence is seeded (FUZZ_SEED, default 1). Two ways to bound a run:
# - FUZZ_SECONDS (default): for exploring; the corpus grows across runs in build-fuzz/corpus/, and
#   how far a run gets depends on the machine's speed, so two runs are not the same run.
# - FUZZ_RUNS=N, or FUZZ_RUNS=ci for the per-target counts below (what CI uses): exactly that many
#   inputs per target, from the seeds alone (a fresh output
#   folder build-fuzz/corpus-fixed/<target>, seeds passed in sorted order with -seed_inputs): the
#   same checkout and compiler give the same inputs here and in CI, so a clean local run means a
#   clean CI run, and a CI finding replays here.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-20}"

# target -> seed files (globs relative to the checkout)
declare -A seeds=(
  [fuzz_vehicle_json]="data/vehicles/*.json tests/data/good/*.json tests/data/bad/vehicle_*.json"
  [fuzz_csv_log]="tests/data/good/*.csv tests/data/bad/*.csv"
  [fuzz_waypoint_path]="tests/data/bad/path_*.txt tests/data/good/*.txt"
  [fuzz_area]="data/areas/* tests/data/bad/*.geojson tests/data/bad/*.kml tests/data/bad/*.wkt tests/data/bad/*.waypoints tests/data/good/*.plan"
  [fuzz_dataflash]="tests/data/bad/*.bin"
  [fuzz_ulog]="tests/data/bad/*.ulg"
  [fuzz_mission]="tests/data/good/*.plan tests/data/good/*.waypoints tests/data/bad/mission_*"
)
# target -> inputs per run for FUZZ_RUNS=ci: about 20 s each on the 2-core build machine
# (docs/robustness.md, "CI cost"); the rates differ by a factor 10 between readers.
declare -A ci_runs=([fuzz_vehicle_json]=10000 [fuzz_csv_log]=300000 [fuzz_waypoint_path]=600000 [fuzz_area]=80000 [fuzz_dataflash]=6000 [fuzz_ulog]=8000 [fuzz_mission]=60000)
# target -> libFuzzer dictionary (structure-aware mutation: JSON tokens for deep nesting, ULog
# message headers and type names for nested formats; issue 20)
declare -A dicts=([fuzz_vehicle_json]=fuzz/dict/json.dict [fuzz_area]=fuzz/dict/json.dict [fuzz_mission]=fuzz/dict/json.dict [fuzz_ulog]=fuzz/dict/ulog.dict)
# target -> extension of the real logs in ../shared/data/autopilot-logs
declare -A real_logs=([fuzz_dataflash]=bin [fuzz_ulog]=ulg)
all_targets=(fuzz_vehicle_json fuzz_csv_log fuzz_waypoint_path fuzz_area fuzz_dataflash fuzz_ulog fuzz_mission)
shared="../shared/data/autopilot-logs"
read -r -a targets <<< "${FUZZ_TARGETS:-${all_targets[*]}}"

source scripts/sanitizer_tree.sh
configure_sanitizer_tree
cmake --build build-fuzz -j2 --target "${targets[@]}"

# A fixed-count run is repeatable only if nothing else varies: libFuzzer mutates with the operands of
# the comparisons it traces, and some are addresses, so address randomisation is turned off
# (setarch -R), the environment is emptied (its size moves the stack) and every path given is
# relative; -reload=0 stops the time-driven corpus reload.
fixed=()
if [[ -n "${FUZZ_RUNS:-}" ]]; then
  fixed=(env -i "PATH=$PATH")
  if setarch "$(uname -m)" -R true 2>/dev/null; then
    fixed+=(setarch "$(uname -m)" -R)
  else
    echo "fuzz: cannot turn address randomisation off here (setarch -R); runs may differ from CI's" >&2
  fi
fi

for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/artifacts/$t"
  # The seed files of this target, in a fixed (sorted) order.
  name="${t#fuzz_}"
  seedfiles=()
  if [[ -d "fuzz/corpus/$name" ]]; then seedfiles+=(fuzz/corpus/"$name"/*); fi
  for f in ${seeds[$t]:-}; do [[ -f "$f" ]] && seedfiles+=("$f"); done
  # Seeds from the real logs: their first 64 kB (definitions and the first data), kept small.
  if [[ -n "${real_logs[$t]:-}" && -d "$shared" ]]; then
    mkdir -p "build-fuzz/real-seeds/$t"
    for f in "$shared"/*."${real_logs[$t]}"; do
      head -c 65536 "$f" > "build-fuzz/real-seeds/$t/real_$(basename "$f")"
      seedfiles+=("build-fuzz/real-seeds/$t/real_$(basename "$f")")
    done
  fi
  mapfile -t seedfiles < <(printf '%s\n' "${seedfiles[@]}" | LC_ALL=C sort -u)
  if [[ -n "${FUZZ_RUNS:-}" ]]; then
    runs="$FUZZ_RUNS"
    if [[ "$runs" == "ci" ]]; then runs="${ci_runs[$t]}"; fi
    work="build-fuzz/corpus-fixed/$t"
    rm -rf "$work"
    mkdir -p "$work"
    (IFS=,; echo "${seedfiles[*]}") > "build-fuzz/$t.seeds"
    bound=(-runs="$runs" -reload=0 -seed_inputs=@"build-fuzz/$t.seeds")
    echo "fuzz: $t for ${runs} inputs from ${#seedfiles[@]} seeds (seed ${FUZZ_SEED:-1})"
  else
    work="build-fuzz/corpus/$t"
    mkdir -p "$work"
    for f in "${seedfiles[@]}"; do cp -n "$f" "$work/seed_$(basename "$f")"; done
    bound=(-max_total_time="$seconds")
    echo "fuzz: $t for ${seconds} s from $(ls "$work" | wc -l) inputs"
  fi
  dict=()
  if [[ -n "${dicts[$t]:-}" ]]; then dict=(-dict="${dicts[$t]}"); fi
  status=0
  SECONDS=0
  "${fixed[@]}" "build-fuzz/bin/$t" "$work" -seed="${FUZZ_SEED:-1}" "${bound[@]}" "${dict[@]}" -max_len=131072 -timeout=10 \
    -rss_limit_mb=2048 -artifact_prefix="build-fuzz/artifacts/$t/" -print_final_stats=1 > "build-fuzz/$t.log" 2>&1 ||
    status=$?
  grep -E "^(stat::|Done|==[0-9]+==|SUMMARY)" "build-fuzz/$t.log" | head -n 20 || true
  echo "fuzz: $t took ${SECONDS} s"
  if ((status != 0)); then
    tail -n 60 "build-fuzz/$t.log" >&2
    echo "fuzz: $t FAILED (exit $status); reproduce with build-fuzz/bin/$t build-fuzz/artifacts/$t/<file>" >&2
    exit "$status"
  fi
done
if [[ -n "${FUZZ_RUNS:-}" ]]; then
  echo "fuzz: all ${#targets[@]} targets ran their ${FUZZ_RUNS} input counts without a finding"
else
  echo "fuzz: all ${#targets[@]} targets ran ${seconds} s each without a finding"
fi
