"""Benchmark: what a wake costs a lake's evaluation per frame, and what baking it costs.

A 200 x 200 m lake meshed at 0.25 m (801 x 801 points) with its `Water Waves`, and a
10 x 3 x 2 m hull running across it at 3.5 m/s on a diagonal. Milliseconds a frame over two
spans of 24 frames, stepped in order (`frame_set`) from frame 1: frames 97 to 120 (a 4 s track)
and 721 to 744 (a 30 s track, the whole of the wake's default `Keep`). The lake alone and with
the hull's wake (its simulation cache cleared before each round, so every step is computed), in
3 interleaved rounds; ratios to the lake alone, round by round, median and range. Then the time
`api.bake` takes per frame over the first 120 frames (4.3 and later). Run with
`tools/bench wake_cost`.
"""

import math
import statistics
import sys
import tempfile
import time

import harness

SPANS = ((97, "a 4 s track"), (721, "a 30 s track"))  # each span's first frame
FRAMES = 24
ROUNDS = 3
SPEED = 3.5
HEADING = 0.6


def hull(bpy, scene):
    """A box hull at 3.5 m/s on a diagonal, from (-60, -40) for 40 s (140 m, inside the lake)."""
    mesh = bpy.data.meshes.new("Hull")
    corners = [(x, y, z) for x in (-5.0, 5.0) for y in (-1.5, 1.5) for z in (-1.0, 1.0)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh.from_pydata(corners, [], faces)
    obj = bpy.data.objects.new("Hull", mesh)
    scene.collection.objects.link(obj)
    for frame, seconds in ((1, 0.0), (961, 40.0)):
        run = SPEED * seconds
        obj.location = (-60.0 + run * math.cos(HEADING), -40.0 + run * math.sin(HEADING), 0.0)
        obj.rotation_euler = (0.0, 0.0, HEADING)
        obj.keyframe_insert("location", frame=frame)
    for fcurve in harness.addon("nodes.material")._action_fcurves(obj.animation_data.action):
        for key in fcurve.keyframe_points:
            key.interpolation = "LINEAR"
    return obj


def per_frame_ms(scene):
    """Milliseconds a frame over each span, stepping every frame from 2 on."""
    found, frame = [], 1
    for first, _name in SPANS:
        while frame < first - 1:
            frame += 1
            scene.frame_set(frame)
        start = time.perf_counter()
        for frame in range(first, first + FRAMES):
            scene.frame_set(frame)
        found.append((time.perf_counter() - start) * 1000.0 / FRAMES)
    return found


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
    wake = harness.addon("water.boats.wake")
    waves = harness.addon("water.waves")
    (modifier,) = wake.wake_modifiers(lake)
    cases = ("the lake alone", "+ a hull's wake")
    times = {(case, span): [] for case in cases for span in range(len(SPANS))}
    for round_number in range(ROUNDS):
        for case in cases:
            modifier.show_viewport = case != "the lake alone"
            # A changed input clears the simulation's cache: every step is computed again.
            waves.set_wave_input(modifier, "Strength", 1.0 + 1e-4 * (round_number % 2))
            scene.frame_set(1)
            for span, ms in enumerate(per_frame_ms(scene)):
                times[case, span].append(ms)
    points = len(lake.data.vertices)
    print(f"\nBlender {bpy.app.version_string}; {points} points, {FRAMES} frames a span, {ROUNDS} rounds")
    print("| case | frames | ms/frame (median) | / the lake alone (median, range) |")
    print("| --- | --- | --- | --- |")
    for span, (first, name) in enumerate(SPANS):
        base = times[cases[0], span]
        for case in cases:
            found = times[case, span]
            ratios = sorted(t / b for t, b in zip(found, base))
            print(
                f"| {case}, {name} | {first}-{first + FRAMES - 1} | {statistics.median(found):.1f} | "
                f"{statistics.median(ratios):.2f} ({ratios[0]:.2f}-{ratios[-1]:.2f}) |"
            )
    if bpy.app.version >= (4, 3, 0):
        modifier.show_viewport = True
        scene.frame_start, scene.frame_end = 1, 120
        start = time.perf_counter()
        api.bake(lake, scene)
        each = (time.perf_counter() - start) * 1000.0 / 120
        print(f"baking frames 1-120: {each:.1f} ms a frame")
    return 0


if __name__ == "__main__":
    sys.exit(main())
