"""`object.water_part_switch`: an optional part of the lake shading (depth colour, shore foam,
caustics) in or out of the shader."""

import bpy

from ..water import underwater, values
from ..water.editable import NotEditableError
from . import _poll

PART_ITEMS = (
    ("depth", "Depth Colour", "Colour by depth: the water absorbs light along the way to the bed"),
    ("foam", "Shore Foam", "Foam along the waterline and around what stands in the water"),
    ("caustics", "Caustics", "Sunlight focused by the ripples onto what lies under the water"),
)


class OBJECT_OT_water_part_switch(bpy.types.Operator):
    """Put an optional part of the water's shading in or out of its shader: out, it costs nothing
    at render time; in, its strength comes back to where it was, or to a usual value from 0"""

    bl_idname = "object.water_part_switch"
    bl_label = "Switch Water Shading Part"
    bl_options = {"REGISTER", "UNDO"}

    part: bpy.props.EnumProperty(name="Part", items=PART_ITEMS, default="caustics")
    enable: bpy.props.BoolProperty(
        name="On",
        description="On: the part is built into the shader (from 0, its strength takes a usual "
        "value). Off: its strength goes to 0 and the part leaves the shader",
        default=True,
    )

    @classmethod
    def poll(cls, context):
        return _poll.water_allowing(cls, context, "shader_parts")

    def execute(self, context):
        water = context.active_object
        try:
            changes = values.switch_part(values.water_material(water), self.part, self.enable)
            changes += underwater.fit_light(water, context.scene)
        except (ValueError, NotEditableError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        self.report({"INFO"}, f"'{water.name}': {'; '.join(changes)}")
        return {"FINISHED"}
