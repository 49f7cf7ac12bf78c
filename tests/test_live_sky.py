"""Issue 38 point 1: whatever world the scene has now is what the water reflects, with nothing to press.

Each water (the lake, the seeds' ocean, the open sea) is added under a plain red world; then, as an
artist lighting a shot does, the scene is given another world (an HDRI-like image), that world's
image is swapped for another, and the scene is given a plain world whose colour is then edited.
After each change the render is compared with the same water added afresh under the new sky, in
EEVEE and Cycles. Before, the ocean shadings copied the world's image or colour when they were
made and kept the red sky's pixels after every change.

The swapped image is also held to numpy: a flat, calm seeds' ocean reflects the image looked up
in each pixel's mirrored direction (Blender's equirectangular mapping), with the seeds' Fresnel.
"""

import bpy
import numpy as np
import pytest
from reference_models import equirect_uv, seeds_ocean_fresnel

import harness

pytestmark = pytest.mark.render

RED = (0.8, 0.1, 0.05)
EDITED = (0.15, 0.35, 0.9)
IMAGE_SIZE = (64, 32)
DEEP = np.array((0.0, 0.2, 0.4))  # the ocean shading's Deep Color


def _sky_pixels(tint):
    """An equirectangular sky (H, W, 3), row 0 at the bottom (v = 0): `tint` at the horizon to
    white-blue straight up, brighter towards u = 0.25, so a swapped image shows everywhere."""
    width, height = IMAGE_SIZE
    u, v = np.meshgrid((np.arange(width) + 0.5) / width, (np.arange(height) + 0.5) / height)
    up = np.clip(2.0 * v - 1.0, 0.0, 1.0)[..., None]
    side = (0.75 + 0.25 * np.cos(2 * np.pi * (u - 0.25)))[..., None]
    return (np.array(tint) * (1.0 - up) + np.array((0.6, 0.75, 1.0)) * up) * side


def _image(name, tint):
    """A packed float image of `_sky_pixels(tint)`."""
    pixels = np.ones((IMAGE_SIZE[1], IMAGE_SIZE[0], 4), dtype=np.float32)
    pixels[..., :3] = _sky_pixels(tint)
    image = bpy.data.images.new(name, *IMAGE_SIZE, float_buffer=True)
    image.pixels.foreach_set(pixels.ravel())
    image.use_half_precision = False
    image.pack()
    return image


def _world(scene, name, image=None, colour=None):
    """A new world, the scene's: an Environment Texture of `image`, or a Background of `colour`."""
    world = bpy.data.worlds.new(name)
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    background = nodes.new("ShaderNodeBackground")
    output = nodes.new("ShaderNodeOutputWorld")
    links.new(background.outputs["Background"], output.inputs["Surface"])
    if image is not None:
        environment = nodes.new("ShaderNodeTexEnvironment")
        environment.image = image
        links.new(environment.outputs["Color"], background.inputs["Color"])
    else:
        background.inputs["Color"].default_value = (*colour, 1.0)
    scene.world = world
    return world


def _warm_image_world(scene):
    return _world(scene, "Warm HDRI", image=_image("Warm", (1.0, 0.6, 0.25)))


def _green_image_world(scene):
    return _world(scene, "Green HDRI", image=_image("Green", (0.2, 0.9, 0.3)))


def _edited_world(scene):
    return _world(scene, "Plain", colour=EDITED)


KINDS = {
    "lake": {"preset": "lake", "size": 60.0},
    "ocean": {"preset": "ocean", "size": 60.0},
    "open_sea": {"preset": "open_sea", "sea_wind_speed": 6.0, "wind_direction": (0.8, 0.6)},
}


def _water_under(engine, kind, make_world):
    """A small scene whose world `make_world` makes first, then the water `kind`, seen from 6 m up."""
    scene = harness.clean_scene(engine=engine, width=40, height=24, samples=1)
    if engine == "CYCLES":
        scene.cycles.samples = 4
        scene.cycles.device = "CPU"
    make_world(scene)
    added = harness.addon("api").add_water(scene, see_surroundings=False, **KINDS[kind])
    camera = harness.add_camera(scene, (0.0, -20.0, 6.0), (3.0, 20.0, 0.0), lens=24.0)
    camera.data.clip_end = 5000.0
    return scene, added


