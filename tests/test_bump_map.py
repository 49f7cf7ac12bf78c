"""Tests for nodes/bump_map.py: numpy only, no Blender needed."""

import importlib.util
import pathlib

import numpy as np
import pytest

# Load by path: nodes/__init__.py (if any) may import bpy, which this module must not need.
_PATH = pathlib.Path(__file__).resolve().parents[1] / "nodes" / "bump_map.py"
_SPEC = importlib.util.spec_from_file_location("bump_map_under_test", _PATH)
bump_map = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(bump_map)

# water_height_field(256, seed=7)[0, :3] for BUMP_MAP_VERSION 1.
REGRESSION_ROW0 = [0.18971298819285384, 0.17463902563994932, 0.29442188564821625]


@pytest.fixture(scope="module")
def normal_map():
    return bump_map.water_normal_map(256, seed=7)


@pytest.fixture(scope="module")
def height():
    return bump_map.water_height_field(256, seed=7)


def _decode(rgba):
    return rgba[..., :3].astype(np.float64) * 2.0 - 1.0


def test_version_is_int():
    assert isinstance(bump_map.BUMP_MAP_VERSION, int)
    assert bump_map.BUMP_MAP_VERSION >= 1


def test_shape_dtype_range(normal_map, height):
    assert normal_map.shape == (256, 256, 4)
    assert normal_map.dtype == np.float32
    assert normal_map.min() >= 0.0 and normal_map.max() <= 1.0
    assert np.all(normal_map[..., 3] == 1.0)
    assert height.shape == (256, 256) and height.dtype == np.float64
    assert abs(height.mean()) < 1e-12 and abs(height.std() - 1.0) < 1e-12


def test_other_sizes():
    for size in (8, 64, 100, 512):
        assert bump_map.water_normal_map(size).shape == (size, size, 4)
    with pytest.raises(ValueError):
        bump_map.water_height_field(4)


def test_ravel_matches_blender_pixels_layout(normal_map):
    flat = normal_map.ravel()
    assert flat.shape == (256 * 256 * 4,)
    # foreach_set order: pixel (row 0 = bottom, col 0) first, RGBA interleaved.
    assert np.array_equal(flat[:4], normal_map[0, 0])
    assert np.array_equal(flat[4:8], normal_map[0, 1])
    assert np.array_equal(flat[256 * 4 : 256 * 4 + 4], normal_map[1, 0])


def test_unit_normals(normal_map):
    length = np.linalg.norm(_decode(normal_map), axis=-1)
    assert np.max(np.abs(length - 1.0)) < 1e-3


def test_mean_normal_points_up(normal_map):
    mean = _decode(normal_map).reshape(-1, 3).mean(axis=0)
    assert mean[2] > 0.9
    assert abs(mean[0]) < 0.05 and abs(mean[1]) < 0.05


def test_normals_follow_downhill_opengl_convention(normal_map, height):
    """x grows with the column, y with the row: the normal leans against the height gradient."""
    n = _decode(normal_map)
    dx = np.roll(height, -1, axis=1) - np.roll(height, 1, axis=1)
    dy = np.roll(height, -1, axis=0) - np.roll(height, 1, axis=0)
    assert np.corrcoef(n[..., 0].ravel(), dx.ravel())[0, 1] < -0.95
    assert np.corrcoef(n[..., 1].ravel(), dy.ravel())[0, 1] < -0.95


def test_strength():
    flat = _decode(bump_map.water_normal_map(64, strength=0.0))
    assert np.allclose(flat, [0.0, 0.0, 1.0], atol=1e-6)
    weak = _decode(bump_map.water_normal_map(64, strength=0.5))[..., 2].mean()
    strong = _decode(bump_map.water_normal_map(64, strength=2.0))[..., 2].mean()
    assert strong < weak < 1.0


def test_deterministic():
    a = bump_map.water_normal_map(128, seed=3)
    b = bump_map.water_normal_map(128, seed=3)
    c = bump_map.water_normal_map(128, seed=4)
    assert a.tobytes() == b.tobytes()
    assert np.mean(np.abs(a - c)) > 0.01


def test_same_surface_at_every_size():
    """A seed names one surface; a larger size only samples it more finely."""
    fine = bump_map.water_height_field(512, seed=7)
    coarse = bump_map.water_height_field(256, seed=7)
    assert np.allclose(fine[::2, ::2], coarse, atol=1e-9)


def test_regression_values(height):
    """If this fails the output changed: bump BUMP_MAP_VERSION and update the numbers."""
    assert np.allclose(height[0, :3], REGRESSION_ROW0, atol=1e-9)


def _wrap_ratio(a, axis):
    """Mean |difference| across the tile edge over the mean between interior neighbours."""
    a = np.moveaxis(a, axis, 0)
    interior = np.mean(np.abs(np.diff(a, axis=0)))
    wrap = np.mean(np.abs(a[0] - a[-1]))
    return wrap / interior


@pytest.mark.parametrize("axis", [0, 1])
def test_seamless(normal_map, height, axis):
    assert _wrap_ratio(height, axis) < 1.5
    assert _wrap_ratio(normal_map[..., :3], axis) < 1.5


def test_smooth_not_static(height):
    """Neighbouring heights are strongly correlated: ripples, not per-pixel noise."""
    for axis in (0, 1):
        lag1 = np.mean(height * np.roll(height, 1, axis=axis)) / np.mean(height**2)
        assert lag1 > 0.9


def test_spectrum_concentrated(height):
    """Over 80% of the variance lies at wavelengths between size/32 and size/2."""
    size = height.shape[0]
    power = np.abs(np.fft.fft2(height)) ** 2
    freq = np.fft.fftfreq(size, 1.0 / size)
    k = np.hypot(*np.meshgrid(freq, freq, indexing="ij"))  # cycles per tile
    band = (k >= 2) & (k <= 32)
    assert power[band].sum() / power.sum() > 0.8


def test_not_one_direction(height):
    """Energy is spread over directions, with a preferred (wind) one: no single plane wave."""
    size = height.shape[0]
    power = np.abs(np.fft.fft2(height)) ** 2
    freq = np.fft.fftfreq(size, 1.0 / size)
    ky, kx = np.meshgrid(freq, freq, indexing="ij")
    angle = np.mod(np.arctan2(ky, kx), np.pi)  # +k and -k carry the same energy
    sectors = np.histogram(angle, bins=8, range=(0, np.pi), weights=power)[0]
    sectors /= sectors.sum()
    assert sectors.max() < 0.6  # not a single direction
    assert sectors.min() > 0.005  # some cross-ripples everywhere
    assert sectors.max() > 2.0 / 8  # but a preferred direction
