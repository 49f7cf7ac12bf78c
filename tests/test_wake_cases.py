"""Issue 37 point 4: the cases a new user met that crashed, went stale or left things half-made.

* Two objects selected and no water: Float on Water (wake on) and Add Wake act on both (the
  water below each found before any is changed: ray casting a water of the depsgraph from before
  a wake was added crashed Blender).
* Typed, one-line errors, with nothing half-made: `bake(None)`, a strength that is not a number
  or out of range, a tilt damping of NaN, floating an empty or a flat mesh.
* A Shift+D copy of the water shares its material: taking the copy's wake off keeps the
  original's foam.
"""

import math

import bpy
import pytest

import harness


def _api():
    return harness.addon("api")


def _box(scene, name, location, size=(4.0, 1.5, 1.0)):
    mesh = bpy.data.meshes.new(name)
    half = [s / 2.0 for s in size]
    corners = [
        (x, y, z) for x in (-half[0], half[0]) for y in (-half[1], half[1]) for z in (-half[2], half[2])
    ]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh.from_pydata(corners, [], faces)
    obj = bpy.data.objects.new(name, mesh)
    obj.location = location
    scene.collection.objects.link(obj)
    return obj


def _select(*objects):
    bpy.ops.object.select_all(action="DESELECT")
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]


@pytest.mark.parametrize("operator", ["water_float", "water_wake_add"])
def test_two_objects_selected_and_no_water_both_act_on_the_water_below(scene, operator):
    water = _api().add_water(scene, preset="lake", size=30.0, resolution=61, name="Lake").object
    boats = [_box(scene, f"Boat {i}", (-5.0 + 10.0 * i, 2.0, 0.0)) for i in range(2)]
    _select(*boats)
    assert getattr(bpy.ops.object, operator)() == {"FINISHED"}
    wake = harness.addon("water.wake")
    assert sorted(s.name for s in wake.wake_sources(water)) == ["Boat 0", "Boat 1"]
    if operator == "water_float":
        floating = harness.addon("water.float_constraints")
        assert all(floating.floating_on(boat) == water for boat in boats)


def test_bad_values_are_one_line_errors_and_leave_nothing_half_made(scene):
    api = _api()
    water = api.add_water(scene, preset="lake", size=30.0, resolution=61, name="Lake").object
    boat = _box(scene, "Boat", (0.0, 0.0, 0.0))
    wake = harness.addon("water.wake")
    floating = harness.addon("water.floating")
    with pytest.raises(wake.WakeError, match="not water"):
        api.bake(None)
    for strength in ("x", None, math.nan, -1.0, 11.0):
        with pytest.raises(wake.WakeError, match="strength"):
            api.add_wake_source(boat, water, strength=strength)
    assert wake.wake_modifiers(water) == [], "nothing half-made"
    with pytest.raises(floating.FloatError, match="tilt damping"):
        api.float_on_water(boat, water, tilt_damping=math.nan)
    with pytest.raises(floating.FloatError, match="must be a number"):
        api.float_on_water(boat, water, draft="deep")
    empty = bpy.data.objects.new("Marker", None)
    scene.collection.objects.link(empty)
    flat = _box(scene, "Sheet", (3.0, 0.0, 0.0), size=(0.0, 0.0, 0.0))
    for obj in (empty, flat):
        with pytest.raises(floating.FloatError, match="no size to float by") as caught:
            api.float_on_water(obj, water)
        assert "\n" not in str(caught.value)
        assert harness.addon("water.float_constraints").floating_on(obj) is None
    assert floating.floating_on(boat) is None and wake.wake_modifiers(water) == []
    # Named, the footprint floats even an empty (a marker a rig hangs from).
    api.float_on_water(empty, water, length=2.0, beam=1.0, wake=False)
    assert floating.floating_on(empty) == water


def test_taking_a_copys_wake_off_keeps_the_originals_foam(scene):
    api = _api()
    water = api.add_water(scene, preset="lake", size=30.0, resolution=61, name="Lake").object
    copy = water.copy()  # what Shift+D makes: the mesh's data copied, the material shared
    copy.data = water.data.copy()
    copy.location.x += 40.0
    scene.collection.objects.link(copy)
    assert copy.active_material == water.active_material
    boats = [_box(scene, "Boat", (0.0, 0.0, 0.0)), _box(scene, "Boat 2", (40.0, 0.0, 0.0))]
    api.add_wake_source(boats[0], water)
    api.add_wake_source(boats[1], copy)
    api.remove_wake_source(boats[1], copy)
    nodes = water.active_material.node_tree.nodes
    assert "Water Wake Foam" in nodes, "the original still leaves foam"
    assert nodes["Material Output"].inputs["Surface"].links[0].from_node.name == "Water Wake Foam"
    api.remove_wake_source(boats[0], water)
    assert "Water Wake Foam" not in nodes


def test_on_the_default_lake_the_panel_says_the_mesh_is_too_coarse_and_offers_a_resolution(scene):
    from test_repair import draw_panel

    api = _api()
    water = api.add_water(scene, preset="lake", name="Lake").object  # its four corners
    assert len(water.data.vertices) == 4
    boat = _box(scene, "Boat", (0.0, 0.0, 0.0))
    changes = api.float_on_water(boat, water)
    note = next(change for change in changes if "too coarse" in change)
    print(note)
    assert "Resolution 129 or more" in note  # 128 m at 1 m: a 4 m hull's waves need 1 m cells
    (modifier,) = harness.addon("water.wake").wake_modifiers(water)
    detail = modifier.node_group.interface.items_tree["Detail"]
    assert harness.addon("water.waves").get_wave_input(modifier, "Detail") <= detail.max_value
    _select(boat)
    labels = [entry[1] for entry in draw_panel() if entry[0] == "label"]
    assert note in labels
    fine = api.add_water(scene, preset="lake", size=30.0, resolution=121, name="Fine").object
    other = _box(scene, "Other", (0.0, 0.0, 0.0))
    assert not any("too coarse" in change for change in api.add_wake_source(other, fine))
