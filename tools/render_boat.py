"""Renders boats and their wakes (out/boat_wakes.png): a boat crossing the lake at 4 m/s and one
on the open sea (4 m/s wind) at 5 m/s, each from a chase camera 10 m from it, behind, aside and
above, side by side. The boat (`render_sea.boat`: a 6 m hull and a cabin) floats with
`api.float_on_water`, which gives it its wake; the frames before are stepped in order, as a render
of the animation does. Run with `tools/demo boat` (`tools/demo --docs boat`: copied to docs/ too).
"""

import math
import sys
import tempfile
import time

import numpy as np
from demo_output import OUT, publish
from render_ocean import sky_world
from render_sea import boat, write_png

import harness

SIZE = (480, 270)
FRAME = 120  # 5 s in
HEADING = math.radians(35.0)


def chase(bpy, scene, water, speed, name):
    """Keys the boat along its heading at `speed`, floats it, steps to FRAME and renders it from
    behind and above; returns the pixels (H, W, 3)."""
    hull = boat(bpy)
    direction = np.array([math.cos(HEADING), math.sin(HEADING)])
    start = -direction * speed * (FRAME - 1) / scene.render.fps
    for frame in (1, FRAME):
        where = start + direction * speed * (frame - 1) / scene.render.fps
        hull.location = (*where, 0.0)
        hull.keyframe_insert("location", frame=frame)
    action = hull.animation_data.action
    for fcurve in harness.addon("nodes.material")._action_fcurves(action):
        for key in fcurve.keyframe_points:
            key.interpolation = "LINEAR"
    api = harness.addon("api")
    print(api.float_on_water(hull, water, draft=0.5), flush=True)
    eye = direction * 2.0 + np.array([direction[1], -direction[0]]) * 7.0  # 10 m from the boat
    harness.add_camera(scene, (*eye, 7.0), (*(-direction * 12.0), 0.0), lens=20.0)
    for frame in range(1, FRAME + 1):
        scene.frame_set(frame)
    evaluated = water.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    heights = np.array([v.co.z for v in evaluated.vertices])
    print(f"[{name}] the water's heights: {heights.min():.3f} to {heights.max():.3f} m", flush=True)
    print(
        f"[{name}] boat at {speed} m/s, {SIZE[0]} x {SIZE[1]}, Blender {bpy.app.version_string} ...",
        flush=True,
    )
    return harness.render(scene, OUT / f"{name}.png")[..., :3]


def scene_with_sky(bpy):
    scene = harness.clean_scene(width=SIZE[0], height=SIZE[1], samples=8)
    scene.render.fps = 24
    sky_world(bpy, scene)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (math.radians(55.0), 0.0, math.radians(-30.0))
    scene.collection.objects.link(sun)
    return scene


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    start = time.monotonic()
    api = harness.addon("api")
    scene = scene_with_sky(bpy)
    lake = api.add_water(scene, preset="calm_mirror", size=160.0, resolution=641, name="Lake").object
    left = chase(bpy, scene, lake, 4.0, "boat_lake")
    scene = scene_with_sky(bpy)
    sea = api.add_water(
        scene, preset="open_sea", sea_wind_speed=4.0, wind_direction=(0.8, 0.6), name="Sea"
    ).object
    right = chase(bpy, scene, sea, 5.0, "boat_sea")
    write_png(OUT / "boat_wakes.png", np.concatenate([left, right], axis=1))
    publish(OUT / "boat_wakes.png", note=f"in {time.monotonic() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
