"""Issue 57 point 4: a water's parts follow it at once.

A water deleted the ordinary way (X: `bpy.ops.object.delete`) is only taken out of the scene:
its underwater body's modifier still refers to it, so Blender keeps it, with its hidden
children, and a camera under where it was would still see its fog and waterline. A kept-out hull
deleted so would keep its dry hole in the water. The add-on's edit-time handler takes them apart
at the first update after: nothing of the water evaluates, its camera renders what it rendered
before the water, and nothing of it is in the saved file. Remove Water leaves nothing either,
saved before or not: every kind of data-block is counted before the water and after, with saves
in between (Blender 5 counts a user more for each modifier input at every save, which kept the
fog's materials and their groups for two more saves).
"""

import bpy
import numpy as np
import pytest

import harness

# What a file holds of the interface: the same before and after, not the water's to leave.
_INTERFACE = {"window_managers", "screens", "workspaces", "all_ids"}


def _api():
    return harness.addon("api")


def _blocks():
    """The names of every data-block in the file, by kind (objects, meshes, materials, node groups,
    images, lights, collections, worlds, texts, actions, ...)."""
    found = {}
    for kind in dir(bpy.data):
        blocks = getattr(bpy.data, kind, None)
        if kind in _INTERFACE or not isinstance(blocks, bpy.types.bpy_prop_collection):
            continue
        found[kind] = sorted(block.name for block in blocks if isinstance(block, bpy.types.ID))
    return found


def _differ(before, after):
    """{kind: (added, gone)} where `after` holds other data-blocks than `before`."""
    return {
        kind: (sorted(set(after[kind]) - set(before[kind])), sorted(set(before[kind]) - set(after[kind])))
        for kind in after
        if after[kind] != before.get(kind)
    }


def _save_and_reopen(path):
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    bpy.ops.wm.open_mainfile(filepath=str(path))
    return bpy.context.scene


def _drawn():
    """(object, vertices) of every instance the scene's depsgraph draws."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    return sorted(
        (instance.object.name, len(instance.object.data.vertices) if instance.object.type == "MESH" else 0)
        for instance in depsgraph.object_instances
    )


def _delete(obj):
    """X in the 3D view: the ordinary delete of the selected object."""
    for other in bpy.context.view_layer.objects.selected:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj
    assert bpy.ops.object.delete() == {"FINISHED"}


def _sun(scene):
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    scene.collection.objects.link(sun)
    sun.rotation_euler = (0.5, 0.2, 0.8)
    return sun


@pytest.fixture
def under(scene):
    """A camera 1 m under where the water goes, looking at a post 4 m away, lit by a sun; 64 x 36
    pixels at one sample (the fog's tint, all of the frame, shows at one)."""
    scene.render.resolution_x, scene.render.resolution_y = 64, 36
    scene.eevee.taa_render_samples = 1
    harness.set_world_color(scene, (0.5, 0.6, 0.7))
    _sun(scene)
    harness.add_cube(scene, (4.0, 0.0, -1.0), size=1.0, name="Post")
    harness.add_camera(scene, (0.0, 0.0, -1.0), (4.0, 0.0, -1.0))
    return scene


def _add_water(scene):
    """A murky pond over the camera (it hides a post 3 m away), with caustics: its underwater body
    and its caustic light."""
    return _api().add_water(scene, preset="murky_pond", size=20, resolution=16, caustics=1.0).object


@pytest.mark.lts
def test_a_deleted_water_leaves_nothing_that_evaluates_and_nothing_in_the_saved_file(under, tmp_path):
    scene = _save_and_reopen(tmp_path / "under.blend")
    blocks, drawn = _blocks(), _drawn()
    water = _add_water(scene)
    name = water.name
    with_water = dict(_drawn())
    for part in ("Underwater", "Caustic Light"):  # the camera is under it: both are made
        assert with_water.get(f"{name} {part}", 0) > 0, (part, with_water)
    _delete(water)
    assert _drawn() == drawn, "nothing of the water evaluates, before any save"
    assert not [o.name for o in bpy.data.objects if o.name.startswith(name)]
    _save_and_reopen(tmp_path / "deleted.blend")
    assert _differ(blocks, _blocks()) == {}


@pytest.mark.render
def test_a_camera_under_a_deleted_water_renders_what_it_did_before_the_water(under, render):
    before = render(under, "before")
    _delete(_add_water(under))
    after = render(under, "after")
    assert np.abs(after - before).max() < 0.02, "no fog, waterline or caustic light is left"


def test_a_deleted_hull_leaves_no_dry_hole_and_the_water_its_parts(scene, tmp_path):
    keep_out = harness.addon("water.boats.keep_out")
    water = _api().add_water(scene, size=12, resolution=16).object
    material = water.active_material
    boat = harness.add_cube(scene, (0.0, 0.0, 0.0), size=2.0, name="Boat")
    _api().float_on_water(boat, water)
    _api().keep_water_out(boat, water)
    assert keep_out.hulls_of(water) == [boat]
    _delete(boat)
    assert keep_out.hull_nodes(material) == [], "no dry mask reads the deleted hull"
    assert material.node_tree.nodes.get(keep_out.MIX_NODE) is None, "nothing cuts the water"
    assert not [n.name for n in material.node_tree.nodes if getattr(n, "object", None) is not None]
    assert not harness.addon("water.boats.wake").wake_modifiers(water), "no wake of it either"
    assert harness.addon("water.underwater").find(water) is not None, "the water keeps its own parts"
    _save_and_reopen(tmp_path / "hull.blend")
    assert "Boat" not in bpy.data.objects
    assert not [i.name for i in bpy.data.images if "Boat" in i.name]
    assert not [g.name for g in bpy.data.node_groups if g.name.startswith(keep_out.MIX_NODE)]


@pytest.mark.parametrize(
    ("preset", "saved_before"), [("lake", False), ("lake", True), ("ocean", True), ("open_sea", True)]
)
def test_remove_water_leaves_nothing_saved_before_or_not(scene, tmp_path, preset, saved_before):
    _sun(scene)
    harness.add_cube(scene, (0.0, 0.0, -3.0), size=4.0, name="Bed")
    harness.add_cube(scene, (-1.0, 0.5, 0.0), size=1.0, name="Boat")
    path = tmp_path / "pool.blend"
    scene = _save_and_reopen(path)
    blocks = _blocks()
    extra = {"sea_wind_speed": 6.0} if preset == "open_sea" else {"waves": True}
    water = _api().add_water(scene, preset=preset, size=12, resolution=16, caustics=1.0, **extra).object
    boat = bpy.data.objects["Boat"]
    _api().float_on_water(boat, water)
    _api().keep_water_out(boat, water)
    if not saved_before:  # Cycles' own caustics (its scene settings, the sun) instead of the caustic light
        _api().set_physical_caustics(water, True, scene)
    else:  # the caustic light's material and groups are what a save kept
        assert harness.addon("water.underwater").find(water, "Caustic Light") is not None
    if saved_before:
        bpy.ops.wm.save_as_mainfile(filepath=str(path))
    _api().remove_water(water, scene)
    assert _differ(blocks, _blocks()) == {}, "Remove Water leaves nothing, before any save"
    _save_and_reopen(path)
    assert _differ(blocks, _blocks()) == {}
