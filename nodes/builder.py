"""Turns a `GroupSpec` into a node tree: found by the add-on's mark, versioned, laid out in columns.

* Only groups the add-on made are reused (`ownership`): a user's group with the
  same name is never touched, ours is made beside it under another name. Groups
  that sample an image are found by the image they sample, not by their name.
* A group whose stamped version equals the spec's is reused as it is.
* An older one is upgraded in place: its interface is brought in line socket by
  socket (so materials keep their links and values) and its nodes rebuilt.
* A newer one (saved by a newer add-on) is left alone, so the file keeps working.
* A group half-built when building fails is removed, and the error names it.
* Image slots: `BUMP_IMAGE` nodes get the image asked for (and the group is found by it);
  `FOAM_IMAGE`, `CAUSTICS_IMAGE` and `ROUGH_FRESNEL_IMAGE` nodes get the add-on's own tiles,
  never part of how a group is found. A reused group whose image of any kind was deleted is
  given the one asked for.
"""

import bpy

from .caustics_image import ensure_caustics_image
from .foam_image import ensure_foam_image
from .ownership import VERSION_KEY, mark, owned
from .sea.rough_fresnel_image import ensure_rough_fresnel_image
from .spec import BUMP_IMAGE, CAUSTICS_IMAGE, FOAM_IMAGE, ROUGH_FRESNEL_IMAGE

# The add-on's own generated tiles: a slot for one is filled with it, made when needed.
OWN_TILES = {
    FOAM_IMAGE: ensure_foam_image,
    CAUSTICS_IMAGE: ensure_caustics_image,
    ROUGH_FRESNEL_IMAGE: ensure_rough_fresnel_image,
}

COLUMN_WIDTH = 240
ROW_GAP = 40
SOCKET_HEIGHT = 22
HEADER_HEIGHT = 60


class NodeGroupError(RuntimeError):
    """A node group could not be built or reused."""


def ensure_group(spec, specs, name=None, image=None, foam=None):
    """The node tree for `spec`, built or upgraded if needed.

    `specs` maps the names of nested groups to their specs (a spec's own `includes` come
    first); `image` fills the spec's `BUMP_IMAGE` slots and `foam` its `FOAM_IMAGE` slots (default:
    the add-on's packed foam tile, made when needed); `name` (default: the spec's) names a new tree.
    """
    lookup = {**specs, **{included.name: included for included in spec.includes}}
    tiles = {placeholder: foam if placeholder == FOAM_IMAGE else None for placeholder in OWN_TILES}
    for placeholder, make in OWN_TILES.items():
        if tiles[placeholder] is None and spec.slots(placeholder):
            tiles[placeholder] = make()
    nested = {group: ensure_group(lookup[group], lookup, foam=foam) for group in spec.nested_groups()}
    tree = find_group(spec, image)
    images = {BUMP_IMAGE: image, **tiles}
    if tree is not None and tree.get(VERSION_KEY, 0) >= spec.version:
        _adopt_images(tree, spec, images)
        return tree
    created = tree is None
    if created:
        tree = bpy.data.node_groups.new(name or spec.name, spec.tree_type)
    if spec.tree_type == "GeometryNodeTree":  # geometry in and out: a modifier, in the Add Modifier menu
        tree.is_modifier = all(
            any(socket.kind == "NodeSocketGeometry" for socket in sockets)
            for sockets in (spec.inputs, spec.outputs)
        )
    try:
        _sync_interface(tree, spec)
        _rebuild_nodes(tree, spec, images, nested)
    except Exception as error:
        tree_name = tree.name
        if created:
            bpy.data.node_groups.remove(tree)
        raise NodeGroupError(f"building node group '{tree_name}' failed: {error}") from error
    mark(tree, spec.name, spec.version)
    tree.description = spec.description
    return tree


def _slot_nodes(tree, spec, placeholder):
    """The image nodes of `tree` that fill `spec`'s `placeholder` slots (found by their keys)."""
    keys = set(spec.slots(placeholder))
    return [node for node in tree.nodes if node.type == "TEX_IMAGE" and node.name in keys]


def _images(tree, spec):
    """The images in `tree`'s bump slots (all its image nodes when none has a slot's key)."""
    nodes = _slot_nodes(tree, spec, BUMP_IMAGE) or [n for n in tree.nodes if n.type == "TEX_IMAGE"]
    return {node.image for node in nodes}


def find_group(spec, image=None):
    """The add-on's own local group for `spec` (sampling `image`, when the spec samples one), or None.

    Only the bump slots count: the foam tile is the add-on's own in every group. A group whose
    bump image was deleted is taken for any image (it is given the new one).
    """
    candidates = [t for t in owned(bpy.data.node_groups, spec.name) if t.bl_idname == spec.tree_type]
    if not spec.slots(BUMP_IMAGE):
        return candidates[0] if candidates else None
    exact = [t for t in candidates if _images(t, spec) == {image}]
    lost = [t for t in candidates if _images(t, spec) == {None}]
    return (exact or lost or [None])[0]


