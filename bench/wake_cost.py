"""Benchmark: what a wake costs a lake's evaluation per frame, and what baking it costs.

A 200 x 200 m lake meshed at 0.25 m (801 x 801 points) with its `Water Waves`, and a
10 x 3 x 2 m hull running across it at 3.5 m/s on a diagonal. Milliseconds a frame over frames
97 to 120 (4 to 5 s in), stepped in order (`frame_set`) from frame 1, the lake alone and with
the hull's wake (its simulation cache cleared before each round, so every step is computed), in
3 interleaved rounds; ratios to the lake alone, round by round, median and range. Then the time
`api.bake` takes per frame (4.3 and later). Run with `tools/bench wake_cost`.
"""

import math
import statistics
import sys
import tempfile
import time

import harness

WARM = 96  # frames stepped, untimed, before the timed ones: a 4 s track
FRAMES = 24
ROUNDS = 3


def hull(bpy, scene):
    mesh = bpy.data.meshes.new("Hull")
    corners = [(x, y, z) for x in (-5.0, 5.0) for y in (-1.5, 1.5) for z in (-1.0, 1.0)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh.from_pydata(corners, [], faces)
    obj = bpy.data.objects.new("Hull", mesh)
    scene.collection.objects.link(obj)
    for frame, seconds in ((1, 0.0), (241, 10.0)):
        obj.location = (-20.0 + 3.5 * seconds * math.cos(0.6), -15.0 + 3.5 * seconds * math.sin(0.6), 0.0)
        obj.rotation_euler = (0.0, 0.0, 0.6)
        obj.keyframe_insert("location", frame=frame)
    return obj


def per_frame_ms(scene):
    for frame in range(1, WARM + 1):
        scene.frame_set(frame)
    start = time.perf_counter()
    for frame in range(WARM + 1, WARM + FRAMES + 1):
        scene.frame_set(frame)
    return (time.perf_counter() - start) * 1000.0 / FRAMES


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(width=64, height=36, samples=1)
    scene.render.fps = 24
    api = harness.addon("api")
    lake = api.add_water(scene, preset="lake", size=200.0, resolution=801, see_surroundings=False).object
    api.add_waves(lake)
    boat = hull(bpy, scene)
    api.add_wake_source(boat, lake)
    wake = harness.addon("water.wake")
    waves = harness.addon("water.waves")
    (modifier,) = wake.wake_modifiers(lake)
    times = {"the lake alone": [], "+ a hull's wake": []}
    for round_number in range(ROUNDS):
        for name in times:
            modifier.show_viewport = name != "the lake alone"
            # A changed input clears the simulation's cache: every step is computed again.
            waves.set_wave_input(modifier, "Strength", 1.0 + 1e-4 * (round_number % 2))
            scene.frame_set(1)
            times[name].append(per_frame_ms(scene))
    base = times["the lake alone"]
    frames = f"frames {WARM + 1}-{WARM + FRAMES}"
    points = len(lake.data.vertices)
    print(f"\nBlender {bpy.app.version_string}; {points} points, {frames}, {ROUNDS} rounds")
    print("| case | ms/frame (median) | / the lake alone (median, range) |")
    print("| --- | --- | --- |")
    for name, found in times.items():
        ratios = sorted(t / b for t, b in zip(found, base))
        print(
            f"| {name} | {statistics.median(found):.1f} | "
            f"{statistics.median(ratios):.2f} ({ratios[0]:.2f}-{ratios[-1]:.2f}) |"
        )
    if bpy.app.version >= (4, 3, 0):
        modifier.show_viewport = True
        scene.frame_start, scene.frame_end = 1, WARM + FRAMES
        start = time.perf_counter()
        api.bake(lake, scene)
        each = (time.perf_counter() - start) * 1000.0 / (WARM + FRAMES)
        print(f"baking frames 1-{WARM + FRAMES}: {each:.1f} ms a frame")
    return 0


if __name__ == "__main__":
    sys.exit(main())
