"""The `Water Surface` group renders the reference model: measured per pixel against numpy."""

import math

import bpy
import numpy as np
import pytest
from mathutils import Vector

import harness

pytestmark = pytest.mark.render

SKY = (0.4, 0.6, 0.9)
CAMERA_AT = (0.0, -6.0, 2.5)
WATER_SIZE = 8.0


def _water_material():
    return harness.addon("nodes.material")


@pytest.fixture(scope="module")
def lake(addon, eevee):
    """One scene for the module: water, a sky, a red floor under it, a green block above it, a sun."""
    scene = harness.clean_scene(engine=eevee, width=128, height=72, samples=4)
    harness.addon("engine").enable_ray_tracing(scene)
    harness.set_world_color(scene, SKY)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    scene.collection.objects.link(sun)
    material = _water_material().make_water_material(scene=scene)
    bpy.ops.mesh.primitive_plane_add(size=WATER_SIZE)
    water = bpy.context.object
    water.data.materials.append(material)
    harness.add_cube(
        scene, (0, 0, -1.2), size=2.0, material=harness.emission_material("Floor", (1, 0.1, 0.05))
    )
    harness.add_cube(
        scene, (1.5, 1.5, 0.8), size=1.0, material=harness.emission_material("Block", (0.1, 1, 0.1))
    )
    camera = harness.add_camera(scene, CAMERA_AT, (0, 0, 0))
    return {
        "scene": scene,
        "material": material,
        "node": _water_material().water_node(material),
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


def _flat_water_mask(lake, render):
    """Pixels showing the water plane itself (not the block, not the sky), from the flat normal view."""
    node = lake["node"]
    node.inputs["Bump Strength"].default_value = 0.0
    node.inputs["Debug View"].default_value = 4
    normal = render(lake["scene"], "mask", exr=True)
    flat = np.all(np.abs(normal[..., :3] - (0.5, 0.5, 1.0)) < 0.01, axis=-1)
    origin, directions = harness.pixel_rays(lake["scene"], lake["camera"])
    hits, ok = harness.hit_plane_z(origin, directions)
    inside = (
        ok & (np.abs(hits[..., 0]) < WATER_SIZE / 2 - 0.3) & (np.abs(hits[..., 1]) < WATER_SIZE / 2 - 0.3)
    )
    return flat & inside, origin, hits


def test_fresnel_view_matches_dot_eye_up(water, render):
    mask, origin, hits = _flat_water_mask(water, render)
    assert mask.sum() > 1000
    water["node"].inputs["Debug View"].default_value = 3
    pixels = render(water["scene"], "fresnel", exr=True)
    eye = origin - hits
    expected = np.clip(eye[..., 2] / np.linalg.norm(eye, axis=-1), 0, 1)
    error = np.abs(pixels[..., 0] - expected)[mask]
    assert error.mean() < 0.02, f"mean error {error.mean():.4f}"
    # Grey: F in every channel; and it spans a real range over this view.
    assert np.allclose(pixels[..., 0][mask], pixels[..., 2][mask], atol=2e-3)
    assert expected[mask].max() - expected[mask].min() > 0.2


def _glint_model(origin, hits, sun_dir, power, strength=1.0):
    eye = origin - hits
    eye /= np.linalg.norm(eye, axis=-1, keepdims=True)
    light = np.asarray(sun_dir, float) / np.linalg.norm(sun_dir)
    reflected = light * np.array([1.0, 1.0, -1.0])  # reflect(L, up)
    return strength * np.maximum((eye * reflected).sum(-1), 0.0) ** power


def test_glint_view_matches_the_formula_and_follows_the_sun(water, render):
    mask, origin, hits = _flat_water_mask(water, render)
    node = water["node"]
    node.inputs["Specular Power"].default_value = 64.0
    node.inputs["Specular Strength"].default_value = 2.0
    node.inputs["Debug View"].default_value = 5
    peaks = []
    for target in ((0.0, 0.0, 0.0), (2.0, 1.5, 0.0)):
        # Aim the sun so that its mirror image reaches the camera from `target`.
        eye = Vector(CAMERA_AT) - Vector(target)
        sun_dir = (eye.x, eye.y, -eye.z)
        _aim_sun(water["sun"], Vector(sun_dir).normalized())
        pixels = render(water["scene"], f"glint_{len(peaks)}", exr=True)
        expected = _glint_model(origin, hits, sun_dir, 64.0, 2.0)
        error = np.abs(pixels[..., 0] - expected)[mask]
        assert error.mean() < 0.02, f"mean error {error.mean():.4f}"
        assert expected[mask].max() > 1.5  # the glint is in view, so the comparison means something
        row, col = np.unravel_index(np.argmax(np.where(mask, pixels[..., 0], 0)), mask.shape)
        ((want_col, want_row),) = harness.world_to_pixel(water["scene"], water["camera"], [target])
        assert abs(col - want_col) <= 3 and abs(row - want_row) <= 3
        peaks.append((row, col))
    assert math.dist(*peaks) > 15


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
    model = (1 - blend) * ((1 - f) * views[1] + f * views[2]) + blend * dull + views[5]
    error = np.abs(views[0] - model)[mask]
    # The refraction's weight squared, as EEVEE gives with Thickness left unconnected.
    squared = (1 - blend) * ((1 - f) * views[1] + f * f * views[2]) + blend * dull + views[5]
    wrong = np.abs(views[0] - squared)[mask]
    assert error.mean() < 0.01, f"mean error {error.mean():.4f}"
    assert wrong.mean() > 3 * error.mean()
    # Reflection and refraction differ here (sky vs red floor), so the blend is really tested.
    assert np.abs(views[1] - views[2])[mask].mean() > 0.1


@pytest.mark.newest_only
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
        for frame in (1, 13):
            scene.frame_set(frame)
            frames.append(render(scene, f"wind_{wind}_frame_{frame}", exr=True)[..., :3])
        differences[wind] = np.abs(frames[0] - frames[1])[mask].mean()
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
    # Reflective: the green block's mirror image shows under it, in green.
    ((col, row),) = harness.world_to_pixel(scene, water["camera"], [(1.5, 1.5, -0.4)])
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