def _adopt_images(tree, spec, images):
    """Gives a reused group whose image (bump or a tile) was deleted the one it is asked for."""
    for placeholder, image in images.items():
        nodes = _slot_nodes(tree, spec, placeholder)
        if placeholder == BUMP_IMAGE and not nodes:
            nodes = [n for n in tree.nodes if n.type == "TEX_IMAGE"]
        if image is not None and nodes and {node.image for node in nodes} == {None}:
            for node in nodes:
                node.image = image


def _interface_sockets(tree):
    return [item for item in tree.interface.items_tree if item.item_type == "SOCKET"]


def _sync_interface(tree, spec):
    """Makes the interface match the spec, keeping sockets that already match by name and type."""
    wanted = [("OUTPUT", s) for s in spec.outputs] + [("INPUT", s) for s in spec.inputs]
    keep = set()
    for position, (in_out, socket) in enumerate(wanted):
        item = next(
            (
                i
                for i in _interface_sockets(tree)
                if i.in_out == in_out and i.name == socket.name and i.socket_type == socket.kind
            ),
            None,
        )
        if item is None:
            item = tree.interface.new_socket(socket.name, in_out=in_out, socket_type=socket.kind)
        tree.interface.move(item, position)
        _set_socket(item, socket)
        keep.add((in_out, socket.name))
    for item in _interface_sockets(tree):
        if (item.in_out, item.name) not in keep:
            tree.interface.remove(item)


def _set_socket(item, socket):
    item.description = socket.tooltip
    if socket.subtype is not None:
        item.subtype = socket.subtype
    if socket.default is not None:
        item.default_value = socket.default
    if socket.min is not None:
        item.min_value = socket.min
    if socket.max is not None:
        item.max_value = socket.max
    item.hide_value = socket.hide_value


def _rebuild_nodes(tree, spec, images, nested):
    tree.nodes.clear()
    nodes = {
        "input": tree.nodes.new("NodeGroupInput"),
        "output": tree.nodes.new("NodeGroupOutput"),
    }
    nodes["input"].location = (0, 0)
    skipped = set()
    for key, description in spec.nodes.items():
        if _built_here(description):
            nodes[key] = _new_node(tree, key, description, images, nested)
        else:
            skipped.add(key)
    for key, description in spec.nodes.items():  # zones: the input takes its output's items
        if description.pair and key in nodes:
            nodes[key].pair_with_output(nodes[description.pair])
            _set_values(nodes[key], description.values)  # its sockets came with the pairing
    for source, target in spec.links:
        if {source.partition(":")[0], target.partition(":")[0]} & skipped:
            continue
        tree.links.new(_socket(nodes, source, "outputs"), _socket(nodes, target, "inputs"))
    _layout(tree, nodes, spec)


def _built_here(description):
    """Whether this Blender builds the node (its `since` / `before` version gates)."""
    version = bpy.app.version
    return (description.since is None or version >= description.since) and (
        description.before is None or version < description.before
    )


def _new_node(tree, key, description, images, nested):
    node = tree.nodes.new(description.type)
    node.name = key
    node.label = description.label
    if description.group:
        node.node_tree = nested[description.group]
    for prop, value in description.props.items():
        setattr(node, prop, images[value] if isinstance(value, str) and value in images else value)
    if description.items:
        node.state_items.clear()
        for socket_type, name in description.items:
            node.state_items.new(socket_type, name)
    if not description.pair:
        _set_values(node, description.values)
    return node


def _set_values(node, values):
    """The node's unlinked input values (a colour given as RGB gets alpha 1)."""
    for socket_key, value in values.items():
        socket = node.inputs[socket_key]
        if hasattr(socket.default_value, "__len__") and len(socket.default_value) == 4 and len(value) == 3:
            value = (*value, 1.0)
        socket.default_value = value


def _socket(nodes, address, side):
    """Resolves "node:Name" or "node:#index" among the enabled sockets on one side of a node."""
    key, _, name = address.partition(":")
    if key not in nodes:
        raise NodeGroupError(f"link names unknown node '{key}'")
    sockets = [s for s in getattr(nodes[key], side) if s.enabled]
    if name.startswith("#"):
        return sockets[int(name[1:])]
    for socket in sockets:
        if socket.name == name or socket.identifier == name:
            return socket
    raise NodeGroupError(f"node '{key}' has no {side[:-1]} '{name}'")


def _layout(tree, nodes, spec):
    """Places nodes in their spec columns, top to bottom in spec order, so the flow reads left to right."""
    columns = {}
    for key, description in spec.nodes.items():
        if key in nodes:
            columns.setdefault(description.column, []).append(nodes[key])
    last = max(columns, default=0) + 1
    for column, members in columns.items():
        y = 0
        for node in members:
            node.location = (column * COLUMN_WIDTH, y)
            visible = sum(s.enabled for s in node.inputs) + sum(s.enabled for s in node.outputs)
            y -= HEADER_HEIGHT + SOCKET_HEIGHT * visible + ROW_GAP
    nodes["output"].location = (last * COLUMN_WIDTH, 0)
