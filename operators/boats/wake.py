"""`object.water_wake`: the selected objects leave a wake as they move, or (`enable` off) no
longer; `object.water_wake_bake` bakes the wakes."""

import bpy

from ...water.boats import wake
from ...water.editable import NotEditableError
from .. import _poll, _switch
from .._selected import run_on_selected, take_off_selected


def _can_add(cls, context):
    """What a wake asks (the poll of `enable` on)."""
    nothing = "Select the objects that leave a wake (and the water, if you like)"
    return _poll.selected_water_allowing(cls, context, "wake", nothing)


def _can_remove(cls, context):
    """What taking the wake off asks (the poll of `enable` off)."""
    if not any(wake.modifiers_of(obj) for obj in context.selected_objects):
        return _poll.refuse(cls, "No selected object leaves a wake")
    return True


class OBJECT_OT_water_wake(bpy.types.Operator):
    """Make the selected objects leave a Kelvin wake and foam on the water as they move (on the
    selected water, else the water they float on or lie over). Again: their sizes brought up to
    date. Off: they leave no wake any more"""

    bl_idname = "object.water_wake"
    bl_label = "Wake"
    bl_options = {"REGISTER", "UNDO"}

    enable: bpy.props.BoolProperty(
        name="Wake",
        description="On: the selected objects leave a wake on the water as they move. Off: they "
        "leave none any more, their wake modifiers removed (and the foam, once no wake needs it)",
        default=True,
    )
    strength: bpy.props.FloatProperty(
        name="Strength",
        description="How high the wake's waves are (1: the draft times the Froude number squared)",
        default=1.0,
        min=0.0,
        soft_max=3.0,
    )

    enable_polls = {True: _can_add, False: _can_remove}  # `_switch`

    @classmethod
    def poll(cls, context):
        return _switch.either_way(cls, context)

    @classmethod
    def description(cls, _context, properties):
        """The tooltip of a button with `enable` off ("" for on: the class's own)."""
        return "" if properties.enable else "The selected objects leave no wake any more"

    def draw(self, _context):
        _switch.draw_switch(self, ("strength",))

    def execute(self, context):
        refused = _switch.refused_way(self, context)
        if refused:
            return refused
        if not self.enable:
            return take_off_selected(self, context, wake.remove_wake_source)

        def act(obj, water):
            return wake.add_wake_source(obj, water, self.strength)

        return run_on_selected(self, context, act, (wake.WakeError,), "No wake added")


class OBJECT_OT_water_wake_bake(bpy.types.Operator):
    """Bake the wakes on the waters the selected objects move on (or the selected water), over
    the scene's frame range, into the .blend: frames rendered apart, on a farm, equal one run"""

    bl_idname = "object.water_wake_bake"
    bl_label = "Bake Wake"
    bl_options = {"REGISTER"}

    @classmethod
    def poll(cls, context):
        if not _waters_to_bake(context):
            return _poll.refuse(cls, "No wake on the selected objects' water")
        return True

    def execute(self, context):
        changes = []
        for water in _waters_to_bake(context):
            try:
                changes += wake.bake(water, context.scene)
            except (wake.WakeError, NotEditableError) as error:
                self.report({"ERROR"}, str(error))
                return {"CANCELLED"}
        self.report({"INFO"}, "; ".join(changes))
        return {"FINISHED"}


def _waters_to_bake(context):
    """The selected waters with a wake, and the waters the selected objects leave one on."""
    found = {obj for obj in context.selected_objects if wake.wake_modifiers(obj)}
    found |= {m.id_data for obj in context.selected_objects for m in wake.modifiers_of(obj)}
    return sorted(found, key=lambda water: water.name)
