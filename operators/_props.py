"""Operator properties made from the preset schema, so ranges and tooltips have one source."""

import bpy

from ..presets import schema


def field_property(key):
    """A Blender property for the preset field `key`, with its default, hard range and tooltip."""
    field = schema.BY_KEY[key]
    common = {"name": field.label, "description": field.tooltip}
    if field.kind == "vec2":
        return bpy.props.FloatVectorProperty(
            size=2, default=field.default, min=field.min, max=field.max, subtype="XYZ", **common
        )
    if field.kind == "color":
        return bpy.props.FloatVectorProperty(
            size=3, default=field.default, min=field.min, max=field.max, subtype="COLOR", **common
        )
    if field.kind == "int":
        return bpy.props.IntProperty(
            default=field.default, min=field.min, max=field.max, soft_max=min(512, field.max), **common
        )
    if field.kind == "bool":
        return bpy.props.BoolProperty(default=field.default, **common)
    if field.kind == "choice":
        items = [(choice, choice.title(), field.tooltip) for choice in field.choices]
        return bpy.props.EnumProperty(items=items, default=field.default, **common)
    extra = {"unit": "LENGTH", "subtype": "DISTANCE"} if key == "size" else {}
    soft = {"soft_max": 1000.0} if key == "size" else {}
    return bpy.props.FloatProperty(
        default=field.default, min=field.min, max=field.max, **extra, **soft, **common
    )


def add_field_properties(cls, keys):
    """Gives operator `cls` (before it is registered) a property for each preset field in `keys`."""
    for key in keys:
        cls.__annotations__[key] = field_property(key)
