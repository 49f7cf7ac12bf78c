"""The open sea: Blender's own Ocean modifier, set from an artist's values, then `Water Sea Fade`.

Blender's Ocean modifier (FFT waves on the Phillips, Pierson-Moskowitz, JONSWAP or TMA
spectrum, with choppiness and foam) displaces the sea's mesh (`sea_mesh.py`); it has no shading
and no horizon of its own. This module chooses its tile and resolution, drives its time by the
scene's clock (a simple expression, no Python at render); `Water Sea Fade`
(`nodes/sea/sea_fade.py`) then flattens the far sea and marks the highest crests for the ocean
shading's whitecaps (`water_whitecaps`; the modifier's own foam is off: not read).

Choices, from the wind speed V (m/s): the tile (`spatial_size`) holds TILE_WAVES lengths
2 pi V^2 / g (4.6 of a grown sea's peak waves), at least MIN_TILE metres; the FFT grid is
`resolution`^2 cells a side, the largest of RESOLUTIONS the free memory holds. The alignment
and damping make Blender's spectrum the grown sea's (`sea_math.WIND_ALIGNMENT`: its peak period
and heights over time), the waves travel along the wind direction (x, y) (`sea_math.wave_angle`),
and `wave_scale` gives the sea its significant height 0.21 V^2 / g, from the heights' spread at
`wave_scale` 1 measured on a copy of the modifier (`height_std_at_scale_1`).

A swell (`sea_swell_height` above 0) is a second Ocean modifier, `Water Swell`, just before
`Water Ocean`: long regular waves of `sea_swell_period` from `sea_swell_direction`, on top of the
wind's sea (`set_swell`, numbers in `sea_math.swell_settings`); without it there is none.
"""

import math

import bpy
import numpy as np

from ...nodes import SPECS
from ...nodes.builder import ensure_group
from ...nodes.material import drive_clock, drive_socket
from ...nodes.ownership import role_of
from ...nodes.sea import sea_fade
from ...nodes.sea.ocean_material import ocean_nodes
from ..editable import check_editable
from ..errors import WaterError
from ..waves import set_wave_input
from .sea_clock import key_clock, unkey_clock
from .sea_math import (
    FADE_END_TILES,
    FADE_START_TILES,
    GRAVITY,
    HEIGHT_STD_AT_SCALE_1,
    RESOLUTIONS,
    SPECTRA,
    SWELL_ALIGNMENT,
    SWELL_STD_AT_SCALE_1,
    SWELL_TILE_WAVES,
    WIND_ALIGNMENT,
    WIND_DAMPING,
    angle_direction,
    ocean_resolution,
    slope_expressions,
    swell_settings,
    swell_wave_scale,
    tile_size,
    wave_angle,
    wave_scale,
)
from .whitecaps import drive_whitecaps

OCEAN_MODIFIER = "Water Ocean"
FADE_MODIFIER = "Water Sea Fade"
SWELL_MODIFIER = "Water Swell"
# The swell's values as asked, on the sea object (the panel shows them, a change starts from them).
SWELL_PROPERTY = "water_sea_swell"
SWELL_KEYS = ("sea_swell_height", "sea_swell_period", "sea_swell_direction")


class OpenSeaError(WaterError, RuntimeError):
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
    "damping",
    "wave_scale_min",
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
    ocean.damping = WIND_DAMPING
    ocean.choppiness = values["sea_choppiness"]
    ocean.depth = values["sea_depth"]
    ocean.random_seed = values["sea_seed"]
    ocean.spatial_size = tile_size(wind)
    ocean.resolution = ocean.viewport_resolution = resolution
    ocean.use_normals = True
    # The whitecaps come from the crests' heights (`sea_fade.py`): the modifier's own foam (its
    # Jacobian, per frame) is not read, so not computed.
    ocean.use_foam = False
    ocean.wave_scale = wave_scale(wind, ocean.spectrum, height_std_at_scale_1(ocean))
    drive_clock(ocean, scene, prop="time")
    key_clock(obj, ocean, scene)
    _set_fade(fade, FADE_START_TILES * ocean.spatial_size, FADE_END_TILES * ocean.spatial_size)
    drive_slopes(obj, ocean, first=found is None)
    if "sea_swell_height" in values:
        set_swell(obj, {key: values[key] for key in SWELL_KEYS}, scene)
    obj.update_tag()


