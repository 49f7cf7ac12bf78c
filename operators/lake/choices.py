"""`object.water_sun_set` and `object.water_bump_set`: the sun the glint follows and the normal map
the water samples (lake shading)."""

import bpy

from ...nodes.bump_image import IMAGE_NAME as BUMP_IMAGE_NAME
from ...nodes.bump_image import is_bump_image
from ...nodes.material import drive_sun, glint_sun, set_bump_image
from ...water import kind, sun_link
from ...water.editable import NotEditableError, check_editable
from ...water.values import water_material
from .. import _poll

_items = {}  # kept alive for Blender's dynamic enums


def _sun_items(_self, context):
    suns = [o for o in context.scene.objects if o.type == "LIGHT" and o.data.type == "SUN"]
    _items["sun"] = [("NONE", "Default Light", "The reference's fixed light direction", "LIGHT", 0)] + [
        (o.name, o.name, f"Follow '{o.name}'", "LIGHT_SUN", i + 1) for i, o in enumerate(suns)
    ]
    return _items["sun"]


def _image_items(_self, _context):
    _items["image"] = [("DEFAULT", BUMP_IMAGE_NAME, "The add-on's packed water normal map", "IMAGE", 0)] + [
        (image.name, image.name, f"Use '{image.name}' as the normal map", "IMAGE_DATA", i + 1)
        for i, image in enumerate(bpy.data.images)
        if image.type not in {"RENDER_RESULT", "COMPOSITING"} and not is_bump_image(image)
    ]
    return _items["image"]


class _LakeChoice:
    """A searchable choice applied to the active object's lake material."""

    bl_options = {"REGISTER", "UNDO"}
    feature = "sun_choice"  # the choice's name in `kind.FEATURES`

    @classmethod
    def poll(cls, context):
        return _poll.water_allowing(cls, context, cls.feature)

    def invoke(self, context, _event):
        context.window_manager.invoke_search_popup(self)
        return {"RUNNING_MODAL"}

    def execute(self, context):
        why = kind.refusal(context.active_object, self.feature)
        if why is not None:
            self.report({"ERROR"}, why)
            return {"CANCELLED"}
        material = water_material(context.active_object)
        try:
            self.report({"INFO"}, self.choose(context, material))
        except NotEditableError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        return {"FINISHED"}


class OBJECT_OT_water_sun_set(_LakeChoice, bpy.types.Operator):
    """Choose the sun whose direction the water's glint follows"""

    bl_idname = "object.water_sun_set"
    bl_label = "Glint Sun"
    bl_property = "sun"

    sun: bpy.props.EnumProperty(name="Sun", items=_sun_items)

    def choose(self, context, material):
        sun = None if self.sun == "NONE" else context.scene.objects.get(self.sun)
        check_editable(sun)  # a linked sun's light linking cannot be set: refused, nothing changed
        previous = glint_sun(material)
        drive_sun(material, sun)
        if previous is not None and previous != sun:
            sun_link.release_water(context.active_object, previous)
        changes = sun_link.exclude_water(context.active_object, sun)
        followed = "the default light" if sun is None else repr(sun.name)
        return f"Glint follows {followed}" + "".join(f"; {change}" for change in changes)


class OBJECT_OT_water_bump_set(_LakeChoice, bpy.types.Operator):
    """Choose the tangent-space normal map the water scrolls"""

    bl_idname = "object.water_bump_set"
    bl_label = "Bump Image"
    bl_property = "image"
    feature = "bump_choice"

    image: bpy.props.EnumProperty(name="Image", items=_image_items)

    def choose(self, _context, material):
        image = None if self.image == "DEFAULT" else bpy.data.images.get(self.image)
        check_editable(material)
        set_bump_image(material, image)
        return f"'{material.name}' samples {'the default bump' if image is None else repr(image.name)}"
