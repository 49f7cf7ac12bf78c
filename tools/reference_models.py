"""The numpy reference models the tests and tools compare the add-on with, each written once
(issue 56 point 3).

Plain numpy, no bpy: importable from the Blender tests, from `tests/plain` and from the tools
(`tools/` is on pytest's `pythonpath`; `tools/bench` puts it on `PYTHONPATH`). Nothing here is
read from the add-on: the constants are written below with their source, so a test's
expectation does not move when the code under test does. `tests/plain/test_reference_models.py`
holds these models to textbook values; `tests/plain/test_reference_constants.py` holds the
add-on's own constants to the same sources.

Conventions: vectors are numpy arrays, the last axis x, y, z (Z up, as Blender); `eye` is the
unit direction from a surface point towards the eye, `light` the way light travels; angles are
radians unless a name says degrees.
"""

import math

import numpy as np

# --- Constants, each with its source ---------------------------------------------------------

# Gravity: standard gravity is 9.80665 m/s^2 (3rd CGPM, 1901), 9.780 at the equator, 9.832 at the
# poles; 9.81 to three figures, as SPEC section 5 and the add-on take it (0.03% off: under every
# tolerance here; tests/plain checks the add-on's wave-length solver to 1e-9 with the same g).
G = 9.81
# Refractive index of water: 1.3330 for fresh water at 589 nm and 20 degrees C (Daimon and
# Masumura 2007, Applied Optics 46, 3811; IAPWS 1997), 1.331-1.344 over the visible, sea water
# about 0.006 more. The add-on takes SPEC's rounded 1.33 (Snell's window 48.75 against 48.61).
WATER_IOR = 1.333
# Capillary waves: surface tension of clean water 0.0728 N/m and its density 998.2 kg/m^3, both at
# 20 degrees C (CRC Handbook of Chemistry and Physics); sigma / rho = 7.29e-5 m^3/s^2 (SPEC: 7.3e-5).
SURFACE_TENSION = 0.0728
WATER_DENSITY = 998.2
TENSION_OVER_DENSITY = SURFACE_TENSION / WATER_DENSITY
# Pierson and Moskowitz (1964): a fully grown sea's significant height 0.21 U^2 / g and its peak
# angular frequency 0.877 g / U, U the wind 19.5 m up.
PM_HEIGHT = 0.21
PM_PEAK = 0.877
# Cox and Munk (1954), a clean sea: mean square slope upwind 3.16e-3 U, crosswind 0.003 + 1.92e-3 U
# (U m/s, 12.5 m up).
COX_MUNK_UPWIND = 3.16e-3
COX_MUNK_CROSSWIND = (0.003, 1.92e-3)
# Monahan and O'Muircheartaigh (1980): whitecaps cover W = 3.84e-6 U^3.41 of the sea (U at 10 m).
MONAHAN = (3.84e-6, 3.41)
# Jerlov's water types (Jerlov 1976, Marine Optics): downwelling diffuse attenuation Kd per metre
# at 650, 550 and 475 nm (red, green, blue), as docs/MODEL.md quotes them.
JERLOV_KD = {
    "jerlov_ocean_i": (0.36, 0.063, 0.018),
    "jerlov_coastal_3": (0.46, 0.19, 0.29),
    "jerlov_coastal_9": (0.76, 0.63, 1.23),
}
# The light shafts' Henyey-Greenstein g, as docs/BENCHMARKS.md ("Light shafts") gives it: sea water
# scatters forward (fits to Petzold's measured volume scattering functions give g of about
# 0.85-0.95; 0.92 for the average particle phase function drawn from them, Mobley, Light and
# Water, 1994).
SHAFTS_PHASE_G = 0.85
# The caustic pattern's contrast falls as exp(-d / 8 m) with the depth d of water under the
# surface (docs/MODEL.md, caustics): the add-on's design value, pinned here, not read from it.
CAUSTICS_FADE_DEPTH = 8.0
# The seeds' four waves, SPEC section 2 as written there, in their Y-up world: (amplitude A,
# wavelength lambda, speed s, direction D in their (x, z) plane), h_i = A_i sin(dot(D_i, xz) /
# lambda_i + t s_i), D_i normalised. An XNA vector (x, y, z) is Blender's (x, -z, y).
SEEDS_WAVES = (
    (0.3, 10.0, 1.0, (-1.0, 0.0)),
    (0.4, 5.0, 2.0, (-1.0, 0.5)),
    (0.2, 15.0, 0.5, (-1.0, 0.7)),
    (0.3, 7.0, 1.5, (-1.0, -0.5)),
)

