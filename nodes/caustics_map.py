"""The caustic tile: sunlight refracted through the bump map's surface, gathered on a bed below
(numpy only, no ``bpy``).

The `Water Surface` group multiplies what it shows through the water by this pattern, so it is
made from the very surface the bump map draws (`bump_map.water_height_field`, same seed): light
falls straight down on a grid of points finer than the tile, bends at each point by Snell's law
(water IOR 1.33) through the surface normal there, travels ``DEPTH`` tile widths down and lands;
every landing adds its share of light to the bed's texels (bilinear splat, wrapping around the
tile's edges, so the tile repeats without a seam). Where neighbouring rays converge the bed gets
bright lines, where they spread it gets dim cells.

The gathered light is divided by its mean, so the tile's mean is exactly 1: the pattern only
moves the sun's light around (energy redistributed, not added). The texels are stored as
``c / PEAK`` in an 8-bit grey image; the few brighter than ``PEAK`` are clipped, and the mean is
brought back to 1 after clipping. The shader reads ``c = texel * PEAK``.

Image layout of :func:`caustics_map_rgba`: row 0 is the bottom row, as in Blender's
``Image.pixels``, and x runs with the column, as in the bump map, so both line up on the water.
"""

import functools

import numpy as np

from .bump_map import surface_normals, water_height_field
from .physics import WATER_IOR

CAUSTICS_MAP_VERSION = 1
"""Bump whenever the generated pixels change, so packed images get made again."""

IOR = WATER_IOR
DEPTH = 0.25
"""How far below the surface the bed lies, in tile widths, for the stored pattern: past the
first focus of the tile's main ripples, where the lines are sharp and the cells dim."""

PEAK = 4.0
"""Brightest stored value (times the mean): the 8-bit texel holds ``c / PEAK``."""

SLOPE_SCALE = 0.3
"""The surface's slopes relative to the bump map's (RMS slope 0.3 there): the shader tilts its
refraction by `Wave Height` (0.3 by default) times the map's normal, so the light bends as much as
what is seen through the water does."""

_RAYS = 2
"""Rays per texel along each axis."""


def _refracted_offsets(size: int, seed: int, depth: float) -> np.ndarray:
    """Where light falling straight down on each of ``size`` x ``size`` surface points lands,
    ``depth`` tile widths below, relative to the point, in texels (``size``, ``size``, 2: x, y)."""
    normal = surface_normals(water_height_field(size, seed), SLOPE_SCALE)
    # Snell for the incoming direction (0, 0, -1): t = eta i + (eta cos_i - cos_t) n.
    eta = 1.0 / IOR
    cos_i = normal[..., 2]
    cos_t = np.sqrt(1.0 - eta**2 * (1.0 - cos_i**2))
    refracted = eta * np.array([0.0, 0.0, -1.0]) + (eta * cos_i - cos_t)[..., None] * normal
    return refracted[..., :2] / -refracted[..., 2:3] * (depth * size)


def _splat(landing: np.ndarray, size: int) -> np.ndarray:
    """Gathers one unit of light per landing point (texel units, any range) into a periodic
    ``size`` x ``size`` grid, bilinearly: the light lands between texel centres."""
    x = landing[..., 0].ravel() - 0.5
    y = landing[..., 1].ravel() - 0.5
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = x - x0, y - y0
    x0 = x0.astype(np.int64) % size
    y0 = y0.astype(np.int64) % size
    x1, y1 = (x0 + 1) % size, (y0 + 1) % size
    light = np.zeros(size * size)
    for xs, ys, weight in (
        (x0, y0, (1 - fx) * (1 - fy)),
        (x1, y0, fx * (1 - fy)),
        (x0, y1, (1 - fx) * fy),
        (x1, y1, fx * fy),
    ):
        np.add.at(light, ys * size + xs, weight)
    return light.reshape(size, size)


@functools.lru_cache(maxsize=4)
def caustics_map(size: int = 512, seed: int = 7, depth: float = DEPTH) -> np.ndarray:
    """The caustic pattern (float64, ``size`` x ``size``, mean 1, at most ``PEAK``), periodic.

    Row 0 is the bottom row, x runs with the column; deterministic for a given ``seed`` (the bump
    map's). ``depth``: the bed's depth in tile widths. Traced with ``_RAYS`` x ``_RAYS`` rays a
    texel, so the lines are smooth.
    """
    if size < 8:
        raise ValueError(f"size must be >= 8, got {size}")
    fine = size * _RAYS
    offsets = _refracted_offsets(fine, seed, depth) / _RAYS  # in texels of the output grid
    rows, cols = np.meshgrid(np.arange(fine), np.arange(fine), indexing="ij")
    start = np.stack([(cols + 0.5) / _RAYS, (rows + 0.5) / _RAYS], axis=-1)
    light = _splat(start + offsets, size)
    light /= light.mean()
    for _ in range(8):  # clip the brightest, then give the clipped light back to all
        light = np.minimum(light, PEAK)
        light /= light.mean()
    return np.minimum(light, PEAK)


def caustics_map_rgba(size: int = 512, seed: int = 7) -> np.ndarray:
    """The tile as float32 RGBA (grey ``c / PEAK``, alpha 1), ready for ``Image.pixels``."""
    grey = (caustics_map(size, seed) / PEAK).astype(np.float32)
    rgba = np.ones((size, size, 4), dtype=np.float32)
    rgba[..., :3] = grey[..., None]
    return rgba