def height_std_at_scale_1(ocean):
    """The standard deviation of the heights the Ocean modifier `ocean` gives at `wave_scale` 1,
    over its whole tile; None when it cannot be measured (then `sea_math`'s typical values stand).

    Blender scales its heights by the highest point of the tile at time 0, so this depends on
    the seed (about 15% either way). Measured on a copy: a grid of the FFT's own cells over one
    tile with the same waves (no chop, time 0), in a scene of its own evaluated once (nothing
    else is), all removed after. With damping 1 every wave runs one way only, so the spread over
    the tile at time 0 is also the spread over time at any point."""
    cells = max(1, ocean.resolution) ** 2
    step = ocean.spatial_size / cells
    made = []  # (collection, block), removed in reverse
    try:
        scene = bpy.data.scenes.new("Water Sea Measure")
        made.append((bpy.data.scenes, scene))
        mesh = bpy.data.meshes.new("Water Sea Measure")
        made.append((bpy.data.meshes, mesh))
        axis = np.arange(cells, dtype=np.float64) * step
        x, y = np.meshgrid(axis, axis)
        co = np.zeros((x.size, 3), dtype=np.float32)
        co[:, 0], co[:, 1] = x.ravel(), y.ravel()
        mesh.vertices.add(x.size)
        mesh.vertices.foreach_set("co", co.ravel())
        obj = bpy.data.objects.new("Water Sea Measure", mesh)
        made.append((bpy.data.objects, obj))
        scene.collection.objects.link(obj)
        copy = obj.modifiers.new("Measure", "OCEAN")
        copy_settings(ocean, copy)
        copy.choppiness = 0.0
        copy.wave_scale = 1.0
        copy.time = 0.0
        copy.use_foam = copy.use_normals = False
        copy.resolution = copy.viewport_resolution = ocean.resolution
        with bpy.context.temp_override(scene=scene, view_layer=scene.view_layers[0]):
            evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
            heights = np.zeros(len(evaluated.vertices) * 3)
            evaluated.vertices.foreach_get("co", heights)
        std = float(heights[2::3].std())
    except (RuntimeError, TypeError, ValueError, AttributeError):  # no context, data not editable
        return None
    finally:
        for blocks, block in reversed(made):
            blocks.remove(block)
    return std if math.isfinite(std) and std > 1e-6 else None


def swell_modifier(obj):
    """The open sea's swell (the Ocean modifier just before its own), or None."""
    found = sea_modifiers(obj)
    if found is None:
        return None
    modifiers = list(obj.modifiers)
    index = modifiers.index(found[0])
    return modifiers[index - 1] if index > 0 and modifiers[index - 1].type == "OCEAN" else None


def swell_values(obj):
    """The swell's values (`SWELL_KEYS`): as last asked, else read back from its modifier (its
    height typical, `SWELL_STD_AT_SCALE_1`); height 0 without a swell."""
    from ...presets import schema

    values = {key: schema.BY_KEY[key].default for key in SWELL_KEYS}
    swell = swell_modifier(obj)
    if swell is None:
        values["sea_swell_height"] = 0.0
        return values
    stored = obj.get(SWELL_PROPERTY)
    try:
        return dict(zip(SWELL_KEYS, (float(stored[0]), float(stored[1]), tuple(map(float, stored[2:4])))))
    except (TypeError, ValueError, IndexError, KeyError):  # none kept, or not as the add-on keeps it
        pass
    k = 2.0 * math.pi * SWELL_TILE_WAVES / max(swell.spatial_size, 1)
    omega = math.sqrt(GRAVITY * k * math.tanh(k * max(swell.depth, 1e-3)))
    values["sea_swell_height"] = round(4.0 * swell.wave_scale * SWELL_STD_AT_SCALE_1, 2)
    values["sea_swell_period"] = round(2.0 * math.pi / omega, 2)
    values["sea_swell_direction"] = tuple(round(v, 3) for v in angle_direction(swell.wave_direction))
    return values


def change_swell(obj, values, scene=None):
    """Changes the open sea `obj`'s swell from `values` (any of `SWELL_KEYS`, from a script, the
    operator or the panel): checked and clamped, the rest kept as they were. Height 0 removes it.
    Returns the change in words. OpenSeaError when `obj` is no open sea."""
    from ...presets import schema

    if sea_modifiers(obj) is None:
        raise OpenSeaError(f"'{getattr(obj, 'name', obj)}' is not an open sea")
    unknown = set(values) - set(SWELL_KEYS)
    if unknown:
        raise schema.PresetError(f"unknown swell value(s): {', '.join(sorted(unknown))}")
    given = {key: value for key, value in values.items() if value is not None}
    schema.check_types(given)
    asked = {**swell_values(obj), **schema.clamp_values(given)}
    return set_swell(obj, asked, scene or bpy.context.scene)


