"""The open sea's mesh: a grid that reaches the horizon with few points.

Its axes are evenly spaced (`spacing`, the Ocean modifier's own cell) over the inner half of
the points, so the waves there lose nothing, then each step grows by the same ratio out to the
sea's edge: `size` 20 km puts the edge 10 km away, which from 2 m up is 0.01 degrees below the
horizon, under a pixel. Each point's rest place is kept as the `water_rest` attribute (the
sea's fade reads it after the Ocean modifier has moved the point). UVs are metres / UV_METRES,
so the bump taps keep the seeds' ocean scale whatever the sea's size.
"""

import numpy as np

from ...nodes.sea.sea_fade import REST_ATTRIBUTE, UV_METRES
from ..grid import grid_mesh

INNER_SHARE = 0.5  # of the points along an axis, evenly spaced around the centre


def growth_ratio(steps, first, reach):
    """The ratio r > 1 with first * (r + r^2 + ... + r^steps) = reach (bisection); 1 if even steps do."""
    if steps <= 0 or first * steps >= reach:
        return 1.0
    low, high = 1.0, 2.0
    while first * sum(high**i for i in range(1, steps + 1)) < reach:
        high *= 2.0
    for _ in range(80):
        middle = (low + high) / 2
        if first * (middle ** (steps + 1) - middle) / (middle - 1.0) < reach:
            low = middle
        else:
            high = middle
    return (low + high) / 2


def sea_axis(points, size, spacing, even_reach=0.0):
    """`points` (odd) coordinates from -size/2 to size/2: even `spacing` in the middle, then growing.

    The even middle reaches at least `even_reach` metres (the steps grow past `spacing` when the
    points are too few), so wherever the waves displace the mesh its points are evenly spaced:
    displaced, sparse points would fold into long overlapping triangles (and a software
    rasteriser spends minutes on them)."""
    half = (points - 1) // 2
    inner = max(1, min(half, round(half * INNER_SHARE)))
    inner_reach = min(max(inner * spacing, even_reach), size / 2)
    step = inner_reach / inner
    outer = half - inner
    ratio = growth_ratio(outer, step, size / 2 - inner_reach)
    positive = [step * i for i in range(inner + 1)]
    gap = step
    for _ in range(outer):
        gap *= ratio
        positive.append(positive[-1] + gap)
    positive = np.array(positive) * ((size / 2) / positive[-1] if outer else 1.0)
    positive[: inner + 1] = np.arange(inner + 1) * step  # the even middle exactly even
    return np.concatenate([-positive[:0:-1], positive])


def new_sea_mesh(name, size, points, spacing, even_reach=0.0):
    """A smooth-shaded grid of `points` x `points` (made odd) over `size` metres, even `spacing`
    in the middle (out to at least `even_reach`), with UVs and the `water_rest` attribute."""
    points = max(5, points | 1)
    mesh = grid_mesh(name, sea_axis(points, size, spacing, even_reach), UV_METRES)
    rest = mesh.attributes.new(REST_ATTRIBUTE, "FLOAT_VECTOR", "POINT")
    co = np.zeros(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    rest.data.foreach_set("vector", co)
    return mesh
