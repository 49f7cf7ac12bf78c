"""Keep Water Out: no water shows inside a hull, as it moves and rocks, in EEVEE and Cycles.

The water's material does it, not its mesh. Cutting the mesh by the hull would close a loop for
a floating hull (the water's mesh would wait for the hull, which waits for its probes, which
wait for the water's mesh); a material is drawn after every mesh is made. Per hull, the material
holds a Texture Coordinate node whose Object is the hull (the point in the hull's own space, as it
moves: constraints, parents and all, no driver) and a `Water Keep Out (<mask>)` group reading
the hull's dry mask (`dry_mask_math.py`, a packed image). The hulls' groups chain into a Mix
Shader between the water's shader and the Material Output, whose other shader is a Transparent
BSDF: where the water is dry, rays go on as if there were no water (the hull's floor shows, with
no water colour, reflection or refraction). All of it is Blender's own nodes, so the file renders
the same without the add-on.

The mask is the hull's outline where the water can meet it: from its keel up to twice its draft
when it floats, its whole height when not. `keep_water_out` again makes it anew (the panel says
when the hull's shape changed); `let_water_in` takes it out. A hull deleted the ordinary way lives
on out of the scene (the Texture Coordinate node holds it): it is let go of at the next update
and before the file is saved (`remove_lost_hulls`, from `removal.remove_leftovers`).
"""

import bpy
import numpy as np

from ...nodes import SPECS
from ...nodes.boats import keep_out as keep_out_spec
from ...nodes.builder import ensure_group
from ...nodes.ownership import is_local, is_original, mark, role_of
from .. import kind
from ..editable import check_editable
from ..errors import WaterError
from ..values import is_water, water_material
from . import dry_mask_math
from .float_rig import footprint_settings

MIX_NODE = "Water Keep Out"
TRANSPARENT_NODE = "Water Keep Out Transparent"
MASK_ROLE = "Water Dry Mask"
MASK_VERSION = 1
SHAPE_KEY = "water_hull_shape"  # on the mask image: what the hull's shape was when it was made
GEOMETRY_TYPES = {"MESH", "CURVE", "SURFACE", "META", "FONT", "CURVES", "POINTCLOUD", "VOLUME"}


class KeepOutError(WaterError, ValueError):
    """Water cannot be kept out of an object (one line, says why)."""


def _output(tree):
    """The material's active Material Output node, or None."""
    outputs = [node for node in tree.nodes if node.type == "OUTPUT_MATERIAL"]
    return next((node for node in outputs if node.is_active_output), outputs[0] if outputs else None)


def hull_nodes(material):
    """[(group node, Texture Coordinate node or None, hull or None)] of `material`'s kept-out
    hulls, in the order they chain."""
    if material is None or material.node_tree is None:
        return []
    found = []
    for node in material.node_tree.nodes:
        if node.type != "GROUP" or node.node_tree is None or role_of(node.node_tree) != keep_out_spec.NAME:
            continue
        position = node.inputs.get("Position")
        coords = position.links[0].from_node if position is not None and position.is_linked else None
        hull = coords.object if coords is not None and coords.type == "TEX_COORD" else None
        found.append((node, coords, hull))
    return sorted(found, key=lambda entry: entry[0].name)


def hulls_of(water):
    """The objects the water `water` is kept out of."""
    return [hull for _group, _coords, hull in hull_nodes(water_material(water)) if hull is not None]


def kept_out_of(obj, scene=None):
    """The waters (in `scene`, default: every scene) kept out of `obj`."""
    objects = scene.objects if scene is not None else bpy.data.objects
    return [water for water in objects if is_water(water) and obj in hulls_of(water)]


# Mix Shaders the add-on puts between the water's shader and the output, outermost first: the
# hulls' keep-out, then the wakes' foam (`wake.py`). Each takes the water's side as Shader 1.
WRAPPERS = (MIX_NODE, "Water Wake Foam")


def water_shader_input(material):
    """The socket the water's own shader feeds: through the add-on's mixes (`WRAPPERS`) to the
    innermost one's Shader 1, else the Material Output's Surface (repair links the water's shader
    there)."""
    output = _output(material.node_tree)
    socket = output.inputs["Surface"] if output is not None else None
    while socket is not None and socket.is_linked:
        feeding = socket.links[0].from_node
        if feeding.type != "MIX_SHADER" or feeding.name not in WRAPPERS:
            break
        socket = feeding.inputs[1]
    return socket


def _evaluated_triangles(obj, depsgraph):
    """(triangles (T, 3, 3) in `obj`'s own space, vertex count) of its evaluated geometry."""
    evaluated = obj.evaluated_get(depsgraph)
    try:
        mesh = evaluated.to_mesh()
    except RuntimeError:
        mesh = None
    if mesh is None:
        return np.zeros((0, 3, 3)), 0
    try:
        mesh.calc_loop_triangles()
        points = np.empty(len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", points)
        corners = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int64)
        mesh.loop_triangles.foreach_get("vertices", corners)
        return points.reshape(-1, 3)[corners].reshape(-1, 3, 3), len(mesh.vertices)
    finally:
        evaluated.to_mesh_clear()


