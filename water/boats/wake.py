"""Wakes: an object that moves through the water leaves a Kelvin wake and foam in its mesh.

Per source, the water gets a `Water Wake` Geometry Nodes modifier (`nodes/boats/`: the track
kept by a simulation zone, the stationary-phase Kelvin pattern, the foam), after its waves and
before its surroundings' sample, so the surroundings see the wake too. The modifier reads where
the object is through an Object socket: a floating object's rig anchor (the anchor moves as the
object does before it floats, and reading the object itself would make a dependency cycle, the
water waiting on the object that waits on the water). The hull's length, beam and draft come
from its float's footprint, else from its bounds.

The material shows the foam through one Mix Shader ("Water Wake Foam") with an unlit white foam (an
Emission), put where the water's shader feeds the output (inside the keep-out, so a dry hull stays
dry): the lake and the ocean shading alike. Its factor is `Water Wake Foam Cover`'s: the stored
amount (`water_wake_foam`) thresholding the foam tile, solid where fresh, patches and lace where thin.
"""

import hashlib
import os

import bpy
import numpy as np

from ...nodes import SPECS
from ...nodes import material as material_spec
from ...nodes.boats import wake as wake_spec
from ...nodes.boats import wake_foam_cover
from ...nodes.builder import ensure_group
from ...nodes.ownership import is_local, role_of
from ...presets import schema
from ..editable import check_editable
from ..errors import WaterError
from ..float_constraints import floating_ancestor, pose_of
from ..kind import allows, refusal
from ..values import is_water, read_values, water_material
from ..waves import SURROUNDINGS_ROLE, get_wave_input, set_wave_input
from . import footprint_math, keep_out
from .float_rig import OWNER_KEY, anchor_of, footprint_of, footprint_settings

FOAM_MIX = "Water Wake Foam"
FOAM_SHADER = "Water Wake Foam Shader"
FOAM_READ = "Water Wake Foam Amount"
FOAM_COLOR = (0.85, 0.88, 0.9, 1.0)
LAKE_DRIFT = 0.3  # m/s: foam drift downwind on a lake or the seeds' ocean
SEA_DRIFT = 0.03  # of the wind speed, on the open sea (the surface drift: about 3%)
STRENGTH_MAX = 10.0  # the group's Strength socket's maximum
DETAIL_MAX = 100.0  # the group's Detail socket's maximum


class WakeError(WaterError, ValueError):
    """A wake cannot be made (one line, says why)."""


def wake_modifiers(water):
    """The water's `Water Wake` modifiers, in order."""
    return [
        m
        for m in getattr(water, "modifiers", ())
        if m.type == "NODES" and m.node_group is not None and role_of(m.node_group) == wake_spec.NAME
    ]


def source_of(modifier):
    """The object a wake modifier follows (a floating object, not its anchor), or None."""
    source = get_wave_input(modifier, "Source")
    if source is None:
        return None
    owner = source.get(OWNER_KEY) if hasattr(source, "get") else None
    return owner if owner is not None else source


def modifiers_of(obj):
    """The wake modifiers (on any water) that follow `obj`."""
    return [m for water in bpy.data.objects for m in wake_modifiers(water) if source_of(m) == obj]


def follow_again(obj, modifiers=None):
    """Points `obj`'s wake modifiers (default: those found now) at what they must read now: its
    rig's anchor while it floats, itself when not (floating and stopping call it)."""
    for modifier in modifiers if modifiers is not None else modifiers_of(obj):
        set_wave_input(modifier, "Source", _follow(obj))


def _follow(obj):
    """What the modifier reads: the rig's anchor of a floating object (no cycle), else `obj`."""
    pose = pose_of(obj)
    anchor = anchor_of(pose) if pose is not None else None
    return anchor if anchor is not None else obj


