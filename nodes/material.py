"""The water material: the `Water Surface` group, its bump image, the clock and the sun.

What animates goes through simple-expression drivers (no Python runs), so a
saved file renders with auto-run scripts off and without the add-on.
"""

import re

import bpy

from . import SPECS, surface_parts
from .builder import ensure_group
from .bump_image import ensure_bump_image
from .foam_image import ensure_foam_image
from .lake import water_surface
from .ownership import VERSION_KEY, is_local, is_original, mark, role_of

WATER_NODE = "Water Surface"
TIME_EXPRESSION = "frame / (fps / fps_base)"


def water_group(image=None, parts=()):
    """The `Water Surface` group sampling `image` (default: the add-on's bump image), with the
    optional parts named in `parts` (`water_surface.PARTS`: "depth", "foam", "caustics") built in.

    A shader group cannot take an image as an input, so a material with its own
    normal map uses a group of its own, named "Water Surface (<image>)", built
    from the same description and reused for every material with that image.
    It is found by the image it samples, so renaming the image changes nothing.
    Each set of parts is a variant of its own, "Water Surface + Foam + Caustics", with the same
    inputs in the same order: a material changes variant without losing a value or a driver.
    The foam tile (`foam_image.py`) is the add-on's own in every such group: it is sampled
    in the nested `Water Surface Foam Coverage` group, made again when lost.
    """
    retire_legacy_groups()
    spec = water_surface.spec_with(parts)
    default = ensure_bump_image()
    foam = ensure_foam_image() if "foam" in parts else None
    if image is None or image == default:
        return ensure_group(spec, SPECS, image=default, foam=foam)
    if image.colorspace_settings.name != "Non-Color" and is_local(image):
        image.colorspace_settings.name = "Non-Color"
    return ensure_group(spec, SPECS, name=f"{spec.name} ({image.name})", image=image, foam=foam)


def retire_legacy_groups():
    """Gives the `Water Surface` groups of files saved before the parts were optional (version 4
    and older, built with the parts of their day: a node keyed "depth", "foam" or "caustics") the
    role and name of the variant with every part, so the lean group takes their old name and their
    materials render as they did (the builder upgrades them in place when that variant is asked for)."""
    full = water_surface.spec_with(water_surface.ALL_PARTS).name
    for tree in bpy.data.node_groups:
        version = tree.get(VERSION_KEY)
        if role_of(tree) != water_surface.NAME or not isinstance(version, int) or version >= 5:
            continue
        # Only a group built with parts: repair stamps a broken lean group 0 to rebuild it.
        if not is_original(tree) or not any(part.name in tree.nodes for part in water_surface.PARTS):
            continue
        # "Water Surface (image).001" becomes "<full> (image)": the image's part of the name stays.
        rest = tree.name[len(water_surface.NAME) :] if tree.name.startswith(water_surface.NAME) else ""
        rest = re.sub(r"\.\d{3,}$", "", rest)
        tree.name = full + (rest if rest.startswith(" (") else "")
        mark(tree, full, version)


def parts_built(tree, spec=water_surface.FULL_SPEC):
    """The optional parts of `spec` (default: the lake's) built into `tree`."""
    if tree is None:
        return frozenset()
    return frozenset(part.name for part in spec.parts if spec.part_nodes(part.name)[0] in tree.nodes)


def parts_wanted(material, node=None, spec=water_surface.FULL_SPEC):
    """The optional parts of `spec` (default: the lake's) that the values of `node` (default:
    `material`'s lake node) turn on: a switch above 0, or one whose value may change (linked,
    animated or driven), is on."""
    node = node or water_node(material)
    moving = _moving_inputs(material, node)
    wanted = set()
    for part in spec.parts:
        socket = node.inputs.get(part.switch)
        if socket is None or not hasattr(socket, "default_value"):
            continue
        value = socket.default_value
        channels = tuple(value)[:3] if hasattr(value, "__len__") else (value,)
        if socket.is_linked or part.switch in moving or max(channels) > 0.0:
            wanted.add(part.name)
    return frozenset(wanted)


