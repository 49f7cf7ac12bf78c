"""The open sea: Blender's own Ocean modifier, set from an artist's values, then `Water Sea Fade`.

Blender's Ocean modifier (FFT waves on the Phillips, Pierson-Moskowitz, JONSWAP or TMA
spectrum, with choppiness and foam) displaces the sea's mesh (`sea_mesh.py`); it has no shading
and no horizon of its own. This module chooses its tile and resolution, drives its time by the
scene's clock (a simple expression, no Python at render) and turns its foam on; `Water Sea
Fade` (`nodes/sea_fade.py`) then flattens the far sea and hands the foam to the ocean shading
as `water_whitecaps`.

Choices, from the wind speed V (m/s): the waves' peak length is about 2 pi V^2 / g; the tile
(`spatial_size`) holds TILE_WAVES of them, at least MIN_TILE metres; the FFT grid is
`resolution`^2 cells a side, the largest of RESOLUTIONS the free memory holds. The waves are
aligned with the wind (`wave_alignment`) and the wind direction (x, y) becomes the modifier's
angle atan2(-y, x) (the simulation's z axis is the object's -y).
"""

import bpy

from ..nodes import SPECS, sea_fade
from ..nodes.builder import ensure_group
from ..nodes.material import drive_clock, drive_socket
from ..nodes.ocean_material import ocean_nodes
from ..nodes.ownership import role_of
from .editable import check_editable
from .sea_math import (
    FADE_END_TILES,
    FADE_START_TILES,
    FOAM_BIAS,
    HEIGHT_STD_AT_SCALE_1,
    RESOLUTIONS,
    SPECTRA,
    WIND_ALIGNMENT,
    ocean_resolution,
    slope_expressions,
    tile_size,
    wave_angle,
    wave_scale,
)
from .waves import set_wave_input

OCEAN_MODIFIER = "Water Ocean"
FADE_MODIFIER = "Water Sea Fade"


class OpenSeaError(RuntimeError):
    """The open sea cannot be set up as asked (a one-line message)."""


def sea_modifiers(obj):
    """(Ocean modifier, fade modifier) of an open sea, or None: the fade is found by its group's
    mark, the Ocean modifier is the one just before it."""
    if obj is None or obj.type != "MESH":
        return None
    modifiers = list(obj.modifiers)
    for index, modifier in enumerate(modifiers):
        group = modifier.node_group if modifier.type == "NODES" else None
        if group is not None and role_of(group) == sea_fade.NAME and index > 0:
            if modifiers[index - 1].type == "OCEAN":
                return modifiers[index - 1], modifier
    return None


# The Ocean modifier settings `set_sea` chooses: what a copy of the sea's waves needs.
SETTINGS = (
    "geometry_mode",
    "spectrum",
    "wind_velocity",
    "wave_direction",
    "wave_alignment",
    "choppiness",
    "wave_scale",
    "depth",
    "random_seed",
    "spatial_size",
    "resolution",
    "viewport_resolution",
    "use_normals",
    "use_foam",
    "foam_layer_name",
    "foam_coverage",
)


def copy_settings(source, target):
    """Gives the Ocean modifier `target` the wave settings of `source` (its time aside)."""
    for prop in SETTINGS:
        setattr(target, prop, getattr(source, prop))


def is_open_sea(obj):
    return sea_modifiers(obj) is not None


def set_sea(obj, values, scene):
    """Adds (or updates) the Ocean modifier and the fade on `obj` from preset values (`sea_*`
    keys, `wind_direction`, clamped beforehand)."""
    check_editable(obj, obj.data)
    found = sea_modifiers(obj)
    if found is None:
        ocean = obj.modifiers.new(OCEAN_MODIFIER, "OCEAN")
        fade = obj.modifiers.new(FADE_MODIFIER, "NODES")
        fade.node_group = ensure_group(SPECS[sea_fade.NAME], SPECS)
    else:
        ocean, fade = found
    wind = values["sea_wind_speed"]
    resolution = ocean_resolution()
    ocean.geometry_mode = "DISPLACE"
    ocean.spectrum = SPECTRA[values["sea_spectrum"]]
    ocean.wind_velocity = wind
    ocean.wave_direction = wave_angle(values["wind_direction"])
    ocean.wave_alignment = WIND_ALIGNMENT
    ocean.choppiness = values["sea_choppiness"]
    ocean.depth = values["sea_depth"]
    ocean.random_seed = values["sea_seed"]
    ocean.spatial_size = tile_size(wind)
    ocean.resolution = ocean.viewport_resolution = resolution
    ocean.use_normals = True
    ocean.use_foam = True
    ocean.foam_layer_name = sea_fade.OCEAN_FOAM_ATTRIBUTE
    ocean.foam_coverage = FOAM_BIAS
    ocean.wave_scale = wave_scale(wind, ocean.spectrum)
    drive_clock(ocean, scene, prop="time")
    _set_fade(fade, FADE_START_TILES * ocean.spatial_size, FADE_END_TILES * ocean.spatial_size)
    drive_slopes(obj, ocean, first=found is None)
    obj.update_tag()


def drive_slopes(obj, ocean, first=False):
    """The ocean shading's bump follows the sea's wind: its slopes along and across the wind are
    Cox and Munk's for the wind speed, its wind direction the modifier's (simple-expression
    drivers on the modifier's settings, so changing the wind in the panel changes them too).
    Bump Strength becomes 1 when the sea is made (a multiplier the artist may change after)."""
    normal = next((nodes[0] for slot in obj.material_slots if (nodes := ocean_nodes(slot.material))), None)
    if normal is None:
        return
    if "Even Slopes" not in normal.inputs:  # a group from before version 3: left as it is
        return
    if first:
        normal.inputs["Bump Strength"].default_value = 1.0
        normal.inputs["Even Slopes"].default_value = 1.0
    path = f'modifiers["{bpy.utils.escape_identifier(ocean.name)}"]'
    speed = [("u", "OBJECT", obj, f"{path}.wind_velocity")]
    angle = [("a", "OBJECT", obj, f"{path}.wave_direction")]
    along, across = slope_expressions()
    drive_socket(normal.inputs["Slope Along Wind"], None, along, speed)
    drive_socket(normal.inputs["Slope Across Wind"], None, across, speed)
    # The modifier's angle is atan2(-y, x) of the wind (`wave_angle`).
    drive_socket(normal.inputs["Wind Direction"], 0, "cos(a)", angle)
    drive_socket(normal.inputs["Wind Direction"], 1, "-sin(a)", angle)


def _set_fade(modifier, start, end):
    set_wave_input(modifier, "Fade Start", float(start))
    set_wave_input(modifier, "Fade End", float(end))


def crest_height(obj):
    """Metres the open sea's crests may reach above its rest plane (its significant wave height,
    object units), 0 for any other water."""
    found = sea_modifiers(obj)
    if found is None:
        return 0.0
    ocean = found[0]
    return 4.0 * ocean.wave_scale * HEIGHT_STD_AT_SCALE_1[ocean.spectrum]


def whitecaps_input(material):
    """The ocean shading's `Whitecaps` input, or None."""
    from ..nodes.ocean_material import ocean_nodes

    nodes = ocean_nodes(material)
    return nodes[1].inputs.get("Whitecaps") if nodes else None


def sea_memory_note(resolution=None):
    """A note when the free memory chose a coarser FFT than the best one, else None."""
    resolution = resolution or ocean_resolution()
    if resolution < RESOLUTIONS[0]:
        return f"ocean resolution lowered to {resolution}: the free memory holds no finer waves"
    return None