def set_swell(obj, values, scene):
    """Adds, updates or (height 0) removes the open sea's swell from clamped values (`SWELL_KEYS`):
    an Ocean modifier just before the sea's own, its time on `scene`'s clock, its depth, seed and
    resolution the sea's. Returns the change in words."""
    check_editable(obj)
    ocean, _fade = sea_modifiers(obj)
    swell = swell_modifier(obj)
    height = values["sea_swell_height"]
    if height <= 0.0:
        if SWELL_PROPERTY in obj:
            del obj[SWELL_PROPERTY]
        if swell is None:
            return "no swell"
        swell.driver_remove("time")
        unkey_clock(obj, swell)
        obj.modifiers.remove(swell)
        return f"swell removed from '{obj.name}'"
    if swell is None:
        swell = obj.modifiers.new(SWELL_MODIFIER, "OCEAN")
        modifiers = list(obj.modifiers)
        obj.modifiers.move(modifiers.index(swell), modifiers.index(ocean))
    swell.geometry_mode = "DISPLACE"
    swell.spectrum = "PHILLIPS"
    for prop, value in swell_settings(
        height, values["sea_swell_period"], values["sea_swell_direction"], ocean.depth
    ).items():
        setattr(swell, prop, value)
    swell.wave_alignment = SWELL_ALIGNMENT
    swell.damping = 1.0
    swell.choppiness = 0.0  # a swell's waves are low and round
    swell.depth = ocean.depth
    swell.random_seed = ocean.random_seed
    swell.resolution = swell.viewport_resolution = ocean.resolution
    swell.use_normals = False
    swell.use_foam = False
    swell.wave_scale = swell_wave_scale(height, height_std_at_scale_1(swell))
    drive_clock(swell, scene, prop="time")
    key_clock(obj, swell, scene)
    direction = values["sea_swell_direction"]
    obj[SWELL_PROPERTY] = [float(height), float(values["sea_swell_period"]), *map(float, direction[:2])]
    obj.update_tag()
    return (
        f"swell of {height:g} m every {values['sea_swell_period']:g} s "
        f"towards ({direction[0]:.2f}, {direction[1]:.2f}) on '{obj.name}'"
    )


def drive_slopes(obj, ocean, first=False):
    """The ocean shading's bump follows the sea's wind: its slopes along and across the wind are
    Cox and Munk's for the wind speed, its wind direction the modifier's (simple-expression
    drivers on the modifier's settings, so changing the wind in the panel changes them too).
    Bump Strength becomes 1 when the sea is made (a multiplier the artist may change after), and
    the shade's Water Fresnel 1 (water's own reflectance).
    The whitecaps' coverage follows the wind the same way (`whitecaps.py`)."""
    drive_whitecaps(obj, ocean, sea_modifiers(obj)[1])
    normal = next((nodes[0] for slot in obj.material_slots if (nodes := ocean_nodes(slot.material))), None)
    if normal is None:
        return
    if "Even Slopes" not in normal.inputs:  # a group from before version 3: left as it is
        return
    if first:
        normal.inputs["Bump Strength"].default_value = 1.0
        normal.inputs["Even Slopes"].default_value = 1.0
        shade = next(nodes[1] for slot in obj.material_slots if (nodes := ocean_nodes(slot.material)))
        if "Water Fresnel" in shade.inputs:  # water's own reflectance: the near sea dark, the far bright
            shade.inputs["Water Fresnel"].default_value = 1.0
    path = f'modifiers["{bpy.utils.escape_identifier(ocean.name)}"]'
    speed = [("u", "OBJECT", obj, f"{path}.wind_velocity")]
    angle = [("a", "OBJECT", obj, f"{path}.wave_direction")]
    along, across = slope_expressions()
    drive_socket(normal.inputs["Slope Along Wind"], None, along, speed)
    drive_socket(normal.inputs["Slope Across Wind"], None, across, speed)
    # The modifier's waves at angle a travel along (-cos a, sin a): the wind's way (`wave_angle`).
    drive_socket(normal.inputs["Wind Direction"], 0, "-cos(a)", angle)
    drive_socket(normal.inputs["Wind Direction"], 1, "sin(a)", angle)


def _set_fade(modifier, start, end):
    set_wave_input(modifier, "Fade Start", float(start))
    set_wave_input(modifier, "Fade End", float(end))


def crest_height(obj):
    """Metres the open sea's crests may reach above its rest plane (its significant wave height,
    the swell's added, object units; typical: a seed's may differ by 15%), 0 for any other water."""
    found = sea_modifiers(obj)
    if found is None:
        return 0.0
    ocean = found[0]
    height = 4.0 * ocean.wave_scale * HEIGHT_STD_AT_SCALE_1[ocean.spectrum]
    swell = swell_modifier(obj)
    return height + (4.0 * swell.wave_scale * SWELL_STD_AT_SCALE_1 if swell is not None else 0.0)


def whitecaps_input(material):
    """The ocean shading's `Whitecaps` input, or None."""
    from ...nodes.sea.ocean_material import ocean_nodes

    nodes = ocean_nodes(material)
    return nodes[1].inputs.get("Whitecaps") if nodes else None


def sea_memory_note(resolution=None):
    """A note when the free memory chose a coarser FFT than the best one, else None."""
    resolution = resolution or ocean_resolution()
    if resolution < RESOLUTIONS[0]:
        return f"ocean resolution lowered to {resolution}: the free memory holds no finer waves"
    return None
