"""Sidebar panel (3D view, tab "Water") for the active water object and the selected boats.

It draws the sockets of the material's group nodes directly: the node is the one source of truth,
so what the `.blend` holds is what shows. What each family draws is in its own module, as in
`water/` and `operators/`: `lake.py`, `sea.py` (ocean shading and the open sea), `under.py`,
`boats.py` (the boat tools, below the water's settings), `common.py` (what every kind has).
"""

import bpy

from ..nodes.material import water_node
from ..water import kind
from ..water.editable import why_not_editable
from ..water.repair import needs_repair
from ..water.values import water_material
from .boats import draw_boat_tools
from .common import draw_waves
from .lake import draw_lake
from .sea import draw_ocean, draw_ocean_surroundings, draw_sea
from .under import draw_underwater


class VIEW3D_PT_water_surface(bpy.types.Panel):
    """Shape the active water object; float the selected objects on it, keep it out of them,
    make them leave a wake"""

    bl_label = "Water Surface"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Water"

    def draw(self, context):
        layout = self.layout
        if water_material(context.active_object) is None:
            layout.label(text="The active object is not water", icon="INFO")
            layout.operator("object.water_add", icon="ADD")
        else:
            draw_water(layout, context)
            layout.use_property_split = False  # the lake's inputs split; the boat rows do not
        draw_boat_tools(layout, context)


def draw_water(layout, context):
    """The active water's own settings, by its kind (or only the way back, needing repair)."""
    obj = context.active_object
    material = water_material(obj)
    row = layout.row(align=True)
    row.label(text=f"Material: {material.name}", icon="MATERIAL")
    row.operator("object.water_remove", text="", icon="TRASH")
    why = why_not_editable(obj, material)
    if why is not None:
        layout.label(text=why, icon="LIBRARY_DATA_DIRECT")
    problem = needs_repair(material)
    if problem is not None:
        # A replaced group, or one missing sockets: no input is drawn, only the way back.
        layout.label(text=problem, icon="ERROR")
        layout.operator("object.water_repair", icon="TOOL_SETTINGS")
        if kind.allows(obj, "waves"):
            draw_waves(layout, obj)
        return
    if kind.allows(obj, "presets"):  # lake shading
        draw_lake(layout, context, material, water_node(material))
    else:  # ocean shading: its own inputs, the sea's or waves
        draw_ocean(layout, material)
        draw_ocean_surroundings(layout, obj, material)
        if kind.allows(obj, "whitecaps"):
            draw_sea(layout, obj, material)
        if kind.allows(obj, "waves"):
            draw_waves(layout, obj)
    draw_underwater(layout, obj)
