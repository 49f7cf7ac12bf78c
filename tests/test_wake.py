"""Issues 25 point 3 and 37: a moving hull leaves a Kelvin wake and foam in the water's mesh.

A 10 x 3 x 2 m box hull floats 0.8 m deep on a 80 m lake meshed at 0.25 m and is keyed to run
at 3.5 m/s (Froude number 0.35) along a diagonal, 0.6 rad off the x axis. After 6 s (frames 1
to 145, stepped in order as a render does), the evaluated mesh is read in the track's frame:
`x` metres behind the hull along its track, `y` across.

* Kelvin's pattern over the whole field (issue 37 point 1): the evaluated heights over the patch
  2 to 30 m behind the stern, both sides and beyond the arms, against the numpy model's
  (`tools/kelvin_model.py`, the integral over the waves' directions of a Gaussian pressure
  patch): one complex constant fitted, the rest of it left unexplained is the residual (0.27
  for a 6 m hull at 4 m/s; the wrong sign off the axis left 0.97). Per region, per wave system,
  the highest waves' angle and what lies beyond the arms; at Froude number 1 the highest waves
  narrow to about 0.2 / Fr, the edge stays. The floating 10 m hull and the open sea's wake are
  checked the same way.
* The transverse waves along the track: wavelength 2πU²/g (7.85 m) within 15%, from the
  crossings of zero between 3 and 15 m behind.
* Heights: Kriebel and Seelig's (2005) over speed, draft and distance across (issue 37 point 2).
* Foam round the hull and along the track behind it, drifted downwind, none ahead of it.
* A turning hull: the foam lies along the bend it took, not along its heading now; the wake,
  worked out only in its zone round the track, is the same as worked out everywhere.
* A stone dropped in: its ring's front (the radius where the waves are highest) runs out at
  the group speed of waves twice its width long, `ω² = g k + (σ/ρ) k³`, within 20%: 0.6 m waves
  (gravity's) and 1.6 cm ones (near the capillary minimum, on a 1 m pond meshed at 2.5 mm).
* Floating and stopping re-point the wake with no dependency cycle; a deleted hull's wake goes
  at save; a baked wake renders any frame alone, without the add-on, as the stepped run, also
  from BAT's pack of the file (on 4.2 the pack holds the bake's folder).
"""

import math

import bpy
import kelvin_model
import numpy as np
import pytest
from reference_models import (
    G,
    capillary_gravity_group_speed,
    kriebel_seelig,
    wavelength_at_speed,
)

import harness

SPEED = 3.5
HEADING = 0.6
START = np.array([-22.0, -14.0])
LAST_FRAME = 145
FPS = 24
HULL = (10.0, 3.0, 2.0)
DRAFT = 0.8
WIND = np.array([0.6, -0.8])  # the lake's wind: the foam drifts this way


def _api():
    return harness.addon("api")


def _lit(scene):
    """A dim blue sky and a sun 40 degrees up: foam is lit, the water reflects a dark sky."""
    harness.set_world_color(scene, (0.08, 0.12, 0.2))
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (math.radians(50.0), 0.0, math.radians(20.0))
    scene.collection.objects.link(sun)


def _linear(obj):
    action = obj.animation_data.action
    for fcurve in harness.addon("nodes.material")._action_fcurves(action):
        for key in fcurve.keyframe_points:
            key.interpolation = "LINEAR"


def _hull(scene, name="Hull", size=HULL):
    return harness.add_box(scene, name, size)


def _run_straight(hull, speed=SPEED, heading=HEADING, start=START):
    direction = np.array([math.cos(heading), math.sin(heading)])
    for frame in (1, LAST_FRAME):
        seconds = (frame - 1) / FPS
        hull.location = (*(start + direction * speed * seconds), 0.0)
        hull.rotation_euler = (0.0, 0.0, heading)
        hull.keyframe_insert("location", frame=frame)
        hull.keyframe_insert("rotation_euler", frame=frame)
    _linear(hull)


def _step(scene, last=LAST_FRAME):
    """Frames 1 to `last` in order (the simulation steps as a render does)."""
    for frame in range(1, last + 1):
        scene.frame_set(frame)


def _surface(water):
    """(points (N, 3), foam (N,)) of the evaluated water, in its own space."""
    return harness.evaluated_points(water, "water_wake_foam")


def _track_frame(points, where, heading):
    """(x behind, y across to the left) of `points` from a hull at `where` heading `heading`."""
    direction = np.array([math.cos(heading), math.sin(heading)])
    offset = points[:, :2] - where
    return -(offset @ direction), offset[:, 1] * direction[0] - offset[:, 0] * direction[1]


def _foam_is_white(scene, water, points, foam, render, name):
    """Renders the water from above, round the hull, and returns (mean brightness where the
    foam is over 0.4, where there is none)."""
    end = _end()
    camera = harness.add_camera(scene, (end[0] - 6.0, end[1] - 3.0, 40.0), (end[0] - 6.0, end[1] - 3.0, 0.0))
    camera.data.type, camera.data.ortho_scale = "ORTHO", 24.0
    image = render(scene, name)[..., :3].mean(axis=2)
    world = np.array(water.matrix_world)
    at = (np.c_[points, np.ones(len(points))] @ world.T)[:, :3]
    pixels = harness.world_to_pixel(scene, camera, at).round().astype(int)
    inside = (
        (pixels[:, 0] >= 0)
        & (pixels[:, 0] < image.shape[1])
        & (pixels[:, 1] >= 0)
        & (pixels[:, 1] < image.shape[0])
    )
    hull = np.linalg.norm(at[:, :2] - end, axis=1) < 6.0  # under the hull: not water
    white = inside & (foam > 0.4) & ~hull
    clear = inside & (foam < 0.01)
    assert white.sum() > 8 and clear.sum() > 200, (white.sum(), clear.sum())
    return image[pixels[white, 1], pixels[white, 0]].mean(), image[pixels[clear, 1], pixels[clear, 0]].mean()


