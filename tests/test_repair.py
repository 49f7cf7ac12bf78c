"""A water whose group was replaced or lost sockets: shown as needing repair (no KeyError), then repaired."""

import types

import bpy
import pytest

import harness


class Layout:
    """Stands in for the panel's `UILayout` (none exists without a window): records what is drawn,
    and fails as Blender would not silently do on an unknown operator or property."""

    def __init__(self, log):
        self.log = log
        self.use_property_split = False

    def label(self, text="", icon="NONE"):
        self.log.append(("label", text, icon))

    def operator(self, idname, text="", icon="NONE", **_options):
        module, name = idname.split(".")
        getattr(getattr(bpy.ops, module), name).get_rna_type()  # KeyError for an unknown operator
        self.log.append(("operator", idname, text))
        return types.SimpleNamespace()  # the button's properties, set by the panel

    def menu(self, menu, text="", icon="NONE"):
        assert hasattr(bpy.types, menu), menu
        self.log.append(("menu", menu, text))

    def prop(self, owner, path, text="", index=-1, **_options):
        value = owner.path_resolve(path)
        if index >= 0:
            value = value[index]
        self.log.append(("prop", getattr(owner, "name", ""), path, text))

    def separator(self, **_options):
        pass

    def box(self):
        return Layout(self.log)

    def row(self, align=False):
        return Layout(self.log)

    def column(self, align=False):
        return Layout(self.log)


def draw_panel():
    """Runs the sidebar panel's own `draw` for the active object; returns what it drew."""
    panel_class = harness.addon("ui.panel").VIEW3D_PT_water_surface
    log = []
    methods = {name: value for name, value in vars(panel_class).items() if name.startswith("draw_")}
    panel = type("Panel", (), {"layout": Layout(log), **methods})()
    # Once anything asks whether the panel is extended, Blender wraps `draw` in a dispatcher that
    # needs a real layout and workspace; the panel's own draw is the first function it holds.
    draw = getattr(panel_class.draw, "_draw_funcs", [panel_class.draw])[0]
    draw(panel, bpy.context)
    return log


def _labels(log, icon):
    return [entry[1] for entry in log if entry[0] == "label" and entry[2] == icon]


def _props(log):
    return [entry[3] for entry in log if entry[0] == "prop"]


def _lake(wave_height=0.7):
    sun = bpy.data.objects.new("Key Sun", bpy.data.lights.new("Key Sun", "SUN"))
    bpy.context.scene.collection.objects.link(sun)
    assert bpy.ops.object.water_add(mirror_setup=False) == {"FINISHED"}
    water = bpy.context.active_object
    material = water.active_material
    node = harness.addon("nodes.material").water_node(material)
    node.inputs["Wave Height"].default_value = wave_height
    node.inputs["Dull Color"].default_value = (0.9, 0.1, 0.2, 1.0)
    return water, material, node


def _remove_input(tree, name):
    tree.interface.remove(next(i for i in tree.interface.items_tree if i.name == name))


def _expected_inputs():
    return [socket.name for socket in harness.addon("nodes.lake.water_surface").INPUTS]


def _refused_until_repaired():
    """Every lake operator refuses the broken water with a message that says to repair it."""
    calls = [
        (bpy.ops.object.water_preset_apply, {"preset": "calm_mirror"}),
        (bpy.ops.object.water_sun_set, {"sun": "NONE"}),
        (bpy.ops.object.water_bump_set, {"image": "DEFAULT"}),
        (bpy.ops.object.water_mirror_setup, {}),
    ]
    for operator, args in calls:
        assert not operator.poll(), operator
        with pytest.raises(RuntimeError, match="needs repair.*repair it first"):
            operator(**args)


def _assert_drivers_on_their_sockets(material):
    """Time and the sun drive the right inputs again, and the glint still follows the scene's sun."""
    tree = material.node_tree
    paths = [f.data_path.rpartition(".")[0] for f in tree.animation_data.drivers]
    driven = sorted(tree.path_resolve(path).name for path in paths)
    assert driven == ["Sun Color"] * 3 + ["Sun Direction"] * 3 + ["Sun Lit", "Time"]
    assert harness.addon("nodes.material").glint_sun(material) == bpy.data.objects["Key Sun"]


