#!/usr/bin/env python3
"""Runs the numbered examples (build/bin/example_*) from the repository root, as their ctest tests
do, and writes docs/examples.md: each example's source and the output it printed. Needs a build
(scripts/build.sh); reads only bundled data.

Usage: scripts/examples_doc.py [--out docs/examples.md]
"""
import argparse
import glob
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "build", "bin")

HEADER = """# Examples: wattswath as a library

Five short programs in `examples/`, from the physics of one leg to fitting a model to a log. Each
is built with the project (`WATTSWATH_BUILD_EXAMPLES`, on by default) and runs as a ctest test
(label `example`) from the repository root on bundled data, so none of them can rot. Run one with
`build/bin/example_01_leg_and_turn` from the repository root; each takes its input files as
optional arguments. The outputs below are what they printed (regenerate this page with
`scripts/examples_doc.py`).

Using the library from your own CMake project: install it, then find the package and link the
namespaced target of what you use (`wattswath::io`, `::geometry`, `::energy`, `::logs`,
`::mission`, `::calibration`, `::planner`; each brings the ones it builds on):

```sh
cmake --install build --prefix $HOME/wattswath
```

```cmake
find_package(wattswath 0.1 REQUIRED)   # with -DCMAKE_PREFIX_PATH=$HOME/wattswath
target_link_libraries(my_program PRIVATE wattswath::planner)
```

The libraries are static, so the package also finds what they link privately (CGAL,
GeographicLib, GDAL, nlohmann_json, Ceres, NLopt, muparser, OMPL: the Debian packages
`scripts/setup.sh` installs).
`examples/consumer/` is such a project; the test `install_consumer` installs the build into a
folder and builds example 1 against it. The headers document every call (units in brackets);
`docs/architecture.md` says which library holds what.

From Python: the module `wattswath` (`python/`, pybind11) offers the same workflows with NumPy
arrays (README, section "Python"); `python/examples/plot_replay.py` is its example, a script that
replays the physics model on an IRIS+ flight, fits translational lift on the two other flights and
plots measured against modelled power and the residuals by speed (run by the ctest test
`python_example_plot_replay`, which writes `build/python/plot_replay.png`).

| example | shows | links |
|---|---|---|
"""

# (file stem, what it shows, the target it links)
EXAMPLES = [
    ("01_leg_and_turn", "the energy of a leg by effect and phase, the optimal cruise speed, a turn flown sharp or rounded",
     "wattswath::energy"),
    ("02_area_and_candidates", "reading an area into its local frame, boustrophedon and spiral coverage paths",
     "wattswath::geometry"),
    ("03_plan_and_write", "the minimum-energy plan of an area and its QGroundControl `.plan` file", "wattswath::planner"),
    ("04_predict_mission", "time, energy and battery of a mission file flown by the vehicle's autopilot",
     "wattswath::mission"),
    ("05_replay_diagnose_fit", "replaying a model on a log, diagnosing the missing effect, fitting it",
     "wattswath::calibration"),
]


def run(stem):
    exe = os.path.join(BIN, "example_" + stem)
    if not os.path.exists(exe):
        sys.exit("%s not found: build first (scripts/build.sh)" % exe)
    r = subprocess.run([exe], cwd=ROOT, capture_output=True, text=True, check=False)
    if r.returncode != 0:
        sys.exit("example_%s failed (exit %d):\n%s%s" % (stem, r.returncode, r.stdout, r.stderr))
    return r.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "examples.md"))
    args = ap.parse_args()
    sources = sorted(os.path.basename(p)[:-4] for p in glob.glob(os.path.join(ROOT, "examples", "[0-9][0-9]_*.cpp")))
    if sources != [e[0] for e in EXAMPLES]:
        sys.exit("examples/ holds %s but this script lists %s" % (sources, [e[0] for e in EXAMPLES]))
    parts = [HEADER]
    parts += ["| [%s](#%s) | %s | `%s` |\n" % (stem, stem, what, lib) for stem, what, lib in EXAMPLES]
    for stem, what, lib in EXAMPLES:
        with open(os.path.join(ROOT, "examples", stem + ".cpp"), encoding="utf-8") as f:
            source = f.read()
        parts.append("\n## %s\n\n%s (`examples/%s.cpp`, links `%s`).\n\n```cpp\n%s```\n\nOutput of "
                     "`build/bin/example_%s`:\n\n```text\n%s```\n" % (stem, what[0].upper() + what[1:], stem, lib,
                                                                      source, stem, run(stem)))
    with open(args.out, "w", encoding="utf-8") as f:
        f.write("".join(parts))
    print("wrote %s" % args.out)


if __name__ == "__main__":
    main()
