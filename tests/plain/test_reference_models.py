"""The tests' numpy reference models (`tools/reference_models.py`) against textbook values: the
models every render and geometry test compares the add-on with are themselves held to the
physics here (the add-on's own constants: test_reference_constants.py)."""

import math

import numpy as np
import pytest
import reference_models as rm


def test_fresnel_at_normal_incidence_grazing_and_from_inside():
    # Normal incidence: ((n - 1) / (n + 1))^2, 2.0% for water (Born and Wolf 1.5.2).
    assert rm.fresnel(1.0, 1.33) == pytest.approx(((1.33 - 1) / (1.33 + 1)) ** 2, rel=1e-9)
    assert rm.fresnel(1.0, 1.33) == pytest.approx(0.0201, abs=5e-5)
    assert rm.fresnel(1.0) == pytest.approx(0.0204, abs=5e-5)  # n 1.333
    # The same from inside the water at normal incidence; all of it at grazing.
    assert rm.fresnel(1.0, 1.0 / 1.333) == pytest.approx(rm.fresnel(1.0), rel=1e-9)
    assert rm.fresnel(0.0) == pytest.approx(1.0, abs=1e-4)
    # Brewster's angle, tan i = n: the p wave is not reflected, so R is half of s's alone.
    brewster = math.atan(1.333)
    cos_i, cos_t = math.cos(brewster), math.cos(math.pi / 2 - brewster)
    rs = ((cos_i - 1.333 * cos_t) / (cos_i + 1.333 * cos_t)) ** 2
    assert rm.fresnel(cos_i) == pytest.approx(rs / 2, rel=1e-9)
    # Reciprocity: light meeting the surface from inside along the refracted ray reflects as much.
    for degrees in (10.0, 30.0, 45.0, 60.0, 80.0):
        cos_i = math.cos(math.radians(degrees))
        assert rm.fresnel(rm.refracted_cos(cos_i), 1.0 / 1.333) == pytest.approx(rm.fresnel(cos_i), rel=1e-9)
    # Rising steadily from 2% to all of it.
    angles = np.radians(np.linspace(0.0, 89.0, 90))
    assert np.all(np.diff(rm.fresnel(np.cos(angles))) > 0)


def test_snells_window_and_snells_law():
    assert rm.critical_angle(1.33) == pytest.approx(48.75, abs=0.005)
    assert rm.critical_angle() == pytest.approx(48.61, abs=0.005)  # n 1.333
    inside = math.radians(rm.critical_angle())
    # From inside, just short of the window's edge some light leaves; past it all is reflected.
    assert rm.fresnel(math.cos(inside - 0.01), 1.0 / rm.WATER_IOR) < 0.5
    assert rm.fresnel(math.cos(inside + 0.01), 1.0 / rm.WATER_IOR) == 1.0
    # sin t = sin i / n; straight down stays straight down; grazing light enters at the critical angle.
    i = math.radians(50.0)
    assert math.sin(math.acos(rm.refracted_cos(math.cos(i)))) == pytest.approx(math.sin(i) / 1.333)
    assert rm.refracted_cos(1.0) == 1.0
    assert math.degrees(math.acos(rm.refracted_cos(0.0))) == pytest.approx(rm.critical_angle())


def test_beer_lambert_and_what_is_seen_through_water():
    kept = rm.beer_lambert((math.log(2.0), 0.0, 2.0 * math.log(2.0)), 1.0)
    assert kept == pytest.approx((0.5, 1.0, 0.25))
    assert rm.beer_lambert((0.1, 0.2, 0.3), np.ones((4, 5))).shape == (4, 5, 3)
    # Nothing kept: the water's own colour; all kept: the light.
    far = np.array((0.0, 0.2, 0.4))
    assert rm.through_water(1.0, far, np.zeros(3)) == pytest.approx(far)
    assert rm.through_water(0.7, far, np.ones(3)) == pytest.approx((0.7, 0.7, 0.7))


def test_a_grown_sea_is_pierson_and_moskowitz_s():
    """Hs = 0.21 U^2 / g, Tp = 2 pi U / (0.877 g): at 10 m/s 2.14 m and 7.30 s, its peak waves
    g T^2 / 2 pi = 83 m long (deep water: L = 1.56 T^2)."""
    assert rm.pm_significant_height(10.0) == pytest.approx(0.21 * 100.0 / 9.81, rel=1e-12)
    assert rm.pm_significant_height(10.0) == pytest.approx(2.14, abs=0.005)
    assert rm.pm_peak_period(10.0) == pytest.approx(7.30, abs=0.005)
    assert rm.deep_water_wavelength(rm.pm_peak_period(10.0)) == pytest.approx(83.3, abs=0.1)
    assert rm.deep_water_wavelength(10.0) == pytest.approx(1.56 * 100.0, rel=0.001)
    # Twice the wind, four times the height, twice the period.
    assert rm.pm_significant_height(20.0) == pytest.approx(4 * rm.pm_significant_height(10.0))
    assert rm.pm_peak_period(20.0) == pytest.approx(2 * rm.pm_peak_period(10.0))


