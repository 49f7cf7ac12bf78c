"""Benchmark: what the `Underwater` switch costs a frame of scrubbing, the camera above the water.

The hidden underwater body and the caustic sheet are Geometry Nodes on the water's children,
evaluated on every frame the water moves. Each asks whether the camera is under the surface, or
over none of it; rays cast against the water's mesh answered that every frame, and building the
mesh's ray tree cost more than the sea's own waves (79 ms a frame on the open sea's 148,225
points, against 21 ms for the rest). A camera over the water's box, Margin over its top, now
needs no ray. Per-frame evaluation (`scene.frame_set` and the water's evaluated mesh, the children
with it) over 24 frames, Underwater on against off, in interleaved rounds; the ratio on / off is
taken round by round and given as the median with its range. Cameras: 12 m over a 15 m/s open
sea, 2 m over `clear_lake`, and 3 m over the sea (among its crests: the rays are still cast).
Target: at most 1.1 with the camera above the water. Run with `tools/bench scrub_cost`.
"""

import statistics
import sys
import tempfile
import time

import harness

FRAMES = 24
ROUNDS = 7


def _scene(bpy, preset, height):
    scene = harness.clean_scene()
    api = harness.addon("api")
    if preset == "open_sea":
        water = api.add_water(scene, preset=preset, sea_wind_speed=15.0, wind_direction=(0.8, 0.6)).object
    else:
        water = api.add_water(scene, preset=preset, size=60.0).object
    scene.camera = harness.add_camera(scene, (0.0, 0.0, height), (300.0, 1000.0, height - 90.0), lens=28.0)
    return scene, water


def _per_frame_ms(bpy, scene, water):
    start = time.perf_counter()
    for frame in range(1, FRAMES + 1):
        scene.frame_set(frame)
        len(water.evaluated_get(bpy.context.evaluated_depsgraph_get()).data.vertices)
    return (time.perf_counter() - start) * 1000.0 / FRAMES


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    api = harness.addon("api")
    print(
        f"\nBlender {bpy.app.version_string}; {FRAMES} frames, {ROUNDS} rounds; "
        "ratio on / off: the median of the rounds' (their range)"
    )
    print("| water, camera | on ms/frame | off ms/frame | on / off |")
    print("| --- | --- | --- | --- |")
    cases = (("open_sea", 12.0, "12 m over a 15 m/s sea"), ("clear_lake", 2.0, "2 m over the lake"))
    cases += (("open_sea", 3.0, "3 m over a 15 m/s sea (among its crests)"),)
    for preset, height, where in cases:
        scene, water = _scene(bpy, preset, height)
        times = {True: [], False: []}
        for state in (True, False):  # a first pass each, not counted
            api.set_underwater(water, state, scene)
            _per_frame_ms(bpy, scene, water)
        for _round in range(ROUNDS):
            for state in (True, False):
                api.set_underwater(water, state, scene)
                times[state].append(_per_frame_ms(bpy, scene, water))
        found = sorted(a / b for a, b in zip(times[True], times[False]))
        print(
            f"| {preset}, {where} | {statistics.median(times[True]):.1f} | "
            f"{statistics.median(times[False]):.1f} | "
            f"{statistics.median(found):.2f} ({found[0]:.2f}-{found[-1]:.2f}) |",
            flush=True,
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
