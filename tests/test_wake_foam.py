"""Issue 58 point 4: a boat's foam widens behind it, breaks into patches and fades, its edges
ragged; a turning boat's lies along its bend; on the lake and the open sea. Measured on the final
picture.

A lake 90 m across (0.25 m cells), and the open sea under a 4 m/s wind, the wind along
(0.6, -0.8), a dim blue sky and a sun 40 degrees up. On each, two 6 m x 2.4 m boats run for 10 s
at 12 frames a second, stepped from frame 1 as a render does: one straight at 5 m/s on a heading
of 0.3 rad, one round a bend of 14 m radius at 4 m/s.
Each is seen straight down (orthographic, 0.125 m a pixel, EEVEE, 1 sample); a pixel is foam where
its mean brightness is over 0.6 (the foam is white, 0.88; the lit water about 0.2).

Behind the straight boat, in 5 m bins along its track (its stern to 45 m behind, ages 0 to 9 s,
each pixel placed in the track's frame by numpy from the camera's projection):

* the trail widens: the spread across the track holding 90% of its foam (5th to 95th percentile);
* its cover falls: the share of a 1.5 m band along the trail's line (the track drifted downwind,
  the young trail's width) that is foam, third by third (a patch can fill a bin), to under half
  the first bin's by 40 m;
* its edges are not straight: the outermost foam pixel across the track, row by row along it,
  strays from a smooth (quadratic) curve through them;
* it breaks into patches: its older half is several separate pieces, not one band.

The sun's glints on the bump are specks of a pixel or a few all over the lake: the straight
boat's foam is taken as the pieces of white over 0.25 m² within 8 m of its track.

Before the work the trail was one smooth band (`water_wake_foam` drawn as it is): its spread
shrank with age, its edge lay on a smooth curve within a pixel, and its older half was one piece.
"""

import math

import bpy
import numpy as np
import pytest

import harness

pytestmark = pytest.mark.render

FPS = 12
SECONDS = 10.0
LAST_FRAME = int(SECONDS * FPS) + 1
WIND = (0.6, -0.8)
HULL = (6.0, 2.4, 1.5)  # length, beam, height
STRAIGHT = {"start": np.array([-40.0, -30.0]), "heading": 0.3, "speed": 5.0}
BEND = {"centre": np.array([10.0, 22.0]), "radius": 14.0, "speed": 4.0, "from": -math.pi / 2.0}
PIXEL = 0.125  # metres a pixel, seen from above
WHITE = 0.6  # mean brightness over which a pixel is foam
BINS = np.arange(0.0, 45.1, 5.0)  # metres behind the stern


def _hull(scene, name):
    return harness.add_box(scene, name, HULL)


def _straight_at(seconds):
    """(where (2,), heading) of the straight boat `seconds` in."""
    heading = STRAIGHT["heading"]
    return STRAIGHT["start"] + np.array([math.cos(heading), math.sin(heading)]) * STRAIGHT[
        "speed"
    ] * seconds, heading


def _bend_at(seconds):
    """(where (2,), heading) of the turning boat `seconds` in (anticlockwise round the bend)."""
    angle = BEND["from"] + BEND["speed"] * seconds / BEND["radius"]
    where = BEND["centre"] + BEND["radius"] * np.array([math.cos(angle), math.sin(angle)])
    return where, angle + math.pi / 2.0


def _key(hull, path):
    """Keys `hull` on every frame along `path(seconds)`."""
    for frame in range(1, LAST_FRAME + 1):
        where, heading = path((frame - 1) / FPS)
        hull.location = (*where, 0.0)
        hull.rotation_euler = (0.0, 0.0, heading)
        hull.keyframe_insert("location", frame=frame)
        hull.keyframe_insert("rotation_euler", frame=frame)


def _top_view(scene, centre, width, height, name, render):
    """The picture straight down over `centre` (width x height metres): (foam mask, the world
    (x, y) of every pixel)."""
    scene.render.resolution_x, scene.render.resolution_y = int(width / PIXEL), int(height / PIXEL)
    camera = harness.add_camera(scene, (*centre, 60.0), (*centre, 0.0))
    camera.data.type, camera.data.ortho_scale = "ORTHO", width
    camera.data.clip_end = 200.0
    image = render(scene, name)[..., :3].mean(axis=2)
    # The camera's projection, affine seen straight down: pixel = p0 + A (world - centre).
    points = np.array([[*centre, 0.0], [centre[0] + 1.0, centre[1], 0.0], [centre[0], centre[1] + 1.0, 0.0]])
    p0, px, py = harness.world_to_pixel(scene, camera, points)
    inverse = np.linalg.inv(np.stack([px - p0, py - p0], axis=1))
    rows, cols = np.mgrid[0 : image.shape[0], 0 : image.shape[1]]
    pixels = np.stack([cols + 0.5, rows + 0.5], axis=-1) - p0
    world = np.asarray(centre) + pixels @ inverse.T
    return image > WHITE, world


