#!/usr/bin/env python3
"""Plans every reference survey area with `wattswath plan --json` and writes docs/plans.md: the
plan against the three baselines (shortest path, ground-station default, best spiral), all scored
by the same model in the same run. Needs build/bin/wattswath and ../shared/data beside the checkout.

Usage: scripts/plan_table.py [--out docs/plans.md]
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(os.path.dirname(ROOT), "shared", "data")
CLI = os.path.join(ROOT, "build", "bin", "wattswath")
IRIS = os.path.join(ROOT, "data", "vehicles", "iris.json")
CAMERA = ["--altitude", "10", "--fov", "100", "--overlap", "0.1"]  # the E-Spiral camera: 21.45 m spacing

# (label, area file, extra arguments)
CASES = [
    ("IRIS+ real-flight area, no-fly zone as a hole (bundled GeoJSON)", os.path.join(ROOT, "data/areas/iris_area.geojson"),
     ["--spacing", "15"]),
    ("IRIS+ real-flight area + obstacle file (shared .waypoints)",
     os.path.join(SHARED, "iris-flights/plan__real_flight_area.waypoints"),
     ["--no-fly", os.path.join(SHARED, "iris-flights/plan__real_flight_obstacles.waypoints"), "--spacing", "15"]),
] + [("E-Spiral " + name, os.path.join(SHARED, "espiral/area__%s.waypoints" % name), CAMERA)
     for name in ("rectangle", "rectangle02", "area01", "polygon", "spiral_concave", "spiral_polygon")]


def plan(area, extra, no_spiral=False, vehicle=IRIS):
    with tempfile.TemporaryDirectory() as out:
        cmd = [CLI, "plan", area, "--vehicle", vehicle, "--out", out, "--no-report", "--json"] + extra
        if no_spiral:
            cmd.append("--no-spiral")
        t0 = time.monotonic()
        res = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.monotonic() - t0
        if res.returncode != 0:
            sys.exit("plan failed for %s:\n%s" % (area, res.stderr))
        return json.loads(res.stdout), wall


def px4_vehicle(folder):
    """The IRIS vehicle flown by PX4 1.15 with its documented defaults (an `autopilot` object)."""
    with open(IRIS) as f:
        v = json.load(f)
    v["autopilot"] = {"firmware": "PX4", "version": "1.15"}
    path = os.path.join(folder, "iris-px4.json")
    with open(path, "w") as f:
        json.dump(v, f, indent=2)
    return path


def flown_row(label, j):
    """One row of the autopilot table: the written flight and the savings against the flown baselines."""
    fl = j["flight"]
    def best(prefix):
        es = [r["energy_j"] for r in fl["finalists"] if r["label"].startswith(prefix)]
        return min(es) if es else None
    e = fl["energy_j"]
    def pct(b):
        return "-" if b is None else "%.1f" % (100.0 * (b - e) / b)
    t = int(round(fl["time_s"]))  # whole seconds first: 239.7 s is 4:00, not 3:00
    return "| %s | %s | %.1f | %d:%02d | %s | %s |" % (label, fl["written"], e / 1000, t // 60, t % 60,
                                                   pct(best("shortest path")), pct(best("ground-station default")))


def saving(base, plan_e):
    if not base:
        return "-"
    return "%.1f" % (100.0 * (base["energy_j"] - plan_e) / base["energy_j"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "plans.md"))
    args = ap.parse_args()
    rows, lines_rows, ac_rows, px4_rows = [], [], [], []
    tmp = tempfile.TemporaryDirectory()
    px4 = px4_vehicle(tmp.name)
    for label, area, extra in CASES:
        if not os.path.exists(area):
            sys.exit("missing %s (../shared/data beside the checkout?)" % area)
        print("plan_table: " + label, file=sys.stderr)
        j, wall = plan(area, extra)
        jl, _ = plan(area, extra, no_spiral=True)
        b = j["baselines"]
        cells = ", ".join("%s %s" % (c["pattern"], "" if c["pattern"] == "spiral" else "%.0f deg" % c["sweep_angle_deg"])
                          for c in j["cell_plans"])
        pattern = j["pattern"] + ("" if j["pattern"] == "spiral" else " %.0f deg" % j["sweep_angle_deg"])
        if cells and j["pattern"] == "mixed":
            pattern += " (" + cells.strip() + ")"
        rows.append("| %s | %s | %.1f | %.1f | %.0f | %.0f | %s | %s | %s | %.2f | %.2f |" % (
            label, pattern, j["energy_j"] / 1000, j["coverage_pct"], j["time_s"], j["length_m"],
            saving(b["shortest_path"], j["energy_j"]), saving(b["ground_station_default"], j["energy_j"]),
            saving(b["best_spiral"], j["energy_j"]), j["energy_j"] / j["lower_bound_j"], wall))
        ac_rows.append(flown_row(label, j))
        px4_rows.append(flown_row(label, plan(area, extra, vehicle=px4)[0]))
        lines_rows.append("| %s | %.1f | %.1f | %s |" % (
            label, jl["energy_j"] / 1000, j["energy_j"] / 1000, saving(jl, j["energy_j"])))
    with open(args.out, "w") as f:
        f.write("""# Plans on the reference areas

Generated by `scripts/plan_table.py` on %s with the IRIS vehicle (`data/vehicles/iris.json`,
Marins et al. model). Every number comes from one `wattswath plan --json` run per area: the plan and
its three baselines are scored by the same model in the same run. Savings are (baseline - plan) /
baseline. "plan / bound" is the plan's energy over the physical lower bound (README, "The answer").
Wall time is the whole command on the 2-core build machine (reading, search, checks, mission files;
no report).

