#!/usr/bin/env python3
"""Measured versus modelled power of an IRIS+ flight, and an effect fitted to the residuals.

Loads a flight log, replays the physics model (hover, kinetic, parasitic drag, coefficients from
the vehicle file) on its kinematics, fits the model with translational lift added on the other
IRIS+ flights (held out: this flight is not in the fit) and writes a PNG of the measured and
modelled power over time and the residuals binned by speed.

Usage (from anywhere, with the module on PYTHONPATH, e.g. PYTHONPATH=build/python):
    python3 python/examples/plot_replay.py [--log F.csv] [--train G.csv ...] [--out replay.png]
"""
import argparse
import os
import pathlib
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import wattswath as ws  # noqa: E402

REPO = pathlib.Path(__file__).resolve().parents[2]
FLIGHTS = REPO.parent / "shared" / "data" / "iris-flights"


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--vehicle", default=str(REPO / "data" / "vehicles" / "iris-plus-arducopter3.json"))
    p.add_argument("--log", default=str(FLIGHTS / "2017-10-18_1449_normal29.csv"), help="the flight to plot")
    p.add_argument("--train", nargs="*", default=[str(FLIGHTS / "2017-10-18_1436_energy14.csv"),
                                                  str(FLIGHTS / "2017-11-20_1610_energy14.csv")],
                   help="flights the effect is fitted on")
    p.add_argument("--out", default="replay.png", help="PNG to write")
    return p.parse_args()


def save_png(fig, out):
    """Writes the figure atomically: to a temporary file beside `out`, then renamed."""
    folder = os.path.dirname(os.path.abspath(out))
    fd, tmp = tempfile.mkstemp(suffix=".png", dir=folder)
    os.close(fd)
    try:
        fig.savefig(tmp, dpi=110)
        os.replace(tmp, out)
    except BaseException:
        os.unlink(tmp)
        raise


def main():
    args = parse_args()
    vehicle = ws.load_vehicle(args.vehicle)
    physics = ws.build_model(vehicle, ["hover", "kinetic", "parasitic_drag"])
    flight = ws.prepare_log(ws.read_log(args.log), vehicle)  # refuses a log whose power is not plausible
    train = [ws.prepare_log(ws.read_log(f), vehicle) for f in args.train]

    before = ws.replay(physics, flight)
    fit = ws.fit(physics.with_candidate("translational_lift", vehicle), train, [flight])
    after = fit["test_replay"][0]
    for label, r, m in (("physics", before, fit["test_before"]), ("fitted", after, fit["test_after"])):
        print(f"{label:8s} measured {r.flight['measured_j']:7.0f} J, modelled {r.flight['modelled_j']:7.0f} J "
              f"({r.flight['error_pct']:+.1f} %), RMSE {m['rmse_w']:.1f} W")
    for c in fit["coefficients"]:
        state = "" if c["determined"] else " (not determined)"
        print(f"  {c['effect']}.{c['name']} = {c['value']:.4g} {c['unit']}{state}")

    fig, (ax_t, ax_v) = plt.subplots(2, 1, figsize=(9, 7))
    t = before.t - before.t[0]
    ax_t.plot(t, before.measured_w, color="0.3", lw=0.8, label="measured")
    ax_t.plot(t, before.modelled_w, lw=1.0, label=f"physics ({fit['test_before']['rmse_w']:.1f} W RMSE)")
    ax_t.plot(t, after.modelled_w, lw=1.0, label=f"fitted on other flights ({fit['test_after']['rmse_w']:.1f} W)")
    ax_t.set(xlabel="time [s]", ylabel="power [W]", title=os.path.basename(args.log))
    ax_t.legend(loc="lower center", fontsize=8)
    for label, r in (("physics", before), ("fitted", after)):
        bins = ws.residual_tables([r])["speed"]
        ax_v.plot(0.5 * (bins["lo"] + bins["hi"]), bins["residual_w"], "o-", label=label)
    ax_v.axhline(0.0, color="0.5", lw=0.8)
    ax_v.set(xlabel="horizontal speed [m/s]", ylabel="mean residual, modelled - measured [W]")
    ax_v.legend(fontsize=8)
    fig.tight_layout()
    save_png(fig, args.out)
    print(f"wrote {args.out}: {len(t)} samples, residual RMSE {np.sqrt(np.mean(before.residual_w ** 2)):.1f} W "
          f"-> {np.sqrt(np.mean(after.residual_w ** 2)):.1f} W")
    return 0


if __name__ == "__main__":
    sys.exit(main())
