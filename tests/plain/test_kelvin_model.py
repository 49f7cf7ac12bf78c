"""The numpy Kelvin model the wake's tests compare with (`tools/kelvin_model.py`) holds the
physics they rely on: on the track the transverse waves are 2πU²/g long; at Froude number
0.5 the highest waves stand just inside Kelvin's arms, 19.47°; above Froude number 0.5 they narrow
as about 0.2 / Fr (Rabaud and Moisy 2013; Darmon, Benzaquen and Raphaël 2014)."""

import math

import kelvin_model
import numpy as np
import pytest
from reference_models import wavelength_at_speed


def test_the_transverse_waves_on_the_track_are_2_pi_u2_over_g_long():
    speed, length = 3.0, 6.0
    x = np.arange(10.0, 40.0, 0.05)
    height = kelvin_model.field(x, np.zeros_like(x), speed, length).real
    crossings = x[1:][np.sign(height[1:]) != np.sign(height[:-1])]
    assert 2.0 * np.diff(crossings).mean() == pytest.approx(wavelength_at_speed(speed), rel=0.03)


def test_at_froude_half_the_highest_waves_stand_near_kelvins_arms():
    """A 6 m hull at 3.84 m/s (Fr 0.5), 15 to 33 m behind: the highest waves stand at Kelvin's
    angle, a little inside it, where the Airy function has its highest (a slower hull's stand
    there only much further behind: the arms fall as r^(-1/3), the transverse waves as r^(-1/2))."""
    length = 6.0
    speed = 0.5 * math.sqrt(kelvin_model.G * length)
    xs, ys = np.meshgrid(np.arange(15.0, 33.0, 0.25), np.arange(-12.0, 12.0, 0.25))
    height = kelvin_model.field(xs.ravel(), ys.ravel(), speed, length).real
    angle = kelvin_model.highest_angle(xs.ravel(), ys.ravel(), height, (15.0, 33.0))
    assert 15.0 < angle < 19.47


@pytest.mark.parametrize("froude", [1.0, 1.5, 2.0])
def test_above_froude_half_the_highest_waves_narrow_as_one_over_fr(froude):
    length = 6.0
    speed = froude * math.sqrt(kelvin_model.G * length)
    xs, ys = np.meshgrid(np.arange(15.0, 33.0, 0.25), np.arange(-12.0, 12.0, 0.25))
    height = kelvin_model.field(xs.ravel(), ys.ravel(), speed, length).real
    angle = math.radians(kelvin_model.highest_angle(xs.ravel(), ys.ravel(), height, (15.0, 33.0)))
    assert angle == pytest.approx(0.2 / froude, rel=0.3)
