"""`object.water_physical_caustics`: Cycles' own caustics (MNEE) for the active water, on or off."""

import bpy

from ...water import physical_caustics
from ...water.editable import NotEditableError
from .. import _poll


class OBJECT_OT_water_physical_caustics(bpy.types.Operator):
    """Let Cycles compute the water's caustics itself (manifold next-event estimation): the water
    casts them, the objects below receive them, the sun lights them. Off puts everything back"""

    bl_idname = "object.water_physical_caustics"
    bl_label = "Physical Caustics"
    bl_options = {"REGISTER", "UNDO"}

    enable: bpy.props.BoolProperty(
        name="Physical Caustics",
        description="On: Cycles traces the caustics (the shader's own pattern is set to 0). "
        "Off: what was changed is put back",
        default=True,
    )

    @classmethod
    def poll(cls, context):
        return _poll.water_allowing(cls, context, "physical_caustics")

    def execute(self, context):
        water = context.active_object
        try:
            if self.enable:
                changes = physical_caustics.enable(water, context.scene)
            else:
                changes = physical_caustics.disable(water, context.scene)
        except (physical_caustics.PhysicalCausticsError, NotEditableError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        state = "on" if self.enable else "off"
        self.report(
            {"INFO"}, f"Physical caustics {state} for '{water.name}': {'; '.join(changes) or 'no change'}"
        )
        return {"FINISHED"}
