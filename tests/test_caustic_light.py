"""Caustics on everything under the water (issue 40 point 5), in EEVEE and Cycles.

A camera 0.8 m under the default lake (caustics 1, wind not along +Y) looks at a white cube
standing on a white bed 3 m down, lit by a sun 55 degrees high from an azimuth of 40 degrees and
nothing else (a black world: the sky's light is not patterned in EEVEE). The water's caustic
light (`nodes/under/caustic_light.py`) patterns the sunlight on the bed and on the cube's side; each
render with it is divided by one with it hidden, per pixel, and compared with numpy's model over
the whole lit patch: the light let through where each point's shadow ray crosses the surface is
`min((1 + k (c - 1)) / (1 + k), 1)` per channel, c the caustic tile as `caustics_map` traces it
(refraction through the bump, mean 1), k from `Caustics`, the depth there and the water's
absorption along the sunlight's way down. 128 x 96, EEVEE 4 samples with its shadow maps at half
resolution (`shadow_resolution_scale` 0.5), Cycles 16. At full resolution software EEVEE spends
40 s a sample drawing the sheet into the sun's shadow maps (7 s at half, as without the sheet);
the light let through reads 0.748 / 0.741 on the bed / the cube's side at half against 0.72 / 0.76
at full, the pattern's spread 0.155 against numpy's 0.195 (`tools/test tests/test_caustic_light.py
-s`).
"""

import math

import bpy
import numpy as np
import pytest
import reference_models
from mathutils import Vector
from test_caustics import _box

import harness

BED = -3.0
CUBE = ((-0.75, 0.25, BED), (0.75, 1.75, -1.5))
SUN_ELEVATION, SUN_AZIMUTH = 55.0, 40.0
CAMERA = ((1.5, -3.0, -0.8), (0.0, 1.0, -2.3))


def _build(engine):
    scene = harness.clean_scene(engine=engine, width=128, height=96, samples=16 if engine == "CYCLES" else 4)
    # EEVEE's shadow maps at half their resolution: the sheet the sun's shadow rays cross costs
    # software EEVEE 40 s a sample at full (7 s at half; 7 s without the sheet).
    scene.eevee.shadow_resolution_scale = 0.5
    harness.set_world_color(scene, (0.0, 0.0, 0.0), 0.0)
    white = harness.lit_material("White", (0.8, 0.8, 0.8), roughness=1.0)
    _box(scene, "Bed", (-8.0, -8.0, BED - 0.1), (8.0, 8.0, BED), white)
    _box(scene, "Cube", *CUBE, white)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (math.radians(90.0 - SUN_ELEVATION), 0.0, math.radians(SUN_AZIMUTH))
    scene.collection.objects.link(sun)
    added = harness.addon("api").add_water(scene, caustics=1.0, wind_direction=(0.6, 0.8), size=40.0)
    camera = harness.add_camera(scene, *CAMERA, lens=28.0)
    return scene, added, camera


@pytest.fixture(scope="module", params=["eevee", "CYCLES"])
def lit(request, addon, tmp_path_factory):
    engine = harness.addon("engine").eevee_engine_id() if request.param == "eevee" else "CYCLES"
    scene, added, camera = _build(engine)
    underwater = harness.addon("water.underwater")
    light = underwater.find(added.object, underwater.LIGHT_ROLE)
    underwater.find(added.object).hide_render = True  # the fog alone would blur the ratio
    out = tmp_path_factory.mktemp(f"caustic_light_{request.param}")
    renders = {}
    for on in (True, False):
        light.hide_render = not on
        renders[on] = harness.render(scene, out / f"{int(on)}.exr", exr=True)[..., :3]
    light.hide_render = False
    return {
        "engine": engine,
        "scene": scene,
        "added": added,
        "camera": camera,
        "light": light,
        "renders": renders,
    }


def _k(added, depth):
    """The pattern's contrast per channel at the surface over `depth` metres of water."""
    node = added.material.node_tree.nodes["Water Surface"]
    caustics = node.inputs["Caustics"].default_value
    absorption = np.array(node.inputs["Absorption"].default_value[:3])
    cos_s = reference_models.refracted_cos(math.sin(math.radians(SUN_ELEVATION)))
    depth = np.asarray(depth)[..., None]
    fade = np.exp(-depth / reference_models.CAUSTICS_FADE_DEPTH)
    return caustics * fade * np.exp(-absorption * depth / cos_s)


