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
import numpy as np
import pytest

import harness


def _api():
    return harness.addon("api")


def _box(scene, name, location, size=(4.0, 1.5, 1.0)):
    return harness.add_box(scene, name, size, location)


def _select(*objects):
    bpy.ops.object.select_all(action="DESELECT")
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]


@pytest.mark.parametrize("operator", ["water_float", "water_wake"])
def test_two_objects_selected_and_no_water_both_act_on_the_water_below(scene, operator):
    water = _api().add_water(scene, preset="lake", size=30.0, resolution=61, name="Lake").object
    boats = [_box(scene, f"Boat {i}", (-5.0 + 10.0 * i, 2.0, 0.0)) for i in range(2)]
    _select(*boats)
    assert getattr(bpy.ops.object, operator)() == {"FINISHED"}
    wake = harness.addon("water.boats.wake")
    assert sorted(s.name for s in map(wake.source_of, wake.wake_modifiers(water))) == ["Boat 0", "Boat 1"]
    if operator == "water_float":
        floating = harness.addon("water.float_constraints")
        assert all(floating.floating_on(boat) == water for boat in boats)


def test_bad_values_are_one_line_errors_and_leave_nothing_half_made(scene):
    api = _api()
    water = api.add_water(scene, preset="lake", size=30.0, resolution=61, name="Lake").object
    boat = _box(scene, "Boat", (0.0, 0.0, 0.0))
    wake = harness.addon("water.boats.wake")
    floating = harness.addon("water.boats.floating")
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
    assert "the wake of 'Boat'" in note, "the note names the hull (it said '?')"
    (modifier,) = harness.addon("water.boats.wake").wake_modifiers(water)
    detail = modifier.node_group.interface.items_tree["Detail"]
    assert harness.addon("water.waves").get_wave_input(modifier, "Detail") <= detail.max_value
    _select(boat)
    labels = [entry[1] for entry in draw_panel() if entry[0] == "label"]
    assert note in labels
    fine = api.add_water(scene, preset="lake", size=30.0, resolution=121, name="Fine").object
    other = _box(scene, "Other", (0.0, 0.0, 0.0))
    assert not any("too coarse" in change for change in api.add_wake_source(other, fine))


