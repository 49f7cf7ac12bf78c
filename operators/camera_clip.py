"""`object.water_camera_clip`: the scene camera's Clip End past the active water's far edge."""

import bpy

from ..water import camera_clip
from ..water.editable import NotEditableError
from . import _poll


class OBJECT_OT_water_camera_clip(bpy.types.Operator):
    """Move the scene camera's Clip End past the water's farthest corner, so none of it is cut
    off at the horizon"""

    bl_idname = "object.water_camera_clip"
    bl_label = "Extend Camera Clip"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        if not _poll.water_allowing(cls, context, "ray_tracing", editable=False):
            return False
        if context.scene.camera is None or context.scene.camera.type != "CAMERA":
            return _poll.refuse(cls, "the scene has no camera")
        return True

    def execute(self, context):
        try:
            changes = camera_clip.extend_clip(context.scene, context.active_object)
        except (ValueError, NotEditableError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        self.report({"INFO"}, "; ".join(changes) or "the camera already sees all of the water")
        return {"FINISHED"}
