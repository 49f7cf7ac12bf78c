"""Issue 59 point 3: the four shared groups the shadings nest, each evaluated alone against numpy.

Each group is built by the add-on's builder and used alone in a fresh material on a mesh of one
face a pixel (64 x 64), a plane square to a Cycles camera's axis, so that each pixel's centre lies
in the middle of its own face. The group's inputs are that face's values (face-domain attributes
written from numpy, read by Attribute nodes; the UV map for `Water Surface Bump UV`), so every
pixel is one case, whichever point of the pixel Cycles samples (only Geometry > Incoming, which
`Water Underside` reads, moves with it: that test allows for it). The output goes to an
Emission of strength 1, rendered at 1 sample into a float EXR (negative values kept): the pixel is
the group's value. numpy computes the same per face from the formula each module's docstring and
docs/MODEL.md state, written here, not read from the add-on.

* `Water Surface Wind Frame`: `w` the wind flattened onto XY and made unit length, +Y when it
  has no length (under 1e-6); `p = (w.y, -w.x)`, over every direction, lengths 1e-9 to 1e3,
  any Z, and zero.
* `Water Surface Bump UV`: `q = (uv . p, uv . w + Time * Wind Force) / Wave Length` and the
  scroll `(0, Time * Wind Force / Wave Length)` (MODEL section 1, step 1), the five inputs all
  varying over the field.
* `Water Underside`: seen by a camera under the plane looking up through it (half the faces
  wound the other way: the top side at the same angles), the normal turned to the eye,
  `n sign(I . n)`, and Fresnel's reflectance of unpolarised light (`reference_models.fresnel`)
  at `|I . n|` for n = 1.33 on the top side and 1 / 1.33 from below, 1 past asin(1 / 1.33).
* `Water Surface Foam Coverage`: `Foam Amount * clamp((b + f - 1) / 0.25)` times the
  surroundings' flag, `f = 1 - smoothstep(0, Foam Width, d)` (MODEL section 6), `b` the foam
  tile read bilinearly with repeat (`reference_models.bilinear` over the image's own pixels).
"""

import math

import bpy
import numpy as np
import pytest
from reference_models import bilinear, fresnel

import harness

pytestmark = pytest.mark.render

SIZE = 64  # pixels each way, one face each
DISTANCE = 2.0  # metres from the camera to the plane of faces
# SPEC's refractive index (SPEC section 4 bends the view ray by sin t = sin i / 1.33; MODEL 15):
# the add-on's, 0.003 under `reference_models.WATER_IOR` (tests/plain/test_reference_constants.py
# holds it to that). The group at 1.333 is up to 0.28 off this one, next to the critical angles.
SPEC_IOR = 1.33
# How far from its centre Cycles' one sample may fall in a pixel: a box filter 0.01 px wide.
FILTER_WIDTH = 0.01
# A wind shorter than this in the plane is none: the frame turns to +Y.
NO_WIND = 1e-6


def _scene():
    """A clean Cycles scene of SIZE x SIZE pixels, one exact sample at each pixel's centre, and its
    camera at the origin looking up +Z (a 12 mm lens: 56° either side)."""
    scene = harness.clean_scene(engine="CYCLES", width=SIZE, height=SIZE, samples=1)
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.use_denoising = False
    cycles.use_adaptive_sampling = False
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = FILTER_WIDTH
    camera = harness.add_camera(scene, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), lens=12.0)
    return scene, camera


def _frame(scene, camera, du=0.0, dv=0.0, corners=False):
    """Camera-space points on the plane at DISTANCE: at the pixels' centres moved by (du, dv)
    pixels (SIZE, SIZE, 3), or at their corners (SIZE + 1, SIZE + 1, 3); row 0 at the top."""
    top_right, _, bottom_left, top_left = (np.array(c) for c in camera.data.view_frame(scene=scene))
    top_right, bottom_left, top_left = (c * (DISTANCE / -c[2]) for c in (top_right, bottom_left, top_left))
    steps = np.arange(SIZE + 1.0) if corners else np.arange(SIZE) + 0.5
    u = (steps + du) / SIZE
    v = (steps + dv) / SIZE
    return top_left + u[None, :, None] * (top_right - top_left) + v[:, None, None] * (bottom_left - top_left)


