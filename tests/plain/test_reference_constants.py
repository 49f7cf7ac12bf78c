"""Issue 56 point 3: the add-on's reference numbers against the spec's and the literature's, written
here or in `tools/reference_models.py` (the tests' models and constants, each with its source), not
read from the add-on (a test that reads its expectation from the code passes whatever the code says).

The sources: `SPEC.md` (the project's restatement of the seeds and of nature's numbers, section 1
the lake's defaults, 2 the ocean's waves, 5 the sea, the wakes and Snell's window), `docs/MODEL.md`
(the caustics' fade, the Jerlov presets) and `docs/BENCHMARKS.md` (the light shafts' phase), each
cited where its number is written.
"""

import json
import math

import numpy as np
import pytest
import reference_models as rm
from conftest import ROOT, load

# SPEC section 2, as written there: the seeds' four waves in their Y-up world,
# (amplitude A, wavelength lambda, speed s, direction D in their (x, z) plane), and
# h_i = A_i sin(dot(D_i, xz) / lambda_i + t s_i), D_i normalised.
SEEDS_WAVES = rm.SEEDS_WAVES


def _to_blender(direction):
    """SPEC: an XNA vector (x, y, z) is Blender's (x, -z, y), so the seeds' (x, z) is (x, -z)."""
    x, z = direction
    return np.array([x, -z]) / math.hypot(x, z)


def _seeds_height_and_slope(xy, t):
    """SPEC section 2's sum at Blender points `xy` (N, 2), worked in the seeds' own frame: a
    Blender point (x, y) is their (x, z) = (x, -y); the slope (d/dx, d/dy) is turned back."""
    seeds_xz = np.column_stack([xy[:, 0], -xy[:, 1]])
    height = np.zeros(len(xy))
    slope_xz = np.zeros((len(xy), 2))
    for amplitude, length, speed, direction in SEEDS_WAVES:
        d = np.array(direction) / math.hypot(*direction)
        arg = seeds_xz @ d / length + t * speed
        height += amplitude * np.sin(arg)
        slope_xz += (amplitude * np.cos(arg) / length)[:, None] * d
    return height, np.column_stack([slope_xz[:, 0], -slope_xz[:, 1]])


def test_the_ocean_s_four_waves_are_the_seeds_table():
    waves = load("nodes.wave_math").DEFAULT_WAVES
    assert len(waves) == len(SEEDS_WAVES)
    for number, (wave, (amplitude, length, speed, direction)) in enumerate(zip(waves, SEEDS_WAVES)):
        assert (wave.amplitude, wave.wavelength, wave.speed) == (amplitude, length, speed), number
        found = np.array(wave.direction[:2]) / np.linalg.norm(wave.direction[:2])
        assert np.allclose(found, _to_blender(direction), atol=1e-12), number


def test_the_wave_reference_model_is_spec_s_sum_of_sines():
    """`wave_math`'s heights and normals (what `tests/test_waves.py` compares the geometry nodes
    with) are SPEC's formulas for its table, worked here in the seeds' frame."""
    wave_math = load("nodes.wave_math")
    rng = np.random.default_rng(56)
    xy = rng.uniform(-40.0, 40.0, (500, 2))
    for t in (0.0, 1.7, 12.25):
        height, slope = _seeds_height_and_slope(xy, t)
        assert np.abs(wave_math.heights(xy, t) - height).max() < 1e-12
        normal = np.column_stack([-slope, np.ones(len(xy))])
        normal /= np.linalg.norm(normal, axis=1, keepdims=True)
        assert np.abs(wave_math.normals(xy, t) - normal).max() < 1e-12
    assert np.ptp(_seeds_height_and_slope(xy, 0.0)[0]) > 1.0, "the points see real waves"


def _defaults(sockets):
    return {socket.name: socket.default for socket in sockets}


