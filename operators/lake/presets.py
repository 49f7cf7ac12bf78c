"""`object.water_preset_apply`, `_add` and `_remove`: lake values from, and into, presets."""

import bpy

from ... import presets
from ...water import apply, kind
from ...water.errors import WaterError
from ...water.values import water_material
from .. import _poll


def _active_water(operator, context):
    """The active object's lake material, or None after reporting why not (`kind.refusal`)."""
    why = kind.refusal(context.active_object, "presets")
    if why is not None:
        operator.report({"ERROR"}, why)
        return None
    return water_material(context.active_object)


class OBJECT_OT_water_preset_apply(bpy.types.Operator):
    """Set the active water's values from a preset"""

    bl_idname = "object.water_preset_apply"
    bl_label = "Apply Water Preset"
    bl_options = {"REGISTER", "UNDO"}

    preset: bpy.props.EnumProperty(name="Preset", items=presets.enum_items)

    @classmethod
    def poll(cls, context):
        return _poll.water_allowing(cls, context, "presets")

    def execute(self, context):
        material = _active_water(self, context)
        if material is None:
            return {"CANCELLED"}
        try:
            preset = presets.get(self.preset)
            # The one path (`apply.py`): shader values, underwater, light shafts, caustic light.
            changes = apply.apply_preset(context.active_object, preset.id, context.scene)
        except WaterError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        done = f": {'; '.join(changes)}" if changes else ""
        self.report({"INFO"}, f"Applied preset '{preset.name}' to '{material.name}'{done}")
        return {"FINISHED"}


class OBJECT_OT_water_preset_add(bpy.types.Operator):
    """Save the active water's values as a user preset"""

    bl_idname = "object.water_preset_add"
    bl_label = "Save Water Preset"

    name: bpy.props.StringProperty(name="Name", description="Name of the new preset", default="My Water")
    # SKIP_SAVE: a tick from an earlier save must not silently replace the next clash.
    replace: bpy.props.BoolProperty(
        name="Replace Existing",
        description="Overwrite your preset of the same name (unticked, a name clash is refused)",
        default=False,
        options={"SKIP_SAVE"},
    )

    @classmethod
    def poll(cls, context):
        # Saving reads the values only: linked water may be saved as a preset.
        return _poll.water_allowing(cls, context, "presets", editable=False)

    def invoke(self, context, _event):
        return context.window_manager.invoke_props_dialog(self)

    def execute(self, context):
        material = _active_water(self, context)
        if material is None:
            return {"CANCELLED"}
        try:
            values = apply.read_water(context.active_object)  # every key a preset applies
            preset_id = presets.save_user_preset(self.name, values, overwrite=self.replace)
        except presets.PresetExistsError:
            self.report(
                {"ERROR"},
                f"A preset named '{self.name}' already exists: tick Replace Existing or pick another name",
            )
            return {"CANCELLED"}
        except (presets.PresetError, OSError) as error:
            self.report({"ERROR"}, f"Cannot save preset '{self.name}': {error}")
            return {"CANCELLED"}
        self.report({"INFO"}, f"Saved preset '{self.name}' ({presets.get(preset_id).path})")
        return {"FINISHED"}


class OBJECT_OT_water_preset_remove(bpy.types.Operator):
    """Delete a user preset (built-in presets stay)"""

    bl_idname = "object.water_preset_remove"
    bl_label = "Remove Water Preset"

    preset: bpy.props.EnumProperty(name="Preset", items=presets.enum_items)

    @classmethod
    def poll(cls, _context):
        if any(preset.user for preset in presets.all_presets()):
            return True
        cls.poll_message_set("There is no user preset to remove: presets built in cannot be removed")
        return False

    def invoke(self, context, _event):
        return context.window_manager.invoke_props_dialog(self)

    def execute(self, _context):
        try:
            name = presets.get(self.preset).name
            presets.remove_user_preset(self.preset)
        except presets.PresetGoneError as error:  # the list is reloaded: the stale entry is gone
            self.report({"ERROR"}, f"Preset '{name}': {error}; it is no longer listed")
            return {"CANCELLED"}
        except (presets.PresetError, OSError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        self.report({"INFO"}, f"Removed preset '{name}'")
        return {"FINISHED"}
