"""`object.water_keep_out` and `object.water_let_in`: no water inside the selected hulls, or
water again."""

import bpy

from ..water import keep_out
from ..water.editable import NotEditableError
from ..water.float_constraints import floating_on
from ..water.floating import water_below
from ..water.values import is_water
from . import _poll


def _hulls(context):
    """The selected objects that are not water."""
    return [obj for obj in context.selected_objects if not is_water(obj)]


class OBJECT_OT_water_keep_out(bpy.types.Operator):
    """Keep the water out of the selected hulls (on the selected water, else the water they float
    on or lie in): no water shows inside them, wherever they move, in EEVEE and Cycles. Again:
    made anew from their shape now"""

    bl_idname = "object.water_keep_out"
    bl_label = "Keep Water Out"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        if not _hulls(context):
            return _poll.refuse(
                cls, "Select the hulls to keep the water out of (and, if you like, the water)"
            )
        return True

    def execute(self, context):
        chosen = [obj for obj in context.selected_objects if is_water(obj)]
        if len(chosen) > 1:
            self.report({"ERROR"}, "Select one water at most: it is kept out of the other objects")
            return {"CANCELLED"}
        depsgraph = context.evaluated_depsgraph_get()
        done, skipped = [], []
        for obj in _hulls(context):
            water = chosen[0] if chosen else floating_on(obj) or water_below(obj, context.scene, depsgraph)
            if water is None:
                skipped.append(f"'{obj.name}' is over no water: select the water too")
                continue
            try:
                done += keep_out.keep_water_out(obj, water, depsgraph)
            except (keep_out.KeepOutError, NotEditableError) as error:
                skipped.append(str(error))
        for message in skipped:
            self.report({"WARNING"}, message)
        if not done:
            self.report({"ERROR"}, "No water kept out: " + "; ".join(skipped))
            return {"CANCELLED"}
        self.report({"INFO"}, "; ".join(done))
        return {"FINISHED"}


class OBJECT_OT_water_let_in(bpy.types.Operator):
    """Let the water show inside the selected hulls again"""

    bl_idname = "object.water_let_in"
    bl_label = "Let Water In"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        if not any(keep_out.kept_out_of(obj) for obj in context.selected_objects):
            return _poll.refuse(cls, "No water is kept out of a selected object")
        return True

    def execute(self, context):
        changes = []
        for obj in context.selected_objects:
            try:
                changes += keep_out.let_water_in(obj)
            except NotEditableError as error:
                self.report({"WARNING"}, str(error))
        self.report({"INFO"}, "; ".join(changes) or "no change")
        return {"FINISHED"}