# The waters, with how fast the foam drifts downwind on each (`water/boats/wake.py`: 0.3 m/s on a
# lake, 3% of the wind on the open sea).
WATERS = {
    "lake": ({"preset": "lake", "size": 90.0, "resolution": 361}, 0.3),
    "open sea": ({"preset": "open_sea", "sea_wind_speed": 4.0}, 0.03 * 4.0),
}


@pytest.fixture(scope="module", params=tuple(WATERS))
def boats(request, addon, eevee):
    """(the scene, its foam's drift in m/s) after both boats' runs on the water `request.param`."""
    api = harness.addon("api")
    values, drift = WATERS[request.param]
    scene = harness.clean_scene(engine=eevee, width=64, height=64, samples=1)
    scene.render.fps = FPS
    harness.set_world_color(scene, (0.08, 0.12, 0.2))
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (math.radians(50.0), 0.0, math.radians(20.0))
    scene.collection.objects.link(sun)
    water = api.add_water(scene, name="Water", wind_direction=WIND, **values).object
    straight, bend = _hull(scene, "Straight"), _hull(scene, "Bend")
    _key(straight, _straight_at)
    _key(bend, _bend_at)
    for hull in (straight, bend):
        api.add_wake_source(hull, water)
    for frame in range(1, LAST_FRAME + 1):
        scene.frame_set(frame)
    return scene, drift


def _track_frame(world, seconds):
    """(metres behind the straight boat's stern, metres across its track) of world points."""
    where, heading = _straight_at(seconds)
    direction = np.array([math.cos(heading), math.sin(heading)])
    offset = world - where
    behind = -(offset @ direction) - HULL[0] / 2.0
    across = offset[..., 1] * direction[0] - offset[..., 0] * direction[1]
    return behind, across


def test_the_trail_widens_breaks_into_patches_and_fades_behind_a_straight_boat(boats, render):
    end, _ = _straight_at(SECONDS)
    start = end - np.array([math.cos(STRAIGHT["heading"]), math.sin(STRAIGHT["heading"])]) * 26.0
    scene, drift = boats
    foam, world = _top_view(scene, start, 60.0, 30.0, "straight", render)
    behind, across = _track_frame(world, SECONDS)
    # Where the trail's line lies across the track: each track point drifted downwind for its age.
    heading = STRAIGHT["heading"]
    sideways = drift * np.dot(np.array(WIND) / np.hypot(*WIND), (-math.sin(heading), math.cos(heading)))
    line = sideways * (behind + HULL[0] / 2.0) / STRAIGHT["speed"]
    # The sun's glints on the bump are specks of a pixel or a few all over the lake: foam is in
    # pieces over 0.25 m² (16 pixels).
    foam = _pieces(foam & (np.abs(across) < 8.0))[0] > 0
    spreads, covers = [], []
    for near, far in zip(BINS[:-1], BINS[1:]):
        here = (behind >= near) & (behind < far) & (np.abs(across) < 8.0)
        lateral = across[here & foam]
        band = here & (np.abs(across - line) < 0.75)
        covers.append(foam[band].mean())
        spreads.append(np.subtract(*np.percentile(lateral, [95, 5])) if len(lateral) > 20 else 0.0)
    print("metres behind", BINS[:-1].tolist())
    print("spread across holding 90% of the foam (m)", np.round(spreads, 2).tolist())
    print("share of the 1.5 m band along its line that is foam", np.round(covers, 3).tolist())
    young, old = slice(0, 2), slice(4, 7)  # 0-10 m and 20-35 m behind: 0-2 s and 4-7 s old
    assert np.mean(spreads[old]) > 1.3 * np.mean(spreads[young])  # it widens
    thirds = [np.mean(covers[i : i + 3]) for i in (0, 3, 6)]  # 0-15, 15-30 and 30-45 m behind
    assert thirds[0] > 0.6  # dense where fresh
    assert thirds[1] < thirds[0] + 0.03 and thirds[2] < thirds[1]  # thinning
    assert covers[-1] < 0.5 * covers[0]  # and fading

    # Its edges: the outermost foam each 0.125 m along, either side, 2-35 m behind.
    steps = np.arange(2.0, 35.0, PIXEL)
    strays = []
    for side in (1.0, -1.0):
        edge = np.full(len(steps), np.nan)
        for i, step in enumerate(steps):
            row = (
                foam & (np.abs(behind - step) < PIXEL / 2.0) & (side * across > 0.0) & (np.abs(across) < 8.0)
            )
            if row.any():
                edge[i] = np.abs(across[row]).max()
        kept = ~np.isnan(edge)
        smooth = np.polyval(np.polyfit(steps[kept], edge[kept], 2), steps[kept])
        strays.append(np.sqrt(np.mean((edge[kept] - smooth) ** 2)))
    print("the edges' stray from a smooth curve (m, rms)", np.round(strays, 3).tolist())
    assert min(strays) > 0.25  # two pixels: ragged, not a line

    # Patches: the older half's foam in separate pieces (4-neighbour), over 0.25 m² each.
    older = foam & (behind > 20.0) & (behind < 45.0)
    pieces = _pieces(older)[1]
    print(
        "pieces of foam 20-45 m behind, over 0.25 m²",
        len(pieces),
        "largest",
        max(pieces, default=0) * PIXEL**2,
    )
    assert len(pieces) >= 6


