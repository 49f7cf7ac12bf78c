"""What floats on a water is never in its surroundings, and the add-on's constraints go by its mark.

The issue's scene: a boat reaching below the water when the water is added (so it is gathered
into the surroundings), then floated on it, made a dependency cycle
(Boat -> Water -> Sample -> cache -> Surroundings -> Boat). Blender prints "Dependency cycle"
when it builds such a graph: the tests read Blender's own output for it.
"""

import bpy
import pytest

import harness


def _api():
    return harness.addon("api")


def _evaluate(scene):
    def run():
        bpy.context.view_layer.depsgraph.update()
        scene.frame_set(scene.frame_current + 1)
        scene.frame_set(scene.frame_current - 1)

    return harness.blender_output(run)[0]


@pytest.fixture
def boat_water(scene):
    boat = harness.add_cube(scene, (1.0, 0.5, 0.0), size=2.0, name="Boat")  # reaches 1 m below
    bed = harness.add_cube(scene, (0.0, 0.0, -3.0), size=4.0, name="Bed")
    added = _api().add_water(scene, size=12, resolution=8, waves=True, mirror_setup=False)
    collection = harness.addon("water.surroundings").surroundings_collection(added.object)
    assert boat.name in collection.objects and bed.name in collection.objects  # gathered
    return scene, added.object, boat, bed


def test_floating_a_gathered_boat_leaves_it_out_and_makes_no_cycle(boat_water):
    scene, water, boat, bed = boat_water
    assert "Dependency cycle" not in _evaluate(scene)
    changes = _api().float_on_water(boat, water)
    assert any("left 'Boat' out" in change for change in changes)
    surroundings = harness.addon("water.surroundings")
    collection = surroundings.surroundings_collection(water)
    assert boat.name not in collection.objects and bed.name in collection.objects
    assert "Dependency cycle" not in _evaluate(scene)
    # Gathering again (the panel's Surroundings button) keeps it out.
    _api().set_surroundings(water)
    assert boat.name not in collection.objects and bed.name in collection.objects
    # Nor does it gather the rig's patch (cut from the water's own surface: a cycle too).
    assert not [o.name for o in collection.objects if o.get("water_surface_float_rig")]
    assert "Dependency cycle" not in _evaluate(scene)


def test_the_cycle_is_real_without_the_rule(boat_water):
    """The control: the same boat put back by hand into the collection the water sees makes
    Blender report the cycle, so the test above can see one."""
    scene, water, boat, _bed = boat_water
    _api().float_on_water(boat, water)
    collection = harness.addon("water.surroundings").surroundings_collection(water)
    collection.objects.link(boat)
    assert "Dependency cycle" in _evaluate(scene)
    _api().set_surroundings(water)  # gathering again takes it out, with a note
    assert boat.name not in collection.objects
    assert "Dependency cycle" not in _evaluate(scene)


def test_a_users_collection_with_the_floating_boat_is_refused_never_edited(boat_water):
    scene, water, boat, bed = boat_water
    mine = bpy.data.collections.new("My Harbour")
    mine.objects.link(bed)
    mine.objects.link(boat)
    _api().float_on_water(boat, water)
    with pytest.raises(_api().SurroundingsError, match="Boat"):
        _api().set_surroundings(water, mine)
    assert sorted(o.name for o in mine.objects) == ["Bed", "Boat"]
    # The other way round: a boat in the user's surroundings collection cannot float on the water.
    _api().stop_floating(boat)
    _api().set_surroundings(water, mine)
    with pytest.raises(_api().FloatError, match="My Harbour"):
        _api().float_on_water(boat, water)
    assert not harness.addon("water.boats.floating").is_floating(boat)
    assert sorted(o.name for o in mine.objects) == ["Bed", "Boat"]
    assert "Dependency cycle" not in _evaluate(scene)


def test_stop_floating_leaves_a_users_constraint_named_like_ours(scene):
    water = _api().add_water(scene, size=8, resolution=8, see_surroundings=False).object
    buoy = harness.add_cube(scene, (0.0, 0.0, 2.0), size=0.5, name="Buoy")
    mine = buoy.constraints.new("LIMIT_LOCATION")
    mine.name = "Water Float"
    theirs_too = buoy.constraints.new("SHRINKWRAP")
    theirs_too.name = "Water Float Tilt"
    theirs_too.target = water  # even a Shrinkwrap of theirs aimed at the water
    _api().float_on_water(buoy, water)
    assert len(buoy.constraints) == 4
    _api().stop_floating(buoy)
    assert [(c.name, c.type) for c in buoy.constraints] == [
        ("Water Float", "LIMIT_LOCATION"),
        ("Water Float Tilt", "SHRINKWRAP"),
    ]
    assert _api().stop_floating(buoy) == []  # nothing of ours left


def test_floating_and_stopping_leaves_no_constraint_behind(scene):
    water = _api().add_water(scene, size=8, resolution=8, see_surroundings=False).object
    buoy = harness.add_cube(scene, (0.0, 0.0, 2.0), size=0.5, name="Buoy")
    _api().float_on_water(buoy, water)
    assert harness.addon("water.boats.floating").floating_on(buoy) == water
    _api().stop_floating(buoy)
    assert len(buoy.constraints) == 0
