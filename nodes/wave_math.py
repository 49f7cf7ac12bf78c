"""The ocean's four sine waves in numpy (SPEC section 2): the reference the
`Water Waves` geometry nodes reproduce, and what the tests compare them with.

Blender is Z-up: the seeds' directions (x, z) in their Y-up world are (x, -z)
here, and their height `y` is `z`.
"""

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Wave:
    amplitude: float
    wavelength: float
    speed: float
    direction: tuple  # in the XY plane; normalised where used


# The seeds' table, turned Z-up.
DEFAULT_WAVES = (
    Wave(0.3, 10.0, 1.0, (-1.0, 0.0)),
    Wave(0.4, 5.0, 2.0, (-1.0, -0.5)),
    Wave(0.2, 15.0, 0.5, (-1.0, -0.7)),
    Wave(0.3, 7.0, 1.5, (-1.0, 0.5)),
)
MIN_WAVELENGTH = 1e-3


def _unit(direction):
    d = np.asarray(direction[:2], dtype=np.float64)
    length = np.linalg.norm(d)
    return d / length if length > 0 else d


def _arguments(xy, time, wave):
    d = _unit(wave.direction)
    return (xy @ d) / max(wave.wavelength, MIN_WAVELENGTH) + time * wave.speed, d


def heights(xy, time, waves=DEFAULT_WAVES):
    """Height `sum A_i sin(dot(D_i, p) / lambda_i + t s_i)` at points `xy` (N, 2)."""
    xy = np.asarray(xy, dtype=np.float64)
    total = np.zeros(len(xy))
    for wave in waves:
        arg, _ = _arguments(xy, time, wave)
        total += wave.amplitude * np.sin(arg)
    return total


def normals(xy, time, waves=DEFAULT_WAVES):
    """Unit normals (N, 3) from the waves' cosine derivatives: normalise(-dh/dx, -dh/dy, 1)."""
    xy = np.asarray(xy, dtype=np.float64)
    slope = np.zeros((len(xy), 2))
    for wave in waves:
        arg, d = _arguments(xy, time, wave)
        slope += (wave.amplitude * np.cos(arg) / max(wave.wavelength, MIN_WAVELENGTH))[:, None] * d
    n = np.column_stack([-slope[:, 0], -slope[:, 1], np.ones(len(xy))])
    return n / np.linalg.norm(n, axis=1, keepdims=True)
