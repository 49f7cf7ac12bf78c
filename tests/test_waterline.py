"""Issue 40 point 2: a camera that sits in the surface shows the view above the water over the line
and the view under it below, the line following the waves where they cross the lens, drawn as a
thin dark meniscus.

The seeds' ocean (its four sines, 0.25 m cells) at frame 30; a camera whose lens (Clip Start
0.3 m) the surface crosses, pitched 4° up under an orange sky, so what is above the line is the
sky or the sky mirrored (red over 0.3) and what is below is the blue-green water (red under 0.15).
Each camera ray starts on the plane of the lens (Cycles starts it there; EEVEE clips what is
nearer): numpy puts it under the water where that start is below the sines' height there. Per
column, the row where the render turns from red to blue-green is numpy's within 1 pixel in EEVEE
and Cycles, and the line is not level (it spans 4 pixels or more across the frame: the wave's
slope at the lens). The meniscus (drawn thicker for the test: 0.03 x Clip Start, 3 pixels) lies on
numpy's line (its darkest row within 1.5 rows) and there the frame is darker than half of what
it is 4 pixels below and 5 above, in 95% of the columns. The line is measured without it. Before
the work there was no line (the view under the water was through air), and no meniscus.
"""

import bpy
import numpy as np
import pytest

import harness

pytestmark = [pytest.mark.render, pytest.mark.lts]  # new nodes (Raycast, Transform Direction) on each LTS

CLIP = 0.3
FRAME = 30
SKY = (1.0, 0.75, 0.45)
WIDTH, HEIGHT = 160, 90
PITCH = 4.0  # degrees up


def _seconds(scene):
    return scene.frame_current / (scene.render.fps / scene.render.fps_base)


def _scene(engine, meniscus):
    scene = harness.clean_scene(
        engine=engine, width=WIDTH, height=HEIGHT, samples=16 if engine == "CYCLES" else 4
    )
    harness.set_world_color(scene, SKY, 1.0)
    wave_math = harness.addon("nodes.wave_math")
    lens = wave_math.heights(np.array([[0.0, CLIP]]), FRAME / scene.render.fps)[0]
    camera = harness.add_camera(
        scene, (0.0, 0.0, lens), (0.0, 10.0, lens + 10.0 * np.tan(np.radians(PITCH))), lens=24.0
    )
    camera.data.clip_start = CLIP
    water = harness.addon("api").add_water(scene, preset="ocean", size=60.0, resolution=241).object
    body = harness.addon("water.underwater").find(water)
    harness.addon("water.waves").set_wave_input(body.modifiers[0], "Meniscus", meniscus)
    scene.frame_set(FRAME)
    return scene, camera


def _predicted_below(scene, camera):
    """(H, W) True where the pixel's ray starts under the sines' surface."""
    origin, directions = harness.pixel_rays(scene, camera)
    forward = -np.array(camera.matrix_world)[:3, 2]
    start = origin + directions * (CLIP / (directions @ forward))[..., None]
    wave_math = harness.addon("nodes.wave_math")
    height = wave_math.heights(start[..., :2].reshape(-1, 2), _seconds(scene)).reshape(start.shape[:2])
    return start[..., 2] < height


def _line_rows(below):
    """Per column, the first row (from the top) under the water, as a float."""
    return np.argmax(below, axis=0).astype(float)


@pytest.fixture(scope="module")
def views(addon, eevee):
    """{(engine, meniscus thickness): (pixels, numpy's mask of the pixels under the water)}."""
    found = {}
    for engine in ("CYCLES", eevee):
        for meniscus in (0.0, 0.03):
            scene, camera = _scene(engine, meniscus)
            path = bpy.app.tempdir + f"waterline_{engine}_{meniscus:g}.exr"
            found[engine, meniscus] = (
                harness.render(scene, path, exr=True)[..., :3],
                _predicted_below(scene, camera),
            )
    return found


@pytest.mark.parametrize("engine", ["CYCLES", "EEVEE"])
def test_the_waterline_follows_the_waves_across_the_lens(views, eevee, engine):
    engine = eevee if engine == "EEVEE" else engine
    pixels, below = views[engine, 0.0]
    predicted = _line_rows(below)
    red = pixels[..., 0]
    assert below.any(axis=0).all() and (~below).any(axis=0).all(), "the line crosses every column"
    measured = []
    for column in range(WIDTH):
        row = int(predicted[column])
        above_rows, under_rows = red[: max(row - 5, 1), column], red[min(row + 5, HEIGHT - 1) :, column]
        assert (above_rows > 0.3).mean() > 0.95, f"column {column}: above the line, the sky"
        assert (under_rows < 0.15).mean() > 0.95, f"column {column}: below it, the water"
        # The first row, from 8 over numpy's line down, under 0.15 red.
        window = red[max(row - 8, 0) : row + 8, column]
        blue = np.nonzero(window < 0.15)[0]
        measured.append(max(row - 8, 0) + blue[0] if len(blue) else np.nan)
    measured = np.array(measured, dtype=float)
    off = np.abs(measured - predicted)
    print(
        f"{engine}: numpy's line rows {predicted.min():.0f}-{predicted.max():.0f},",
        f"the render's within {np.nanmax(off):.1f} rows (median {np.nanmedian(off):.1f})",
    )
    assert predicted.max() - predicted.min() >= 4, "the line follows the wave, not level"
    assert np.all(off <= 1.0)


@pytest.mark.parametrize("engine", ["CYCLES", "EEVEE"])
def test_the_meniscus_is_a_thin_dark_line_on_it(views, eevee, engine):
    engine = eevee if engine == "EEVEE" else engine
    pixels, below = views[engine, 0.03]
    brightness = pixels.mean(axis=2)
    rows = _line_rows(below).astype(int)
    columns = np.arange(WIDTH)
    inner = (rows >= 6) & (rows < HEIGHT - 6)
    # numpy's line crosses between the row over it and its first row under: 0.5 over the latter.
    darkest = np.array([rows[c] - 6 + np.argmin(brightness[rows[c] - 6 : rows[c] + 6, c]) for c in columns])
    centre_off = np.abs(darkest - (rows - 0.5))[inner]
    line = np.min([brightness[np.clip(rows + k, 0, HEIGHT - 1), columns] for k in (-2, -1, 0, 1)], axis=0)
    over = brightness[np.clip(rows - 5, 0, HEIGHT - 1), columns]
    under = brightness[np.clip(rows + 4, 0, HEIGHT - 1), columns]
    darker = line < 0.5 * np.minimum(over, under)
    print(
        f"{engine}: on the line {np.median(line[inner]):.3f}, over it {np.median(over[inner]):.3f},",
        f"under it {np.median(under[inner]):.3f}; darker in {darker[inner].mean():.0%} of the columns;",
        f"its darkest row within {centre_off.max():.1f} rows of numpy's line",
    )
    assert darker[inner].mean() > 0.95
    assert centre_off.max() <= 1.5