def _hull_sizes(obj):
    """(length, beam, draft) in metres: the float's footprint, else the bounds."""
    settings = footprint_settings(obj)
    if settings:
        return settings["length"], settings["beam"], settings["draft"]
    length, beam, _centre, _axis, _keel, height = footprint_of(obj)
    return max(length, 0.01), max(beam, 0.01), footprint_math.default_draft(height)


def _cell(water):
    """The water mesh's finest cells, metres (the 5th percentile of its edges' lengths: the
    open sea's graded mesh is finest round the middle, where the camera is)."""
    mesh = water.data
    if not len(mesh.edges):
        return 1.0
    ends = np.empty(len(mesh.edges) * 2, dtype=np.int64)
    mesh.edges.foreach_get("vertices", ends)
    points = np.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", points)
    points = points.reshape(-1, 3)
    ends = ends.reshape(-1, 2)
    scale = max(water.matrix_world.to_scale()[:2])
    lengths = np.linalg.norm(points[ends[:, 0]] - points[ends[:, 1]], axis=1)
    return float(np.percentile(lengths, 5)) * scale


def _drift(water):
    """The foam's drift, metres a second, downwind (the water's wind direction)."""
    values = read_values(water_material(water))
    direction = np.array(values.get("wind_direction", (0.0, 1.0))[:2], dtype=float)
    norm = np.linalg.norm(direction)
    direction = direction / norm if norm > 0 else np.array([0.0, 1.0])
    ocean = next((m for m in water.modifiers if m.type == "OCEAN"), None)
    speed = SEA_DRIFT * ocean.wind_velocity if ocean is not None else LAKE_DRIFT
    return (*(direction * speed), 0.0)


def _depth(water):
    """Metres of water under the hull: the open sea's Ocean depth, else the group's default."""
    ocean = next((m for m in water.modifiers if m.type == "OCEAN"), None)
    return ocean.depth if ocean is not None else wake_spec.DEPTH_DEFAULT


def _place(water, modifier):
    """Before the surroundings' sample (which measures the surface), after everything else."""
    modifiers = list(water.modifiers)
    later = [
        i
        for i, m in enumerate(modifiers)
        if m.type == "NODES" and m.node_group is not None and role_of(m.node_group) == SURROUNDINGS_ROLE
    ]
    if later:
        water.modifiers.move(modifiers.index(modifier), later[0])


def add_wake_source(obj, water, strength=1.0):
    """Makes `obj` leave a wake on `water` as it moves (again: its sizes and what it follows
    brought up to date). Returns the changes in words."""
    why = refusal(water, "wake", subject=f"'{getattr(water, 'name', water)}'")
    if why is not None:
        raise WakeError(why)
    if obj is None or obj == water or is_water(obj):
        raise WakeError("Water leaves no wake on water: select the moving object and the water")
    ancestor = floating_ancestor(obj)
    if ancestor is not None:  # its motion waits on the water: the water cannot wait on it
        raise WakeError(
            f"'{obj.name}' rides on '{ancestor.name}', which floats: add the wake to '{ancestor.name}'"
        )
    try:  # checked before anything is made: a bad value leaves nothing half-made
        strength = float(strength)
    except (TypeError, ValueError):
        raise WakeError(f"The wake's strength must be a number (got {strength!r})") from None
    if not 0.0 <= strength <= STRENGTH_MAX:
        raise WakeError(f"The wake's strength must be 0 to {STRENGTH_MAX:g} (got {strength})")
    material = water_material(water)
    check_editable(water, material)
    modifier = next((m for m in wake_modifiers(water) if source_of(m) == obj), None)
    change = f"'{obj.name}' leaves a wake on '{water.name}'"
    if modifier is None:
        modifier = water.modifiers.new(f"{wake_spec.NAME}: {obj.name}", "NODES")
        modifier.node_group = ensure_group(wake_spec.SPEC, SPECS)
        _place(water, modifier)
    else:
        change = f"brought '{obj.name}''s wake on '{water.name}' up to date"
    _forget_bake(water, modifier)  # its bake, if any, is of the wake before
    length, beam, draft = _hull_sizes(obj)
    for name, value in (
        ("Source", _follow(obj)),
        ("Length", length),
        ("Beam", beam),
        ("Draft", draft),
        ("Depth", _depth(water)),
        ("Strength", strength),
        ("Detail", min(_cell(water), DETAIL_MAX)),
        ("Drift", _drift(water)),
        ("Shading Normal", allows(water, "stored_normal")),
    ):
        set_wave_input(modifier, name, value)
    show_foam(material)
    note = coarse_note(modifier)
    return [change] + ([note] if note else [])


