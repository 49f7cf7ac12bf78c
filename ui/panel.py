"""Sidebar panel (3D view, tab "Water")."""

import bpy


class VIEW3D_PT_water_surface(bpy.types.Panel):
    """Shape the active water object."""

    bl_label = "Water Surface"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Water"

    def draw(self, context):
        self.layout.label(text="Add water from Add > Mesh > Water Surface")
