"""The open sea's numbers, from the wind: tile, FFT resolution, heights, periods, angle, and the
swell's. Plain Python.

No Blender here, so these are imported and tested without it (`tests/plain/`); `open_sea.py`
sets Blender's Ocean modifier from them.
"""

import math

from ...nodes.physics import G

GRAVITY = G
TILE_WAVES = 6.0
MIN_TILE = 20
MAX_TILE = 4000
RESOLUTIONS = (16, 12, 8)  # the modifier's resolution: an FFT of resolution^2 a side
BYTES_PER_CELL = 400  # the modifier's arrays (heights, chop, normals, Jacobian, foam), with margin
MEMORY_SHARE = 0.25  # of the free memory the FFT may take
# Periods. Blender's Pierson-Moskowitz spectrum (JONSWAP and TMA alike) gives each cell k of its
# FFT the frequency spectrum S(omega(k)) times an alignment term pow(|k.w| / k^2, 10 a) (4.2 to
# 5.2 divide by k^2 where k was meant): cos^(10 a) / k^(10 a) of the angle to the wind. A real
# sea's spectrum over wave numbers is S(omega) (d omega / dk) / k, S(omega) k^-1.5 in deep water;
# so alignment 0.15 makes Blender's spectrum exactly that (spread as cos^1.5 about the wind), and
# the sea's heights over time at a point Pierson and Moskowitz's: peak 0.877 g / U, significant
# height 0.21 U^2 / g (measured: `tests/test_sea_state.py`). (Alignment 0.5 made it k^-5: a peak
# period 1.24 times Pierson-Moskowitz's, and hardly any short waves.)
WIND_ALIGNMENT = 0.15
# No waves against the wind (Blender's `damping` 1: its default 0.5 sends a third of the sea's
# energy upwind with alignment 0.15).
WIND_DAMPING = 1.0
PM_PEAK = 0.877  # a fully grown sea's peak angular frequency, in g / U
PM_HEIGHT = 0.21  # its significant wave height, in U^2 / g
# The waves start to flatten a quarter of a tile from the centre and are gone at half a tile:
# no two points a tile apart both carry waves, so the tile cannot be seen to repeat.
FADE_START_TILES = 0.25
FADE_END_TILES = 0.5
# Height: a fully grown sea's significant wave height is 0.21 V^2 / g (Pierson-Moskowitz), a
# standard deviation of a quarter of that. Blender scales the modifier's heights so that the
# highest point of its tile at time 0 stands `wave_scale` high, so their standard deviation at
# `wave_scale` 1 is that of the seed's own waves: `open_sea.py` measures it on a copy of the
# modifier when it sets one. These are its typical values (mean over seeds 0-3 at 3, 6, 12 and
# 20 m/s, each seed within about 15% of it; 5.2.3, resolution 16, alignment 0.15, damping 1),
# used when it cannot be measured and for the crests' height (`open_sea.crest_height`).
HEIGHT_STD_AT_SCALE_1 = {
    "PHILLIPS": 0.26,
    "PIERSON_MOSKOWITZ": 0.26,
    "JONSWAP": 0.23,
    "TEXEL_MARSEN_ARSLOE": 0.23,
}
SPECTRA = {
    "phillips": "PHILLIPS",
    "pierson_moskowitz": "PIERSON_MOSKOWITZ",
    "jonswap": "JONSWAP",
    "tma": "TEXEL_MARSEN_ARSLOE",
}


def peak_wavelength(wind_speed):
    """Metres: the wind's wave length scale 2 pi V^2 / g (the tile holds TILE_WAVES of them; a
    grown sea's peak waves are 1 / 0.877^2 = 1.3 times longer, `sea_peak_wavelength`)."""
    return 2.0 * math.pi * wind_speed**2 / GRAVITY


def significant_height(wind_speed):
    """Metres: a fully grown sea's significant wave height, 4 standard deviations (0.21 U^2 / g)."""
    return PM_HEIGHT * wind_speed**2 / GRAVITY


def peak_period(wind_speed):
    """Seconds: a fully grown sea's peak period 2 pi U / (0.877 g)."""
    return 2.0 * math.pi * wind_speed / (PM_PEAK * GRAVITY) if wind_speed > 0 else 0.0


def sea_peak_wavelength(wind_speed):
    """Metres: a fully grown sea's peak waves in deep water, g Tp^2 / (2 pi)."""
    return GRAVITY * peak_period(wind_speed) ** 2 / (2.0 * math.pi)


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


