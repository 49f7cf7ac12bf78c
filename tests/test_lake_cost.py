"""A part of the lake shading that is off costs nothing: depth colour, foam and caustics are in
the material's group only while their switch (Absorption, Foam Amount, Caustics) is above 0.

Every entry point switches them (the API, presets, the preset and part operators, adding
water, repair, physical caustics); values and drivers survive the swap; a switch that moves
(animated, driven, linked) keeps its part; groups saved by older versions (every part built in)
keep rendering as they did; and a part at 0 renders exactly as the part left out.
"""

import bpy
import numpy as np
import pytest

import harness

EVERY = {"depth", "foam", "caustics"}


def _api():
    return harness.addon("api")


def _material():
    return harness.addon("nodes.material")


def _parts(water):
    return set(_material().parts_built(_material().water_node(water.active_material).node_tree))


def _flat_nodes(tree):
    """Every node of `tree` and of the groups nested in it, as (type, node) pairs."""
    found = []
    for node in tree.nodes:
        found.append((node.bl_idname, node))
        if node.type == "GROUP" and node.node_tree is not None:
            found += _flat_nodes(node.node_tree)
    return found


def _add(scene, **values):
    added = _api().add_water(
        scene, size=8, resolution=8, see_surroundings=False, mirror_setup=False, **values
    )
    return added.object


@pytest.mark.lts
def test_the_default_lake_computes_no_part_and_the_full_one_all(scene):
    lake = _add(scene)
    nodes = _flat_nodes(lake.active_material.node_tree)
    types = [kind for kind, _node in nodes]
    attributes = [n.attribute_name for kind, n in nodes if kind == "ShaderNodeAttribute"]
    images = {n.image.name for kind, n in nodes if kind == "ShaderNodeTexImage" and n.image}
    # Only the bump's layers: no depth, shore or surroundings attribute, no foam or caustic tile,
    # no diffuse closure, no transform of the caustics.
    assert attributes == [] and images == {"Water Surface Bump"}
    assert "ShaderNodeBsdfDiffuse" not in types and "ShaderNodeVectorTransform" not in types
    assert _parts(lake) == set()

    full = _add(scene, absorption=(0.4, 0.1, 0.1), foam_amount=0.5, caustics=1.0)
    nodes = _flat_nodes(full.active_material.node_tree)
    attributes = {n.attribute_name for kind, n in nodes if kind == "ShaderNodeAttribute"}
    images = {n.image.name for kind, n in nodes if kind == "ShaderNodeTexImage" and n.image}
    assert {"water_depth", "water_shore_distance", "water_surroundings"} <= attributes
    assert images == {"Water Surface Bump", "Water Surface Foam", "Water Surface Caustics"}
    assert _parts(full) == EVERY
    name = _material().water_node(full.active_material).node_tree.name
    assert name == "Water Surface + Depth + Foam + Caustics"


