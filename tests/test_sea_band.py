"""No band where the open sea's waves fade out: from 3, 12, 40 and 150 m up under a plain sky, the
mean of each row of sea pixels stays within 3% of a smooth curve through them (a quartic in the
row), from the foreground to the horizon. The far sea, flat past half a tile, is shaded by the bump
alone, whose slopes are the sea's (test_sea_slopes.py); the whitecaps are scattered, not blotches
(test_whitecaps.py). Averaged over two moments, so one big wave in the foreground is not a band.
The wind (0.8, 0.6) is off the view's axis.
"""

import bpy
import numpy as np
import pytest

import harness

pytestmark = pytest.mark.render

HEIGHTS = (3.0, 12.0, 40.0, 150.0)
FRAMES = (1, 41)


@pytest.fixture(scope="module")
def rows(addon, eevee):
    """{height: (row means of sea pixels, averaged over FRAMES)} of the 15 m/s sea."""
    scene = harness.clean_scene(engine=eevee, width=160, height=90, samples=1)
    harness.set_world_color(scene, (0.45, 0.6, 0.8), 1.0)
    harness.addon("api").add_water(scene, preset="open_sea", sea_wind_speed=15.0, wind_direction=(0.8, 0.6))
    found = {}
    for height in HEIGHTS:
        camera = harness.add_camera(scene, (0.0, 0.0, height), (300.0, 1000.0, height - 90.0), lens=28.0)
        camera.data.clip_end = 30000.0
        scene.camera = camera
        directions = harness.pixel_rays(scene, camera)[1]
        sea_rows = [r for r in range(directions.shape[0]) if (directions[r, :, 2] < -0.01).all()]
        means = []
        for frame in FRAMES:
            scene.frame_set(frame)
            image = harness.render(scene, bpy.app.tempdir + f"band_{height:g}_{frame}.png")
            means.append(image[sea_rows, :, :3].mean(axis=(1, 2)))
        found[height] = np.mean(means, axis=0)
    return found


@pytest.mark.parametrize("height", HEIGHTS)
def test_the_sea_s_brightness_changes_smoothly_to_the_horizon(rows, height):
    means = rows[height]
    x = np.arange(len(means))
    smooth = np.polyval(np.polyfit(x, means, 4), x)
    deviation = np.abs(means / smooth - 1.0)
    worst = deviation.argmax()
    print(f"{height:g} m up: {len(means)} rows, largest deviation {deviation[worst]:.2%} at row {worst}")
    assert len(means) > 30
    assert deviation.max() <= 0.03
