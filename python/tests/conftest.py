"""Shared paths and helpers of the Python tests.

ctest runs them with PYTHONPATH=build/python (the module), WATTSWATH_CLI (the command line, whose
--json output the bindings are checked against) and, when ../shared/data exists,
WATTSWATH_SHARED_DATA; tests that need the shared reference data are skipped without it, as the
C++ tests that read it are not registered without it.
"""
import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "data"
TESTDATA = REPO / "tests" / "data"
SHARED = pathlib.Path(os.environ.get("WATTSWATH_SHARED_DATA", REPO.parent / "shared" / "data"))
CLI = pathlib.Path(os.environ.get("WATTSWATH_CLI", REPO / "build" / "bin" / "wattswath")).resolve()

IRIS = str(DATA / "vehicles" / "iris.json")
IRIS_PLUS = str(DATA / "vehicles" / "iris-plus-arducopter3.json")
IRIS_AREA = str(DATA / "areas" / "iris_area.geojson")
IRIS_FLIGHT = SHARED / "iris-flights" / "2017-10-18_1449_normal29.csv"

needs_shared = pytest.mark.skipif(not SHARED.is_dir(), reason="../shared/data is not beside the checkout")


def cli_json(*args):
    """Runs the wattswath command line with --json from the repository root and parses its output."""
    if not CLI.is_file():
        pytest.fail(f"the command line {CLI} is not built (set WATTSWATH_CLI)")
    out = subprocess.run([str(CLI), *map(str, args), "--json"], cwd=REPO, capture_output=True, text=True)
    if out.returncode != 0:
        pytest.fail(f"wattswath {' '.join(map(str, args))} exited with {out.returncode}: {out.stderr}")
    return json.loads(out.stdout)