def _to_world(camera, points):
    matrix = np.array(camera.matrix_world)
    return points @ matrix[:3, :3].T + matrix[:3, 3]


def _incoming(scene, camera, du=0.0, dv=0.0):
    """Geometry > Incoming at every pixel (moved by (du, dv) pixels): the unit vector to the eye."""
    rays = _to_world(camera, _frame(scene, camera, du, dv)) - np.array(camera.matrix_world)[:3, 3]
    return -rays / np.linalg.norm(rays, axis=-1, keepdims=True)


def _faces(scene, camera, facing_camera, scale=1.0):
    """A mesh object of SIZE x SIZE faces, face r * SIZE + c seen exactly on pixel (r, c), wound to
    face the camera where `facing_camera` (SIZE, SIZE) is true, away from it elsewhere; the object
    scaled by `scale` (its own coordinates the world's / `scale`)."""
    corners = _to_world(camera, _frame(scene, camera, corners=True)).reshape(-1, 3) / scale
    row, col = np.mgrid[0:SIZE, 0:SIZE]
    top_left = row * (SIZE + 1) + col
    # Seen from the camera (x right, y up), top left, bottom left, bottom right, top right runs
    # counter-clockwise: the face's normal points at the camera.
    towards = np.stack([top_left, top_left + SIZE + 1, top_left + SIZE + 2, top_left + 1], axis=-1)
    quads = np.where(facing_camera[..., None], towards, towards[..., ::-1]).reshape(-1, 4)
    mesh = bpy.data.meshes.new("test: one face a pixel")
    mesh.from_pydata(corners.tolist(), [], quads.tolist())
    mesh.polygons.foreach_set("use_smooth", np.zeros(len(mesh.polygons), dtype=bool))
    obj = bpy.data.objects.new("test: one face a pixel", mesh)
    obj.scale = (scale,) * 3
    scene.collection.objects.link(obj)
    return obj


def _face_attribute(mesh, name, values):
    values = np.asarray(values, dtype=np.float32)
    vector = values.ndim == 3
    stored = mesh.attributes.new(name, "FLOAT_VECTOR" if vector else "FLOAT", "FACE")
    stored.data.foreach_set("vector" if vector else "value", values.ravel())
    return vector


def _evaluate(
    render, made, group, fed, outputs=None, facing_camera=None, uv=None, attributes=None, scale=1.0
):
    """Renders `group` alone on one face a pixel: its inputs named in `fed` take each face's value
    ((SIZE, SIZE) floats or (SIZE, SIZE, 3) vectors, row 0 at the top); `uv` (SIZE, SIZE, 2) is
    the faces' UV map and `attributes` more face attributes by name, for the group to read.
    `made` is `_scene()`'s scene and camera; `scale` the faces' object's (`_faces`). Returns each of
    `outputs` (default all) as (SIZE, SIZE, 3) floats (a float output grey)."""
    scene, camera = made
    if facing_camera is None:
        facing_camera = np.ones((SIZE, SIZE), dtype=bool)
    obj = _faces(scene, camera, facing_camera, scale)
    mesh = obj.data
    material = bpy.data.materials.new("test: " + group.name)
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    if hasattr(material.cycles, "emission_sampling"):  # an emitter, but no light for anything else
        material.cycles.emission_sampling = "NONE"
    mesh.materials.append(material)
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    node = nodes.new("ShaderNodeGroup")
    node.node_tree = group
    for index, (name, values) in enumerate(fed.items()):
        attribute = f"test_input_{index}"
        vector = _face_attribute(mesh, attribute, values)
        read = nodes.new("ShaderNodeAttribute")
        read.attribute_type, read.attribute_name = "GEOMETRY", attribute
        links.new(read.outputs["Vector" if vector else "Fac"], node.inputs[name])
    for name, values in (attributes or {}).items():
        _face_attribute(mesh, name, values)
    if uv is not None:
        layer = mesh.uv_layers.new(name="UVMap")
        per_loop = np.repeat(np.asarray(uv, dtype=np.float32).reshape(-1, 2), 4, axis=0)
        layer.data.foreach_set("uv", per_loop.ravel())
    mesh.update()
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Strength"].default_value = 1.0
    output = nodes.new("ShaderNodeOutputMaterial")
    links.new(emission.outputs[0], output.inputs["Surface"])
    rendered = {}
    for name in outputs or [socket.name for socket in node.outputs]:
        links.new(node.outputs[name], emission.inputs["Color"])
        pixels = render(scene, f"{group.name} {name}".replace(" ", "_"), exr=True)
        rendered[name] = pixels[..., :3].astype(np.float64)
    return rendered