def _pieces(mask):
    """The 4-connected pieces of `mask` over 0.25 m²: (each pixel's piece, numbered from 1, 0 where
    none or in a smaller one; the pieces' sizes in pixels)."""
    labels = np.zeros(mask.shape, dtype=np.int64)
    sizes = []
    for start in zip(*np.nonzero(mask)):
        if labels[start]:
            continue
        sizes.append(0)
        stack = [start]
        labels[start] = len(sizes)
        while stack:
            r, c = stack.pop()
            sizes[-1] += 1
            for nr, nc in ((r + 1, c), (r - 1, c), (r, c + 1), (r, c - 1)):
                if (
                    0 <= nr < mask.shape[0]
                    and 0 <= nc < mask.shape[1]
                    and mask[nr, nc]
                    and not labels[nr, nc]
                ):
                    labels[nr, nc] = len(sizes)
                    stack.append((nr, nc))
    big = np.array([0, *(size * PIXEL**2 > 0.25 for size in sizes)], dtype=bool)
    kept = big[labels]
    numbered = np.zeros(len(big), dtype=np.int64)
    numbered[big] = np.arange(1, big.sum() + 1)
    return numbered[labels] * kept, [size for size in sizes if size * PIXEL**2 > 0.25]


def test_a_turning_boat_leaves_its_foam_along_the_bend(boats, render):
    """Its foam lies along the bend it ran, each track point drifted downwind 0.3 m/s for its age
    (the lake's foam drift), not along its heading now: in each 10 degrees of the bend behind the
    hull, the foam's median distance from the bend's centre is the drifted track's within 1 m,
    over 90 degrees or more."""
    scene, speed = boats
    foam, world = _top_view(scene, BEND["centre"], 40.0, 40.0, "bend", render)
    ages = np.linspace(0.5, SECONDS * 0.8, 300)
    drift = np.outer(ages * speed, np.array(WIND) / np.hypot(*WIND))
    track = np.array([_bend_at(SECONDS - age)[0] for age in ages]) + drift - BEND["centre"]
    where, _ = _bend_at(SECONDS)
    relative = world - BEND["centre"]
    radius, angle = (
        np.linalg.norm(relative, axis=-1),
        np.degrees(np.arctan2(relative[..., 1], relative[..., 0])),
    )
    track_radius = np.linalg.norm(track, axis=-1)
    track_angle = np.degrees(np.arctan2(track[:, 1], track[:, 0]))
    clear_of_hull = np.linalg.norm(world - where, axis=-1) > HULL[0]
    offsets = []
    for low in np.arange(-180.0, 180.0, 10.0):
        on_track = (track_angle >= low) & (track_angle < low + 10.0)
        if not on_track.any():
            continue
        expected = track_radius[on_track].mean()
        here = (
            foam & clear_of_hull & (angle >= low) & (angle < low + 10.0) & (np.abs(radius - expected) < 5.0)
        )
        if here.sum() > 20:
            offsets.append(np.median(radius[here]) - expected)
    print("the foam's median off the drifted bend, per 10 degrees (m)", np.round(offsets, 2).tolist())
    assert sum(abs(offset) < 1.0 for offset in offsets) >= 9


