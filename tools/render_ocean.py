"""Renders the ocean preset under a generated sky image: out/ocean.png.

The sky is an equirectangular image made here with numpy (a gradient, a sun,
soft cloud bands) and packed as the world's Environment Texture, so the ocean
shading looks it up in the reflected direction, as the seeds sample their sky
cube, and glints where it reflects the sun. Run with `tools/demo ocean` (`tools/demo --docs
ocean`: copied to docs/ too).
"""

import sys
import tempfile
import time

import numpy as np
from demo_output import OUT, publish

import harness

SIZE = (640, 360)
SUN_DIRECTION = np.array((0.0, 0.96, 0.28))  # towards the sun: ahead of the camera, low


def sky_pixels(width=1024, height=512):
    """RGBA float pixels of an equirectangular sky, bottom row first (Blender's order)."""
    v = (np.arange(height) + 0.5) / height  # 0 at the bottom
    u = (np.arange(width) + 0.5) / width
    latitude = (v - 0.5) * np.pi
    longitude = (0.5 - u) * 2 * np.pi  # Blender: u = 0.5 - atan2(y, x) / 2 pi
    lon, lat = np.meshgrid(longitude, latitude)
    # Blender's equirectangular mapping: direction = (cos lat cos lon, cos lat sin lon, sin lat).
    direction = np.stack([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)], axis=-1)
    up = np.clip(direction[..., 2], -1, 1)
    zenith, horizon, ground = (
        np.array((0.08, 0.22, 0.6)),
        np.array((0.65, 0.75, 0.88)),
        np.array((0.12, 0.3, 0.45)),
    )
    blend = np.clip(up, 0, 1)[..., None] ** 0.45
    color = horizon * (1 - blend) + zenith * blend
    color = np.where(up[..., None] < 0, ground, color)
    bands = 0.5 + 0.5 * np.sin(lon * 7 + np.sin(lat * 23) * 2) * np.sin(lat * 31 + lon * 3)
    clouds = np.clip((bands - 0.55) * 3, 0, 1) * np.clip(up * 6, 0, 1)
    color = color * (1 - 0.6 * clouds[..., None]) + 0.95 * 0.6 * clouds[..., None]
    sun = SUN_DIRECTION / np.linalg.norm(SUN_DIRECTION)
    angle = np.arccos(np.clip(direction @ sun, -1, 1))
    color += (20.0 * (angle < 0.02) + 1.5 * np.exp(-angle / 0.08))[..., None] * np.array((1.0, 0.9, 0.7))
    rgba = np.concatenate([color, np.ones((*color.shape[:2], 1))], axis=-1)
    return rgba.astype(np.float32)


def sky_world(bpy, scene):
    """The world: the generated sky, packed, as an Environment Texture."""
    pixels = sky_pixels()
    image = bpy.data.images.new("Ocean Sky", pixels.shape[1], pixels.shape[0], float_buffer=True)
    image.pixels.foreach_set(pixels.ravel())
    image.pack()
    world = bpy.data.worlds.new("Ocean Sky")
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    nodes = world.node_tree.nodes
    nodes.clear()
    environment = nodes.new("ShaderNodeTexEnvironment")
    environment.image = image
    background = nodes.new("ShaderNodeBackground")
    output = nodes.new("ShaderNodeOutputWorld")
    world.node_tree.links.new(environment.outputs["Color"], background.inputs["Color"])
    world.node_tree.links.new(background.outputs["Background"], output.inputs["Surface"])
    scene.world = world


def main():
    start = time.monotonic()
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(width=SIZE[0], height=SIZE[1], samples=8)
    sky_world(bpy, scene)  # first: the ocean material looks the world's image up when it is made
    bpy.ops.object.water_add(preset="ocean", size=1200, resolution=1024)
    harness.add_camera(scene, (0, -30, 6), (0, 40, 0), lens=28)
    scene.frame_set(48)
    print(f"[1/1] ocean, {SIZE[0]} x {SIZE[1]}, Blender {bpy.app.version_string} ...", flush=True)
    OUT.mkdir(parents=True, exist_ok=True)
    harness.render(scene, OUT / "ocean.png")
    publish(OUT / "ocean.png", note=f"in {time.monotonic() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