def _built(module):
    """The add-on's group of `nodes.<module>`, built by its builder as the shadings build it."""
    specs = harness.addon("nodes").SPECS
    return harness.addon("nodes.builder").ensure_group(harness.addon(f"nodes.{module}").SPEC, specs)


def _unit_wind(wind):
    """numpy's wind frame: `wind` (..., 3) flattened onto XY and made unit length, +Y where it has
    no length (under 1e-6); and its perpendicular p = (w.y, -w.x) (so that (p, w, Z) is turned (X, Y, Z))."""
    flat = np.asarray(wind, float)[..., :2]
    length = np.linalg.norm(flat, axis=-1, keepdims=True)
    # No wind: shorter than the group's documented 1e-6 (nodes/wind_frame.py), too short to normalise.
    some = length > NO_WIND
    w = np.where(some, flat / np.where(some, length, 1.0), (0.0, 1.0))
    return w, np.stack([w[..., 1], -w[..., 0]], axis=-1)


def _stored(values):
    """`values` as the float32 attributes hold them, so that numpy starts from the same inputs."""
    return np.asarray(values, dtype=np.float32).astype(np.float64)


def _with_z(xy, z=0.0):
    return np.concatenate([xy, np.full(xy.shape[:-1] + (1,), z)], axis=-1)


def _winds(rng):
    """A field of wind vectors: every direction over the columns (the axes among them), lengths
    1e-9 to 1e3 over the rows (none within 19% of the 1e-6 taken for none), any Z; every fifth
    face no wind in the plane (Z alone, or zero)."""
    row, col = np.mgrid[0:SIZE, 0:SIZE]
    angle = 2.0 * math.pi * col / SIZE  # 0, 90, 180 and 270 degrees exactly on columns 0, 16, 32, 48
    length = 10.0 ** (-9.0 + 12.0 * (row + 0.5) / SIZE)
    z = rng.uniform(-5.0, 5.0, (SIZE, SIZE))
    wind = np.stack([length * np.cos(angle), length * np.sin(angle), z], axis=-1)
    still = (row * SIZE + col) % 5 == 0
    wind[still, :2] = 0.0
    wind[still & (col % 2 == 0), 2] = 0.0  # the zero vector itself
    return _stored(wind), still


def _check_wind_frame(render, made, group):
    wind, still = _winds(np.random.default_rng(1))
    rendered = _evaluate(render, made, group, {"Wind Direction": wind})
    w, p = _unit_wind(wind)
    errors = {}
    for name, expected in (("Wind", _with_z(w)), ("Across", _with_z(p))):
        error = np.abs(rendered[name] - expected)
        errors[name] = error
        print(f"wind frame {name}: worst {error.max():.2e}, mean {error.mean():.2e}; no wind", end=" ")
        print(f"{error[still].max():.2e}")
    for name, error in errors.items():
        assert error.max() < 1e-5, name
        assert error[still].max() < 1e-6, f"{name}: no wind is +Y"


