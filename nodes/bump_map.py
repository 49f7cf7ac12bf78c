"""Procedural, seamlessly tiling water normal map (numpy only, no ``bpy``).

Replaces the ``waterBump`` texture of the old XNA water tutorial: small, choppy ripples of a
lake surface. The height field is built spectrally (random complex amplitudes on integer wave
vectors of the tile, then an inverse FFT), so it tiles exactly by construction.

Image layout of :func:`water_normal_map`: row 0 is the bottom row, as in Blender's
``Image.pixels``, and columns run left to right. So ``water_normal_map(...).ravel()`` can be
passed straight to ``image.pixels.foreach_set`` of a ``size`` x ``size`` RGBA image.
"""

import numpy as np

BUMP_MAP_VERSION = 1
"""Bump whenever the generated pixels change, so cached images get regenerated."""

_GRID = 128
"""Wave vectors are drawn on a fixed 128 x 128 grid, so a seed gives the same surface at every
size >= 128 (only sampled more finely); smaller sizes drop the finest ripples."""

_PEAK = 8.0
"""Dominant wave number in cycles per tile (wavelength = tile / 8)."""

_CUTOFF = 24.0
"""Gaussian cut-off wave number: finer ripples would read as pixel noise, not water."""

_SPREAD_POWER = 8
"""Directional spreading cos^8 around the wind: crests get some length, but not one direction."""

_ISOTROPIC = 0.1
"""Share of the energy spread evenly over all directions (cross-ripples)."""

_RMS_SLOPE = 0.3
"""RMS slope of the surface at ``strength == 1``: visible ripples, normals still mostly up."""


def _amplitudes(wind: float) -> np.ndarray:
    """Spectral amplitudes (sqrt of energy) on the fixed grid, [ky, kx] in numpy FFT order."""
    freq = np.fft.fftfreq(_GRID, 1.0 / _GRID)
    ky, kx = np.meshgrid(freq, freq, indexing="ij")
    k = np.hypot(kx, ky)
    k[0, 0] = 1.0  # avoids 0 / 0; the mean (k = 0) gets no energy below
    # Pierson-Moskowitz-like deep-water spectrum in wave number, per unit area of k-space:
    # exp(-1.25 (kp/k)^2) suppresses the lowest frequencies, the Gaussian the highest.
    energy = k**-4 * np.exp(-1.25 * (_PEAK / k) ** 2 - (k / _CUTOFF) ** 2)
    cos = (kx * np.cos(wind) + ky * np.sin(wind)) / k
    energy *= _ISOTROPIC + (1.0 - _ISOTROPIC) * np.abs(cos) ** _SPREAD_POWER
    energy[0, 0] = 0.0
    return np.sqrt(energy)


def water_height_field(size: int = 256, seed: int = 7) -> np.ndarray:
    """Heights (float64, ``size`` x ``size``, zero mean, unit std), periodic on the torus.

    Rows run along y, columns along x. Deterministic for a given ``seed``; for sizes >= 128,
    doubling the size gives the same surface sampled twice as finely.
    """
    if size < 8:
        raise ValueError(f"size must be >= 8, got {size}")
    rng = np.random.default_rng(seed)
    wind = rng.uniform(0.0, 2.0 * np.pi)
    noise = rng.standard_normal((2, _GRID, _GRID))
    coeffs = _amplitudes(wind) * (noise[0] + 1j * noise[1])

    # Keep the wave vectors below Nyquist and place them into the size x size spectrum.
    freq = np.fft.fftfreq(_GRID, 1.0 / _GRID).astype(int)
    ky, kx = np.meshgrid(freq, freq, indexing="ij")
    keep = np.maximum(abs(kx), abs(ky)) < min(size, _GRID) / 2
    spectrum = np.zeros((size, size), dtype=complex)
    spectrum[ky[keep] % size, kx[keep] % size] = coeffs[keep]

    height = np.fft.ifft2(spectrum).real
    height -= height.mean()
    return height / height.std()


def surface_normals(height: np.ndarray, strength: float = 1.0) -> np.ndarray:
    """Unit normals (``size``, ``size``, 3) of a periodic height field, its RMS slope
    ``strength * _RMS_SLOPE`` whatever the size (slopes in pixel units shrink as it grows)."""
    # Periodic central differences keep the normals seamless across the tile edges.
    dx = (np.roll(height, -1, axis=1) - np.roll(height, 1, axis=1)) * 0.5
    dy = (np.roll(height, -1, axis=0) - np.roll(height, 1, axis=0)) * 0.5
    scale = strength * _RMS_SLOPE / np.sqrt(np.mean(dx**2 + dy**2))
    normal = np.stack([-dx * scale, -dy * scale, np.ones_like(height)], axis=-1)
    return normal / np.linalg.norm(normal, axis=-1, keepdims=True)


def water_normal_map(size: int = 256, seed: int = 7, strength: float = 1.0) -> np.ndarray:
    """Tangent-space normal map, float32 RGBA (``size``, ``size``, 4) in [0, 1], OpenGL style.

    Row 0 is the bottom row, as in Blender's ``Image.pixels``; x grows with the column index
    and y with the row index (up the image). R, G, B = normal x, y, z * 0.5 + 0.5 with z out of
    the surface; A = 1. ``strength`` scales the slopes (RMS slope 0.3 at 1; 0 gives flat).
    """
    normal = surface_normals(water_height_field(size, seed), strength)
    rgba = np.ones((size, size, 4), dtype=np.float32)
    rgba[..., :3] = normal * 0.5 + 0.5
    return rgba
