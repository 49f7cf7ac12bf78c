"""Operators, one job a module, grouped by family as `water/` is: what every water has here, the
lake's own, the boats', the open sea's and the view from below in packages; the shared polls,
properties, selection pass and switches (`_poll`, `_props`, `_selected`, `_switch`) at the top.
Registered in order, unregistered in reverse, with the old ids kept working (`_aliases`)."""

import bpy

from . import boats, lake, sea, under
from ._aliases import aliases
from .add_water import OBJECT_OT_water_add
from .camera_clip import OBJECT_OT_water_camera_clip
from .mirror_setup import OBJECT_OT_water_mirror_setup
from .parts import OBJECT_OT_water_part_switch
from .remove import OBJECT_OT_water_remove
from .repair import OBJECT_OT_water_repair
from .surroundings import OBJECT_OT_water_surroundings_set
from .waves import OBJECT_OT_water_waves_add

classes = (
    OBJECT_OT_water_add,
    OBJECT_OT_water_mirror_setup,
    OBJECT_OT_water_waves_add,
    OBJECT_OT_water_repair,
    OBJECT_OT_water_surroundings_set,
    OBJECT_OT_water_part_switch,
    OBJECT_OT_water_remove,
    OBJECT_OT_water_camera_clip,
    *lake.classes,
    *boats.classes,
    *sea.classes,
    *under.classes,
)
classes += aliases(classes)

_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()


def unregister():
    _unregister_classes()
