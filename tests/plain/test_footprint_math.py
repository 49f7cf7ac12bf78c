"""Where a floating hull feels the water: the probes' weights give the footprint's plane."""

import math

import pytest
from conftest import load


def _heights(points, wave):
    return [wave(x, y) for x, y, _w in points]


def test_the_weights_recover_a_plane_exactly_off_centre():
    fm = load("water.boats.footprint_math")
    points = fm.probe_grid(12.0, 4.0, centre=(1.5, -0.3), long_axis="Y")
    weights = fm.plane_weights(points)
    heights = _heights(points, lambda x, y: 0.7 + 0.05 * x - 0.12 * y)
    h, sx, sy = (sum(w[i] * z for w, z in zip(weights, heights)) for i in range(3))
    assert (h, sx, sy) == pytest.approx((0.7, 0.05, -0.12), abs=1e-9)


def test_long_waves_tilt_it_as_the_footprint_and_short_ones_cancel():
    """Waves 4 hull lengths long: the probes' slope within 3% of the footprint's (continuous
    least-squares) slope, their mean within 3% of the footprint's mean; waves a quarter of its
    length: under a tenth of their own slope and height, at every phase."""
    fm = load("water.boats.footprint_math")
    length = 20.0
    points = fm.probe_grid(length, 5.0)
    weights = fm.plane_weights(points)
    for wavelength, long_waves in ((4.0 * length, True), (length / 4.0, False)):
        k = 2.0 * math.pi / wavelength
        for phase in (0.3, 1.2, 2.0, 2.9):
            heights = _heights(points, lambda x, _y, p=phase: math.sin(k * x + p))
            h = sum(w[0] * z for w, z in zip(weights, heights))
            slope = sum(w[1] * z for w, z in zip(weights, heights))
            a = k * length / 2.0
            mean = math.sin(phase) * math.sin(a) / a  # the footprint's mean height
            ls_slope = math.cos(phase) * 3.0 * (math.sin(a) - a * math.cos(a)) / (a**3) * k
            if long_waves:
                assert h == pytest.approx(mean, abs=0.03)
                assert slope == pytest.approx(ls_slope, abs=0.03 * k)
            else:
                assert abs(slope) < 0.1 * k and abs(h) < 0.1


def test_sizes_are_checked_and_the_draft_has_a_default():
    fm = load("water.boats.footprint_math")
    with pytest.raises(ValueError, match="above 0"):
        fm.probe_grid(0.0, 2.0)
    with pytest.raises(ValueError, match="odd"):
        fm.simpson(4)
    assert fm.default_draft(3.0) == pytest.approx(1.0)
    assert sum(fm.simpson(7)) == pytest.approx(1.0)
