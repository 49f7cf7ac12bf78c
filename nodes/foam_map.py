"""Procedural, seamlessly tiling foam texture (numpy only, no ``bpy``).

The shore foam of the `Water Surface` group is broken up by this grey tile: a lace of bubbles, made
of three octaves of cellular (Worley) noise on a torus. In each octave, feature points are jittered
one per cell of a ``cells`` x ``cells`` grid that wraps around the tile's edges, and each pixel takes
``F2 - F1``, the difference between the distances to its nearest and second-nearest point: 0 on the
border between two bubbles, largest in a bubble's middle. The lace is ``exp(-(F2 - F1) / width)``,
bright on the borders and dark inside the bubbles; the octaves (big, medium and small bubbles) are
added with falling weights.

The sum is then **equalised**: every pixel is replaced by its rank among all pixels, scaled to 0..1,
so the tile's values are spread evenly over 0..1 (mean 0.5). The shader thresholds the tile against
the distance to the shore (``clamp((b + f - 1) / SOFTNESS)``, see `foam_coverage.py`), and an even
spread makes the covered share predictable: at falloff ``f`` about ``f - SOFTNESS / 2`` of the water
is foam. Near the waterline only the darkest bubble middles stay open; further out only the
brightest lace survives.

Everything is periodic (feature points wrap, distances are measured on the torus) and the ranks are
taken pixel by pixel, so the tile repeats without a seam. Deterministic for a given ``seed``.

Image layout of :func:`foam_map_rgba`: row 0 is the bottom row, as in Blender's ``Image.pixels``,
so ``foam_map_rgba(...).ravel()`` can go straight into ``image.pixels.foreach_set``.
"""

import functools

import numpy as np

FOAM_MAP_VERSION = 1
"""Bump whenever the generated pixels change, so packed images get made again."""

OCTAVES = ((5, 1.0, 0.10), (13, 0.6, 0.08), (31, 0.35, 0.06))
"""(bubbles across the tile, weight, lace width in cells) of each octave, big to small."""

SOFTNESS = 0.25
"""Width of the threshold ramp the shader applies to the tile (documented here, used there)."""


def _cellular(size: int, cells: int, rng: np.random.Generator) -> np.ndarray:
    """``F2 - F1`` of periodic Worley noise with ``cells`` x ``cells`` jittered points, in cell units."""
    jitter = rng.uniform(0.1, 0.9, (cells, cells, 2))
    coords = (np.arange(size) + 0.5) * (cells / size)
    y, x = np.meshgrid(coords, coords, indexing="ij")
    cy, cx = np.floor(y).astype(int), np.floor(x).astype(int)
    f1 = np.full((size, size), np.inf)
    f2 = np.full((size, size), np.inf)
    for dy in (-2, -1, 0, 1, 2):
        for dx in (-2, -1, 0, 1, 2):
            ny, nx = cy + dy, cx + dx
            point = jitter[ny % cells, nx % cells]
            # The neighbour's point, unwrapped next to this pixel: cells beyond an edge are its copies.
            d = np.hypot(x - (nx + point[..., 1]), y - (ny + point[..., 0]))
            f2 = np.where(d < f1, f1, np.minimum(f2, d))
            f1 = np.minimum(f1, d)
    return f2 - f1


def foam_map(size: int = 512, seed: int = 11) -> np.ndarray:
    """The foam tile, float32 (``size``, ``size``) with values spread evenly over [0, 1], periodic.

    Rows run along y (row 0 at the bottom), columns along x. High values are the lace between
    bubbles, low values the bubbles' open middles. (About 1.5 s for 512 on one core, so the
    result is kept for the session: every new file needs the same tile.)
    """
    return _foam_map(size, seed).copy()


@functools.lru_cache(maxsize=4)
def _foam_map(size, seed):
    if size < 16:
        raise ValueError(f"size must be >= 16, got {size}")
    rng = np.random.default_rng(seed)
    field = np.zeros((size, size))
    for cells, weight, width in OCTAVES:
        field += weight * np.exp(-_cellular(size, cells, rng) / width)
    ranks = np.empty(size * size)
    ranks[np.argsort(field, axis=None, kind="stable")] = np.arange(size * size)
    return (ranks / (size * size - 1)).reshape(size, size).astype(np.float32)


def foam_map_rgba(size: int = 512, seed: int = 11) -> np.ndarray:
    """The foam tile as grey RGBA float32 (``size``, ``size``, 4), alpha 1, for a Blender image."""
    grey = foam_map(size, seed)
    rgba = np.ones((size, size, 4), dtype=np.float32)
    rgba[..., :3] = grey[..., None]
    return rgba