def test_every_entry_point_switches_the_parts_and_keeps_the_values(scene):
    scene.render.fps, scene.render.fps_base = 24, 1.0
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    scene.collection.objects.link(sun)
    lake = _add(scene)
    material = lake.active_material
    bpy.context.view_layer.objects.active = lake

    _api().write_values(lake, {"caustics": 1.5})
    assert _parts(lake) == {"caustics"}
    _api().write_values(lake, {"caustics": 0.0})
    assert _parts(lake) == set()
    _api().apply_preset(lake, "clear_lake")
    assert _parts(lake) == EVERY
    _api().apply_preset(lake, "murky_pond")  # absorption, no foam, no caustics
    assert _parts(lake) == {"depth"}
    assert bpy.ops.object.water_preset_apply(preset="tropical_shallows") == {"FINISHED"}
    assert _parts(lake) == EVERY
    assert bpy.ops.object.water_preset_apply(preset="lake") == {"FINISHED"}
    assert _parts(lake) == set()

    # The part switch: on from 0 takes the part's usual value; off sets 0.
    assert bpy.ops.object.water_part_switch(part="foam", enable=True) == {"FINISHED"}
    node = _material().water_node(material)
    assert _parts(lake) == {"foam"} and node.inputs["Foam Amount"].default_value == pytest.approx(0.5)
    node.inputs["Foam Amount"].default_value = 0.8
    node.inputs["Wave Height"].default_value = 0.77
    assert _api().switch_part(lake, "depth", True)[0].startswith("Depth on")
    assert tuple(node.inputs["Absorption"].default_value)[:3] == pytest.approx((0.45, 0.09, 0.06))
    assert _parts(lake) == {"foam", "depth"}
    assert node.inputs["Foam Amount"].default_value == pytest.approx(0.8), "a value kept across the swap"
    assert bpy.ops.object.water_part_switch(part="foam", enable=False) == {"FINISHED"}
    assert _parts(lake) == {"depth"} and node.inputs["Foam Amount"].default_value == 0.0
    with pytest.raises(ValueError, match="no part 'whitecaps'"):
        _api().switch_part(lake, "whitecaps", True)

    # Values and drivers came through every swap: the clock still drives Time, the sun still
    # drives Sun Direction, and the wave height set by hand before the last swaps is there.
    assert node.inputs["Wave Height"].default_value == pytest.approx(0.77)
    scene.frame_set(48)
    evaluated = material.evaluated_get(bpy.context.evaluated_depsgraph_get())
    assert _material().water_node(evaluated).inputs["Time"].default_value == pytest.approx(2.0)
    drivers = material.node_tree.animation_data.drivers
    driven = {node.path_resolve(fc.data_path.split(".", 1)[1].rsplit(".", 1)[0]).name for fc in drivers}
    assert driven == {"Time", "Sun Direction", "Sun Color", "Sun Lit"}

    # No group is left behind: one of each variant in use, none twice.
    names = [g.name for g in bpy.data.node_groups if g.name.startswith("Water Surface")]
    assert not [n for n in names if n[-4:-3] == "." and n[-3:].isdigit()], names
    assert "Water Surface + Foam" not in names, "an unused variant the add-on made is removed"


def test_undo_puts_the_part_back(scene):
    lake = _add(scene)
    bpy.context.view_layer.objects.active = lake
    bpy.ops.ed.undo_push(message="before")
    assert bpy.ops.object.water_part_switch("EXEC_DEFAULT", True, part="caustics", enable=True) == {
        "FINISHED"
    }
    assert _parts(bpy.data.objects[lake.name]) == {"caustics"}
    bpy.ops.ed.undo()
    assert _parts(bpy.data.objects["Water"]) == set()


@pytest.mark.lts
def test_a_switch_that_moves_keeps_its_part(scene):
    lake = _add(scene)
    material = lake.active_material
    node = _material().water_node(material)
    # Caustics keyframed from 0 (frame 1) to 1 (frame 20): at frame 1 the part is still needed.
    node.inputs["Caustics"].default_value = 0.0
    node.inputs["Caustics"].keyframe_insert("default_value", frame=1)
    node.inputs["Caustics"].default_value = 1.0
    node.inputs["Caustics"].keyframe_insert("default_value", frame=20)
    scene.frame_set(1)
    # Foam Amount fed by a node of the user's.
    value = material.node_tree.nodes.new("ShaderNodeValue")
    material.node_tree.links.new(value.outputs[0], node.inputs["Foam Amount"])
    _api().write_values(lake, {"wave_height": 0.4})
    assert _parts(lake) == {"caustics", "foam"}
    assert _api().switch_part(lake, "caustics", False)[0].startswith("Caustics stays")
    assert _parts(lake) >= {"caustics"}


def test_an_old_files_group_keeps_its_parts_and_its_materials(scene):
    # A `Water Surface` group as version 4 saved it: every part built in, the lake's role and name.
    old = _material().make_water_material("Old", scene=scene)
    node = _material().water_node(old)
    lean = node.node_tree
    node.node_tree = legacy = _material().water_group(parts=EVERY)
    bpy.data.node_groups.remove(lean)
    legacy.name = "Water Surface"
    harness.addon("nodes.ownership").mark(legacy, "Water Surface", 4)
    node.inputs["Caustics"].default_value = 0.7

    new = _add(scene)  # the updated add-on meets the old group
    assert _material().water_node(old).node_tree == legacy, "the old material keeps its group"
    assert legacy.name == "Water Surface + Depth + Foam + Caustics"
    assert harness.addon("nodes.ownership").role_of(legacy) == legacy.name
    assert _material().water_node(new.active_material).node_tree.name == "Water Surface"
    assert _parts(new) == set()
    # Writing the old water's values fits it: only caustics are on.
    old_water = bpy.data.objects.new("Old Water", new.data.copy())
    old_water.data.materials.clear()
    old_water.data.materials.append(old)
    scene.collection.objects.link(old_water)
    _api().write_values(old_water, {"wave_height": 0.5})
    assert _parts(old_water) == {"caustics"}
    assert _material().water_node(old).inputs["Caustics"].default_value == pytest.approx(0.7)