UP = np.array((0.0, 0.0, 1.0))


# --- Optics ----------------------------------------------------------------------------------


def fresnel(cos_i, n=WATER_IOR):
    """Fresnel's reflectance of unpolarised light, the mean of the s and p reflectances (Born and
    Wolf, Principles of Optics, 1.5.2), meeting a surface at `cos_i` (cosine to its normal) into a
    medium `n` times as dense (`n` the ratio: 1.333 from air into water, 1 / 1.333 from inside
    water up into the air); 1 past the critical angle (total internal reflection)."""
    cos_i = np.clip(cos_i, 1e-6, 1.0)
    sin_t = np.sqrt(1.0 - cos_i**2) / n
    cos_t = np.sqrt(np.clip(1.0 - sin_t**2, 0.0, 1.0))
    rs = ((cos_i - n * cos_t) / (cos_i + n * cos_t)) ** 2
    rp = ((n * cos_i - cos_t) / (n * cos_i + cos_t)) ** 2
    return np.where(sin_t >= 1.0, 1.0, (rs + rp) / 2.0)


def critical_angle(n=WATER_IOR):
    """Snell's window: degrees from the normal past which light inside water (index `n`) cannot
    leave it, asin(1 / n) (48.6 degrees for 1.333)."""
    return math.degrees(math.asin(1.0 / n))


def refracted_cos(cos_i, n=WATER_IOR):
    """Snell's law, sin t = sin i / n: the cosine of the refracted ray's angle to the normal, for a
    ray meeting the surface at `cos_i` from the side of index 1."""
    return np.sqrt(1.0 - (1.0 - np.asarray(cos_i) ** 2) / n**2)


def to_sun(elevation, azimuth):
    """The unit vector towards a sun `elevation` degrees up at `azimuth` degrees: where a Blender
    sun lamp turned (90 - elevation, 0, azimuth) degrees shines from."""
    e, a = math.radians(elevation), math.radians(azimuth)
    return np.array([math.cos(e) * math.sin(a), -math.cos(e) * math.cos(a), math.sin(e)])


def beer_lambert(absorption, path):
    """Beer and Lambert: the share T = exp(-c d) of light kept over `path` metres (any shape) of
    water absorbing `absorption` per metre (one value per channel: the channels are a last axis)."""
    return np.exp(-np.asarray(absorption) * np.asarray(path)[..., None])


def through_water(light, far, kept):
    """What is seen through water that keeps the share `kept` (Beer-Lambert's T) of `light`: the
    rest is filled in with the water's own far colour, T light + L (1 - T) (single-scattering
    fog: the in-scattered light grows as the transmitted fades)."""
    return kept * light + far * (1.0 - kept)


def cox_munk(wind):
    """Cox and Munk (1954), a clean sea: (upwind, crosswind) mean square slopes at `wind` m/s."""
    return COX_MUNK_UPWIND * wind, COX_MUNK_CROSSWIND[0] + COX_MUNK_CROSSWIND[1] * wind


# --- The lake's and the seeds' ocean shading (SPEC sections 1 and 2) -------------------------


def lake_fresnel(eye):
    """The seeds' lake: F = dot(eye, up), the refraction's share on flat water (SPEC section 1's
    Fresnel stand-in), for `eye` towards the eye (any length), clipped to 0..1."""
    eye = np.asarray(eye, float)
    return np.clip(eye[..., 2] / np.linalg.norm(eye, axis=-1), 0.0, 1.0)


def lake_composition(reflection, refraction, f, blend, dull, glint):
    """The lake's final colour from its parts (SPEC section 1):
    (1 - b) ((1 - F) reflection + F refraction) + b dull + glint."""
    return (1 - blend) * ((1 - f) * reflection + f * refraction) + blend * np.asarray(dull) + glint


