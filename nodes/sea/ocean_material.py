"""The ocean material: wave normal and bump, the sky looked up in the reflected
direction, and the ocean colour (groups in `ocean_normal.py` and `ocean_shade.py`), with the open sea's
whitecaps where the mesh carries them.

The sky is reflected by the renderer itself: the shade's "+ Traced Sky" variant adds a sharp
Glossy closure at the sky's weight, so every wave shows whatever world the scene has now (an
HDRI, a swapped image, Sky Texture, a gradient, an edited colour, another world), in EEVEE and
Cycles, with nothing to press: a copy of the world made when the material is could not follow
it (issue 38). The seeds' own look-up stays beside it for `Traced Sky` 0: the Sky node, the
world's environment image when it has one (an Environment Texture node in the material, as the
seeds sample their sky cube) or its one colour (followed by simple-expression drivers), as the
world was when the material was made. The shade's clock and sun (for the surroundings' foam and
caustics) are drivers too, as the lake's.
"""

import itertools

import bpy

from .. import SPECS
from ..builder import ensure_group
from ..bump_image import ensure_bump_image
from ..material import (
    drive_clock,
    drive_socket,
    drive_sun_inputs,
    first_sun,
    fit_node_parts,
    new_node_material,
    trace_refraction,
)
from ..ownership import VERSION_KEY, is_original, mark, role_of
from . import ocean_normal, ocean_parts, ocean_shade, sea_fade

OCEAN_NODE = "Water Ocean"
NORMAL_NODE = "Water Ocean Normal"
SKY_NODE = "Sky"
FOAM_NODE = "Whitecaps"
DEFAULT_SKY = (0.5, 0.7, 1.0)


def _world_environment(world):
    """The world's Environment Texture node that has an image, or None."""
    if world is None or world.node_tree is None:
        return None
    return next(
        (n for n in world.node_tree.nodes if n.type == "TEX_ENVIRONMENT" and n.image is not None),
        None,
    )


def _sky_node(tree, world):
    """A node giving the sky's colour: the world's image, or its background colour."""
    environment = _world_environment(world)
    if environment is not None:
        node = tree.nodes.new("ShaderNodeTexEnvironment")
        node.image, node.projection = environment.image, environment.projection
        node.interpolation = environment.interpolation
        return node, node.inputs["Vector"]
    node = tree.nodes.new("ShaderNodeRGB")
    background = None
    if world is not None and world.node_tree is not None:
        background = next((n for n in world.node_tree.nodes if n.type == "BACKGROUND"), None)
    if background is None:
        node.outputs[0].default_value = (*(world.color if world else DEFAULT_SKY), 1.0)
        return node, None
    colour = background.inputs["Color"]
    node.outputs[0].default_value = tuple(colour.default_value)
    path = f'node_tree.nodes["{background.name}"].inputs[0].default_value'
    for i in range(3):
        drive_socket(node.outputs[0], i, "c", [("c", "WORLD", world, f"{path}[{i}]")])
    return node, None


# Shade groups saved before the caustics were an optional part (version 5 and older) have them
# built in.
CAUSTICS_OPTIONAL_SINCE = 6


def _variant_of(role):
    """The parts of the shade variant named `role`, or None for no variant of ours."""
    names = [part.name for part in ocean_shade.FULL_SHADE_SPEC.parts]
    for size in range(len(names) + 1):
        for parts in itertools.combinations(names, size):
            if ocean_shade.FULL_SHADE_SPEC.variant(parts).name == role:
                return set(parts)
    return None