def test_a_removed_socket_shows_repair_and_repair_keeps_the_values_left(scene):
    values = harness.addon("water.values")
    water, material, node = _lake()
    assert _props(draw_panel()), "a sound water shows its inputs"

    _remove_input(node.node_tree, "Wave Length")
    log = draw_panel()  # no KeyError
    repair = harness.addon("water.repair")
    problem = repair.needs_repair(material)
    assert problem is not None and "'Wave Length'" in problem
    assert _labels(log, "ERROR") == [problem]
    assert ("operator", "object.water_repair", "") in log
    assert not _props(log), "no input of a broken water is drawn"

    read = values.read_values(material)  # no KeyError: the missing input is left out
    assert "wave_length" not in read and read["wave_height"] == pytest.approx(0.7)
    assert "wave_length" not in values.write_values(material, {"wave_length": 0.5, "wind_force": 0.05})
    _refused_until_repaired()
    assert node.inputs["Wave Height"].default_value == pytest.approx(0.7)

    assert bpy.ops.object.water_repair() == {"FINISHED"}
    assert repair.needs_repair(material) is None
    assert node.node_tree.name == "Water Surface", "the add-on's group is rebuilt in place"
    assert [s.name for s in node.inputs] == _expected_inputs()
    assert node.inputs["Wave Height"].default_value == pytest.approx(0.7)
    assert tuple(node.inputs["Dull Color"].default_value) == pytest.approx((0.9, 0.1, 0.2, 1.0))
    assert node.inputs["Wave Length"].default_value == pytest.approx(0.1), "a lost input takes its default"
    _assert_drivers_on_their_sockets(material)
    log = draw_panel()
    assert not _labels(log, "ERROR")[:1] or "Mirror" in _labels(log, "ERROR")[0]
    assert "Wave Length" in _props(log)
    assert bpy.ops.object.water_preset_apply(preset="calm_mirror") == {"FINISHED"}
    assert repair.needs_repair(material) is None
    assert bpy.ops.object.water_repair.poll() is False  # nothing to repair
    with pytest.raises(RuntimeError, match="needs no repair"):
        bpy.ops.object.water_repair()


def test_a_replaced_group_shows_repair_and_repair_brings_back_the_add_ons(scene):
    water, material, node = _lake()
    own = node.node_tree
    group = bpy.data.node_groups.new("My Group", "ShaderNodeTree")
    group.interface.new_socket("Wave Height", in_out="INPUT", socket_type="NodeSocketFloat")
    group.interface.new_socket("Shader", in_out="OUTPUT", socket_type="NodeSocketShader")
    node.node_tree = group
    node.inputs["Wave Height"].default_value = 0.7

    log = draw_panel()  # no KeyError
    problem = harness.addon("water.repair").needs_repair(material)
    assert "'My Group', not the add-on's group" in problem
    assert _labels(log, "ERROR") == [problem] and ("operator", "object.water_repair", "") in log
    assert "wave_length" not in harness.addon("water.values").read_values(material)
    _refused_until_repaired()

    assert bpy.ops.object.water_repair() == {"FINISHED"}
    assert harness.addon("water.repair").needs_repair(material) is None
    assert node.node_tree == own and group.users == 0
    assert [s.name for s in node.inputs] == _expected_inputs()
    assert node.inputs["Wave Height"].default_value == pytest.approx(0.7), "a kept socket's value stays"
    _assert_drivers_on_their_sockets(material)
    output = next(n for n in material.node_tree.nodes if n.type == "OUTPUT_MATERIAL")
    assert [link.from_socket.name for link in output.inputs["Surface"].links] == ["Shader"]
    assert output.inputs["Surface"].links[0].from_node == node
    assert "Wave Height" in _props(draw_panel())


def test_an_ocean_whose_group_lost_a_socket_shows_repair_and_is_repaired(scene):
    assert bpy.ops.object.water_add(preset="ocean", resolution=3, size=10) == {"FINISHED"}
    material = bpy.context.active_object.active_material
    normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(material)
    normal.inputs["Bump Strength"].default_value = 0.7
    assert "Deep Color" in _props(draw_panel())

    _remove_input(shade.node_tree, "Deep Color")
    log = draw_panel()  # no KeyError
    repair = harness.addon("water.repair")
    problem = repair.needs_repair(material)
    assert "'Deep Color'" in problem
    assert _labels(log, "ERROR") == [problem] and ("operator", "object.water_repair", "") in log

    assert bpy.ops.object.water_repair() == {"FINISHED"}
    assert repair.needs_repair(material) is None
    normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(material)
    assert "Deep Color" in [s.name for s in shade.inputs]
    assert normal.inputs["Bump Strength"].default_value == pytest.approx(0.7)
    assert shade.inputs["Normal"].links[0].from_socket == normal.outputs["Normal"]
    tree = material.node_tree
    driven = [tree.path_resolve(f.data_path.rpartition(".")[0]) for f in tree.animation_data.drivers]
    assert [socket.name for socket in driven if socket.node == normal] == ["Time"]
    assert "Deep Color" in _props(draw_panel())


def test_repairing_one_of_two_waters_gives_the_other_the_lost_input_s_default(scene):
    api = harness.addon("api")
    first = api.add_water(scene, see_surroundings=False, mirror_setup=False)
    second = api.add_water(scene, see_surroundings=False, mirror_setup=False, location=(200.0, 0.0, 0.0))
    material = harness.addon("nodes.material")
    a, b = material.water_node(first.material), material.water_node(second.material)
    assert a.node_tree == b.node_tree, "one group shared"
    b.inputs["Wave Height"].default_value = 0.45
    _remove_input(a.node_tree, "Wave Length")
    harness.addon("water.repair").repair_water(first.material, scene)
    bpy.context.view_layer.update()
    assert a.node_tree == b.node_tree and harness.addon("water.repair").needs_repair(second.material) is None
    # Blender gives a socket added back to a shared group 0 on the other nodes: the default here.
    assert b.inputs["Wave Length"].default_value == pytest.approx(0.1)
    assert b.inputs["Wave Height"].default_value == pytest.approx(0.45), "the other's own values stay"
