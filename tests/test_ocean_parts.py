"""The ocean shading's caustics cost nothing while they are off (issue 24 point 6: the open sea's
render within 1.1x the Ocean modifier under a Principled water; `tools/bench open_sea_cost`).

They are in the `Water Ocean Shade` group only while `Caustics` is above 0: the default open sea
(its bed 200 m down) has none; every entry point that writes values switches them; repair keeps
them; groups saved before (version 5, caustics built in) keep rendering as they did. That a
shade with the caustics built in and at 0 renders as the lean one is held in
`test_sea_surroundings.py`, over a shallow bed.
"""

import bpy
import pytest

import harness


def _api():
    return harness.addon("api")


def _ocean_material():
    return harness.addon("nodes.sea.ocean_material")


def _shade(water):
    return _ocean_material().ocean_nodes(water.active_material)[1]


def _has_caustics(water):
    return "caustics" in _shade(water).node_tree.nodes


def test_the_default_open_sea_has_no_caustics_in_its_shade(scene):
    sea = _api().add_water(scene, preset="open_sea", resolution=33, name="Sea").object
    tree = _shade(sea).node_tree
    assert tree.name == "Water Ocean Shade + Traced Sky"
    assert not any(node.type == "GROUP" and "Caustics" in node.node_tree.name for node in tree.nodes)
    assert _api().read_values(sea)["caustics"] == 0.0


def test_caustics_come_and_go_with_their_value_keeping_every_other(scene):
    sea = _api().add_water(scene, preset="open_sea", resolution=33, caustics=0.8, name="Sea").object
    assert _has_caustics(sea)
    assert _shade(sea).node_tree.name == "Water Ocean Shade + Traced Sky + Caustics"
    _api().write_values(sea, {"foam_width": 2.5})
    assert _has_caustics(sea)
    _api().write_values(sea, {"caustics": 0.0})
    assert not _has_caustics(sea)
    values = _api().read_values(sea)
    assert values["foam_width"] == pytest.approx(2.5)
    _api().write_values(sea, {"caustics": 1.5})
    assert _has_caustics(sea)
    assert _api().read_values(sea)["caustics"] == pytest.approx(1.5)
    # The whitecaps' coverage is driven from the wind: the driver survives the swaps.
    shade = _shade(sea)
    driven = [
        sea.active_material.node_tree.path_resolve(curve.data_path.rpartition(".")[0])
        for curve in sea.active_material.node_tree.animation_data.drivers
    ]
    assert shade.inputs["Whitecap Coverage"] in driven
    assert not [
        g.name for g in bpy.data.node_groups if g.name.startswith("Water Ocean Shade") and g.users == 0
    ]


def test_repair_keeps_the_caustics_variant(scene):
    """The user takes an input out of the shade; repair gives back the variant with the caustics."""
    sea = _api().add_water(scene, preset="open_sea", resolution=33, caustics=1.0, name="Sea").object
    tree = _shade(sea).node_tree
    tree.interface.remove(next(i for i in tree.interface.items_tree if i.name == "Foam Width"))
    repair = harness.addon("water.repair")
    assert repair.needs_repair(sea.active_material)
    repair.repair_water(sea.active_material, scene)
    assert repair.needs_repair(sea.active_material) is None
    assert _has_caustics(sea)
    assert _api().read_values(sea)["caustics"] == pytest.approx(1.0)


def test_an_old_files_shade_keeps_its_caustics_and_its_materials(scene):
    """A `Water Ocean Shade` group as version 5 saved it: caustics built in, the lean group's role
    and name. The updated add-on gives it the caustics variant's; a new sea gets the group without
    caustics (with the traced sky, every new sea's)."""
    old = _api().add_water(scene, preset="open_sea", resolution=33, caustics=0.7, name="Old Sea").object
    legacy = _shade(old).node_tree
    ownership = harness.addon("nodes.ownership")
    for tree in [g for g in bpy.data.node_groups if g.name == "Water Ocean Shade"]:
        bpy.data.node_groups.remove(tree)
    legacy.name = "Water Ocean Shade"
    ownership.mark(legacy, "Water Ocean Shade", 5)

    new = _api().add_water(scene, preset="open_sea", resolution=33, name="New Sea").object
    assert _shade(old).node_tree == legacy, "the old material keeps its group"
    assert legacy.name == "Water Ocean Shade + Caustics"
    assert ownership.role_of(legacy) == legacy.name
    assert _shade(new).node_tree.name == "Water Ocean Shade + Traced Sky"
    assert not _has_caustics(new)
    assert _shade(old).inputs["Caustics"].default_value == pytest.approx(0.7)


def test_the_panel_switch_puts_the_seas_caustics_in_and_out(scene):
    """`object.water_part_switch` (the panel's Caustics switch) on the open sea and the seeds' ocean."""
    for preset in ("open_sea", "ocean"):
        water = _api().add_water(scene, preset=preset, resolution=33, name=f"Water {preset}").object
        bpy.ops.object.select_all(action="DESELECT")
        water.select_set(True)
        bpy.context.view_layer.objects.active = water
        assert not _has_caustics(water)
        assert bpy.ops.object.water_part_switch(part="caustics", enable=True) == {"FINISHED"}
        assert _has_caustics(water)
        assert _shade(water).inputs["Caustics"].default_value == pytest.approx(1.0)
        assert bpy.ops.object.water_part_switch(part="caustics", enable=False) == {"FINISHED"}
        assert not _has_caustics(water)
        with pytest.raises(RuntimeError, match="no part 'foam' to switch on the ocean shading"):
            bpy.ops.object.water_part_switch(part="foam", enable=False)
        with pytest.raises(ValueError, match="no part 'depth'"):
            _api().switch_part(water, "depth", False)
