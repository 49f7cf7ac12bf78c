"""The ocean shading reflects whatever world the scene has, in EEVEE and Cycles.

Every new ocean material has the renderer reflect the world (the shade's "+ Traced Sky" variant;
test_live_sky.py switches and edits the world after the water is added); at Traced Sky 0 the
seeds' look-up of the sky is held to the seeds' model by test_ocean_render.py. Before, a procedural
world was one flat colour and the whole sea one tone.
"""

import bpy
import numpy as np
import pytest
from reference_models import flat_glint, seeds_ocean_fresnel

import harness

pytestmark = pytest.mark.render

HORIZON = np.array((0.9, 0.55, 0.3))  # warm at the horizon ...
ZENITH = np.array((0.1, 0.25, 0.9))  # ... deep blue straight up
DEEP = np.array((0.0, 0.2, 0.4))  # the ocean shading's Deep Color


def _new_world(scene, name):
    """A new world with an empty node tree, the scene's: (world, its nodes, its links)."""
    world = bpy.data.worlds.new(name)
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    world.node_tree.nodes.clear()
    scene.world = world
    return world, world.node_tree.nodes, world.node_tree.links


def _gradient_world(scene):
    """A procedural sky: HORIZON at the horizon to ZENITH straight up, linear in the direction's
    height z (and HORIZON below the horizon): no image, no single colour."""
    world, nodes, links = _new_world(scene, "Gradient Sky")
    coords = nodes.new("ShaderNodeTexCoord")
    split = nodes.new("ShaderNodeSeparateXYZ")
    ramp = nodes.new("ShaderNodeMix")
    ramp.data_type = "RGBA"
    ramp.clamp_factor = True
    ramp.inputs["A"].default_value = (*HORIZON, 1.0)
    ramp.inputs["B"].default_value = (*ZENITH, 1.0)
    background = nodes.new("ShaderNodeBackground")
    output = nodes.new("ShaderNodeOutputWorld")
    links.new(coords.outputs["Generated"], split.inputs["Vector"])
    links.new(split.outputs["Z"], ramp.inputs["Factor"])
    links.new(ramp.outputs["Result"], background.inputs["Color"])
    links.new(background.outputs["Background"], output.inputs["Surface"])
    return world


def _sky_texture_world(scene):
    """Blender's own Sky Texture (its physical model: Nishita, or its successor from 5.0), a sun
    18 degrees up."""
    world, nodes, links = _new_world(scene, "Sky Texture")
    sky = nodes.new("ShaderNodeTexSky")
    kinds = [item.identifier for item in sky.bl_rna.properties["sky_type"].enum_items]
    sky.sky_type = next(k for k in ("NISHITA", "MULTIPLE_SCATTERING", "SINGLE_SCATTERING") if k in kinds)
    sky.sun_elevation = np.radians(18.0)
    sky.sun_rotation = np.radians(200.0)
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = 0.3
    output = nodes.new("ShaderNodeOutputWorld")
    links.new(sky.outputs["Color"], background.inputs["Color"])
    links.new(background.outputs["Background"], output.inputs["Surface"])
    return world


def _flat_sea(scene):
    """A 400 m plane with the ocean shading, its bump off: the shading normal is +Z."""
    added = harness.addon("api").add_water(scene, shading="ocean", size=400.0, see_surroundings=False)
    normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(added.material)
    normal.inputs["Bump Strength"].default_value = 0.0
    return added, shade


def _on_sea(origin, directions, reach=190.0):
    """Pixels whose ray meets the 400 m sea within `reach` of its centre on both axes."""
    hits, ok = harness.hit_plane_z(origin, directions)
    return ok & (np.abs(hits[..., :2]) < reach).all(axis=-1)


def _expected(scene, camera):
    """numpy: deep F + sky(reflect(d)) (1 - F), F = dot(-d, n) / 2 + 0.5, on the flat sea."""
    origin, directions = harness.pixel_rays(scene, camera)
    ok = _on_sea(origin, directions)
    f = seeds_ocean_fresnel(-directions)[..., None]
    reflected_z = np.clip(-directions[..., 2], 0.0, 1.0)[..., None]
    sky = HORIZON + (ZENITH - HORIZON) * reflected_z
    return DEEP * f + sky * (1 - f), ok


@pytest.mark.lts
@pytest.mark.parametrize("engine", ["eevee", "CYCLES"])
def test_a_procedural_sky_is_reflected_as_it_is(addon, eevee, render, engine):
    scene = harness.clean_scene(
        engine=eevee if engine == "eevee" else "CYCLES", width=48, height=32, samples=4
    )
    _gradient_world(scene)
    added, shade = _flat_sea(scene)
    assert shade.node_tree.name == "Water Ocean Shade + Traced Sky"
    camera = harness.add_camera(scene, (0.0, -20.0, 6.0), (0.0, 40.0, 0.0), lens=30.0)
    scene.camera = camera
    expected, on_sea = _expected(scene, camera)
    pixels = render(scene, f"gradient-{engine}", exr=True)[..., :3]
    error = np.abs(pixels - expected)[on_sea]
    # The reflected sky runs from warm near the horizon to blue nearer the camera; one flat tone
    # (the world's old stand-in colour) misses by 0.2-0.5.
    spread = expected[on_sea].max(axis=0) - expected[on_sea].min(axis=0)
    assert spread.max() > 0.2, spread
    print(f"{engine}: mean error {error.mean():.4f}, 95th percentile {np.percentile(error, 95):.4f}")
    assert error.mean() < 0.015 and np.percentile(error, 95) < 0.03


