"""`object.water_repair`: point a broken water's node back to the add-on's group."""

import bpy

from ..nodes.builder import NodeGroupError
from ..water.repair import repair_water
from ..water.values import water_material
from . import _poll


class OBJECT_OT_water_repair(bpy.types.Operator):
    """Rebuild the active water's node group (replaced, or missing sockets), keeping the values it can"""

    bl_idname = "object.water_repair"
    bl_label = "Repair Water"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return _poll.broken_water(cls, context)

    def execute(self, context):
        material = water_material(context.active_object)
        try:
            message = repair_water(material, context.scene)
        except (ValueError, NodeGroupError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        self.report({"INFO"}, message)
        return {"FINISHED"}