E-Spiral areas use the E-Spiral camera (10 m altitude, 100 deg field of view, 10 %% side overlap:
21.45 m between passes); the IRIS+ area uses 15 m between passes.

Coverage is exact: the union of the camera footprints along every sweep line and arc (CGAL Boolean
operations, `geometry::checkCoverage`) over the area minus its no-fly zones; a plan must keep 99 %%.
Until 2026-11-23 the planner used its own sample-grid estimate, which was conservative (for one, it
left out the footprint beyond the chords of arcs) and so rejected some spirals flown with wide arcs
that keep coverage: with the exact check, the E-Spiral rectangle's plan fell from 60.9 to 59.2 kJ,
polygon from 92.5 to 84.2 kJ, and spiral_polygon became a spiral (100.9 -> 95.0 kJ).

Every flown point keeps 2 m from the no-fly zones (`plan --no-fly-margin`, default 2 m, for GPS and
tracking error; docs/missions.md): the zones are grown by the margin before the search, and coverage
is of the area outside the grown zones. Since 2026-11-24 (issue 17) this changes the two IRIS+ rows,
the only areas with a no-fly zone (before, their legs passed 1.68 m from it): the plan keeps its
66 deg sweep but its lines shift, 83.3 -> 83.2 kJ, 2025 -> 2022 m, plan / bound 2.95 (2.98 with the
obstacle file) -> 3.02 (the bound falls with the area left to cover, 28.3 -> 27.5 kJ); its baselines
change more (shortest path 84.7 -> 87.4 kJ, so the energy objective now saves 4.8 %% instead of
1.7 %%; ground-station default 127.6 -> 126.4 kJ; best spiral 170.6 -> 175.0 kJ). The E-Spiral rows
are unchanged.

No flown point is outside the area (issue 22, README "Inside the lines"): every row's plan has
`outside_area_m` = `in_no_fly_m` = 0. Until 2026-11-24 every sweep line ending on the boundary ran
on by half a spacing (7.5-10.7 m here) and turned out there. Lines now end on the boundary and
turn inside on arcs that cut back into the line; the angle search also tries each edge's direction
and the line count one below full coverage. Against the table before (same model): IRIS+ 83.2 ->
80.4 kJ, rectangle 59.2 -> 58.7, area01 68.0 -> 55.3, spiral_concave 98.7 -> 87.8, spiral_polygon
95.0 -> 92.5 (now straight lines), rectangle02 and polygon unchanged (spirals, 57.5 and 84.2);
lines only: rectangle02 62.4 -> 65.3 kJ (the only row dearer), polygon 96.9 -> 88.7. Wall times
are of an otherwise idle machine (2 cores); they halved when the cell-order search began estimating
its moves in O(1) (docs/performance.md), with every plan the same to the joule.

Since the camera-coverage fallback (2026-11-27: the camera is off along turns, so when the cheapest
plan's photos cover less than 99 %% of the area, `plan` plans again with straight sweeps only and
writes those when their photos cover more), a row may be such a second plan: its run searched no
spirals, so it has no best-spiral baseline ("-", JSON `best_spiral` null) and the straight-lines
table below shows no saving from spirals for it. The E-Spiral polygon is one: its spiral (84.2 kJ,
99.6 kJ as flown on 2026-11-27) photographed 90.5 %% of the area, the straight sweeps 97.7 %%.

| area | plan | energy [kJ] | coverage [%%] | time [s] | length [m] | saving vs shortest path [%%] | vs ground-station default [%%] | vs best spiral [%%] | plan / bound | wall [s] |
|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|
%s

The ground-station default is what QGroundControl / Mission Planner survey tools fly out of the box:
sweep lines parallel to the longest edge, one constant speed (5 m/s, ArduPilot's WPNAV_SPEED
default), a stop at every corner. The shortest path is the minimum-length boustrophedon (angle and
cell order chosen for length), flown with our optimal speeds and corners, so the saving against it
is what the energy objective itself buys. A saving of 0.0 means the energy search and the length
search found the same route.

## As the autopilot flies them

Since 2026-11-24 (issue 17) `plan` also writes each finalist (the search's choice, the per-cell
plan, the best spiral, the shortest path; arcs as chords and as waypoints along the arc) as the
mission the autopilot is told and flies it with the vehicle's autopilot model from take-off to
landing, exactly as `wattswath predict` does for the written file; the cheapest flight is written.
The ground-station default is flown too, as a baseline. Energies below are those flights (take-off,
survey, return, landing), so they are larger than the closed-form coverage energies above, and the
savings are against the flown baselines (the shortest path's cheaper arc variant).

ArduCopter 4.x firmware defaults (S-curve model; the IRIS vehicle file has no `autopilot` object):

| area | written | flown [kJ] | flown [min:s] | saving vs shortest path [%%] | vs ground-station default [%%] |
|---|---|---:|---:|---:|---:|
%s

PX4 1.15 firmware defaults (jerk-limited trajectories, MPC_XY_CRUISE 5 m/s as the default speed):

| area | written | flown [kJ] | flown [min:s] | saving vs shortest path [%%] | vs ground-station default [%%] |
|---|---|---:|---:|---:|---:|
%s

## Straight lines only

`--no-spiral` (straight parallel lines, as photogrammetry often wants) against the full search:

| area | lines only [kJ] | full search [kJ] | what spirals save [%%] |
|---|---:|---:|---:|
%s
""" % (datetime.date.today().isoformat(), "\n".join(rows), "\n".join(ac_rows), "\n".join(px4_rows), "\n".join(lines_rows)))
    print("plan_table: wrote " + args.out, file=sys.stderr)


if __name__ == "__main__":
    main()
