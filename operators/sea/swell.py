"""`object.water_sea_swell`: the open sea's swell (height, period, direction), or (`enable` off, or
0 high) none."""

import bpy

from ...presets import PresetError
from ...water.editable import NotEditableError
from ...water.sea import open_sea
from .. import _poll, _switch
from .._props import add_field_properties


class OBJECT_OT_water_sea_swell(bpy.types.Operator):
    """Set the open sea's swell: long regular waves from their own direction on top of the wind's
    (off, or height 0, takes it away)"""

    bl_idname = "object.water_sea_swell"
    bl_label = "Swell"
    bl_options = {"REGISTER", "UNDO"}

    enable: bpy.props.BoolProperty(
        name="Swell",
        description="On: the sea has the swell set here. Off: the swell goes, as at height 0",
        default=True,
    )
    # sea_swell_height, sea_swell_period, sea_swell_direction: made from the schema below the class.

    @classmethod
    def poll(cls, context):
        return _poll.water_allowing(cls, context, "swell")

    @classmethod
    def description(cls, _context, properties):
        """The tooltip of a button with `enable` off ("" for on: the class's own)."""
        return "" if properties.enable else "Take the open sea's swell away"

    def draw(self, _context):
        _switch.draw_switch(self, open_sea.SWELL_KEYS)

    def invoke(self, context, _event):
        if not self.enable:  # nothing to ask
            return self.execute(context)
        for key, value in open_sea.swell_values(context.active_object).items():
            if not self.properties.is_property_set(key):
                setattr(self, key, value)
        return context.window_manager.invoke_props_dialog(self)

    def execute(self, context):
        # The values given (or shown in the dialog); the others stay as the sea's swell has them.
        given = [key for key in open_sea.SWELL_KEYS if self.properties.is_property_set(key)]
        values = {key: getattr(self, key) for key in given}
        if not self.enable:
            values["sea_swell_height"] = 0.0  # as height 0 does: the swell goes
        if "sea_swell_direction" in values:
            values["sea_swell_direction"] = tuple(values["sea_swell_direction"])
        try:
            change = open_sea.change_swell(context.active_object, values, context.scene)
        except (PresetError, NotEditableError, open_sea.OpenSeaError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        self.report({"INFO"}, change)
        return {"FINISHED"}


add_field_properties(OBJECT_OT_water_sea_swell, open_sea.SWELL_KEYS)
