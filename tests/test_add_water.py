"""`object.water_add`, `object.water_mirror_setup`, the preset operators and the panel's data."""

import json
import math
from pathlib import Path

import addon_utils
import bpy
import pytest
from mathutils import Vector
from test_presets import REFERENCE as LAKE

import harness

REFERENCE = {**LAKE, "mirror_setup": True}


def _values(obj):
    return harness.addon("water.values").read_values(obj.active_material)


def _probe(water):
    return harness.addon("water.mirror").find_probe(water)


def test_operator_defaults_are_the_reference(addon):
    assert harness.addon("presets").enum_items()[0][0] == "lake", "the first (default) preset is the lake"
    properties = bpy.ops.object.water_add.get_rna_type().properties
    for key, value in REFERENCE.items():
        default = properties[key].default_array if getattr(properties[key], "is_array", False) else None
        assert (tuple(default) if default is not None else properties[key].default) == pytest.approx(value), (
            key
        )


def test_adds_a_uv_mapped_plane_with_the_water_material_at_the_cursor(scene):
    scene.cursor.location = (1.0, 2.0, 3.0)
    assert bpy.ops.object.water_add() == {"FINISHED"}
    water = bpy.context.active_object
    assert water.select_get() and water.type == "MESH"
    assert tuple(water.location) == pytest.approx((1.0, 2.0, 3.0))
    assert tuple(water.dimensions) == pytest.approx((128.0, 128.0, 0.0))
    uvs = sorted(tuple(round(c, 6) for c in d.uv) for d in water.data.uv_layers.active.data)
    assert uvs == [(0, 0), (0, 1), (1, 0), (1, 1)]
    values = _values(water)
    for key in ("wave_height", "wave_length", "wind_direction", "wind_force", "dull_color", "dull_blend"):
        assert values[key] == pytest.approx(REFERENCE[key]), key
    node = harness.addon("nodes.material").water_node(water.active_material)
    assert node.node_tree.name == "Water Surface"


def test_location_rotation_and_values_given_win_over_the_preset_in_any_order(scene):
    bpy.ops.object.water_add(
        wave_height=0.7, preset="murky_pond", location=(5, 0, 0), rotation=(0, 0, math.pi / 2)
    )
    water = bpy.context.active_object
    assert tuple(water.location) == pytest.approx((5, 0, 0))
    assert water.rotation_euler.z == pytest.approx(math.pi / 2)
    values = _values(water)
    murky = harness.addon("presets").get("murky_pond").values
    assert values["wave_height"] == pytest.approx(0.7)
    assert values["dull_blend"] == pytest.approx(murky["dull_blend"]) != REFERENCE["dull_blend"]
    assert water.dimensions.x == pytest.approx(murky["size"])


def test_from_edit_mode_it_returns_to_object_mode_and_leaves_the_edited_mesh_alone(scene):
    bpy.ops.mesh.primitive_cube_add()
    cube = bpy.context.active_object
    bpy.ops.object.mode_set(mode="EDIT")
    assert bpy.ops.object.water_add(mirror_setup=False) == {"FINISHED"}
    assert bpy.context.mode == "OBJECT"
    assert len(cube.data.vertices) == 8
    assert bpy.context.active_object is not cube and bpy.context.active_object.active_material is not None


def test_adding_water_three_times_reuses_the_group_and_the_bump_image(scene):
    for _ in range(3):
        bpy.ops.object.water_add()
    waters = [o for o in bpy.data.objects if harness.addon("water.values").is_water(o)]
    assert len(waters) == 3
    assert len({o.active_material.name for o in waters}) == 3, "each water has its own values"
    groups = sorted(g.name for g in bpy.data.node_groups)
    # The default lake has no optional part (depth, foam, caustics) in its shader: no group or
    # tile of theirs is made.
    lake = ["Water Surface", "Water Surface Bump UV", "Water Surface Wind Frame"]
    lake += ["Water Surroundings", "Water Surroundings Sample", "Water Underside"]
    lake += ["Water Underwater Fog", "Water Meniscus", "Water Underwater Shell"]
    assert groups == sorted(lake), "each group once, no .001 (each water has its surroundings)"
    assert sorted(i.name for i in bpy.data.images) == ["Water Surface Bump"]


def test_undo_removes_the_water_and_its_set_up(scene):
    scene.eevee.use_raytracing = False
    bpy.ops.ed.undo_push(message="before water")
    before = {o.name for o in bpy.data.objects}
    bpy.ops.object.water_add("EXEC_DEFAULT", True)  # with an undo step, as from the menu
    assert {o.name for o in bpy.data.objects} - before == {
        "Water",
        "Water Mirror",
        "Water Surroundings",
        "Water Underwater",
    }
    bpy.ops.ed.undo()
    assert {o.name for o in bpy.data.objects} == before
    assert not bpy.context.scene.eevee.use_raytracing
    assert not [m for m in bpy.data.materials if m.name.startswith("Water")]


