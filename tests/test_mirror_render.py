"""What an artist sees after one click: the water mirrors, shows what is under it, and glints.

One scene for the module, made with `object.water_add` (mirror set-up
on), rendered small. The water is a still mirror (Wave Height, Bump Strength,
Dull Blend 0) so that every pixel can be predicted.
"""

import math

import bpy
import numpy as np
import pytest
from mathutils import Vector
from reference_models import flat_glint, lake_fresnel

import harness

pytestmark = pytest.mark.render

SKY = (0.2, 0.4, 0.8)
RED, GREEN, YELLOW = (1.0, 0.05, 0.05), (0.05, 1.0, 0.05), (1.0, 1.0, 0.05)
STILL = {"wave_height": 0.0, "bump_strength": 0.0, "dull_blend": 0.0, "specular_strength": 0.0}


def _glow(name, color, location, size):
    scene = bpy.context.scene
    return harness.add_cube(
        scene, location, size=size, material=harness.emission_material(name, color), name=name
    )


@pytest.fixture(scope="module")
def pond(addon, eevee):
    """Still water (40 m) made by the operator, a sky, three coloured glowing blocks and a sun."""
    # One sample: software EEVEE's cost is per sample, hardly per pixel (this module: 156 s at 4
    # samples, 58 s at 1). The mirror is still (no bump, no waves): each pixel is one colour, so
    # the models hold at 1 sample as at 4, and the wobble is counted in whole pixels either way.
    scene = harness.clean_scene(engine=eevee, width=128, height=72, samples=1)
    harness.set_world_color(scene, SKY)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 0.0  # only the group's glint, not the lamp's own highlight
    scene.collection.objects.link(sun)
    bpy.ops.object.water_add(size=40.0, location=(0, 0, 0), **STILL)
    water = bpy.context.object
    objects = {
        "red": _glow("Red", RED, (0, 6, 1), 1.0),  # above the water, in view
        "green": _glow("Green", GREEN, (0, 8, 4), 2.0),  # above the water, above the frame
        "yellow": _glow("Yellow", YELLOW, (3, 0, -1.5), 1.0),  # under the water
        "floor": _glow("Floor", (0, 0, 0), (0, 0, -0.8), 1.0),  # black, just under all the water
    }
    objects["floor"].scale = (40, 40, 1)
    for obj in objects.values():
        obj.hide_render = True
    return {"scene": scene, "water": water, "sun": sun, **objects}


@pytest.fixture
def shown(pond):
    """Shows the named objects for one test; everything is hidden again afterwards."""
    made = []

    def _show(*names):
        for name in names:
            pond[name].hide_render = False
            made.append(pond[name])

    yield _show
    for obj in made:
        obj.hide_render = True


def _mean(pixels, col, row, radius=1):
    col, row = int(col), int(row)
    return pixels[row - radius : row + radius + 1, col - radius : col + radius + 1, :3].mean(axis=(0, 1))


def _is(color, expected, tolerance=0.25):
    """The pixel colour, normalised, points the way `expected` does."""
    color, expected = np.asarray(color), np.asarray(expected)
    return np.abs(color / max(color.max(), 1e-6) - expected / expected.max()).max() < tolerance


def _still_water(camera, point, reflected, refracted=SKY):
    """The model on still water at `point`: (1 - F) * reflected + F * refracted, F = dot(eye, up)."""
    f = lake_fresnel(np.array(camera.matrix_world.translation) - np.asarray(point, float))
    return (1 - f) * np.asarray(reflected) + f * np.asarray(refracted)


def test_object_above_the_water_shows_mirrored_below_it_and_not_when_hidden(pond, shown, render, project):
    scene = pond["scene"]
    camera = harness.add_camera(scene, (0, -4, 2), (0, 6, 0))
    shown("red")
    pixels = render(scene, "red", exr=True)
    (obj_col, obj_row), (mirror_col, mirror_row) = project(scene, camera, [(0, 6, 1), (0, 6, -1)])
    assert mirror_row > obj_row + 5, "the mirror image lies below the object"
    assert _is(_mean(pixels, obj_col, obj_row), RED)
    # Where the mirror image lands, the water shows the red block (nothing under it but sky).
    seen = _mean(pixels, mirror_col, mirror_row)
    reflection_point = (0, 6 - 1 * (6 + 4) / (2 + 1), 0)  # where the ray to the image crosses the water
    assert np.abs(seen - _still_water(camera, reflection_point, RED)).max() < 0.1, seen

    pond["red"].hide_render = True
    hidden = _mean(render(scene, "red-hidden", exr=True), mirror_col, mirror_row)
    assert np.abs(hidden - SKY).max() < 0.03, "the sky shows instead"


@pytest.mark.lts
def test_object_outside_the_view_shows_in_the_mirror(pond, shown, render, project):
    scene = pond["scene"]
    camera = harness.add_camera(scene, (0, -2, 3), (0, 6, 0))
    shown("green")
    ((_, obj_row),) = project(scene, camera, [(0, 8, 5)])
    assert obj_row < 0, "the block itself is above the frame"
    ((col, row),) = project(scene, camera, [(0, 8, -4)])
    pixels = render(scene, "green", exr=True)
    seen = _mean(pixels, col, row)
    assert np.abs(seen - _still_water(camera, (0, 8 - 4 * 10 / 7, 0), GREEN)).max() < 0.1, seen

    # Without the planar probe, screen tracing cannot see the block: the sky shows.
    probe = pond["water"].children[0]
    probe.hide_render = True
    try:
        without = render(scene, "green-no-probe", exr=True)
    finally:
        probe.hide_render = False
    assert np.abs(_mean(without, col, row) - SKY).max() < 0.03, _mean(without, col, row)