def wave_scale(wind_speed, spectrum, std_at_scale_1=None):
    """The modifier's `wave_scale` giving a fully grown sea's heights for the wind: the height's
    standard deviation at `wave_scale` 1 measured (`std_at_scale_1`) or else typical."""
    return significant_height(wind_speed) / 4.0 / (std_at_scale_1 or HEIGHT_STD_AT_SCALE_1[spectrum])


def cell_size(wind_speed, resolution=None):
    """Metres between the FFT's samples: the finest detail the modifier gives."""
    return tile_size(wind_speed) / (resolution or ocean_resolution()) ** 2


def wave_angle(direction):
    """The modifier's `wave_direction` (radians) for waves travelling along `direction` (x, y) in
    the object's plane (the wind's way). Measured: the modifier's waves at angle a travel along
    (-cos a, sin a) in the object's plane (its simulation's z axis is the object's -y, and its
    waves with k along the wind run against k), so a = atan2(y, -x)."""
    x, y = direction[0], direction[1]
    return math.atan2(y, -x) if (x or y) else 0.0  # no direction: +Y, as the lake


def angle_direction(angle):
    """The unit (x, y) the modifier's waves at `wave_direction` `angle` travel along (`wave_angle`'s
    inverse)."""
    return (-math.cos(angle), math.sin(angle))


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


# The swell: waves raised far away, long and regular, from their own direction. A second Ocean
# modifier (`open_sea.set_swell`) on Blender's Phillips spectrum, exp(-1 / (k L)^2) k^-4 cos^(10 a)
# with L = V^2 / g, times exp(-(k l)^2) for its smallest wave l: with l = SWELL_NARROWNESS L its
# peak (of the spectrum over the FFT's cells) is at k0 with (1 / (k0 L))^2 - (k0 l)^2 = 2, and
# narrow (a standard deviation of about 1 / sqrt(8 * SWELL_NARROWNESS) in log k, 6%); alignment 1
# (cos^10, Blender's narrowest) and damping 1 keep it to its direction. Its tile holds
# SWELL_TILE_WAVES of its waves, so the FFT's cells near the peak are 6% apart in k. Its
# heights, as the sea's, are set from their standard deviation at `wave_scale` 1, measured on a
# copy of the modifier (else SWELL_STD_AT_SCALE_1, typical: seeds 0-5 gave 0.22 to 0.33).
SWELL_TILE_WAVES = 16
SWELL_NARROWNESS = 30.0
SWELL_ALIGNMENT = 1.0
SWELL_STD_AT_SCALE_1 = 0.28


def wavelength(period, depth=math.inf):
    """Metres: the length of waves of `period` seconds over `depth` metres (omega^2 = g k tanh(k d));
    in deep water g T^2 / (2 pi)."""
    omega = 2.0 * math.pi / period
    k = omega**2 / GRAVITY  # deep water
    if math.isfinite(depth):
        for _ in range(60):  # Newton on f(k) = g k tanh(k d) - omega^2, from the deep-water k
            t = math.tanh(k * depth)
            f = GRAVITY * k * t - omega**2
            df = GRAVITY * (t + k * depth * (1.0 - t * t))
            step = f / df
            k -= step
            if abs(step) < 1e-12 * k:
                break
    return 2.0 * math.pi / k


def swell_settings(height, period, direction, depth):
    """The swell's Ocean modifier settings (all but its `wave_scale`, time, seed and resolution):
    a dict of `spatial_size`, `wind_velocity`, `wave_scale_min`, `wave_direction`."""
    length = wavelength(period, depth)
    tile = max(1, round(SWELL_TILE_WAVES * length))
    k0 = 2.0 * math.pi * SWELL_TILE_WAVES / tile  # the FFT's own ring nearest the swell
    r = SWELL_NARROWNESS
    q = -1.0 + math.sqrt(1.0 + r * r)  # (k0 l)^2, from 1 / (k0 L)^2 - (k0 l)^2 = 2 and l = r L
    smallest = math.sqrt(q) / k0
    return {
        "spatial_size": tile,
        "wind_velocity": math.sqrt(GRAVITY * smallest / r),
        "wave_scale_min": smallest,
        "wave_direction": wave_angle(direction),
    }


def swell_wave_scale(height, std_at_scale_1=None):
    """The swell modifier's `wave_scale` for a significant height of `height` metres (4 standard
    deviations)."""
    return height / 4.0 / (std_at_scale_1 or SWELL_STD_AT_SCALE_1)
