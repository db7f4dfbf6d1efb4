"""Mission files and their prediction as the vehicle's autopilot flies them."""
import numpy as np
import pytest
import wattswath as ws

from conftest import IRIS_PLUS, TESTDATA, cli_json

SURVEY = str(TESTDATA / "good" / "mission_survey.plan")


@pytest.fixture(scope="module")
def prediction():
    vehicle = ws.load_vehicle(IRIS_PLUS)
    model = ws.build_model(vehicle, ["hover", "kinetic", "parasitic_drag"])
    return ws.predict_mission(ws.read_mission(SURVEY), vehicle, model)


def test_mission_file():
    m = ws.read_mission(SURVEY)
    assert m.format == "plan" and len(m) == 13 and len(m.commands) == 13
    assert "NAV_WAYPOINT" in m.commands
    assert m.home[:2] == pytest.approx((43.716004, 10.461304), abs=5e-7)


def test_prediction_as_example_4(prediction):
    # Example 4: 111 s, 23795 J, 345 m with the ArduCopter 3.2 leash model.
    assert prediction["autopilot"]["model"] == "arducopter-leash"
    assert prediction["energy_j"] == pytest.approx(23795, abs=1)
    assert prediction["time_s"] == pytest.approx(111, abs=1)
    assert prediction["distance_m"] == pytest.approx(345, abs=1)
    phases = prediction["phases"]
    assert sum(p["energy_j"] for p in phases.values()) == pytest.approx(prediction["energy_j"], rel=1e-9)
    assert prediction["breakdown"]["energy_j"] == pytest.approx(prediction["energy_j"], rel=1e-9)
    assert prediction["battery"]["known"] and prediction["battery"]["fits"]
    assert 0 < prediction["battery"]["usable_left_end"] < 1


def test_prediction_matches_the_cli(prediction):
    ref = cli_json("predict", SURVEY, "--vehicle", IRIS_PLUS, "--effects", "hover,kinetic,parasitic_drag")
    for key in ("energy_j", "time_s", "distance_m"):
        assert prediction[key] == pytest.approx(ref[key], rel=1e-9)


def test_trajectory_arrays(prediction):
    tr = prediction["trajectory"]
    n = len(tr["t"])
    assert tr["position"].shape == (n, 3) and tr["velocity"].shape == (n, 3) and len(tr["phase"]) == n
    assert np.all(np.diff(tr["t"]) > 0)
    assert tr["phase"][0] == "takeoff" and tr["phase"][-1] == "landing"
    # The path length of the samples is the distance flown (0.1 s samples: within 1 %).
    length = np.sum(np.linalg.norm(np.diff(tr["position"], axis=0), axis=1))
    assert length == pytest.approx(prediction["distance_m"], rel=0.01)


def test_bad_mission_names_the_item():
    with pytest.raises(RuntimeError, match="mission_bad_frame.waypoints"):
        ws.read_mission(str(TESTDATA / "bad" / "mission_bad_frame.waypoints"))


def test_wind_matches_the_cli():
    # 6 m/s from the east is air moving west: wind=(-6, 0); the same as `predict --wind 6,90`.
    vehicle = ws.load_vehicle(IRIS_PLUS)
    model = ws.build_model(vehicle, ["hover", "kinetic", "parasitic_drag"])
    p = ws.predict_mission(ws.read_mission(SURVEY), vehicle, model, wind=(-6.0, 0.0))
    ref = cli_json("predict", SURVEY, "--vehicle", IRIS_PLUS, "--effects", "hover,kinetic,parasitic_drag", "--wind", "6,90")
    assert p["energy_j"] == pytest.approx(ref["energy_j"], rel=1e-9)
    assert "wind" in p["breakdown"]["by_effect"] and p["energy_j"] > ws.predict_mission(ws.read_mission(SURVEY), vehicle, model)["energy_j"]
