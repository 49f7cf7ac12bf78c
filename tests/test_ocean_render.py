"""The ocean renders the reference model in EEVEE and Cycles, and its crests move between frames.

With the bump taps off (Bump Strength 0), every pixel is predictable: the ray
meets the wave surface, whose analytic normal gives `F = dot(-eye, n) / 2 + 0.5`
and the colour `deep * F + sky * (1 - F) + mean(sky) ** 30`.
"""

import bpy
import numpy as np
import pytest

import harness

pytestmark = pytest.mark.render

SKY = np.array((0.5, 0.7, 1.0))
DEEP = np.array((0.0, 0.2, 0.4))


@pytest.fixture(scope="module")
def sea(addon, eevee):
    scene = harness.clean_scene(engine=eevee, width=128, height=72, samples=4)
    harness.set_world_color(scene, SKY)
    bpy.ops.object.water_surface_add(preset="ocean", size=80, resolution=161)
    ocean = bpy.context.active_object
    normal, _shade = harness.addon("nodes.ocean_material").ocean_nodes(ocean.active_material)
    normal.inputs["Bump Strength"].default_value = 0.0
    camera = harness.add_camera(scene, (0, -18, 22), (0, 2, 0), lens=30)
    return scene, camera


def _predicted(scene, camera):
    """The model's colour per pixel, and the mask of pixels that see the ocean."""
    wave_math = harness.addon("nodes.wave_math")
    seconds = scene.frame_current / (scene.render.fps / scene.render.fps_base)
    origin, rays = harness.pixel_rays(scene, camera)
    flat = rays.reshape(-1, 3)
    t = (0.0 - origin[2]) / flat[:, 2]
    for _ in range(20):  # walk along each ray to where it meets the lifted surface
        hits = origin + t[:, None] * flat
        t = (wave_math.heights(hits[:, :2], seconds) - origin[2]) / flat[:, 2]
    hits = origin + t[:, None] * flat
    n = wave_math.normals(hits[:, :2], seconds)
    f = (-flat * n).sum(axis=1) / 2 + 0.5
    color = DEEP * f[:, None] + SKY * (1 - f[:, None]) + SKY.mean() ** 30
    inside = (np.abs(hits[:, :2]) < 38).all(axis=1) & (t > 0)
    shape = rays.shape[:2]
    return color.reshape(*shape, 3), inside.reshape(shape)


def _error(pixels, predicted, inside):
    return np.abs(pixels[..., :3] - predicted)[inside].mean()


def test_eevee_renders_the_model_and_the_crests_move(sea, render):
    scene, camera = sea
    frames = {}
    for frame in (1, 25):
        scene.frame_set(frame)
        pixels = render(scene, f"frame-{frame}", exr=True)
        predicted, inside = _predicted(scene, camera)
        assert inside.sum() > 3000
        assert _error(pixels, predicted, inside) < 0.01, frame
        frames[frame] = (pixels, predicted, inside)
    (first, predicted_first, inside), (second, predicted_second, _) = frames[1], frames[25]
    moved = np.abs(first[..., :3] - second[..., :3]).mean(axis=-1)[inside]
    assert moved.mean() > 0.004, "the crests move in a second (the model error is under 0.01)"
    # And they move as the model says: frame 25 does not match frame 1's prediction.
    assert _error(second, predicted_first, inside) > 3 * _error(second, predicted_second, inside)


def test_cycles_renders_the_same_ocean(sea, render):
    scene, camera = sea
    scene.render.engine = "CYCLES"
    scene.cycles.samples = 8
    scene.cycles.use_denoising = False
    try:
        scene.frame_set(7)
        pixels = render(scene, "cycles", exr=True)
    finally:
        scene.render.engine = harness.addon("engine").eevee_engine_id()
    predicted, inside = _predicted(scene, camera)
    assert _error(pixels, predicted, inside) < 0.01
