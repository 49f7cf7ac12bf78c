"""The sea's clock keyed as well as driven, so that the Ocean modifier's own Bake moves.

Blender's Ocean Bake reads a modifier's `time` at each frame from the object's F-curves only
(`ocean_bake_exec` evaluates the animation, not the drivers): with the add-on's driven clock alone
every baked frame held the first frame's waves. So `time` also gets an F-curve with no keys,
whose Generator gives frame x fps_base / fps, the seconds the driver gives. The driver still sets
what the sea shows (drivers are evaluated after the animation) and follows a change of frame rate;
the F-curve follows it when the sea is set again (Update Water, a preset). The F-curve lives in
the object's action: one of ours, marked, when the object had none, which goes with the sea.
"""

import bpy

from ...nodes.ownership import mark, role_of

ACTION_ROLE = "Water Sea Clock"
ACTION_VERSION = 1


def _fcurves(obj):
    """The F-curve collection of `obj`'s action for `obj`, or None (4.4 and later keep F-curves in
    the slot's channel bag; 4.2 on the action)."""
    animation = obj.animation_data
    action = animation.action if animation else None
    if action is None:
        return None
    if not hasattr(action, "fcurve_ensure_for_datablock"):
        return action.fcurves
    from bpy_extras import anim_utils

    bag = anim_utils.action_get_channelbag_for_slot(action, animation.action_slot)
    return bag.fcurves if bag is not None else None


def clock_fcurve(obj, modifier):
    """The F-curve keying `modifier`'s time on `obj`, or None."""
    fcurves = _fcurves(obj)
    return fcurves.find(modifier.path_from_id("time")) if fcurves is not None else None


def key_clock(obj, modifier, scene):
    """`modifier.time` keyed to seconds on `scene`'s clock by a keyless F-curve's Generator."""
    animation = obj.animation_data or obj.animation_data_create()
    if animation.action is None:
        action = bpy.data.actions.new(f"{obj.name} {ACTION_ROLE}")
        mark(action, ACTION_ROLE, ACTION_VERSION)
        animation.action = action
    fcurve = clock_fcurve(obj, modifier)
    if fcurve is None:
        path = modifier.path_from_id("time")
        action = animation.action
        if hasattr(action, "fcurve_ensure_for_datablock"):
            fcurve = action.fcurve_ensure_for_datablock(obj, path)
        else:
            fcurve = action.fcurves.new(path)
    for old in list(fcurve.modifiers):
        fcurve.modifiers.remove(old)
    generator = fcurve.modifiers.new("GENERATOR")
    generator.poly_order = 1
    generator.coefficients = (0.0, scene.render.fps_base / scene.render.fps)
    return fcurve


def unkey_clock(obj, modifier):
    """Removes the F-curve keying `modifier`'s time, and the action too where it was ours alone."""
    fcurve = clock_fcurve(obj, modifier)
    if fcurve is None:
        return
    fcurves = _fcurves(obj)
    fcurves.remove(fcurve)
    action = obj.animation_data.action
    if len(fcurves) == 0 and role_of(action) == ACTION_ROLE and action.users <= 1:
        obj.animation_data.action = None
        bpy.data.actions.remove(action)
