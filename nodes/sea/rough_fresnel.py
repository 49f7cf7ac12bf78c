"""Water's reflectance over slopes a pixel cannot resolve (numpy; the table `Water Ocean Shade` reads).

Far off, EEVEE reads the bump map from its mipmaps, whose texels are averages: the taps' slopes
average to nothing and the sea turns into a flat mirror, bright at grazing, where Cycles (no
mipmaps, many samples a pixel) sees every ripple and a darker far sea. How much slope the
averaging took is measured where it happened (`Water Ocean Normal`'s `Unresolved Slope`: an
averaged unit normal is shorter, 1 - |n|^2 the slope variance lost, as Toksvig noted), and the
shade gives back what those slopes would have reflected: R(c, s), the mean of Fresnel's
reflectance at water's IOR over a Gaussian of slopes with `s` rms each way about a normal seen
at cos c, each facet turned to face the eye as `Water Underside` turns it. The table holds
R(c, s) - R(c, 0): exactly 0 where nothing was lost.
"""

import numpy as np

from ..physics import WATER_IOR

SIZE = 64  # c from 0 to 1 along x, s from 0 to SLOPE_MAX along y
SLOPE_MAX = 0.5  # rms slope each way at the table's top row (25 m/s is about 0.26)
TABLE_VERSION = 1
_STEPS = 49  # grid points each way, out to 4 rms (the facets' turning makes R(cos) kinked at 0)


def reflectance(cos_i, ior=WATER_IOR):
    """Fresnel's reflectance of unpolarised light from air onto water at |cos_i|."""
    cos_i = np.clip(np.abs(cos_i), 1e-6, 1.0)
    sin_t = np.sqrt(1.0 - cos_i**2) / ior
    cos_t = np.sqrt(np.clip(1.0 - sin_t**2, 0.0, 1.0))
    rs = ((cos_i - ior * cos_t) / (cos_i + ior * cos_t)) ** 2
    rp = ((ior * cos_i - cos_t) / (ior * cos_i + cos_t)) ** 2
    return (rs + rp) / 2.0


def mean_reflectance(cos_view, slope):
    """R(c, s) for arrays of c and s (broadcast): the mean over slopes N(0, s^2) each way."""
    nodes = np.linspace(-4.0, 4.0, _STEPS)
    weights = np.exp(-(nodes**2) / 2.0)
    weights = weights / weights.sum()
    cos_view, slope = np.broadcast_arrays(np.asarray(cos_view, float), np.asarray(slope, float))
    sin_view = np.sqrt(np.clip(1.0 - cos_view**2, 0.0, 1.0))
    total = np.zeros(cos_view.shape)
    for x, wx in zip(nodes, weights, strict=True):
        for y, wy in zip(nodes, weights, strict=True):
            # The facet's normal (-sx, -sy, 1) / |.|, the eye at (sin, 0, cos).
            sx, sy = x * slope, y * slope
            cos_facet = (cos_view - sx * sin_view) / np.sqrt(1.0 + sx**2 + sy**2)
            total += wx * wy * reflectance(cos_facet)
    return total


def table():
    """(SIZE, SIZE) float32: row j (s = j / (SIZE - 1) x SLOPE_MAX), column i (c = i / (SIZE - 1)),
    R(c, s) - R(c, 0)."""
    axis = np.linspace(0.0, 1.0, SIZE)
    cos_view, slope = np.meshgrid(axis, axis * SLOPE_MAX)
    lost = mean_reflectance(cos_view, slope) - reflectance(cos_view)
    lost[0] = 0.0  # no slope lost: no change, exactly
    return lost.astype(np.float32)


def table_rgba(size=SIZE):
    """The table as an RGBA image's pixels (row 0 at the bottom, as `Image.pixels`), grey."""
    if size != SIZE:
        raise ValueError(f"the rough Fresnel table is {SIZE} x {SIZE}, not {size}")
    rgba = np.ones((SIZE, SIZE, 4), dtype=np.float32)
    rgba[..., :3] = table()[..., None]
    return rgba


def lookup(cos_view, slope_variance):
    """Where the shade reads the table for |cos| and a lost mean square slope: texel centres at
    the table's c and s (UV from 0 to 1)."""
    slope = np.sqrt(np.maximum(slope_variance, 0.0))
    u = 0.5 / SIZE + np.clip(np.abs(cos_view), 0.0, 1.0) * (SIZE - 1) / SIZE
    v = 0.5 / SIZE + slope / SLOPE_MAX * (SIZE - 1) / SIZE
    return u, v


# Toksvig's measure on the bump map (`bump_map.water_normal_map`, 512 x 512, 8 bits): 1 - |2c - 1|^2 of a
# read, its mean over the three taps. At full resolution bilinear reads lose about 0.002
# (quantisation and interpolation, the floor); averaged over the whole tile 0.0803 (every slope).
# Measured in numpy (tests/plain/test_rough_fresnel.py holds them to the map).
LOST_FLOOR = 0.003
LOST_FULL = 0.0803
# The taps' mean square slope each way at Bump Strength 1 when combined as the seeds do
# (`ocean_normal.BUMP_SLOPE_COVARIANCE`'s mean diagonal); with Even Slopes 1 it is 1 before the wind
# scales it.
SEEDS_SLOPE_VARIANCE = 0.013275