def test_an_older_wakes_foam_mix_gets_the_cover_and_none_is_left_when_the_wake_goes(scene):
    """A material whose wake foam mix read the stored amount as it is (before the cover) gets
    `Water Wake Foam Cover` when a wake is added again; taking the last wake off leaves neither
    the mix nor the group."""
    api, wake = harness.addon("api"), harness.addon("water.boats.wake")
    water = api.add_water(scene, preset="lake", size=20.0, name="Pond").object
    hull = _hull(scene, "Hull")
    api.add_wake_source(hull, water)
    material = water.active_material
    tree = material.node_tree
    mix = tree.nodes[wake.FOAM_MIX]
    tree.nodes.remove(tree.nodes[wake.FOAM_READ])  # the layout before: an Attribute node
    amount = tree.nodes.new("ShaderNodeAttribute")
    amount.name, amount.attribute_type, amount.attribute_name = wake.FOAM_READ, "GEOMETRY", "water_wake_foam"
    tree.links.new(amount.outputs["Fac"], mix.inputs["Fac"])
    cover = bpy.data.node_groups["Water Wake Foam Cover"]
    api.add_wake_source(hull, water)
    read = tree.nodes[wake.FOAM_READ]
    assert read.bl_idname == "ShaderNodeGroup" and read.node_tree == cover
    assert mix.inputs["Fac"].links[0].from_node == read
    assert (
        sum(
            node.bl_idname == "ShaderNodeAttribute" and node.attribute_name == "water_wake_foam"
            for node in tree.nodes
        )
        == 0
    )
    api.remove_wake_source(hull, water)
    assert wake.FOAM_MIX not in tree.nodes and wake.FOAM_READ not in tree.nodes
    assert "Water Wake Foam Cover" not in bpy.data.node_groups


def _evaluated(water):
    """(points (N, 3), water_wake_foam (N,)) of the evaluated water, in its own space."""
    return harness.evaluated_points(water, "water_wake_foam")


@pytest.mark.parametrize(("strength", "speed", "breaks"), ((6.0, 6.0, True), (1.0, 3.0, False)))
def test_the_wakes_steep_crests_break_white(scene, strength, speed, breaks):
    """A blunt hull (Strength 6) at 6 m/s (Fr 0.78) raises crests steep enough to break; a gentle
    one (Strength 1, 3 m/s) none. Over the whole lake, the foam is at least numpy's breaking foam
    clamp((a k - 0.25) / 0.1), a the wake's height (the water with the wake less without it) and
    k = 1.5 g / U², the cusp waves' wavenumber at the fastest the hull ran: white where a k passes
    0.35."""
    api = harness.addon("api")
    scene.render.fps = FPS
    water = api.add_water(scene, preset="lake", size=60.0, resolution=241, name="Lake").object
    hull = _hull(scene, "Hull")
    heading = 0.4
    for frame in (1, 49):
        seconds = (frame - 1) / FPS
        hull.location = (
            -20.0 + math.cos(heading) * speed * seconds,
            -8.0 + math.sin(heading) * speed * seconds,
            0.0,
        )
        hull.rotation_euler = (0.0, 0.0, heading)
        hull.keyframe_insert("location", frame=frame)
        hull.keyframe_insert("rotation_euler", frame=frame)
    for fcurve in harness.addon("nodes.material")._action_fcurves(hull.animation_data.action):
        for key in fcurve.keyframe_points:
            key.interpolation = "LINEAR"
    api.add_wake_source(hull, water, strength=strength)
    for frame in range(1, 49):
        scene.frame_set(frame)
    points, foam = _evaluated(water)
    wake = harness.addon("water.boats.wake").wake_modifiers(water)[0]
    wake.show_viewport = False
    before, _ = _evaluated(water)
    height = points[:, 2] - before[:, 2]
    steepness = height * 1.5 * 9.81 / speed**2
    crests = np.clip((steepness - 0.25) / 0.1, 0.0, 1.0)
    short = crests - foam
    print(
        f"Strength {strength:g} at {speed:g} m/s: a k up to {steepness.max():.2f}, "
        f"{int((crests > 0.5).sum())} points breaking (over half white), the foam short of it by "
        f"{short.max():.2e} at most"
    )
    assert short.max() < 1e-4
    if breaks:
        assert (crests > 0.5).sum() > 50 and foam[crests > 0.99].min() > 0.99
    else:
        assert steepness.max() < 0.25 and not (crests > 0).any()