def test_the_wind_frame_is_the_unit_wind_in_the_plane_and_its_clockwise_perpendicular(addon, render):
    """Over every direction (the axes among them), lengths 1e-9 to 1e3 and any Z: Wind is the wind
    flattened onto XY and made unit, +Y where it has none in the plane (under 1e-6, or Z alone),
    Across is (w.y, -w.x); both with Z 0. Within 1e-5 per component (measured: 1e-7)."""
    made = _scene()
    _check_wind_frame(render, made, _built("wind_frame"))


def _bump_uv_field(rng):
    """Each face's UV, wind, Wave Length, Wind Force and Time: all varying, every fifth wind zero."""
    uv = rng.uniform(-2.0, 2.0, (SIZE, SIZE, 2))
    wind, _still = _winds(rng)
    fed = {
        "Wave Length": 10.0 ** rng.uniform(-1.3, 0.7, (SIZE, SIZE)),  # 0.05 to 5
        "Wind Direction": wind[::-1, ::-1],
        "Wind Force": rng.uniform(0.0, 0.5, (SIZE, SIZE)),
        "Time": rng.uniform(0.0, 30.0, (SIZE, SIZE)),
    }
    return _stored(uv), {name: _stored(values) for name, values in fed.items()}


def _check_bump_uv(render, made, group):
    uv, fed = _bump_uv_field(np.random.default_rng(2))
    rendered = _evaluate(render, made, group, fed, uv=uv)
    w, p = _unit_wind(fed["Wind Direction"])
    scroll = fed["Time"] * fed["Wind Force"]
    length = fed["Wave Length"][..., None]
    expected = {
        "Vector": _with_z(np.stack([(uv * p).sum(-1), (uv * w).sum(-1) + scroll], axis=-1) / length),
        "Scroll": _with_z(np.stack([np.zeros_like(scroll), scroll], axis=-1) / length),
    }
    # float32 rounds each term: the error is relative to the terms' size (the sum may cancel).
    size = np.maximum((np.linalg.norm(uv, axis=-1) + scroll) / fed["Wave Length"], 1.0)[..., None]
    for name, theirs in expected.items():
        error = np.abs(rendered[name] - theirs) / size
        print(f"bump UV {name}: worst {error.max():.2e} of the terms' size (or absolute under 1)")
        assert error.max() < 1e-5, name


def test_the_bump_uv_is_the_uv_in_the_wind_frame_scrolled_downwind_and_tiled(addon, render):
    """Over UVs -2 to 2, every wind direction (none among them), Wave Length 0.05 to 5 m, Wind
    Force 0 to 0.5 and Time 0 to 30 s, each face its own: Vector is
    (uv . p, uv . w + Time Wind Force) / Wave Length and Scroll (0, Time Wind Force / Wave Length),
    w and p numpy's wind frame, Z 0; within 1e-5 of the terms' size (float32's rounding: measured
    3e-7)."""
    made = _scene()
    _check_bump_uv(render, made, _built("bump_uv"))


def _underside_model(normal, incoming, from_below):
    """The turned normal and Fresnel's reflectance: `incoming` towards the eye; the index ratio
    SPEC_IOR on the top side, its inverse from below (past asin(1 / 1.33): 1)."""
    facing = (incoming * normal).sum(-1)
    turned = normal * np.sign(facing)[..., None]
    reflected = fresnel(np.abs(facing), np.where(from_below, 1.0 / SPEC_IOR, SPEC_IOR))
    return turned, reflected