def _band(obj, low, high):
    """The heights (in `obj`'s own space) where water can meet it: keel to twice the draft when it
    floats by its footprint, else all of it."""
    draft = footprint_settings(obj).get("draft")
    scale = abs(obj.matrix_world.to_scale().z) or 1.0
    if draft is None or draft <= 0.0:
        return low, high
    return low, min(high, low + 2.0 * draft / scale)


def _shape_of(triangles, count, band):
    """What the mask was made from, to tell later whether the hull changed shape."""
    points = triangles.reshape(-1, 3)
    return [float(count), *points.min(axis=0).round(4), *points.max(axis=0).round(4), *np.round(band, 4)]


def _new_mask_image(obj, mask):
    """A packed Non-Color image of `mask` (rows from the hull's -y side up), marked as ours."""
    rows, columns = mask.shape
    image = bpy.data.images.new(f"Water Dry {obj.name}", columns, rows, alpha=False, float_buffer=False)
    image.colorspace_settings.name = "Non-Color"
    rgba = np.ones((rows * columns, 4), dtype=np.float32)
    rgba[:, :3] = mask.reshape(-1, 1)
    image.pixels.foreach_set(rgba.ravel())
    image.update()
    image.pack()  # in the .blend: renders need neither the add-on nor a file beside it
    mark(image, MASK_ROLE, MASK_VERSION)
    return image


def _mask_of(group_node):
    node = group_node.node_tree.nodes.get("mask") if group_node.node_tree is not None else None
    return node.image if node is not None else None


def mask_out_of_date(obj, water, depsgraph=None):
    """Why the water's mask of `obj` no longer fits it (its shape or draft changed), or None."""
    entry = next((e for e in hull_nodes(water_material(water)) if e[2] == obj), None)
    image = _mask_of(entry[0]) if entry is not None else None
    if image is None:
        return None
    depsgraph = depsgraph or bpy.context.evaluated_depsgraph_get()
    triangles, count = _evaluated_triangles(obj, depsgraph)
    if not len(triangles):
        return f"'{obj.name}' has no surface any more"
    points = triangles.reshape(-1, 3)
    band = _band(obj, float(points[:, 2].min()), float(points[:, 2].max()))
    if list(image.get(SHAPE_KEY, [])) != _shape_of(triangles, count, band):
        return f"'{obj.name}' changed shape or draft since the water was kept out of it"
    return None


def _insert_mix(tree):
    """The Mix Shader between the water's shader and the output (made when missing)."""
    mix = tree.nodes.get(MIX_NODE)
    if mix is not None and mix.type == "MIX_SHADER":
        return mix
    output = _output(tree)
    if output is None or not output.inputs["Surface"].is_linked:
        raise KeepOutError(f"Material '{tree.id_data.name}' has no shader linked to its output")
    source = output.inputs["Surface"].links[0].from_socket
    mix = tree.nodes.new("ShaderNodeMixShader")
    mix.name, mix.label = MIX_NODE, "no water inside hulls"
    mix.location = (output.location.x, output.location.y + 200)
    output.location.x += 200
    transparent = tree.nodes.new("ShaderNodeBsdfTransparent")
    transparent.name, transparent.label = TRANSPARENT_NODE, "as if no water were there"
    transparent.location = (mix.location.x - 200, mix.location.y + 150)
    tree.links.new(source, mix.inputs[1])
    tree.links.new(transparent.outputs[0], mix.inputs[2])
    tree.links.new(mix.outputs[0], output.inputs["Surface"])
    return mix


def _remove_mix(tree):
    mix, transparent = tree.nodes.get(MIX_NODE), tree.nodes.get(TRANSPARENT_NODE)
    if mix is not None and mix.type == "MIX_SHADER":
        source = mix.inputs[1].links[0].from_socket if mix.inputs[1].is_linked else None
        output = _output(tree)
        if source is not None and output is not None:
            tree.links.new(source, output.inputs["Surface"])
        tree.nodes.remove(mix)
    if transparent is not None:
        tree.nodes.remove(transparent)


def _chain(material):
    """Links the hulls' groups one after another into the mix; no hull: no mix."""
    tree = material.node_tree
    entries = hull_nodes(material)
    if not entries:
        _remove_mix(tree)
        return
    mix = _insert_mix(tree)
    before = None
    for group, _coords, _hull in entries:
        for link in list(group.inputs["Dry"].links):
            tree.links.remove(link)
        group.inputs["Dry"].default_value = 0.0
        if before is not None:
            tree.links.new(before.outputs["Dry"], group.inputs["Dry"])
        before = group
    tree.links.new(before.outputs["Dry"], mix.inputs["Fac"])


