"""Finds and repairs water whose group node lost its group or sockets.

A user may replace the `Water Surface` node's group, or remove a socket from
its interface. The panel and the operators need every socket by name, so such
a water is shown as needing repair, and `repair_water` points the node back to
the add-on's group (rebuilt if it is the broken one), keeping the values of
the sockets still there.
"""

import itertools

import bpy

from ..nodes import SPECS
from ..nodes.builder import VERSION_KEY, ensure_group
from ..nodes.bump_image import ensure_bump_image
from ..nodes.lake import water_surface
from ..nodes.material import (
    WATER_NODE,
    bump_image,
    drive_clock,
    drive_sun,
    drive_sun_inputs,
    drive_time,
    first_sun,
    fit_parts,
    water_group,
    water_node,
)
from ..nodes.ownership import role_of
from ..nodes.sea import ocean_normal, ocean_shade
from ..nodes.sea.ocean_material import NORMAL_NODE, OCEAN_NODE, SKY_NODE, fit_shade_parts, ocean_nodes
from .boats import keep_out
from .editable import NotEditableError, check_editable, why_not_editable
from .errors import WaterError
from .kind import LAKE, OCEAN, shading_of
from .sea import open_sea

# Inputs the material drives: never kept or reset, driven again after a repair.
_DRIVEN = {
    WATER_NODE: ("Time", "Sun Direction", "Sun Color", "Sun Lit"),
    NORMAL_NODE: ("Time",),
    OCEAN_NODE: ("Time", "Sun Direction", "Sun Lit"),
}


class RepairError(WaterError, ValueError):
    """A water that cannot be repaired."""


def _interface(tree):
    """{(in_out, name): socket type} of a group's interface."""
    return {
        (item.in_out, item.name): item.socket_type
        for item in tree.interface.items_tree
        if item.item_type == "SOCKET"
    }


def _missing(tree, spec):
    """Names of the sockets of `spec` that `tree` lacks (or has with another type)."""
    have = _interface(tree)
    wanted = [("OUTPUT", s) for s in spec.outputs] + [("INPUT", s) for s in spec.inputs]
    return [s.name for in_out, s in wanted if have.get((in_out, s.name)) != s.kind]


def _group_problem(node, spec):
    """What is wrong with `node`'s group against `spec`, in words, or None."""
    if node.type != "GROUP":
        return f"node '{node.name}' is not a group node"
    tree = node.node_tree
    if tree is None:
        return f"node '{node.name}' has no group"
    if tree.get(VERSION_KEY) is None:
        return f"node '{node.name}' uses '{tree.name}', not the add-on's group"
    missing = _missing(tree, spec)
    if missing:
        names = ", ".join(f"'{name}'" for name in missing[:3]) + (" ..." if len(missing) > 3 else "")
        return f"group '{tree.name}' lacks {names}"
    return None


def _parts(material):
    """[(node, spec)] of the add-on's group nodes in `material` (by its shading, `kind`), [] for others."""
    shading = shading_of(material)
    if shading == LAKE:
        return [(water_node(material), SPECS[water_surface.NAME])]
    if shading == OCEAN:
        normal, shade = ocean_nodes(material)
        return [(normal, SPECS[ocean_normal.NORMAL_NAME]), (shade, SPECS[ocean_shade.SHADE_NAME])]
    return []


def needs_repair(material):
    """Why `material`'s water group cannot be used as it is (a sentence), or None when it can."""
    for node, spec in _parts(material):
        problem = _group_problem(node, spec)
        if problem is not None:
            return f"Water '{material.name}' needs repair: {problem}"
    return None


def _value(socket):
    value = getattr(socket, "default_value", None)
    if value is None:
        return None
    return tuple(value) if hasattr(value, "__len__") and not isinstance(value, str) else value


def _kept_values(node, driven):
    """{input name: value} of the node's unlinked inputs, the driven ones aside."""
    return {
        socket.name: _value(socket)
        for socket in node.inputs
        if socket.name not in driven and not socket.is_linked and _value(socket) is not None
    }