def test_the_dispersion_relation_and_its_group_speed():
    k = np.array((0.05, 0.5, 5.0))
    # Without surface tension, deep water's omega^2 = g k; waves run at sqrt(g / k), groups at half.
    assert rm.capillary_gravity_omega(k, tension=0.0) ** 2 == pytest.approx(9.81 * k, rel=1e-12)
    phase = rm.capillary_gravity_omega(k, tension=0.0) / k
    assert rm.capillary_gravity_group_speed(k, tension=0.0) == pytest.approx(phase / 2, rel=1e-12)
    # Waves whose crests run at U are 2 pi U^2 / g long (the Kelvin wake's transverse waves).
    for speed in (1.0, 3.5, 8.0):
        wavenumber = 2.0 * math.pi / rm.wavelength_at_speed(speed)
        assert rm.capillary_gravity_omega(wavenumber, tension=0.0) / wavenumber == pytest.approx(speed)
    assert rm.wavelength_at_speed(3.5) == pytest.approx(7.85, abs=0.005)
    # sigma / rho of clean water, 7.3e-5 m^3/s^2; the slowest ripples, (4 g sigma / rho)^(1/4) =
    # 23 cm/s, are 2 pi sqrt(sigma / (rho g)) = 1.7 cm long (Lamb, Hydrodynamics, 267).
    assert rm.TENSION_OVER_DENSITY == pytest.approx(7.3e-5, rel=0.005)
    k = np.linspace(100.0, 1000.0, 90001)
    speeds = rm.capillary_gravity_omega(k) / k
    assert speeds.min() == pytest.approx(0.231, abs=0.001)
    assert 2.0 * math.pi / k[np.argmin(speeds)] == pytest.approx(0.0171, abs=0.0002)
    # The analytic group speed is the dispersion relation's derivative.
    for wavenumber in (2.0, 400.0):
        step = wavenumber * 1e-6
        numeric = (
            rm.capillary_gravity_omega(wavenumber + step) - rm.capillary_gravity_omega(wavenumber - step)
        ) / (2 * step)
        assert rm.capillary_gravity_group_speed(wavenumber) == pytest.approx(numeric, rel=1e-7)


def test_whitecaps_slopes_and_wakes():
    # Monahan and O'Muircheartaigh: 1% of the sea at 10 m/s, 4% at 15.
    assert rm.monahan(10.0) == pytest.approx(0.0099, abs=5e-5)
    assert rm.monahan(15.0) == pytest.approx(0.0393, abs=5e-4)
    # Cox and Munk: the two mean square slopes add up to their total, fitted apart as 0.003 +
    # 5.12e-3 U (+- 0.004): 0.054 at 10 m/s.
    upwind, crosswind = rm.cox_munk(10.0)
    assert upwind + crosswind == pytest.approx(0.054, abs=0.001)
    assert upwind > crosswind
    # Kriebel and Seelig: at Froude 0.5 on deep water, g H / U^2 = (0.5 - 0.1)^2 a hull length
    # across, falling as (y / L)^(-1/3): half as high 8 hull lengths across; held above Froude 0.5.
    length = 10.0
    speed = 0.5 * math.sqrt(rm.G * length)
    height = rm.kriebel_seelig(0.5, length, 0.0, 100.0)
    assert rm.G * height / speed**2 == pytest.approx(0.4**2, rel=1e-12)
    assert rm.kriebel_seelig(0.5, length, 0.0, 100.0, across=8 * length) == pytest.approx(height / 2)
    assert rm.kriebel_seelig(0.8, length, 0.0, 100.0) == pytest.approx(height)
    assert rm.kriebel_seelig(0.3, length, 1.0, 4.0) > rm.kriebel_seelig(0.3, length, 0.0, 4.0)
    # A hull's wake spectrum peaks at waves one hull length long, at 1.
    k = np.linspace(0.1, 3.0, 29001)
    spectrum = rm.hull_spectrum(k, 2.0 * math.pi)
    assert k[np.argmax(spectrum)] == pytest.approx(1.0, abs=1e-4) and spectrum.max() == pytest.approx(1.0)


