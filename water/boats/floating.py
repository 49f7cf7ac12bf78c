"""Objects that float: they ride the water under their whole footprint, with Blender's own parts.

`float_on_water` gives the object a rig (`float_rig.py`): an anchor that moves as the object
would, and a pose whose Geometry Nodes modifier drops probes over its footprint onto the water's
evaluated surface and fits a plane to their heights: its height gives the heave (less the draft)
and its tilt the pitch and roll. The object copies the pose's height and, at 1 - `tilt_damping`,
its tilt. Waves much longer than the hull rock it as the surface does; ripples much shorter than
it cancel out over it. The pose reads the water's evaluated surface, so the object follows
whichever waves the water has: the lake's flat surface, the seeds' four sines (`Water Waves`)
or the open sea's Ocean modifier. No Python runs at render.
"""

import bpy
from mathutils import Vector

from .. import kind, physical_caustics, surroundings
from ..editable import check_editable
from ..errors import WaterError
from ..float_constraints import (
    FLOAT,
    TILT,
    float_constraints,
    floating_ancestor,
    floating_on,
    forget,
    pose_of,
    remember,
)
from ..float_constraints import constraint as constraint_for
from ..values import is_water
from . import float_rig, wake
from .float_rig import footprint_settings

WAKE_BY_FLOAT = "water_surface_wake_by_float"  # on the object: floating added its wake

__all__ = (
    "FloatError",
    "float_on_water",
    "floating_on",
    "footprint_settings",
    "is_floating",
    "release",
    "rig_out_of_date",
    "stop_floating",
    "tilt_damping_of",
    "water_for",
)


class FloatError(WaterError, RuntimeError):
    """An object cannot float as asked (a one-line message)."""


def is_floating(obj):
    return bool(float_constraints(obj))


def _water_below(obj, scene, depsgraph=None):
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


def water_for(obj, scene, error, chosen=None, floating_first=True, depsgraph=None):
    """The water `obj` acts on (floats on, is kept out of, leaves a wake on), the one rule for the
    operators and the API: `chosen` when given, else (with `floating_first`) the water it floats
    on, else the nearest water straight below or above its origin. Raises `error` (the caller's
    exception class) when there is none, in the one wording `no_water` gives."""
    water = chosen or (floating_on(obj) if floating_first else None) or _water_below(obj, scene, depsgraph)
    if water is None:
        raise error(no_water(obj))
    return water


def no_water(obj):
    """Why `obj` acts on no water: none is below or above it and none was named."""
    return f"'{obj.name}' has no water below or above it: select or name the water"


def _constraint(obj, role, name, kind):
    """The add-on's constraint `role` on `obj`: reused when of `kind`, else made and recorded
    (an old Shrinkwrap of the add-on's is replaced)."""
    found = constraint_for(obj, role)
    if found is not None and found.type != kind:
        obj.constraints.remove(found)
        found = None
    if found is None:
        found = obj.constraints.new(kind)
        found.name = name  # Blender adds ".001" when the user has one of that name
        remember(obj, role, found)
    return found


def _number(name, value):
    """`value` as a float, or FloatError saying which input was not a number."""
    try:
        return float(value)
    except (TypeError, ValueError):
        raise FloatError(f"The {name} must be a number (got {value!r})") from None


def _check_family(obj):
    """A parent and its child cannot both wait on the water (a dependency cycle): a child of a
    floating object rides with it; a child that floats, or leaves a wake, keeps its parent from
    floating."""
    ancestor = floating_ancestor(obj)
    if ancestor is not None:
        raise FloatError(f"'{obj.name}' is a child of '{ancestor.name}', which floats: it rides with it")
    for child in obj.children_recursive:
        if pose_of(child) is not None:
            raise FloatError(f"'{child.name}', a child of '{obj.name}', floats itself: stop it first")
        if wake.modifiers_of(child):
            raise FloatError(
                f"'{child.name}', a child of '{obj.name}', leaves a wake: take it off and add it to "
                f"'{obj.name}' instead"
            )


def _check_sizes(draft, length, beam):
    for name, value in (("draft", draft), ("length", length), ("beam", beam)):
        if value is not None and not (_number(name, value) >= 0.0 and float(value) < 1e5):
            raise FloatError(f"The {name} must be 0 m or more (got {value})")
        if name != "draft" and value is not None and float(value) == 0.0:
            raise FloatError(f"The footprint's {name} must be above 0 m (leave it out to take the bounds')")