def _wavy_sea_under_the_sky_texture(engine_id):
    scene = harness.clean_scene(engine=engine_id, width=64, height=36, samples=4)
    _sky_texture_world(scene)
    added = harness.addon("api").add_water(scene, preset="ocean", size=200.0, see_surroundings=False)
    camera = harness.add_camera(scene, (0.0, -30.0, 8.0), (0.0, 30.0, 0.0), lens=30.0)
    scene.camera = camera
    origin, directions = harness.pixel_rays(scene, camera)
    hits, ok = harness.hit_plane_z(origin, directions)
    ok &= (np.abs(hits[..., :2]) < 90.0).all(axis=-1)
    return scene, added, ok


def test_the_sky_texture_shows_every_wave_in_eevee_and_cycles(addon, eevee, render):
    seen = {}
    for engine in (eevee, "CYCLES"):
        scene, added, on_sea = _wavy_sea_under_the_sky_texture(engine)
        _normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(added.material)
        assert shade.inputs["Traced Sky"].default_value == 1.0
        pixels = render(scene, f"sky-texture-{engine}", exr=True)[..., :3]
        luminance = pixels @ np.array((0.2126, 0.7152, 0.0722))
        sea = luminance[on_sea]
        # Waves: neighbouring pixels of the sea differ (one flat tone would give 0).
        across = np.abs(np.diff(luminance, axis=1))[on_sea[:, 1:] & on_sea[:, :-1]]
        seen[engine] = (sea.mean(), np.median(across) / sea.mean())
        print(f"{engine}: sea mean {sea.mean():.3f}, median step between neighbours {seen[engine][1]:.3f}")
        assert seen[engine][1] > 0.02, "the waves show"
    # The two engines agree on how bright the sea is.
    means = [mean for mean, _step in seen.values()]
    assert max(means) / min(means) < 1.3, seen


def test_the_ocean_debug_views_show_f_the_normal_and_the_sun_glint(addon, eevee, render):
    scene = harness.clean_scene(engine=eevee, width=40, height=24, samples=1)
    _gradient_world(scene)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.rotation_euler = (np.radians(70.0), 0.0, np.radians(150.0))  # low, behind the view
    scene.collection.objects.link(sun)
    _added, shade = _flat_sea(scene)
    shade.inputs["Glint Power"].default_value = 8.0
    camera = harness.add_camera(scene, (0.0, -20.0, 6.0), (0.0, 40.0, 0.0), lens=30.0)
    scene.camera = camera
    origin, d = harness.pixel_rays(scene, camera)
    on_sea = _on_sea(origin, d)
    light = np.array(sun.matrix_world.to_3x3().col[2]) * -1.0  # the way sunlight travels
    expected = {
        3: np.repeat(seeds_ocean_fresnel(-d)[..., None], 3, axis=-1),
        4: np.broadcast_to((0.5, 0.5, 1.0), d.shape),
        5: np.repeat(flat_glint(-d, light, 8.0)[..., None], 3, axis=-1),  # off the flat sea, n = +Z
        6: np.zeros(d.shape),  # no surroundings: no bed seen through
        7: np.zeros(d.shape),
        8: np.ones(d.shape),  # the caustic factor: 1, nothing changed
    }
    final = render(scene, "view-0", exr=True)[..., :3]
    for number, want in expected.items():
        shade.inputs["Debug View"].default_value = number
        got = render(scene, f"view-{number}", exr=True)[..., :3]
        error = np.abs(got - want)[on_sea]
        assert error.max() < 0.01, (number, error.max())
    assert np.ptp(expected[5][on_sea]) > 0.1, "the glint varies over the view"
    shade.inputs["Debug View"].default_value = 1  # not an ocean view: the final picture
    assert np.abs(render(scene, "view-1", exr=True)[..., :3] - final).max() < 1e-4


@pytest.mark.lts
def test_a_traced_sky_sea_with_a_float_renders_the_same_without_the_add_on(
    addon, eevee, render, tmp_path, addon_disabled_afterwards
):
    """The traced sky with the rest: an open sea under the gradient sky, its surroundings (a
    bed), a buoy floating on it; saved, reopened without the add-on and auto-run off, the same."""
    scene = harness.clean_scene(engine="CYCLES", width=32, height=20, samples=2)
    _gradient_world(scene)
    harness.add_cube(scene, (0.0, 10.0, -3.0), size=6.0, name="Bed")
    added = harness.addon("api").add_water(scene, preset="open_sea", sea_wind_speed=6.0)
    _normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(added.material)
    assert shade.node_tree.name == "Water Ocean Shade + Traced Sky"
    buoy = harness.add_cube(scene, (1.0, 6.0, 0.0), size=0.8, name="Buoy")
    harness.addon("api").float_on_water(buoy, added.object)
    camera = harness.add_camera(scene, (0.0, -6.0, 4.0), (0.0, 8.0, 0.0), lens=30.0)
    camera.data.clip_end = 20000.0
    scene.camera = camera
    scene.frame_set(12)
    path = tmp_path / "traced.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    before = render(scene, "with-addon", exr=True)[..., :3]
    scene = harness.reopen_without_add_on(path)
    scene.frame_set(1)
    scene.frame_set(12)
    after = render(scene, "without-addon", exr=True)[..., :3]
    assert np.abs(after - before).mean() < 0.01, np.abs(after - before).mean()