def test_the_seeds_shading_models():
    straight_down, grazing = np.array((0.0, 0.0, 1.0)), np.array((1.0, 0.0, 0.0))
    # The lake's F = dot(eye, up): all refraction looking straight down, none at grazing.
    assert rm.lake_fresnel(np.array((0.0, 0.0, 3.0))) == 1.0 and rm.lake_fresnel(grazing) == 0.0
    assert rm.lake_fresnel(np.array((1.0, 0.0, 1.0))) == pytest.approx(math.sqrt(0.5))
    # The seeds' ocean F = dot(eye, n) / 2 + 0.5: 1 straight down, a half at grazing.
    assert rm.seeds_ocean_fresnel(straight_down) == 1.0 and rm.seeds_ocean_fresnel(grazing) == 0.5
    # The composition: F 1 is the refraction alone, blend 1 the dull colour, plus the glint.
    one = np.ones(3)
    assert rm.lake_composition(0 * one, 0.5 * one, 1.0, 0.0, one, 0.1) == pytest.approx(0.6 * one)
    assert rm.lake_composition(0.2 * one, 0.5 * one, 0.3, 1.0, (0.3, 0.3, 0.5), 0.0) == pytest.approx(
        (0.3, 0.3, 0.5)
    )
    # The glint: the strength where the eye sees the sun mirrored, falling off as cos^power.
    light = np.array((0.0, 0.6, -0.8))  # the way the sunlight travels
    mirrored = np.array((0.0, 0.6, 0.8))
    assert rm.flat_glint(mirrored, light, 64.0, 2.0) == pytest.approx(2.0)
    off = np.array((0.0, math.sin(math.asin(0.6) + 0.1), math.cos(math.asin(0.6) + 0.1)))
    assert rm.flat_glint(off, light, 64.0) == pytest.approx(math.cos(0.1) ** 64)
    assert rm.flat_glint(-mirrored, light, 64.0) == 0.0


def test_equirectangular_look_up_and_the_sun():
    u, v = rm.equirect_uv(np.array([(1.0, 0.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 1.0)]))
    assert u[:2] == pytest.approx((0.5, 0.75)) and v == pytest.approx((0.5, 0.5, 1.0))
    assert rm.to_sun(90.0, 30.0) == pytest.approx((0.0, 0.0, 1.0))
    assert rm.to_sun(0.0, 90.0) == pytest.approx((1.0, 0.0, 0.0))
    assert np.linalg.norm(rm.to_sun(55.0, 40.0)) == pytest.approx(1.0)


def test_bilinear_sampling_and_the_bump_normal():
    image = np.arange(12.0).reshape(3, 4, 1)  # row 0 at v = 0
    centres = np.array([((i + 0.5) / 4, (j + 0.5) / 3) for j in range(3) for i in range(4)])
    for wrap in ("repeat", "mirror", "clamp"):
        assert rm.bilinear(image, centres, wrap)[:, 0] == pytest.approx(np.arange(12.0))
    between = np.array([(1.0 / 4, 0.5 / 3)])  # halfway between texels 0 and 1 of row 0
    assert rm.bilinear(image, between)[0, 0] == pytest.approx(0.5)
    left_edge = np.array([(0.0, 0.5 / 3)])  # halfway between texel 0 and the one past the edge
    assert rm.bilinear(image, left_edge, "repeat")[0, 0] == pytest.approx((0.0 + 3.0) / 2)
    assert rm.bilinear(image, left_edge, "mirror")[0, 0] == pytest.approx(0.0)
    assert rm.bilinear(image, np.array([(0.5 / 4, 0.0)]), "repeat", wrap_v="clamp")[0, 0] == pytest.approx(
        0.0
    )
    # A flat bump (the normal straight up, stored as 0.5, 0.5, 1) is flat water whatever the wind.
    flat = np.broadcast_to((0.5, 0.5, 1.0), (8, 8, 3))
    uv = np.random.default_rng(5).uniform(0.0, 1.0, (10, 2))
    colour = rm.bump_normal_colour(flat, uv, 0.1, (0.6, -0.8), 1.5, 0.02, turn=0.3)
    assert colour == pytest.approx(np.broadcast_to((0.5, 0.5, 1.0), (10, 3)))


def test_a_plane_fit_recovers_the_plane():
    rng = np.random.default_rng(3)
    u, v = rng.uniform(-1.0, 1.0, (2, 50))
    assert rm.plane_fit(u, v, 0.4 + 0.1 * u - 0.3 * v) == pytest.approx((0.4, 0.1, -0.3))
