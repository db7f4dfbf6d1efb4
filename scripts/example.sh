#!/usr/bin/env bash
# The README's first quick-start command: install, build, run the main job on a bundled area.
set -euo pipefail
cd "$(dirname "$0")/.."
WATTSWATH_SETUP_TESTS=0 scripts/setup.sh
scripts/build.sh
build/bin/wattswath hover --vehicle data/vehicles/iris.json
