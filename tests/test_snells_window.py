"""Issue 26 point 1: from below, the sky shows through Snell's window, the water below outside it.

A camera 3 m under the water looks straight up through a 12 mm lens (113° across), under a
bright, even sky, above a dark floor 12 m down. The brightness is averaged in rings of 1° about
the view's centre (the angle from straight up). The window's edge is where the rings' brightness
crosses halfway between inside (under 30°) and outside (58° to 62°): asin(1 / 1.33) = 48.75°
(the issue's 48.6° ± 2°, for 1.333). Without the work the lake's underside was a mirror (no
window) and the ocean's clear (the sky everywhere).

Checked: the lake, the seeds' ocean and the open sea in Cycles, the lake in EEVEE. EEVEE shows
outside the window what its probes hold: the lake's planar mirror probe; the ocean and the open
sea have none, so there it reflects the world (the README's limits).
"""

import math

import numpy as np
import pytest

import harness

pytestmark = pytest.mark.render

LENS = 12.0
SENSOR_HALF = 18.0  # mm: the default 36 mm sensor, fitted horizontally
CRITICAL = math.degrees(math.asin(1.0 / 1.33))


def _from_below(engine, preset, render, samples):
    scene = harness.clean_scene(engine=engine, width=96, height=96, samples=samples)
    harness.set_world_color(scene, (1.0, 1.0, 1.0))
    # The open sea in a light wind (3 m/s, waves 0.2 m high): in a rough sea the window breaks up
    # among the waves, as it does in nature, and has no one edge to measure.
    light = {"sea_wind_speed": 3.0} if preset == "open_sea" else {}
    harness.addon("api").add_water(scene, preset=preset, size=60.0, name="Water", **light)
    dark = harness.emission_material("Dark", (0.02, 0.03, 0.04))
    floor = harness.add_cube(scene, (0.0, 0.0, -12.0), size=1.0, material=dark, name="Floor")
    floor.scale = (200.0, 200.0, 1.0)
    camera = harness.add_camera(scene, (0.3, -0.2, -3.0), (0.3, -0.2, 10.0), lens=LENS)
    camera.data.sensor_fit = "HORIZONTAL"
    return render(scene, f"below_{preset}_{engine}")


def _edge(pixels):
    """(inside, outside, the angle from straight up where the brightness, averaged in 1° rings,
    crosses halfway between them)."""
    brightness = pixels[..., :3].mean(axis=2)
    height, width = brightness.shape
    rows, cols = np.mgrid[0:height, 0:width]
    u = (cols + 0.5 - width / 2) / (width / 2) * SENSOR_HALF
    v = (rows + 0.5 - height / 2) / (width / 2) * SENSOR_HALF
    angle = np.degrees(np.arctan(np.hypot(u, v) / LENS))
    inside = brightness[angle < 30.0].mean()
    outside = brightness[(angle > 58.0) & (angle < 62.0)].mean()
    half = (inside + outside) / 2.0
    angles = np.arange(30, 62)
    values = np.array([brightness[np.abs(angle - a) < 0.5].mean() for a in angles])
    below = np.nonzero(values < half)[0]
    if len(below) == 0 or below[0] == 0:
        return inside, outside, None
    i = below[0]  # the first ring under halfway, and the one before it: interpolate
    a0, a1, v0, v1 = angles[i - 1], angles[i], values[i - 1], values[i]
    return inside, outside, float(a0 + (v0 - half) / (v0 - v1) * (a1 - a0))


@pytest.mark.parametrize(
    "engine, preset",
    [("CYCLES", "lake"), ("CYCLES", "ocean"), ("CYCLES", "open_sea"), ("EEVEE", "lake")],
)
def test_the_sky_shows_through_snells_window_and_the_water_below_outside_it(
    addon, eevee, render, engine, preset
):
    engine = eevee if engine == "EEVEE" else engine
    pixels = _from_below(engine, preset, render, samples=8 if engine == "CYCLES" else 4)
    inside, outside, edge = _edge(pixels)
    print(
        f"{preset} {engine}: inside {inside:.3f}, outside {outside:.3f}, edge {edge}",
        f"(expected {CRITICAL:.2f})",
    )
    assert inside > 0.85, "the sky fills the window"
    assert inside - outside > 0.3, "outside the window the surface mirrors the dark water below"
    assert edge is not None and abs(edge - CRITICAL) < 2.0