def float_on_water(
    obj, water, tilt_damping=0.0, draft=None, length=None, beam=None, scene=None, wake_on=True
):
    """Makes `obj` ride `water` by its footprint: its heave from the water's mean height under it,
    `draft` metres of it below the waterline (None: a third of its height), its pitch and roll from
    the plane fitted over `length` x `beam` (None: its bounds'), damped by `tilt_damping` (0 =
    follows fully, 1 = stays upright). With `wake_on`, it leaves a wake as it moves (`wake.py`;
    stopping takes off a wake floating added). Returns the changes in words."""
    check_editable(obj)
    if water is None:
        raise FloatError(no_water(obj))
    name = f"'{getattr(water, 'name', water)}'"
    why = kind.refusal(water, "floating", subject=name) or (
        kind.refusal(water, "wake", subject=name) if wake_on else None
    )
    if why is not None:
        raise FloatError(why)
    if water == obj:
        raise FloatError(f"'{obj.name}' is the water itself")
    _check_family(obj)
    _check_sizes(draft, length, beam)
    damping = _number("tilt damping", tilt_damping)
    if not 0.0 <= damping <= 1.0:  # NaN too
        raise FloatError(f"The tilt damping must be 0 to 1 (got {tilt_damping})")
    if length is None or beam is None:
        size_length, size_beam, *_rest = float_rig.footprint_of(obj)
        if (length is None and size_length <= 0.0) or (beam is None and size_beam <= 0.0):
            raise FloatError(
                f"'{obj.name}' has no size to float by ({obj.type.lower()}, its bounds flat): "
                "give it a mesh, or name the footprint's length and beam"
            )
    try:  # what floats on a water is never in its surroundings: the two would make a cycle
        changes = surroundings.leave_out(water, obj)
    except surroundings.SurroundingsError as error:
        raise FloatError(str(error)) from error
    changes += physical_caustics.let_go_of_receiver(water, obj)  # out of the surroundings: no receiver
    old = pose_of(obj)
    if old is not None and float_rig.owned_by(old, obj):  # a copy's rig is the original's: kept
        float_rig.remove(old)
    ours = float_constraints(obj)
    own = [c for c in obj.constraints if c not in ours]
    pose, settings = float_rig.build(obj, water, scene or bpy.context.scene, own, draft, length, beam)
    obj[float_rig.SETTINGS_KEY] = settings
    tilt = _constraint(obj, "tilt", TILT, "COPY_ROTATION")
    tilt.target = pose
    tilt.subtarget = float_rig.pose_group(pose)
    tilt.mix_mode = "AFTER"
    # After its own rotation: the pose's tilt about the object's own axes (in world space:
    # Blender's local space leaves an object's Copy Rotation without effect).
    tilt.target_space = tilt.owner_space = "WORLD"
    tilt.influence = 1.0 - damping
    last = _constraint(obj, "float", FLOAT, "COPY_LOCATION")
    last.target = pose
    last.subtarget = float_rig.pose_group(pose)
    last.use_x = last.use_y = False
    last.use_z = True
    last.use_offset = False
    last.target_space = last.owner_space = "WORLD"
    last.influence = 1.0
    # The tilt before the height, whatever order they were in.
    order = [c.name for c in obj.constraints]
    if order.index(tilt.name) > order.index(last.name):
        obj.constraints.move(order.index(tilt.name), order.index(last.name))
    wake.follow_again(obj)  # its wake reads the new anchor (reading `obj` would be a cycle)
    if wake_on and not [m for m in wake.modifiers_of(obj) if m.id_data == water]:
        changes += wake.add_wake_source(obj, water)
        obj[WAKE_BY_FLOAT] = water.name
    return [
        f"'{obj.name}' floats on '{water.name}' (draft {settings['draft']:.3g} m, footprint "
        f"{settings['length']:.3g} x {settings['beam']:.3g} m, tilt damping {damping:g})"
    ] + changes


def tilt_damping_of(obj):
    """The tilt damping `obj` floats with (0 when it does not float)."""
    tilt = constraint_for(obj, "tilt")
    return 1.0 - tilt.influence if tilt is not None else 0.0


def rig_out_of_date(obj):
    """Why `obj`'s floating rig no longer moves as it does (float it again), or None."""
    pose = pose_of(obj)
    return float_rig.out_of_date(obj, pose) if pose is not None else None


def release(obj):
    """Takes the add-on's floating constraints and rig off `obj` (no checks); returns the changes."""
    found = float_constraints(obj)
    pose = pose_of(obj)
    wakes = wake.modifiers_of(obj)  # found by the anchor, which goes
    for constraint in found:
        obj.constraints.remove(constraint)
    if pose is not None and float_rig.owned_by(pose, obj):
        float_rig.remove(pose)
    float_rig.let_go_of_action(obj)
    forget(obj)
    if float_rig.SETTINGS_KEY in obj:
        del obj[float_rig.SETTINGS_KEY]
    wake.follow_again(obj, wakes)
    changes = [f"'{obj.name}' no longer floats"] if found else []
    if WAKE_BY_FLOAT in obj:  # the wake floating added goes with it
        for water in {m.id_data for m in wakes if m.id_data.name == obj[WAKE_BY_FLOAT]}:
            changes += wake.remove_wake_source(obj, water)
        del obj[WAKE_BY_FLOAT]
    return changes


def stop_floating(obj):
    """Removes the floating constraints and rig the add-on made (by its record on the object,
    never a user's constraint of the same name); the object goes back to where it was before."""
    check_editable(obj)
    return release(obj)