def _model(k):
    """numpy's light let through, per channel, for contrasts `k` (N, 3): each point's mean over
    the tile, and the spread over the tile at the patch's mean contrast."""
    c = harness.addon("nodes.caustics_map").caustics_map(256).ravel()[::7]
    mean = np.empty_like(k)
    for channel in range(3):
        levels = np.unique(np.round(k[:, channel], 3))
        table = {v: np.minimum((1.0 + v * (c - 1.0)) / (1.0 + v), 1.0).mean() for v in levels}
        mean[:, channel] = [table[v] for v in np.round(k[:, channel], 3)]
    k_mid = k.mean(axis=0)
    spread = np.array([np.minimum((1.0 + v * (c - 1.0)) / (1.0 + v), 1.0).std() for v in k_mid])
    return mean, spread


def _patch(scene, camera):
    """Bed and cube-side pixels in the sun (not in the cube's shadow), and where each one's
    shadow ray crosses the surface: its depth of water there (the cube's top or the bed)."""
    origin, directions = harness.pixel_rays(scene, camera)
    bed, ok = harness.hit_plane_z(origin, directions, BED)
    (x0, y0, z0), (x1, y1, z1) = CUBE
    # The cube's face towards the camera and the sun (y = y0), where rays meet it first.
    t_face = (y0 - origin[1]) / directions[..., 1]
    face = origin + t_face[..., None] * directions
    on_face = (t_face > 0) & (face[..., 0] > x0 + 0.1) & (face[..., 0] < x1 - 0.1)
    on_face &= (face[..., 2] > z0 + 0.1) & (face[..., 2] < z1 - 0.1)
    t_bed = (BED - origin[2]) / directions[..., 2]
    on_bed = ok & ~on_face & (t_bed < t_face + 1e9)
    # Bed points the cube hides from the camera, or from the sun, are left out.
    hidden = _through_box(origin, bed - origin, CUBE)
    sun = reference_models.to_sun(SUN_ELEVATION, SUN_AZIMUTH)
    shadowed = _through_box(bed, np.broadcast_to(sun * 10.0, bed.shape), CUBE)
    on_bed &= ~hidden & ~shadowed & (np.abs(bed[..., 0]) < 7.0) & (np.abs(bed[..., 1]) < 7.0)
    points = np.where(on_face[..., None], face, bed)
    crossing = points + ((-0.01 - points[..., 2]) / sun[2])[..., None] * sun
    over_cube = (
        (crossing[..., 0] > x0) & (crossing[..., 0] < x1) & (crossing[..., 1] > y0) & (crossing[..., 1] < y1)
    )
    depth = np.where(over_cube, -z1, -BED)
    return on_bed, on_face, depth


def _through_box(start, along, box):
    """Whether the segments start -> start + along pass through the box (slab test)."""
    low, high = (np.array(v) for v in box)
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = (low - start) / along
        t1 = (high - start) / along
    near = np.nanmax(np.minimum(t0, t1), axis=-1)
    far = np.nanmin(np.maximum(t0, t1), axis=-1)
    return (near < far) & (far > 1e-3) & (near < 1.0 - 1e-3)


@pytest.mark.render
def test_the_sunlight_under_the_water_carries_the_caustic_pattern(lit):
    """The bed and the cube's side: the light let through matches numpy's mean per channel and
    shows its pattern (at least a fifth of the model's spread, which the pixels average down),
    where without the light it would be 1 and flat. Cycles within 0.04 (measured 0.570 and 0.572
    against 0.563); EEVEE within 0.2: it lets through more of a fine pattern (0.75 against 0.56;
    a uniform sheet's light it renders linearly, within 0.03), which the README states."""
    on, off = lit["renders"][True], lit["renders"][False]
    on_bed, on_face, depth = _patch(lit["scene"], lit["camera"])
    lit_enough = off.mean(axis=-1) > 0.05
    for name, mask in (("bed", on_bed & lit_enough), ("cube's side", on_face & lit_enough)):
        assert mask.sum() > 200, f"{name}: {mask.sum()} pixels"
        ratio = on[mask] / off[mask]
        expected, spread = _model(_k(lit["added"], depth[mask]))
        got, want = ratio.mean(axis=0), expected.mean(axis=0)
        print(
            f"{name}: {mask.sum()} px, let through {np.round(got, 3)} (numpy {np.round(want, 3)}), "
            f"spread {np.round(ratio.std(axis=0), 3)} (numpy, unblurred {np.round(spread, 3)})"
        )
        assert np.all(np.abs(got - want) < (0.04 if lit["engine"] == "CYCLES" else 0.2)), name
        assert np.all(ratio.std(axis=0) > spread / 5.0), name


