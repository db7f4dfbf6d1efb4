"""Vehicles, energy models and their effects, legs, optimal speeds and turns."""
import math

import pytest
import wattswath as ws

from conftest import IRIS, TESTDATA, cli_json


@pytest.fixture(scope="module")
def iris():
    return ws.load_vehicle(IRIS)


def test_vehicle_fields_match_the_cli(iris):
    hover = cli_json("hover", "--vehicle", IRIS)
    assert iris.name.startswith("3DR IRIS")
    assert iris.mass_kg == pytest.approx(1.3)
    assert iris.rotor_count == 4
    assert iris.hover_power_w == pytest.approx(hover["p_hover_w"], rel=1e-12)
    assert iris.total_efficiency == pytest.approx(iris.motor_efficiency * iris.propeller_efficiency)


def test_vehicle_round_trips_through_json(iris):
    again = ws.parse_vehicle(iris.to_json(), "round trip")
    assert again.mass_kg == iris.mass_kg and again.drag_area_m2 == iris.drag_area_m2


def test_bad_vehicle_file_names_the_file_and_field(tmp_path):
    with pytest.raises(RuntimeError, match="no_such_vehicle.json"):
        ws.load_vehicle(str(tmp_path / "no_such_vehicle.json"))
    with pytest.raises(RuntimeError, match=r"vehicle_mass_negative.json: .*field 'mass_kg' = -1.3"):
        ws.load_vehicle(str(TESTDATA / "bad" / "vehicle_mass_negative.json"))


@pytest.mark.parametrize("speed", [5.0, 10.0, 14.85])
def test_leg_energy_matches_the_cli(iris, speed):
    model = ws.marins_model(iris)
    leg = ws.leg_energy(model, iris, 600.0, speed)
    ref = cli_json("leg", "--vehicle", IRIS, "--distance", 600, "--speed", speed)
    assert leg["energy_j"] == pytest.approx(ref["energy_j"], rel=1e-9)
    assert leg["time_s"] == pytest.approx(ref["time_s"], rel=1e-9)
    for effect in ("hover", "kinetic", "parasitic_drag"):
        assert leg["by_effect"][effect] == pytest.approx(ref["breakdown"][effect], rel=1e-9, abs=1e-9)
    assert sum(leg["by_phase"].values()) == pytest.approx(leg["energy_j"], rel=1e-12)


def test_paper_drag_overcharges_the_ramps(iris):
    # README: IRIS at 600 m and 14.85 m/s, exact 14,220 J vs Eq. 9's 14,635 J.
    exact = ws.leg_energy(ws.marins_model(iris), iris, 600.0, 14.85)["energy_j"]
    paper = ws.leg_energy(ws.marins_model(iris, drag="paper"), iris, 600.0, 14.85)["energy_j"]
    assert exact == pytest.approx(14220, abs=1)
    assert paper == pytest.approx(14635, abs=1)
    with pytest.raises(ValueError, match="'exact' or 'paper'"):
        ws.marins_model(iris, drag="approximate")


def test_optimal_speed(iris):
    model = ws.build_model(iris, ["hover", "kinetic", "parasitic_drag"])
    capped = ws.optimal_speed(model, iris, 600.0)
    assert capped["speed_mps"] == pytest.approx(iris.max_speed_mps) and capped["at_upper_bound"]
    free = ws.optimal_speed(model, iris, 600.0, max_speed=40.0)
    ref = cli_json("vopt", "--vehicle", IRIS, "--distance", 600, "--max-speed", 40)
    assert free["speed_mps"] == pytest.approx(ref["v_opt_mps"], rel=1e-6)
    assert free["energy_j"] == pytest.approx(ref["energy_j"], rel=1e-9)
    assert free["energy_j"] < capped["energy_j"]
    # The optimum is a minimum: 0.5 m/s either side costs more.
    for dv in (-0.5, 0.5):
        assert ws.leg_energy(model, iris, 600.0, free["speed_mps"] + dv)["energy_j"] > free["energy_j"]


def test_turns_match_example_1(iris):
    t = ws.compare_turns(ws.marins_model(iris), iris, 100.0, math.pi / 2)
    assert t["sharp_stop"]["energy_j"] == pytest.approx(9336, abs=1)
    assert t["rounded"]["radius_m"] == pytest.approx(7.6, abs=0.05)
    assert t["saving_pct"] == pytest.approx(52.1, abs=0.05)


def test_model_effects_and_coefficients(iris):
    model = ws.build_model(iris, ["hover", "kinetic", "wind"])
    assert model.effect_names == ["hover", "kinetic", "wind"]
    assert set(model.coefficients()["wind"]) == {"drag_area", "wind_east", "wind_north"}
    info = {(c["effect"], c["name"]): c for c in model.coefficient_info()}
    assert info[("hover", "hover_power")]["unit"] == "W"
    still_air = model.power([8.0, 0.0, 0.0])
    model.set_coefficient("wind", "wind_east", 3.0)  # a tail wind: less air speed, less drag
    assert model.coefficient("wind", "wind_east") == 3.0
    assert model.power([8.0, 0.0, 0.0]) < still_air
    with pytest.raises(ValueError, match="hover.hover_power"):
        model.set_coefficient("hover", "hover_power", -5.0)
    with pytest.raises(ValueError, match="no coefficient 'speed'"):
        model.set_coefficient("wind", "speed", 1.0)
    with pytest.raises(ValueError, match="no effect 'climb'"):
        model.coefficient("climb", "climb_mass")
    with pytest.raises(ValueError, match="banana"):
        ws.build_model(iris, ["hover", "banana"])
    assert "translational_lift" in ws.known_effects()


def test_level_power_is_hover_power_at_rest(iris):
    model = ws.marins_model(iris)
    assert model.level_power(0.0) == pytest.approx(iris.hover_power_w, rel=1e-12)
    assert model.power([0.0, 0.0, 0.0], airborne=False) < model.level_power(0.0)
    with_lift = model.with_candidate("translational_lift", iris)
    assert with_lift.effect_names[-1] == "translational_lift" and not model.has("translational_lift")
