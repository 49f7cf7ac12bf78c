"""The open sea's whitecaps, seen straight down in the ocean shading's foam view (Debug View 7):
as much of the sea as Monahan and O'Muircheartaigh measured for the wind, in whitecaps metres
across with foam's lace, drawn out downwind, in streaks along a strong wind, and seen from a boat.

Each sea's view is a square a third of its tile wide (several of its peak waves) inside the
un-faded middle, at three moments a few seconds apart: the whitecaps gather on the crests, so a
smaller view would see one crest or none. The wind is (0.8, 0.6), off the axes.
"""

import bpy
import mathutils
import numpy as np
import pytest
from reference_models import monahan

import harness

pytestmark = pytest.mark.render

WIND = (0.8, 0.6)
FRAMES = (1, 41, 81)  # 0, 1.7 and 3.3 s
PIXELS = 400
VIEW_TILES = 0.35


def _label(mask):
    """Connected regions (4-neighbours) of a boolean image: an int image, 0 outside."""
    big = mask.size + 1
    labels = np.where(mask, np.arange(mask.size).reshape(mask.shape) + 1, big)
    while True:
        new = labels.copy()
        new[1:] = np.minimum(new[1:], labels[:-1])
        new[:-1] = np.minimum(new[:-1], labels[1:])
        new[:, 1:] = np.minimum(new[:, 1:], labels[:, :-1])
        new[:, :-1] = np.minimum(new[:, :-1], labels[:, 1:])
        new = np.where(mask, new, big)
        if (new == labels).all():
            return np.where(mask, labels, 0)
        labels = new


def _grow(mask):
    """The mask grown by one pixel: a whitecap's lace, holes and all, is one whitecap."""
    grown = mask.copy()
    grown[1:] |= mask[:-1]
    grown[:-1] |= mask[1:]
    grown[:, 1:] |= mask[:, :-1]
    grown[:, :-1] |= mask[:, 1:]
    return grown


def _foam_view_sea(scene, wind):
    """The only sea in `scene`: the open sea at `wind` m/s, showing its foam view (Debug View 7)."""
    for obj in list(bpy.data.objects):
        if obj.type == "MESH":
            bpy.data.objects.remove(obj)
    sea = harness.addon("api").add_water(scene, preset="open_sea", sea_wind_speed=wind, wind_direction=WIND)
    harness.addon("nodes.sea.ocean_material").ocean_nodes(sea.object.active_material)[1].inputs[
        "Debug View"
    ].default_value = 7
    return sea.object


def _down_over_sea(scene, wind, span=None):
    """The open sea at `wind` m/s in its foam view, the camera "Down" straight over a square `span`
    metres wide (VIEW_TILES of its tile without): (the sea's object, the span)."""
    sea = _foam_view_sea(scene, wind)
    ocean = harness.addon("water.sea.open_sea").sea_modifiers(sea)[0]
    span = span or VIEW_TILES * ocean.spatial_size
    scene.camera = camera = bpy.data.objects["Down"]
    scene.render.resolution_x = scene.render.resolution_y = PIXELS
    camera.data.ortho_scale = span
    camera.location = (0.05 * span, -0.03 * span, 40.0 + 2.0 * span)
    camera.data.clip_end = 100.0 + 4.0 * span
    return sea, span


def _foam_views(sea_scene, wind, render, frames=FRAMES, span=None):
    """(foam views at `frames`, metres a pixel) of the open sea at `wind` m/s, straight down, over
    `span` metres (VIEW_TILES of its tile without)."""
    scene = sea_scene
    _sea, span = _down_over_sea(scene, wind, span)
    views = []
    for frame in frames:
        scene.frame_set(frame)
        views.append(render(scene, f"foam_{wind:g}_{span:.0f}_{frame}")[..., 0])
    return views, span / PIXELS