def retire_legacy_shades():
    """Gives the `Water Ocean Shade` groups of files saved before the caustics were optional
    (built with them: a node keyed "caustics") the role and name of the variant with the
    caustics, so their materials render as they did and the lean variant takes their old name
    (the builder upgrades them in place when that variant is asked for)."""
    for tree in bpy.data.node_groups:
        version = tree.get(VERSION_KEY)
        if not isinstance(version, int) or version >= CAUSTICS_OPTIONAL_SINCE or not is_original(tree):
            continue
        parts = _variant_of(role_of(tree))
        if parts is None or "caustics" in parts or "caustics" not in tree.nodes:
            continue
        role = ocean_shade.FULL_SHADE_SPEC.variant(parts | {"caustics"}).name
        tree.name = role
        mark(tree, role, version)


def make_ocean_material(name="Ocean", scene=None):
    """A new ocean material for a mesh with the `Water Waves` modifier (or any flat mesh), no
    caustics built in (`set_values` fits the shade's parts to its values)."""
    scene = scene or bpy.context.scene
    retire_legacy_shades()
    normal_group = ensure_group(SPECS[ocean_normal.NORMAL_NAME], SPECS, image=ensure_bump_image())
    # Whatever the world is, now or later, the renderer reflects it (the traced sky).
    shade_group = ensure_group(ocean_shade.FULL_SHADE_SPEC.variant({"traced_sky"}), SPECS)
    material = new_node_material(name)
    tree = material.node_tree
    normal = tree.nodes.new("ShaderNodeGroup")
    normal.node_tree, normal.name, normal.location, normal.width = normal_group, NORMAL_NODE, (-600, 0), 220
    sky, lookup = _sky_node(tree, scene.world)
    sky.name, sky.label, sky.location = SKY_NODE, "sky in the reflected direction", (-300, -150)
    shade = tree.nodes.new("ShaderNodeGroup")
    shade.node_tree, shade.name, shade.location, shade.width = shade_group, OCEAN_NODE, (0, 0), 220
    shade.inputs[ocean_shade.TRACED_SKY].default_value = 1.0
    output = tree.nodes.new("ShaderNodeOutputMaterial")
    output.location = (300, 0)
    tree.links.new(normal.outputs["Normal"], shade.inputs["Normal"])
    tree.links.new(normal.outputs[ocean_parts.UNRESOLVED_SLOPE], shade.inputs[ocean_parts.UNRESOLVED_SLOPE])
    if lookup is not None:
        tree.links.new(normal.outputs["Reflection"], lookup)
    tree.links.new(sky.outputs[0], shade.inputs["Sky"])
    tree.links.new(shade.outputs["Shader"], output.inputs["Surface"])
    # The open sea's whitecaps (`sea_fade.py` stores them); 0 on any other mesh.
    foam = tree.nodes.new("ShaderNodeAttribute")
    foam.attribute_type, foam.attribute_name = "GEOMETRY", sea_fade.WHITECAPS_ATTRIBUTE
    foam.name, foam.label, foam.location = FOAM_NODE, "whitecaps (open sea)", (-300, -350)
    tree.links.new(foam.outputs["Fac"], shade.inputs["Foam"])
    trace_refraction(material, output)  # the bed through shallow water, with the surroundings
    drive_clock(normal.inputs["Time"], scene)
    drive_clock(shade.inputs["Time"], scene)
    drive_sun_inputs(shade, first_sun(scene))
    return material


def ocean_nodes(material):
    """(normal group node, shade group node) of an ocean material, or None."""
    if material is None or material.node_tree is None:
        return None
    shade = material.node_tree.nodes.get(OCEAN_NODE)
    normal = material.node_tree.nodes.get(NORMAL_NODE)
    if shade is None or normal is None or shade.type != "GROUP":
        return None
    return normal, shade


def fit_shade_parts(material):
    """`fit_node_parts` for an ocean material's shade: the traced sky built in while its
    `Traced Sky` is above 0, the caustics while `Caustics` is."""
    nodes = ocean_nodes(material)
    if nodes is None:
        return False
    retire_legacy_shades()
    spec = ocean_shade.FULL_SHADE_SPEC
    return fit_node_parts(material, nodes[1], spec, lambda parts: ensure_group(spec.variant(parts), SPECS))
