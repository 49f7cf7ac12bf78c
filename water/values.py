"""The water's values live on its material's group node (the lake's `Water Surface`, the
ocean's `Water Ocean Shade`): one source of truth that the panel shows, presets fill and the
`.blend` keeps."""

from ..nodes.lake.water_surface import FULL_SPEC, PARTS
from ..nodes.material import fit_parts, parts_built, parts_wanted, water_node
from ..nodes.sea.ocean_material import fit_shade_parts, ocean_nodes
from ..nodes.sea.ocean_shade import FULL_SHADE_SPEC
from ..presets import schema
from .errors import KindError, NeedsRepairError
from .kind import LAKE, OCEAN, shading_of, water_material

__all__ = ("is_water", "read_values", "switch_part", "water_material", "write_values")

PART_NAMES = tuple(part.name for part in PARTS)
# The ocean shading's parts a user switches (its traced sky follows the world by itself).
OCEAN_PARTS = tuple(part for part in FULL_SHADE_SPEC.parts if part.name == "caustics")
OCEAN_PART_NAMES = tuple(part.name for part in OCEAN_PARTS)


def is_water(obj):
    return water_material(obj) is not None


def _socket(node, field):
    """The node's input for `field`, or None when its group lacks it (a water needing repair)."""
    if node.node_tree is None:
        return None
    socket = node.inputs.get(field.socket)
    return socket if socket is not None and hasattr(socket, "default_value") else None


def _shader_node(material):
    """The node holding the material's shader values: the lake's `Water Surface` node, or the
    ocean's `Water Ocean Shade` node (the keys it shares with the lake: the bump's scroll,
    absorption, foam, caustics); None for any other material."""
    shading = shading_of(material)
    if shading == LAKE:
        return water_node(material)
    return ocean_nodes(material)[1] if shading == OCEAN else None


def read_values(material):
    """The shader values of a water material, keyed as in presets (an ocean's: those its
    shading shares with the lake's).

    Inputs its group lacks, or holds with another type, are left out.
    """
    node = _shader_node(material)
    values = {}
    if node is None:
        return values
    for field in schema.SHADER_FIELDS:
        socket = _socket(node, field)
        if socket is None:
            continue
        value = socket.default_value
        try:
            if field.kind == "float":
                values[field.key] = float(value)
            elif field.kind == "int":
                values[field.key] = int(value)
            else:
                values[field.key] = tuple(float(v) for v in value[: 2 if field.kind == "vec2" else 3])
        except (TypeError, ValueError):
            continue
    return values


def write_values(material, values):
    """Sets the shader values among `values` (preset keys) from a script or the panel: their types
    checked and clamped here, where they enter (PresetError names a key of the wrong type).

    The plane's keys are ignored; an ocean material takes the keys its shading shares with the
    lake's (`_shader_node`). Returns the keys set.
    """
    schema.check_types(values)  # a value of the wrong type: PresetError, before anything is set
    shader_keys = {field.key for field in schema.SHADER_FIELDS}
    return set_values(material, schema.clamp_values({k: v for k, v in values.items() if k in shader_keys}))


def set_values(material, values):
    """Sets shader values already checked and clamped (a preset's, or `add_water`'s resolved ones).

    Inputs the group lacks, or holds with another type, are skipped; returns the keys set.
    """
    node = _shader_node(material)
    if node is None:
        return []
    shader_keys = {field.key for field in schema.SHADER_FIELDS}
    written = []
    for key, value in values.items():
        if key not in shader_keys:
            continue
        field = schema.BY_KEY[key]
        socket = _socket(node, field)
        if socket is None:
            continue
        if field.kind == "vec2":
            value = (value[0], value[1], 0.0)
        elif field.kind == "color":
            value = (*value, 1.0)
        try:
            socket.default_value = value
        except (TypeError, ValueError):
            continue
        written.append(key)
    if shading_of(material) == LAKE:
        fit_parts(material)  # the parts the values turn on built in, those at 0 taken out
    else:
        fit_shade_parts(material)  # the ocean's caustics likewise
    return written


def switch_part(material, name, on):
    """Turns an optional part of the shading on or off: on the lake (`PART_NAMES`) depth colour,
    foam or caustics, on the ocean shading (`OCEAN_PART_NAMES`) its caustics. Its switch
    (Absorption, Foam Amount, Caustics) goes to the part's usual value when it was 0, or to 0,
    and the group becomes the variant with the parts now on (`fit_parts`, `fit_shade_parts`).
    Returns what it did, in words; KindError (a ValueError) for a part the water's shading does
    not switch, NeedsRepairError for a group without the part's switch.
    """
    shading = shading_of(material)
    parts, names, spec = (
        (PARTS, PART_NAMES, FULL_SPEC)
        if shading == LAKE
        else (OCEAN_PARTS, OCEAN_PART_NAMES, FULL_SHADE_SPEC)
    )
    part = next((p for p in parts if p.name == name), None)
    if part is None:
        kind = "the ocean shading" if shading == OCEAN else "the lake"
        raise KindError(f"no part '{name}' to switch on {kind}: choose from {', '.join(names)}")
    node = _shader_node(material)
    if node is None or node.inputs.get(part.switch) is None:
        raise NeedsRepairError(
            f"'{getattr(material, 'name', material)}' has no water shading with {part.switch}"
        )
    socket = node.inputs[part.switch]
    value = socket.default_value
    colour = hasattr(value, "__len__")
    above_zero = max(tuple(value)[:3] if colour else (value,)) > 0.0
    if on and not above_zero:
        socket.default_value = (*part.on_value, 1.0) if colour else part.on_value
    elif not on:
        socket.default_value = (0.0, 0.0, 0.0, 1.0) if colour else 0.0
    if shading == LAKE:
        fit_parts(material)
    else:
        fit_shade_parts(material)
    built = name in parts_built(node.node_tree, spec)
    if built and not on and name in parts_wanted(material, node, spec):
        return [f"{part.label} stays in the shader: {part.switch} is linked, animated or driven"]
    return [f"{part.label} {'on' if built else 'off'} ({node.node_tree.name})"]