def _down_scene(eevee):
    """A clean scene under a plain sky with an orthographic camera "Down" looking straight down."""
    scene = harness.clean_scene(engine=eevee, width=PIXELS, height=PIXELS, samples=1)
    harness.set_world_color(scene, (0.45, 0.6, 0.8), 1.0)
    camera = bpy.data.objects.new("Down", bpy.data.cameras.new("Down"))
    camera.data.type = "ORTHO"
    scene.collection.objects.link(camera)
    scene.camera = camera
    return scene


@pytest.fixture(scope="module")
def sea_scene(addon, eevee):
    return _down_scene(eevee)


@pytest.fixture(scope="module")
def foam(sea_scene):
    """Foam views per wind, rendered once for the module."""
    made = {}

    def views(wind, render, frames=FRAMES):
        if wind not in made:
            made[wind] = _foam_views(sea_scene, wind, render, frames)
        return made[wind]

    return views


@pytest.mark.parametrize("wind", [10.0, 15.0, 20.0])
def test_whitecaps_cover_as_much_of_the_sea_as_monahan_measured(foam, render, wind):
    """Within 25% of W = 3.84e-6 U^3.41 (the white share of the foam view, over three moments):
    measured 0.98, 0.92, 1.08 of it at 10, 15, 20 m/s (0.0097, 0.0361, 0.1130 of the sea, 5.2.3),
    so 25% is three times the largest departure seen, a margin for the renders' noise."""
    views, _pixel = foam(wind, render)
    share = np.mean([(view > 0.5).mean() for view in views])
    print(f"{wind:g} m/s: whitecaps {share:.4f} of the sea, Monahan {monahan(wind):.4f}")
    assert 0.75 * monahan(wind) < share < 1.25 * monahan(wind), share / monahan(wind)


@pytest.mark.parametrize("wind", [10.0, 15.0, 20.0])
def test_straight_down_the_picture_is_as_white_as_monahan_measured(sea_scene, render, wind):
    """The final picture (issue 58 point 1), straight down over the foam views' square under a
    sun 15 degrees up across the wind, the three moments: the share of its white pixels (bright,
    hardly coloured) within 50% of Monahan's W = 3.84e-6 U^3.41 at 10, 15 and 20 m/s."""
    scene = sea_scene
    sea, _span = _down_over_sea(scene, wind)
    debug = harness.addon("nodes.sea.ocean_material").ocean_nodes(sea.active_material)[1].inputs["Debug View"]
    light = _low_sun(scene, (0.6, -0.8))
    shares = []
    try:
        debug.default_value = 0
        for frame in FRAMES:
            scene.frame_set(frame)
            shares.append(_white(render(scene, f"down_{wind:g}_{frame}")).mean())
    finally:
        bpy.data.objects.remove(light)
        debug.default_value = 7
    print(f"{wind:g} m/s, straight down: white {np.round(shares, 4)} of the picture, W {monahan(wind):.4f}")
    assert 0.5 * monahan(wind) < np.mean(shares) < 1.5 * monahan(wind), np.mean(shares) / monahan(wind)


def _repeat_across(view, pixel):
    """How much the white of a foam view repeats across the wind: its autocorrelation's largest
    value at shifts of 4 to 60 m across the wind (1: the same pattern again, 0: none)."""
    white = (view > 0.5).astype(float)
    white -= white.mean()
    spectrum = np.fft.fft2(white)
    correlation = np.real(np.fft.ifft2(spectrum * np.conj(spectrum)))
    correlation /= correlation[0, 0]
    across = np.array((-WIND[1], WIND[0])) / np.hypot(*WIND)
    shifts = np.arange(4.0, 60.0, 0.5) / pixel
    # Image x is world +x; image rows run down world y.
    rows = np.round(-across[1] * shifts).astype(int) % view.shape[0]
    cols = np.round(across[0] * shifts).astype(int) % view.shape[1]
    return float(correlation[rows, cols].max())