@pytest.mark.render
def test_the_light_is_made_only_while_the_camera_is_under(lit):
    """Above the water the water shader already patterns what it shows below: the caustic light's
    sheet is not made, so nothing is patterned twice (and a camera above pays nothing)."""
    camera, light = lit["camera"], lit["light"]
    depsgraph = bpy.context.evaluated_depsgraph_get()
    assert len(light.evaluated_get(depsgraph).data.polygons) > 1000
    saved = camera.location.copy()
    try:
        camera.location.z = 0.3
        depsgraph = bpy.context.evaluated_depsgraph_get()
        assert len(light.evaluated_get(depsgraph).data.polygons) == 0
    finally:
        camera.location = saved


def test_the_light_comes_and_goes_with_the_caustics(scene):
    """A water without caustics has no caustic light (nor its tile packed in the file); switching
    its caustics on gives it one, off takes it away with its material, Underwater off too."""
    api = harness.addon("api")
    underwater = harness.addon("water.underwater")
    water = api.add_water(scene).object
    assert underwater.find(water, underwater.LIGHT_ROLE) is None
    assert not [i for i in bpy.data.images if "Caustics" in i.name]
    api.switch_part(water, "caustics", True)
    light = underwater.find(water, underwater.LIGHT_ROLE)
    assert light is not None and light.parent == water and not light.visible_camera and light.visible_shadow
    material_name = f"{water.name} Caustic Light"
    assert material_name in bpy.data.materials
    assert harness.addon("water.kind").water_material(light) is None, "not a water itself"
    api.switch_part(water, "caustics", False)
    assert underwater.find(water, underwater.LIGHT_ROLE) is None
    assert material_name not in bpy.data.materials
    api.write_values(water, {"caustics": 0.5})
    assert underwater.find(water, underwater.LIGHT_ROLE) is not None
    api.set_underwater(water, False, scene)
    assert underwater.find(water, underwater.LIGHT_ROLE) is None
    assert material_name not in bpy.data.materials


@pytest.mark.render
def test_a_saved_file_renders_its_caustic_light_without_the_add_on(
    addon, eevee, render, tmp_path, addon_disabled_afterwards
):
    """Farm-safe: the sheet, its material and its drivers (the water's values, the clock) are
    saved in the file. Reopened without the add-on and with scripts off, the shot under the water
    (its light shafts on too) renders the same, the pattern still moves from frame to frame, and
    the shafts' sun follows the sun when it turns."""
    import addon_utils

    scene, added, _camera = _build(eevee)
    harness.addon("api").set_light_shafts(added.object, 1.0)
    scene.render.resolution_x, scene.render.resolution_y = 96, 72
    scene.eevee.taa_render_samples = 1  # the same settings both times: any difference is the add-on's
    scene.frame_set(10)
    path = tmp_path / "caustic_light.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    with_addon = render(scene, "with-addon", exr=True)[..., :3]

    addon_utils.disable(harness.ADDON_MODULE, default_set=True)
    bpy.context.preferences.filepaths.use_scripts_auto_execute = False
    bpy.ops.wm.open_mainfile(filepath=str(path), load_ui=False, use_scripts=False)
    scene = bpy.context.scene
    scene.frame_set(1)
    scene.frame_set(10)
    without = render(scene, "without-addon", exr=True)[..., :3]
    difference = np.abs(without - with_addon)
    print(f"mean difference {difference.mean():.5f}")
    assert difference.mean() < 0.005
    scene.frame_set(40)
    later = render(scene, "later", exr=True)[..., :3]
    moved = np.abs(later - without).mean()
    print(f"frames 10 and 40 apart by {moved:.4f}")
    assert moved > 5 * max(difference.mean(), 0.002), "the pattern moves with the clock"

    sun = bpy.data.objects["Sun"]
    sun.rotation_euler.z += math.radians(60.0)
    scene.frame_set(41)
    fog = next(m for m in bpy.data.materials if m.name.endswith(" Underwater"))
    water = next(m for m in bpy.data.materials if m.node_tree and "Water Surface" in m.node_tree.nodes)
    fog_sun = fog.node_tree.nodes["Water Underwater Fog"].inputs["Sun Direction"].default_value
    water_sun = water.node_tree.nodes["Water Surface"].inputs["Sun Direction"].default_value
    expected = sun.matrix_world.to_3x3() @ Vector((0.0, 0.0, -1.0))
    assert tuple(fog_sun) == pytest.approx(tuple(water_sun), abs=1e-5)
    assert tuple(fog_sun) == pytest.approx(tuple(expected), abs=1e-3), "the shafts' sun turned with the sun"