def coarse_note(modifier):
    """A sentence when the water's mesh is too coarse to show the wake `modifier` makes (the hull
    makes waves about its own length best; a wave needs four cells), with the resolution that
    would, else None."""
    water = modifier.id_data
    length = get_wave_input(modifier, "Length") or 1.0
    cell, wanted = _cell(water), length / 4.0
    if cell <= wanted:
        return None
    size = max(water.dimensions[:2]) or 1.0
    source = getattr(source_of(modifier), "name", "?")  # the hull's name
    resolution = min(int(np.ceil(size / wanted)) + 1, schema.RESOLUTION.max)
    return (
        f"'{water.name}''s mesh is too coarse to show the wake of '{source}' "
        f"(cells {cell:.3g} m, its waves need {wanted:.2g} m): add the water with Resolution "
        f"{resolution} or more, or subdivide it"
    )


def remove_wake_source(obj, water=None):
    """Takes `obj`'s wake off `water` (None: off every water); returns the changes."""
    changes = []
    waters = [water] if water is not None else [o for o in bpy.data.objects if wake_modifiers(o)]
    for each in waters:
        for modifier in [m for m in wake_modifiers(each) if source_of(m) in (obj, None)]:
            check_editable(each)
            each.modifiers.remove(modifier)
            changes.append(f"'{obj.name}' leaves no wake on '{each.name}'")
        _hide_foam_when_unused(each)
    return changes


def _hide_foam_when_unused(water):
    """Takes the foam out of `water`'s material once no water using it has a wake left (a Shift+D
    copy shares the material: its wake going must not take the original's foam)."""
    material = water_material(water)
    if material is None or wake_modifiers(water):
        return
    if any(wake_modifiers(o) for o in bpy.data.objects if o != water and water_material(o) == material):
        return
    hide_foam(material)


def _foam_cover(tree, mix):
    """The `Water Wake Foam Cover` node feeding `mix`'s factor (named FOAM_READ)."""
    cover = tree.nodes.new("ShaderNodeGroup")
    cover.node_tree = ensure_group(wake_foam_cover.SPEC, SPECS)
    cover.name, cover.label = FOAM_READ, "wake foam cover (0..1)"
    cover.location = (mix.location.x - 300, mix.location.y + 150)
    tree.links.new(cover.outputs["Cover"], mix.inputs["Fac"])
    return cover


def show_foam(material):
    """The foam mix in `material` (made when missing): the wake's foam over the water's shader. A
    mix from before the foam broke up (its factor the stored amount as it is) gets the cover."""
    tree = material.node_tree
    mix = tree.nodes.get(FOAM_MIX)
    if mix is not None:
        read = tree.nodes.get(FOAM_READ)
        if read is not None and read.bl_idname == "ShaderNodeAttribute" and is_local(material):
            location = read.location.copy()
            tree.nodes.remove(read)
            _foam_cover(tree, mix).location = location
        return
    target = keep_out.water_shader_input(material)
    if target is None or not target.is_linked:
        raise WakeError(f"Material '{material.name}' has no shader linked to its output")
    source = target.links[0].from_socket
    feeding = target.node
    mix = tree.nodes.new("ShaderNodeMixShader")
    mix.name, mix.label = FOAM_MIX, "wake foam"
    mix.location = (feeding.location.x - 200, feeding.location.y - 250)
    # Unlit, as the shore foam is before 4.5: a diffuse closure in the water's material would
    # drop EEVEE 4.2's traced refraction, and the sun, light-linked off the water, would not
    # light it anyway.
    foam = tree.nodes.new("ShaderNodeEmission")
    foam.name, foam.label = FOAM_SHADER, "foam: white, unlit"
    foam.inputs["Color"].default_value = FOAM_COLOR
    foam.inputs["Strength"].default_value = 1.0
    foam.location = (mix.location.x - 300, mix.location.y - 150)
    _foam_cover(tree, mix)
    tree.links.new(source, mix.inputs[1])
    tree.links.new(foam.outputs[0], mix.inputs[2])
    tree.links.new(mix.outputs[0], target)


