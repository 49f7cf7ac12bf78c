"""`object.water_mirror_setup`: make the scene show the selected water as a true mirror."""

import bpy

from ..water import mirror
from ..water.values import is_water


class OBJECT_OT_water_mirror_setup(bpy.types.Operator):
    """Turn on EEVEE ray tracing and fit a planar probe to the selected water, so it mirrors
    even what the camera cannot see"""

    bl_idname = "object.water_mirror_setup"
    bl_label = "Set Up Mirror"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        selected = list(context.selected_objects)
        if context.active_object is not None and context.active_object not in selected:
            selected.append(context.active_object)
        waters = [obj for obj in selected if is_water(obj)]
        if not waters:
            self.report({"ERROR"}, "Select a water object (one with a Water Surface material) first")
            return {"CANCELLED"}
        for water in waters:
            changes = mirror.setup_mirror(context.scene, water)
            self.report({"INFO"}, f"Mirror set-up for '{water.name}': " + ", ".join(changes))
        return {"FINISHED"}
