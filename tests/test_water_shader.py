"""The `Water Surface` group renders the reference model: measured per pixel against numpy.

The water is placed as a user would leave it, not as it is made: moved (up too), turned about Z
by 30 degrees and scaled unevenly, with a wind along no axis. The models work from its transform:
where the camera's rays meet its plane, which of those points lie on it, and its UVs and tangent
frame there (the bump, its wind and the normal are in the water's own UV space).
"""

import math

import bpy
import numpy as np
import pytest
from mathutils import Vector
from reference_models import bump_normal_colour, flat_glint, lake_composition, lake_fresnel

import harness

pytestmark = pytest.mark.render

SKY = (0.4, 0.6, 0.9)
CAMERA_AT = (0.0, -6.0, 2.5)
WATER_SIZE = 8.0  # before scaling: UVs 0..1 across it
WATER_AT = (0.6, -0.3, 0.2)
WATER_TURN = math.radians(30.0)
WATER_SCALE = (1.25, 0.8, 1.0)
WIND = (-0.6, 0.8)  # in the water's UV space


def _water_material():
    return harness.addon("nodes.material")


@pytest.fixture(scope="module")
def lake(addon, eevee):
    """One scene for the module: water, a sky, a red floor under it, a green block above it, a sun."""
    # One sample: software EEVEE's cost is per sample, hardly per pixel (measured: 5 s a render, 14 s
    # at 4 samples, the same at 64 x 36 and 256 x 144). At 1 sample the models fit as closely (the
    # bump normal's mean error 0.0007 either way, each wrong placement as far off) and frames 1
    # and 25 differ by 0.016 with wind (0.014 at 4 samples), none without.
    scene = harness.clean_scene(engine=eevee, width=128, height=72, samples=1)
    harness.addon("engine").enable_ray_tracing(scene)
    harness.set_world_color(scene, SKY)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    scene.collection.objects.link(sun)
    added = harness.addon("api").add_water(
        scene,
        size=WATER_SIZE,
        wind_direction=WIND,
        location=WATER_AT,
        rotation=(0.0, 0.0, WATER_TURN),
        mirror_setup=False,
        see_surroundings=False,
    )
    water = added.object
    water.scale = WATER_SCALE
    harness.add_cube(
        scene, (0, 0, -1.2), size=2.0, material=harness.emission_material("Floor", (1, 0.1, 0.05))
    )
    harness.add_cube(
        scene, (1.5, 1.5, 0.8), size=1.0, material=harness.emission_material("Block", (0.1, 1, 0.1))
    )
    camera = harness.add_camera(scene, CAMERA_AT, (0, 0, 0))
    return {
        "scene": scene,
        "water": water,
        "material": added.material,
        "node": _water_material().water_node(added.material),
        "sun": sun,
        "camera": camera,
    }


@pytest.fixture
def water(lake):
    """The lake with the group's defaults restored after each test."""
    node = lake["node"]
    saved = {
        s.name: tuple(s.default_value) if hasattr(s.default_value, "__len__") else s.default_value
        for s in node.inputs
        if hasattr(s, "default_value")
    }
    yield lake
    for name, value in saved.items():
        socket = node.inputs[name]
        if not socket.is_linked and not _driven(lake["material"], socket):
            socket.default_value = value
    lake["scene"].frame_set(1)


def _driven(material, socket):
    animation = material.node_tree.animation_data
    path = socket.path_from_id("default_value")
    return any(fc.data_path == path for fc in (animation.drivers if animation else ()))


def _aim_sun(sun, direction):
    sun.rotation_euler = Vector(direction).to_track_quat("-Z", "Y").to_euler()
    bpy.context.view_layer.update()


def _on_water(lake, camera=None):
    """Where each pixel's ray meets the water's plane, (H, W, 3) world and the water's own
    coordinates, and the mask of rays that reach it."""
    origin, directions = harness.pixel_rays(lake["scene"], camera or lake["camera"])
    hits, ok = harness.hit_plane_z(origin, directions, WATER_AT[2])
    to_water = np.linalg.inv(np.array(lake["water"].matrix_world))
    local = hits @ to_water[:3, :3].T + to_water[:3, 3]
    return origin, hits, local, ok


