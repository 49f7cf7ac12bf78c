"""`object.water_float`: selected objects ride the water below them, or (`enable` off) no longer."""

import bpy

from ...water.boats import floating
from ...water.editable import why_not_editable
from .. import _poll, _switch
from .._selected import not_water, run_on_selected, take_off_selected


def _metres(name, description, soft_max):
    """A length in metres, 0 or more (0 where the operator takes it from the object's bounds)."""
    return bpy.props.FloatProperty(
        name=name, description=description, default=0.0, min=0.0, soft_max=soft_max, unit="LENGTH"
    )


def _can_float(cls, context):
    """What floating asks (the poll of `enable` on)."""
    nothing = "Select the objects to float (and, if you like, the water)"
    if not _poll.selected_water_allowing(cls, context, "floating", nothing):
        return False
    for obj in not_water(context):
        why = why_not_editable(obj)
        if why is not None:
            return _poll.refuse(cls, why)
    return True


def _can_stop(cls, context):
    """What stopping asks (the poll of `enable` off)."""
    if not any(floating.is_floating(obj) for obj in context.selected_objects):
        return _poll.refuse(cls, "No selected object floats on water")
    return True


class OBJECT_OT_water_float(bpy.types.Operator):
    """Make the selected objects float on the water below them (or on the selected water): each
    rides the water under its whole footprint (heave, pitch and roll), at its draft, with
    constraints and drivers (no scripts at render), and with Wake leaves a wake as it moves. Off:
    they stop floating"""

    bl_idname = "object.water_float"
    bl_label = "Float on Water"
    bl_options = {"REGISTER", "UNDO"}

    enable: bpy.props.BoolProperty(
        name="Float",
        description="On: the selected objects float on the water. Off: they stop floating, their "
        "floating constraints and rig removed with the wake floating added",
        default=True,
    )
    draft: _metres(
        "Draft",
        "How deep the object sits: metres of it below the waterline, from its lowest point (0 with "
        "Draft from Bounds: a third of its height)",
        20.0,
    )
    draft_from_bounds: bpy.props.BoolProperty(
        name="Draft from Bounds",
        description="Sink the object by a third of its height (its bounding box's)",
        default=True,
    )
    length: _metres(
        "Length",
        "Length of the footprint whose water rocks the object, along its longer horizontal axis "
        "(0: its bounding box's)",
        500.0,
    )
    beam: _metres(
        "Beam", "Width of the footprint whose water rocks the object (0: its bounding box's)", 100.0
    )
    wake: bpy.props.BoolProperty(
        name="Wake",
        description="Leave a Kelvin wake and foam on the water as it moves (Stop takes it off)",
        default=True,
    )
    tilt_damping: bpy.props.FloatProperty(
        name="Tilt Damping",
        description="How much less than the water the objects tilt (0: they follow the surface, "
        "1: they stay upright)",
        default=0.0,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
    )

    enable_polls = {True: _can_float, False: _can_stop}  # `_switch`

    @classmethod
    def poll(cls, context):
        return _switch.either_way(cls, context)

    @classmethod
    def description(cls, _context, properties):
        """The tooltip of a button with `enable` off ("" for on: the class's own)."""
        return (
            ""
            if properties.enable
            else "Stop the selected objects floating: their floating constraints are removed"
        )

    def draw(self, _context):
        _switch.draw_switch(self, ("draft_from_bounds", "draft", "length", "beam", "wake", "tilt_damping"))

    def execute(self, context):
        refused = _switch.refused_way(self, context)
        if refused:
            return refused
        if not self.enable:
            return take_off_selected(self, context, floating.stop_floating)

        def act(obj, water):
            return floating.float_on_water(
                obj,
                water,
                self.tilt_damping,
                None if self.draft_from_bounds else self.draft,
                self.length or None,
                self.beam or None,
                context.scene,
                self.wake,
            )

        return run_on_selected(
            self, context, act, (floating.FloatError,), "Nothing floats", floating_first=False
        )
