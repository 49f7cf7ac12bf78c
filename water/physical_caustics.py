"""Cycles' own caustics (manifold next-event estimation) for a water, switched on and off.

MNEE finds the paths from the sun through the refractive water to what lies below: it needs
the water to be a caustics caster that casts shadows, with smooth normals; the objects below to
be receivers; the sun to be a caustics light; and refractive caustics on. Switched on, the
shader's own pattern (`Caustics`) is set to 0, so the light is not focused twice. Every setting
goes through the ledger (`ledger.py`): switched off, a setting is put back only when it still
holds what the switch set and no other water with physical caustics on needs it, so nothing of
the user's is lost and one water switched off never breaks another. Every change is reported
in words. Only Cycles renders these; EEVEE shows no caustics while they are on.
"""

import json

import bpy

from ..nodes.material import first_sun, fit_parts, glint_sun, water_node
from . import kind, underwater
from .editable import check_editable
from .errors import WaterError
from .ledger import claim, holder_object, release
from .ledger import holder as ledger_holder
from .surroundings import surroundings_collection
from .values import water_material

STATE_KEY = "water_surface_physical_caustics"  # on the water: JSON of what to let go of when off
RECEIVER = "cycles.is_caustics_receiver"
LIGHT = "cycles.is_caustics_light"
REFRACTIVE = "cycles.caustics_refractive"
MIN_BOUNCES = {"transmission_bounces": 8, "transparent_max_bounces": 8, "max_bounces": 8}


class PhysicalCausticsError(WaterError, ValueError):
    """Physical caustics cannot be set up as asked (one line, says why)."""


def is_on(water):
    """Whether `water` has Cycles' physical caustics switched on by the add-on."""
    return water is not None and STATE_KEY in water


def _holder(water, stamp=True):
    return ledger_holder("caustics", water, stamp)


def _shader_path(material):
    node = bpy.utils.escape_identifier(water_node(material).name)
    return f'node_tree.nodes["{node}"].inputs["Caustics"].default_value'


def _sun(water, scene):
    # Only a water that may choose its sun (`sun_choice`) has a glint that follows one.
    sun = glint_sun(water_material(water)) if kind.allows(water, "sun_choice") else None
    return sun if sun is not None else first_sun(scene)


def _receivers(water):
    collection = surroundings_collection(water)
    if collection is None:
        return []
    return [o for o in collection.all_objects if o.type == "MESH" and o.library is None and o != water]


def enable(water, scene):
    """Sets Cycles' manifold next-event estimation up for `water`; returns the changes in words.

    Raises PhysicalCausticsError when there is no water material, no surroundings below or no sun.
    """
    why = kind.refusal(water, "physical_caustics", subject=f"'{getattr(water, 'name', water)}'")
    if why is not None:
        raise PhysicalCausticsError(why)
    material = water_material(water)
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
    holder, changes = _holder(water), []
    claim(water, "cycles.is_caustics_caster", True, holder, f"'{water.name}' caustics caster", changes)
    claim(water, "visible_shadow", True, holder, f"'{water.name}' casts shadows", changes)
    smooth = [p.use_smooth for p in water.data.polygons]
    if not all(smooth):
        water.data.polygons.foreach_set("use_smooth", [True] * len(smooth))
        water.data.update()
        changes.append(f"'{water.name}' shaded smooth")
    for obj in receivers:
        claim(obj, RECEIVER, True, holder, f"receiver '{obj.name}'", changes)
    claim(sun.data, LIGHT, True, holder, f"light '{sun.data.name}' caustics", changes)
    claim(scene, REFRACTIVE, True, holder, "Cycles refractive caustics", changes)
    for name, least in MIN_BOUNCES.items():
        label = f"Cycles {name.replace('_', ' ')}"
        claim(scene, f"cycles.{name}", least, holder, label, changes, at_least=True)
    label = "shader Caustics (Cycles computes them now)"
    claim(material, _shader_path(material), 0.0, holder, label, changes)
    fit_parts(material)  # the shader's caustics at 0 leave the shader: they cost nothing
    changes += underwater.fit_light(water, scene)  # nor a caustic light under the water
    # What to let go of when switched off: the receivers and the sun by name (one renamed since is
    # left as it is), and whether the mesh was shaded flat.
    state = {"receivers": [o.name for o in receivers], "sun": sun.data.name, "flat": not all(smooth)}
    water[STATE_KEY] = json.dumps(state)
    return changes


def _alive(holder):
    """Whether the water named in `holder` still has its physical caustics on."""
    return is_on(holder_object(holder))


def disable(water, scene):
    """Puts back what `enable` changed: only settings that still hold the value it set (the
    user's later changes stay), and only what no other water with physical caustics on needs."""
    if not is_on(water):
        return []
    check_editable(water)
    state = json.loads(water[STATE_KEY])
    del water[STATE_KEY]
    holder, changes = _holder(water, stamp=False), []
    release(water, "cycles.is_caustics_caster", holder, f"'{water.name}' caustics caster", changes)
    release(water, "visible_shadow", holder, f"'{water.name}' casts shadows", changes)
    if state.get("flat") and all(p.use_smooth for p in water.data.polygons):
        water.data.polygons.foreach_set("use_smooth", [False] * len(water.data.polygons))
        water.data.update()
        changes.append(f"'{water.name}' shaded flat again")
    for name in state.get("receivers", ()):
        release(bpy.data.objects.get(name), RECEIVER, holder, f"receiver '{name}'", changes, _alive)
    light = bpy.data.lights.get(state.get("sun", ""))
    release(light, LIGHT, holder, f"light '{state.get('sun')}' caustics", changes, _alive)
    release(scene, REFRACTIVE, holder, "Cycles refractive caustics", changes, _alive)
    for name in MIN_BOUNCES:
        release(scene, f"cycles.{name}", holder, f"Cycles {name.replace('_', ' ')}", changes, _alive)
    if kind.allows(water, "physical_caustics"):  # the shader's Caustics `enable` set to 0
        material = water_material(water)
        release(material, _shader_path(material), holder, "shader Caustics", changes)
        fit_parts(material)  # the shader's caustics back in when their value came back
        changes += underwater.fit_light(water, scene)
    return changes


def let_go_of_receiver(water, obj):
    """`obj` no longer receives `water`'s physical caustics (it floats on it now, out of its
    surroundings): its receiver flag goes back when no other water holds it. Returns the changes."""
    changes = []
    release(obj, RECEIVER, _holder(water, stamp=False), f"receiver '{obj.name}'", changes, _alive)
    if is_on(water) and STATE_KEY in water.keys():
        state = json.loads(water[STATE_KEY])
        state["receivers"] = [name for name in state.get("receivers", ()) if name != obj.name]
        water[STATE_KEY] = json.dumps(state)
    return changes
