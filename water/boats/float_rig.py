"""The rig that makes a hull ride the water under its whole footprint, from Blender's own parts.

For a floating object the add-on makes, in a hidden collection `RIG_COLLECTION`:

* an anchor: an empty that moves as the object itself moves before it floats: the same parent,
  transform and action (shared, so keys added to the object later move it too) and copies of the
  object's own constraints (a Follow Path). The probes cannot follow the object itself: Blender
  makes any reading of an object's transform wait for all its constraints, the float's too, so
  probes placed from the object would close a dependency cycle;
* probes: empties parented to the anchor over the object's footprint (`footprint_math`), each
  dropped onto the water's evaluated surface, straight down or up, by a Shrinkwrap constraint:
  onto a patch of it, a hidden mesh with the water's transform whose `Water Float Patch`
  modifier keeps the water's evaluated surface round the anchor only (a Shrinkwrap builds a
  ray-cast tree of all its target's mesh every frame: the whole sea's cost 4.65x the sea alone);
* a pose: an empty whose Z is where the origin belongs (the plane fitted to the probes' heights,
  at the origin, less the keel's depth below the origin and the draft) and whose X and Y
  rotations are that plane's tilt in the object's own axes, by simple-expression drivers that
  read the probes' world Z.

The object takes its height from the pose (Copy Location, world Z only) and its tilt (Copy
Rotation, after its own: about its own axes) at 1 - tilt damping. Nothing runs Python at render,
so a saved file floats the same without the add-on. The rig's empties carry `RIG_KEY` (their
role); the anchor also names its object (`OWNER_KEY`), so a rig whose object was deleted is
found and removed (`remove_lost_rigs`).
"""

import math

import bpy
import numpy as np

from ...nodes import SPECS, float_patch
from ...nodes.builder import ensure_group
from .. import waves
from ..float_constraints import PATCH_WATER_KEY, RIG_KEY
from . import footprint_math

RIG_COLLECTION = "Water Float Rigs"
OWNER_KEY = "water_surface_float_owner"  # on the anchor: the floating object
SETTINGS_KEY = "water_surface_float_footprint"  # on the floating object: draft, length, beam
PROBE_NAMES = "abcdefghijklmnopqrstu"  # a driver variable per probe (21 = ALONG x ACROSS)
_EXPRESSION_MAX = 255  # Blender keeps a driver's expression in 256 bytes
_TRANSFORM = (
    "rotation_mode",
    "location",
    "rotation_euler",
    "rotation_quaternion",
    "rotation_axis_angle",
    "scale",
    "delta_location",
    "delta_rotation_euler",
    "delta_rotation_quaternion",
    "delta_scale",
)


def footprint_of(obj):
    """(length, beam, centre (x, y), long axis "X"/"Y", keel z, height) from `obj`'s bounds in
    its own axes, in metres (scale applied): the length along the longer of X and Y."""
    xs = [corner[0] * obj.scale.x for corner in obj.bound_box]
    ys = [corner[1] * obj.scale.y for corner in obj.bound_box]
    zs = [corner[2] * obj.scale.z for corner in obj.bound_box]
    size_x, size_y = max(xs) - min(xs), max(ys) - min(ys)
    centre = ((max(xs) + min(xs)) / 2.0, (max(ys) + min(ys)) / 2.0)
    long_axis = "X" if size_x >= size_y else "Y"
    length, beam = (size_x, size_y) if long_axis == "X" else (size_y, size_x)
    return length, beam, centre, long_axis, min(zs), max(zs) - min(zs)


def rig_collection(scene):
    """The hidden collection of the floating rigs, linked into `scene` (made when missing)."""
    collection = next(
        (c for c in bpy.data.collections if c.get(RIG_KEY) == "collection" and c.library is None), None
    )
    if collection is None:
        collection = bpy.data.collections.new(RIG_COLLECTION)
        collection[RIG_KEY] = "collection"
    if collection not in scene.collection.children_recursive:
        scene.collection.children.link(collection)
    collection.hide_render = True
    collection.hide_viewport = True
    return collection


def _empty(name, role, collection):
    obj = bpy.data.objects.new(name, None)
    obj.empty_display_type = "SPHERE" if role == "probe" else "ARROWS"
    obj.empty_display_size = 0.2
    obj[RIG_KEY] = role
    collection.objects.link(obj)
    return obj