def _check_underside(render, made, group):
    rng = np.random.default_rng(3)
    normal = rng.normal(size=(SIZE, SIZE, 3))
    normal = _stored(normal / np.linalg.norm(normal, axis=-1, keepdims=True))
    normal[:, :8] = (0.0, 0.0, 1.0)  # the water's own normal, up
    normal[:, 8:12] = (0.0, 0.0, -1.0)  # and turned over
    row, col = np.mgrid[0:SIZE, 0:SIZE]
    # The camera is under the plane looking up: a face wound with its normal up (away from the
    # camera) is water seen from below, Backfacing; the others show the top side.
    from_below = (row + col) % 2 == 0
    rendered = _evaluate(render, made, group, {"Normal": normal}, facing_camera=~from_below)
    scene, camera = made
    # Cycles' sample falls within FILTER_WIDTH / 2 of the pixel's centre: the model's range there
    # (it matters where the angle is at the critical one or the normal edge-on to the eye).
    reach = FILTER_WIDTH / 2
    models = [
        _underside_model(normal, _incoming(scene, camera, du, dv), from_below)
        for du, dv in ((0.0, 0.0), (-reach, -reach), (-reach, reach), (reach, -reach), (reach, reach))
    ]
    expected = {
        "Normal": [turned for turned, _ in models],
        "Reflected": [np.repeat(r[..., None], 3, -1) for _, r in models],
        "Refracted": [np.repeat(1.0 - r[..., None], 3, -1) for _, r in models],
    }
    worst = {}
    for name, cases in expected.items():
        low, high = np.min(cases, axis=0), np.max(cases, axis=0)
        beyond = np.maximum(low - rendered[name], rendered[name] - high).max(-1)
        centre = np.abs(rendered[name] - cases[0]).max(-1)
        worst[name] = beyond
        print(
            f"underside {name}: worst {beyond.max():.2e} beyond the sample's reach, {centre.max():.2e} "
            f"from the centre's (mean {centre.mean():.2e}); {int((centre > 1e-4).sum())} px over 1e-4"
        )
    incoming = _incoming(scene, camera)
    angle = np.degrees(np.arccos(np.abs((incoming * normal).sum(-1))))
    window = from_below & (angle > math.degrees(math.asin(1.0 / SPEC_IOR)) + 0.2)
    print(
        f"underside: {int(window.sum())} px past the critical angle from below, Reflected there "
        f"{rendered['Reflected'][window, 0].min():.6f} to {rendered['Reflected'][window, 0].max():.6f}; "
        f"angles {angle.min():.1f}-{angle.max():.1f}°, {int(from_below.sum())} px from below"
    )
    for name, beyond in worst.items():
        assert beyond.max() < 1e-4, name
    assert window.sum() > 200 and np.all(rendered["Reflected"][window] > 1.0 - 1e-6)


def test_the_underside_turns_the_normal_to_the_eye_and_weighs_by_fresnel_from_either_side(addon, render):
    """A camera under a plane of faces looking up through it (12 mm lens, 56° out), half the faces
    wound to show it their top side: over random unit normals (the water's own up and down among
    them), Normal is n sign(I . n), Reflected Fresnel's F at |I . n| for the index ratio 1.33 on
    the top side and 1 / 1.33 from below (1 past asin(1 / 1.33) = 48.75°: total internal
    reflection), Refracted 1 - F; within 1e-4 of numpy's range over where in the pixel Cycles'
    sample can fall (measured: 3e-8). That range matters where Fresnel is steep: 50 pixels, 46.9°
    to the critical angle from below and 86.5-90° on the top side, are up to 3e-3 off the value
    at their centre."""
    made = _scene()
    _check_underside(render, made, _built("underside"))


SHORE = "water_shore_distance"  # metres to the nearest waterline (MODEL section 9)
FLAG = "water_surroundings"  # 1 where the surroundings were measured


