"""The water's values live on its material's `Water Surface` group node: one
source of truth that the panel shows, presets fill and the `.blend` keeps."""

from ..nodes.material import water_node
from ..nodes.ocean_material import ocean_nodes
from ..presets import schema


def water_material(obj):
    """The first material of `obj` made by the add-on (lake or ocean shading), or None."""
    if obj is None or obj.type != "MESH":
        return None
    for slot in obj.material_slots:
        if water_node(slot.material) is not None or ocean_nodes(slot.material) is not None:
            return slot.material
    return None


def is_water(obj):
    return water_material(obj) is not None


def read_values(material):
    """The shader values of a lake material, keyed as in presets ({} for the ocean's)."""
    node = water_node(material)
    values = {}
    if node is None:
        return values
    for field in schema.SHADER_FIELDS:
        value = node.inputs[field.socket].default_value
        if field.kind == "float":
            values[field.key] = float(value)
        elif field.kind == "int":
            values[field.key] = int(value)
        else:
            values[field.key] = tuple(float(v) for v in value[: 2 if field.kind == "vec2" else 3])
    return values


def write_values(material, values):
    """Sets the shader values among `values` (preset keys), clamped first.

    The plane's keys are ignored, and so is an ocean material: its values live in its own groups.
    """
    node = water_node(material)
    if node is None:
        return
    shader_keys = {field.key for field in schema.SHADER_FIELDS}
    safe = schema.clamp_values({k: v for k, v in values.items() if k in shader_keys})
    for key, value in safe.items():
        field = schema.BY_KEY[key]
        socket = node.inputs[field.socket]
        if field.kind == "vec2":
            socket.default_value = (value[0], value[1], 0.0)
        elif field.kind == "color":
            socket.default_value = (*value, 1.0)
        else:
            socket.default_value = value