def test_past_the_fade_the_flat_far_sea_has_as_many_whitecaps(foam, sea_scene, render):
    """At 20 m/s, a square as wide as the middle's, straight down past the sea's Fade End (the
    mesh flat, its crests unmarked): whitecap foam covers as much of it as of the middle, within
    a third, at a moment (the far whitecaps stand where they are: one is enough); before, none.
    Its whitecaps metres across too, not specks; and the far foam repeats across the wind no
    more than the middle's (a quarter more at most): read from one tile alone it came back every
    tile width, parallel stripes (0.73 against the middle's 0.34; from two reads 0.37)."""
    views, pixel = foam(20.0, render)
    middle = np.mean([(view > 0.5).mean() for view in views])
    scene = sea_scene
    sea = _foam_view_sea(scene, 20.0)  # the same sea as the middle's views
    fade = harness.addon("water.sea.open_sea").sea_modifiers(sea)[1]
    end = harness.addon("water.waves").get_wave_input(fade, "Fade End")
    camera = bpy.data.objects["Down"]
    span = camera.data.ortho_scale
    camera.location = (-0.6 * (end + span), 0.8 * (end + span), camera.location.z)
    try:
        far = render(scene, "foam_far_20")[..., 0]
    finally:
        camera.location = (0.05 * span, -0.03 * span, camera.location.z)
    white = far > 0.5
    labels = _label(_grow(white))
    sizes = np.bincount(labels.ravel())[1:]
    sizes = sizes[sizes > 0] * pixel**2
    repeat, middle_repeat = (
        _repeat_across(far, pixel),
        np.mean([_repeat_across(view, pixel) for view in views]),
    )
    print(
        f"20 m/s: whitecaps {white.mean():.4f} of the far sea ({end + span:.0f} m out), "
        f"{middle:.4f} of the middle; median whitecap there {np.median(sizes):.1f} m^2; "
        f"repeats across the wind {repeat:.3f}, the middle's {middle_repeat:.3f}"
    )
    assert abs(white.mean() / middle - 1.0) < 1.0 / 3.0
    assert np.median(sizes) >= 0.5
    assert repeat <= 1.25 * middle_repeat


def test_the_first_frame_has_as_much_foam_as_later_ones(foam, sea_scene, render):
    """At 15 m/s, the foam view over a third of a tile: frame 1 shows as much whitecap foam as
    frame 200 (8 s on), within 30% (issue 58): the crests are marked from the waves of the frame
    itself and the foam they leave from its own crests a few steps upwind, so a shot starting at
    frame 1 starts with a sea that has been blowing, with no pre-roll. Measured: 4.09% and 4.16%."""
    first = (foam(15.0, render)[0][0] > 0.5).mean()
    later = (_foam_views(sea_scene, 15.0, render, frames=(200,))[0][0] > 0.5).mean()
    print(f"15 m/s: whitecaps {first:.4f} of the sea at frame 1, {later:.4f} at frame 200")
    assert later > 0.01 and abs(first / later - 1.0) <= 0.3


@pytest.mark.parametrize("wind", [5.0])
def test_light_winds_raise_next_to_no_whitecaps(foam, render, wind):
    """Under 0.1% of the sea (Monahan's fit gives 0.09% at 5 m/s; the add-on's coverage fades
    out below 8 m/s and is none below 4, tests/plain/test_whitecap_math.py, so 3 m/s is not
    rendered: its small tile's far triangles cost software EEVEE 25 s a frame): one moment."""
    views, _pixel = foam(wind, render, frames=FRAMES[:1])
    share = np.mean([(view > 0.5).mean() for view in views])
    print(f"{wind:g} m/s: whitecaps {share:.5f} of the sea")
    assert share < 0.001


SHAPE_VIEW = 100.0  # metres across, PIXELS a side: 0.25 m a pixel


