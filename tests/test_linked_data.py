"""Water, materials, groups and lights linked or overridden from a library: every operator refuses
them in its `poll`, with a message, and nothing of them is edited."""

import re

import bpy
import pytest
from test_repair import draw_panel

import harness

LINKED = "is linked from library.blend: make it local (Object > Relations > Make Local)"
OVERRIDE = "is a library override of library.blend: make it local"


@pytest.fixture
def library(scene, tmp_path):
    """A .blend holding a water with waves, a sun and a collection, saved; then a clean scene."""
    sun = bpy.data.objects.new("Lib Sun", bpy.data.lights.new("Lib Sun", "SUN"))
    collection = bpy.data.collections.new("Lib Stuff")
    scene.collection.children.link(collection)
    collection.objects.link(sun)
    assert bpy.ops.object.water_add(mirror_setup=False, resolution=8, waves=True) == {"FINISHED"}
    node = harness.addon("nodes.material").water_node(bpy.context.active_object.active_material)
    node.inputs["Wave Height"].default_value = 0.7
    path = tmp_path / "library.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path), copy=True)
    harness.clean_scene()
    return path


def _link(path, **names):
    """Links (not appends) the named data-blocks; returns them by kind."""
    with bpy.data.libraries.load(str(path), link=True) as (_source, target):
        for kind, wanted in names.items():
            setattr(target, kind, list(wanted))
    return {kind: list(getattr(target, kind)) for kind in names}


def _make_active(obj):
    scene = bpy.context.scene
    if obj.name not in scene.objects:
        scene.collection.objects.link(obj)
    for other in bpy.context.selected_objects:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def _state(water):
    """What an operator would change on the water: material values, drivers, modifiers, group."""
    material = water.active_material
    node = harness.addon("nodes.material").water_node(material)
    animation = material.node_tree.animation_data
    return {
        "values": harness.addon("water.values").read_values(material),
        "drivers": sorted(f.data_path for f in animation.drivers) if animation else [],
        "modifiers": [(m.name, m.type, m.node_group.name if m.node_group else None) for m in water.modifiers],
        "group": node.node_tree.name,
        "children": [child.name for child in water.children],
        "hide_probe_plane": water.hide_probe_plane,
        "groups": sorted(g.name for g in bpy.data.node_groups),
        "raytracing": bpy.context.scene.eevee.use_raytracing,
    }


# Each water operator with the arguments it would run with.
WATER_OPERATORS = [
    ("water_mirror_setup", {}),
    ("water_waves_add", {}),
    ("water_sun_set", {"sun": "NONE"}),
    ("water_bump_set", {"image": "DEFAULT"}),
    ("water_preset_apply", {"preset": "calm_mirror"}),
    ("water_repair", {}),
]


def _assert_all_refused(water, message):
    """Every operator's poll fails; `bpy.ops` raises with the poll message (the repair operator,
    which edits only the material, names the linked material)."""
    before = _state(water)
    for name, args in WATER_OPERATORS:
        operator = getattr(bpy.ops.object, name)
        assert operator.poll() is False, name
        with pytest.raises(RuntimeError, match=re.escape(f"bpy.ops.object.{name}.poll()")) as error:
            operator(**args)
        owner = "Material 'Water'" if name == "water_repair" else "Object 'Water'"
        expected = f"{owner} {LINKED if name == 'water_repair' else message}"
        assert expected in str(error.value), (name, str(error.value))
    assert _state(water) == before, "nothing linked was edited"
    assert _state(water)["values"]["wave_height"] == pytest.approx(0.7)


def test_linked_water_is_refused_by_every_operator_and_left_as_it_was(library):
    water = _link(library, objects=["Water"])["objects"][0]
    assert water.library is not None and water.active_material.library is not None
    _make_active(water)
    _assert_all_refused(water, LINKED)
    editable = harness.addon("water.editable")
    assert editable.why_not_editable(water) == (
        "Object 'Water' is linked from library.blend: "
        "make it local (Object > Relations > Make Local) or edit it in its library"
    )
    with pytest.raises(editable.NotEditableError, match="Material 'Water' is linked"):
        editable.check_editable(None, water.active_material)
    # Reading it is no edit: its values may still be saved as a preset.
    assert bpy.ops.object.water_preset_add.poll()
    log = draw_panel()
    assert any(entry[0] == "label" and LINKED in entry[1] for entry in log)


def test_an_overridden_water_is_refused_too(library):
    linked = _link(library, objects=["Water"])["objects"][0]
    bpy.context.scene.collection.objects.link(linked)
    water = linked.override_create(remap_local_usages=True)
    assert water is not None and water.override_library is not None and water.library is None
    _make_active(water)
    _assert_all_refused(water, OVERRIDE)


def test_a_linked_sun_is_refused_as_the_glint_sun(scene, library):
    material_module = harness.addon("nodes.material")
    assert bpy.ops.object.water_add(mirror_setup=False) == {"FINISHED"}
    water = bpy.context.active_object
    sun = _link(library, objects=["Lib Sun"])["objects"][0]
    bpy.context.scene.collection.objects.link(sun)
    assert bpy.ops.object.water_sun_set.poll(), "the water itself is local"
    with pytest.raises(RuntimeError, match=re.escape(f"Object 'Lib Sun' {LINKED}")):
        bpy.ops.object.water_sun_set(sun="Lib Sun")
    assert material_module.glint_sun(water.active_material) is None
    assert sun.light_linking.receiver_collection is None
    assert bpy.ops.object.water_sun_set(sun="NONE") == {"FINISHED"}


def test_adding_water_into_a_linked_collection_or_scene_is_refused(library):
    linked = _link(library, collections=["Lib Stuff"], scenes=["Scene"])
    collection, lib_scene = linked["collections"][0], linked["scenes"][0]
    scene = bpy.context.scene
    assert bpy.ops.object.water_add.poll()
    scene.collection.children.link(collection)
    layer = bpy.context.view_layer.layer_collection.children[collection.name]
    bpy.context.view_layer.active_layer_collection = layer
    assert not bpy.ops.object.water_add.poll()
    before = set(bpy.data.objects)
    with pytest.raises(RuntimeError, match=re.escape(f"Collection 'Lib Stuff' {LINKED}")):
        bpy.ops.object.water_add()
    assert set(bpy.data.objects) == before and len(collection.objects) == 1
    with bpy.context.temp_override(scene=lib_scene):
        assert not bpy.ops.object.water_add.poll()
        with pytest.raises(RuntimeError, match=re.escape(f"Scene 'Scene' {LINKED}")):
            bpy.ops.object.water_add()
    assert set(bpy.data.objects) == before
