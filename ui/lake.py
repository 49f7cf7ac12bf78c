"""The lake's part of the panel: its presets, its inputs box by box with their buttons (the
glint's sun, Cycles' caustics), the bump image, the debug view and the mirror's state."""

import bpy

from ..nodes.lake.lake_parts import DEBUG_VIEWS
from ..nodes.material import bump_image, glint_sun
from ..water import physical_caustics
from ..water.mirror import find_probe
from .common import draw_part, draw_surroundings, draw_waves

_SECTIONS = (
    ("Waves", "MOD_WAVE", ("Wave Height", "Wave Length", "Bump Strength", "Bump Layers")),
    ("Wind", "FORCE_WIND", ("Wind Direction", "Wind Force")),
    ("Tint", "COLOR", ("Dull Color", "Dull Blend")),
    ("Glint", "LIGHT_SUN", ("Specular Power", "Specular Strength")),
    ("Surroundings", "OUTLINER_COLLECTION", ("part:depth", "part:foam")),
    ("Caustics", "LIGHT_SUN", ("part:caustics",)),
)


class WATER_MT_presets(bpy.types.Menu):
    """Water presets: built-in and the user's."""

    bl_label = "Water Presets"
    bl_idname = "WATER_MT_presets"

    def draw(self, _context):
        from .. import presets

        for preset in presets.all_presets():
            op = self.layout.operator(
                "object.water_preset_apply", text=preset.name, icon="USER" if preset.user else "NONE"
            )
            op.preset = preset.id


def draw_lake(layout, context, material, node):
    """Everything the lake shading offers, below its material row."""
    row = layout.row(align=True)
    row.menu("WATER_MT_presets", text="Presets", icon="PRESET")
    row.operator("object.water_preset_add", text="", icon="ADD")
    row.operator("object.water_preset_remove", text="", icon="REMOVE")
    layout.use_property_split = True
    for section in _SECTIONS:
        _draw_section(layout.box(), context, material, node, section)
    _draw_tail(layout, context, material, node)


def _draw_section(box, context, material, node, section):
    """One box of the lake's inputs, `section` = (title, icon, input names or "part:<name>"),
    with the box's own button (surroundings, physical caustics, the glint's sun)."""
    title, icon, names = section
    box.label(text=title, icon=icon)
    for name in names:
        if name.startswith("part:"):
            draw_part(box, node, name[len("part:") :])
            continue
        socket = node.inputs[name]
        if name == "Wind Direction":
            col = box.column(align=True)
            col.prop(socket, "default_value", index=0, text="Wind X")
            col.prop(socket, "default_value", index=1, text="Y")
        else:
            box.prop(socket, "default_value", text=name)
    if title == "Surroundings":
        draw_surroundings(box, context.active_object)
    if title == "Caustics":
        on = physical_caustics.is_on(context.active_object)
        op = box.operator(
            "object.water_physical_caustics",
            text=f"Physical Caustics (Cycles): {'On' if on else 'Off'}",
            icon="CHECKBOX_HLT" if on else "CHECKBOX_DEHLT",
        )
        if op is not None:  # None while the operator's poll refuses (linked water)
            op.enable = not on
    if title == "Glint":
        sun = glint_sun(material)
        box.operator(
            "object.water_sun_set",
            text=f"Sun: {sun.name if sun else 'Default Light'}",
            icon="LIGHT_SUN",
        )


def _draw_tail(layout, context, material, node):
    """Below the lake's inputs: its bump image, the debug view, its waves and the mirror's state."""
    image = bump_image(material)
    layout.operator(
        "object.water_bump_set",
        text=f"Bump: {image.name if image else 'none'}",
        icon="IMAGE_DATA",
    )
    view = node.inputs["Debug View"]
    names = {number: label for number, _id, label, _tip in DEBUG_VIEWS}
    layout.prop(view, "default_value", text=f"Debug: {names.get(view.default_value, '?')}")

    draw_waves(layout, context.active_object)

    box = layout.box()
    probe = find_probe(context.active_object)
    eevee = context.scene.eevee
    ready = probe is not None and eevee.use_raytracing
    box.label(
        text="Mirror ready" if ready else "Mirror not set up",
        icon="CHECKMARK" if ready else "ERROR",
    )
    box.operator("object.water_mirror_setup", icon="MOD_MIRROR")