def _end(start=START, speed=SPEED, heading=HEADING):
    return start + np.array([math.cos(heading), math.sin(heading)]) * speed * (LAST_FRAME - 1) / FPS


@pytest.fixture(scope="module")
def lake_wake(addon, eevee):
    scene = harness.clean_scene(width=64, height=64, samples=1)
    scene.render.fps = FPS
    _lit(scene)
    water = _api().add_water(scene, preset="lake", size=80.0, resolution=321, name="Lake").object
    _api().write_values(water, {"wind_direction": tuple(WIND)})
    hull = _hull(scene)
    _run_straight(hull)
    _api().float_on_water(hull, water, draft=DRAFT)
    changes = _api().add_wake_source(hull, water)
    _step(scene)
    points, foam = _surface(water)
    return {"scene": scene, "water": water, "hull": hull, "points": points, "foam": foam, "changes": changes}


def _track_seconds():
    return (LAST_FRAME - 1) / FPS


def test_a_floating_hull_at_froude_0_35_leaves_the_models_wake(lake_wake):
    """The 10 m hull, floating and 6 s into its run (21 m of track): the whole field behind its
    stern is the numpy model's. At this Froude number and this near, the model's highest waves
    are the transverse ones on the track, not the arms (those win only much further behind)."""
    x, y = _track_frame(lake_wake["points"], _end(), HEADING)
    (modifier,) = harness.addon("water.boats.wake").wake_modifiers(lake_wake["water"])
    fade = harness.addon("water.waves").get_wave_input(modifier, "Fade")
    reach = SPEED * _track_seconds() - HULL[0] / 2
    x, y, height, model, residual = _against_kelvin(
        x, y, lake_wake["points"][:, 2], HULL[0], SPEED, fade, reach=reach
    )
    print("floating, Fr 0.35: residual", round(residual, 3))
    assert residual < 0.45
    ours = kelvin_model.highest_angle(x, y, height, (10.0, 21.0))
    theirs = kelvin_model.highest_angle(x, y, model, (10.0, 21.0))
    print("highest waves at", ours, "the model's at", theirs)
    assert ours < 12.0 and theirs < 12.0  # both near the track: the transverse waves


def test_the_transverse_waves_are_2_pi_u2_over_g_long(lake_wake):
    x, y = _track_frame(lake_wake["points"], _end(), HEADING)
    line = (np.abs(y) < 0.2) & (x > 3.0) & (x < 15.0)
    order = np.argsort(x[line])
    xs, zs = x[line][order], lake_wake["points"][line, 2][order]
    crossings = xs[1:][np.sign(zs[1:]) != np.sign(zs[:-1])]
    measured = 2.0 * np.diff(crossings).mean()
    expected = wavelength_at_speed(SPEED)
    print(
        "transverse wavelength",
        round(measured, 2),
        "expected",
        round(expected, 2),
        "crossings",
        crossings.round(2),
    )
    assert abs(measured - expected) < 0.15 * expected


def test_foam_round_the_hull_and_behind_it_drifted_downwind_none_ahead(lake_wake):
    x, y = _track_frame(lake_wake["points"], _end(), HEADING)
    foam = lake_wake["foam"]
    beside = (np.abs(x) < 4.0) & (np.abs(y) < 2.0)
    assert foam[beside].max() > 0.9
    ahead = (x < -8.0) & (np.abs(y) < 3.0)  # a beam ahead of the bow
    assert foam[ahead].max() < 0.05
    behind = (x > 12.0) & (x < 14.0)
    assert foam[behind].max() > 0.3
    # Downwind: the foam's middle 13 m behind lies on the wind's side of the track.
    direction = np.array([math.cos(HEADING), math.sin(HEADING)])
    left = np.array([-direction[1], direction[0]])
    side = np.sign(WIND @ left)
    middle = (foam[behind] * y[behind]).sum() / foam[behind].sum()
    print("foam's middle across the track, 13 m behind", round(middle, 2))
    assert side * middle > 0.5


@pytest.mark.render
def test_the_lakes_shading_shows_the_wakes_foam(lake_wake, render):
    foam, water = _foam_is_white(
        lake_wake["scene"], lake_wake["water"], lake_wake["points"], lake_wake["foam"], render, "lake"
    )
    print("lake: brightness in the foam", round(foam, 3), "clear water", round(water, 3))
    assert foam > water + 0.25


def _highest_across(x, y, height, length, lines):
    """Crest to trough along lines `lines` hull lengths across (both sides, each 0.1 L wide):
    the largest swing behind the hull, as a gauge there records the passing wake, brought to
    `y = L` by `(y / L)^(1/3)`; their mean."""
    behind = x > 0.8 * length
    out = []
    for line in lines:
        for side in (1.0, -1.0):
            pick = behind & (np.abs(side * y / length - line) < 0.05)
            out.append(np.ptp(height[pick]) * line ** (1.0 / 3.0))
    return float(np.mean(out))


