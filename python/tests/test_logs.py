"""Flight logs (canonical CSV, DataFlash, ULog) as NumPy arrays."""
import numpy as np
import pytest
import wattswath as ws

from conftest import IRIS_FLIGHT, SHARED, TESTDATA, needs_shared


@needs_shared
def test_iris_flight_csv():
    log = ws.read_log(str(IRIS_FLIGHT))
    n = len(log)
    assert log.format == "csv" and n > 300
    assert log.position.shape == (n, 3) and log.velocity.shape == (n, 3) and log.acceleration.shape == (n, 3)
    assert np.all(np.diff(log.t) > 0)
    assert log.duration == pytest.approx(log.t[-1] - log.t[0])
    # Power is voltage times current where the file gives both.
    assert np.allclose(log.power, log.voltage * log.current, rtol=1e-12)
    assert 100 < np.median(log.power) < 400  # an IRIS+ (about 1.5 kg) cruises on 200-300 W
    again = ws.parse_csv_log(log.to_csv(), "round trip")
    assert np.array_equal(again.t, log.t) and np.array_equal(again.power, log.power)


@needs_shared
def test_time_window():
    full = ws.read_log(str(IRIS_FLIGHT))
    part = ws.read_log(str(IRIS_FLIGHT), from_s=full.t[0] + 60, to_s=full.t[0] + 120)
    assert part.t[0] >= full.t[0] + 60 and part.t[-1] <= full.t[0] + 120 and len(part) < len(full)


@needs_shared
@pytest.mark.parametrize("name, fmt", [("arducopter-3.5_quad_rtl.bin", "dataflash"),
                                       ("px4-1.9_quad_mission_rtl.ulg", "ulog")])
def test_autopilot_logs(name, fmt):
    log = ws.read_log(str(SHARED / "autopilot-logs" / name))
    assert log.format == fmt and len(log) > 50 and log.duration > 30
    assert np.all(np.isfinite(log.position)) and np.all(np.diff(log.t) > 0)
    assert log.airborne and all(b < e for b, e in log.airborne)
    assert any(e["kind"] == "mode" for e in log.events)


def test_bad_logs_name_file_line_and_column():
    with pytest.raises(RuntimeError, match=r"log_position_inf.csv:3: column 'x_m' \(field 2\): value 'inf'"):
        ws.read_log(str(TESTDATA / "bad" / "log_position_inf.csv"))
    with pytest.raises(RuntimeError, match=r"log_missing_power.csv:1: missing required column 'voltage_v'"):
        ws.read_log(str(TESTDATA / "bad" / "log_missing_power.csv"))


def test_waypoint_path():
    path = ws.read_waypoint_path(str(TESTDATA / "good" / "path_lawnmower.txt"))
    assert path.ndim == 2 and path.shape[1] == 3 and len(path) >= 2
