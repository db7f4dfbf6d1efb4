"""Replay, residuals, diagnosis and fits: the model against measured and simulated logs."""
import numpy as np
import pytest
import wattswath as ws

from conftest import IRIS, IRIS_FLIGHT, IRIS_PLUS, TESTDATA, cli_json, needs_shared

EFFECTS = ["hover", "kinetic", "parasitic_drag"]


@pytest.fixture(scope="module")
def simulated():
    """Example 5's log: a 3 m/s east, 2 m/s south wind the model does not know (fixed seed)."""
    iris = ws.load_vehicle(IRIS)
    truth = ws.build_model(iris, ["hover", "kinetic", "wind"])
    truth.set_coefficient("wind", "wind_east", 3.0)
    truth.set_coefficient("wind", "wind_north", -2.0)
    path = ws.read_waypoint_path(str(TESTDATA / "good" / "path_lawnmower.txt"))
    log = ws.simulate_flight(path, truth, rate_hz=5.0, seed=1)
    return iris, log


@needs_shared
def test_replay_of_an_iris_plus_flight_matches_the_cli():
    vehicle = ws.load_vehicle(IRIS_PLUS)
    model = ws.build_model(vehicle, EFFECTS)
    r = ws.replay(model, ws.prepare_log(ws.read_log(str(IRIS_FLIGHT)), vehicle))
    ref = cli_json("replay", "--vehicle", IRIS_PLUS, "--effects", ",".join(EFFECTS), "--log", IRIS_FLIGHT)
    flight = ref["flights"][0]
    assert r.flight["measured_j"] == pytest.approx(flight["measured_j"], rel=1e-9)
    assert r.flight["modelled_j"] == pytest.approx(flight["modelled_j"], rel=1e-9)
    m = ws.error_metrics([r])
    assert m["rmse_w"] == pytest.approx(ref["metrics"]["rmse_w"], rel=1e-9)
    # The arrays are the samples: residual = modelled - measured, RMSE from them.
    assert np.allclose(r.residual_w, r.modelled_w - r.measured_w)
    assert np.sqrt(np.mean(r.residual_w ** 2)) == pytest.approx(m["rmse_w"], rel=1e-9)
    assert len(r.legs) == r.leg.max() + 1


def test_replay_and_residuals_of_a_simulated_log(simulated):
    iris, log = simulated
    model = ws.build_model(iris, EFFECTS)
    prepared = ws.prepare_log(log, iris)
    r = ws.replay(model, prepared)
    assert len(r) == len(log) == len(prepared)
    # Example 5: measured 30236 J, modelled 30065 J, RMSE 8.0 W.
    assert r.flight["measured_j"] == pytest.approx(30236, abs=1)
    assert r.flight["modelled_j"] == pytest.approx(30065, abs=1)
    assert ws.error_metrics([r])["rmse_w"] == pytest.approx(8.0, abs=0.05)
    tables = ws.residual_tables([r])
    speed = tables["speed"]
    assert speed["unit"] == "m/s" and speed["count"].sum() == len(r)
    assert np.allclose(speed["residual_w"], speed["modelled_mean_w"] - speed["measured_mean_w"])


def test_diagnose_finds_the_wind_and_fit_recovers_it(simulated):
    iris, log = simulated
    model = ws.build_model(iris, EFFECTS)
    prepared = ws.prepare_log(log, iris)
    d = ws.diagnose(model, iris, [prepared], candidates=["wind", "translational_lift", "climb", "payload_mass"])
    assert d["candidates"][0]["effect"] == "wind"
    assert d["candidates"][0]["improvement_pct"] > 20
    fit = ws.fit(model.with_candidate("wind", iris), [prepared])
    assert fit["train_after"]["rmse_w"] < fit["train_before"]["rmse_w"] - 2
    values = {(c["effect"], c["name"]): c for c in fit["coefficients"]}
    east, north = values[("wind", "wind_east")], values[("wind", "wind_north")]
    assert east["value"] == pytest.approx(3.0, abs=3 * east["sigma"] + 0.5)
    assert north["value"] == pytest.approx(-2.0, abs=3 * north["sigma"] + 0.5)
    fitted = fit["model"]
    assert fitted.coefficient("wind", "wind_east") == east["value"]
    replay = fit["train_replay"][0]
    assert ws.error_metrics([replay])["rmse_w"] == pytest.approx(fit["train_after"]["rmse_w"], rel=1e-9)


def test_implausible_power_is_refused_unless_trusted():
    iris = ws.load_vehicle(IRIS)
    log = ws.read_log(str(TESTDATA / "bad" / "log_current_zero.csv"))
    check = ws.check_measurement(log, iris)
    assert "0 A" in check["power_problem"] and check["position_problem"] == ""
    with pytest.raises(ValueError, match=r"log_current_zero.csv: the battery current reads 0 A.*trust_power=True"):
        ws.prepare_log(log, iris)
    assert len(ws.prepare_log(log, iris, trust_power=True)) == len(log)


def test_diverged_position_is_cut():
    iris = ws.load_vehicle(IRIS)
    log = ws.read_log(str(TESTDATA / "good" / "log_position_diverges_late.csv"))
    check = ws.check_measurement(log, iris)
    assert check["cut_at_s"] is not None
    assert len(ws.prepare_log(log, iris)) < len(log)


def test_simulation_is_reproducible_and_checks_its_input(simulated):
    iris, log = simulated
    truth = ws.build_model(iris, EFFECTS)
    path = np.array([[0, 0, 10], [100, 0, 10], [100, 50, 10]], dtype=float)
    a = ws.simulate_flight(path, truth, seed=7)
    b = ws.simulate_flight(path, truth, seed=7)
    c = ws.simulate_flight(path, truth, seed=8)
    assert np.array_equal(a.power, b.power) and not np.array_equal(a.power, c.power)
    with pytest.raises(ValueError, match=r"waypoints: expected an N x 3 array .* got shape \(3 x 2\)"):
        ws.simulate_flight(path[:, :2], truth)