BAD_INPUTS = [
    ("wave_length", 0.0, 0.001),
    ("wave_length", -1.0, 0.001),
    ("size", 0.0, 0.01),
    ("size", -5.0, 0.01),
    ("size", 1e12, 100000.0),
    ("wave_height", 1e9, 10.0),
    ("wind_direction", (0.0, 0.0), (0.0, 1.0)),
    ("wind_force", -1.0, 0.0),
    ("specular_power", 0.0, 1.0),
]  # NaN is refused, not clamped (issue 57: test_one_path.py)


@pytest.mark.parametrize("key, given, used", BAD_INPUTS)
def test_bad_input_is_clamped_never_nan(scene, key, given, used):
    assert bpy.ops.object.water_add(**{key: given}) == {"FINISHED"}
    water = bpy.context.active_object
    value = water.dimensions.x if key == "size" else _values(water)[key]
    assert value == pytest.approx(used, rel=1e-5), key
    assert all(math.isfinite(v) for v in _values(water)["wind_direction"])


def test_mirror_set_up_refuses_without_water(scene):
    bpy.ops.mesh.primitive_cube_add()
    with pytest.raises(RuntimeError, match="Select a water object"):
        bpy.ops.object.water_mirror_setup()


def test_mirror_set_up_turns_tracing_on_adds_a_world_and_one_probe_that_follows_the_water(scene):
    scene.world = None
    scene.eevee.use_raytracing = False
    bpy.ops.object.water_add(size=10, mirror_setup=False)
    water = bpy.context.active_object
    assert _probe(water) is None and scene.world is None
    changes = harness.addon("water.mirror").setup_mirror(scene, water)
    assert "added planar probe 'Water Mirror'" in changes and "EEVEE ray tracing: False -> True" in changes
    assert any(change.startswith("world: none -> 'Sky") for change in changes)
    bpy.ops.object.water_mirror_setup()  # again: reused, not duplicated
    probes = [o for o in bpy.data.objects if o.type == "LIGHT_PROBE"]
    assert len(probes) == 1 and probes[0].parent is water
    assert scene.eevee.use_raytracing and scene.eevee.ray_tracing_method == "SCREEN"
    assert scene.world is not None and water.active_material.use_raytrace_refraction

    # Moved, turned and scaled, the water keeps its mirror: the probe covers it, 1 cm above its plane.
    water.location = (3, -2, 1.5)
    water.rotation_euler = (0.2, 0.0, 0.7)
    water.scale = (2.0, 0.5, 1.0)
    bpy.context.view_layer.update()
    probe = probes[0]
    normal = water.matrix_world.to_3x3() @ Vector((0, 0, 1))
    normal.normalize()
    lift = (probe.matrix_world.translation - water.matrix_world.translation).dot(normal)
    assert lift == pytest.approx(0.01, abs=1e-4)
    assert lift < probe.data.influence_distance and lift > probe.data.clip_start
    corners = [water.matrix_world @ Vector(c) for c in ((-5, -5, 0), (5, 5, 0))]
    probe_corners = [probe.matrix_world @ Vector(c) for c in ((-1, -1, 0), (1, 1, 0))]
    for mine, theirs in zip(probe_corners, corners):
        assert (mine - theirs - normal * 0.01).length < 1e-4


def test_add_mesh_menus_offer_the_operator(addon):
    for menu in (bpy.types.VIEW3D_MT_mesh_add, bpy.types.VIEW3D_MT_add):
        entries = [f.__module__ + "." + f.__qualname__ for f in menu._dyn_ui_initialize()]
        assert any(entry.startswith(harness.ADDON_MODULE) for entry in entries), menu


def test_panel_sections_name_real_group_inputs(addon):
    lake, common = harness.addon("ui.lake"), harness.addon("ui.common")
    inputs = {s.name for s in harness.addon("nodes.lake.water_surface").INPUTS}
    for _title, _icon, names in lake._SECTIONS:
        for name in names:
            if name.startswith("part:"):
                part = name[len("part:") :]
                assert part in {p.name for p in harness.addon("nodes.lake.water_surface").PARTS}
                assert set(common.PARTS[part]) <= inputs
            else:
                assert name in inputs


def test_user_presets_are_saved_outside_the_add_on_applied_and_removed(scene):
    presets = harness.addon("presets")
    bpy.ops.object.water_add(mirror_setup=False)
    first = bpy.context.active_object
    node = harness.addon("nodes.material").water_node(first.active_material)
    node.inputs["Wave Height"].default_value = 0.55
    node.inputs["Dull Color"].default_value = (0.9, 0.1, 0.2, 1.0)
    assert bpy.ops.object.water_preset_add(name="Test Red") == {"FINISHED"}
    path = Path(presets.get("user:test_red").path)
    assert path.is_file() and Path(presets.user_dir()) in path.parents
    assert Path(harness.addon().__file__).parent not in path.parents, "never inside the add-on's folder"
    assert "user:test_red" in [item[0] for item in presets.enum_items()]

    bpy.ops.object.water_add(preset="lake", mirror_setup=False)
    second = bpy.context.active_object
    bpy.ops.object.water_preset_apply(preset="user:test_red")
    assert _values(second)["wave_height"] == pytest.approx(0.55)
    assert _values(second)["dull_color"] == pytest.approx((0.9, 0.1, 0.2))

    bpy.ops.object.water_preset_remove(preset="user:test_red")
    assert not path.exists()
    with pytest.raises(RuntimeError, match="built in"):
        bpy.ops.object.water_preset_remove(preset="lake")