def flat_glint(eye, light, power, strength=1.0):
    """The seeds' glint on flat water (SPEC section 1, Phong's lobe): strength x
    max(eye . reflect(light, up), 0)^power, `eye` towards the eye (any length), `light` the way the
    sunlight travels (any length)."""
    eye = np.asarray(eye, float)
    eye = eye / np.linalg.norm(eye, axis=-1, keepdims=True)
    light = np.asarray(light, float) / np.linalg.norm(light)
    reflected = light * np.array([1.0, 1.0, -1.0])  # reflect(L, up)
    return strength * np.maximum((eye * reflected).sum(-1), 0.0) ** power


def seeds_ocean_fresnel(eye, normal=UP):
    """The seeds' ocean Fresnel (SPEC section 2): F = dot(eye, n) / 2 + 0.5, the deep colour's
    share (the sky's 1 - F), `eye` the unit direction towards the eye."""
    return (np.asarray(eye) * normal).sum(axis=-1) / 2 + 0.5


def equirect_uv(direction):
    """Blender's equirectangular look-up of a unit direction (the Environment Texture's default):
    (u, v), u = 0.5 - atan2(y, x) / 2 pi, v = 0.5 + atan2(z, |xy|) / pi."""
    direction = np.asarray(direction)
    x, y, z = direction[..., 0], direction[..., 1], direction[..., 2]
    return 0.5 - np.arctan2(y, x) / (2 * np.pi), 0.5 + np.arctan2(z, np.hypot(x, y)) / np.pi


# --- Texture sampling and the lake's bump normal ---------------------------------------------


def _address(index, size, wrap):
    if wrap == "mirror":
        index = np.mod(index, 2 * size)
        return np.where(index >= size, 2 * size - 1 - index, index)
    if wrap == "clamp":
        return np.clip(index, 0, size - 1)
    return np.mod(index, size)  # "repeat"


def bilinear(image, uv, wrap="repeat", wrap_v=None):
    """GPU bilinear sampling at mip level 0 (texel centres at (i + 0.5) / size, the OpenGL rule),
    `image` (H, W, C) with row 0 at v = 0 as `Image.pixels` holds it; `wrap` ("repeat", "mirror":
    mirrored repeat, "clamp") addresses both axes, `wrap_v` v alone when given."""
    height, width = image.shape[:2]
    x = uv[..., 0] * width - 0.5
    y = uv[..., 1] * height - 0.5
    x0, y0 = np.floor(x).astype(np.int64), np.floor(y).astype(np.int64)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    xs = _address(x0, width, wrap), _address(x0 + 1, width, wrap)
    ys = _address(y0, height, wrap_v or wrap), _address(y0 + 1, height, wrap_v or wrap)
    first = image[ys[0], xs[0]] * (1 - fx) + image[ys[0], xs[1]] * fx
    second = image[ys[1], xs[0]] * (1 - fx) + image[ys[1], xs[1]] * fx
    return first * (1 - fy) + second * fy