def test_object_under_the_water_shows_through_it_at_a_steep_view(pond, shown, render, project):
    scene = pond["scene"]
    camera = harness.add_camera(scene, (3, 0.01, 8), (3, 0, 0))
    shown("yellow")
    ((col, row),) = project(scene, camera, [(3, 0, -1.5)])
    pixels = render(scene, "yellow", exr=True)
    seen = _mean(pixels, col, row)
    assert _is(seen, YELLOW), seen
    # Straight down, F is about 1: nearly all of it is the refraction.
    assert seen[0] > 0.8 and seen[1] > 0.8


def _sky_share(pixels):
    """How much of the sky the water shows, per pixel (the floor under it is black)."""
    return pixels[..., 2] / SKY[2]


def test_sky_share_is_higher_at_a_grazing_view_than_a_steep_one(pond, shown, render):
    scene = pond["scene"]
    shown("floor")
    shares = {}
    for name, location, target in (("steep", (0, -3, 12), (0, 0, 0)), ("grazing", (0, -15, 0.8), (0, 0, 0))):
        camera = harness.add_camera(scene, location, target)
        pixels = render(scene, name, exr=True)
        origin, rays = harness.pixel_rays(scene, camera)
        hits, reach = harness.hit_plane_z(origin, rays)
        on_water = reach & (np.abs(hits[..., 0]) < 19) & (np.abs(hits[..., 1]) < 19)
        # Refraction rays that leave the bottom of the screen fall back to the sky: screen tracing
        # cannot follow them (the planar probe only mirrors). Compare above the bottom rows.
        on_water[-8:] = False
        assert on_water.sum() > 500
        # The reference: share = 1 - F, F = dot(eye, up) for a still mirror.
        expected = 1.0 - lake_fresnel(-rays)
        share = _sky_share(pixels)
        shares[name] = share[on_water].mean()
        assert np.abs(share[on_water] - expected[on_water]).mean() < 0.05, name
    assert shares["grazing"] > shares["steep"] + 0.3, shares


def _aim(sun, direction):
    sun.rotation_euler = Vector(direction).to_track_quat("-Z", "Y").to_euler()
    bpy.context.view_layer.update()


def _predicted_glint(scene, camera, light):
    """Pixel where the sun's mirror reflection reaches the camera on still water."""
    _origin, rays = harness.pixel_rays(scene, camera)
    score = flat_glint(-rays, light, 1.0)  # the glint's peak, whatever its power
    row, col = np.unravel_index(np.argmax(score), score.shape)
    return col, row


def test_glint_follows_the_sun(pond, render):
    scene, node = pond["scene"], harness.addon("nodes.material").water_node(pond["water"].active_material)
    camera = harness.add_camera(scene, (0, -10, 3), (0, 0, 0))
    node.inputs["Specular Strength"].default_value = 1.0
    node.inputs["Specular Power"].default_value = 512.0
    node.inputs["Debug View"].default_value = 5
    peaks = []
    try:
        for tilt in (-0.25, 0.35):
            light = (math.sin(tilt), -math.cos(tilt) * 0.9, -0.45)  # towards the camera
            _aim(pond["sun"], light)
            pixels = render(scene, f"glint-{tilt}", exr=True)
            row, col = np.unravel_index(np.argmax(pixels[..., 0]), pixels.shape[:2])
            expected = _predicted_glint(scene, camera, light)
            assert pixels[row, col, 0] > 0.5
            assert math.dist((col, row), expected) < 2.5, (col, row, expected)
            peaks.append((col, row))
    finally:
        node.inputs["Specular Strength"].default_value = 0.0
        node.inputs["Debug View"].default_value = 0
    assert math.dist(*peaks) > 15


def test_wave_height_widens_the_wobble_of_a_mirrored_block(pond, shown, render, project):
    """Wave Height tilts the reflection: the red block's mirror image frays more the higher it is."""
    scene = pond["scene"]
    node = harness.addon("nodes.material").water_node(pond["water"].active_material)
    camera = harness.add_camera(scene, (0, -4, 2), (0, 6, 0))
    shown("red")
    ((col, row),) = project(scene, camera, [(0, 6, -1)])
    band = np.zeros((scene.render.resolution_y, scene.render.resolution_x), dtype=bool)
    band[int(row) - 12 : int(row) + 13, int(col) - 16 : int(col) + 17] = True
    node.inputs["Wave Length"].default_value = 0.5  # ripples a few pixels wide at this distance
    images = {}
    try:
        for height in (0.0, 0.1, 0.4):
            node.inputs["Wave Height"].default_value = height
            images[height] = render(scene, f"wobble-{height}", exr=True)[..., :3]
    finally:
        node.inputs["Wave Height"].default_value = 0.0
        node.inputs["Wave Length"].default_value = 0.1
    # Red where the still mirror shows the block; the wobble moves red pixels in and out of it.
    still = images[0.0][..., 0] > 0.5
    assert still[band].sum() > 20, "the mirror image is in the band"
    changed = {h: (np.abs(images[h] - images[0.0]).max(axis=-1) > 0.05)[band].sum() for h in (0.1, 0.4)}
    assert changed[0.1] > 5, changed
    assert changed[0.4] > 1.5 * changed[0.1], changed
