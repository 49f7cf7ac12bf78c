"""The ocean shading's part of the panel (the seeds' ocean and the open sea) and the open sea's
own: its Ocean modifier, swell, whitecaps and the camera's reach to its horizon."""

import bpy

from ..nodes.sea import ocean_shade
from ..nodes.sea.ocean_material import ocean_nodes
from ..water import camera_clip
from ..water.sea import open_sea
from .common import PARTS, draw_part, draw_surroundings

# The ocean shading's inputs the panel shows: (which group node, input name).
_OCEAN_INPUTS = (
    ("normal", "Bump Strength"),
    ("normal", "Tex Stretch"),
    ("shade", "Deep Color"),
    ("shade", "Glint Power"),
    ("shade", "Water Fresnel"),  # from version 8 of the shade
    ("shade", "Debug View"),
)
# The ocean shading's surroundings inputs (as the lake's): absent from groups before version 3.
_OCEAN_SURROUNDINGS = ("Absorption", "Foam Width", "Foam Amount", "Caustics", "Caustics Scale")

# The open sea's Ocean modifier settings the panel shows: (property, label).
_SEA_PROPS = (
    ("wind_velocity", "Wind Speed (m/s)"),
    ("wave_direction", "Wind Direction"),
    ("spectrum", "Spectrum"),
    ("choppiness", "Choppiness"),
    ("depth", "Depth"),
    ("random_seed", "Seed"),
)


def draw_ocean(layout, material):
    """The ocean shading's inputs: bump taps, deep colour, glint."""
    normal, shade = ocean_nodes(material)
    box = layout.box()
    box.label(text="Ocean", icon="MOD_OCEAN")
    box.use_property_split = True
    nodes = {"normal": normal, "shade": shade}
    for which, name in _OCEAN_INPUTS:
        if name in nodes[which].inputs:  # an older group lacks the newer inputs
            box.prop(nodes[which].inputs[name], "default_value", text=name)


def draw_ocean_surroundings(layout, obj, material):
    """The ocean's depth colour, shore foam and caustics, and what it measures them against."""
    _normal, shade = ocean_nodes(material)
    box = layout.box()
    box.label(text="Surroundings", icon="OUTLINER_COLLECTION")
    box.use_property_split = True
    for name in _OCEAN_SURROUNDINGS:
        if name in shade.inputs and name not in PARTS["caustics"]:
            box.prop(shade.inputs[name], "default_value", text=name)
    if "Caustics" in shade.inputs:  # a part: in the shader only while on
        draw_part(box, shade, "caustics", ocean_shade.FULL_SHADE_SPEC)
    draw_surroundings(box, obj)


def draw_sea(layout, obj, material):
    """The open sea's Ocean modifier settings and its whitecaps."""
    modifier, _fade = open_sea.sea_modifiers(obj)
    box = layout.box()
    box.label(text="Open Sea (Ocean modifier)", icon="MOD_OCEAN")
    box.use_property_split = True
    for prop, text in _SEA_PROPS:
        box.prop(modifier, prop, text=text)
    swell = open_sea.swell_values(obj)
    if swell["sea_swell_height"] > 0.0:
        height, period, (x, y) = (swell[key] for key in open_sea.SWELL_KEYS)
        text = f"Swell: {height:g} m, {period:g} s, to ({x:.2f}, {y:.2f})"
    else:
        text = "Swell: none"
    box.operator("object.water_sea_swell", text=text, icon="MOD_OCEAN")
    whitecaps = open_sea.whitecaps_input(material)
    if whitecaps is not None:
        box.prop(whitecaps, "default_value", text="Whitecaps")
    note = camera_clip.clip_note(bpy.context.scene, obj)
    if note is not None:  # the camera cuts the far sea off: offer to see it all
        clip_end = bpy.context.scene.camera.data.clip_end
        box.label(text=f"The camera's Clip End cuts the sea off at {clip_end:g} m", icon="ERROR")
        box.operator("object.water_camera_clip", icon="CAMERA_DATA")
