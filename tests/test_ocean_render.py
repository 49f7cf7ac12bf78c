"""The ocean renders the reference model in EEVEE and Cycles, and its crests move between frames.

With the bump taps off (Bump Strength 0), every pixel is predictable: the ray
meets the wave surface, whose analytic normal gives `F = dot(-eye, n) / 2 + 0.5`
and the colour `deep * F + sky * (1 - F) + mean(sky) ** 30`.

With the taps on, under a bright sky image looked up as the seeds do (`Traced Sky` 0; by
default the renderer reflects the world, test_live_sky.py), numpy also samples the packed bump
image three times per pixel as the node does (bilinear, repeating), tilts the
wave normal through its tangent frame, and looks the sky image up in the
reflected direction, where `mean(sky) ** 30` is a glint of 1.5 to 5.
"""

import bpy
import numpy as np
import pytest
from reference_models import bilinear, equirect_uv, seeds_ocean_fresnel

import harness

pytestmark = pytest.mark.render

SKY = np.array((0.5, 0.7, 1.0))
DEEP = np.array((0.0, 0.2, 0.4))


@pytest.fixture(scope="module")
def sea(addon, eevee):
    # One sample: software EEVEE's cost is per sample, hardly per pixel (this module 14 s at 4
    # samples, 11 s at 1); the model is per pixel centre and holds within 0.01 either way.
    scene = harness.clean_scene(engine=eevee, width=128, height=72, samples=1)
    harness.set_world_color(scene, SKY)
    bpy.ops.object.water_add(preset="ocean", size=80, resolution=161)
    ocean = bpy.context.active_object
    normal, _shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(ocean.active_material)
    normal.inputs["Bump Strength"].default_value = 0.0
    camera = harness.add_camera(scene, (0, -18, 22), (0, 2, 0), lens=30)
    return scene, camera


def _seconds(scene):
    return scene.frame_current / (scene.render.fps / scene.render.fps_base)


def _surface(scene, camera):
    """Per pixel, flattened: ray directions, where they meet the lifted surface, its wave normal there, t."""
    wave_math = harness.addon("nodes.wave_math")
    seconds = _seconds(scene)
    origin, rays = harness.pixel_rays(scene, camera)
    flat = rays.reshape(-1, 3)
    t = (0.0 - origin[2]) / flat[:, 2]
    for _ in range(20):  # walk along each ray to where it meets the lifted surface
        hits = origin + t[:, None] * flat
        t = (wave_math.heights(hits[:, :2], seconds) - origin[2]) / flat[:, 2]
    hits = origin + t[:, None] * flat
    return flat, hits, wave_math.normals(hits[:, :2], seconds), t


def _predicted(scene, camera):
    """The model's colour per pixel, and the mask of pixels that see the ocean."""
    flat, hits, n, t = _surface(scene, camera)
    f = seeds_ocean_fresnel(-flat, n)
    color = DEEP * f[:, None] + SKY * (1 - f[:, None]) + SKY.mean() ** 30
    inside = (np.abs(hits[:, :2]) < 38).all(axis=1) & (t > 0)
    shape = scene.render.resolution_y, scene.render.resolution_x
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


@pytest.mark.lts
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


# The bright sky: an equirectangular float image whose colour is a pale blue `TINT * m`, with
# m = mean(sky) linear in the image's (u, v). Linear, so every mip level and every bilinear lookup
# of it is the same plane: only the reflected direction decides what the GPU reads. Over the
# directions this view reflects into, m runs from about 1.015 to 1.056 (brighter towards the
# horizon and towards +X), so the glint `m ** 30` runs from about 1.5 to 5.
SKY_SIZE = (64, 32)
TINT = np.array((0.9, 1.0, 1.1))
SKY_MEAN, SKY_DU, SKY_DV = 1.03, 0.08, -0.1  # m = 1.03 + 0.08 (u - 0.25) - 0.1 (v - 0.75)
# Bump taps magnified: the finest tap (3.1 Tex Stretch) spans at most 0.96 texels a pixel here,
# so the GPU samples mip level 0 and plain bilinear sampling is its model.
OCEAN_SIZE = 60.0  # m, UVs 0..1 across it
TEX_STRETCH = 0.085
BUMP_STRENGTH = 0.5  # the seeds'


def _bright_sky_pixels():
    """RGBA float pixels (H, W, 4), row 0 at the bottom (v = 0), as `Image.pixels` holds them."""
    width, height = SKY_SIZE
    u, v = np.meshgrid((np.arange(width) + 0.5) / width, (np.arange(height) + 0.5) / height)
    mean = SKY_MEAN + SKY_DU * (u - 0.25) + SKY_DV * (v - 0.75)
    pixels = np.ones((height, width, 4), dtype=np.float32)
    pixels[..., :3] = mean[..., None] * TINT
    return pixels


