"""The open sea's numbers, from the wind: tile, FFT resolution, heights, angle. Plain Python.

No Blender here, so these are imported and tested without it (`tests/plain/`); `open_sea.py`
sets Blender's Ocean modifier from them.
"""

import math

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


# Slopes: Cox and Munk (1954) measured the sea's mean square slope (clean surface) as
# 3.16e-3 U upwind and 0.003 + 1.92e-3 U crosswind at a wind of U m/s. The open sea's shading
# makes its bump's slopes even (`Even Slopes` 1: a mean square of 1 each way, the Ocean
# modifier's own slopes being small beside them at 5 cm) and scales them by the square roots of
# these along and across the wind (`Slope Along Wind`, `Slope Across Wind`).
COX_MUNK_UPWIND = 3.16e-3  # per m/s
COX_MUNK_CROSSWIND = (0.003, 1.92e-3)  # constant, per m/s


def cox_munk_slopes(wind_speed):
    """(upwind, crosswind) mean square slopes of a clean sea at `wind_speed` m/s (Cox and Munk)."""
    return COX_MUNK_UPWIND * wind_speed, COX_MUNK_CROSSWIND[0] + COX_MUNK_CROSSWIND[1] * wind_speed


def slope_expressions():
    """Simple-expression drivers (variable `u`, the wind speed) for `Slope Along Wind` and
    `Slope Across Wind`: the square roots of Cox and Munk's mean square slopes."""
    return (
        f"sqrt({COX_MUNK_UPWIND:g} * u)",
        f"sqrt({COX_MUNK_CROSSWIND[0]:g} + {COX_MUNK_CROSSWIND[1]:g} * u)",
    )
