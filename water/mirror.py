"""The mirror set-up: what EEVEE needs to show the water as a true mirror.

Screen-trace ray tracing reflects and refracts what is on screen (the seeds'
reflection and refraction maps). What the camera cannot see comes from a
planar light probe. EEVEE ignores a probe whose capture contains the surface
that receives it, so the probe is lifted 1 cm above the water (more than its
clip start, less than its influence distance) and the water is also hidden
from planar captures (`hide_probe_plane`). The probe is a child of the water:
it follows it when moved, rotated or scaled.
"""

import bpy

from ..engine import eevee_engine_id, enable_ray_tracing
from ..nodes.material import water_node
from .values import water_material
from .waves import amplitude_sum, wave_modifier

PROBE_TAG = "water_surface_mirror"  # custom property naming the water a probe mirrors
PROBE_LIFT = 0.01  # metres above the water
SKY_COLOR = (0.45, 0.6, 0.85)

_SETTING_NAMES = {
    "use_raytracing": "EEVEE ray tracing on",
    "ray_tracing_method": "ray tracing method: screen trace",
    "resolution_scale": "ray tracing at full resolution",
}


class MirrorSetupError(ValueError):
    """The mirror set-up cannot run on what it was given."""


def find_probe(water):
    """The planar probe made for `water`, or None."""
    for child in water.children:
        if child.get(PROBE_TAG) is not None and child.type == "LIGHT_PROBE" and child.data.type == "PLANE":
            return child
    return None


def _place_probe(probe, water):
    """Covers the water's local bounds, lifted PROBE_LIFT metres above its top."""
    corners = [tuple(c) for c in water.bound_box]
    xs, ys, zs = ([c[i] for c in corners] for i in range(3))
    scale_z = abs(water.matrix_world.to_scale().z) or 1.0
    probe.matrix_parent_inverse.identity()
    probe.location = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, max(zs) + PROBE_LIFT / scale_z)
    probe.rotation_euler = (0.0, 0.0, 0.0)
    # A planar probe spans -1..1 in its local X and Y; keep its own Z at world scale 1.
    probe.scale = (max((max(xs) - min(xs)) / 2, 1e-3), max((max(ys) - min(ys)) / 2, 1e-3), 1.0 / scale_z)


def _ensure_probe(scene, water):
    probe = find_probe(water)
    if probe is not None:
        _place_probe(probe, water)
        return probe, f"planar probe '{probe.name}' fitted to the water"
    data = bpy.data.lightprobes.new(f"{water.name} Mirror", "PLANE")
    data.influence_distance = max(data.influence_distance, 4 * PROBE_LIFT)
    probe = bpy.data.objects.new(f"{water.name} Mirror", data)
    probe[PROBE_TAG] = water.name
    for collection in water.users_collection or (scene.collection,):
        collection.objects.link(probe)
    probe.parent = water
    _place_probe(probe, water)
    return probe, f"added planar probe '{probe.name}'"


def setup_mirror(scene, water):
    """Sets `scene` and `water` up for a true mirror; returns what it changed, in words.

    Runs again safely: the probe is reused and only settings that differ are changed.
    """
    material = water_material(water)
    if material is None:
        raise MirrorSetupError(
            f"'{getattr(water, 'name', water)}' is not a water object (no Water Surface material)"
        )
    changes = []
    if scene.render.engine == "BLENDER_WORKBENCH":
        scene.render.engine = eevee_engine_id()
        changes.append("render engine set to EEVEE")
    changes += [_SETTING_NAMES[name] for name in enable_ray_tracing(scene)]
    if water_node(material) is not None and not material.use_raytrace_refraction:
        material.use_raytrace_refraction = True
        changes.append(f"ray-traced refraction on for '{material.name}'")
    if scene.world is None:
        world = bpy.data.worlds.new("Sky")
        if bpy.app.version < (5, 0, 0):
            world.use_nodes = True
        background = world.node_tree.nodes.get("Background")
        if background is not None:
            background.inputs["Color"].default_value = (*SKY_COLOR, 1.0)
        else:
            world.color = SKY_COLOR
        scene.world = world
        changes.append(f"added world '{world.name}'")
    if not water.hide_probe_plane:
        water.hide_probe_plane = True
        changes.append(f"'{water.name}' hidden from planar captures")
    probe, what = _ensure_probe(scene, water)
    changes.append(what)
    modifier = wave_modifier(water)
    if modifier is not None:  # the probe must reach the crests and the troughs
        reach = amplitude_sum(modifier) + 4 * PROBE_LIFT
        if probe.data.influence_distance < reach:
            probe.data.influence_distance = reach
            changes.append(f"probe influence widened to {reach:.2f} m for the waves")
    return changes
