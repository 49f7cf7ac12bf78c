"""`object.water_mirror_setup`: make the scene show the selected water as a true mirror."""

import bpy

from ..water import kind, mirror
from ..water.values import is_water
from . import _poll


class OBJECT_OT_water_mirror_setup(bpy.types.Operator):
    """Turn on EEVEE ray tracing and fit a planar probe to the selected water, so it mirrors
    even what the camera cannot see"""

    bl_idname = "object.water_mirror_setup"
    bl_label = "Set Up Mirror"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return _poll.selected_water(cls, context)

    def execute(self, context):
        selected = list(context.selected_objects)
        if context.active_object is not None and context.active_object not in selected:
            selected.append(context.active_object)
        waters = [obj for obj in selected if is_water(obj)]
        if not waters:
            self.report({"ERROR"}, "Select a water object (one with a Water Surface material) first")
            return {"CANCELLED"}
        for water in waters:
            try:
                changes = mirror.setup_mirror(context.scene, water)
            except ValueError as error:  # needs repair, or linked data: one line, nothing changed
                self.report({"ERROR"}, str(error))
                return {"CANCELLED"}
            why = kind.refusal(water, "mirror", subject=f"'{water.name}'")
            if why is not None:  # ray tracing only, no probe
                self.report({"INFO"}, why)
            else:
                done = ", ".join(changes) or "already set up, nothing changed"
                self.report({"INFO"}, f"Mirror set-up for '{water.name}': {done}")
        return {"FINISHED"}
