"""`object.water_remove`: Remove Water, with everything the add-on made for it."""

import bpy

from ..water import removal
from ..water.editable import NotEditableError
from . import _poll


class OBJECT_OT_water_remove(bpy.types.Operator):
    """Remove the active water and everything the add-on made for it that nothing else uses (its
    probe, surroundings, light linking; scene settings it changed, when no other water needs them)"""

    bl_idname = "object.water_remove"
    bl_label = "Remove Water"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return _poll.any_water(cls, context)

    def execute(self, context):
        try:
            changes = removal.remove_water(context.active_object, context.scene)
        except (removal.RemoveWaterError, NotEditableError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        self.report({"INFO"}, "; ".join(changes))
        return {"FINISHED"}
