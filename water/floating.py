"""Objects that float: they ride the water below them, with Blender's own Shrinkwrap constraint.

Two constraints, no Python at render. First `Water Float Tilt` projects the object's origin
straight down (or up) onto the water's evaluated surface and turns its up axis (+Z) to the
surface normal there, at an influence of 1 - `tilt_damping`, so a damped object tilts less than
the water; then `Water Float` projects the origin again along Z, at full influence, so it sits
on the surface whatever the damping (a projection along Z keeps x and y). Both name the water as their
target, so the object follows whichever waves the water has: the lake's flat surface, the seeds'
four sines (`Water Waves`) or the open sea's Ocean modifier.
"""

import bpy
from mathutils import Vector

from . import physical_caustics, surroundings
from .editable import check_editable
from .float_constraints import FLOAT, TILT, float_constraints, floating_on, forget, remember
from .float_constraints import constraint as constraint_for
from .values import is_water

__all__ = ("FloatError", "float_on_water", "floating_on", "is_floating", "stop_floating", "water_below")


class FloatError(RuntimeError):
    """An object cannot float as asked (a one-line message)."""


def is_floating(obj):
    return bool(float_constraints(obj))


def water_below(obj, scene, depsgraph=None):
    """The water whose surface lies straight below (or above) `obj`'s origin: the nearest, or None."""
    depsgraph = depsgraph or bpy.context.evaluated_depsgraph_get()
    origin = obj.matrix_world.translation
    best = None
    for candidate in scene.objects:
        if candidate == obj or not is_water(candidate):
            continue
        evaluated = candidate.evaluated_get(depsgraph)
        inverse = evaluated.matrix_world.inverted()
        start = inverse @ origin
        for direction in ((0.0, 0.0, -1.0), (0.0, 0.0, 1.0)):
            local = (inverse.to_3x3() @ Vector(direction)).normalized()
            hit, location, _normal, _index = evaluated.ray_cast(start, local)
            if hit:
                distance = ((evaluated.matrix_world @ location) - origin).length
                if best is None or distance < best[0]:
                    best = (distance, candidate)
    return best[1] if best else None


def _shrinkwrap(obj, role, name, water):
    """The add-on's constraint `role` on `obj` (reused, or made and recorded) aimed at `water`."""
    constraint = constraint_for(obj, role)
    if constraint is None:
        constraint = obj.constraints.new("SHRINKWRAP")
        constraint.name = name  # Blender adds ".001" when the user has one of that name
        remember(obj, role, constraint)
    constraint.target = water
    constraint.shrinkwrap_type = "PROJECT"
    constraint.project_axis = "NEG_Z"
    constraint.project_axis_space = "WORLD"
    constraint.use_project_opposite = True  # an object below the surface comes up
    constraint.cull_face = "OFF"
    constraint.project_limit = 0.0  # any distance
    constraint.distance = 0.0
    return constraint


def float_on_water(obj, water, tilt_damping=0.0):
    """Makes `obj` ride `water`: its origin on the surface below, its up axis along the surface's
    normal damped by `tilt_damping` (0 = follows fully, 1 = stays upright). Returns the changes."""
    check_editable(obj)
    if water is None or not is_water(water):
        raise FloatError(f"'{obj.name}' has no water below it to float on")
    if water == obj:
        raise FloatError(f"'{obj.name}' is the water itself")
    damping = min(max(float(tilt_damping), 0.0), 1.0)
    try:  # what floats on a water is never in its surroundings: the two would make a cycle
        changes = surroundings.leave_out(water, obj)
    except surroundings.SurroundingsError as error:
        raise FloatError(str(error)) from error
    changes += physical_caustics.let_go_of_receiver(water, obj)  # out of the surroundings: no receiver
    tilt = _shrinkwrap(obj, "tilt", TILT, water)
    tilt.use_track_normal = True
    tilt.track_axis = "TRACK_Z"
    tilt.influence = 1.0 - damping
    last = _shrinkwrap(obj, "float", FLOAT, water)
    last.use_track_normal = False
    # The tilt before the last projection, whatever order they were in.
    order = [c.name for c in obj.constraints]
    if order.index(tilt.name) > order.index(last.name):
        obj.constraints.move(order.index(tilt.name), order.index(last.name))
    return [f"'{obj.name}' floats on '{water.name}' (tilt damping {damping:g})"] + changes


def stop_floating(obj):
    """Removes the floating constraints the add-on made (by its record on the object, never a
    user's constraint of the same name); the object goes back to where it was before."""
    check_editable(obj)
    found = float_constraints(obj)
    for constraint in found:
        obj.constraints.remove(constraint)
    forget(obj)
    return [f"'{obj.name}' no longer floats"] if found else []
