"""The node groups as data: interface, reuse by name, versioned upgrades, bump image, per-material images."""

import bpy
import numpy as np
import pytest

import harness

EXPECTED_INPUTS = {
    "Wave Height": 0.3,
    "Wave Length": 0.1,
    "Wind Direction": (0.0, 1.0, 0.0),
    "Wind Force": 0.02,
    "Time": 0.0,
    "Bump Layers": 1,
    "Dull Color": (0.3, 0.3, 0.5, 1.0),
    "Dull Blend": 0.2,
    "Specular Power": 256.0,
    "Specular Strength": 1.0,
    "Sun Direction": (-0.57735, 0.57735, -0.57735),
    "Sun Color": (1.0, 1.0, 1.0, 1.0),
    "Bump Strength": 1.0,
    "Debug View": 0,
    "Absorption": (0.0, 0.0, 0.0, 1.0),
    "Scatter Color": (0.0, 0.05, 0.06, 1.0),
    "Foam Width": 1.0,
    "Foam Amount": 0.0,
    "Caustics": 0.0,
    "Caustics Scale": 1.0,
    "Sun Lit": 1.0,
}


def _nodes():
    return harness.addon("nodes")


def _material():
    return harness.addon("nodes.material")


def _built(name):
    """How many of the spec's nodes this Blender builds (some are built from or before a version)."""
    builder = harness.addon("nodes.builder")
    return sum(builder._built_here(node) for node in _nodes().SPECS[name].nodes.values())


def _sockets(tree, in_out):
    return [i for i in tree.interface.items_tree if i.item_type == "SOCKET" and i.in_out == in_out]


def test_group_interface_is_the_reference_model(scene):
    tree = _material().water_group()
    assert tree.bl_idname == "ShaderNodeTree" and tree.name == "Water Surface"
    outputs = _sockets(tree, "OUTPUT")
    assert [(s.name, s.socket_type) for s in outputs] == [("Shader", "NodeSocketShader")]
    inputs = {s.name: s for s in _sockets(tree, "INPUT")}
    assert list(inputs) == list(EXPECTED_INPUTS)
    for name, default in EXPECTED_INPUTS.items():
        value = inputs[name].default_value
        value = tuple(value) if hasattr(value, "__len__") else value
        assert value == pytest.approx(default, abs=1e-5), name
        assert len(inputs[name].description) > 10, f"{name} has no tooltip"
    assert inputs["Debug View"].socket_type == "NodeSocketInt"
    assert (inputs["Debug View"].min_value, inputs["Debug View"].max_value) == (0, 8)
    assert (inputs["Caustics"].min_value, inputs["Caustics Scale"].min_value) == (0, pytest.approx(0.05))
    assert inputs["Foam Width"].min_value == pytest.approx(0.01)
    assert (inputs["Foam Amount"].min_value, inputs["Foam Amount"].max_value) == (0, 1)
    assert inputs["Wave Length"].min_value > 0
    assert inputs["Specular Power"].min_value >= 1
    assert inputs["Dull Blend"].max_value == 1
    assert inputs["Time"].subtype == "TIME_ABSOLUTE"


def test_building_again_reuses_groups_and_image(scene):
    first = _material().make_water_material("A", scene=scene)
    groups = {g.name: g.as_pointer() for g in bpy.data.node_groups}
    for name in ("B", "C"):
        _material().make_water_material(name, scene=scene)
    assert {g.name: g.as_pointer() for g in bpy.data.node_groups} == groups
    assert not [g.name for g in bpy.data.node_groups if g.name[-4:-3] == "." and g.name[-3:].isdigit()]
    # A new material has no optional part (depth, foam, caustics): neither their groups nor
    # their tiles are made until a value turns one on.
    assert sorted(i.name for i in bpy.data.images) == ["Water Surface Bump"]
    assert sorted(groups) == [
        "Water Surface",
        "Water Surface Bump UV",
        "Water Surface Wind Frame",
        "Water Underside",
    ]
    assert _material().water_node(first).node_tree.name == "Water Surface"
    full = _material().water_group(parts=("depth", "foam", "caustics"))
    assert full.name == "Water Surface + Depth + Foam + Caustics"
    assert sorted(i.name for i in bpy.data.images) == [
        "Water Surface Bump",
        "Water Surface Caustics",
        "Water Surface Foam",
    ]
    assert {"Water Surface Caustics", "Water Surface Foam Coverage"} < set(bpy.data.node_groups.keys())
    assert _material().water_group(parts=("caustics", "foam", "depth")) == full


