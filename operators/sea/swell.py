"""`object.water_sea_swell`: the open sea's swell (height, period, direction), 0 high for none."""

import bpy

from ...presets import PresetError
from ...water.editable import NotEditableError
from ...water.sea import open_sea
from .. import _poll
from .._props import add_field_properties


class OBJECT_OT_water_sea_swell(bpy.types.Operator):
    """Set the open sea's swell: long regular waves from their own direction on top of the wind's
    (height 0 takes it away)"""

    bl_idname = "object.water_sea_swell"
    bl_label = "Swell"
    bl_options = {"REGISTER", "UNDO"}

    # sea_swell_height, sea_swell_period, sea_swell_direction: made from the schema below the class.

    @classmethod
    def poll(cls, context):
        return _poll.water_allowing(cls, context, "swell")

    def invoke(self, context, _event):
        for key, value in open_sea.swell_values(context.active_object).items():
            if not self.properties.is_property_set(key):
                setattr(self, key, value)
        return context.window_manager.invoke_props_dialog(self)

    def execute(self, context):
        # The values given (or shown in the dialog); the others stay as the sea's swell has them.
        given = [key for key in open_sea.SWELL_KEYS if self.properties.is_property_set(key)]
        values = {key: getattr(self, key) for key in given}
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
