"""The sidebar panel and menu entries."""

import bpy

from . import panel

classes = (panel.VIEW3D_PT_water_surface,)

_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()


def unregister():
    _unregister_classes()
