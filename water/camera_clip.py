"""Whether the scene's camera sees all of a water: its Clip End against the water's far edge.

An open sea reaches kilometres (its edge is under the horizon), a camera's Clip End is 100 m by
default: beyond it the sea is cut off and the world shows through as a band at the horizon.
Adding water says so, and `extend_clip` moves the Clip End past the water's farthest corner.
"""

import math

from mathutils import Vector

from .editable import check_editable
from .errors import NoCameraError

MARGIN = 1.05  # the Clip End goes this much past the farthest corner


def far_edge(camera, water):
    """Metres from `camera` to the farthest corner of `water`'s bounds (its mesh at rest, in the world)."""
    eye = camera.matrix_world.translation
    corners = [water.matrix_world @ Vector(corner) for corner in water.bound_box]
    return max((corner - eye).length for corner in corners)


def clip_note(scene, water):
    """A sentence when the scene's camera cuts part of `water` off, else None."""
    camera = scene.camera
    if camera is None or camera.type != "CAMERA":
        return None
    reach = far_edge(camera, water)
    if camera.data.clip_end >= reach:
        return None
    return (
        f"camera '{camera.name}' sees to {camera.data.clip_end:g} m (Clip End) but '{water.name}' "
        f"reaches {reach:.0f} m: the rest is cut off; Extend Camera Clip in the panel moves it"
    )


def extend_clip(scene, water, camera=None):
    """Moves the Clip End of `camera` (default: the scene's) past `water`'s farthest corner;
    returns the change in words ([] when it already sees all of it). NoCameraError without one;
    NotEditableError for a linked camera."""
    camera = camera or scene.camera
    if camera is None or camera.type != "CAMERA":
        raise NoCameraError("the scene has no camera")
    reach = far_edge(camera, water)
    if camera.data.clip_end >= reach:
        return []
    check_editable(camera, camera.data)
    before = camera.data.clip_end
    camera.data.clip_end = math.ceil(reach * MARGIN)
    return [f"camera '{camera.name}' Clip End {before:g} m -> {camera.data.clip_end:g} m"]
