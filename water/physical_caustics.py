"""Cycles' own caustics (manifold next-event estimation) for a water, switched on and off.

MNEE finds the paths from the sun through the refractive water to what lies below: it needs
the water to be a caustics caster that casts shadows, with smooth normals; the objects below to
be receivers; the sun to be a caustics light; and refractive caustics on. Switched on, the
shader's own pattern (`Caustics`) is set to 0, so the light is not focused twice; what was there
before is kept on the water (`STATE_KEY`) and put back when switched off, so nothing of the
user's is lost. Every change is reported in words. Only Cycles renders these; EEVEE shows no
caustics while they are on.
"""

import json

import bpy

from ..nodes.material import first_sun, glint_sun, water_node
from .editable import check_editable
from .surroundings import surroundings_collection
from .values import water_material

STATE_KEY = "water_surface_physical_caustics"  # on the water: JSON of what was changed, to undo it
MIN_BOUNCES = {"transmission_bounces": 8, "transparent_max_bounces": 8, "max_bounces": 8}


class PhysicalCausticsError(ValueError):
    """Physical caustics cannot be set up as asked (one line, says why)."""


def is_on(water):
    """Whether `water` has Cycles' physical caustics switched on by the add-on."""
    return water is not None and STATE_KEY in water


def _sun(water, scene):
    material = water_material(water)
    sun = glint_sun(material) if material is not None and water_node(material) is not None else None
    return sun if sun is not None else first_sun(scene)


def _receivers(water):
    collection = surroundings_collection(water)
    if collection is None:
        return []
    return [o for o in collection.all_objects if o.type == "MESH" and o.library is None and o != water]


def _set(owner, path, value, before, key, label, changes):
    """Sets `owner.<path>` to `value`, keeping the old value in `before[key]` (a key that does
    not change when things are renamed)."""
    *parents, name = path.split(".")
    for parent in parents:
        owner = getattr(owner, parent)
    old = getattr(owner, name)
    if old == value:
        return
    before[key] = old
    setattr(owner, name, value)
    changes.append(f"{label}: {old} -> {value}")


def enable(water, scene):
    """Sets Cycles' manifold next-event estimation up for `water`; returns the changes in words.

    Raises PhysicalCausticsError when there is no water material, no surroundings below or no sun.
    """
    material = water_material(water)
    if material is None or water_node(material) is None:
        raise PhysicalCausticsError(f"'{getattr(water, 'name', water)}' is not lake water")
    check_editable(water, material)
    if is_on(water):
        return []
    receivers = _receivers(water)
    if not receivers:
        raise PhysicalCausticsError(
            f"'{water.name}' sees nothing below it: add its surroundings first (nothing to receive caustics)"
        )
    sun = _sun(water, scene)
    if sun is None:
        raise PhysicalCausticsError("the scene has no sun light to cast caustics")
    before, changes = {}, []
    _set(
        water, "cycles.is_caustics_caster", True, before, "caster", f"'{water.name}' caustics caster", changes
    )
    _set(water, "visible_shadow", True, before, "shadow", f"'{water.name}' casts shadows", changes)
    smooth = [p.use_smooth for p in water.data.polygons]
    if not all(smooth):
        water.data.polygons.foreach_set("use_smooth", [True] * len(smooth))
        water.data.update()
        before["smooth"] = False
        changes.append(f"'{water.name}' shaded smooth")
    receivers_before = {}
    for obj in receivers:
        _set(
            obj,
            "cycles.is_caustics_receiver",
            True,
            receivers_before,
            obj.name,
            f"receiver '{obj.name}'",
            changes,
        )
    _set(
        sun.data,
        "cycles.is_caustics_light",
        True,
        before,
        "light",
        f"light '{sun.data.name}' caustics",
        changes,
    )
    _set(
        scene, "cycles.caustics_refractive", True, before, "refractive", "Cycles refractive caustics", changes
    )
    for name, least in MIN_BOUNCES.items():
        if getattr(scene.cycles, name) < least:
            _set(scene, f"cycles.{name}", least, before, name, f"Cycles {name.replace('_', ' ')}", changes)
    socket = water_node(material).inputs["Caustics"]
    _set(
        socket, "default_value", 0.0, before, "shader", "shader Caustics (Cycles computes them now)", changes
    )
    # Objects are kept by pointer-free names; a renamed receiver is simply left as it is.
    water[STATE_KEY] = json.dumps({"before": before, "receivers": receivers_before, "sun": sun.data.name})
    return changes


def disable(water, scene):
    """Puts back what `enable` changed (values the user changed since are left as they are)."""
    if not is_on(water):
        return []
    check_editable(water)
    state = json.loads(water[STATE_KEY])
    before = state["before"]
    changes = []
    material = water_material(water)

    def put_back(key, owner, path, label, saved=before):
        if key in saved and owner is not None:
            _set(owner, path, saved[key], {}, key, label, changes)

    put_back("caster", water, "cycles.is_caustics_caster", f"'{water.name}' caustics caster")
    put_back("shadow", water, "visible_shadow", f"'{water.name}' casts shadows")
    if before.get("smooth") is False:
        water.data.polygons.foreach_set("use_smooth", [False] * len(water.data.polygons))
        water.data.update()
        changes.append(f"'{water.name}' shaded flat again")
    for name in state["receivers"]:
        obj = bpy.data.objects.get(name)
        put_back(name, obj, "cycles.is_caustics_receiver", f"receiver '{name}'", state["receivers"])
    light = bpy.data.lights.get(state["sun"])
    put_back("light", light, "cycles.is_caustics_light", f"light '{state['sun']}' caustics")
    put_back("refractive", scene, "cycles.caustics_refractive", "Cycles refractive caustics")
    for name in MIN_BOUNCES:
        put_back(name, scene, f"cycles.{name}", f"Cycles {name.replace('_', ' ')}")
    if material is not None and water_node(material) is not None:
        put_back("shader", water_node(material).inputs["Caustics"], "default_value", "shader Caustics")
    del water[STATE_KEY]
    return changes