def hide_foam(material):
    """Takes the foam mix out of `material`, the water's shader linked where it was."""
    if material is None or material.node_tree is None:
        return
    tree = material.node_tree
    mix = tree.nodes.get(FOAM_MIX)
    if mix is None:
        return
    source = mix.inputs[1].links[0].from_socket if mix.inputs[1].is_linked else None
    targets = [link.to_socket for link in mix.outputs[0].links]
    cover = getattr(tree.nodes.get(FOAM_READ), "node_tree", None)
    for name in (FOAM_MIX, FOAM_SHADER, FOAM_READ):
        node = tree.nodes.get(name)
        if node is not None:
            tree.nodes.remove(node)
    if cover is not None and cover.users == 0 and role_of(cover) is not None:
        bpy.data.node_groups.remove(cover)  # ours, and no material shows a wake's foam any more
    for target in targets if source is not None else ():
        tree.links.new(source, target)


def remove_lost_sources():
    """Takes off the wakes whose object was deleted (gone, or in no scene any more); returns the
    changes."""
    changes = []
    for water in [o for o in bpy.data.objects if is_local(o) and wake_modifiers(o)]:
        for modifier in wake_modifiers(water):
            source = source_of(modifier)
            if source is None or (not source.users_scene and not source.use_fake_user):
                name = source.name if source is not None else modifier.name
                water.modifiers.remove(modifier)
                changes.append(f"'{water.name}' lost the wake of '{name}' (it was deleted)")
        _hide_foam_when_unused(water)
    return changes


PACKED_BAKES_SINCE = (4, 3, 0)  # before: bakes go to a folder on disk


BAKED_KEY = "water_surface_wake_baked"  # on the water: the names of its wake modifiers `bake` baked
# On the water: {modifier name: what the bake was made of}, to tell a bake gone stale.
BAKE_PRINT_KEY = "water_surface_wake_bake_print"


def _baked_names(water):
    return [str(name) for name in water.get(BAKED_KEY, ())]


def _forget_bake(water, modifier):
    if modifier.name in _baked_names(water):
        water[BAKED_KEY] = [name for name in _baked_names(water) if name != modifier.name]


def _motion(modifier):
    """What a bake of `modifier` depends on, as text: how its object (and each parent) moves, its
    constraints, the modifier's inputs and the water's place."""
    parts = []
    obj = source_of(modifier)
    while obj is not None:
        parts.append((obj.name, tuple(obj.matrix_basis.col[3]), tuple(obj.rotation_euler), tuple(obj.scale)))
        action = obj.animation_data.action if obj.animation_data else None
        for fcurve in material_spec._action_fcurves(action):
            keys = [
                (tuple(k.co), tuple(k.handle_left), tuple(k.handle_right), k.interpolation)
                for k in fcurve.keyframe_points
            ]
            parts.append((fcurve.data_path, fcurve.array_index, fcurve.mute, keys))
        parts += [
            (c.type, c.mute, c.influence, getattr(getattr(c, "target", None), "name", None))
            for c in obj.constraints
        ]
        obj = obj.parent
    for item in modifier.node_group.interface.items_tree if modifier.node_group else ():
        if getattr(item, "in_out", None) == "INPUT" and item.socket_type != "NodeSocketGeometry":
            value = get_wave_input(modifier, item.name)
            if hasattr(value, "name"):  # the Source: an object
                value = value.name
            elif hasattr(value, "__len__"):  # a vector
                value = tuple(value)
            parts.append((item.name, value))
    parts.append(tuple(tuple(row) for row in modifier.id_data.matrix_world))
    return hashlib.sha1(repr(parts).encode("utf-8")).hexdigest()


