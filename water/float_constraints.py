"""Which constraints make an object float, told by the add-on's record on the object, not by name.

Now an object floats by its footprint (`float_rig.py`): "float" is a Copy Location
and "tilt" a Copy Rotation aiming at the rig's pose; before, both were Shrinkwrap constraints
aiming at the water, and files saved then still float that way until floated again.

Blender's constraints hold no ID properties, so the object keeps the names of the two
constraints the add-on made for it (`RECORD_KEY`, a small dict); a constraint of the
user's that happens to be named "Water Float" is theirs and never touched. Objects
floated before the record existed are recognised only when both constraints are there,
Shrinkwrap, named as the add-on named them and aiming at the same water.
"""

from .values import is_water

RIG_KEY = "water_surface_float_rig"  # on a rig's objects (float_rig.py): "pose", "probe", "patch", ...
PATCH_WATER_KEY = "water_surface_float_water"  # on a rig's pose (or older patch): its water
_KINDS = {"float": ("SHRINKWRAP", "COPY_LOCATION"), "tilt": ("SHRINKWRAP", "COPY_ROTATION")}

FLOAT = "Water Float"
TILT = "Water Float Tilt"
RECORD_KEY = "water_surface_float"  # on the object: {"float": name, "tilt": name}


def _legacy(obj):
    found = {name: obj.constraints.get(name) for name in (FLOAT, TILT)}
    if any(c is None or c.type != "SHRINKWRAP" for c in found.values()):
        return {}
    targets = {c.target for c in found.values()}
    if len(targets) != 1 or not is_water(next(iter(targets))):
        return {}
    return {"float": FLOAT, "tilt": TILT}


def record(obj):
    """{"float": name, "tilt": name} of the constraints the add-on made on `obj` ({} when none)."""
    held = obj.get(RECORD_KEY)
    if held is None:
        return _legacy(obj)
    try:
        return {role: str(held[role]) for role in ("float", "tilt") if role in held}
    except (TypeError, KeyError):
        return {}


def remember(obj, role, constraint):
    """Notes on `obj` that `constraint` is the add-on's `role` ("float" or "tilt")."""
    held = record(obj)
    held[role] = constraint.name
    obj[RECORD_KEY] = held


def forget(obj):
    if RECORD_KEY in obj:
        del obj[RECORD_KEY]


def constraint(obj, role):
    """The add-on's constraint `role` on `obj`, or None."""
    name = record(obj).get(role)
    found = obj.constraints.get(name) if name else None
    return found if found is not None and found.type in _KINDS[role] else None


def floating_ancestor(obj):
    """The nearest parent of `obj` (its parent, theirs, ...) that floats, or None: what floats
    with it, whose motion waits on the water."""
    parent = obj.parent
    while parent is not None:
        if pose_of(parent) is not None:
            return parent
        parent = parent.parent
    return None


def pose_of(obj):
    """The footprint rig's pose `obj` follows, or None (not floating, or floating the old way)."""
    for found in float_constraints(obj):
        target = found.target
        if target is not None and target.get(RIG_KEY) == "pose":
            return target
    return None


def water_of(target):
    """The water a constraint's target stands for: a water itself, or the water a rig's pose's
    probes are dropped onto."""
    if target is None:
        return None
    if target.get(RIG_KEY) != "pose":
        return target if is_water(target) else None
    fitted = target.get(PATCH_WATER_KEY)  # a pose that fits its own plane names its water
    if fitted is not None:
        return fitted if is_water(fitted) else None
    animation = target.animation_data
    for curve in animation.drivers if animation else ():
        for variable in curve.driver.variables:
            probe = variable.targets[0].id
            if probe is None or probe.get(RIG_KEY) != "probe":
                continue
            for found in probe.constraints:
                surface = found.target if found.type == "SHRINKWRAP" else None
                if surface is not None and surface.get(RIG_KEY) == "patch":
                    surface = surface.get(PATCH_WATER_KEY)
                if surface is not None and is_water(surface):
                    return surface
    return None


def float_constraints(obj):
    """The floating constraints the add-on made on `obj` (tilt first when both are there)."""
    return [c for c in (constraint(obj, "tilt"), constraint(obj, "float")) if c is not None]


def floating_on(obj):
    """The water `obj` floats on, or None."""
    if obj is None:
        return None
    found = [water_of(c.target) for c in float_constraints(obj)]
    found = [water for water in found if water is not None]
    return found[0] if found else None
