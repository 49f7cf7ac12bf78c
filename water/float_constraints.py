"""Which constraints make an object float, told by the add-on's record on the object, not by name.

Blender's constraints hold no ID properties, so the object keeps the names of the two
constraints the add-on made for it (`RECORD_KEY`, a small dict); a constraint of the
user's that happens to be named "Water Float" is theirs and never touched. Objects
floated before the record existed are recognised only when both constraints are there,
Shrinkwrap, named as the add-on named them and aiming at the same water.
"""

from .values import is_water

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
    """The add-on's Shrinkwrap constraint `role` on `obj`, or None."""
    name = record(obj).get(role)
    found = obj.constraints.get(name) if name else None
    return found if found is not None and found.type == "SHRINKWRAP" else None


def float_constraints(obj):
    """The floating constraints the add-on made on `obj` (tilt first when both are there)."""
    return [c for c in (constraint(obj, "tilt"), constraint(obj, "float")) if c is not None]


def floating_on(obj):
    """The water `obj` floats on, or None."""
    if obj is None:
        return None
    found = [c.target for c in float_constraints(obj) if c.target is not None]
    return found[0] if found else None