def test_heights_follow_kriebel_and_seelig_over_speed_draft_and_distance(addon):
    """Issue 37 point 2: a 4 m hull on 5 m of water at Froude 0.3 and 0.4, drawing 0.5 m and
    1 m: the highest waves a hull length across are Kriebel and Seelig's (2005) within 20%,
    and their ratios over speed and draft theirs within 15%; at Froude 0.4, run long enough
    for the waves twice as far across to have passed (40 m behind), those too within 25% (they
    fall as `y^(-1/3)`)."""
    length, depth = 4.0, 5.0
    lines = np.linspace(0.85, 1.2, 8)
    ours, theirs = {}, {}
    for froude, draft, seconds in ((0.3, 0.5, 10.0), (0.3, 1.0, 10.0), (0.4, 0.5, 17.0)):
        speed = froude * math.sqrt(G * length)
        run = np.array([math.cos(2.3), math.sin(2.3)]) * speed * seconds / 2.0
        x, y, height, _fade = _straight_wake(
            length, speed, seconds, end=run, size=52.0, fade=600.0, inputs={"Draft": draft, "Depth": depth}
        )
        ours[froude, draft] = _highest_across(x, y, height, length, lines)
        theirs[froude, draft] = kriebel_seelig(froude, length, draft, depth)
        print(
            f"Fr {froude} draft {draft}: at L {ours[froude, draft]:.4f} m,",
            f"theirs {theirs[froude, draft]:.4f}",
        )
        assert ours[froude, draft] == pytest.approx(theirs[froude, draft], rel=0.2)
    far = _highest_across(x, y, height, length, 2.0 * lines) * 2.0 ** (-1.0 / 3.0)
    their_far = kriebel_seelig(froude, length, draft, depth, across=2.0 * length)
    print(f"Fr 0.4 at 2 L: {far:.4f} m, theirs {their_far:.4f}")
    assert far == pytest.approx(their_far, rel=0.25)
    for a, b in (((0.3, 1.0), (0.3, 0.5)), ((0.4, 0.5), (0.3, 0.5))):
        ratio, their_ratio = ours[a] / ours[b], theirs[a] / theirs[b]
        print("ratio", a, "over", b, round(ratio, 3), "theirs", round(their_ratio, 3))
        assert ratio == pytest.approx(their_ratio, rel=0.15)


def _straight_wake(length, speed, seconds, heading=2.3, end=(-8.0, 8.0), size=90.0, fade=None, inputs=None):
    """A box hull `length` x 0.4 `length` x 0.25 `length` running straight at `speed` for
    `seconds` along `heading` (a diagonal, so the wake's frame is turned), ending at `end` on a
    lake meshed at 0.25 m: (x behind, y across, height) of the evaluated water."""
    scene = harness.clean_scene(width=32, height=32, samples=1)
    scene.render.fps = FPS
    water = (
        _api().add_water(scene, preset="lake", size=size, resolution=int(size * 4) + 1, name="Lake").object
    )
    hull = _hull(scene, size=(length, 0.4 * length, 0.25 * length))
    direction = np.array([math.cos(heading), math.sin(heading)])
    end = np.array(end)
    last = int(seconds * FPS) + 1
    for frame in (1, last):
        hull.location = (*(end - direction * speed * (last - frame) / FPS), 0.0)
        hull.rotation_euler = (0.0, 0.0, heading)
        hull.keyframe_insert("location", frame=frame)
        hull.keyframe_insert("rotation_euler", frame=frame)
    _linear(hull)
    _api().add_wake_source(hull, water)
    (modifier,) = harness.addon("water.boats.wake").wake_modifiers(water)
    for name, value in (({"Fade": fade} if fade is not None else {}) | (inputs or {})).items():
        harness.addon("water.waves").set_wave_input(modifier, name, value)
    _step(scene, last)
    points, _foam = _surface(water)
    x, y = _track_frame(points, end, heading)
    fade = harness.addon("water.waves").get_wave_input(modifier, "Fade")
    return x, y, points[:, 2], fade


def _against_kelvin(x, y, height, length, speed, fade, reach=30.0):
    """The wake over the patch 2 to `reach` m behind the stern, both sides and beyond the arms, against
    the numpy model's (`tools/kelvin_model.py`: the integral over the waves' directions), faded
    by its age `x / U` as the group fades it: (model heights, fit residual, the two systems'
    constants)."""
    patch = (x > length / 2 + 2.0) & (x < length / 2 + reach) & (np.abs(y) < 0.5 * x)
    x, y, height = x[patch], y[patch], height[patch]
    age = np.exp(-x / speed / fade)
    both = kelvin_model.field(x, y, speed, length) * age
    (c,), residual = kelvin_model.fit(height, both)
    return x, y, height, (c * both).real, residual


def _regions(x, y, height, model, bands):
    """The residual (rms of height - model over the model's) in each band of distance behind and
    angle from the track, each side apart."""
    angle = np.degrees(np.arctan2(y, x))
    out = {}
    for x0, x1 in bands:
        for a0, a1 in ((0.0, 8.0), (8.0, 16.0), (16.0, 22.0)):
            for side in (1.0, -1.0):
                pick = (x >= x0) & (x < x1) & (side * angle >= a0) & (side * angle < a1)
                out[(x0, a0, side)] = math.sqrt(
                    np.mean((height[pick] - model[pick]) ** 2) / np.mean(model[pick] ** 2)
                )
    return out


