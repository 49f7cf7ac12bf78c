"""The sidebar panel and menu entries; the panel's parts by family (see `panel.py`)."""

import bpy

from . import lake, menus, panel

classes = (lake.WATER_MT_presets, panel.VIEW3D_PT_water_surface)

_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()
    menus.register()


def unregister():
    menus.unregister()
    _unregister_classes()
