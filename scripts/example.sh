#!/usr/bin/env bash
# The README's first quick-start command: install, build, plan the minimum-energy mission of a bundled area.
set -euo pipefail
cd "$(dirname "$0")/.."
WATTSWATH_SETUP_TESTS=0 scripts/setup.sh
scripts/build.sh
build/bin/wattswath plan data/areas/iris_area.geojson --vehicle data/vehicles/iris.json --spacing 15 \
  --out out/example --force
# How the autopilot will fly the mission just written (ArduCopter 4.x defaults: the vehicle file has
# no autopilot object): time, energy and distance from take-off to landing, by phase.
build/bin/wattswath predict out/example/mission.plan --vehicle data/vehicles/iris.json
