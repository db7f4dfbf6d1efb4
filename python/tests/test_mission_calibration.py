"""Mission calibration from Python: the same fit as `wattswath calibrate`, and its vehicle predicts."""
import pytest
import wattswath as ws

from conftest import DATA, IRIS_PLUS, SHARED, cli_json, needs_shared

FLIGHTS = ["2017-10-18_1436_energy14", "2017-10-18_1449_normal29"]
HELD_OUT = "2017-11-20_1610_energy14"
EVALUATIONS = 30  # a short fit: the test checks the binding, not the fit's quality


def log_path(name):
    return SHARED / "iris-flights" / f"{name}.csv"


def mission_path(name):
    return SHARED / "iris-flights" / f"mission__{name}.waypoints"


@pytest.fixture(scope="module")
def calibration():
    vehicle = ws.load_vehicle(IRIS_PLUS)
    logs = [ws.read_log(str(log_path(f))) for f in FLIGHTS]
    missions = [ws.read_mission(str(mission_path(f))) for f in FLIGHTS]
    return ws.calibrate_missions(vehicle, logs, missions, evaluations=EVALUATIONS)


@needs_shared
def test_calibration_matches_the_cli(calibration, tmp_path):
    out = tmp_path / "calibrated.json"
    args = ["calibrate", "--vehicle", IRIS_PLUS, "--out", out, "--evaluations", EVALUATIONS]
    for f in FLIGHTS:
        args += ["--log", log_path(f), "--mission", mission_path(f)]
    ref = cli_json(*args)
    assert calibration["takeoff_delay_s"] == pytest.approx(ref["takeoff_delay_s"], rel=1e-12)
    assert calibration["parameters"] == pytest.approx(ref["autopilot"]["parameters"], rel=1e-12)
    assert calibration["kept_at_start"] == ref["kept_at_start"]
    assert calibration["fitted"] == ref["fitted"]
    for mine, theirs in zip(calibration["after"], ref["after"]):
        assert mine["energy_error_pct"] == pytest.approx(theirs["energy_error_pct"], rel=1e-12)
        assert mine["time_error_pct"] == pytest.approx(theirs["time_error_pct"], rel=1e-12)
    # The calibrated vehicle predicts the held-out mission as the file the command wrote does: with
    # model None, predict_mission takes the calibration's model, take-off delay and behaviour.
    vehicle = calibration["vehicle"]
    mine = ws.predict_mission(ws.read_mission(str(mission_path(HELD_OUT))), vehicle)
    theirs = cli_json("predict", mission_path(HELD_OUT), "--vehicle", out)
    assert mine["energy_j"] == pytest.approx(theirs["energy_j"], rel=1e-12)
    assert mine["time_s"] == pytest.approx(theirs["time_s"], rel=1e-12)
    assert ws.parse_vehicle(vehicle.to_json()).to_json() == vehicle.to_json()


@needs_shared
def test_calibrated_vehicle_says_what_it_kept(calibration):
    assert calibration["before"] and calibration["after"]
    assert len(calibration["before"]) == len(FLIGHTS)
    for name in calibration["kept_at_start"]:
        assert any(n.startswith(f"{name} kept at its starting value") for n in calibration["notes"])
    assert all(isinstance(v, float) for v in calibration["parameters"].values())


@needs_shared
def test_an_uncalibrated_vehicle_needs_a_model():
    with pytest.raises(ValueError, match="no calibration"):
        ws.predict_mission(ws.read_mission(str(mission_path(HELD_OUT))), ws.load_vehicle(IRIS_PLUS))


@needs_shared
def test_logs_and_missions_must_pair():
    vehicle = ws.load_vehicle(IRIS_PLUS)
    log = ws.read_log(str(log_path(FLIGHTS[0])))
    with pytest.raises(ValueError, match="one mission per log"):
        ws.calibrate_missions(vehicle, [log], [], evaluations=EVALUATIONS)
    with pytest.raises(ValueError, match="evaluations"):
        ws.calibrate_missions(vehicle, [log], [ws.read_mission(str(mission_path(FLIGHTS[0])))], evaluations=5)


@needs_shared
def test_an_autopilot_log_read_whole_is_compared_from_the_switch_to_auto(tmp_path):
    """As the CLI: a DataFlash log of a mission is compared from AUTO to the landing, and the notes say so."""
    iris = str(DATA / "vehicles" / "iris.json")
    log = SHARED / "sitl" / "square_5mps.BIN"
    mission = SHARED / "sitl" / "square_5mps.waypoints"
    got = ws.calibrate_missions(ws.load_vehicle(iris), [ws.read_log(str(log))], [ws.read_mission(str(mission))],
                                evaluations=EVALUATIONS, keep_energy=True)
    assert any("compared from the switch to AUTO (3) at 54.10 s" in n for n in got["notes"]), got["notes"]
    ref = cli_json("calibrate", "--vehicle", iris, "--log", log, "--mission", mission, "--out", tmp_path / "v.json",
                   "--evaluations", EVALUATIONS, "--keep-energy")
    assert got["takeoff_delay_s"] == pytest.approx(ref["takeoff_delay_s"], rel=1e-12)
