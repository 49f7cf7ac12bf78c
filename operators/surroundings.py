"""`object.water_surroundings_set`: choose the collection whose objects the water sees (depth, foam)."""

import bpy

from ..water import surroundings
from ..water.editable import NotEditableError
from . import _poll

_items = []  # kept alive for Blender's dynamic enum


def _collection_items(_self, _context):
    _items[:] = [
        ("AUTO", "Automatic", "The objects reaching below this water, gathered again", "AUTO", 0)
    ] + [
        (c.name, c.name, f"The objects of '{c.name}'", "OUTLINER_COLLECTION", i + 1)
        for i, c in enumerate(bpy.data.collections)
    ]
    return _items


class OBJECT_OT_water_surroundings_set(bpy.types.Operator):
    """Choose the collection whose objects the water measures its depth and shore foam against"""

    bl_idname = "object.water_surroundings_set"
    bl_label = "Water Surroundings"
    bl_options = {"REGISTER", "UNDO"}
    bl_property = "collection"

    collection: bpy.props.EnumProperty(name="Collection", items=_collection_items)

    @classmethod
    def poll(cls, context):
        return _poll.any_water(cls, context, "surroundings")

    def invoke(self, context, _event):
        context.window_manager.invoke_search_popup(self)
        return {"RUNNING_MODAL"}

    def execute(self, context):
        water = context.active_object
        chosen = None if self.collection == "AUTO" else bpy.data.collections.get(self.collection)
        try:
            changes = surroundings.ensure_surroundings(water, context.scene, collection=chosen)
        except (surroundings.SurroundingsError, NotEditableError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        done = "; ".join(changes) or "nothing changed"
        self.report({"INFO"}, f"Surroundings of '{water.name}': {done}")
        coarse = surroundings.coarse_grid_note(water)
        if coarse:
            self.report({"WARNING"}, coarse)
        return {"FINISHED"}