def _world_heights(water):
    """{(x, y) in world, rounded to 1 cm: the wake's height in metres} of the evaluated water."""
    evaluated = water.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    try:
        points = np.empty(len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", points)
    finally:
        evaluated.to_mesh_clear()
    points = points.reshape(-1, 3)
    world = np.c_[points, np.ones(len(points))] @ np.array(water.matrix_world).T
    order = np.lexsort((world[:, 1].round(2), world[:, 0].round(2)))
    return world[order, :2], world[order, 2] - water.matrix_world.translation.z


def test_a_scaled_and_turned_water_makes_the_same_wake_in_metres(scene):
    """Two lakes on the same 0.25 m grid in the world, one 40 m scaled 2 and turned a quarter
    turn: the same boat's wake is the same in metres on both (it was worked out in the water's
    units: scale 2 made it ten times lower)."""
    api = _api()
    scene.render.fps = 24
    plain = api.add_water(scene, preset="lake", size=60.0, resolution=241, name="Plain").object
    scaled = api.add_water(scene, preset="lake", size=30.0, resolution=241, name="Scaled").object
    scaled.scale = (2.0, 2.0, 2.0)
    scaled.rotation_euler.z = math.pi / 2
    boat = _box(scene, "Boat", (0.0, 0.0, 0.0), size=(6.0, 2.4, 1.5))
    for frame, x in ((1, -20.0), (121, 10.0)):
        boat.location = (x, 0.4 * x, 0.0)
        boat.rotation_euler.z = math.atan2(0.4, 1.0)
        boat.keyframe_insert("location", frame=frame)
        boat.keyframe_insert("rotation_euler", frame=frame)
    for fcurve in harness.addon("nodes.material")._action_fcurves(boat.animation_data.action):
        for key in fcurve.keyframe_points:
            key.interpolation = "LINEAR"
    for water in (plain, scaled):
        api.add_wake_source(boat, water)
    for frame in range(1, 122):
        scene.frame_set(frame)
    where, ours = _world_heights(scaled)
    where_plain, theirs = _world_heights(plain)
    assert np.abs(where - where_plain).max() < 0.01, "the same points in the world"
    print("wake height: plain", round(np.abs(theirs).max(), 3), "scaled", round(np.abs(ours).max(), 3))
    assert np.abs(theirs).max() > 0.03
    assert np.abs(ours - theirs).max() < 0.05 * np.abs(theirs).max()


@pytest.mark.lts
@pytest.mark.render
def test_a_bake_gone_stale_is_said_in_the_panel_and_when_rendering_the_file(scene, tmp_path):
    """Re-keying the boat, running the scene past the bake's last frame (the wake would freeze
    there) and a bake of one frame (flat on every frame) each leave the bake stale: the panel
    and `render_file` say so; baking again clears it."""
    from test_repair import draw_panel

    api = _api()
    scene.frame_start, scene.frame_end = 1, 30
    water = api.add_water(scene, preset="lake", size=40.0, resolution=81, name="Lake").object
    harness.add_camera(scene, (0.0, -20.0, 10.0), (0.0, 0.0, 0.0))
    boat = _box(scene, "Boat", (-10.0, 0.0, 0.0))
    for frame, x in ((1, -10.0), (30, 0.0)):
        boat.location.x = x
        boat.keyframe_insert("location", frame=frame)
    api.add_wake_source(boat, water)
    path = tmp_path / "stale.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))  # 4.2 bakes beside the saved file
    _select(boat)

    def problems():
        return [e[1] for e in draw_panel() if e[0] == "label" and e[2] == "ERROR" and "wake" in e[1]]

    assert problems() == ["The wake on 'Lake' is not baked: farms render it flat"]
    api.bake(water, scene)
    assert problems() == []
    boat.location.x = 5.0
    boat.keyframe_insert("location", frame=30)  # re-keyed
    assert problems() == ["The wake of 'Boat' was baked before its motion or the wake changed: bake again"]
    api.bake(water, scene)
    assert problems() == []
    scene.frame_end = 60
    assert problems() == ["The wake of 'Boat' was baked for frames 1-30, the scene runs 1-60: bake again"]
    bpy.ops.wm.save_mainfile()
    said = []
    api.render_file(str(path), str(tmp_path / "frame.png"), progress=said.append)
    assert any("baked for frames 1-30, the scene runs 1-60" in line for line in said), said
    scene = bpy.context.scene
    water = bpy.data.objects["Lake"]
    scene.frame_start = scene.frame_end = 1
    api.bake(water, scene)
    assert harness.addon("water.boats.wake").bake_problems(water, scene) == [
        "The wake of 'Boat' was baked over one frame: it has no wake; bake the range"
    ]


def test_a_hull_and_its_child_float_and_leave_a_wake_without_a_cycle(scene):
    """A cabin parented to a hull: selected together, Float on Water floats the hull (the cabin
    rides with it, refused with a reason); a wake on the cabin of a floating hull, or floating a
    hull whose child floats or leaves a wake, is refused in one line; no dependency cycle."""
    api = _api()
    water = api.add_water(scene, preset="lake", size=30.0, resolution=61, name="Lake").object
    hull = _box(scene, "Hull", (0.0, 0.0, 0.0))
    cabin = _box(scene, "Cabin", (0.0, 0.0, 1.0), size=(1.5, 1.0, 1.0))
    cabin.parent = hull
    for frame, x in ((1, -5.0), (20, 0.0)):
        hull.location.x = x
        hull.keyframe_insert("location", frame=frame)
    floating = harness.addon("water.float_constraints")
    wake = harness.addon("water.boats.wake")
    _select(cabin, hull)  # the child first in the selection
    assert bpy.ops.object.water_float() == {"FINISHED"}
    assert floating.floating_on(hull) == water and floating.floating_on(cabin) is None
    assert [s.name for s in map(wake.source_of, wake.wake_modifiers(water))] == ["Hull"]
    with pytest.raises(wake.WakeError, match="rides on 'Hull', which floats"):
        api.add_wake_source(cabin, water)
    float_error = harness.addon("water.boats.floating").FloatError
    with pytest.raises(float_error, match="child of 'Hull', which floats"):
        api.float_on_water(cabin, water)
    output, _result = harness.blender_output(lambda: [scene.frame_set(f) for f in range(1, 21)])
    assert "Dependency cycle" not in output
    api.stop_floating(hull)
    api.add_wake_source(cabin, water)
    with pytest.raises(
        harness.addon("water.boats.floating").FloatError, match="'Cabin', a child of 'Hull', leaves a wake"
    ):
        api.float_on_water(hull, water)


def _surface_foam(water):
    return harness.evaluated_points(water, "water_wake_foam")


@pytest.mark.parametrize("speed", [25.0, 100.0])
def test_the_foam_trail_is_continuous_at_any_speed(scene, speed):
    """One track point a frame lies `speed / 24` m apart (4.2 m at 100 m/s): the trail along the
    track behind the boat has no gaps between them (it broke into dots)."""
    api = _api()
    scene.render.fps = 24
    water = api.add_water(scene, preset="lake", size=100.0, resolution=401, name="Lake").object
    api.write_values(water, {"wind_direction": (1.0, 0.0)})
    boat = _box(scene, "Boat", (0.0, 0.0, 0.0), size=(6.0, 2.4, 1.5))
    frames = int(60.0 / speed * 24) + 1
    heading = 0.5
    for frame in (1, frames):
        along = -30.0 + speed * (frame - 1) / 24
        boat.location = (along * math.cos(heading), along * math.sin(heading), 0.0)
        boat.rotation_euler.z = heading
        boat.keyframe_insert("location", frame=frame)
        boat.keyframe_insert("rotation_euler", frame=frame)
    for fcurve in harness.addon("nodes.material")._action_fcurves(boat.animation_data.action):
        for key in fcurve.keyframe_points:
            key.interpolation = "LINEAR"
    api.add_wake_source(boat, water)
    for frame in range(1, frames + 1):
        scene.frame_set(frame)
    points, foam = _surface_foam(water)
    end = np.array(boat.matrix_world.translation[:2])
    direction = np.array([math.cos(heading), math.sin(heading)])
    offset = points[:, :2] - end
    behind = -(offset @ direction)
    across = offset[:, 1] * direction[0] - offset[:, 0] * direction[1]
    # The trail's middle: the foam's highest across each 0.25 m of track, 8 to 40 m behind
    # (within the drift, which is small this soon after).
    bins = np.arange(8.0, 40.0, 0.25)
    along_trail = [foam[(behind >= b) & (behind < b + 0.25) & (np.abs(across) < 2.0)].max() for b in bins]
    print(f"{speed} m/s: trail foam from", round(min(along_trail), 3), "to", round(max(along_trail), 3))
    assert min(along_trail) > 0.5 * max(along_trail) > 0.05