def _flat_water_mask(lake, render):
    """Pixels showing the water plane itself (not the block, not the sky), from the flat normal view.

    Leaves the water flat (Bump Strength 0) on Debug View 4. That view of the flat water is the same
    whatever the frame, wind, wave length or sun, so it is rendered once for the module (from the
    lake's camera, the only one the tests that ask for the mask use)."""
    node = lake["node"]
    node.inputs["Bump Strength"].default_value = 0.0
    node.inputs["Debug View"].default_value = 4
    if "flat" not in lake:
        normal = render(lake["scene"], "mask", exr=True)
        lake["flat"] = np.all(np.abs(normal[..., :3] - (0.5, 0.5, 1.0)) < 0.01, axis=-1)
    flat = lake["flat"]
    origin, hits, local, ok = _on_water(lake)
    # 0.4 m inside the water's edges (in world metres: the water is scaled), and a pixel from
    # anything else: an edge pixel's filter blends in what lies beyond it.
    margin = 0.4 / np.array(WATER_SCALE[:2])
    inside = ok & (np.abs(local[..., :2]) < WATER_SIZE / 2 - margin).all(axis=-1)
    for axis in (0, 1):
        for shift in (1, -1):
            flat = flat & np.roll(flat, shift, axis)
    return flat & inside, origin, hits


def test_fresnel_view_matches_dot_eye_up(water, render):
    mask, origin, hits = _flat_water_mask(water, render)
    assert mask.sum() > 1000
    water["node"].inputs["Debug View"].default_value = 3
    pixels = render(water["scene"], "fresnel", exr=True)
    expected = lake_fresnel(origin - hits)
    error = np.abs(pixels[..., 0] - expected)[mask]
    assert error.mean() < 0.02, f"mean error {error.mean():.4f}"
    # Grey: F in every channel; and it spans a real range over this view.
    assert np.allclose(pixels[..., 0][mask], pixels[..., 2][mask], atol=2e-3)
    assert expected[mask].max() - expected[mask].min() > 0.2


def test_glint_view_matches_the_formula_and_follows_the_sun(water, render):
    mask, origin, hits = _flat_water_mask(water, render)
    node = water["node"]
    node.inputs["Specular Power"].default_value = 64.0
    node.inputs["Specular Strength"].default_value = 2.0
    node.inputs["Debug View"].default_value = 5
    peaks = []
    for target in ((0.0, 0.0, WATER_AT[2]), (2.0, 1.5, WATER_AT[2])):
        # Aim the sun so that its mirror image reaches the camera from `target`.
        eye = Vector(CAMERA_AT) - Vector(target)
        sun_dir = (eye.x, eye.y, -eye.z)
        _aim_sun(water["sun"], Vector(sun_dir).normalized())
        pixels = render(water["scene"], f"glint_{len(peaks)}", exr=True)
        expected = flat_glint(origin - hits, sun_dir, 64.0, 2.0)
        error = np.abs(pixels[..., 0] - expected)[mask]
        assert error.mean() < 0.02, f"mean error {error.mean():.4f}"
        assert expected[mask].max() > 1.5  # the glint is in view, so the comparison means something
        row, col = np.unravel_index(np.argmax(np.where(mask, pixels[..., 0], 0)), mask.shape)
        ((want_col, want_row),) = harness.world_to_pixel(water["scene"], water["camera"], [target])
        assert abs(col - want_col) <= 3 and abs(row - want_row) <= 3
        peaks.append((row, col))
    assert math.dist(*peaks) > 15


@pytest.mark.lts
def test_final_view_is_the_composition_of_the_debug_views(water, render):
    node = water["node"]
    # Sun straight down: its mirror highlight (a lamp's specular on the sharp glossy) stays out of view.
    _aim_sun(water["sun"], (0.0, 0.0, -1.0))
    views = {}
    for number in (0, 1, 2, 3, 5):
        node.inputs["Debug View"].default_value = number
        views[number] = render(water["scene"], f"view_{number}", exr=True)[..., :3]
    mask, _origin, _hits = _flat_water_mask(water, render)
    blend = node.inputs["Dull Blend"].default_value
    dull = np.array(node.inputs["Dull Color"].default_value[:3])
    f = views[3][..., :1]
    model = lake_composition(views[1], views[2], f, blend, dull, views[5])
    error = np.abs(views[0] - model)[mask]
    # The refraction's weight squared, as EEVEE gives with Thickness left unconnected.
    squared = (1 - blend) * ((1 - f) * views[1] + f * f * views[2]) + blend * dull + views[5]
    wrong = np.abs(views[0] - squared)[mask]
    assert error.mean() < 0.01, f"mean error {error.mean():.4f}"
    assert wrong.mean() > 3 * error.mean()
    # Reflection and refraction differ here (sky vs red floor), so the blend is really tested.
    assert np.abs(views[1] - views[2])[mask].mean() > 0.1