def _bright_sky_world(scene):
    """The world: the bright sky image, packed, as an Environment Texture."""
    pixels = _bright_sky_pixels()
    image = bpy.data.images.new("Bright Sky", SKY_SIZE[0], SKY_SIZE[1], float_buffer=True)
    image.pixels.foreach_set(pixels.ravel())
    image.use_half_precision = False  # half floats would step m by 1/1024, the glint by 3%
    image.pack()
    world = bpy.data.worlds.new("Bright Sky")
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    nodes = world.node_tree.nodes
    nodes.clear()
    environment = nodes.new("ShaderNodeTexEnvironment")
    environment.image = image
    background = nodes.new("ShaderNodeBackground")
    output = nodes.new("ShaderNodeOutputWorld")
    world.node_tree.links.new(environment.outputs["Color"], background.inputs["Color"])
    world.node_tree.links.new(background.outputs["Background"], output.inputs["Surface"])
    scene.world = world
    return pixels[..., :3].astype(np.float64)


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _bumped_ocean(surface, seconds, bump, sky, strength=BUMP_STRENGTH, taps=(1, 2, 3), swap=True, drift=True):
    """numpy model of the ocean shading with its bump taps: (colour (N, 3), glint (N,)).

    `surface` is `_surface(...)`; the keyword arguments switch parts of the model off,
    so the test can show each one matters.
    """
    eye, hits, wave_normal, _t = surface
    uv = hits[:, :2] / OCEAN_SIZE + 0.5  # the grid's UVs: 0..1 across it
    if drift:
        uv = uv + np.array((-seconds / 50.0, 0.0))
    tap_uv = {
        1: TEX_STRETCH * uv,
        2: 1.8 * TEX_STRETCH * (uv[:, ::-1] if swap else uv),
        3: 3.1 * TEX_STRETCH * uv,
    }
    tangent = sum(bilinear(bump, tap_uv[k]) - 0.5 for k in taps)  # repeating, mip level 0
    tangent[:, :2] *= strength
    tangent = _unit(tangent)
    # The wave's tangent frame: B along +X, T = N x B.
    b = _unit(np.array((1.0, 0.0, 0.0)) - wave_normal[:, :1] * wave_normal)
    t = np.cross(wave_normal, b)
    n = _unit(tangent[:, :1] * b + tangent[:, 1:2] * t + tangent[:, 2:3] * wave_normal)
    reflected = _unit(eye - 2 * (eye * n).sum(axis=1, keepdims=True) * n)
    # Blender's equirectangular lookup of a direction, clamped at the poles.
    seen = bilinear(sky, np.stack(equirect_uv(reflected), axis=-1), wrap_v="clamp")
    f = seeds_ocean_fresnel(-eye, n)[:, None]
    glint = seen.mean(axis=1) ** 30
    return DEEP * f + seen * (1 - f) + glint[:, None], glint


@pytest.fixture
def bright_sea(addon, eevee):
    """A fresh scene: the ocean under the bright sky image, seen from 12 m up, taps magnified."""
    # One sample: software EEVEE's cost is per sample, hardly per pixel (this module 14 s at 4
    # samples, 11 s at 1); the model is per pixel centre and holds within 0.01 either way.
    scene = harness.clean_scene(engine=eevee, width=128, height=72, samples=1)
    sky = _bright_sky_world(scene)  # first: the ocean material takes the world's image when made
    bpy.ops.object.water_add(preset="ocean", size=OCEAN_SIZE, resolution=241)
    ocean = bpy.context.active_object
    normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(ocean.active_material)
    shade.inputs["Traced Sky"].default_value = 0.0  # the seeds' own look-up of their sky, and its glint
    normal.inputs["Bump Strength"].default_value = BUMP_STRENGTH
    normal.inputs["Tex Stretch"].default_value = TEX_STRETCH
    image = normal.node_tree.nodes["tap_1"].image  # the packed bump image the taps sample
    bump = np.empty(image.size[0] * image.size[1] * 4, dtype=np.float32)
    image.pixels.foreach_get(bump)
    bump = bump.reshape(image.size[1], image.size[0], 4)[..., :3].astype(np.float64)
    camera = harness.add_camera(scene, (0, -10, 12), (0, 2, 0), lens=35)
    scene.frame_set(30)
    return scene, camera, bump, sky


def test_eevee_renders_the_bump_taps_and_the_glint_under_a_bright_sky(bright_sea, render):
    scene, camera, bump, sky = bright_sea
    pixels = render(scene, "bright-sky", exr=True)[..., :3].reshape(-1, 3)
    surface = _surface(scene, camera)
    _eye, hits, _n, t = surface
    assert ((np.abs(hits[:, :2]) < 28).all(axis=1) & (t > 0)).all(), "the sea fills the frame"
    # The taps are magnified, as the model assumes (the finest tap at most one texel a pixel).
    shape = scene.render.resolution_y, scene.render.resolution_x, 2
    texels = (3.1 * TEX_STRETCH * bump.shape[0] / OCEAN_SIZE) * hits[:, :2].reshape(shape)
    assert max(np.abs(np.diff(texels, axis=0)).max(), np.abs(np.diff(texels, axis=1)).max()) < 1.0
    seconds = _seconds(scene)
    model, glint = _bumped_ocean(surface, seconds, bump, sky)
    assert glint.min() > 1.2 and glint.max() > 4.0, "the glint is well above the tolerance"

    def error(predicted):
        return np.abs(pixels - predicted).mean()

    measured = error(model)
    assert measured < 0.01, f"mean error {measured:.4f}"
    # Each of these is clearly worse, so the test sees the taps and the glint.
    wrong = {
        "no taps (Bump Strength 0)": _bumped_ocean(surface, seconds, bump, sky, strength=0.0)[0],
        "no glint": model - glint[:, None],
        "the glint one value, not the reflected sky's": model - glint[:, None] + glint.mean(),
        "tap 1 left out": _bumped_ocean(surface, seconds, bump, sky, taps=(2, 3))[0],
        "tap 2 left out": _bumped_ocean(surface, seconds, bump, sky, taps=(1, 3))[0],
        "tap 3 left out": _bumped_ocean(surface, seconds, bump, sky, taps=(1, 2))[0],
        "tap 2 at uv, not uv.yx": _bumped_ocean(surface, seconds, bump, sky, swap=False)[0],
        "no drift": _bumped_ocean(surface, seconds, bump, sky, drift=False)[0],
    }
    for what, other in wrong.items():
        assert error(other) > 3 * measured, f"{what}: {error(other):.4f} against {measured:.4f}"
