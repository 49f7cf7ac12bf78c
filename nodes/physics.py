"""The physical constants of water every part reads, here once (SPEC section 5).

`nodes/` is the lowest layer (it imports nothing of the add-on's outside it), so the shader and
Geometry Nodes groups and the Python in `water/` all take them from here.
"""

import math

WATER_IOR = 1.33  # refractive index of water (Snell's window asin(1 / 1.33) = 48.8°)
G = 9.81  # gravity, m/s²
SURFACE_TENSION = 7.3e-5  # σ / ρ of clean water, m³/s² (capillary waves: ω² = g k + (σ/ρ) k³)
KELVIN_TAN = 1.0 / math.sqrt(8.0)  # tan 19.47°: the Kelvin wedge's arms, whatever the speed
# A little wider than the wedge: the arms' Airy tail fades just beyond it (tan 20.8°).
KELVIN_ZONE_TAN = 0.38
