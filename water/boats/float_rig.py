"""The rig that makes a hull ride the water under its whole footprint, from Blender's own parts.

For a floating object the add-on makes, in a hidden collection `RIG_COLLECTION`:

* an anchor: an empty that moves as the object itself moves before it floats: the same parent,
  transform and action (shared, so keys added to the object later move it too) and copies of the
  object's own constraints (a Follow Path). The pose cannot follow the object itself: Blender
  makes any reading of an object's transform wait for all its constraints, the float's too, so a
  pose placed from the object would close a dependency cycle;
* a pose: a hidden mesh whose `Water Float Fit` modifier (`nodes/boats/float_fit.py`) does the rest
  each frame: its own points are the probes over the object's footprint (`footprint_math`), in
  the anchor's own space, each with its weights for the fitted plane; the modifier drops them
  onto the water's evaluated surface, straight down or up, onto a patch of it round them only
  (a ray-cast tree of all the sea's mesh would cost 4.65x the sea alone), fits the plane to
  their heights and lays the pose's triangle (the vertex group `float_fit.POSE_GROUP`) on it
  over the anchor: its mean height where the origin belongs (the plane at the origin, less the
  keel's depth below the origin and the draft), its normal the plane's tilt in the object's own
  axes.

The object takes its height from the triangle (Copy Location, world Z only) and its tilt (Copy
Rotation, after its own: about its own axes) at 1 - tilt damping, both with the vertex group as
subtarget. Two objects a hull, where rigs made before had 24 (21 Shrinkwrap probe empties, a
patch, three drivers of 21 variables: about 2 ms a hull; `remove` still takes those apart).
Nothing runs Python at render, so a saved file floats the same without the add-on. The rig's
objects carry `RIG_KEY` (their role); the anchor also names its object (`OWNER_KEY`), so a rig
whose object was deleted is found and removed (`remove_lost_rigs`).
"""

import math

import bpy
import numpy as np

from ...nodes import SPECS
from ...nodes.boats import float_fit
from ...nodes.builder import ensure_group
from ...nodes.ownership import is_local
from .. import waves
from ..float_constraints import PATCH_WATER_KEY, RIG_KEY
from . import footprint_math

RIG_COLLECTION = "Water Float Rigs"
OWNER_KEY = "water_surface_float_owner"  # on the anchor: the floating object
SETTINGS_KEY = "water_surface_float_footprint"  # on the floating object: draft, length, beam
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


# Off an even grid, beyond the footprint the patch keeps this much of the water each way: the
# probes stand over the footprint (they do not tilt with the hull), and the waves' sideways
# displacement (the open sea's choppiness, a few metres at most at the swell it takes) stays
# within it.
PATCH_MARGIN = 3.0  # metres


def _pose_mesh(name, points, weights):
    """The pose's own mesh: a point per probe (in the anchor's own units) with its weights
    (`float_fit.WEIGHTS`), then a triangle round the origin, the vertex group `POSE_GROUP`
    (the fit lays it on the plane; its points' offsets give the tilt, the group's mean normal)."""
    triangle = [(math.cos(turn), math.sin(turn), 0.0) for turn in (0.0, 2.0 * math.pi / 3, 4.0 * math.pi / 3)]
    mesh = bpy.data.meshes.new(name)
    first = len(points)
    mesh.from_pydata([*points, *triangle], [], [(first, first + 1, first + 2)])
    values = [value for row in weights for value in row] + [0.0] * 9
    mesh.attributes.new(float_fit.WEIGHTS, "FLOAT_VECTOR", "POINT").data.foreach_set("vector", values)
    return mesh