def _foam_field(rng):
    """Each face's tile position (repeats, negative too), Foam Width, Foam Amount, shore distance
    (0 to past the width, some at the waterline and some 1000 m: no shore) and flag."""
    width = 10.0 ** rng.uniform(-1.3, 1.3, (SIZE, SIZE))  # 0.05 to 20 m
    distance = width * rng.uniform(0.0, 1.3, (SIZE, SIZE))
    pick = rng.uniform(size=(SIZE, SIZE))
    distance[pick < 0.05] = 0.0
    distance[pick > 0.95] = 1000.0
    amount = np.where(rng.uniform(size=(SIZE, SIZE)) < 0.3, 1.0, rng.uniform(0.0, 1.0, (SIZE, SIZE)))
    flag = rng.choice([0.0, 0.5, 1.0, 1.0, 1.0, 1.0], size=(SIZE, SIZE))
    where = np.zeros((SIZE, SIZE, 3))
    where[..., :2] = rng.uniform(-1.5, 2.5, (SIZE, SIZE, 2))
    return tuple(_stored(values) for values in (where, width, amount, distance, flag))


def _foam_model(tile, where, width, amount, distance, flag):
    """MODEL section 6: f = 1 - smoothstep(0, Foam Width, d), c = Foam Amount clamp((b + f - 1) /
    0.25) times the flag, b the tile read bilinearly with repeat at `where`."""
    t = np.clip(distance / width, 0.0, 1.0)
    f = 1.0 - t * t * (3.0 - 2.0 * t)
    b = bilinear(tile, where[..., :2])[..., 0]
    return np.clip(amount * np.clip((b + f - 1.0) / 0.25, 0.0, 1.0) * flag, 0.0, 1.0)


def _tile(group):
    """The foam tile the group reads (H, W, 3), row 0 at v = 0."""
    image = {node.image for node in group.nodes if node.type == "TEX_IMAGE"}.pop()
    tile = np.empty(image.size[0] * image.size[1] * 4, dtype=np.float32)
    image.pixels.foreach_get(tile)
    return tile.reshape(image.size[1], image.size[0], 4)[..., :3].astype(np.float64)


def _check_foam_coverage(render, made, group):
    where, width, amount, distance, flag = _foam_field(np.random.default_rng(4))
    tile = _tile(group)
    fed = {"Vector": where, "Foam Width": width, "Foam Amount": amount}
    rendered = _evaluate(
        render, made, group, fed, outputs=["Coverage"], attributes={SHORE: distance, FLAG: flag}
    )
    coverage = _foam_model(tile, where, width, amount, distance, flag)
    error = np.abs(rendered["Coverage"] - coverage[..., None]).max(-1)
    partial = (coverage > 0.0) & (coverage < amount * flag)
    print(
        f"foam coverage: worst {error.max():.2e}, mean {error.mean():.2e}; covered {coverage.mean():.3f}, "
        f"{int(partial.sum())} px on the ramp, {int((coverage == 0).sum())} bare"
    )
    assert error.max() < 1e-4
    assert partial.sum() > 300 and (coverage == 0).sum() > 300 and (coverage == 1).sum() > 100


def test_the_foam_coverage_is_the_tile_thresholded_by_the_falloff_from_the_waterline(addon, render):
    """Over tile positions across several repeats (negative too), Foam Width 0.05 to 20 m, shore
    distances from the waterline to past the width (and 1000 m: no shore), Foam Amount 0 to 1 and
    the surroundings' flag 0, 0.5 or 1, each face its own: Coverage is
    clamp(Foam Amount clamp((b + f - 1) / 0.25) flag), f = 1 - smoothstep(0, Foam Width, d), b the
    group's foam tile read bilinearly with repeat; within 1e-4 (measured: 5e-6)."""
    made = _scene()
    _check_foam_coverage(render, made, _built("foam_coverage"))


def _nearest(tile, uv):
    """The tile read at `uv` (..., 2) with repeat, no filtering (Closest): the texel holding it."""
    height, width = tile.shape[:2]
    return tile[
        np.floor(uv[..., 1] * height).astype(np.int64) % height,
        np.floor(uv[..., 0] * width).astype(np.int64) % width,
    ]


