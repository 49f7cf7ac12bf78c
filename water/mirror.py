"""The mirror set-up: what EEVEE needs to show the water as a true mirror.

Screen-trace ray tracing reflects and refracts what is on screen (the seeds'
reflection and refraction maps). What the camera cannot see comes from a
planar light probe. EEVEE ignores a probe whose capture contains the surface
that receives it, so the probe is lifted 1 cm above the water (more than its
clip start, less than its influence distance) and the water is also hidden
from planar captures (`hide_probe_plane`). The probe is a child of the water:
it follows it when moved, rotated or scaled. It is fitted to the water's own
mesh (the rest plane), never to the evaluated waves, so it is the same at every
frame; with waves its influence reaches their crests and troughs.

The followed sun is kept off the water by light linking (`sun_link`), so the
water's only highlight is its glint.
"""

import bpy
import numpy as np

from ..engine import RAY_TRACING, eevee_engine_id
from ..nodes.material import glint_sun
from ..nodes.ownership import is_original, mark, owned
from . import kind, sun_link
from .editable import check_editable
from .errors import WaterError
from .ledger import claim, held_paths, holder_object, holders, release
from .ledger import holder as ledger_holder
from .repair import needs_repair
from .values import water_material
from .waves import amplitude_sum, wave_modifier

PROBE_TAG = "water_surface_mirror"  # custom property naming the water a probe mirrors
PROBE_ROLE = "Mirror Probe"
PROBE_LIFT = 0.01  # metres above the water
SKY_COLOR = (0.45, 0.6, 0.85)
SKY_NAME = "Sky"


class MirrorSetupError(WaterError, ValueError):
    """The mirror set-up cannot run on what it was given."""


def _is_mirror_probe(obj):
    return (
        obj.get(PROBE_TAG) is not None
        and obj.type == "LIGHT_PROBE"
        and obj.data is not None
        and obj.data.type == "PLANE"
        and is_original(obj)
    )


def is_lost_probe(obj):
    """Whether `obj` is a mirror probe of the add-on's whose water is gone (deleted, or no longer
    a water): neither its parent nor the object of the name it records is a water."""
    if not _is_mirror_probe(obj):
        return False
    water = obj.parent if obj.parent is not None else bpy.data.objects.get(obj[PROBE_TAG])
    return water is None or water_material(water) is None


def find_probe(water):
    """The planar probe made for `water`, or None: its child, or one the user unparented or
    parented elsewhere (tagged with the water's name)."""
    children = [child for child in water.children if _is_mirror_probe(child)]
    if children:
        return children[0]
    return next(
        (o for o in bpy.data.objects if _is_mirror_probe(o) and o[PROBE_TAG] == water.name),
        None,
    )


def needs_mirror(water):
    """Whether `water` gets the mirror set-up's probe and light linking (`kind.FEATURES`): lake
    shading does; the ocean shading reflects the world's sky."""
    return kind.allows(water, "mirror")


def rest_bounds(water):
    """(low, high) corners of the water's own mesh: the rest plane, whatever its modifiers do."""
    mesh = water.data
    if len(mesh.vertices) == 0:
        return np.zeros(3), np.zeros(3)
    co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3)
    return co.min(axis=0), co.max(axis=0)


def _place_probe(probe, water):
    """Covers the rest plane's local bounds, lifted PROBE_LIFT metres above its top."""
    low, high = rest_bounds(water)
    scale_z = abs(water.matrix_world.to_scale().z) or 1.0
    probe.matrix_parent_inverse.identity()
    probe.location = ((low[0] + high[0]) / 2, (low[1] + high[1]) / 2, high[2] + PROBE_LIFT / scale_z)
    probe.rotation_euler = (0.0, 0.0, 0.0)
    # A planar probe spans -1..1 in its local X and Y; keep its own Z at world scale 1.
    probe.scale = (max((high[0] - low[0]) / 2, 1e-3), max((high[1] - low[1]) / 2, 1e-3), 1.0 / scale_z)


def fit_probe(water):
    """Refits the water's probe to its rest plane and its influence to the waves' reach.

    Returns what changed, in words; nothing when the water has no probe.
    """
    probe = find_probe(water)
    if probe is None:
        return []
    _place_probe(probe, water)
    changes = [f"planar probe '{probe.name}' fitted to the water's rest plane"]
    modifier = wave_modifier(water)
    if modifier is not None:  # the probe must reach the crests and the troughs
        reach = amplitude_sum(modifier) + 4 * PROBE_LIFT
        if probe.data.influence_distance < reach:
            probe.data.influence_distance = reach
            changes.append(f"probe influence widened to {reach:.2f} m for the waves")
    return changes


def _orphan_probe_data(water):
    """Probe data the add-on made for `water` whose object was deleted, to reuse."""
    return next(
        (
            d
            for d in bpy.data.lightprobes
            if d.users == 0 and d.get(PROBE_TAG) == water.name and d.type == "PLANE" and is_original(d)
        ),
        None,
    )