def test_two_frames_differ_only_with_wind(water, render):
    node, scene = water["node"], water["scene"]
    mask, _origin, _hits = _flat_water_mask(water, render)
    node.inputs["Bump Strength"].default_value = 1.0
    node.inputs["Debug View"].default_value = 0
    # One bump tile across this small plane, so its ripples span pixels instead of averaging out in one.
    node.inputs["Wave Length"].default_value = 1.0
    differences = {}
    for wind in (0.02, 0.0):
        node.inputs["Wind Force"].default_value = wind
        frames = []
        for frame in (1, 25):
            scene.frame_set(frame)
            frames.append(render(scene, f"wind_{wind}_frame_{frame}", exr=True)[..., :3])
        differences[wind] = np.abs(frames[0] - frames[1])[mask].mean()
    print(f"frames 1 and 25 differ by {differences[0.02]:.4f} with wind, {differences[0.0]:.5f} without")
    assert differences[0.02] > 0.01
    assert differences[0.0] < 0.1 * differences[0.02]


def test_time_follows_the_scene_clock(water):
    scene, material = water["scene"], water["material"]
    scene.render.fps, scene.render.fps_base = 24, 1.0
    scene.frame_set(49)
    evaluated = material.evaluated_get(bpy.context.evaluated_depsgraph_get())
    time = _water_material().water_node(evaluated).inputs["Time"].default_value
    assert time == pytest.approx(49 / 24)
    drivers = material.node_tree.animation_data.drivers
    assert all(fc.driver.is_simple_expression for fc in drivers)


@pytest.mark.lts
def test_group_renders_in_cycles(water, render):
    scene, node = water["scene"], water["node"]
    eevee = scene.render.engine
    scene.render.engine = "CYCLES"
    scene.cycles.samples = 16
    scene.cycles.device = "CPU"
    node.inputs["Wave Height"].default_value = 0.0
    node.inputs["Dull Blend"].default_value = 0.0
    try:
        pixels = render(scene, "cycles", exr=True)
    finally:
        scene.render.engine = eevee
    assert np.isfinite(pixels).all()
    # Reflective: the green block's mirror image shows under it, in green (a point 0.1 m above
    # its foot, mirrored in the water's plane).
    mirrored = (1.5, 1.5, 2.0 * WATER_AT[2] - 0.4)
    ((col, row),) = harness.world_to_pixel(scene, water["camera"], [mirrored])
    patch = pixels[int(row) - 1 : int(row) + 2, int(col) - 1 : int(col) + 2, :3].mean(axis=(0, 1))
    assert patch[1] > 0.3 and patch[1] > 2 * patch[0]


def test_zero_wind_gives_finite_water_that_scrolls_along_y(water, render):
    node = water["node"]
    node.inputs["Wave Length"].default_value = 1.0  # ripples wider than a pixel
    node.inputs["Debug View"].default_value = 4
    water["scene"].frame_set(30)
    renders = {}
    for wind in ((0.0, 1.0, 0.0), (0.0, 0.0, 0.0)):
        node.inputs["Wind Direction"].default_value = wind
        renders[wind] = render(water["scene"], f"wind_{wind[1]:.0f}", exr=True)
    mask, _origin, _hits = _flat_water_mask(water, render)
    still = renders[(0.0, 0.0, 0.0)]
    assert np.isfinite(still).all()
    normals = still[..., :3][mask] * 2 - 1
    assert normals[:, 2].mean() > 0.8 and normals[:, :2].std() > 0.05  # a real bump, not a flat colour
    # No wind falls back to the default +Y wind.
    assert np.abs(still - renders[(0.0, 1.0, 0.0)])[mask].mean() < 1e-3