def _take_drivers(material, node):
    """Removes the drivers on `node`'s inputs; returns the (scene, sun) they followed.

    Driver paths name inputs by index, so after the group changes they point to
    the wrong sockets (or none): they are removed and made again.
    """
    tree = material.node_tree
    animation = tree.animation_data
    scene = sun = None
    if animation is None:
        return scene, sun
    prefix = f'nodes["{bpy.utils.escape_identifier(node.name)}"].inputs['
    for fcurve in list(animation.drivers):
        if not fcurve.data_path.startswith(prefix):
            continue
        for variable in fcurve.driver.variables:
            for target in variable.targets:
                owner = target.id
                if owner is None:
                    continue
                if target.id_type == "SCENE" and scene is None:
                    scene = owner
                elif target.id_type == "OBJECT" and owner.type == "LIGHT" and sun is None:
                    sun = owner
        animation.drivers.remove(fcurve)
    return scene, sun


# The descriptions with every optional part, by the name of the group without any.
_FULL = {water_surface.NAME: water_surface.FULL_SPEC, ocean_shade.SHADE_NAME: ocean_shade.FULL_SHADE_SPEC}


def _variant_parts(node, spec):
    """The optional parts of the variant `node`'s group is (read from its role); () for a group
    that is no variant of ours (a user's, or none)."""
    full = _FULL.get(spec.name)
    tree = getattr(node, "node_tree", None)
    role = role_of(tree) if tree is not None else None
    if full is None or role is None:
        return ()
    names = [part.name for part in full.parts]
    for size in range(len(names) + 1):
        for parts in itertools.combinations(names, size):
            if full.variant(parts).name == role:
                return parts
    return ()


def _target_group(node, spec, image_source):
    """The add-on's group for `node` (the same variant as its own), rebuilt when it is the broken one."""
    parts = _variant_parts(node, spec)

    def build():
        if spec.name == water_surface.NAME:
            return water_group(image_source, parts)
        if spec.name == ocean_shade.SHADE_NAME:
            return ensure_group(ocean_shade.FULL_SHADE_SPEC.variant(parts), SPECS)
        image = ensure_bump_image() if spec.name == ocean_normal.NORMAL_NAME else None
        return ensure_group(spec, SPECS, image=image)

    target = build()
    missing = _missing(target, spec)
    if missing:
        check_editable(target)
        others = _other_users(target, node)
        # Version 0 keeps the add-on's mark: the builder upgrades it in place, interface and nodes.
        target[VERSION_KEY] = 0
        target = build()
        _defaults_on_others(target, others, missing)
    return target


def _other_users(tree, node):
    """[(material, group node name)] of the materials other than `node`'s that use `tree`."""
    return [
        (material, other.name)
        for material in bpy.data.materials
        if material.node_tree is not None
        for other in material.node_tree.nodes
        if other.type == "GROUP" and other.node_tree == tree and other != node
    ]


def _defaults_on_others(tree, others, names):
    """The inputs `names` a shared group got back: their default on every other material using it
    (Blender gives a socket added to a group 0 on the nodes already using it)."""
    defaults = {
        item.name: item.default_value
        for item in tree.interface.items_tree
        if item.item_type == "SOCKET" and item.in_out == "INPUT" and item.name in names
    }
    for material, name in others:
        material.node_tree.update_tag()
    bpy.context.view_layer.update()  # the group nodes take the rebuilt interface
    for material, name in others:
        other = material.node_tree.nodes.get(name)
        for socket_name, value in defaults.items():
            socket = other.inputs.get(socket_name) if other is not None else None
            if socket is not None and not socket.is_linked:
                socket.default_value = value


def _restore(node, kept, driven):
    """Writes the kept values back by name; inputs without one go back to their default.

    Returns (names kept, names reset).
    """
    defaults = {
        item.name: item.default_value
        for item in node.node_tree.interface.items_tree
        if item.item_type == "SOCKET" and item.in_out == "INPUT" and hasattr(item, "default_value")
    }
    restored, reset = [], []
    for socket in node.inputs:
        if socket.name in driven or socket.is_linked or not hasattr(socket, "default_value"):
            continue
        if socket.name in kept:
            try:
                socket.default_value = kept[socket.name]
                restored.append(socket.name)
                continue
            except (TypeError, ValueError):
                pass
        if socket.name in defaults:
            socket.default_value = defaults[socket.name]
            reset.append(socket.name)
    return restored, reset