def _pose(obj, water, anchor, collection, probes, weights, height, reach):
    """The pose: a hidden mesh whose `Water Float Fit` modifier drops the probes onto the water
    within `reach` metres of the anchor (each way) and lays its triangle on the plane fitted to
    their heights, `height` above it (see the module's docstring)."""
    name = f"{obj.name} Float Pose"
    pose = bpy.data.objects.new(name, _pose_mesh(name, probes, weights))
    pose[RIG_KEY] = "pose"
    pose[PATCH_WATER_KEY] = water
    pose.display_type = "WIRE"
    pose.hide_render = True
    pose.rotation_euler = (0.0, 0.0, math.pi)  # see `float_fit`: the group's X comes out along X
    collection.objects.link(pose)
    group = pose.vertex_groups.new(name=float_fit.POSE_GROUP)
    group.add([len(probes), len(probes) + 1, len(probes) + 2], 1.0, "REPLACE")
    modifier = pose.modifiers.new(float_fit.NAME, "NODES")
    modifier.node_group = ensure_group(SPECS[float_fit.NAME], SPECS)
    waves.set_wave_input(modifier, "Water", water)
    waves.set_wave_input(modifier, "Anchor", anchor)
    waves.set_wave_input(modifier, "Height", height)
    waves.set_wave_input(modifier, "Radius", reach)
    grid = _even_grid(water)
    if grid is not None and grid[0] >= float_fit.BLOCK:
        side, corner, cell = grid
        waves.set_wave_input(modifier, "Grid Side", side)
        waves.set_wave_input(modifier, "Grid Corner", (*corner, 0.0))
        waves.set_wave_input(modifier, "Grid Cell", cell)
    return pose


def fit_modifier(pose):
    """The pose's `Water Float Fit` modifier, or None (a rig made before it: probes and drivers)."""
    found = pose.modifiers.get(float_fit.NAME) if pose is not None and pose.type == "MESH" else None
    return found if found is not None and found.type == "NODES" else None


def pose_group(pose):
    """The vertex group of `pose` the object's constraints read ("" for an older rig's empty)."""
    return float_fit.POSE_GROUP if fit_modifier(pose) is not None else ""


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
    """The patches a rig made before `Water Float Fit` drops its probes onto."""
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
        data = obj.data if obj.get(RIG_KEY) in ("patch", "pose") and obj.type == "MESH" else None
        bpy.data.objects.remove(obj)
        if data is not None and data.users == 0:
            bpy.data.meshes.remove(data)


def build(obj, water, scene, own_constraints, draft=None, length=None, beam=None):
    """Makes `obj`'s anchor and pose on `water`; returns (pose, settings used).
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
    scale = [s if abs(s) > 1e-9 else 1.0 for s in obj.scale]
    # In the anchor's (the object's) own units: the probes move and turn with it, not tilting.
    probes = [(x / scale[0], y / scale[1], 0.0) for x, y, _w in points]
    pose = _pose(obj, water, anchor, collection, probes, weights, -draft - keel, reach + PATCH_MARGIN)
    return pose, {"draft": draft, "length": length, "beam": beam}


def probes_of(pose):
    """The probes the pose's drivers read, on a rig made before `Water Float Fit` ([] on one
    made since: its probes are points of its own mesh)."""
    found = []
    animation = pose.animation_data if pose is not None else None
    for curve in animation.drivers if animation else ():
        for variable in curve.driver.variables:
            target = variable.targets[0].id
            if target is not None and target.get(RIG_KEY) == "probe" and target not in found:
                found.append(target)
    return found


def anchor_of(pose):
    """The anchor the pose follows (its fit's, or its probes' parent on an older rig), or None."""
    modifier = fit_modifier(pose)
    if modifier is not None:
        anchor = waves.get_wave_input(modifier, "Anchor")
        return anchor if anchor is not None and anchor.get(RIG_KEY) == "anchor" else None
    parents = [probe.parent for probe in probes_of(pose) if probe.parent is not None]
    return parents[0] if parents and parents[0].get(RIG_KEY) == "anchor" else None


def remove(pose):
    """Removes a pose and its anchor (an older rig's probes and patch too), and the rig
    collection once it is empty."""
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
    for anchor in [o for o in bpy.data.objects if o.get(RIG_KEY) == "anchor" and is_local(o)]:
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
