"""Works out `nodes/boats/wake_height.py`'s PATTERN_HEIGHT: how high the group's own Kelvin
pattern stands, crest to trough, a hull's length to the side of its track, by Froude number,
before it is scaled to Kriebel and Seelig's height.

The group's height is `scale x f(x / L, y / L, Fr)`: `f` the stationary-phase pattern (its two
waves, each `p̂(k) sqrt(2π / |ψ''|) cos(ψ ± π/4)`, Airy's width on the arms), which depends on
the Froude number alone once lengths are in hull lengths. For the wake to be as high as
Kriebel and Seelig's relation says at `y = L`, `scale` is their height over `N(Fr)`, the
pattern's crest-to-trough height there (the mean over 0.8 to 1.25 L of the height along each
line, times `(y / L)^(1/3)`, from 0.3 L to 40 L behind). `N` falls steeply below Fr 0.35 (a
smooth hull makes few waves shorter than itself), so it is fitted as

    ln N = c0 + c1 / Fr + c2 / Fr² + c3 / Fr⁴ + c4 ln Fr,     0.25 <= Fr <= 3

and the group clamps Fr to that range. Run: `~/.cache/water_surface/venv-bpy-5.2.3/bin/python
tools/wake_heights.py`; it prints the constants and the fit's worst error (about 5%).
"""

import numpy as np
from reference_models import G, hull_spectrum

FROUDE = np.concatenate([np.arange(0.25, 1.0, 0.0125), np.arange(1.0, 3.001, 0.05)])


def pattern(x, y, froude, length=1.0, cell=0.0):
    """The group's pattern `f` (`nodes/boats/wake_kelvin.py`), `x` behind and `y` across in
    metres; with a mesh `cell`, waves shorter than four cells fade out (to none at two cells, as
    the group's "the mesh can hold it")."""
    speed = froude * np.sqrt(G * length)
    x = np.maximum(x, 1e-3)
    y = np.abs(y)
    t = np.maximum(y / x, 1e-4)
    disc = 1.0 - 8.0 * t * t
    s = np.sqrt(np.maximum(disc, 0.0))
    k_scale = G / speed**2
    kx = k_scale * np.maximum(x, length / 4.0)
    eps2 = (4.0 / kx) ** (2.0 / 3.0)
    curvature = kx * np.sqrt(s * s + eps2)
    total = 0.0
    for tau, sign in ((2.0 * t / (1.0 + s), 1.0), ((1.0 + s) / (4.0 * t), -1.0)):
        q2 = 1.0 + tau * tau
        q = np.sqrt(q2)
        phase = k_scale * (x - y * tau) * q + sign * np.pi / 4.0
        share = hull_spectrum(q2 * k_scale, length)
        if cell > 0.0:
            wavelength = 2.0 * np.pi / (q2 * k_scale)
            share = share * np.clip((wavelength / (4.0 * cell) - 0.5) / 0.5, 0.0, 1.0)
        total = total + share * np.sqrt(2.0 * np.pi / (q2 * q * curvature)) * np.cos(phase)
    return total * np.exp(np.minimum(disc, 0.0) / eps2)


def crest_to_trough(froude, lines=np.linspace(0.8, 1.25, 10)):
    """N(Fr): the pattern's crest-to-trough height a hull's length across, as defined above."""
    x = np.linspace(0.3, 40.0, 100000)
    heights = []
    for y in lines:
        f = pattern(x, y, froude)
        heights.append((f.max() - f.min()) * y ** (1.0 / 3.0))
    return float(np.mean(heights))


def basis(froude):
    froude = np.asarray(froude, float)
    return np.stack([froude**0, 1.0 / froude, froude**-2, froude**-4, np.log(froude)], axis=1)


def fit():
    heights = np.array([crest_to_trough(f) for f in FROUDE])
    constants, *_ = np.linalg.lstsq(basis(FROUDE), np.log(heights), rcond=None)
    error = np.exp(basis(FROUDE) @ constants) / heights - 1.0
    return constants, float(np.abs(error).max())


if __name__ == "__main__":
    constants, worst = fit()
    print("PATTERN_HEIGHT =", tuple(round(float(c), 6) for c in constants))
    print("worst error of the fit:", round(worst, 4))
