"""Operators, one a module; registered in order, unregistered in reverse."""

import bpy

classes = ()

_register_classes, _unregister_classes = bpy.utils.register_classes_factory(classes)


def register():
    _register_classes()


def unregister():
    _unregister_classes()
