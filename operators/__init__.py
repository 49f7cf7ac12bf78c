"""Operators, one job a module; registered in order, unregistered in reverse."""

import bpy

from .add_water import OBJECT_OT_water_surface_add
from .camera_ops import OBJECT_OT_water_camera_clip
from .caustics_ops import OBJECT_OT_water_physical_caustics
from .float_ops import OBJECT_OT_water_float, OBJECT_OT_water_float_stop
from .keep_out_ops import OBJECT_OT_water_keep_out, OBJECT_OT_water_let_in
from .link_ops import OBJECT_OT_water_surface_bump_set, OBJECT_OT_water_surface_sun_set
from .mirror_setup import OBJECT_OT_water_mirror_setup
from .part_ops import OBJECT_OT_water_part_switch
from .preset_ops import (
    OBJECT_OT_water_surface_preset_add,
    OBJECT_OT_water_surface_preset_apply,
    OBJECT_OT_water_surface_preset_remove,
)
from .remove_ops import OBJECT_OT_water_remove
from .repair_ops import OBJECT_OT_water_surface_repair
from .surroundings_ops import OBJECT_OT_water_surroundings_set
from .swell_ops import OBJECT_OT_water_sea_swell
from .underwater_ops import OBJECT_OT_water_underwater
from .wake_ops import OBJECT_OT_water_wake_add, OBJECT_OT_water_wake_bake, OBJECT_OT_water_wake_remove
from .waves_ops import OBJECT_OT_water_waves_add

classes = (
    OBJECT_OT_water_surface_add,
    OBJECT_OT_water_mirror_setup,
    OBJECT_OT_water_surface_preset_apply,
    OBJECT_OT_water_surface_preset_add,
    OBJECT_OT_water_surface_preset_remove,
    OBJECT_OT_water_surface_sun_set,
    OBJECT_OT_water_surface_bump_set,
    OBJECT_OT_water_waves_add,
    OBJECT_OT_water_surface_repair,
    OBJECT_OT_water_surroundings_set,
    OBJECT_OT_water_physical_caustics,
    OBJECT_OT_water_part_switch,
    OBJECT_OT_water_float,
    OBJECT_OT_water_float_stop,
    OBJECT_OT_water_keep_out,
    OBJECT_OT_water_let_in,
    OBJECT_OT_water_wake_add,
    OBJECT_OT_water_wake_remove,
    OBJECT_OT_water_wake_bake,
    OBJECT_OT_water_remove,
    OBJECT_OT_water_camera_clip,
    OBJECT_OT_water_sea_swell,
    OBJECT_OT_water_underwater,
)

_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()


def unregister():
    _unregister_classes()
