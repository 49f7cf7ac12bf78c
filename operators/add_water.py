"""`object.water_add`: one click, a water plane that mirrors and moves."""

import bpy
from bpy_extras import object_utils

from .. import presets
from ..presets import schema
from ..water.errors import WaterError
from ..water.plane import add_water
from ._props import add_field_properties

KEYS = tuple(field.key for field in schema.FIELDS)


def _apply_preset(self, _context):
    """Shows the chosen preset's values in the redo panel.

    In a fresh call from Python, values given alongside `preset` win whatever
    their order; once the operator has run (redo panel), choosing a preset
    replaces them all.
    """
    try:
        values = presets.get(self.preset).values
    except presets.PresetError:
        return
    properties = getattr(self, "properties", self)  # update callbacks get the properties themselves
    for key in KEYS:
        if self.ran or not properties.is_property_set(key):
            setattr(self, key, values[key])


class OBJECT_OT_water_add(object_utils.AddObjectHelper, bpy.types.Operator):
    """Add a water plane that reflects and refracts the scene, with its mirror set-up"""

    bl_idname = "object.water_add"
    bl_label = "Water Surface"
    bl_options = {"REGISTER", "UNDO"}

    preset: bpy.props.EnumProperty(
        name="Preset",
        description="Starting values for the water (built-in and user presets)",
        items=presets.enum_items,
        default=0,
        update=_apply_preset,
    )
    # Every preset key (`schema.FIELDS`) is a property too, made from the schema below the class.
    mirror_setup: bpy.props.BoolProperty(
        name="Mirror Set-Up",
        description="Turn on EEVEE ray tracing and add a planar probe so the water shows a true mirror",
        default=True,
    )
    see_surroundings: bpy.props.BoolProperty(
        name="Surroundings",
        description=(
            "Gather the objects that reach below the water into its own surroundings collection and "
            "measure depth and shore distance from them (adds the points the waterline needs)"
        ),
        default=True,
    )
    ran: bpy.props.BoolProperty(options={"HIDDEN", "SKIP_SAVE"})

    @classmethod
    def poll(cls, context):
        from ._poll import scene_editable

        return scene_editable(cls, context)

    def draw(self, _context):
        layout = self.layout
        layout.use_property_split = True
        layout.prop(self, "preset")
        for key in KEYS:
            layout.prop(self, key)
        layout.prop(self, "mirror_setup")
        layout.prop(self, "see_surroundings")
        layout.separator()
        layout.prop(self, "align")
        layout.prop(self, "location")
        layout.prop(self, "rotation")

    def _given(self, key):
        value = getattr(self, key)
        return value if isinstance(value, (bool, int, float, str)) else tuple(value)

    def execute(self, context):
        try:
            preset = presets.get(self.preset)
        except presets.PresetError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        # Values not given take the preset's; the pipeline clamps them, and they are shown as used.
        given = {key: self._given(key) for key in KEYS if self.properties.is_property_set(key)}

        if context.mode != "OBJECT":
            if not bpy.ops.object.mode_set.poll():
                self.report(
                    {"ERROR"}, f"Cannot leave {context.mode.replace('_', ' ').title()} mode to add water"
                )
                return {"CANCELLED"}
            bpy.ops.object.mode_set(mode="OBJECT")
            self.report({"INFO"}, "Switched to Object Mode to add the water")

        try:
            added = add_water(
                context.scene,
                preset=preset.id,
                collection=context.collection,
                mirror_setup=self.mirror_setup,
                see_surroundings=self.see_surroundings,
                matrix=object_utils.add_object_align_init(context, self),
                **given,
            )
        except WaterError as error:  # PresetError (a wrong type, NaN), UnderwaterError, AddWaterError
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        for key, value in added.values.items():
            setattr(self, key, value)
        self.ran = True
        for obj in context.view_layer.objects.selected:
            obj.select_set(False)
        added.object.select_set(True)
        context.view_layer.objects.active = added.object
        for note in added.notes:
            self.report({"WARNING"}, note[0].upper() + note[1:])
        summary = added.summary(preset.name)
        self.report({"INFO"}, summary[0].upper() + summary[1:])
        return {"FINISHED"}


add_field_properties(OBJECT_OT_water_add, KEYS)
