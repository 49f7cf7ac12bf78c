"""Bad input renders as water: never NaN, never black, never a crash."""

import math

import bpy
import numpy as np
import pytest
from test_add_water import BAD_INPUTS

import harness

pytestmark = pytest.mark.render

SKY = (0.3, 0.5, 0.8)


@pytest.fixture(scope="module")
def view(addon, eevee):
    scene = harness.clean_scene(engine=eevee, width=64, height=36, samples=2)
    harness.set_world_color(scene, SKY)
    camera = harness.add_camera(scene, (0, -3, 2), (0, 2, 0))
    return scene, camera


@pytest.mark.parametrize("key, given, used", BAD_INPUTS)
def test_bad_input_still_renders_lit_water(view, render, key, given, used):
    scene, camera = view
    for obj in [o for o in scene.objects if o.type != "CAMERA"]:
        bpy.data.objects.remove(obj)
    bpy.ops.object.water_add(location=(0, 2, 0), **{key: given})
    water = bpy.context.active_object
    pixels = render(scene, f"{key}-{given}", exr=True)
    assert np.isfinite(pixels).all()
    origin, rays = harness.pixel_rays(scene, camera)
    hits, reach = harness.hit_plane_z(origin, rays)
    half = water.dimensions.x / 2
    on_water = reach & (np.abs(hits[..., 0]) < half) & (np.abs(hits[..., 1] - 2) < half)
    if not on_water.any():  # a clamped 1 cm plane: still a finite image, nothing more to see
        assert math.isclose(water.dimensions.x, 0.01, rel_tol=1e-3)
        return
    # Water shows the sky and its tint: lit everywhere, not black anywhere. (The dull tint alone
    # gives 0.2 * mean(0.3, 0.3, 0.5) = 0.073; a steep bump can hide the sky from single pixels.)
    luminance = pixels[..., :3].mean(axis=-1)
    assert luminance[on_water].min() > 0.05, (key, given, luminance[on_water].min())
    assert luminance[on_water].mean() > 0.2, (key, given, luminance[on_water].mean())
