"""The dry mask of a hull: enclosed by its outline at the waterline's heights, its edge just inside."""

import numpy as np
from conftest import load


def _quads(quads):
    """Triangles of quads given as four (x, y, z) corners each."""
    return np.array([tri for q in quads for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))], float)


def _open_box(x0, x1, y0, y1, z0, z1):
    """Floor and four walls, no lid, walls of no thickness."""
    return _quads(
        [
            ((x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)),
            ((x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)),
            ((x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)),
            ((x1, y1, z0), (x0, y1, z0), (x0, y1, z1), (x1, y1, z1)),
            ((x0, y1, z0), (x0, y0, z0), (x0, y0, z1), (x0, y1, z1)),
        ]
    )


def _sample(mask, origin, cell, x, y):
    """The mask read as the renderer reads an image with linear interpolation (texel centres at
    half cells), clamped at the border."""
    rows, columns = mask.shape
    u, v = (x - origin[0]) / cell - 0.5, (y - origin[1]) / cell - 0.5
    i0, j0 = int(np.floor(u)), int(np.floor(v))
    fu, fv = u - i0, v - j0

    def at(i, j):
        return mask[min(max(j, 0), rows - 1), min(max(i, 0), columns - 1)]

    return (
        at(i0, j0) * (1 - fu) * (1 - fv)
        + at(i0 + 1, j0) * fu * (1 - fv)
        + at(i0, j0 + 1) * (1 - fu) * fv
        + at(i0 + 1, j0 + 1) * fu * fv
    )


def test_an_open_box_is_dry_inside_and_its_edge_lies_just_inside_its_walls():
    dm = load("water.boats.dry_mask_math")
    mask, origin, cell = dm.dry_mask(_open_box(-1.0, 1.0, -0.6, 0.6, -0.5, 0.5), -0.5, 0.5)
    assert mask.shape[1] == dm.LONG_SIDE
    assert _sample(mask, origin, cell, 0.0, 0.0) == 1.0
    assert _sample(mask, origin, cell, 0.9, 0.5) == 1.0
    assert _sample(mask, origin, cell, 1.0 + cell, 0.0) == 0.0
    # Along lines crossing each wall (off any axis of symmetry), the cut at 0.5 lies inside the
    # wall by half a cell to two and a half.
    for start, end, wall in (((0.3, 0.2), (1.2, 0.2), 1.0), ((-0.3, 0.1), (-1.2, 0.1), 1.0)):
        xs = np.linspace(start[0], end[0], 4000)
        values = np.array([_sample(mask, origin, cell, x, start[1]) for x in xs])
        edge = abs(xs[np.argmax(values < 0.5)])
        assert 0.5 * cell <= wall - edge <= 2.5 * cell, (wall - edge) / cell
    ys = np.linspace(0.1, 0.8, 4000)
    values = np.array([_sample(mask, origin, cell, 0.37, y) for y in ys])
    assert 0.5 * cell <= 0.6 - ys[np.argmax(values < 0.5)] <= 2.5 * cell


def test_a_turned_box_keeps_its_edge_just_inside_its_walls():
    dm = load("water.boats.dry_mask_math")
    turn = 0.5
    c, s = np.cos(turn), np.sin(turn)
    box = _open_box(-1.0, 1.0, -0.6, 0.6, -0.5, 0.5) @ np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])
    mask, origin, cell = dm.dry_mask(box, -0.5, 0.5)
    for along, wall in (((c, s), 1.0), ((-s, c), 0.6), ((-c, -s), 1.0)):
        ts = np.linspace(0.3, wall + 0.2, 4000)
        values = np.array([_sample(mask, origin, cell, t * along[0], t * along[1]) for t in ts])
        assert values[0] == 1.0
        assert 0.5 * cell <= wall - ts[np.argmax(values < 0.5)] <= 2.5 * cell


def test_thick_walls_and_a_concave_outline_are_filled_as_enclosed():
    dm = load("water.boats.dry_mask_math")
    # An L of two open boxes' outlines (thin walls) sliced at mid height: the notch stays wet.
    outline = np.array(
        [
            ((0, 0), (4, 0)),
            ((4, 0), (4, 1)),
            ((4, 1), (1, 1)),
            ((1, 1), (1, 3)),
            ((1, 3), (0, 3)),
            ((0, 3), (0, 0)),
        ],
        float,
    )
    origin, cell, shape = dm.grid_for((0.0, 0.0), (4.0, 3.0), 256)
    filled = dm.enclosed(dm.draw_segments(outline, origin, cell, shape))

    def cell_at(x, y):
        return filled[int((y - origin[1]) / cell), int((x - origin[0]) / cell)]

    assert cell_at(0.5, 2.5) and cell_at(3.5, 0.5) and not cell_at(3.0, 2.0)
    # A single wall encloses nothing.
    ring = _quads([((-1, -1, 0), (1, -1, 0), (1, -1, 1), (-1, -1, 1))])  # one wall only: no enclosure
    mask, origin, cell = dm.dry_mask(ring, 0.0, 1.0, 64)
    assert mask.max() == 0.0


def test_thick_walled_box_is_dry_between_its_walls():
    dm = load("water.boats.dry_mask_math")
    outer = _open_box(-2.0, 2.0, -1.0, 1.0, 0.0, 1.0)[2:]  # walls only
    inner = _open_box(-1.9, 1.9, -0.9, 0.9, 0.1, 1.0)[2:]
    mask, origin, cell = dm.dry_mask(np.concatenate([outer, inner]), 0.0, 1.0, 128)
    assert _sample(mask, origin, cell, 0.0, 0.0) == 1.0  # the inside, between the inner walls
    assert _sample(mask, origin, cell, 1.95, 0.3) == 1.0  # the wall itself
    assert _sample(mask, origin, cell, 2.0 + 2 * cell, 0.3) == 0.0


def test_only_the_band_counts_a_bowsprit_above_it_stays_wet():
    dm = load("water.boats.dry_mask_math")
    hull = _open_box(-2.0, 2.0, -1.0, 1.0, 0.0, 1.0)
    bowsprit = _open_box(2.0, 3.5, -0.1, 0.1, 1.5, 1.7)
    mask, origin, cell = dm.dry_mask(np.concatenate([hull, bowsprit]), 0.0, 1.2)
    assert _sample(mask, origin, cell, 1.0, 0.0) == 1.0
    assert _sample(mask, origin, cell, 3.0, 0.0) == 0.0
    mask, origin, cell = dm.dry_mask(np.concatenate([hull, bowsprit]), 0.0, 1.7)
    assert _sample(mask, origin, cell, 3.0, 0.0) == 1.0
