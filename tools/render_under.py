"""Renders the view under the water (out/underwater.png): on the left a diver 4 m under the open
sea (4 m/s wind) looking up at a floating 6 m boat through Snell's window; on the right a camera
in the surface (Clip Start 0.1 m) at an island's sandy shore, half over and half under the water,
the waterline and its meniscus across the lens. EEVEE, as the add-on sets it up. Run with
`tools/demo under` (`tools/demo --docs under`: copied to docs/ too).
"""

import math
import sys
import tempfile

import numpy as np
from demo_output import OUT, publish
from render_sea import SKY_SUN, boat, island, sunny_sea, write_png

import harness

SIZE = (480, 270)
FRAME = 60


def diver(bpy):
    scene, water = sunny_sea(bpy, SKY_SUN, 4.0)
    scene.render.resolution_x, scene.render.resolution_y = SIZE
    hull = boat(bpy)
    print(harness.addon("api").float_on_water(hull, water, draft=0.5, wake=False), flush=True)
    x, y = hull.location.x, hull.location.y
    harness.add_camera(scene, (x + 2.0, y - 9.0, -4.0), (x, y, 0.5), lens=16.0)
    scene.frame_set(FRAME)
    print(f"[diver] {SIZE[0]} x {SIZE[1]}, Blender {bpy.app.version_string} ...", flush=True)
    return harness.render(scene, OUT / "under_diver.png")[..., :3]


def shore(bpy):
    # The camera before the sea: the underwater body drives its Near from the scene's camera.
    def before_sea():
        island(bpy)
        centre = np.array([-10.0, 50.0])
        away = np.array([math.sin(math.radians(20.0)), -math.cos(math.radians(20.0))])
        eye = centre + away * 21.0  # over a bed 1 m down, rising 1 in 7 to the beach 7 m ahead
        camera = harness.add_camera(bpy.context.scene, (*eye, 0.0), (*(centre + away * 6.0), -1.2), lens=18.0)
        camera.data.clip_start = 0.1

    scene, _water = sunny_sea(bpy, SKY_SUN, 4.0, before_sea=before_sea)
    scene.render.resolution_x, scene.render.resolution_y = SIZE
    scene.frame_set(FRAME)
    print(f"[shore] {SIZE[0]} x {SIZE[1]}, Blender {bpy.app.version_string} ...", flush=True)
    return harness.render(scene, OUT / "under_shore.png")[..., :3]


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    left = diver(bpy)
    right = shore(bpy)
    gap = np.ones((SIZE[1], 6, 3))
    write_png(OUT / "underwater.png", np.concatenate([left, gap, right], axis=1))
    publish(OUT / "underwater.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
