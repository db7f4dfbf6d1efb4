"""Survey areas read from files into the local ENU frame."""
import numpy as np
import pytest
import wattswath as ws

from conftest import IRIS_AREA, SHARED, TESTDATA, needs_shared


def shoelace(ring):
    x, y = ring[:, 0], ring[:, 1]
    return 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)


def test_iris_area_as_example_2():
    area = ws.read_area(IRIS_AREA)
    assert area.area_m2 == pytest.approx(20941, abs=0.5)
    assert area.perimeter_m == pytest.approx(710, abs=0.5)
    assert area.outer.shape == (11, 2) and len(area.holes) == 1
    # The area is the outer ring's (counter-clockwise: positive) minus the hole's (clockwise).
    assert shoelace(area.outer) > 0 > shoelace(area.holes[0])
    assert shoelace(area.outer) + shoelace(area.holes[0]) == pytest.approx(area.area_m2, rel=1e-9)
    lat, lon, _ = area.origin
    assert (lat, lon) == pytest.approx((43.715806, 10.462285), abs=5e-7)
    assert area.to_geodetic(*area.outer[0]) == pytest.approx((43.715946, 10.461301), abs=5e-7)


@needs_shared
def test_waypoints_area_has_a_home():
    area = ws.read_area(str(SHARED / "espiral" / "area__rectangle.waypoints"), origin="home")
    assert area.home == pytest.approx((0.0, 0.0), abs=1e-6)
    assert area.area_m2 > 0 and area.region_count == 1


def test_bad_area_names_the_file_and_edges():
    with pytest.raises(RuntimeError, match=r"bowtie.geojson: .*self-intersection: edge 0"):
        ws.read_area(str(TESTDATA / "bad" / "bowtie.geojson"))
    with pytest.raises(ValueError, match="'bbox', 'first_vertex' or 'home'"):
        ws.read_area(IRIS_AREA, origin="centre")