def _add_probe(scene, water):
    data = _orphan_probe_data(water) or bpy.data.lightprobes.new(f"{water.name} Mirror", "PLANE")
    data[PROBE_TAG] = water.name
    mark(data, PROBE_ROLE, 1)
    data.influence_distance = max(data.influence_distance, 4 * PROBE_LIFT)
    probe = bpy.data.objects.new(f"{water.name} Mirror", data)
    probe[PROBE_TAG] = water.name
    mark(probe, PROBE_ROLE, 1)
    for collection in water.users_collection or (scene.collection,):
        collection.objects.link(probe)
    probe.parent = water
    return probe


def _keep_probe(probe, water):
    """Re-attaches a probe the user unparented, and follows a renamed water; returns what changed."""
    changes = []
    if probe.parent != water:
        probe.parent = water
        changes.append(f"planar probe '{probe.name}' parented to '{water.name}' again")
    if probe[PROBE_TAG] != water.name:
        probe[PROBE_TAG] = water.name
        probe.data[PROBE_TAG] = water.name
    return changes


def sky_world():
    """The add-on's sky world, made once and reused by every scene that has none."""
    found = owned(bpy.data.worlds, SKY_NAME)
    if found:
        return found[0], False
    world = bpy.data.worlds.new(SKY_NAME)
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    background = world.node_tree.nodes.get("Background") if world.node_tree else None
    if background is not None:
        background.inputs["Color"].default_value = (*SKY_COLOR, 1.0)
    else:
        world.color = SKY_COLOR
    mark(world, SKY_NAME, 1)
    return world, True


def _holder(water, stamp=True):
    return ledger_holder("mirror", water, stamp)


def _holds_mirror(holder):
    """Whether the water named in `holder` still has its mirror set-up (it is still water)."""
    water = holder_object(holder)
    return water is not None and water_material(water) is not None and bool(water.users_scene)


def release_mirror(scene, water):
    """Lets go of what `setup_mirror` set for `water` in `scene` (the engine, ray tracing, the
    world): each goes back only when it still holds the add-on's value and no other water in the
    file needs it; the sun's light linking lets go of the water. Returns the changes in words."""
    changes = []
    holder = _holder(water, stamp=False)
    for path in held_paths(scene, holder):
        release(scene, path, holder, path.rpartition(".")[2].replace("_", " "), changes, _holds_mirror)
    sun_link.release_everywhere(water)
    return changes


def setup_mirror(scene, water):
    """Sets `scene` and `water` up for a true mirror; returns what it changed, in words.

    Runs again safely: the probe is reused and only settings that differ are changed.
    Ocean shading needs no mirror (`needs_mirror`): it gets EEVEE's ray tracing (its refraction
    shows the bed through shallow water) and, in a scene with none, the Sky world (seen through
    Snell's window from below).
    """
    material = water_material(water)
    if material is None:
        raise MirrorSetupError(
            f"'{getattr(water, 'name', water)}' is not a water object (no Water Surface material)"
        )
    check_editable(scene, water, material)
    problem = needs_repair(material)
    if problem:
        raise MirrorSetupError(problem)
    changes = []
    holder = _holder(water)
    # Workbench shows no water; once the add-on chose EEVEE, each water needs it too.
    if scene.render.engine == "BLENDER_WORKBENCH" or holders(scene, "render.engine"):
        claim(scene, "render.engine", eevee_engine_id(), holder, "render engine", changes)
    # Both shadings trace refraction (the ocean's through shallow water to the bed).
    for path, value, label in RAY_TRACING:
        claim(scene, path, value, holder, label, changes)
    # A sky for every shading: the lake mirrors it, the ocean reflects it and, from below, shows
    # it through Snell's window (a scene with no world showed the window black).
    if scene.world is None:
        world, made = sky_world()
        if made:
            changes.append(f"added world '{world.name}'")
        claim(scene, "world", {"id": "WORLD", "name": world.name}, holder, "world", changes)
    elif holders(scene, "world"):  # the sky the add-on gave the scene: this water needs it too
        claim(scene, "world", {"id": "WORLD", "name": scene.world.name}, holder, "world", changes)
    if not needs_mirror(water):
        return changes
    if not material.use_raytrace_refraction:
        material.use_raytrace_refraction = True
        changes.append(f"ray-traced refraction on for '{material.name}'")
    if not water.hide_probe_plane:
        water.hide_probe_plane = True
        changes.append(f"'{water.name}' hidden from planar captures")
    probe = find_probe(water)
    if probe is None:
        changes.append(f"added planar probe '{_add_probe(scene, water).name}'")
    else:
        changes += _keep_probe(probe, water)
    changes += fit_probe(water)
    changes += sun_link.exclude_water(water, glint_sun(material))
    return changes
