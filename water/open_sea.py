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

import math

from ..nodes import SPECS, sea_fade
from ..nodes.builder import ensure_group
from ..nodes.material import drive_clock
from ..nodes.ownership import role_of
from .editable import check_editable
from .waves import set_wave_input

OCEAN_MODIFIER = "Water Ocean"
FADE_MODIFIER = "Water Sea Fade"
GRAVITY = 9.81
TILE_WAVES = 6.0
MIN_TILE = 20
MAX_TILE = 4000
RESOLUTIONS = (16, 12, 8)  # the modifier's resolution: an FFT of resolution^2 a side
BYTES_PER_CELL = 400  # the modifier's arrays (heights, chop, normals, Jacobian, foam), with margin
MEMORY_SHARE = 0.25  # of the free memory the FFT may take
WIND_ALIGNMENT = 0.5
# The waves start to flatten a quarter of a tile from the centre and are gone at half a tile:
# no two points a tile apart both carry waves, so the tile cannot be seen to repeat.
FADE_START_TILES = 0.25
FADE_END_TILES = 0.5
# Height: a fully grown sea's significant wave height is 0.21 V^2 / g (Pierson-Moskowitz), a
# standard deviation of a quarter of that. The modifier's heights at `wave_scale` 1 hardly grow
# with the wind; their standard deviation there, measured per spectrum (a tile of six peak
# waves, resolution 16, 3 to 20 m/s), sets `wave_scale`.
HEIGHT_STD_AT_SCALE_1 = {
    "PHILLIPS": 0.3,
    "PIERSON_MOSKOWITZ": 0.34,
    "JONSWAP": 0.16,
    "TEXEL_MARSEN_ARSLOE": 0.16,
}
# Foam: the modifier's own coverage bias, 0. (A negative bias measured well on the evaluated mesh
# but left no foam at all in renders: the render's foam is weaker than the viewport's.)
FOAM_BIAS = 0.0
SPECTRA = {
    "phillips": "PHILLIPS",
    "pierson_moskowitz": "PIERSON_MOSKOWITZ",
    "jonswap": "JONSWAP",
    "tma": "TEXEL_MARSEN_ARSLOE",
}


class OpenSeaError(RuntimeError):
    """The open sea cannot be set up as asked (a one-line message)."""


def peak_wavelength(wind_speed):
    """Metres: the length of the waves a wind of `wind_speed` m/s raises most (2 pi V^2 / g)."""
    return 2.0 * math.pi * wind_speed**2 / GRAVITY


def tile_size(wind_speed):
    """The modifier's `spatial_size` (whole metres) for a wind: TILE_WAVES peak waves across."""
    return int(min(MAX_TILE, max(MIN_TILE, math.ceil(TILE_WAVES * peak_wavelength(wind_speed)))))


def _available_bytes():
    try:
        with open("/proc/meminfo", encoding="ascii") as meminfo:
            return next(int(line.split()[1]) * 1024 for line in meminfo if line.startswith("MemAvailable"))
    except (OSError, StopIteration, ValueError):
        return None


def ocean_resolution(available=None):
    """The largest of RESOLUTIONS whose FFT fits in MEMORY_SHARE of the free memory (or the least)."""
    available = _available_bytes() if available is None else available
    if available is None:
        return RESOLUTIONS[0]
    for resolution in RESOLUTIONS:
        if resolution**4 * BYTES_PER_CELL <= MEMORY_SHARE * available:
            return resolution
    return RESOLUTIONS[-1]


def wave_scale(wind_speed, spectrum):
    """The modifier's `wave_scale` giving a fully grown sea's heights for the wind."""
    target = 0.21 * wind_speed**2 / GRAVITY / 4.0
    return target / HEIGHT_STD_AT_SCALE_1[spectrum]


def cell_size(wind_speed, resolution=None):
    """Metres between the FFT's samples: the finest detail the modifier gives."""
    return tile_size(wind_speed) / (resolution or ocean_resolution()) ** 2


def wave_angle(wind_direction):
    """The modifier's `wave_direction` (radians) for a wind direction (x, y) in the object's plane."""
    x, y = wind_direction[0], wind_direction[1]
    return math.atan2(-y, x) if (x or y) else -math.pi / 2  # no direction: +Y, as the lake


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
    obj.update_tag()


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