def test_bump_image_is_packed_and_survives_save_and_reload(scene, tmp_path):
    material = _material().make_water_material(scene=scene)
    image = _material().bump_image(material)
    assert image.packed_file is not None and image.colorspace_settings.name == "Non-Color"
    path = tmp_path / "packed.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    bpy.ops.wm.open_mainfile(filepath=str(path))
    reloaded = bpy.data.images["Water Surface Bump"]
    assert reloaded.packed_file is not None and reloaded.size[:] == (512, 512)
    # The pixels read back from the file are the generated normal map (8-bit rounding aside).
    pixels = np.empty(512 * 512 * 4, dtype=np.float32)
    reloaded.pixels.foreach_get(pixels)
    expected = harness.addon("nodes.bump_map").water_normal_map(512).ravel()
    assert np.abs(pixels - expected).max() <= 1 / 255 + 1e-6


def test_older_group_is_upgraded_in_place_keeping_material_values(scene):
    # The variant with every part: the lean `Water Surface` of an older stamp is a legacy group,
    # retired rather than upgraded (test_lake_cost.py).
    every = ("depth", "foam", "caustics")
    spec = harness.addon("nodes.lake.water_surface").spec_with(every)
    material = _material().make_water_material(scene=scene)
    node = _material().water_node(material)
    node.node_tree = tree = _material().water_group(parts=every)
    node.inputs["Wave Height"].default_value = 0.7
    tree["water_surface_version"] = spec.version - 1
    tree.nodes.remove(tree.nodes["fresnel"])  # an old, different build
    pointer = tree.as_pointer()
    again = _material().water_group(parts=every)
    assert again.as_pointer() == pointer
    assert again["water_surface_version"] == spec.version
    builder = harness.addon("nodes.builder")
    assert "fresnel" in again.nodes
    assert len(again.nodes) == sum(builder._built_here(n) for n in spec.nodes.values()) + 2
    node = _material().water_node(material)
    assert node.inputs["Wave Height"].default_value == pytest.approx(0.7)
    assert node.outputs["Shader"].is_linked


def test_lake_and_ocean_see_from_below_by_the_one_underside_group(scene):
    """Issue 41 point 2: Snell's window is worked out once, in `Water Underside` (the normal
    turned to face the eye, F and 1 - F by the Fresnel node at water's IOR); the lake (every
    variant) and the ocean shading each use that group and have no Fresnel node of their own."""
    physics = harness.addon("nodes.physics")
    role_of = harness.addon("nodes.ownership").role_of
    lean = _material().water_group()
    full = _material().water_group(parts=("depth", "foam", "caustics"))
    ocean = harness.addon("nodes.sea.ocean_material").make_ocean_material("Ocean", scene=scene)
    _normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(ocean)
    undersides = set()
    for tree in (lean, full, shade.node_tree):
        users = [n for n in tree.nodes if n.type == "GROUP" and role_of(n.node_tree) == "Water Underside"]
        assert len(users) == 1, f"{tree.name} uses the underside group once"
        assert users[0].inputs["Normal"].is_linked
        assert {link.from_socket.name for link in tree.links if link.from_node == users[0]} >= {
            "Reflected",
            "Refracted",
        }
        assert not [n.name for n in tree.nodes if n.bl_idname == "ShaderNodeFresnel"], tree.name
        undersides.add(users[0].node_tree)
    (underside,) = undersides
    assert underside.name == "Water Underside"
    (fresnel,) = [n for n in underside.nodes if n.bl_idname == "ShaderNodeFresnel"]
    assert fresnel.inputs["IOR"].default_value == pytest.approx(physics.WATER_IOR)
    assert [s.name for s in _sockets(underside, "OUTPUT")] == ["Normal", "Reflected", "Refracted"]


