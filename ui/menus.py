"""Entries for Add > Mesh and the 3D view's Add menu."""

import bpy


def draw_add_entry(self, _context):
    self.layout.operator("object.water_add", text="Water Surface", icon="MOD_OCEAN")


_MENUS = ("VIEW3D_MT_mesh_add", "VIEW3D_MT_add")


def register():
    for name in _MENUS:
        getattr(bpy.types, name).append(draw_add_entry)


def unregister():
    for name in reversed(_MENUS):
        getattr(bpy.types, name).remove(draw_add_entry)