def bump_normal_colour(
    image, uv, wave_length, wind, seconds, wind_force, layers=((1.0, 1.0),), strength=1.0, turn=0.0
):
    """The lake's bump normal, as Debug View 4 shows it (`n * 0.5 + 0.5`; docs/MODEL.md 1, steps
    1-3), at plane UVs `uv` (..., 2): the bump image read (mirrored repeat) in the wind's frame,
    scrolled downwind by `seconds x wind_force`, each layer (UV scale, scroll speed) of `layers`
    averaged, its slopes turned back onto the UV axes, scaled by `strength`, and into the world
    through the water's tangent frame (+u and +v its X and Y axes, turned by `turn` about Z)."""
    w = np.array(wind, float) / np.hypot(*wind)
    p = np.array((w[1], -w[0]))
    base = np.stack((uv @ p, uv @ w), axis=-1) / wave_length
    scroll = np.array((0.0, seconds * wind_force / wave_length))
    total = sum(bilinear(image, scale * base + speed * scroll, "mirror") for scale, speed in layers)
    t = 2.0 * total / len(layers) - 1.0
    slope = strength * (t[..., :1] * p + t[..., 1:2] * w)
    tangent = np.array((math.cos(turn), math.sin(turn)))
    bitangent = np.array((-math.sin(turn), math.cos(turn)))
    n = np.concatenate((slope[..., :1] * tangent + slope[..., 1:2] * bitangent, t[..., 2:]), axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return n * 0.5 + 0.5


# --- Waves -----------------------------------------------------------------------------------


def deep_water_wavelength(period, g=G):
    """Deep-water waves of `period` seconds (omega^2 = g k): g T^2 / 2 pi metres long."""
    return g * period**2 / (2.0 * math.pi)


def wavelength_at_speed(speed, g=G):
    """The deep-water waves whose crests run at `speed` (c = sqrt(g / k)): 2 pi U^2 / g metres long;
    behind a hull at `speed`, the Kelvin wake's transverse waves (they stand still behind it)."""
    return 2.0 * math.pi * speed**2 / g


def capillary_gravity_omega(k, g=G, tension=TENSION_OVER_DENSITY):
    """The dispersion relation of deep water with surface tension (Lamb, Hydrodynamics, 267):
    omega^2 = g k + (sigma / rho) k^3, angular frequency of waves of wavenumber `k`."""
    return np.sqrt(g * k + tension * k**3)


def capillary_gravity_group_speed(k, g=G, tension=TENSION_OVER_DENSITY):
    """d omega / d k of `capillary_gravity_omega`: (g + 3 (sigma / rho) k^2) / (2 omega), the speed
    a group of waves of wavenumber `k` (a stone's ring) runs out at."""
    return (g + 3.0 * tension * k**2) / (2.0 * capillary_gravity_omega(k, g, tension))


def pm_significant_height(wind, g=G):
    """Pierson and Moskowitz (1964): a fully grown sea's significant height 0.21 U^2 / g, metres."""
    return PM_HEIGHT * wind**2 / g


def pm_peak_period(wind, g=G):
    """Pierson and Moskowitz (1964): a fully grown sea's peak period 2 pi U / (0.877 g), seconds."""
    return 2.0 * math.pi * wind / (PM_PEAK * g)


def monahan(wind):
    """Monahan and O'Muircheartaigh (1980): the share of the sea whitecaps cover at `wind` m/s,
    3.84e-6 U^3.41 (about 1% at 10 m/s)."""
    return MONAHAN[0] * wind ** MONAHAN[1]


# --- Boat wakes ------------------------------------------------------------------------------


def kriebel_seelig(froude, length, draft, depth, across=None, block=0.6, beta=1.0, g=G):
    """Kriebel and Seelig (2005, "An empirical model for ship-generated waves"): the highest wave,
    crest to trough, `across` metres (a hull length when not given) from the track of a hull
    `length` long at Froude number `froude` drawing `draft` in `depth` of water:
    `g H / U^2 = beta (F* - 0.1)^2 (y / L)^(-1/3)`, `F* = F exp(alpha T / d)`,
    `alpha = 2.35 (1 - Cb)` (Cb the block coefficient), held where their data end (F* and F at 0.5)."""
    across = length if across is None else across
    raised = min(froude * math.exp(2.35 * (1.0 - block) * draft / depth), 0.5)
    return beta * (raised - 0.1) ** 2 * min(froude, 0.5) ** 2 * length * (across / length) ** (-1.0 / 3.0)


def hull_spectrum(k, length):
    """A Gaussian pressure patch `exp(-pi^2 r^2 / L^2)` L long (Darmon, Benzaquen and Raphael 2014):
    each wave direction's share of its Kelvin wake by wavenumber, `k^2 exp(-(k L / 2 pi)^2)`, made
    1 at its peak (waves one hull length long): `(k L / 2 pi)^2 exp(1 - (k L / 2 pi)^2)`."""
    kl = np.asarray(k) * length / (2.0 * np.pi)
    return kl**2 * np.exp(1.0 - kl**2)


# --- Measuring -------------------------------------------------------------------------------


def plane_fit(u, v, z):
    """Least squares plane z = h + a u + b v through points (u, v, z): (h, a, b), the height at
    u = v = 0 and the slopes along u and v."""
    design = np.column_stack([np.ones(len(u)), u, v])
    (height, slope_u, slope_v), *_ = np.linalg.lstsq(design, np.asarray(z, float), rcond=None)
    return height, slope_u, slope_v