def _moving_inputs(material, node):
    """Names of `node`'s inputs that a driver or an animation changes."""
    animation = material.node_tree.animation_data
    if animation is None:
        return set()
    prefix = f'nodes["{bpy.utils.escape_identifier(node.name)}"].inputs['
    names = set()
    for fcurve in (*animation.drivers, *_action_fcurves(animation.action)):
        path = fcurve.data_path
        if path.startswith(prefix) and path.endswith("].default_value"):
            index = path[len(prefix) : -len("].default_value")]
            if index.isdigit() and int(index) < len(node.inputs):
                names.add(node.inputs[int(index)].name)
            elif index.startswith('"'):
                names.add(index.strip('"'))
    return names


def _action_fcurves(action):
    """The F-curves of an action: in its layers' channel bags (slotted actions, 4.4 and later),
    else in the action itself."""
    if action is None:
        return []
    layers = getattr(action, "layers", None)
    if layers:
        return [
            fcurve
            for layer in layers
            for strip in layer.strips
            for bag in strip.channelbags
            for fcurve in bag.fcurves
        ]
    return list(getattr(action, "fcurves", ()))


def fit_node_parts(material, node, spec, build):
    """Points `node` (a group node of `material`) at the variant of `spec` with the parts its
    values turn on (`parts_wanted`), made by `build(parts)`, keeping every value; returns whether
    it changed. A group that is not the add-on's own, lacks inputs (needs repair) or is library
    data is left as it is; the group left behind is removed when nothing uses it any more."""
    if node is None or node.node_tree is None or not is_local(material):
        return False
    tree = node.node_tree
    if role_of(tree) is None or not is_original(tree):
        return False
    if [socket.name for socket in node.inputs] != [socket.name for socket in spec.inputs]:
        return False
    wanted = parts_wanted(material, node, spec)
    if parts_built(tree, spec) == wanted:
        return False
    kept = {s.name: _copy(s.default_value) for s in node.inputs if hasattr(s, "default_value")}
    node.node_tree = build(wanted)
    for socket in node.inputs:
        if socket.name in kept:
            socket.default_value = kept[socket.name]
    if tree.users == 0 and not tree.use_fake_user:
        bpy.data.node_groups.remove(tree)  # ours, and no material uses it any more
    return True


def fit_parts(material):
    """`fit_node_parts` for `material`'s lake group: the parts its values turn on built in, those
    at 0 taken out."""
    return fit_node_parts(
        material,
        water_node(material),
        water_surface.FULL_SPEC,
        lambda parts: water_group(bump_image(material), parts),
    )


def _copy(value):
    return tuple(value) if hasattr(value, "__len__") and not isinstance(value, str) else value


def make_water_material(name="Water", scene=None, image=None, sun=None):
    """A new water material, no optional part built in (`set_values` adds them as its values
    ask). `image` is a tangent-space normal map (default: the packed water bump); `sun` a sun light
    object for the glint (default: the scene's first sun)."""
    scene = scene or bpy.context.scene
    group = water_group(image)
    material = new_node_material(name)
    tree = material.node_tree
    water = tree.nodes.new("ShaderNodeGroup")
    water.node_tree, water.name, water.location, water.width = group, WATER_NODE, (-150, 0), 220
    output = tree.nodes.new("ShaderNodeOutputMaterial")
    output.location = (150, 0)
    tree.links.new(water.outputs["Shader"], output.inputs["Surface"])
    trace_refraction(material, output)
    drive_time(material, scene)
    drive_sun(material, sun if sun is not None else first_sun(scene))
    return material


def trace_refraction(material, output):
    """What EEVEE needs to trace refraction through the water's one surface."""
    zero = material.node_tree.nodes.new("ShaderNodeValue")
    zero.name, zero.label = "Thickness", "Thickness 0 (one interface)"
    zero.location = (output.location[0] - 300, output.location[1] - 420)
    zero.outputs[0].default_value = 0.0
    # Thickness 0: EEVEE models one interface and mixes the closures linearly;
    # left unconnected, the object gets a thickness and the refraction's weight is squared.
    material.node_tree.links.new(zero.outputs[0], output.inputs["Thickness"])
    material.surface_render_method = "DITHERED"
    material.use_raytrace_refraction = True
    material.thickness_mode = "SLAB"
    material.use_backface_culling = False


def new_node_material(name):
    """A new material with an empty node tree (Blender 4.x needs `use_nodes` switched on)."""
    material = bpy.data.materials.new(name)
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    material.node_tree.nodes.clear()
    return material


def water_node(material):
    """The material's `Water Surface` group node, or None."""
    if material is None or material.node_tree is None:
        return None
    node = material.node_tree.nodes.get(WATER_NODE)
    return node if node is not None and node.type == "GROUP" else None