def _diffuse(name, color):
    material = bpy.data.materials.new(name)
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (*color, 1.0)
    return material


@pytest.fixture(scope="module")
def shore(addon, eevee):
    """A lake over a bed that rises through it, a sun low in the south-west, the camera looking
    across the shore: depth colour, foam and caustics all show where they are on."""
    scene = harness.clean_scene(engine=eevee, width=64, height=40, samples=2)
    harness.addon("engine").enable_ray_tracing(scene)
    harness.set_world_color(scene, (0.35, 0.5, 0.8), 0.6)
    bed = harness.add_cube(scene, (0.0, 0.0, -0.6), material=_diffuse("Sand", (0.8, 0.7, 0.5)), name="Bed")
    bed.scale = (8.0, 8.0, 0.02)
    bed.rotation_euler = (0.0, -0.3, 0.0)
    harness.add_cube(
        scene, (-1.0, 1.0, 0.0), size=0.6, material=_diffuse("Post", (0.3, 0.3, 0.3)), name="Post"
    )
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.rotation_euler = (0.7, 0.0, 2.3)
    sun.data.energy = 3.0
    scene.collection.objects.link(sun)
    added = _api().add_water(scene, size=8, wind_direction=(0.6, 0.8), mirror_setup=False)
    harness.add_camera(scene, (-1.5, -5.0, 3.0), (0.5, 0.5, -0.3))
    return {"scene": scene, "water": added.object, "material": added.material}


@pytest.mark.lts
@pytest.mark.render
def test_a_part_at_zero_renders_as_the_part_left_out(shore, render):
    scene, material = shore["scene"], shore["material"]
    node = _material().water_node(material)
    lean = render(scene, "lean", exr=True)[..., :3]
    assert node.node_tree.name == "Water Surface"
    # Every part built in, each at 0: the picture of the lean group.
    node.node_tree = _material().water_group(parts=EVERY)
    at_zero = render(scene, "every-part-at-zero", exr=True)[..., :3]
    assert np.abs(at_zero - lean).max() < 2e-3, np.abs(at_zero - lean).max()
    # On, they show: the same water with clear_lake's depth, foam and caustics differs.
    _api().write_values(
        shore["water"], {"absorption": (0.45, 0.09, 0.06), "foam_amount": 0.6, "caustics": 1.0}
    )
    on = render(scene, "every-part-on", exr=True)[..., :3]
    assert np.abs(on - lean).mean() > 0.01
    _api().write_values(shore["water"], {"absorption": (0.0, 0.0, 0.0), "foam_amount": 0.0, "caustics": 0.0})
    assert node.node_tree.name == "Water Surface"


@pytest.mark.render
def test_saved_with_parts_on_or_off_renders_the_same_without_the_add_on(
    shore, render, tmp_path, addon_disabled_afterwards
):
    scene, water = shore["scene"], shore["water"]
    second = water.copy()
    second.data = water.data.copy()
    second.data.materials[0] = water.active_material.copy()
    second.location.x += 8.0
    scene.collection.objects.link(second)
    _api().write_values(second, {"absorption": (0.45, 0.09, 0.06), "foam_amount": 0.6, "caustics": 1.0})
    assert _parts(water) == set() and _parts(second) == EVERY
    harness.add_camera(scene, (4.0, -9.0, 5.0), (4.0, 0.5, -0.3))
    path = tmp_path / "parts.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    before = render(scene, "with-addon", exr=True)[..., :3]

    after = render(harness.reopen_without_add_on(path), "without-addon", exr=True)[..., :3]
    assert np.abs(after - before).max() < 2e-3, np.abs(after - before).max()