def keep_water_out(obj, water, depsgraph=None):
    """Makes `water` invisible inside `obj` (a hull: its outline at the heights the water meets
    it), in EEVEE and Cycles, wherever `obj` moves; again: the mask is made anew from its shape
    now. Returns the changes in words."""
    why = kind.refusal(water, "keep_out", subject=f"'{getattr(water, 'name', water)}'")
    if why is not None:
        raise KeepOutError(why)
    if obj is None or obj == water or is_water(obj):
        raise KeepOutError("Water cannot be kept out of water: select the hull and the water")
    if obj.type not in GEOMETRY_TYPES:
        raise KeepOutError(f"'{obj.name}' has no surface to keep the water out of")
    if not set(obj.users_scene) & set(water.users_scene):  # its hole would show where no hull is
        raise KeepOutError(f"'{obj.name}' is not in a scene with '{water.name}': link it to that scene first")
    material = water_material(water)
    check_editable(material)
    depsgraph = depsgraph or bpy.context.evaluated_depsgraph_get()
    triangles, count = _evaluated_triangles(obj, depsgraph)
    if not len(triangles):
        raise KeepOutError(f"'{obj.name}' has no faces to keep the water out of")
    points = triangles.reshape(-1, 3)
    keel, top = float(points[:, 2].min()), float(points[:, 2].max())
    band = _band(obj, keel, top)
    mask, origin, cell = dry_mask_math.dry_mask(triangles, *band)
    if not mask.any():
        raise KeepOutError(f"'{obj.name}' encloses nothing at the waterline: no water to keep out")
    image = _new_mask_image(obj, mask)
    image[SHAPE_KEY] = _shape_of(triangles, count, band)
    tree = material.node_tree
    entry = next((e for e in hull_nodes(material) if e[2] == obj), None)
    if entry is None:
        group = tree.nodes.new("ShaderNodeGroup")
        name = f"{keep_out_spec.NAME} ({image.name})"
        group.node_tree = ensure_group(keep_out_spec.SPEC, SPECS, name=name, image=image)
        coords = tree.nodes.new("ShaderNodeTexCoord")
        coords.object = obj
        coords.label = "in the hull's own space"
        output = _output(tree)
        x, y = (output.location.x, output.location.y) if output is not None else (0.0, 0.0)
        placed = len(hull_nodes(material))
        group.location = (x - 250, y + 450 + 220 * placed)
        coords.location = (x - 500, y + 450 + 220 * placed)
        group.label = f"dry inside '{obj.name}'"
        tree.links.new(coords.outputs["Object"], group.inputs["Position"])
        change = f"kept '{water.name}' out of '{obj.name}'"
    else:
        group = entry[0]
        old = _mask_of(group)
        if old is not None and old != image:
            old_name = old.name
            old.user_remap(image)
            if old.users == 0 and role_of(old) == MASK_ROLE and is_original(old):
                bpy.data.images.remove(old)
            image.name = old_name
            mark(image, MASK_ROLE, MASK_VERSION)
        change = f"made '{water.name}''s dry mask of '{obj.name}' anew"
    rows, columns = mask.shape
    group.inputs["Low Corner"].default_value = (float(origin[0]), float(origin[1]), keel)
    group.inputs["Size"].default_value = (columns * cell, rows * cell, max(top - keel, 1e-6))
    _chain(material)
    return [change]


def _remove_entry(material, group, coords):
    tree = material.node_tree
    tree_group, image = group.node_tree, _mask_of(group)
    tree.nodes.remove(group)
    if coords is not None and not any(socket.is_linked for socket in coords.outputs):
        tree.nodes.remove(coords)
    if tree_group is not None and tree_group.users == 0 and is_original(tree_group):
        bpy.data.node_groups.remove(tree_group)
    if image is not None and image.users == 0 and role_of(image) == MASK_ROLE and is_original(image):
        bpy.data.images.remove(image)


def let_water_in(obj, water=None):
    """Takes the keep-out of `obj` off `water` (None: off every water); returns the changes."""
    changes = []
    for each in [water] if water is not None else kept_out_of(obj):
        material = water_material(each)
        entries = [e for e in hull_nodes(material) if e[2] == obj]
        if not entries:
            continue
        check_editable(material)
        for group, coords, _hull in entries:
            _remove_entry(material, group, coords)
        _chain(material)
        changes.append(f"'{each.name}' shows inside '{obj.name}' again")
    return changes


def remove_lost_hulls():
    """Lets the water in where a hull was deleted (in no scene any more, or gone); returns the
    changes."""
    changes = []
    for material in bpy.data.materials:
        if not is_local(material) or material.node_tree is None:  # never linked or overridden
            continue
        lost = [
            (group, coords, hull)
            for group, coords, hull in hull_nodes(material)
            if hull is None or (not hull.users_scene and not hull.use_fake_user)
        ]
        for group, coords, hull in lost:
            name = hull.name if hull is not None else group.label
            _remove_entry(material, group, coords)
            changes.append(f"'{material.name}' no longer keeps water out of '{name}' (it was deleted)")
        if lost:
            _chain(material)
    return changes