def bump_image(material):
    """The normal map the material's water group samples."""
    node = water_node(material)
    bump = node.node_tree.nodes.get("bump") if node is not None and node.node_tree is not None else None
    return bump.image if bump is not None else None


def foam_image(material):
    """The foam tile the material's water group samples (in its nested foam group), or None."""
    node = water_node(material)
    foam = node.node_tree.nodes.get("foam") if node is not None and node.node_tree is not None else None
    tile = foam.node_tree.nodes.get("tile") if foam is not None and foam.node_tree is not None else None
    return tile.image if tile is not None else None


def set_bump_image(material, image):
    """Makes the material sample `image` (None: the default bump); its values and parts stay as
    they were."""
    node = water_node(material)
    node.node_tree = water_group(image, parts_built(node.node_tree))


def drive_socket(socket, index, expression, variables):
    """A simple-expression driver on `socket.default_value[index]`.

    `variables` are (name, id_type, id, path) of single-property variables.
    """
    return drive_property(socket, "default_value", index, expression, variables)


def drive_property(owner, prop, index, expression, variables):
    """A simple-expression driver on `owner.prop[index]` (`index` None: the whole property)."""
    args = (prop,) if index is None else (prop, index)
    owner.driver_remove(*args)
    driver = owner.driver_add(*args).driver
    driver.type = "SCRIPTED"
    for var_name, id_type, target_id, path in variables:
        var = driver.variables.new()
        var.name, var.type = var_name, "SINGLE_PROP"
        var.targets[0].id_type = id_type
        var.targets[0].id = target_id
        var.targets[0].data_path = path
    driver.expression = expression
    return driver


def drive_clock(socket, scene, prop="default_value"):
    """`socket.prop` (a socket's value, or any float property) = seconds on `scene`'s clock:
    frame / (fps / fps_base)."""
    drive_property(
        socket,
        prop,
        None,
        TIME_EXPRESSION,
        [("fps", "SCENE", scene, "render.fps"), ("fps_base", "SCENE", scene, "render.fps_base")],
    )


def drive_time(material, scene):
    """The water group's `Time` follows `scene`'s clock."""
    drive_clock(water_node(material).inputs["Time"], scene)


def first_sun(scene):
    """The first sun light in `scene`, or None."""
    return next((o for o in scene.objects if o.type == "LIGHT" and o.data.type == "SUN"), None)


def glint_sun(material):
    """The sun object the glint follows, or None."""
    path = water_node(material).inputs["Sun Direction"].path_from_id("default_value")
    animation = material.node_tree.animation_data
    for fcurve in animation.drivers if animation else ():
        if fcurve.data_path == path:
            return fcurve.driver.variables[0].targets[0].id
    return None


def drive_sun(material, sun):
    """`Sun Direction` follows `sun`'s -Z axis (the way its light travels), `Sun Color` its colour,
    `Sun Lit` whether it renders (caustics need it).

    With `sun` None they are the reference's default light, white, and `Sun Lit` is 0.
    """
    drive_sun_inputs(water_node(material), sun)


def drive_sun_inputs(node, sun):
    """`drive_sun` on a group node: the lake's, or the ocean shading's (which has no Sun Color)."""
    direction, color = node.inputs["Sun Direction"], node.inputs.get("Sun Color")
    lit = node.inputs.get("Sun Lit")  # caustics need a sun; absent from groups before version 4
    for i in range(3):
        direction.driver_remove("default_value", i)
        if color is not None:
            color.driver_remove("default_value", i)
    if lit is not None:
        lit.driver_remove("default_value")
    if sun is None:
        direction.default_value = surface_parts.DEFAULT_SUN
        if color is not None:
            color.default_value = (1.0, 1.0, 1.0, 1.0)
        if lit is not None:
            lit.default_value = 0.0
        return
    if lit is not None:
        drive_socket(lit, None, "1 - h", [("h", "OBJECT", sun, "hide_render")])
    for i in range(3):
        # RNA stores matrices by column: matrix_world[2] is the local Z axis in world space.
        drive_socket(direction, i, "-z", [("z", "OBJECT", sun, f"matrix_world[2][{i}]")])
        if color is not None:
            drive_socket(color, i, "c", [("c", "OBJECT", sun, f"data.color[{i}]")])