def test_the_lake_preset_and_the_groups_hold_the_seeds_defaults():
    """SPEC section 1: waveHeight 0.3, waveLength 0.1, the "forward" wind (+Y in Blender),
    windForce 0.02, dull colour (0.3, 0.3, 0.5) at 0.2, specular exponent 256, a 128 m plane;
    section 2: bumpStrength 0.5, texStretch 4, deep blue (0, 0.2, 0.4)."""
    lake = json.loads((ROOT / "presets" / "lake.json").read_text(encoding="utf-8"))["values"]
    assert lake["size"] == 128.0
    assert lake["wave_height"] == 0.3 and lake["wave_length"] == 0.1 and lake["wind_force"] == 0.02
    assert lake["wind_direction"] == [0.0, 1.0]
    assert lake["dull_color"] == [0.3, 0.3, 0.5] and lake["dull_blend"] == 0.2
    assert lake["specular_power"] == 256.0
    lake_inputs = load("nodes.lake.water_surface").INPUTS
    surface = _defaults(lake_inputs) | _defaults(load("nodes.bump_uv").SCROLL_INPUTS)
    assert surface["Wave Height"] == 0.3 and surface["Wave Length"] == 0.1 and surface["Wind Force"] == 0.02
    assert tuple(surface["Wind Direction"]) == (0.0, 1.0, 0.0)
    assert tuple(surface["Dull Color"])[:3] == (0.3, 0.3, 0.5) and surface["Dull Blend"] == 0.2
    assert surface["Specular Power"] == 256.0
    normal = _defaults(load("nodes.sea.ocean_normal").NORMAL_SPEC.inputs)
    assert normal["Bump Strength"] == 0.5 and normal["Tex Stretch"] == 4.0
    shade = _defaults(load("nodes.sea.ocean_shade").FULL_SHADE_SPEC.inputs)
    assert tuple(shade["Deep Color"])[:3] == (0.0, 0.2, 0.4)


def test_water_s_physical_constants():
    physics = load("nodes.physics")
    # Refractive index: SPEC section 4 bends the view ray by sin(t) = sin(i) / 1.33; fresh water
    # is 1.333 at 589 nm and 20 degrees C, 1.331-1.344 over the visible (sea water about 0.006 more).
    assert physics.WATER_IOR == pytest.approx(1.33, abs=1e-12)
    # Snell's window (SPEC section 5): the sky within asin(1 / 1.333) = 48.6 degrees of straight up.
    assert math.degrees(math.asin(1.0 / physics.WATER_IOR)) == pytest.approx(rm.critical_angle(), abs=0.25)
    # Gravity: standard 9.80665 m/s^2 (9.780 at the equator, 9.832 at the poles).
    assert physics.G == pytest.approx(9.80665, abs=0.005)
    # Capillary waves (SPEC section 5): sigma / rho = 7.3e-5 m^3/s^2; clean water at 20 degrees C
    # has sigma 0.0728 N/m and rho 998.2 kg/m^3.
    assert physics.SURFACE_TENSION == pytest.approx(7.3e-5, rel=1e-12)
    assert physics.SURFACE_TENSION == pytest.approx(rm.TENSION_OVER_DENSITY, rel=0.01)
    # Kelvin's wedge (SPEC section 5): arms at asin(1/3) = 19.47 degrees to the track.
    assert math.degrees(math.atan(physics.KELVIN_TAN)) == pytest.approx(19.47, abs=0.005)
    assert physics.KELVIN_TAN == pytest.approx(math.tan(math.asin(1.0 / 3.0)), rel=1e-12)
    # The zone the arms' Airy tail is drawn in: a little wider than the wedge (within 2 degrees).
    assert 19.47 < math.degrees(math.atan(physics.KELVIN_ZONE_TAN)) < 21.5


