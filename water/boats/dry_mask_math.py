"""The dry mask of a hull, as plain numbers: what `keep_out.py` packs into an image.

Seen from above in the hull's own frame, the mask is 1 over everything its outline encloses at
the heights where the water can meet it, and 0 outside. The hull's triangles are sliced at a few
heights; the slices' segments are drawn into one grid, and every cell the grid's border cannot
reach without crossing a drawn one is enclosed: a cockpit, a hold or an open box is dry however
thin its walls, and meshes that are not closed still work. The mask is then shrunk by two cells, so
that where the renderer reads it (linear interpolation, cut at 0.5) its edge lies just inside
the hull's outer surface (1 to 2 cells: 2.5 to 5 cm on a 25 m hull): no see-through ring shows
round the hull.

Plain Python and numpy, so it is tested without Blender (`tests/plain`).
"""

import numpy as np

LONG_SIDE = 1024  # cells along the hull's longer side
MIN_CELLS = 16  # cells along its shorter side, at least
BORDER = 3  # empty cells round the outline, so the grid's border is outside the hull
LEVELS = 8  # slices over the height band
SHRINK = 2  # cells taken off the edge: at 0.5 between texels, the edge lies 1 to 2 cells inside


def slice_segments(triangles, z):
    """The segments ((x0, y0), (x1, y1)) where the plane at height `z` cuts `triangles` ((T, 3, 3)
    vertex positions), as an (S, 2, 2) array."""
    triangles = np.asarray(triangles, dtype=float).reshape(-1, 3, 3)
    side = triangles[:, :, 2] > z
    cut = side.any(axis=1) & ~side.all(axis=1)
    triangles, side = triangles[cut], side[cut]
    segments = []
    for a, b in ((0, 1), (1, 2), (2, 0)):
        crosses = side[:, a] != side[:, b]
        pa, pb = triangles[:, a], triangles[:, b]
        dz = pb[:, 2] - pa[:, 2]
        t = np.where(crosses, (z - pa[:, 2]) / np.where(dz == 0.0, 1.0, dz), np.nan)
        segments.append(pa[:, :2] + t[:, None] * (pb[:, :2] - pa[:, :2]))
    points = np.stack(segments, axis=1)  # (T, 3 edges, 2): two edges of three cross
    found = ~np.isnan(points[:, :, 0])
    ends = points[found].reshape(-1, 2, 2)  # each cut triangle has exactly two crossing edges
    return ends


def grid_for(bounds_min, bounds_max, long_side=LONG_SIDE):
    """(origin (x, y), cell size, (rows, columns)) of a grid of square cells over the box from
    `bounds_min` to `bounds_max` (x, y), with `BORDER` empty cells round it."""
    lo, hi = np.asarray(bounds_min[:2], float), np.asarray(bounds_max[:2], float)
    extent = np.maximum(hi - lo, 1e-6)
    # `long_side` cells along the longer side, unless the shorter then has fewer than `MIN_CELLS`
    # (a narrow hull): finer cells then, up to four times as many.
    along = extent.max() / (long_side - 2 * BORDER)
    cell = max(min(along, extent.min() / (MIN_CELLS - 2 * BORDER)), along / 4.0, 1e-6)
    cells = np.ceil(extent / cell - 1e-6).astype(int) + 2 * BORDER
    origin = lo - BORDER * cell - (cells * cell - 2 * BORDER * cell - extent) / 2.0
    return origin, cell, (int(cells[1]), int(cells[0]))


def draw_segments(segments, origin, cell, shape):
    """A (rows, columns) boolean grid, True in every cell a segment passes through (sampled at a
    quarter of a cell, so a line is never crossed diagonally)."""
    drawn = np.zeros(shape, dtype=bool)
    segments = np.asarray(segments, float).reshape(-1, 2, 2)
    if not len(segments):
        return drawn
    lengths = np.linalg.norm(segments[:, 1] - segments[:, 0], axis=1)
    steps = np.maximum(np.ceil(lengths / (cell / 4.0)).astype(int), 1)
    repeat = np.repeat(np.arange(len(segments)), steps + 1)
    fraction = np.concatenate([np.linspace(0.0, 1.0, n + 1) for n in steps])
    points = segments[repeat, 0] + fraction[:, None] * (segments[repeat, 1] - segments[repeat, 0])
    columns = np.clip(((points[:, 0] - origin[0]) / cell).astype(int), 0, shape[1] - 1)
    rows = np.clip(((points[:, 1] - origin[1]) / cell).astype(int), 0, shape[0] - 1)
    drawn[rows, columns] = True
    return drawn


def _spread_along_rows(outside, free):
    """`outside` grown along each row through runs of free cells: a run touching it is outside."""
    starts = free.copy()
    starts[:, 1:] &= ~free[:, :-1]
    runs = np.cumsum(starts.ravel()).reshape(free.shape) * free  # 0 on drawn cells
    touched = np.bincount(runs[outside & free], minlength=runs.max() + 1) > 0
    touched[0] = False
    return touched[runs]


def enclosed(drawn):
    """The cells the grid's border cannot reach through undrawn cells (4-neighbour steps), the
    drawn cells included. Reach spreads along whole runs of free cells, by rows then columns, until
    it stops growing (a few rounds for a hull)."""
    free = ~drawn
    outside = np.zeros_like(drawn)
    outside[[0, -1], :] = free[[0, -1], :]
    outside[:, [0, -1]] = free[:, [0, -1]]
    while True:
        grown = _spread_along_rows(outside, free)
        grown = _spread_along_rows(grown.T, free.T).T
        if np.array_equal(grown, outside):
            return ~outside
        outside = grown


def shrink(mask, cells=1):
    """`mask` less its edge, `cells` cells deep (4-neighbour)."""
    for _ in range(cells):
        inner = mask.copy()
        inner[1:, :] &= mask[:-1, :]
        inner[:-1, :] &= mask[1:, :]
        inner[:, 1:] &= mask[:, :-1]
        inner[:, :-1] &= mask[:, 1:]
        mask = inner
    return mask


def band_levels(low, high, levels=LEVELS):
    """Heights at which to slice the band from `low` to `high`: the middles of `levels` equal
    steps (never a face's own height at the band's ends)."""
    return low + (np.arange(levels) + 0.5) / levels * (high - low)


def dry_mask(triangles, low, high, long_side=LONG_SIDE):
    """(mask (rows, columns) of 0 and 1, grid origin (x, y), cell size) of `triangles` (in the
    hull's frame) enclosed at any height from `low` to `high`."""
    triangles = np.asarray(triangles, float).reshape(-1, 3, 3)
    points = triangles.reshape(-1, 3)
    origin, cell, shape = grid_for(points.min(axis=0), points.max(axis=0), long_side)
    drawn = np.zeros(shape, dtype=bool)
    for z in band_levels(low, high):
        drawn |= draw_segments(slice_segments(triangles, z), origin, cell, shape)
    return shrink(enclosed(drawn), SHRINK).astype(np.float32), origin, cell
