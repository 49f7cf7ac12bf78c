"""`object.water_waves_add`: lift an existing water with the four-sine-wave modifier."""

import bpy

from ..water import mirror, waves
from . import _poll


class OBJECT_OT_water_waves_add(bpy.types.Operator):
    """Add the Water Waves modifier (four summed sine waves) to the active water"""

    bl_idname = "object.water_waves_add"
    bl_label = "Add Waves"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return _poll.any_water(cls, context, "waves")

    def execute(self, context):
        obj = context.active_object
        waves.add_waves(obj)
        refit = mirror.fit_probe(obj)
        if len(obj.data.vertices) <= 4:
            self.report(
                {"WARNING"},
                f"'{obj.name}' has only its corners: the waves tilt it but cannot ripple it. "
                "Add water with a higher Resolution, or subdivide it",
            )
        else:
            self.report({"INFO"}, f"Added waves to '{obj.name}'" + "".join(f"; {change}" for change in refit))
        return {"FINISHED"}
