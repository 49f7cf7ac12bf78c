"""The bump normal against numpy: wind frame, scroll, tiling, mirror addressing, seed 001's layers.

An orthographic camera looks straight down on a small patch of an operator-made
lake, away from the origin, with a wind that is not +Y, at a frame where the
scroll has moved the bump. The finest sampled layer is magnified (at least one
pixel a texel), so the GPU samples mip level 0 bilinearly, as numpy does here
from the packed bump image's own pixels. Debug View 4 shows `n * 0.5 + 0.5`.
"""

import bpy
import numpy as np
import pytest
import reference_models

import harness

pytestmark = pytest.mark.render

SIZE = 4.0  # m, UV 0..1 across the plane
PATCH = 0.06  # m seen by the camera
PIXELS = 80
CENTRE = (1.1, -0.7)
WIND = (0.6, -0.8)
WIND_FORCE = 0.05
FRAME = 37
FPS = 24
LAYERS = ((1.0, 1.0), (2.0, 2.0), (4.0, 1.0), (8.0, 0.5))  # (UV scale, scroll speed) of each layer


def bump_normal_colour(image, uv, wave_length, layers, wind=WIND, seconds=FRAME / FPS, strength=1.0):
    """numpy model of Debug View 4 at plane UVs `uv` (..., 2), the first `layers` of LAYERS
    (`reference_models.bump_normal_colour`: bilinear, mirrored repeat)."""
    return reference_models.bump_normal_colour(
        image, uv, wave_length, wind, seconds, WIND_FORCE, LAYERS[:layers], strength
    )


@pytest.fixture(scope="module")
def patch(addon, eevee):
    scene = harness.clean_scene(engine=eevee, width=PIXELS, height=PIXELS, samples=1)
    scene.render.filter_size = 0.0
    scene.render.fps, scene.render.fps_base = FPS, 1.0
    bpy.ops.object.water_add(size=SIZE, wind_direction=WIND, wind_force=WIND_FORCE, mirror_setup=False)
    water = bpy.context.object
    camera = harness.add_camera(scene, (CENTRE[0], CENTRE[1], 2.0), (CENTRE[0], CENTRE[1], 0.0))
    camera.data.type = "ORTHO"
    camera.data.ortho_scale = PATCH
    camera.rotation_euler = (0.0, 0.0, 0.0)
    scene.frame_set(FRAME)
    bpy.context.view_layer.update()
    node = harness.addon("nodes.material").water_node(water.active_material)
    node.inputs["Debug View"].default_value = 4
    image = harness.addon("nodes.material").bump_image(water.active_material)
    pixels = np.empty(image.size[0] * image.size[1] * 4, dtype=np.float32)
    image.pixels.foreach_get(pixels)
    image = pixels.reshape(image.size[1], image.size[0], 4)[..., :3].astype(np.float64)
    # Plane UVs of the pixel centres, row 0 at the top.
    offsets = (np.arange(PIXELS) + 0.5) / PIXELS * PATCH - PATCH / 2
    xs, ys = np.meshgrid(CENTRE[0] + offsets, CENTRE[1] - offsets)
    uv = np.stack((xs / SIZE + 0.5, ys / SIZE + 0.5), axis=-1)
    return {"scene": scene, "node": node, "image": image, "uv": uv}


@pytest.mark.parametrize("layers, wave_length", [(1, 0.125), (4, 1.0)])
def test_normal_view_is_the_sampled_bump_in_the_wind_frame(patch, render, layers, wave_length):
    node = patch["node"]
    node.inputs["Bump Layers"].default_value = layers
    node.inputs["Wave Length"].default_value = wave_length
    pixels = render(patch["scene"], f"normal_{layers}", exr=True)[..., :3]
    model = bump_normal_colour(patch["image"], patch["uv"], wave_length, layers)
    error = np.abs(pixels - model).mean()
    assert error < 0.01, f"mean error {error:.4f}"
    assert pixels[..., :2].std() > 0.03, "a real bump fills the patch"
    # Each of these is clearly worse, so the test sees the wind frame, the scroll, the layers and the
    # tiling: the patch lies several tiles from the UV origin, so a period off by 5% misplaces it.
    wrong = {
        "+Y wind": bump_normal_colour(patch["image"], patch["uv"], wave_length, layers, wind=(0.0, 1.0)),
        "no scroll": bump_normal_colour(patch["image"], patch["uv"], wave_length, layers, seconds=0.0),
        "another layer count": bump_normal_colour(patch["image"], patch["uv"], wave_length, 5 - layers),
        "tiles 5% longer": bump_normal_colour(patch["image"], patch["uv"], 1.05 * wave_length, layers),
    }
    for what, other in wrong.items():
        assert np.abs(pixels - other).mean() > 3 * error, what