def _wake_cover_model(tile, where, foam):
    """nodes/boats/wake_foam_cover.py's rule, written out: g = clamp((f^0.35 - c) / (1 - c)),
    c = 0.005^0.35; b = 0.35 lace + 0.65 middles, the tile read nearest at `where` / 11 m and at
    `where` turned 0.5 rad about z / 37 m; cover = clamp((b + 1.25 g - 1) / 0.25)."""
    cut = 0.005**0.35
    g = np.clip((foam**0.35 - cut) / (1.0 - cut), 0.0, 1.0)
    c, s = math.cos(0.5), math.sin(0.5)
    turned = np.stack([where[..., 0] * c - where[..., 1] * s, where[..., 0] * s + where[..., 1] * c], axis=-1)
    lace = _nearest(tile, where[..., :2] / 11.0)[..., 0]
    middles = 1.0 - _nearest(tile, turned / 37.0)[..., 0]
    return np.clip((0.35 * lace + 0.65 * middles + 1.25 * g - 1.0) / 0.25, 0.0, 1.0)


def test_the_wake_foam_cover_is_the_tile_thresholded_by_the_raised_foam_amount(addon, render):
    """Issue 58 point 4: `Water Wake Foam Cover` alone, over 38 m of the water's own space (faces
    0.6 m apart, where its two reads of the tile, 11 m and 37 m turned 0.5 rad, both vary) and
    foam amounts 0 to 1 (some 0, some 1, some about the 0.005 where the wake stops storing foam):
    Cover is numpy's clamp((b + 1.25 g - 1) / 0.25) with g = clamp((f^0.35 - c) / (1 - c)),
    c = 0.005^0.35, b = 0.35 lace + 0.65 turned bubble middles, both read nearest, within 1e-4
    of numpy's at the pixel's centre or at a point of its 0.01 px filter (a nearest read jumps a
    texel within it)."""
    made = _scene()
    scene, camera = made
    group = _built("boats.wake_foam_cover")
    rng = np.random.default_rng(8)
    foam = rng.uniform(0.0, 1.0, (SIZE, SIZE)) ** 2
    pick = rng.uniform(size=(SIZE, SIZE))
    foam[pick < 0.1] = 0.0
    foam[pick > 0.9] = 1.0
    foam[(pick > 0.45) & (pick < 0.5)] = 0.005 * rng.uniform(
        0.5, 2.0, int(((pick > 0.45) & (pick < 0.5)).sum())
    )
    foam = _stored(foam)
    spacing = 0.6  # metres of the water's own space a face
    scale = np.linalg.norm(_frame(scene, camera)[0, 1] - _frame(scene, camera)[0, 0]) / spacing
    attribute = harness.addon("nodes.boats.wake_parts").FOAM_ATTRIBUTE
    rendered = _evaluate(
        render, made, group, {}, outputs=["Cover"], attributes={attribute: foam}, scale=scale
    )
    cover = rendered["Cover"][..., 0]
    models = [
        _wake_cover_model(_tile(group), _to_world(camera, _frame(scene, camera, du, dv)) / scale, foam)
        for du in (-0.005, 0.0, 0.005)
        for dv in (-0.005, 0.0, 0.005)
    ]
    centre = models[4]
    low, high = np.min(models, axis=0), np.max(models, axis=0)
    error = np.maximum(np.maximum(low - cover, cover - high), 0.0)
    at_centre = np.abs(cover - centre) < 1e-4
    print(
        f"wake foam cover: worst {error.max():.2e} off numpy's within the filter; {at_centre.mean():.3f} "
        f"of pixels at the centre's; covered {centre.mean():.3f}, {int(((centre > 0) & (centre < 1)).sum())} "
        f"px on the ramp, {int((centre == 0).sum())} bare, {int((centre == 1).sum())} whole"
    )
    assert error.max() < 1e-4 and at_centre.mean() > 0.9
    assert (
        ((centre > 0) & (centre < 1)).sum() > 200 and (centre == 0).sum() > 300 and (centre == 1).sum() > 300
    )
    # The amount's floor: at 0.005 and below the wake's foam covers nothing.
    assert cover[foam <= 0.005].max() < 1e-4
