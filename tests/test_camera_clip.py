"""A camera whose Clip End cuts part of a water off: adding the water says so, and Extend Camera
Clip (operator, API) moves the Clip End past the water's farthest corner."""

import bpy
import pytest

import harness


def _api():
    return harness.addon("api")


def _camera(scene, clip_end):
    camera = harness.add_camera(scene, (30.0, -40.0, 3.0), (0.0, 0.0, 0.0))
    camera.data.clip_end = clip_end
    scene.camera = camera
    return camera


def test_adding_a_sea_says_the_camera_cuts_it_off_and_the_operator_extends_the_clip(scene):
    camera = _camera(scene, 100.0)
    added = _api().add_water(scene, preset="open_sea", mirror_setup=False)
    sea = added.object
    reach = harness.addon("water.camera_clip").far_edge(camera, sea)
    assert reach > 5000.0, "the open sea reaches kilometres"
    notes = [note for note in added.notes if "Clip End" in note]
    assert len(notes) == 1 and "100 m" in notes[0] and f"{reach:.0f} m" in notes[0], added.notes

    bpy.context.view_layer.objects.active = sea
    assert bpy.ops.object.water_camera_clip.poll()
    assert bpy.ops.object.water_camera_clip() == {"FINISHED"}
    assert reach <= camera.data.clip_end <= reach * 1.06
    assert harness.addon("water.camera_clip").clip_note(scene, sea) is None
    assert _api().extend_camera_clip(sea) == [], "already sees it all: nothing changes"
    # The whole sea is now in front of the far plane: every corner of its bounds.
    from mathutils import Vector

    inverse = camera.matrix_world.inverted()
    depths = [-(inverse @ (sea.matrix_world @ Vector(c))).z for c in sea.bound_box]
    assert max(depths) < camera.data.clip_end


def test_a_water_the_camera_sees_whole_gets_no_note(scene):
    _camera(scene, 100.0)
    added = _api().add_water(scene, size=20.0, see_surroundings=False, mirror_setup=False)
    assert not [note for note in added.notes if "Clip End" in note]


def test_extend_refuses_a_scene_without_a_camera(scene):
    added = _api().add_water(scene, size=20.0, see_surroundings=False, mirror_setup=False)
    scene.camera = None
    with pytest.raises(ValueError, match="no camera"):
        _api().extend_camera_clip(added.object)
    bpy.context.view_layer.objects.active = added.object
    assert not bpy.ops.object.water_camera_clip.poll()
