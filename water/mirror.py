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

from ..engine import eevee_engine_id, enable_ray_tracing
from ..nodes.material import glint_sun, water_node
from ..nodes.ownership import is_original, mark, owned
from . import sun_link
from .editable import check_editable
from .repair import needs_repair
from .values import water_material
from .waves import amplitude_sum, wave_modifier

PROBE_TAG = "water_surface_mirror"  # custom property naming the water a probe mirrors
PROBE_ROLE = "Mirror Probe"
PROBE_LIFT = 0.01  # metres above the water
SKY_COLOR = (0.45, 0.6, 0.85)
SKY_NAME = "Sky"

_SETTING_NAMES = {
    "use_raytracing": "EEVEE ray tracing on",
    "ray_tracing_method": "ray tracing method: screen trace",
    "resolution_scale": "ray tracing at full resolution",
}


class MirrorSetupError(ValueError):
    """The mirror set-up cannot run on what it was given."""


def _is_mirror_probe(obj):
    return (
        obj.get(PROBE_TAG) is not None
        and obj.type == "LIGHT_PROBE"
        and obj.data is not None
        and obj.data.type == "PLANE"
        and is_original(obj)
    )


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


def needs_mirror(material):
    """The one rule for which water gets the mirror set-up: lake shading does; the ocean
    shading reflects the world's sky and needs none."""
    return water_node(material) is not None


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


def setup_mirror(scene, water):
    """Sets `scene` and `water` up for a true mirror; returns what it changed, in words.

    Runs again safely: the probe is reused and only settings that differ are changed.
    Ocean shading needs no mirror (`needs_mirror`): it gets EEVEE's ray tracing only (its
    refraction shows the bed through shallow water).
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
    if scene.render.engine == "BLENDER_WORKBENCH":
        scene.render.engine = eevee_engine_id()
        changes.append("render engine set to EEVEE")
    # Both shadings trace refraction (the ocean's through shallow water to the bed).
    changes += [_SETTING_NAMES[name] for name in enable_ray_tracing(scene)]
    if not needs_mirror(material):
        return changes
    if not material.use_raytrace_refraction:
        material.use_raytrace_refraction = True
        changes.append(f"ray-traced refraction on for '{material.name}'")
    if scene.world is None:
        world, made = sky_world()
        scene.world = world
        changes.append(f"{'added' if made else 'set the'} world '{world.name}'")
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