def _anchor(obj, collection, own_constraints):
    """An empty that moves as `obj` does before it floats (see the module's docstring)."""
    anchor = _empty(f"{obj.name} Float Anchor", "anchor", collection)
    anchor[OWNER_KEY] = obj
    anchor.parent = obj.parent
    anchor.parent_type = obj.parent_type
    if obj.parent_type == "BONE":
        anchor.parent_bone = obj.parent_bone
    anchor.matrix_parent_inverse = obj.matrix_parent_inverse.copy()
    for prop in _TRANSFORM:
        setattr(anchor, prop, getattr(obj, prop))
    follow(anchor, obj)
    for constraint in own_constraints:
        anchor.constraints.copy(constraint)
    return anchor


def _shared_action(obj):
    """`obj`'s action, given one (empty, marked ours) when it has none, so keys added later land
    where the anchor plays them too; returns (action, slot or None before 4.4, made)."""
    data = obj.animation_data or obj.animation_data_create()
    made = data.action is None
    if made:
        data.action = bpy.data.actions.new(f"{obj.name} Action")
        data.action[RIG_KEY] = "action"
    slot = None
    if hasattr(data, "action_slot"):  # slotted actions (4.4 and later)
        if data.action_slot is None:
            data.action_slot = data.action.slots.new(id_type="OBJECT", name=obj.name)
        slot = data.action_slot
    return data.action, slot, made


def follow(anchor, obj):
    """The anchor plays `obj`'s action (the same slot); returns whether `obj` was given one."""
    action, slot, made = _shared_action(obj)
    target = anchor.animation_data or anchor.animation_data_create()
    target.action = action
    if slot is not None:
        target.action_slot = slot
    return made


def _fcurve_count(action):
    layers = getattr(action, "layers", None)
    if layers:
        return sum(
            len(bag.fcurves) for layer in layers for strip in layer.strips for bag in strip.channelbags
        )
    return len(getattr(action, "fcurves", ()))


def let_go_of_action(obj):
    """Takes back the empty action `follow` gave `obj` (one the user keyed stays)."""
    data = obj.animation_data
    action = data.action if data is not None else None
    if action is None or action.get(RIG_KEY) != "action" or _fcurve_count(action):
        return
    data.action = None
    if action.users == 0:
        bpy.data.actions.remove(action)


def _variable(driver, name, target):
    variable = driver.variables.new()
    variable.name, variable.type = name, "TRANSFORMS"
    variable.targets[0].id = target
    variable.targets[0].transform_type = "LOC_Z"
    variable.targets[0].transform_space = "WORLD_SPACE"


def _drive(owner, prop, index, expression, probes):
    """A simple-expression driver on `owner.prop[index]` reading the probes' world Z."""
    if len(expression) > _EXPRESSION_MAX:
        raise ValueError(f"driver expression too long ({len(expression)} characters)")
    owner.driver_remove(prop, index)
    driver = owner.driver_add(prop, index).driver
    driver.type = "SCRIPTED"
    for name, probe in zip(PROBE_NAMES, probes):
        _variable(driver, name, probe)
    driver.expression = expression


def _weighted_sum(weights, constant=0.0, room=12):
    """'w1*a+w2*b+...+c' with numbers as short as the expression's 255 characters ask."""
    for digits in (6, 5, 4, 3):
        terms = [f"{w:+.{digits}g}*{PROBE_NAMES[i]}" for i, w in enumerate(weights) if abs(w) > 1e-9]
        text = "".join(terms) + (f"{constant:+.{digits + 1}g}" if constant else "")
        text = text.lstrip("+") or "0"
        if len(text) <= _EXPRESSION_MAX - room:
            return text
    raise ValueError("too many probes for one driver expression")


# Beyond the footprint the patch keeps this much of the water each way: the probes stand over
# the footprint (they do not tilt with the hull), and the waves' sideways displacement (the open
# sea's choppiness, a few metres at most at the swell it takes) stays within it.
PATCH_MARGIN = 3.0  # metres


def _patch(obj, water, anchor, collection, reach):
    """The piece of `water`'s evaluated surface within `reach` metres of the anchor (each way),
    for the probes to drop onto (see the module's docstring)."""
    name = f"{obj.name} Float Patch"
    patch = bpy.data.objects.new(name, bpy.data.meshes.new(name))
    patch[RIG_KEY] = "patch"
    patch[PATCH_WATER_KEY] = water
    patch.display_type = "WIRE"
    patch.hide_render = True
    collection.objects.link(patch)
    same_place = patch.constraints.new("COPY_TRANSFORMS")
    same_place.name = "Water Float Patch"
    same_place.target = water
    modifier = patch.modifiers.new(float_patch.NAME, "NODES")
    modifier.node_group = ensure_group(SPECS[float_patch.NAME], SPECS)
    waves.set_wave_input(modifier, "Water", water)
    waves.set_wave_input(modifier, "Anchor", anchor)
    waves.set_wave_input(modifier, "Radius", reach)
    grid = _even_grid(water)
    if grid is not None:
        side, corner, cell = grid
        scale = max(abs(water.scale.x), abs(water.scale.y), 1e-6)
        waves.set_wave_input(modifier, "Grid Side", side)
        waves.set_wave_input(modifier, "Grid Corner", (*corner, 0.0))
        waves.set_wave_input(modifier, "Grid Cell", cell)
        waves.set_wave_input(modifier, "Patch Side", min(side, math.ceil(2.0 * reach / scale / cell) + 3))
    return patch