def test_a_grown_sea_is_pierson_and_moskowitz_s():
    """SPEC section 5: Hs = 0.21 U^2 / g, peak angular frequency 0.877 g / U (its crests run at
    g / omega_p = U / 0.877), deep-water waves g T^2 / 2 pi long."""
    sea_math, whitecap_math = load("water.sea.sea_math"), load("water.sea.whitecap_math")
    g = 9.80665
    assert (sea_math.PM_HEIGHT, sea_math.PM_PEAK) == (rm.PM_HEIGHT, rm.PM_PEAK) == (0.21, 0.877)
    for wind in (5.0, 12.0, 20.0):
        assert sea_math.significant_height(wind) == pytest.approx(rm.pm_significant_height(wind, g), rel=1e-3)
        period = rm.pm_peak_period(wind, g)
        assert sea_math.peak_period(wind) == pytest.approx(period, rel=1e-3)
        assert sea_math.sea_peak_wavelength(wind) == pytest.approx(
            rm.deep_water_wavelength(period, g), rel=2e-3
        )
        assert whitecap_math.crest_speed(wind) == pytest.approx(wind / 0.877, rel=1e-12)


def test_the_sea_s_slopes_are_cox_and_munk_s():
    """SPEC section 5 (Cox and Munk 1954, clean sea): mean square slope upwind 3.16e-3 U,
    crosswind 0.003 + 1.92e-3 U; both together 0.003 + 5.12e-3 U (+- 0.004)."""
    sea_math = load("water.sea.sea_math")
    assert sea_math.COX_MUNK_UPWIND == rm.COX_MUNK_UPWIND == 3.16e-3
    assert tuple(sea_math.COX_MUNK_CROSSWIND) == rm.COX_MUNK_CROSSWIND == (0.003, 1.92e-3)
    for wind in (0.0, 5.0, 12.0, 20.0):
        upwind, crosswind = sea_math.cox_munk_slopes(wind)
        assert upwind == pytest.approx(rm.cox_munk(wind)[0], abs=1e-15)
        assert crosswind == pytest.approx(rm.cox_munk(wind)[1], rel=1e-12)
        assert abs(upwind + crosswind - (0.003 + 5.12e-3 * wind)) <= 0.004


def test_whitecaps_cover_what_monahan_and_o_muircheartaigh_measured():
    """SPEC section 5: W = 3.84e-6 U^3.41 (U at 10 m)."""
    whitecap_math = load("water.sea.whitecap_math")
    assert tuple(whitecap_math.MONAHAN) == rm.MONAHAN == (3.84e-6, 3.41)
    for wind in (5.0, 10.0, 15.0, 20.0):
        assert whitecap_math.monahan(wind) == pytest.approx(rm.monahan(wind), rel=1e-12)


# Jerlov's water types (Jerlov 1976, Marine Optics): downwelling diffuse attenuation Kd per metre
# at 650, 550 and 475 nm (red, green, blue), as docs/MODEL.md quotes them (`rm.JERLOV_KD`, which
# tests/test_underwater_fog.py renders); the presets carry them as their absorption.
@pytest.mark.parametrize("preset", list(rm.JERLOV_KD))
def test_the_jerlov_presets_carry_jerlov_s_attenuation(preset):
    values = json.loads((ROOT / "presets" / f"{preset}.json").read_text(encoding="utf-8"))["values"]
    assert tuple(values["absorption"]) == rm.JERLOV_KD[preset]


def test_the_caustics_fade_and_the_shafts_phase():
    # docs/MODEL.md section 8: the caustics' contrast falls as exp(-d / 8 m).
    assert load("nodes.caustics").FADE_DEPTH == rm.CAUSTICS_FADE_DEPTH == 8.0
    # docs/BENCHMARKS.md, light shafts: Henyey-Greenstein's g 0.85. Sea water scatters forward:
    # fits to Petzold's measured volume scattering functions give g of about 0.85-0.95 (0.92 for
    # the average particle phase function drawn from them, Mobley, Light and Water, 1994).
    anisotropy = load("nodes.under.underwater_fog").SHAFTS_ANISOTROPY
    assert anisotropy == rm.SHAFTS_PHASE_G == 0.85
    assert 0.8 <= anisotropy <= 0.95