def bake_problems(water, scene):
    """A sentence for each wake of `water` a farm would render wrong: not baked, baked before its
    object's motion or the wake's inputs changed, or over frames that do not cover the scene's
    (the wake freezes past the bake's last frame; one frame has no wake at all)."""
    prints = water.get(BAKE_PRINT_KEY, {})
    problems = []
    for modifier in wake_modifiers(water):
        name = getattr(source_of(modifier), "name", "?")
        made = prints.get(modifier.name) if modifier.name in _baked_names(water) else None
        if made is None:
            problems.append(f"The wake on '{water.name}' is not baked: farms render it flat")
            continue
        start, end, motion = int(made["start"]), int(made["end"]), str(made["motion"])
        if end <= start:
            problems.append(f"The wake of '{name}' was baked over one frame: it has no wake; bake the range")
        elif start > scene.frame_start or end < scene.frame_end:
            problems.append(
                f"The wake of '{name}' was baked for frames {start}-{end}, the scene runs "
                f"{scene.frame_start}-{scene.frame_end}: bake again"
            )
        elif motion != _motion(modifier):
            problems.append(
                f"The wake of '{name}' was baked before its motion or the wake changed: bake again"
            )
    return problems


def unbaked(water, scene=None):
    """Whether a farm rendering frames apart would render a wake of `water` wrong (see
    `bake_problems`)."""
    return bool(bake_problems(water, scene or bpy.context.scene))


def bake_folder():
    """Where 4.2 writes wake bakes: a folder beside the saved .blend, relative to it (so the file
    and the folder move together, and BAT packs it)."""
    name = os.path.splitext(bpy.path.basename(bpy.data.filepath))[0] or "untitled"
    return f"//{name}_water_bakes"


def bake(water, scene):
    """Bakes the wakes of `water` over `scene`'s frame range: packed into the .blend from 4.3, into
    `bake_folder()` beside the saved .blend on 4.2. Frames rendered apart, on a farm, then equal
    one run from the start. Returns the changes."""
    if not is_water(water):
        raise WakeError(f"'{getattr(water, 'name', water)}' is not water: name the water to bake")
    modifiers = wake_modifiers(water)
    if not modifiers:
        raise WakeError(f"'{water.name}' has no wake to bake")
    packed = bpy.app.version >= PACKED_BAKES_SINCE
    if not packed and not bpy.data.filepath:
        raise WakeError("Save the file first: Blender 4.2 bakes to a folder beside the .blend")
    check_editable(water)
    override = {
        "scene": scene,
        "object": water,
        "active_object": water,
        "selected_objects": [water],
        "selected_editable_objects": [water],
    }
    for modifier in modifiers:
        if packed:
            modifier.bake_target = "PACKED"
        else:
            modifier.bake_directory = bake_folder()
        for each in modifier.bakes:
            with bpy.context.temp_override(**override):
                result = bpy.ops.object.geometry_node_bake_single(
                    session_uid=water.session_uid, modifier_name=modifier.name, bake_id=each.bake_id
                )
            if "FINISHED" not in result:
                raise WakeError(f"Baking the wake of '{water.name}' failed")
    water[BAKED_KEY] = [m.name for m in modifiers]
    water[BAKE_PRINT_KEY] = {
        m.name: {"start": scene.frame_start, "end": scene.frame_end, "motion": _motion(m)} for m in modifiers
    }
    where = "into the file" if packed else f"to {bake_folder()}"
    return [f"baked the wake of '{water.name}', frames {scene.frame_start} to {scene.frame_end}, {where}"]