def test_a_broken_user_preset_leaves_the_add_on_working(scene, capfd):
    presets = harness.addon("presets")
    folder = Path(presets.user_dir())
    broken = folder / "broken.json"
    ill_typed = folder / "ill_typed.json"
    broken.write_text("{ this is not json", encoding="utf-8")
    ill_typed.write_text(json.dumps({"values": {"wave_height": "tall"}}), encoding="utf-8")
    try:
        addon_utils.disable(harness.ADDON_MODULE, default_set=True)
        addon_utils.enable(harness.ADDON_MODULE, default_set=True)
        console = capfd.readouterr().err
        assert "broken.json" in console and "ill_typed.json" in console
        ids = [item[0] for item in harness.addon("presets").enum_items()]
        assert "user:broken" not in ids and "user:ill_typed" not in ids and "lake" in ids
        assert bpy.ops.object.water_add(mirror_setup=False) == {"FINISHED"}
        assert _values(bpy.context.active_object)["wave_height"] == pytest.approx(0.3)
    finally:
        broken.unlink()
        ill_typed.unlink()
        harness.addon("presets").reload()


def test_glint_sun_and_bump_image_are_chosen_by_operators(scene):
    material_module = harness.addon("nodes.material")
    sun = bpy.data.objects.new("Key Sun", bpy.data.lights.new("Key Sun", "SUN"))
    scene.collection.objects.link(sun)
    bpy.ops.object.water_add(mirror_setup=False)
    water = bpy.context.active_object
    assert material_module.glint_sun(water.active_material) is sun
    bpy.ops.object.water_sun_set(sun="NONE")
    assert material_module.glint_sun(water.active_material) is None
    image = bpy.data.images.new("Ripples", 8, 8)
    bpy.ops.object.water_bump_set(image="Ripples")
    assert material_module.bump_image(water.active_material) == image
    bpy.ops.object.water_bump_set(image="DEFAULT")
    assert material_module.bump_image(water.active_material).name == "Water Surface Bump"


def test_lake_only_choices_refuse_ocean_water_with_a_message(scene):
    bpy.ops.object.water_add(preset="ocean", resolution=3, size=10)
    with pytest.raises(RuntimeError, match="ocean shading"):
        bpy.ops.object.water_sun_set(sun="NONE")
    with pytest.raises(RuntimeError, match="ocean shading"):
        bpy.ops.object.water_preset_apply(preset="lake")
    bpy.ops.object.water_add(preset="lake", mirror_setup=False)
    with pytest.raises(RuntimeError, match="builds its own mesh"):
        bpy.ops.object.water_preset_apply(preset="ocean")


def test_probe_stays_on_the_rest_plane_with_waves_at_any_frame(scene):
    """Add Waves and `waves=True` fit the probe to the rest plane and widen it to the crests, at any frame."""
    waves = harness.addon("water.waves")
    bpy.ops.object.water_add(size=40, resolution=64)
    water = bpy.context.active_object
    probe = _probe(water)
    assert probe.data.influence_distance < 0.5  # still water: a thin influence
    scene.frame_set(1)
    assert bpy.ops.object.water_waves_add() == {"FINISHED"}
    reach = waves.amplitude_sum(waves.wave_modifier(water))
    assert reach > 0.5
    assert probe.data.influence_distance >= reach, "Add Waves widens the probe to the crests"
    fitted = {}
    for frame in (1, 40):
        scene.frame_set(frame)
        bpy.context.view_layer.update()
        top = max((water.matrix_world @ Vector(c)).z for c in water.bound_box)
        assert top > 0.5, "the waves lift the evaluated surface"
        bpy.ops.object.water_mirror_setup()
        bpy.context.view_layer.update()
        fitted[frame] = (probe.matrix_world.copy(), probe.data.influence_distance)
        assert probe.matrix_world.translation.z == pytest.approx(0.01, abs=1e-5), frame
        assert probe.data.influence_distance >= reach
    first, later = fitted[1][0], fitted[40][0]
    assert max(abs(a - b) for row_a, row_b in zip(first, later) for a, b in zip(row_a, row_b)) < 1e-6
    assert fitted[1][1] == fitted[40][1]
    # Added with waves from the start: the same probe.
    bpy.ops.object.water_add(size=40, resolution=64, waves=True, location=(100, 0, 0))
    other = _probe(bpy.context.active_object)
    assert other.matrix_world.translation.z == pytest.approx(0.01, abs=1e-5)
    assert other.data.influence_distance == pytest.approx(fitted[1][1])