def _link(tree, output, socket):
    """Links `output` to `socket` when `socket` is free or fed by another socket of `output`'s node.

    A socket fed by another node stays as the user linked it.
    """
    sources = [link.from_socket for link in socket.links]
    if sources == [output] or any(source.node != output.node for source in sources):
        return
    tree.links.new(output, socket)


def repair_water(material, scene=None):
    """Points `material`'s water group node(s) back to the add-on's group; returns what it did, in words.

    Values of the inputs still there are kept by name; missing ones take their defaults.
    Raises NotEditableError for library data and RepairError when there is nothing to repair.
    """
    parts = _parts(material)
    if not parts:
        raise RepairError(f"'{getattr(material, 'name', material)}' is not a water material")
    check_editable(material)
    if needs_repair(material) is None:
        return f"'{material.name}' needed no repair"
    tree = material.node_tree
    done, all_reset, followed_scene = [], [], None
    for node, spec in parts:
        if node.type != "GROUP":
            raise RepairError(
                f"node '{node.name}' of '{material.name}' is not a group node: add the water again"
            )
        driven = _DRIVEN.get(node.name, ())
        kept = _kept_values(node, driven)
        image = bump_image(material) if spec.name == water_surface.NAME else None
        found_scene, sun = _take_drivers(material, node)
        followed_scene = followed_scene or found_scene
        group = _target_group(node, spec, image)
        why = why_not_editable(group) if _missing(group, spec) else None
        if why is not None:
            raise NotEditableError(why)
        node.node_tree = group
        restored, reset = _restore(node, kept, driven)
        if spec.name == water_surface.NAME:
            fit_parts(material)  # the variant with the parts the kept values turn on
        elif spec.name == ocean_shade.SHADE_NAME:
            fit_shade_parts(material)  # the traced sky back when it was on
        all_reset += reset
        done.append(f"'{node.name}' uses '{node.node_tree.name}' ({len(restored)} values kept)")
        clock_scene = followed_scene or scene or bpy.context.scene
        if spec.name == water_surface.NAME:
            drive_time(material, clock_scene)
            drive_sun(material, sun)
            target = keep_out.water_shader_input(material)  # through the hulls' keep-out, if any
            if target is not None:
                _link(tree, node.outputs["Shader"], target)
        elif spec.name == ocean_normal.NORMAL_NAME:
            drive_clock(node.inputs["Time"], clock_scene)
        else:  # the ocean shade: the surroundings' foam and caustics follow the clock and the sun
            drive_clock(node.inputs["Time"], clock_scene)
            drive_sun_inputs(node, sun if sun is not None else first_sun(clock_scene))
    # An open sea's bump follows its Ocean modifier's wind (drivers by input index, so made again).
    for obj in bpy.data.objects:
        found = open_sea.sea_modifiers(obj)
        if found is not None and any(slot.material == material for slot in obj.material_slots):
            open_sea.drive_slopes(obj, found[0])
    nodes = ocean_nodes(material)
    if nodes is not None:
        normal, shade = nodes
        _link(tree, normal.outputs["Normal"], shade.inputs["Normal"])
        sky = tree.nodes.get(SKY_NODE)
        if sky is not None:
            _link(tree, sky.outputs[0], shade.inputs["Sky"])
            if sky.type == "TEX_ENVIRONMENT":
                _link(tree, normal.outputs["Reflection"], sky.inputs["Vector"])
        target = keep_out.water_shader_input(material)
        if target is not None:
            _link(tree, shade.outputs["Shader"], target)
    message = f"Repaired '{material.name}': " + "; ".join(done)
    if all_reset:
        message += "; back to default: " + ", ".join(all_reset)
    return message
