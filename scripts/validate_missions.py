#!/usr/bin/env python3
"""Mission prediction on the shared IRIS+ flights, leave one flight out (issue 16).

For each flight: `wattswath calibrate` on the other two (logs + missions) writes a calibrated
vehicle; `wattswath predict` then predicts the held-out flight from its mission file alone, and
`wattswath replay --mission` compares it leg by leg with its log. The uncalibrated row is the same
prediction with the firmware's documented defaults and the vehicle's physics (Marins et al. model).
Measured take-off-to-landing energy and time come from ../shared/data/iris-flights/measured_phases.json.
Its times count from the take-off command; ArduCopter 3.x on the ground in AUTO starts the mission only
when the pilot raises the throttle, so the time is also compared from the log's first sample with the
motors spinning (the pilot's wait is not in the mission file; no energy is drawn during it).
Prints a Markdown table (docs/validation.md, "Missions predicted from the mission file").

Usage: scripts/validate_missions.py [--binary build/bin/wattswath] [--json]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DATA = os.path.join(ROOT, "..", "shared", "data", "iris-flights")
FLIGHTS = ["2017-10-18_1436_energy14", "2017-10-18_1449_normal29", "2017-11-20_1610_energy14"]
BASE = os.path.join(ROOT, "data", "vehicles", "iris-plus-arducopter3.json")


def run(binary, args):
    out = subprocess.run([binary] + args, check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def log(f):
    return os.path.join(DATA, f + ".csv")


def mission(f):
    return os.path.join(DATA, "mission__" + f + ".waypoints")


def pilot_wait_s(f):
    """Time [s] from the take-off command (t = 0 in the log) to its first sample with the motors spinning."""
    with open(log(f)) as fh:
        for line in fh:
            if line.startswith("#") or line.startswith("time_s"):
                continue
            return float(line.split(",")[0])
    raise ValueError(f"{log(f)}: no samples")


def row(binary, vehicle, f, measured, effects=None):
    extra = ["--effects", effects] if effects else []
    p = run(binary, ["predict", mission(f), "--vehicle", vehicle, "--json"] + extra)
    r = run(binary, ["replay", "--vehicle", vehicle, "--log", log(f), "--mission", mission(f), "--json"] + extra)
    m = r["mission_prediction"][0]
    return {
        "flight": f,
        "energy_j": p["energy_j"],
        "time_s": p["time_s"],
        "energy_error_pct": 100.0 * (p["energy_j"] - measured["E_takeoff_to_land_J"]) / measured["E_takeoff_to_land_J"],
        "time_error_pct": 100.0 * (p["time_s"] - measured["T_takeoff_to_land_s"]) / measured["T_takeoff_to_land_s"],
        "pilot_wait_s": pilot_wait_s(f),
        "time_from_spin_up_error_pct": 100.0 * (p["time_s"] - (measured["T_takeoff_to_land_s"] - pilot_wait_s(f)))
        / (measured["T_takeoff_to_land_s"] - pilot_wait_s(f)),
        "leg_time_mape_pct": m["leg_time_mape_pct"],
        "legs": m["legs_matched"],
        "kinematics_error_j": m["kinematics_error_j"],
        "physics_error_j": m["physics_error_j"],
        "coverage": p.get("calibration_coverage"),
        "dispute": p.get("calibration_dispute"),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=os.path.join(ROOT, "build", "bin", "wattswath"))
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    measured = json.load(open(os.path.join(DATA, "measured_phases.json")))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for f in FLIGHTS:
            rows.append(("firmware defaults, vehicle physics", row(a.binary, BASE, f, measured[f], "hover,kinetic,parasitic_drag")))
            train = [g for g in FLIGHTS if g != f]
            out = os.path.join(tmp, "calibrated_without_" + f + ".json")
            args = ["calibrate", "--vehicle", BASE, "--out", out, "--json"]
            for g in train:
                args += ["--log", log(g), "--mission", mission(g)]
            cal = run(a.binary, args)
            r = row(a.binary, out, f, measured[f])
            r["fitted"] = cal["fitted"]
            r["flights_agree"] = cal.get("flights_agree")
            rows.append(("calibrated on the other two flights", r))
    if a.json:
        print(json.dumps([{"model": m, **r} for m, r in rows], indent=1))
        return
    print("| held-out flight | prediction | energy [kJ] | error [%] | time [s] | error [%] | error from spin-up [%] (pilot's wait [s]) | leg time MAPE [%] (legs) | kinematics / physics error [kJ] |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for m, r in rows:
        print(f"| {r['flight']} | {m} | {r['energy_j'] / 1000:.1f} | {r['energy_error_pct']:+.1f} | {r['time_s']:.0f} | "
              f"{r['time_error_pct']:+.1f} | {r['time_from_spin_up_error_pct']:+.1f} ({r['pilot_wait_s']:.1f}) | {r['leg_time_mape_pct']:.1f} ({r['legs']}) | "
              f"{r['kinematics_error_j'] / 1000:+.1f} / {r['physics_error_j'] / 1000:+.1f} |")
    print()
    for m, r in rows:
        for key, what in (("dispute", "calibration dispute"), ("coverage", "calibration coverage")):
            if r.get(key):
                print(f"- {r['flight']}, {m}, {what}: {r[key]['text']}")
    print()
    for m, r in rows:
        if "fitted" in r:
            agree = {True: "the two flights agree", False: "the two flights do not agree", None: "agreement not assessed"}[r.get("flights_agree")]
            print(f"- without {r['flight']} ({agree}): " + "; ".join(r["fitted"]))


if __name__ == "__main__":
    sys.exit(main())