def _bump_colour(image, uv, seconds, wind=WIND, turn=WATER_TURN, wave_length=0.1, wind_force=0.02):
    """numpy model of Debug View 4 (MODEL.md 1, steps 1-3, one layer, Bump Strength 1): the bump
    read at the wind-frame UV, its slopes turned back onto the UV axes, then into the world
    through the water's tangent frame: +u and +v are its X and Y axes, turned by `turn`
    (`reference_models.bump_normal_colour`)."""
    return bump_normal_colour(image, uv, wave_length, wind, seconds, wind_force, turn=turn)


def test_the_bump_normal_is_read_in_the_placed_water_s_uvs_and_turned_with_it(water, render):
    """A long lens looks straight down on 9 cm of the placed water (the bump magnified, so the
    GPU reads its full-size image bilinearly, as numpy does): Debug View 4 is the model at the
    water's UVs there, its wind and its turned tangent frame. Leaving out any part of the
    placement, or the wind, is clearly worse. The patch lies in a tile read as it is, not
    mirrored: the renderer here reads a mirrored tile one texel off the GL rule numpy follows
    (a mean error of about 0.01 on its own; `test_bump_layers.py` covers the mirroring)."""
    scene, node = water["scene"], water["node"]
    at = (0.46, 0.7, WATER_AT[2])
    close = harness.add_camera(scene, (at[0], at[1], at[2] + 1.0), at, lens=400.0)
    close.rotation_euler = (0.0, 0.0, 0.0)
    bpy.context.view_layer.update()
    _origin, hits, local, ok = _on_water(water, close)
    scene.render.filter_size, filter_size = 0.0, scene.render.filter_size
    scene.frame_set(30)
    seconds = 30 / (scene.render.fps / scene.render.fps_base)
    node.inputs["Debug View"].default_value = 4
    try:
        pixels = render(scene, "bump_normal", exr=True)[..., :3]
    finally:
        scene.render.filter_size = filter_size
        scene.camera = water["camera"]
        bpy.data.objects.remove(close)
    assert ok.all() and (np.abs(local[..., :2]) < WATER_SIZE / 2).all()
    image = harness.addon("nodes.material").bump_image(water["material"])
    texels = np.empty(image.size[0] * image.size[1] * 4, dtype=np.float32)
    image.pixels.foreach_get(texels)
    image = texels.reshape(image.size[1], image.size[0], 4)[..., :3].astype(np.float64)
    uv = local[..., :2] / WATER_SIZE + 0.5
    wind = np.array(WIND) / np.hypot(*WIND)
    tiles = np.floor(np.stack((uv @ (wind[1], -wind[0]), uv @ wind + seconds * 0.02), axis=-1) / 0.1)
    assert (tiles % 2 == 0).all(), "one tile, not mirrored"
    model = _bump_colour(image, uv, seconds)
    error = np.abs(pixels - model).mean()
    assert pixels[..., :2].std() > 0.03, "a real bump fills the view"
    # The same point's UV had the water not been moved, turned or scaled, or only not scaled.
    to_water = np.array(water["water"].matrix_world.inverted())
    unscaled = (hits - WATER_AT)[..., :2] @ np.array(
        ((math.cos(WATER_TURN), -math.sin(WATER_TURN)), (math.sin(WATER_TURN), math.cos(WATER_TURN)))
    )
    wrong = {
        "unplaced": _bump_colour(image, hits[..., :2] / WATER_SIZE + 0.5, seconds, turn=0.0),
        "not scaled": _bump_colour(image, unscaled / WATER_SIZE + 0.5, seconds),
        "normal not turned": _bump_colour(image, uv, seconds, turn=0.0),
        "wind along +Y": _bump_colour(image, uv, seconds, wind=(0.0, 1.0)),
        "wind in world axes": _bump_colour(image, uv, seconds, wind=to_water[:2, :2] @ np.array(WIND)),
    }
    errors = {what: float(np.abs(pixels - other).mean()) for what, other in wrong.items()}
    print(f"mean error {error:.4f}; " + ", ".join(f"{what} {value:.4f}" for what, value in errors.items()))
    assert error < 0.003, f"mean error {error:.4f}"
    for what, value in errors.items():
        assert value > 3 * error, what
