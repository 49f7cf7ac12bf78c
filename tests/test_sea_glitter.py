"""The sun's glitter on the open sea spreads as Cox and Munk's slopes predict (issue 24, point 3).

From 10 m up, looking towards a sun 25 degrees up across a 10 m/s wind from (0.8, 0.6), the ocean
shading's glint view (Debug View 5, `pow(max(reflect(L, n) . eye, 0), Glint Power)`) with a sharp
lobe (Glint Power 1000, so the slopes, not the lobe, set the spread) is compared with numpy's:
a pixel glints as often as the sea holds the slope that mirrors the sun into it, Cox and Munk's
normal distribution of the half vector's slopes (upwind 3.16e-3 U, crosswind 0.003 + 1.92e-3 U),
over cos^3 of its tilt (slopes to solid angle). The glitter's width across and down the frame
(the spread of the glint around its centre, weighted by it) agrees within 30%.

Measured: EEVEE 1.01 across and 0.90 down; Cycles 1.24 and 1.14. EEVEE filters the bump taps
with distance (mipmaps), so in the glitter's far band (the frame's second sixth from the top,
the sea 60 m and more ahead) it is 0.45 as wide as numpy's, where Cycles keeps 0.89: the README
says so, and this test prints it without holding EEVEE to it.
"""

import math

import bpy
import numpy as np
import pytest
from mathutils import Vector
from reference_models import cox_munk

import harness

pytestmark = pytest.mark.render

WIND_SPEED = 10.0
WIND = (0.8, 0.6)
SUN_ELEVATION, SUN_AZIMUTH = math.radians(25.0), math.radians(70.0)
POWER = 1000.0


def _glitter_scene(engine):
    scene = harness.clean_scene(engine=engine, width=240, height=135, samples=1)
    if engine == "CYCLES":
        scene.cycles.samples = 4
        scene.cycles.device = "CPU"
    harness.set_world_color(scene, (0.45, 0.6, 0.8), 1.0)
    toward = Vector((math.cos(SUN_AZIMUTH), math.sin(SUN_AZIMUTH), 0.0))
    travels = Vector(
        (-toward.x * math.cos(SUN_ELEVATION), -toward.y * math.cos(SUN_ELEVATION), -math.sin(SUN_ELEVATION))
    )
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.rotation_euler = travels.to_track_quat("-Z", "Y").to_euler()
    scene.collection.objects.link(sun)
    sea = harness.addon("api").add_water(
        scene, preset="open_sea", sea_wind_speed=WIND_SPEED, wind_direction=WIND
    )
    shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(sea.object.active_material)[1]
    shade.inputs["Debug View"].default_value = 5
    shade.inputs["Glint Power"].default_value = POWER
    ahead = 100.0 * toward
    camera = harness.add_camera(
        scene, (0.0, 0.0, 10.0), (ahead.x, ahead.y, 10.0 - 100.0 * math.tan(math.radians(14.0))), lens=24.0
    )
    camera.data.clip_end = 20000.0
    scene.camera = camera
    scene.frame_set(30)
    return scene, camera, Vector(shade.inputs["Sun Direction"].default_value).normalized()


def _predicted(eye, sun):
    """Cox and Munk's glitter: the density of the half vector's slopes over cos^3 of its tilt."""
    half = eye - np.array(sun)[None, None, :]
    half /= np.linalg.norm(half, axis=-1, keepdims=True)
    slope_x, slope_y = -half[..., 0] / half[..., 2], -half[..., 1] / half[..., 2]
    along = np.array(WIND) / np.hypot(*WIND)
    up = slope_x * along[0] + slope_y * along[1]
    cross = -slope_x * along[1] + slope_y * along[0]
    upwind, crosswind = cox_munk(WIND_SPEED)
    return np.exp(-(up**2) / (2 * upwind) - cross**2 / (2 * crosswind)) / half[..., 2] ** 3


def _widths(image):
    """(spread across, spread down) of an image's weight around its centre, in pixels."""
    rows, cols = np.indices(image.shape)
    total = image.sum()
    x, y = (image * cols).sum() / total, (image * rows).sum() / total
    return (
        math.sqrt((image * (cols - x) ** 2).sum() / total),
        math.sqrt((image * (rows - y) ** 2).sum() / total),
    )


@pytest.mark.parametrize("engine", ["eevee", "CYCLES"])
def test_the_sun_s_glitter_spreads_as_cox_and_munk_s_slopes_predict(addon, eevee, render, engine):
    scene, camera, sun = _glitter_scene(eevee if engine == "eevee" else engine)
    origin, directions = harness.pixel_rays(scene, camera)
    sea = directions[..., 2] < -0.005
    glint = np.where(sea, render(scene, f"glitter_{engine}", exr=True)[..., 0], 0.0)
    predicted = np.where(sea, _predicted(-directions, sun), 0.0)
    (across, down), (want_across, want_down) = _widths(glint), _widths(predicted)
    far = slice(glint.shape[0] // 3, glint.shape[0] // 2)
    far_ratio = _widths(glint[far])[0] / _widths(predicted[far])[0]
    print(
        f"{engine}: glitter {across:.1f} x {down:.1f} px, Cox and Munk {want_across:.1f} x {want_down:.1f} "
        f"({across / want_across:.2f}, {down / want_down:.2f}); far band across {far_ratio:.2f}"
    )
    assert 0.7 < across / want_across < 1.3
    assert 0.7 < down / want_down < 1.3
