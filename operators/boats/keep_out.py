"""`object.water_keep_out`: no water inside the selected hulls, or (`enable` off) water again."""

import bpy

from ...water.boats import keep_out
from .. import _poll, _switch
from .._selected import run_on_selected, take_off_selected


def _can_keep_out(cls, context):
    """What keeping the water out asks (the poll of `enable` on)."""
    nothing = "Select the hulls to keep the water out of (and, if you like, the water)"
    return _poll.selected_water_allowing(cls, context, "keep_out", nothing)


def _can_let_in(cls, context):
    """What letting the water in asks (the poll of `enable` off)."""
    if not any(keep_out.kept_out_of(obj) for obj in context.selected_objects):
        return _poll.refuse(cls, "No water is kept out of a selected object")
    return True


class OBJECT_OT_water_keep_out(bpy.types.Operator):
    """Keep the water out of the selected hulls (on the selected water, else the water they float
    on or lie in): no water shows inside them, wherever they move, in EEVEE and Cycles. Again:
    made anew from their shape now. Off: the water shows inside them again"""

    bl_idname = "object.water_keep_out"
    bl_label = "Keep Water Out"
    bl_options = {"REGISTER", "UNDO"}

    enable: bpy.props.BoolProperty(
        name="Keep Out",
        description="On: no water shows inside the selected hulls (made anew from their shape). "
        "Off: the water shows inside them again",
        default=True,
    )

    enable_polls = {True: _can_keep_out, False: _can_let_in}  # `_switch`

    @classmethod
    def poll(cls, context):
        return _switch.either_way(cls, context)

    @classmethod
    def description(cls, _context, properties):
        """The tooltip of a button with `enable` off ("" for on: the class's own)."""
        return "" if properties.enable else "Let the water show inside the selected hulls again"

    def execute(self, context):
        refused = _switch.refused_way(self, context)
        if refused:
            return refused
        if not self.enable:
            return take_off_selected(self, context, keep_out.let_water_in)
        return run_on_selected(
            self, context, keep_out.keep_water_out, (keep_out.KeepOutError,), "No water kept out"
        )