def test_newer_group_is_left_as_it_is(scene):
    tree = _material().water_group()
    tree["water_surface_version"] = 999
    marker = tree.nodes.new("ShaderNodeValue")
    marker.name = "from a newer add-on"
    count = len(bpy.data.node_groups)
    assert _material().water_group() == tree
    assert "from a newer add-on" in tree.nodes and len(bpy.data.node_groups) == count


def test_half_built_group_is_removed_and_named_in_the_error(scene):
    spec_module = harness.addon("nodes.spec")
    broken = spec_module.GroupSpec(
        name="Broken Water",
        version=1,
        description="",
        inputs=(spec_module.Socket("X", "NodeSocketFloat", 1.0),),
        outputs=(spec_module.Socket("Shader", "NodeSocketShader"),),
        nodes={"add": spec_module.math("ADD", 1)},
        links=(("input:X", "add:#0"), ("add:Value", "nowhere:#0")),
    )
    with pytest.raises(RuntimeError, match="'Broken Water'.*nowhere"):
        harness.addon("nodes.builder").ensure_group(broken, {})
    assert "Broken Water" not in bpy.data.node_groups


def test_each_material_can_pick_its_own_normal_map(scene):
    default = _material().make_water_material("Default", scene=scene)
    custom = _material().make_water_material("Custom", scene=scene)
    mine = bpy.data.images.new("My Ripples", 64, 64)
    _material().water_node(custom).inputs["Wave Height"].default_value = 0.5
    _material().set_bump_image(custom, mine)
    assert _material().bump_image(custom) == mine
    assert _material().bump_image(default).name == "Water Surface Bump"
    assert _material().water_node(custom).inputs["Wave Height"].default_value == pytest.approx(0.5)
    third = _material().make_water_material("Also Mine", scene=scene, image=mine)
    assert _material().water_node(third).node_tree == _material().water_node(custom).node_tree
    assert mine.colorspace_settings.name == "Non-Color"
    _material().set_bump_image(custom, None)
    assert _material().bump_image(custom).name == "Water Surface Bump"


def test_sun_direction_follows_the_first_or_picked_sun(scene):
    from mathutils import Vector

    no_sun = _material().make_water_material("NoSun", scene=scene)
    assert tuple(_material().water_node(no_sun).inputs["Sun Direction"].default_value) == pytest.approx(
        EXPECTED_INPUTS["Sun Direction"], abs=1e-5
    )
    suns = []
    for name, rotation in (("First", (0.4, 0.0, 0.0)), ("Second", (0.0, 1.0, 0.5))):
        sun = bpy.data.objects.new(name, bpy.data.lights.new(name, "SUN"))
        sun.rotation_euler = rotation
        scene.collection.objects.link(sun)
        suns.append(sun)
    first = _material().make_water_material("First", scene=scene)
    picked = _material().make_water_material("Picked", scene=scene, sun=suns[1])
    assert _material().glint_sun(first) == suns[0] and _material().glint_sun(picked) == suns[1]
    for material in (first, picked):  # the depsgraph evaluates only materials that objects use
        harness.add_cube(scene, (0, 0, 0)).data.materials.append(material)
    for material, sun in ((first, suns[0]), (picked, suns[1])):
        sun.rotation_euler.x += 0.3  # moving the sun moves the glint
        depsgraph = bpy.context.evaluated_depsgraph_get()
        depsgraph.update()
        travels = sun.matrix_world.to_3x3() @ Vector((0, 0, -1))
        node = _material().water_node(material.evaluated_get(depsgraph))
        assert tuple(node.inputs["Sun Direction"].default_value) == pytest.approx(tuple(travels), abs=1e-5)
    assert all(fc.driver.is_simple_expression for fc in first.node_tree.animation_data.drivers)