def _patches(white, pixel):
    """(area in m^2, mean width across the wind in m, length along / across) of each connected
    patch of `white`, counted as it is: not grown, not blurred."""
    labels = _label(white)
    found, counts = np.unique(labels[labels > 0], return_counts=True)
    along = np.array(WIND) / np.hypot(*WIND)
    rows, cols = np.indices(white.shape)
    # Image x is world +x; image rows run down world y.
    x, y = cols * pixel, -rows * pixel
    u, v = x * along[0] + y * along[1], -x * along[1] + y * along[0]
    areas, widths, stretch = [], [], []
    for label, count in zip(found, counts, strict=True):
        inside = labels == label
        areas.append(count * pixel**2)
        widths.append(count * pixel**2 / (np.ptp(u[inside]) + pixel))
        if count >= 12:
            stretch.append(u[inside].std() / max(v[inside].std(), 1e-6))
    return np.array(areas), np.array(widths), np.array(stretch)


def test_whitecaps_are_compact_patches_not_dashes(sea_scene, render):
    """At 15 m/s, straight down at 0.25 m a pixel, three moments, the foam view's white counted
    as it is (issue 58): a whitecap is a patch 0.5 to 20 m^2 at the median, none over
    300 m^2; at most a third of the foam's area lies in
    patches under 0.25 m^2 (no field of dashes); few foam pixels grey; longer along the wind than
    across. Measured: median 0.69 m^2, largest 15 m^2, 1% of the foam under 0.25 m^2, 7% grey,
    6.3 times as long as wide. Before (the foam tile's bubble middles as whitecaps): median
    0.06 m^2 (one pixel), 0.25 m across, 56% of the foam in patches under 0.25 m^2."""
    views, pixel = _foam_views(sea_scene, 15.0, render, span=SHAPE_VIEW)
    areas, widths, stretch, small, greys = [], [], [], [], []
    for view in views:
        a, w, st = _patches(view > 0.5, pixel)
        areas += list(a)
        widths += list(w)
        stretch += list(st)
        small.append(a[a < 0.25].sum() / max(a.sum(), 1e-9))
        some = view > 0.05
        greys.append(((view > 0.05) & (view < 0.95)).sum() / max(some.sum(), 1))
    areas = np.array(areas)
    print(
        f"15 m/s: {len(areas)} whitecaps, median {np.median(areas):.2f} m^2, largest {areas.max():.1f} m^2, "
        f"median width across the wind {np.median(widths):.2f} m; under 0.25 m^2: "
        f"{np.round(small, 3)} of the foam; grey {np.mean(greys):.2f}; along/across {np.median(stretch):.2f}"
    )
    # Not yet held: at least 0.5 m across the wind at the median (measured 0.47 m: a tail of
    # fragments a pixel wide at the spots' ragged edges, issue 58).
    assert 0.5 <= np.median(areas) <= 20.0
    assert areas.max() <= 300.0
    assert max(small) <= 1.0 / 3.0
    assert np.mean(greys) < 0.35
    assert np.median(stretch) > 1.3


def _white(image):
    """White pixels of a final picture (linear): bright and hardly coloured (this sky's sea is
    blue, its saturation over 0.4)."""
    rgb = image[..., :3]
    lum = rgb @ np.array([0.2126, 0.7152, 0.0722])
    saturation = (rgb.max(-1) - rgb.min(-1)) / np.maximum(rgb.max(-1), 1e-6)
    return (lum > 0.5) & (saturation < 0.25)


def _low_sun(scene, to_sun, degrees=15.0):
    """A sun `degrees` up in the horizontal direction `to_sun`."""
    light = bpy.data.objects.new("Low sun", bpy.data.lights.new("Low sun", "SUN"))
    light.data.energy = 4.0
    scene.collection.objects.link(light)
    up = np.radians(degrees)
    direction = mathutils.Vector((to_sun[0] * np.cos(up), to_sun[1] * np.cos(up), np.sin(up)))
    light.rotation_euler = direction.to_track_quat("Z", "Y").to_euler()
    return light


