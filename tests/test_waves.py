"""The ocean: `Water Waves` geometry nodes against the numpy sum of four sines, and the ocean shading."""

import addon_utils
import bpy
import numpy as np
import pytest
from reference_models import SEEDS_WAVES

import harness

# SPEC section 2, as written there: the seeds' four waves (amplitude, wavelength, speed, direction in
# their Y-up (x, z) plane), `reference_models.SEEDS_WAVES`. Not read from the add-on: the group and
# `wave_math` both take their defaults from `wave_math.DEFAULT_WAVES`, so comparing them with each
# other alone would pass with the table changed.
SPEC_WAVES = SEEDS_WAVES


@pytest.fixture(scope="module")
def wave_math(addon):
    return harness.addon("nodes.wave_math")


@pytest.fixture(scope="module")
def seeds(wave_math):
    """SPEC's table turned Z-up (an XNA vector (x, y, z) is Blender's (x, -z, y): their (x, z) is
    our (x, -y)), as `wave_math.Wave`s for its sums."""
    return tuple(wave_math.Wave(a, length, s, (d[0], -d[1])) for a, length, s, d in SPEC_WAVES)


@pytest.fixture(scope="module")
def waves(addon):
    return harness.addon("water.waves")


def _evaluated(obj):
    """Evaluated vertex positions (N, 3) and stored wave normals (N, 3), object space."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        count = len(mesh.vertices)
        co = np.empty(count * 3)
        mesh.vertices.foreach_get("co", co)
        normal = np.empty(count * 3)
        mesh.attributes["water_normal"].data.foreach_get("vector", normal)
    finally:
        evaluated.to_mesh_clear()
    return co.reshape(-1, 3), normal.reshape(-1, 3)


def _rest(obj):
    co = np.empty(len(obj.data.vertices) * 3)
    obj.data.vertices.foreach_get("co", co)
    return co.reshape(-1, 3)


def _seconds(scene):
    return scene.frame_current / (scene.render.fps / scene.render.fps_base)


def _angles(a, b):
    return np.degrees(np.arccos(np.clip((a * b).sum(axis=1), -1.0, 1.0)))


def test_heights_and_normals_match_the_four_sines_at_two_times(scene, wave_math, seeds):
    """The ocean preset's waves are SPEC's four, summed by `wave_math` (its formulas checked
    against SPEC's in tests/plain/test_reference_constants.py)."""
    bpy.ops.object.water_add(preset="ocean", size=60, resolution=97)
    ocean = bpy.context.active_object
    rest = _rest(ocean)
    amplitude_sum = sum(a for a, _length, _speed, _direction in SPEC_WAVES)
    for frame in (1, 61):
        scene.frame_set(frame)
        co, normal = _evaluated(ocean)
        expected = wave_math.heights(rest[:, :2], _seconds(scene), seeds)
        assert np.abs(co[:, 2] - expected).max() < 1e-4 * amplitude_sum, frame
        assert np.abs(co[:, :2] - rest[:, :2]).max() < 1e-5, "points move only up and down"
        assert _angles(normal, wave_math.normals(rest[:, :2], _seconds(scene), seeds)).max() < 1.0
    assert np.ptp(co[:, 2]) > amplitude_sum, "real waves, not a flat sheet"


@pytest.mark.lts
def test_every_wave_input_counts_and_zero_amplitude_removes_a_wave(scene, wave_math, waves, seeds):
    bpy.ops.mesh.primitive_circle_add(vertices=64, radius=20, fill_type="TRIFAN")  # any flat mesh
    disc = bpy.context.active_object
    modifier = waves.add_waves(disc)
    changed = list(seeds)
    changed[1] = wave_math.Wave(0.0, 5.0, 2.0, (-1.0, -0.5))
    changed[2] = wave_math.Wave(0.9, 3.0, -1.0, (0.3, 1.0))
    waves.set_wave_input(modifier, "Amplitude 2", 0.0)
    waves.set_wave_input(modifier, "Amplitude 3", 0.9)
    waves.set_wave_input(modifier, "Wavelength 3", 3.0)
    waves.set_wave_input(modifier, "Speed 3", -1.0)
    waves.set_wave_input(modifier, "Direction 3", (0.3, 1.0, 0.0))
    scene.frame_set(30)
    co, normal = _evaluated(disc)
    rest = _rest(disc)
    t = _seconds(scene)
    assert np.abs(co[:, 2] - wave_math.heights(rest[:, :2], t, changed)).max() < 1e-4
    assert _angles(normal, wave_math.normals(rest[:, :2], t, changed)).max() < 1.0
    assert np.abs(co[:, 2] - wave_math.heights(rest[:, :2], t, seeds)).max() > 0.1, (
        "the inputs changed the waves"
    )


def test_with_every_amplitude_zero_the_grid_is_flat(scene, waves):
    bpy.ops.object.water_add(preset="ocean", size=30, resolution=33)
    ocean = bpy.context.active_object
    modifier = waves.wave_modifier(ocean)
    for number in range(1, 5):
        waves.set_wave_input(modifier, f"Amplitude {number}", 0.0)
    scene.frame_set(17)
    co, normal = _evaluated(ocean)
    assert np.abs(co[:, 2]).max() == 0.0
    assert np.allclose(normal, (0, 0, 1))


@pytest.mark.lts
def test_the_lake_combines_with_waves_and_the_panel_finds_their_inputs(scene, waves, seeds):
    bpy.ops.object.water_add(preset="lake", waves=True, resolution=65, size=40)
    lake = bpy.context.active_object
    modifier = waves.wave_modifier(lake)
    assert modifier is not None
    assert harness.addon("nodes.material").water_node(lake.active_material) is not None, "lake shading kept"
    names = set(waves.input_ids(modifier))
    assert {
        f"{kind} {n}" for kind in ("Amplitude", "Wavelength", "Speed", "Direction") for n in range(1, 5)
    } == names
    for number, wave in enumerate(seeds, 1):  # what the panel draws: every input, readable
        owner, path = waves.input_property(modifier, f"Speed {number}")
        assert owner.path_resolve(path) == pytest.approx(wave.speed)
    probe = harness.addon("water.mirror").find_probe(lake)
    assert probe.data.influence_distance >= waves.amplitude_sum(modifier), "the mirror reaches the crests"


def _available_bytes():
    with open("/proc/meminfo", encoding="ascii") as meminfo:
        return next(int(line.split()[1]) * 1024 for line in meminfo if line.startswith("MemAvailable"))


def _vertices_a_side(obj):
    """The grid's distinct x and y coordinates, counted on its mesh."""
    co = _rest(obj)
    sides = tuple(len(np.unique(co[:, axis].round(5))) for axis in (0, 1))
    assert sides[0] * sides[1] == len(co), "a full grid"
    return sides


def test_resolution_is_clamped_to_what_a_machine_can_hold(scene, monkeypatch):
    """A grid of n x n points needs n^2 x BYTES_PER_VERTEX bytes, so the side is held to
    sqrt(free memory / BYTES_PER_VERTEX) (and to the schema's 2..2048). This machine holds the
    schema's 2048; a machine short of memory is made here by making each point cost more, so that
    the free memory holds a grid of about 60 a side: asking for more gives at most that many
    points a side (counted on the mesh), four times the cost per point halves the side, and a
    request within the cap is given exactly."""
    grid = harness.addon("water.grid")
    api = harness.addon("api")
    schema = harness.addon("presets.schema")
    assert schema.clamp_values({"resolution": 10**9})["resolution"] == 2048
    assert schema.clamp_values({"resolution": -5})["resolution"] == 2
    available = _available_bytes()
    sides = {}
    for cost in (1, 4):
        monkeypatch.setattr(grid, "BYTES_PER_VERTEX", cost * available / 60**2)
        cap = grid.max_resolution()
        added = api.add_water(
            scene,
            resolution=10**9,
            size=10.0,
            mirror_setup=False,
            see_surroundings=False,
            name=f"Cost {cost}",
        )
        side = _vertices_a_side(added.object)
        print(f"{cost} x the cost per point: cap {cap}, grid {side}, notes {added.notes}")
        assert side[0] == side[1] <= cap
        assert side[0] ** 2 * grid.BYTES_PER_VERTEX <= 1.05 * _available_bytes(), "it fits"
        assert any("lowered" in note for note in added.notes)
        sides[cost] = side[0]
    assert 55 <= sides[1] <= 65
    assert abs(sides[4] - sides[1] / 2) <= 2, "the side goes as the square root of the memory"
    within = api.add_water(scene, resolution=20, size=10.0, mirror_setup=False, see_surroundings=False)
    assert _vertices_a_side(within.object) == (20, 20) and within.notes == []
    monkeypatch.setattr(grid, "BYTES_PER_VERTEX", 10.0 * available)
    starved = api.add_water(scene, resolution=10**9, size=10.0, mirror_setup=False, see_surroundings=False)
    assert _vertices_a_side(starved.object) == (2, 2), "never less than one quad"


def test_the_add_operator_grid_has_the_asked_resolution_and_uvs(scene):
    bpy.ops.object.water_add(preset="ocean", size=10, resolution=5)
    ocean = bpy.context.active_object
    assert len(ocean.data.vertices) == 25 and len(ocean.data.polygons) == 16
    assert all(p.normal.z > 0.99 for p in ocean.data.polygons)
    uv = np.empty(len(ocean.data.loops) * 2)
    ocean.data.uv_layers.active.data.foreach_get("uv", uv)
    assert uv.min() == pytest.approx(0) and uv.max() == pytest.approx(1)


@pytest.mark.lts
def test_saved_ocean_animates_with_the_add_on_disabled(scene, wave_math, seeds, tmp_path):
    bpy.ops.object.water_add(preset="ocean", size=20, resolution=17)
    rest = _rest(bpy.context.active_object)
    path = tmp_path / "ocean.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    addon_utils.disable(harness.ADDON_MODULE, default_set=True)
    try:
        bpy.context.preferences.filepaths.use_scripts_auto_execute = False
        bpy.ops.wm.open_mainfile(filepath=str(path), load_ui=False, use_scripts=False)
        scene = bpy.context.scene
        ocean = bpy.data.objects["Water"]
        for frame in (5, 40):
            scene.frame_set(frame)
            co, _normal = _evaluated(ocean)
            assert np.abs(co[:, 2] - wave_math.heights(rest[:, :2], _seconds(scene), seeds)).max() < 1e-4
        node = bpy.data.materials["Water"].node_tree.nodes["Water Ocean Normal"]
        assert node.inputs["Time"].default_value == pytest.approx(_seconds(scene)), "the bump clock runs too"
    finally:
        bpy.context.preferences.filepaths.use_scripts_auto_execute = True
        addon_utils.enable(harness.ADDON_MODULE, default_set=True)


def test_the_sky_comes_from_the_world_image_or_follows_the_world_colour(scene, tmp_path):
    ocean_material = harness.addon("nodes.sea.ocean_material")
    harness.set_world_color(scene, (0.2, 0.3, 0.4))
    material = ocean_material.make_ocean_material("Plain Sky", scene)
    sky = material.node_tree.nodes["Sky"]
    assert sky.type == "RGB"
    scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.9, 0.5, 0.1, 1)
    bpy.ops.mesh.primitive_plane_add()
    bpy.context.active_object.data.materials.append(material)  # drivers run for used materials
    scene.frame_set(2)
    assert tuple(sky.outputs[0].default_value)[:3] == pytest.approx((0.9, 0.5, 0.1))

    image = bpy.data.images.new("Sky HDR", 16, 8, float_buffer=True)
    environment = scene.world.node_tree.nodes.new("ShaderNodeTexEnvironment")
    environment.image = image
    material = ocean_material.make_ocean_material("Image Sky", scene)
    sky = material.node_tree.nodes["Sky"]
    assert sky.type == "TEX_ENVIRONMENT" and sky.image == image
    assert sky.inputs["Vector"].links[0].from_socket.name == "Reflection"


def test_panel_ocean_inputs_name_real_group_inputs(scene):
    bpy.ops.object.water_add(preset="ocean", resolution=3, size=10)
    material = bpy.context.active_object.active_material
    normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(material)
    nodes = {"normal": normal, "shade": shade}
    for which, name in harness.addon("ui.sea")._OCEAN_INPUTS:
        assert name in nodes[which].inputs
