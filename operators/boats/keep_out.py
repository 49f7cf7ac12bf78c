"""`object.water_keep_out` and `object.water_let_in`: no water inside the selected hulls, or
water again."""

import bpy

from ...water.boats import keep_out
from .. import _poll
from .._selected import run_on_selected, take_off_selected


class OBJECT_OT_water_keep_out(bpy.types.Operator):
    """Keep the water out of the selected hulls (on the selected water, else the water they float
    on or lie in): no water shows inside them, wherever they move, in EEVEE and Cycles. Again:
    made anew from their shape now"""

    bl_idname = "object.water_keep_out"
    bl_label = "Keep Water Out"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        nothing = "Select the hulls to keep the water out of (and, if you like, the water)"
        return _poll.selected_water_allowing(cls, context, "keep_out", nothing)

    def execute(self, context):
        return run_on_selected(
            self, context, keep_out.keep_water_out, (keep_out.KeepOutError,), "No water kept out"
        )


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
        return take_off_selected(self, context, keep_out.let_water_in)