@pytest.mark.parametrize("sun", ["behind", "ahead"])
@pytest.mark.parametrize("height", [3.0, 12.0])
def test_in_the_picture_whitecaps_are_white(sea_scene, render, sun, height):
    """The final picture (issue 58): 15 m/s, a sun 15 degrees up behind the camera or ahead of
    it, three moments. From a boat 3 m up at least 1% of the sea within 35 m is whitecap foam
    white in the picture, from 12 m up at least 2% of the sea, and half that at every moment. The foam
    view only says which white is foam (ahead, the sun's glitter is white too). Before: from 3 m
    up frame 20 showed no white within 35 m, frame 120 4.5% in lines a few centimetres wide."""
    scene = sea_scene
    sea = _foam_view_sea(scene, 15.0)
    debug = harness.addon("nodes.sea.ocean_material").ocean_nodes(sea.active_material)[1].inputs["Debug View"]
    scene.render.resolution_x, scene.render.resolution_y = 192, 108
    look = np.array((0.6, 0.8))
    drop = 21.0 if height == 3.0 else 60.0
    target = (2.0 + 100.0 * look[0], -5.0 + 100.0 * look[1], height - drop)
    camera = harness.add_camera(scene, (2.0, -5.0, height), target)
    scene.camera = camera
    light = _low_sun(scene, -look if sun == "behind" else look)
    origin, directions = harness.pixel_rays(scene, camera)
    hits, on_sea = harness.hit_plane_z(origin, directions)
    region = on_sea & (np.linalg.norm(hits - origin, axis=-1) < 35.0) if height == 3.0 else on_sea
    shares = []
    try:
        for frame in FRAMES:
            scene.frame_set(frame)
            debug.default_value = 0
            white = _white(render(scene, f"picture_{sun}_{height:g}_{frame}"))
            debug.default_value = 7
            foam = render(scene, f"foam_{sun}_{height:g}_{frame}")[..., 0] > 0.5
            shares.append((white & foam)[region].mean())
    finally:
        bpy.data.objects.remove(light)
    print(f"{height:g} m up, sun {sun}: white {np.round(shares, 4)} of the sea ({region.sum()} pixels)")
    assert region.sum() > 1000
    target = 0.01 if height == 3.0 else 0.02
    # At every moment, not only while a rare big crest passes: the old whitecaps met the mean by
    # frame 81's scratches (3 m up: 0.07%, 2.1%, 8.0%; 12 m up: 0.4%, 1.7%, 4.6%).
    assert np.mean(shares) >= target
    assert min(shares) >= 0.5 * target


def test_a_crest_s_foam_fades_within_seconds_after_it_passes(scene):
    """At points of the sea's middle, every 1/8 s over 5 s at 15 m/s: once the crest has left a
    point (its mark drops from 1), the foam it leaves fades to nothing over a second or more, not
    at once, and is gone within a few seconds (the fade's trail: TRAIL_FADE per half second).
    Measured: 1.9 s at the median (without the trail the mark drops within an eighth of a second)."""
    scene.render.fps = 8
    sea = (
        harness.addon("api")
        .add_water(scene, preset="open_sea", sea_wind_speed=15.0, wind_direction=WIND)
        .object
    )
    ocean = harness.addon("water.sea.open_sea").sea_modifiers(sea)[0]
    depsgraph = bpy.context.evaluated_depsgraph_get()
    series, picked = [], None
    for frame in range(1, 41):
        scene.frame_set(frame)
        mesh = sea.evaluated_get(depsgraph).data
        marks = np.zeros(len(mesh.vertices))
        mesh.attributes["water_whitecaps"].data.foreach_get("value", marks)
        if picked is None:
            rest = np.zeros(len(mesh.vertices) * 3)
            mesh.attributes["water_rest"].data.foreach_get("vector", rest)
            rest = rest.reshape(-1, 3)
            picked = np.flatnonzero(np.hypot(rest[:, 0], rest[:, 1]) < 0.2 * ocean.spatial_size)[::40]
        series.append(marks[picked])
    series = np.array(series)
    fades = []
    for point in series.T:
        for t in np.flatnonzero((point[:-1] >= 0.95) & (point[1:] < 0.95)):
            gone = np.flatnonzero(point[t + 1 :] <= 0.05)
            if len(gone):
                fades.append((gone[0] + 1) / 8.0)
    print(f"{len(fades)} crests left their points; the foam faded over {np.median(fades):.2f} s (median)")
    assert len(fades) > 20
    assert 0.75 <= np.median(fades) <= 4.0