def test_the_wake_is_kelvins_over_the_whole_field_both_systems_and_the_cusps(addon):
    """Issue 37 point 1: a 6 m hull at 4 m/s (Froude number 0.52) on a diagonal; over the whole
    patch 2-30 m behind its stern the evaluated heights are one constant times the numpy model's
    (phases and both wave systems on both sides: a wrong sign off the axis leaves 0.95 of it
    unexplained, a wrong phase in either system most of its share), and their highest waves lie
    where the model's do, near Kelvin's 19.47°, with almost none beyond."""
    length, speed = 6.0, 4.0
    x, y, height, fade = _straight_wake(length, speed, 10.0)
    x, y, height, model, residual = _against_kelvin(x, y, height, length, speed, fade)
    regions = _regions(x, y, height, model, ((5.0, 12.0), (12.0, 20.0), (20.0, 33.0)))
    print(
        "whole patch: residual",
        round(residual, 3),
        "height rms",
        round(float(np.sqrt(np.mean(height**2))), 4),
    )
    print("regions (x from, angle from, side): residual", {k: round(v, 2) for k, v in regions.items()})
    assert residual < 0.4
    for (x0, a0, side), value in regions.items():
        assert value < (0.65 if a0 >= 16.0 else 0.45), ((x0, a0, side), value)
    # Both systems: the model split at the cusp's direction (tan θ = 1/√2); fitted apart away
    # from the arms, where the split is clean, each needs the same constant.
    angle = np.degrees(np.arctan2(np.abs(y), x))
    clean = (angle < 15.0) | (angle > 24.0)
    age = np.exp(-x / speed / fade)
    transverse = kelvin_model.field(x, y, speed, length, "transverse") * age
    diverging = kelvin_model.field(x, y, speed, length, "diverging") * age
    (ct, cd), _ = kelvin_model.fit(height[clean], transverse[clean], diverging[clean])
    print(
        "systems' constants: transverse / diverging",
        round(abs(ct / cd), 2),
        "phase",
        round(math.degrees(np.angle(ct / cd))),
    )
    assert 0.7 < abs(ct / cd) < 1.45 and abs(np.angle(ct / cd)) < math.radians(25.0)
    # The cusps: the highest waves' angle, each side, 15 to 33 m behind, as the model's.
    far = x > 15.0
    for side in (1.0, -1.0):
        pick = far & (side * y > 0)
        ours = kelvin_model.highest_angle(x[pick], y[pick], height[pick], (15.0, 33.0))
        theirs = kelvin_model.highest_angle(x[pick], y[pick], model[pick], (15.0, 33.0))
        print("highest waves at", ours, "the model's at", theirs)
        assert abs(ours - theirs) < 3.5 and 15.0 < ours < 21.0  # ours on the caustic, Airy's 2-3° inside
    # Beyond the arms: as little as the model leaves there this near (its Airy tail and the
    # hull's near field: 2 to 30 m is 1.2 to 20 transverse wavelengths, no far field yet).
    ours, theirs = _beyond(x, y, height), _beyond(x, y, model)
    print("beyond 23° over within 19°: ours", round(ours, 2), "the model's", round(theirs, 2))
    assert abs(ours - theirs) < 0.2


def _beyond(x, y, height):
    angle = np.degrees(np.arctan2(np.abs(y), x))
    beyond = (angle > 23.0) & (x > 10.0)
    within = (angle < 19.0) & (x > 10.0)
    return math.sqrt(np.mean(height[beyond] ** 2) / np.mean(height[within] ** 2))


def _reach(x, y, height):
    """The widest 1-degree sector, 12 m behind and more, whose waves are over 0.15 of the highest."""
    angle = np.degrees(np.arctan2(np.abs(y), x))
    rms = [math.sqrt(np.mean(height[(x > 12.0) & (angle >= a) & (angle < a + 1.0)] ** 2)) for a in range(27)]
    return max(a for a in range(27) if rms[a] > 0.15 * max(rms))


def _slope(distances, sizes):
    return float(np.polyfit(np.log(distances), np.log(sizes), 1)[0])


def test_the_cusp_waves_fall_as_r_to_minus_a_third_and_the_transverse_as_minus_a_half(addon):
    """Issue 37 point 2 (its fall with distance): stationary phase, with the fading in time off
    (`Fade` 600 s), a 6 m hull at 4 m/s, 8 to 33 m behind: the highest waves on the arms fall as
    `r^(-1/3)` (Airy's), those on the track as `r^(-1/2)`, each within 0.1 of the exponent."""
    length, speed = 6.0, 4.0
    x, y, height, _fade = _straight_wake(length, speed, 10.0, fade=600.0)
    wavelength = wavelength_at_speed(speed)
    angle = np.degrees(np.arctan2(np.abs(y), x))
    starts = np.arange(8.0, 33.0 - wavelength, wavelength / 2.0)
    middles, axis, arms = [], [], []
    for x0 in starts:
        band = (x >= x0) & (x < x0 + wavelength)
        middles.append(x0 + wavelength / 2.0)
        axis.append(np.abs(height[band & (np.abs(y) < 0.2)]).max())
        arms.append(np.abs(height[band & (angle > 15.0) & (angle < 21.0)]).max())
    transverse, cusp = _slope(middles, axis), _slope(middles, arms)
    print("fall with distance: on the track", round(transverse, 3), "on the arms", round(cusp, 3))
    assert abs(transverse + 0.5) < 0.1
    assert abs(cusp + 1.0 / 3.0) < 0.1


def test_above_froude_half_the_highest_waves_narrow_the_outer_edge_stays(addon):
    """Issue 37 point 1: at Froude number 1 (a 6 m hull at 7.67 m/s) the highest waves stand
    near 0.2 / Fr rad (11.5°) from the track, as Rabaud and Moisy (2013) measured and the model
    gives, while the waves still reach out as far as at low speed, past Kelvin's 19.47°."""
    length, speed = 6.0, 7.67
    x, y, height, fade = _straight_wake(length, speed, 5.0)
    x, y, height, model, residual = _against_kelvin(x, y, height, length, speed, fade)
    print("Fr 1: residual", round(residual, 3))
    assert residual < 0.6
    ours = kelvin_model.highest_angle(x, y, height, (15.0, 33.0))
    theirs = kelvin_model.highest_angle(x, y, model, (15.0, 33.0))
    print("Fr 1: highest waves at", ours, "the model's at", theirs, "0.2 / Fr:", round(math.degrees(0.2), 1))
    assert abs(ours - theirs) < 3.0 and ours < 15.0
    # The edge does not narrow with them: the waves reach as wide as the model's, past Kelvin's
    # angle (this near, its Airy tail spreads a few degrees beyond it, as at Froude 0.5).
    ours, theirs = _reach(x, y, height), _reach(x, y, model)
    print("Fr 1: waves reach", ours, "degrees, the model's", theirs)
    assert abs(ours - theirs) <= 2 and ours >= 19