def _changes():
    """(what changed, the change made to a scene, the world a fresh water is added under)."""

    def swap_image(scene):
        environment = next(n for n in scene.world.node_tree.nodes if n.type == "TEX_ENVIRONMENT")
        environment.image = _image("Green", (0.2, 0.9, 0.3))

    def edit_colour(scene):
        _world(scene, "Plain", colour=RED)
        scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (*EDITED, 1.0)

    return (
        ("another world, an image", _warm_image_world, _warm_image_world),
        ("the image swapped", swap_image, _green_image_world),
        ("another plain world, its colour edited", edit_colour, _edited_world),
    )


def _red(scene):
    _world(scene, "Red", colour=RED)


@pytest.mark.parametrize("engine", ["eevee", "CYCLES"])
@pytest.mark.parametrize("kind", list(KINDS))
def test_the_water_reflects_the_world_the_scene_has_now(addon, eevee, render, kind, engine):
    engine = eevee if engine == "eevee" else engine
    changed, _added = _water_under(engine, kind, _red)
    red = render(changed, f"{kind}-red", exr=True)[..., :3]
    seen = []
    for what, change, _new_world in _changes():  # one scene, changed after its water was added
        change(changed)
        seen.append(render(changed, f"{kind}-{what}", exr=True)[..., :3])
    for (what, _change, new_world), after in zip(_changes(), seen, strict=True):
        fresh, _added = _water_under(engine, kind, new_world)
        want = render(fresh, f"{kind}-{what}-fresh", exr=True)[..., :3]
        lower = slice(want.shape[0] // 2, None)  # the water (the camera looks down at it)
        error = np.abs(after - want)[lower]
        moved = np.abs(red - want)[lower]
        print(
            f"{kind} {engine}, {what}: mean difference from a water added under it {error.mean():.4f}, "
            f"95th percentile {np.percentile(error, 95):.4f} (from the red sky's {moved.mean():.4f})"
        )
        assert moved.mean() > 0.05, "the new sky differs from the red one on the water"
        assert error.mean() < 0.1 * moved.mean() and np.percentile(error, 95) < 0.03


@pytest.mark.lts
@pytest.mark.parametrize("engine", ["eevee", "CYCLES"])
def test_a_swapped_image_is_reflected_as_numpy_looks_it_up(addon, eevee, render, engine):
    """A flat seeds' ocean (bump off) under the warm image, swapped for the green one: each pixel
    is Deep F + sky(reflect(d)) (1 - F), F = dot(-d, n) / 2 + 0.5, the sky looked up in the
    green image."""
    engine = eevee if engine == "eevee" else engine
    scene = harness.clean_scene(engine=engine, width=48, height=32, samples=1)
    if engine == "CYCLES":
        scene.cycles.samples = 8
        scene.cycles.device = "CPU"
    _warm_image_world(scene)
    added = harness.addon("api").add_water(scene, shading="ocean", size=400.0, see_surroundings=False)
    normal, _shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(added.material)
    normal.inputs["Bump Strength"].default_value = 0.0
    camera = harness.add_camera(scene, (0.0, -20.0, 6.0), (10.0, 40.0, 0.0), lens=30.0)
    environment = next(n for n in scene.world.node_tree.nodes if n.type == "TEX_ENVIRONMENT")
    environment.image = _image("Green", (0.2, 0.9, 0.3))
    pixels = render(scene, f"swapped-{engine}", exr=True)[..., :3]
    origin, d = harness.pixel_rays(scene, camera)
    hits, on_sea = harness.hit_plane_z(origin, d)
    on_sea &= (np.abs(hits[..., :2]) < 190.0).all(axis=-1)
    r = d * np.array((1.0, 1.0, -1.0))  # mirrored by the flat sea
    u, v = equirect_uv(r)
    sky = _sky_pixels((0.2, 0.9, 0.3))
    rows = np.clip((v * IMAGE_SIZE[1]).astype(int), 0, IMAGE_SIZE[1] - 1)
    columns = np.mod((u * IMAGE_SIZE[0]).astype(int), IMAGE_SIZE[0])
    f = seeds_ocean_fresnel(-d)[..., None]
    want = DEEP * f + sky[rows, columns] * (1 - f)
    warm = DEEP * f + _sky_pixels((1.0, 0.6, 0.25))[rows, columns] * (1 - f)
    error = np.abs(pixels - want)[on_sea]
    print(
        f"{engine}: mean error {error.mean():.4f}, 95th percentile {np.percentile(error, 95):.4f} "
        f"(the warm image's {np.abs(pixels - warm)[on_sea].mean():.4f})"
    )
    assert np.abs(want - warm)[on_sea].mean() > 0.05
    assert error.mean() < 0.02 and np.percentile(error, 95) < 0.05
