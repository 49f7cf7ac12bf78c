"""Water's reflectance over the slopes a pixel cannot resolve (issue 38 points 2 and 4): the table
the ocean shade reads far off, against a Monte Carlo mean of Fresnel over Gaussian slopes, and
Toksvig's constants against the bump map they describe."""

import numpy as np
import pytest
from conftest import load
from reference_models import fresnel


def _monte_carlo(cos_view, slope, count=400_000):
    """Mean reflectance over facets with slopes N(0, slope^2) each way, each turned to face the
    eye (numpy's own, independent of the table's quadrature and of the add-on's Fresnel:
    `reference_models.fresnel` at SPEC's index 1.33, the one the table is built for)."""
    slopes = np.random.default_rng(3).standard_normal((count, 2)) * slope
    normals = np.column_stack([-slopes, np.ones(count)])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    eye = np.array([np.sqrt(1.0 - cos_view**2), 0.0, cos_view])
    return fresnel(np.abs(normals @ eye), 1.33).mean()


@pytest.mark.parametrize(
    ("cos_view", "slope"), [(0.02, 0.2), (0.05, 0.1), (0.1, 0.3), (0.3, 0.15), (0.5, 0.25), (0.9, 0.2)]
)
def test_the_mean_reflectance_is_monte_carlo_s(cos_view, slope):
    rough = load("nodes.sea.rough_fresnel")
    assert rough.mean_reflectance(cos_view, slope) == pytest.approx(_monte_carlo(cos_view, slope), rel=0.015)


def test_the_table_changes_nothing_where_no_slope_was_lost_and_darkens_the_grazing_sea():
    rough = load("nodes.sea.rough_fresnel")
    table = rough.table()
    assert table.shape == (rough.SIZE, rough.SIZE) and table.dtype == np.float32
    assert np.all(table[0] == 0.0)
    # Rough water reflects less at grazing (facets turn towards the eye) and more in between.
    grazing, middle = table[:, 1], table[:, rough.SIZE // 3]
    assert np.all(np.diff(grazing[1:]) < 0) and grazing[-1] < -0.4
    assert middle[rough.SIZE // 2] > 0.02
    # Its texel centres are where the shade reads (|cos|, s).
    u, v = rough.lookup(np.array([0.0, 1.0]), np.array([0.0, rough.SLOPE_MAX**2]))
    assert u * rough.SIZE == pytest.approx([0.5, rough.SIZE - 0.5])
    assert v * rough.SIZE == pytest.approx([0.5, rough.SIZE - 0.5])
    # 1 - R(c, 0) + ... stays a reflectance.
    axis = np.linspace(0.0, 1.0, rough.SIZE)
    total = table + rough.reflectance(axis)[None, :]
    assert total.min() > 0.0 and total.max() <= 1.0


def test_toksvig_s_constants_are_the_bump_map_s():
    """A sharp read of the 8-bit map loses about the floor (bilinear reads between texels); the
    whole tile averaged loses the full share."""
    rough = load("nodes.sea.rough_fresnel")
    bump = load("nodes.bump_map")
    size = 512  # packed_image.SIZE, the bump image's
    texels = np.round(bump.water_normal_map(size)[..., :3] * 255.0) / 255.0
    d = 2.0 * texels - 1.0
    assert 1.0 - (d.reshape(-1, 3).mean(axis=0) ** 2).sum() == pytest.approx(rough.LOST_FULL, rel=0.03)
    rng = np.random.default_rng(0)
    where = rng.random((20_000, 2)) * size
    low = np.floor(where).astype(int)
    f = where - low
    read = sum(
        d[(low[:, 0] + i) % size, (low[:, 1] + j) % size]
        * (np.where(i, f[:, 0], 1 - f[:, 0]) * np.where(j, f[:, 1], 1 - f[:, 1]))[:, None]
        for i in (0, 1)
        for j in (0, 1)
    )
    lost = 1.0 - (read**2).sum(axis=1)
    assert abs(lost.mean()) < rough.LOST_FLOOR < 0.1 * rough.LOST_FULL