def test_a_turning_hull_leaves_its_foam_along_the_bend(addon, eevee):
    scene = harness.clean_scene(width=64, height=64, samples=1)
    scene.render.fps = FPS
    water = _api().add_water(scene, preset="lake", size=80.0, resolution=161, name="Lake").object
    hull = _hull(scene)
    # A quarter circle of 15 m radius in 6 s, turning left from heading 0.3 rad.
    radius, turn = 15.0, math.pi / 2
    centre = np.array([-10.0, 0.0])
    path = []
    for frame in range(1, LAST_FRAME + 1, 12):
        angle = -math.pi / 2 + 0.3 + turn * (frame - 1) / (LAST_FRAME - 1)
        where = centre + radius * np.array([math.cos(angle), math.sin(angle)])
        hull.location = (*where, 0.0)
        hull.rotation_euler = (0.0, 0.0, angle + math.pi / 2)
        hull.keyframe_insert("location", frame=frame)
        hull.keyframe_insert("rotation_euler", frame=frame)
        path.append(where)
    _api().add_wake_source(hull, water)
    _step(scene)
    points, foam = _surface(water)
    now = np.array(hull.matrix_world.translation[:2])
    heading = hull.matrix_world.to_euler().z

    def foam_near(point):
        return foam[np.linalg.norm(points[:, :2] - point, axis=1) < 1.0].max()

    on_bend = path[len(path) // 3]  # where it was 4 s ago
    straight_back = now - np.array([math.cos(heading), math.sin(heading)]) * np.linalg.norm(now - on_bend)
    print("foam on the bend", foam_near(on_bend), "straight back", foam_near(straight_back))
    assert foam_near(on_bend) > 0.2
    assert foam_near(straight_back) < 0.02


def _nearest_instead_of_walked(group):
    """The group, each water point's track point (and drifted track point) found by a
    nearest-point search instead of walked to: the costly way, right everywhere."""
    for walked, geometry in (("tw_i2", "track_group"), ("dw_i1", "drifted")):
        nearest = group.nodes.new("GeometryNodeSampleNearest")
        nearest.domain = "POINT"
        position = group.nodes.new("GeometryNodeInputPosition")
        flat = group.nodes.new("ShaderNodeVectorMath")
        flat.operation = "MULTIPLY"
        flat.inputs[1].default_value = (1.0, 1.0, 0.0)
        group.links.new(position.outputs[0], flat.inputs[0])
        source = group.nodes[geometry]
        group.links.new(source.outputs[0], nearest.inputs["Geometry"])
        group.links.new(flat.outputs[0], nearest.inputs["Sample Position"])
        for link in list(group.nodes[walked].outputs[0].links):
            group.links.new(nearest.outputs["Index"], link.to_socket)
    return group


def test_the_wake_worked_out_only_round_its_track_equals_it_worked_out_everywhere(addon):
    """The wake is worked out only in a zone round its track (the wedge round the chord from
    the object back to the oldest point, wider by how far the track strays), each point walking
    to its point of the track from a coarse grid's guess (`nodes/boats/wake_frame.py`). On a long
    S-bend at 6 m/s, 48 m in 8 s: a copy of the group with no selections gives the same water;
    and a copy that finds each point's track point by a nearest-point search everywhere (the
    costly way) the same wake, each walked foot as near as the nearest one."""
    scene = harness.clean_scene(width=32, height=32, samples=1)
    scene.render.fps = FPS
    water = _api().add_water(scene, preset="lake", size=80.0, resolution=161, name="Lake").object
    hull = _hull(scene)
    last = 8 * FPS + 1
    for frame in range(1, last + 1, 6):
        seconds = (frame - 1) / FPS
        heading = 0.9 * math.sin(seconds * math.pi / 4.0)  # an S: left, then right
        along = -30.0 + 6.0 * seconds
        hull.location = (along * math.cos(0.5), along * math.sin(0.5) + 6.0 * math.sin(heading), 0.0)
        hull.keyframe_insert("location", frame=frame)
    _api().add_wake_source(hull, water)
    (modifier,) = harness.addon("water.boats.wake").wake_modifiers(water)
    walked = _with_feet(modifier.node_group.copy())
    found = {}
    for name, group in (
        ("culled", walked),
        ("everywhere", _unculled(walked.copy())),
        ("nearest", _nearest_instead_of_walked(_unculled(walked.copy()))),
    ):
        modifier.node_group = group
        _step(scene, last)
        found[name] = _surface_and_feet(water)
    (points, foam, feet), (everywhere, foam_everywhere, _) = found["culled"], found["everywhere"]
    height = np.abs(everywhere[:, 2])
    print(
        "height",
        height.max(),
        "culled off by",
        np.abs(everywhere - points).max(),
        "foam",
        np.abs(foam_everywhere - foam).max(),
    )
    assert height.max() > 0.05
    assert np.abs(everywhere - points).max() < 0.01 * height.max()  # the zone's edge: waves 1% high
    assert np.abs(foam_everywhere - foam).max() < 0.01
    nearest, foam_nearest, nearest_feet = found["nearest"]
    moved = (height > 0.002) | (np.abs(nearest[:, 2]) > 0.002)
    farther = np.linalg.norm(points[:, :2] - feet["test_foot"][:, :2], axis=1) - np.linalg.norm(
        points[:, :2] - nearest_feet["test_foot"][:, :2], axis=1
    )
    # Where the walked and the nearest feet are one track segment apart at most (0.4 m), the
    # heights still differ by about 8% (rms): on a bend a vertex's step moves a point's frame
    # by y x the turn (both ways take a vertex, not the foot between). Between the S's arms,
    # as near to either, the feet differ. What the walk promises is a foot as near.
    close = moved & (np.linalg.norm(feet["test_foot"] - nearest_feet["test_foot"], axis=1) < 0.4)

    def rms(where):
        return math.sqrt(
            np.mean((everywhere[where, 2] - nearest[where, 2]) ** 2) / np.mean(nearest[where, 2] ** 2)
        )

    print(
        "walked feet farther than the nearest: 99th percentile",
        np.percentile(farther[moved], 99),
        "; heights off (rms / rms) where the feet are close",
        rms(close),
        "(",
        close.sum(),
        "of",
        moved.sum(),
        "points), everywhere",
        rms(moved),
    )
    assert np.percentile(farther[moved], 99) < 0.1 and close.sum() > 0.9 * moved.sum()


def _unculled(group):
    """The group with no selections: the wake worked out on every water point."""
    for node in group.nodes:
        if node.label in ("the wake", "store water_wake_foam"):
            for link in list(node.inputs["Selection"].links):
                group.links.remove(link)
    return group


def _with_feet(group):
    """The group, storing on each water point its track point (`test_foot`) and drifted track
    point (`test_dfoot`): the points its wake and its foam are worked out from."""
    output = group.nodes["drop_zone"]
    last = output.inputs["Geometry"].links[0].from_socket
    # The drifted foot is sampled inside the foam's group: sampled here again, from its index.
    drifted_foot = group.nodes.new("GeometryNodeSampleIndex")
    drifted_foot.data_type, drifted_foot.domain = "FLOAT_VECTOR", "POINT"
    group.links.new(group.nodes["drifted"].outputs[0], drifted_foot.inputs["Geometry"])
    group.links.new(group.nodes.new("GeometryNodeInputPosition").outputs[0], drifted_foot.inputs["Value"])
    group.links.new(group.nodes["dw_i1"].outputs[0], drifted_foot.inputs["Index"])
    for name, foot in (("test_foot", group.nodes["at_position"]), ("test_dfoot", drifted_foot)):
        store = group.nodes.new("GeometryNodeStoreNamedAttribute")
        store.data_type = "FLOAT_VECTOR"
        store.inputs["Name"].default_value = name
        group.links.new(last, store.inputs["Geometry"])
        group.links.new(foot.outputs[0], store.inputs["Value"])
        last = store.outputs[0]
    group.links.new(last, output.inputs["Geometry"])
    return group


def _surface_and_feet(water):
    points, foam = _surface(water)
    evaluated = water.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    try:
        feet = {}
        for name in ("test_foot", "test_dfoot"):
            values = np.empty(len(mesh.vertices) * 3)
            mesh.attributes[name].data.foreach_get("vector", values)
            feet[name] = values.reshape(-1, 3)
        return points, foam, feet
    finally:
        evaluated.to_mesh_clear()


def _normals_and_heights(water, cell):
    """The evaluated water on its grid (rows along y): heights (n, n), the stored `water_normal`
    (n, n, 3) and numpy's normal of the heights' slopes (central differences, `cell` apart)."""
    evaluated = water.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    try:
        points = np.empty(len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", points)
        stored = np.empty(len(mesh.vertices) * 3)
        mesh.attributes["water_normal"].data.foreach_get("vector", stored)
    finally:
        evaluated.to_mesh_clear()
    points, stored = points.reshape(-1, 3), stored.reshape(-1, 3)
    order = np.lexsort((np.round(points[:, 0] / cell), np.round(points[:, 1] / cell)))
    side = int(round(math.sqrt(len(points))))
    heights = points[order, 2].reshape(side, side)
    d_dy, d_dx = np.gradient(heights, cell)
    slope = np.stack([-d_dx, -d_dy, np.ones_like(d_dx)], axis=-1)
    return heights, stored[order].reshape(side, side, 3), slope / np.linalg.norm(slope, axis=-1)[..., None]


def _degrees(a, b):
    return np.degrees(np.arccos(np.clip(np.sum(a * b, axis=-1), -1.0, 1.0)))


def test_on_the_seeds_ocean_the_wake_tilts_the_normal_it_shades_with(addon):
    """The seeds' ocean shades with the normal its waves store (`water_normal`, their analytic
    one), not the mesh's: a 4 m hull at 3 m/s for 6 s on it; where the wake moved the water
    (over 2 mm), that normal is the moved surface's (numpy's, from its slopes, within 1.5° for
    95% of the points), tilted from the waves' own by the wake; elsewhere the waves' own."""
    scene = harness.clean_scene(width=32, height=32, samples=1)
    scene.render.fps = FPS
    cell = 0.25
    water = _api().add_water(scene, preset="ocean", size=40.0, resolution=161, name="Ocean").object
    hull = _hull(scene, size=(4.0, 1.6, 1.0))
    _run_straight(hull, speed=3.0, heading=0.6, start=np.array([-12.0, -8.0]))
    _api().add_wake_source(hull, water)
    (modifier,) = harness.addon("water.boats.wake").wake_modifiers(water)
    _step(scene)
    heights, stored, slopes = _normals_and_heights(water, cell)
    modifier.show_viewport = False
    still, waves_own, still_slopes = _normals_and_heights(water, cell)
    modifier.show_viewport = True
    inside = np.zeros(heights.shape, bool)
    inside[2:-2, 2:-2] = True
    moved = inside & (np.abs(heights - still) > 0.002)
    off = _degrees(stored, slopes)[moved]
    tilt = _degrees(stored, waves_own)[moved]
    print(
        "wake:",
        moved.sum(),
        "points moved; stored normal off the surface's (95th percentile)",
        round(float(np.percentile(off, 95)), 3),
        "degrees, tilted from the waves' own (median)",
        round(float(np.median(tilt)), 3),
        "; without the wake off (95th)",
        round(float(np.percentile(_degrees(waves_own, still_slopes)[inside], 95)), 3),
    )
    assert moved.sum() > 1500
    assert np.percentile(off, 95) < 1.5 and np.median(tilt) > 1.0
    near = np.abs(heights - still) > 0.0  # a point's normal is its neighbours' too
    near = near | np.roll(near, 1, 0) | np.roll(near, -1, 0)
    near = near | np.roll(near, 1, 1) | np.roll(near, -1, 1)
    untouched = inside & ~near
    assert untouched.sum() > 10000
    assert _degrees(stored, waves_own)[untouched].max() < 0.05


@pytest.mark.render
def test_the_wake_on_the_open_sea_is_the_models_and_its_shading_shows_the_foam(addon, eevee, render):
    scene = harness.clean_scene(width=64, height=64, samples=1)
    scene.render.fps = FPS
    _lit(scene)
    sea = (
        _api()
        .add_water(scene, preset="open_sea", sea_wind_speed=5.0, wind_direction=(0.6, -0.8), name="Sea")
        .object
    )
    hull = _hull(scene)
    _run_straight(hull)
    _api().add_wake_source(hull, sea)
    _step(scene)
    with_wake, _foam = _surface(sea)
    (modifier,) = harness.addon("water.boats.wake").wake_modifiers(sea)
    modifier.show_viewport = False
    without, _none = _surface(sea)
    height = with_wake[:, 2] - without[:, 2]
    x, y = _track_frame(with_wake, _end(), HEADING)
    fade = harness.addon("water.waves").get_wave_input(modifier, "Fade")
    reach = SPEED * _track_seconds() - HULL[0] / 2
    *_, residual = _against_kelvin(x, y, height, HULL[0], SPEED, fade, reach=reach)
    print("the wake on the open sea against the model: residual", round(residual, 3))
    print("the sea's own waves", round(np.abs(without[:, 2]).max(), 2))
    assert np.abs(without[:, 2]).max() > 0.1, "the sea has waves of its own"
    assert residual < 0.45
    modifier.show_viewport = True
    foam_white, water_colour = _foam_is_white(scene, sea, with_wake, _foam, render, "sea")
    print("open sea: brightness in the foam", round(foam_white, 3), "clear water", round(water_colour, 3))
    assert foam_white > water_colour + 0.25


@pytest.mark.lts
def test_floating_and_stopping_keep_the_wake_without_a_cycle_and_a_deleted_hull_leaves_none(scene, tmp_path):
    water = _api().add_water(scene, preset="lake", size=40.0, resolution=81, name="Lake").object
    hull = _hull(scene)
    _run_straight(hull, start=np.array([-12.0, -8.0]))
    _api().add_wake_source(hull, water)
    wake = harness.addon("water.boats.wake")
    (modifier,) = wake.wake_modifiers(water)
    waves = harness.addon("water.waves")
    assert waves.get_wave_input(modifier, "Source") == hull

    def cycles():
        output, _result = harness.blender_output(lambda: _step(scene, 30))
        return "Dependency cycle" in output

    _api().float_on_water(hull, water, draft=0.6)
    source = waves.get_wave_input(modifier, "Source")
    assert source != hull and wake.source_of(modifier) == hull, "it reads the rig's anchor"
    assert waves.get_wave_input(modifier, "Draft") == pytest.approx(2.0 / 3.0)  # bounds' until added again
    _api().add_wake_source(hull, water)
    assert waves.get_wave_input(modifier, "Draft") == pytest.approx(0.6), "the float's draft"
    assert not cycles()
    points, _foam = _surface(water)
    assert np.abs(points[:, 2]).max() > 0.01, "a wake"
    _api().stop_floating(hull)
    assert waves.get_wave_input(modifier, "Source") == hull
    assert wake.modifiers_of(hull) == [modifier]

    bpy.ops.object.select_all(action="DESELECT")
    hull.select_set(True)
    bpy.context.view_layer.objects.active = hull
    bpy.ops.object.delete()
    path = tmp_path / "deleted.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))  # the add-on's save handler tidies up
    assert wake.wake_modifiers(water) == []
    assert "Water Wake Foam" not in water.active_material.node_tree.nodes
    bpy.ops.wm.open_mainfile(filepath=str(path))
    assert [m.name for m in bpy.data.objects["Lake"].modifiers] == ["Water Surroundings Sample"]


@pytest.mark.lts
def test_a_baked_wake_renders_any_frame_alone_without_the_add_on(scene, tmp_path, addon_disabled_afterwards):
    from test_repair import draw_panel

    scene.render.fps = FPS
    scene.frame_start, scene.frame_end = 1, 40
    water = _api().add_water(scene, preset="lake", size=40.0, resolution=81, name="Lake").object
    hull = _hull(scene)
    _run_straight(hull, start=np.array([-12.0, -8.0]))
    _api().add_wake_source(hull, water)
    _step(scene, 40)
    stepped = _surface(water)
    assert np.abs(stepped[0][:, 2]).max() > 0.01
    bpy.ops.object.select_all(action="DESELECT")
    hull.select_set(True)
    bpy.context.view_layer.objects.active = hull
    labels = [entry[1] for entry in draw_panel() if entry[0] == "label"]
    assert "The wake on 'Lake' is not baked: farms render it flat" in labels
    path = tmp_path / "baked.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))  # 4.2 bakes beside the saved file
    assert _api().bake(water, scene)
    assert "The wake on 'Lake' is not baked: farms render it flat" not in [e[1] for e in draw_panel()]
    if bpy.app.version < (4, 3, 0):
        assert list((tmp_path / "baked_water_bakes").rglob("*.blob")), "the bake's folder beside it"
    bpy.ops.wm.save_mainfile()
    packed = tmp_path / "packed"  # as a farm gets it: BAT's pack, the original moved away
    status, output = harness.bat("pack", path, packed)
    assert status in (0, None), output
    files = [p.relative_to(packed).as_posix() for p in packed.rglob("*") if p.is_file()]
    blobs = [p for p in files if p.endswith(".blob")]
    if bpy.app.version < (4, 3, 0):
        assert blobs and all(p.startswith("baked_water_bakes/") for p in blobs), files
    else:
        assert not blobs, f"packed into the .blend, nothing beside it: {files}"
    path.rename(tmp_path / "moved.blend")
    if (tmp_path / "baked_water_bakes").exists():
        (tmp_path / "baked_water_bakes").rename(tmp_path / "moved_bakes")
    scene = harness.reopen_without_add_on(packed / "baked.blend")
    scene.frame_set(40)  # straight to the last frame, as a farm's worker does
    points, foam = _surface(bpy.data.objects["Lake"])
    assert np.abs(points - stepped[0]).max() < 1e-5
    assert np.abs(foam - stepped[1]).max() < 1e-5
    # The foam's breakup (its group and the foam tile it reads) travels in the file, packed.
    tiles = [n.image for n in bpy.data.node_groups["Water Wake Foam Cover"].nodes if n.type == "TEX_IMAGE"]
    assert len(tiles) == 2 and all(tile is not None and tile.packed_file is not None for tile in tiles)


@pytest.mark.parametrize(
    "stone, pond, resolution, times",
    [
        (0.3, 16.0, 161, (2.0, 4.0)),  # waves 0.6 m long: gravity's, group speed 0.49 m/s
        (0.008, 1.0, 401, (0.4, 0.8)),  # 1.6 cm: near the capillary minimum, group speed 0.24 m/s
    ],
)
def test_a_stone_dropped_in_makes_a_ring_that_spreads_at_the_group_speed(
    scene, stone, pond, resolution, times
):
    scene.render.fps = FPS
    water = _api().add_water(scene, preset="lake", size=pond, resolution=resolution, name="Pond").object
    centre = (0.13 * pond / 1.6, -0.07 * pond / 1.6)
    rock = _hull(scene, "Stone", (stone, stone, stone))
    for frame, z in ((1, 1.0), (13, -0.5)):  # it falls through the surface at about frame 9
        rock.location = (*centre, z)
        rock.keyframe_insert("location", frame=frame)
    _linear(rock)
    _api().add_wake_source(rock, water)
    entered = 1 + 12 * (1.0 / 1.5)  # the frame its origin crosses z = 0
    wavelength = 2.0 * stone
    radii = []
    for seconds in times:
        frame = int(round(entered + seconds * FPS))
        _step(scene, frame)
        points, _foam = _surface(water)
        r = np.linalg.norm(points[:, :2] - centre, axis=1)
        width = wavelength / 4.0
        bins = np.arange(0.0, pond / 2.0, width)
        which = np.digitize(r, bins)
        rms = [
            np.sqrt(np.mean(points[which == i, 2] ** 2)) if (which == i).any() else 0.0
            for i in range(1, len(bins))
        ]
        radii.append((bins[int(np.argmax(rms))] + width / 2.0, (frame - entered) / FPS))
    (r1, t1), (r2, t2) = radii
    k = 2.0 * math.pi / wavelength
    group = capillary_gravity_group_speed(k)
    speed = (r2 - r1) / (t2 - t1)
    print("ring radii", radii, "speed", round(speed, 3), "group speed", round(group, 3))
    assert abs(speed - group) < 0.2 * group


def test_the_operators_and_the_panel(scene):
    from test_repair import draw_panel

    water = _api().add_water(scene, preset="lake", size=20.0, resolution=41, name="Lake").object
    hull = _hull(scene)
    bpy.ops.object.select_all(action="DESELECT")
    water.select_set(True)
    bpy.context.view_layer.objects.active = water
    assert not bpy.ops.object.water_wake.poll(), "neither way: no object that leaves a wake selected"
    hull.select_set(True)
    bpy.context.view_layer.objects.active = hull
    with pytest.raises(RuntimeError, match="No selected object leaves a wake"):
        bpy.ops.object.water_wake(enable=False)  # the panel's Remove, nothing to remove
    assert bpy.ops.object.water_wake(strength=0.5) == {"FINISHED"}
    wake = harness.addon("water.boats.wake")
    (modifier,) = wake.wake_modifiers(water)
    assert harness.addon("water.waves").get_wave_input(modifier, "Strength") == pytest.approx(0.5)
    labels = [entry[1] for entry in draw_panel() if entry[0] == "label"]
    assert "Leaves a wake on 'Lake'" in labels
    assert "The wake on 'Lake' is not baked: farms render it flat" in labels
    nodes = water.active_material.node_tree.nodes
    assert nodes["Material Output"].inputs["Surface"].links[0].from_node.name == "Water Wake Foam"
    assert bpy.ops.object.water_wake(enable=False) == {"FINISHED"}
    assert wake.wake_modifiers(water) == [] and "Water Wake Foam" not in nodes
    assert nodes["Material Output"].inputs["Surface"].links[0].from_node.name == "Water Surface"


def test_a_dry_hull_stays_dry_under_its_own_foam_whichever_came_first(scene):
    keep_out = harness.addon("water.boats.keep_out")
    for first in ("keep out", "wake"):
        water = _api().add_water(scene, preset="lake", size=20.0, resolution=41, name=f"Lake {first}").object
        hull = _hull(scene, f"Hull {first}")
        steps = [lambda: _api().keep_water_out(hull, water), lambda: _api().add_wake_source(hull, water)]
        for step in steps if first == "keep out" else steps[::-1]:
            step()
        nodes = water.active_material.node_tree.nodes
        surface = nodes["Material Output"].inputs["Surface"]
        outer = surface.links[0].from_node
        inner = outer.inputs[1].links[0].from_node
        assert (outer.name, inner.name) == (keep_out.MIX_NODE, "Water Wake Foam"), first
        assert inner.inputs[1].links[0].from_node.name == "Water Surface"
        assert keep_out.water_shader_input(water.active_material) == inner.inputs[1]
        _api().let_water_in(hull)
        _api().remove_wake_source(hull)
        assert surface.links[0].from_node.name == "Water Surface"


@pytest.mark.render
def test_rendering_a_file_with_an_unbaked_wake_says_so(scene, tmp_path):
    water = _api().add_water(scene, preset="lake", size=20.0, resolution=41, name="Lake").object
    harness.add_camera(scene, (0.0, -10.0, 6.0), (0.0, 0.0, 0.0))
    _api().add_wake_source(_hull(scene), water)
    source = tmp_path / "unbaked.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(source))
    said = []
    _api().render_file(str(source), str(tmp_path / "frame.png"), progress=said.append)
    assert any("the wake on 'Lake' is not baked" in line for line in said), said