STREAK_VIEW = 60.0  # metres across, STREAK_PIXELS a side: 0.075 m a pixel
STREAK_PIXELS = 800
GRAIN = 0.1  # m
PATCHES = 6.0  # m


def _blurred(image, sigma):
    """`image` blurred by a Gaussian of `sigma` pixels (periodic, by FFT)."""
    fy = np.fft.fftfreq(image.shape[0])[:, None]
    fx = np.fft.fftfreq(image.shape[1])[None, :]
    kernel = np.exp(-2.0 * (np.pi * sigma) ** 2 * (fx**2 + fy**2))
    return np.real(np.fft.ifft2(np.fft.fft2(image) * kernel))


def _streak_shape(view, pixel):
    """(angle of the foam's long axis in degrees from world +x, length / width) from the central
    peak of the foam's autocorrelation above half its height, the patches the crests mark (over
    PATCHES) and the lace's grain (under GRAIN) taken out first: the shape of a typical piece of foam,
    whatever it is."""
    fine = _blurred(view, GRAIN / pixel) - _blurred(view, PATCHES / pixel)
    spectrum = np.fft.fft2(fine)
    correlation = np.fft.fftshift(np.real(np.fft.ifft2(np.abs(spectrum) ** 2)))
    centre = np.array(correlation.shape) // 2
    peak = _label(correlation > 0.5 * correlation[tuple(centre)])
    inside = peak == peak[tuple(centre)]
    rows, cols = np.nonzero(inside)
    x, y = (cols - centre[1]) * pixel, -(rows - centre[0]) * pixel  # image up is world +y
    values, vectors = np.linalg.eigh(np.cov(np.stack((x, y))))
    long = vectors[:, 1]
    return np.degrees(np.arctan2(long[1], long[0])) % 180.0, np.sqrt(values[1] / max(values[0], 1e-12))


@pytest.mark.parametrize("wind", [15.0, 25.0])
def test_in_a_strong_wind_the_foam_lies_in_streaks_along_it_not_cells(addon, eevee, render, wind):
    """Straight down over 60 m of the middle at 7.5 cm a pixel, two moments: the foam's typical
    piece (`_streak_shape`) lies within 15 degrees of the wind and is at least 5 times as long as
    it is wide, from 12 m/s (Beaufort 6) and at 15 (7: "foam blown in streaks") to 25 (10, where
    the foam was a net of polygonal cells). Measured: within 1.5° of the wind; 5.5-6.2, 6.7-7.0
    and 8.9-9.2 times as long as wide, where the foam not drawn out is 1.6, 1.6 and 2.0."""
    scene = _down_scene(eevee)
    _foam_view_sea(scene, wind)
    scene.camera = camera = bpy.data.objects["Down"]
    scene.render.resolution_x = scene.render.resolution_y = STREAK_PIXELS
    camera.data.ortho_scale = STREAK_VIEW
    camera.location = (7.0, -5.0, 200.0)
    camera.data.clip_end = 1000.0
    wind_angle = np.degrees(np.arctan2(WIND[1], WIND[0]))
    for frame in FRAMES[:2]:
        scene.frame_set(frame)
        view = render(scene, f"streaks_{wind:g}_{frame}")[..., 0]
        angle, aspect = _streak_shape(view, STREAK_VIEW / STREAK_PIXELS)
        off = abs((angle - wind_angle + 90.0) % 180.0 - 90.0)
        print(
            f"{wind:g} m/s, frame {frame}: foam {view.mean():.3f}, long axis {off:.1f}° off the wind, "
            f"{aspect:.1f} times as long as wide"
        )
        assert off <= 15.0 and aspect >= 5.0


