"""`object.water_underwater`: the `Underwater` switch, the water a camera under the surface sees
through, on or off."""

import bpy

from ...water import apply
from ...water.errors import WaterError
from .. import _poll


class OBJECT_OT_water_underwater(bpy.types.Operator):
    """A camera under the water sees through water: what is far fades into the water's own colour.
    A camera that never goes under pays nothing for it; off removes the water's underwater body"""

    bl_idname = "object.water_underwater"
    bl_label = "Underwater"
    bl_options = {"REGISTER", "UNDO"}

    enable: bpy.props.BoolProperty(
        name="Underwater",
        description="On: the water gets its hidden underwater body (fog by distance, made only "
        "while the camera is near or under the surface). Off: the body goes, and the volume "
        "samples it raised go back",
        default=True,
    )

    @classmethod
    def poll(cls, context):
        return _poll.water_allowing(cls, context, "underwater")

    def execute(self, context):
        water = context.active_object
        try:
            changes = apply.apply_values(water, {"underwater": self.enable}, context.scene)  # the one path
        except WaterError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        state = "on" if self.enable else "off"
        done = "; ".join(changes) if changes else "nothing to change"
        self.report({"INFO"}, f"'{water.name}': Underwater {state}: {done}")
        return {"FINISHED"}
