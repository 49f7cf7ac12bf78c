"""`object.water_wake_add` and `object.water_wake_remove`: the selected objects leave a wake as
they move, or no longer."""

import bpy

from ...water.boats import wake
from ...water.editable import NotEditableError
from .. import _poll
from .._selected import run_on_selected, take_off_selected


class OBJECT_OT_water_wake_add(bpy.types.Operator):
    """Make the selected objects leave a Kelvin wake and foam on the water as they move (on the
    selected water, else the water they float on or lie over). Again: their sizes brought up to
    date"""

    bl_idname = "object.water_wake_add"
    bl_label = "Add Wake"
    bl_options = {"REGISTER", "UNDO"}

    strength: bpy.props.FloatProperty(
        name="Strength",
        description="How high the wake's waves are (1: the draft times the Froude number squared)",
        default=1.0,
        min=0.0,
        soft_max=3.0,
    )

    @classmethod
    def poll(cls, context):
        nothing = "Select the objects that leave a wake (and the water, if you like)"
        return _poll.selected_water_allowing(cls, context, "wake", nothing)

    def execute(self, context):
        def act(obj, water):
            return wake.add_wake_source(obj, water, self.strength)

        return run_on_selected(self, context, act, (wake.WakeError,), "No wake added")


class OBJECT_OT_water_wake_remove(bpy.types.Operator):
    """The selected objects leave no wake any more"""

    bl_idname = "object.water_wake_remove"
    bl_label = "Remove Wake"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        if not any(wake.modifiers_of(obj) for obj in context.selected_objects):
            return _poll.refuse(cls, "No selected object leaves a wake")
        return True

    def execute(self, context):
        return take_off_selected(self, context, wake.remove_wake_source)


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