def _even_grid(water):
    """(points a side, first point (x, y), spacing) of `water`'s mesh if it is an even grid laid
    out as `grid.grid_mesh` lays it (row by row, point i at column i % side, row i // side), in
    its own space; else None (the open sea's graded grid, a user's mesh)."""
    mesh = water.data
    side = math.isqrt(len(mesh.vertices))
    if side < 2 or side * side != len(mesh.vertices):
        return None
    points = np.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", points)
    points = points.reshape(-1, 3)
    corner, cell = points[0, :2], float(points[1, 0] - points[0, 0])
    if cell <= 0.0:
        return None
    index = np.arange(len(points))
    expected = corner + np.column_stack([index % side, index // side]) * cell
    if np.abs(points[:, :2] - expected).max() > 1e-3 * cell:
        return None
    return side, (float(corner[0]), float(corner[1])), cell


def _cell(water):
    """The water's cell in metres: the median length of its evaluated mesh's edges (a coarse open
    sea's are metres long; its far ring's fewer, longer edges do not move the median)."""
    mesh = water.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    if not mesh.edges:
        return 0.0
    points = np.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", points)
    ends = np.empty(len(mesh.edges) * 2, dtype=np.int64)
    mesh.edges.foreach_get("vertices", ends)
    points, ends = points.reshape(-1, 3), ends.reshape(-1, 2)
    lengths = np.linalg.norm(points[ends[:, 0]] - points[ends[:, 1]], axis=1)
    return float(np.median(lengths)) * max(abs(water.scale.x), abs(water.scale.y), 1e-6)


def patches_of(probes):
    """The patches the probes drop onto."""
    found = []
    for probe in probes:
        for constraint in probe.constraints:
            target = constraint.target if constraint.type == "SHRINKWRAP" else None
            if target is not None and target.get(RIG_KEY) == "patch" and target not in found:
                found.append(target)
    return found


def _remove_objects(objects):
    for obj in objects:
        if obj is None or obj.name not in bpy.data.objects:
            continue
        data = obj.data if obj.get(RIG_KEY) == "patch" else None
        bpy.data.objects.remove(obj)
        if data is not None and data.users == 0:
            bpy.data.meshes.remove(data)


def _drop_onto(probe, surface):
    """Shrinkwrap: the probe onto the water's evaluated surface (its patch), straight down or up."""
    constraint = probe.constraints.new("SHRINKWRAP")
    constraint.name = "Water Float Probe"
    constraint.target = surface
    constraint.shrinkwrap_type = "PROJECT"
    constraint.project_axis = "NEG_Z"
    constraint.project_axis_space = "WORLD"
    constraint.use_project_opposite = True
    constraint.cull_face = "OFF"
    constraint.project_limit = 0.0


def build(obj, water, scene, own_constraints, draft=None, length=None, beam=None):
    """Makes `obj`'s anchor, probes and pose on `water`; returns (pose, settings used).
    `own_constraints`: the object's constraints the anchor copies (those before the float's)."""
    own_length, own_beam, centre, long_axis, keel, height = footprint_of(obj)
    length = own_length if length is None else float(length)
    beam = own_beam if beam is None else float(beam)
    draft = footprint_math.default_draft(height) if draft is None else float(draft)
    # A flat object (a plane) has no beam: it still feels the water over a narrow strip.
    length = max(length, 1e-3)
    beam = max(beam, 0.05 * length)
    points = footprint_math.probe_grid(length, beam, centre, long_axis)
    weights = footprint_math.plane_weights(points)
    collection = rig_collection(scene)
    anchor = _anchor(obj, collection, own_constraints)
    # The footprint's farthest probe from the origin, whichever way the object turns, and two of
    # the water's cells more: the faces round a probe keep all their corners.
    reach = math.hypot(*centre) + math.hypot(length / 2.0, beam / 2.0) + 2.0 * _cell(water)
    patch = _patch(obj, water, anchor, collection, reach + PATCH_MARGIN)
    scale = [s if abs(s) > 1e-9 else 1.0 for s in obj.scale]
    probes = []
    for index, (x, y, _w) in enumerate(points):
        probe = _empty(f"{obj.name} Float Probe {index + 1}", "probe", collection)
        probe.parent = anchor
        probe.location = (x / scale[0], y / scale[1], 0.0)  # in the anchor's (the object's) own units
        _drop_onto(probe, patch)
        probes.append(probe)
    pose = _empty(f"{obj.name} Float Pose", "pose", collection)
    _drive(pose, "location", 2, _weighted_sum([w[0] for w in weights], -draft - keel), probes)
    # Euler XYZ: X by atan(sy) raises +Y, Y by -atan(sx) raises +X (second order left out).
    _drive(pose, "rotation_euler", 0, f"atan({_weighted_sum([w[2] for w in weights])})", probes)
    _drive(pose, "rotation_euler", 1, f"-atan({_weighted_sum([w[1] for w in weights])})", probes)
    return pose, {"draft": draft, "length": length, "beam": beam}


def probes_of(pose):
    """The probes the pose's drivers read."""
    found = []
    animation = pose.animation_data if pose is not None else None
    for curve in animation.drivers if animation else ():
        for variable in curve.driver.variables:
            target = variable.targets[0].id
            if target is not None and target.get(RIG_KEY) == "probe" and target not in found:
                found.append(target)
    return found


def anchor_of(pose):
    """The anchor the pose's probes hang from, or None."""
    parents = [probe.parent for probe in probes_of(pose) if probe.parent is not None]
    return parents[0] if parents and parents[0].get(RIG_KEY) == "anchor" else None


def remove(pose):
    """Removes a pose, its probes and its anchor (and the rig collection once it is empty)."""
    if pose is None or pose.get(RIG_KEY) != "pose":
        return
    anchor = anchor_of(pose)
    probes = probes_of(pose)
    _remove_objects([*patches_of(probes), *probes, pose, anchor])
    _remove_empty_collections()


def _remove_empty_collections():
    for collection in [c for c in bpy.data.collections if c.get(RIG_KEY) == "collection"]:
        if collection.library is None and not collection.all_objects:
            bpy.data.collections.remove(collection)


def owned_by(pose, obj):
    """Whether the rig of `pose` was made for `obj` (a copy of a floating object shares it)."""
    anchor = anchor_of(pose)
    return anchor is not None and anchor.get(OWNER_KEY) == obj


def out_of_date(obj, pose):
    """Why `obj`'s rig no longer moves as `obj` does (moved or keyed since it floated, or a copy
    of another floating object: float it again), or None."""
    anchor = anchor_of(pose)
    if anchor is None:
        return None
    owner = anchor.get(OWNER_KEY)
    if owner != obj:
        return f"'{obj.name}' floats by the rig of '{getattr(owner, 'name', '?')}' (a copy?)"
    source = obj.animation_data.action if obj.animation_data else None
    played = anchor.animation_data.action if anchor.animation_data else None
    if source != played:
        return f"'{obj.name}' has another animation since it floated"
    if anchor.parent != obj.parent:
        return f"'{obj.name}' has another parent since it floated"
    moved = anchor.matrix_basis - obj.matrix_basis
    if max(abs(value) for row in moved for value in row) > 1e-4:
        return f"'{obj.name}' was moved since it floated"
    return None


def footprint_settings(obj):
    """{"draft", "length", "beam"} the object floats with ({} when it does not, or the old way)."""
    held = obj.get(SETTINGS_KEY)
    try:
        return {key: float(held[key]) for key in ("draft", "length", "beam")} if held else {}
    except (TypeError, KeyError, ValueError):
        return {}


def remove_lost_rigs():
    """Removes the rigs whose object was deleted or no longer floats by them; returns the changes."""
    changes = []
    for anchor in [o for o in bpy.data.objects if o.get(RIG_KEY) == "anchor" and o.library is None]:
        owner = anchor.get(OWNER_KEY)
        poses = [o for o in bpy.data.objects if o.get(RIG_KEY) == "pose" and anchor_of(o) == anchor]
        # A floating object deleted the ordinary way may live on, in no scene, while something
        # holds it (a water kept out of it, until `keep_out.remove_lost_hulls`): it is gone too.
        used = (
            owner is not None
            and bool(owner.users_scene)
            and any(c.target in poses for c in getattr(owner, "constraints", ()) if hasattr(c, "target"))
        )
        if used:
            continue
        name = anchor.name
        if poses:
            for pose in poses:
                remove(pose)
        else:
            probes = [o for o in bpy.data.objects if o.parent == anchor and o.get(RIG_KEY) == "probe"]
            _remove_objects([*patches_of(probes), *probes, anchor])
        changes.append(f"removed floating rig '{name}': its object is gone or floats no more")
    _remove_empty_collections()
    return changes
