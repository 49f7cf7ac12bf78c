"""A numpy model of a hull's Kelvin wake, for the tests: the linear deep-water waves a pressure
patch moving at a steady speed leaves behind it, summed over the waves' directions.

The hull is a Gaussian pressure patch `exp(-π² r² / L²)` (L its length), as Darmon, Benzaquen
and Raphaël (2014, "Kelvin wake pattern at large Froude numbers") model it. A wave running at
`θ` to the track stands still behind it when its phase speed is `U cos θ`: `k = g / (U² cos² θ)`.
The residue of the steady response at that `k` gives each direction's share,
`k² p̂(k)`, `p̂(k) = exp(-(k L / 2π)²)`; the wake is their sum,

    Z(x, y) = ∫ k² p̂(k) exp(i k (x cos θ - y sin θ)) dθ,   θ in (-π/2, π/2),

with `x` metres behind the hull and `y` across. Nothing here is the add-on's formula: it is the
integral itself, worked out numerically, so its phases, both wave systems, the cusps, their fall
with distance and the narrowing at high Froude numbers come from the physics alone. The height
is `Re(c Z)` for some complex constant `c` (the hull's strength and the response's phase).
"""

import numpy as np
from reference_models import G, hull_spectrum

CUSP_TAN = 1.0 / np.sqrt(2.0)  # tan θ where the two systems meet (the cusp): 35.26°


def field(x, y, speed, length, system="both", samples=6000, chunk=2000):
    """Z at the points (x behind, y across, metres): complex, the height being Re(c Z).

    `system`: "both", "transverse" (|tan θ| below the cusp's) or "diverging" (above it)."""
    x = np.asarray(x, float).ravel()
    y = np.asarray(y, float).ravel()
    k0 = G / speed**2
    # Directions up to where the spectrum has fallen below 1e-6 of its peak.
    k_max = 2.0 * np.pi / length * np.sqrt(1.0 + np.log(1e6))
    theta_max = np.arccos(np.sqrt(min(1.0, k0 / k_max)))
    theta = np.linspace(-theta_max, theta_max, samples)
    tau = np.abs(np.tan(theta))
    keep = {
        "both": np.ones_like(theta, bool),
        "transverse": tau <= CUSP_TAN,
        "diverging": tau > CUSP_TAN,
    }[system]
    theta = theta[keep]
    k = k0 / np.cos(theta) ** 2
    weight = hull_spectrum(k, length) * (theta_max * 2.0 / (samples - 1))
    kc, ks = k * np.cos(theta), k * np.sin(theta)
    out = np.empty(len(x), complex)
    for start in range(0, len(x), chunk):
        part = slice(start, start + chunk)
        phase = np.outer(x[part], kc) - np.outer(y[part], ks)
        out[part] = np.exp(1j * phase) @ weight
    return out


def fit(height, *fields):
    """Least squares: complex constants c_i with height ≈ Re(Σ c_i Z_i); returns (c, residual),
    the residual's rms over the height's."""
    columns = []
    for z in fields:
        columns += [z.real, -z.imag]
    a = np.stack(columns, axis=1)
    solution, *_ = np.linalg.lstsq(a, height, rcond=None)
    c = solution[0::2] + 1j * solution[1::2]
    residual = height - a @ solution
    return c, float(np.sqrt(np.mean(residual**2)) / np.sqrt(np.mean(height**2)))


def highest_angle(x, y, height, x_band, bins=np.arange(0.0, 30.0, 0.5)):
    """The angle (degrees) from the track of the 0.5-degree sector where the waves are highest
    (their rms), among the points `x_band` = (low, high) metres behind."""
    pick = (x > x_band[0]) & (x < x_band[1])
    angle = np.degrees(np.arctan2(np.abs(y[pick]), x[pick]))
    which = np.digitize(angle, bins)
    rms = [
        np.sqrt(np.mean(height[pick][which == i] ** 2)) if (which == i).any() else 0.0
        for i in range(1, len(bins))
    ]
    return float(bins[int(np.argmax(rms))] + 0.25)