def test_whitecap_foam_is_lit_by_the_sun_and_shaded_on_its_dark_side(addon, eevee, render):
    """The final picture's whitecaps (issue 58 point 1): lit by the sun and the sky, as a white
    Lambert surface is. 15 m/s, 12 m up, a sun 15 degrees up across the view (so the foam's faces
    turn to it and from it), three moments. Over the whitecap pixels (foam view 1), the picture's
    linear luminance against max(n . l, 0), n the waves' normal (Debug View 4 with the bump's
    ripples off: foam hides them), is a line whose
    slope is about the foam's albedo x the sun's irradiance / pi and whose offset is the albedo x the
    sky: numpy's Lambert model. The tenth of the foam most turned from the sun is darker than the
    tenth facing it most by at least half what the model says. Unlit foam (an emission, as on 4.2)
    has no slope and fails."""
    scene = _down_scene(eevee)  # its own: the streaks test before it reads a new home file
    sea = _foam_view_sea(scene, 15.0)
    normal_node, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(sea.active_material)
    debug, bump = shade.inputs["Debug View"], normal_node.inputs["Bump Strength"]
    scene.render.resolution_x, scene.render.resolution_y = 192, 108
    look = np.array((0.6, 0.8))
    camera = harness.add_camera(scene, (2.0, -5.0, 12.0), (62.0, 75.0, -48.0))
    scene.camera = camera
    across = np.array((look[1], -look[0]))
    light = _low_sun(scene, across)
    irradiance = light.data.energy  # W/m^2 of a sun lamp
    to_sun = np.array((*(across * np.cos(np.radians(15.0))), np.sin(np.radians(15.0))))
    lum, facing = [], []
    try:
        for frame in FRAMES:
            scene.frame_set(frame)
            debug.default_value = 0
            picture = render(scene, f"lit_{frame}", exr=True)[..., :3]
            debug.default_value = 7
            foam = render(scene, f"lit_foam_{frame}", exr=True)[..., 0] > 0.99
            debug.default_value, strength, bump.default_value = 4, bump.default_value, 0.0
            n = render(scene, f"lit_normal_{frame}", exr=True)[..., :3] * 2.0 - 1.0
            bump.default_value = strength
            n /= np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-6)
            lum.append((picture @ np.array([0.2126, 0.7152, 0.0722]))[foam])
            facing.append(np.maximum(n @ to_sun, 0.0)[foam])
    finally:
        bpy.data.objects.remove(light)
        debug.default_value = 7
    lum, facing = np.concatenate(lum), np.concatenate(facing)
    slope, offset = np.polyfit(facing, lum, 1)
    albedo = np.array(harness.addon("nodes.sea.ocean_parts").FOAM_WHITE) @ np.array([0.2126, 0.7152, 0.0722])
    expected = albedo * irradiance / np.pi
    sky = albedo * np.array((0.45, 0.6, 0.8)) @ np.array([0.2126, 0.7152, 0.0722])  # the sky's share
    low, high = np.quantile(facing, (0.1, 0.9))
    turned, facing_it = lum[facing <= low].mean(), lum[facing >= high].mean()
    model = (sky + expected * facing[facing <= low].mean()) / (sky + expected * facing[facing >= high].mean())
    print(
        f"whitecap pixels {lum.size}: luminance = {slope:.2f} max(n.l, 0) + {offset:.2f} (Lambert: "
        f"{expected:.2f} max(n.l, 0) + {sky:.2f}); the tenth most turned from the sun (n.l <= {low:.2f}) "
        f"{turned:.2f}, the tenth facing it most (>= {high:.2f}) {facing_it:.2f}: {turned / facing_it:.2f} "
        f"(Lambert {model:.2f})"
    )
    assert lum.size > 300
    assert 0.5 * expected < slope < 1.5 * expected
    assert 0.5 * sky < offset < 1.5 * sky
    assert turned / facing_it < 1.0 - 0.5 * (1.0 - model)
