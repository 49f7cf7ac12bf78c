"""Benchmark: what the `Underwater` switch costs a camera that never goes under (issue 40 point 3).

Each water twice, the switch on (its hidden body, its caustic light where it has caustics, and
EEVEE's volume samples raised to 256) and off (none of them, the scene's own 64), with the camera
above it: 3 m over the open sea at 15 m/s (a gale whose highest crests rise over 3 m elsewhere on
its tile: the body follows the surface under the camera, so it is not made) and 1.5 m over
`clear_lake`. EEVEE, 256 x 144, 8 samples, on frames 1 and 25 (the sea moves, so the body's
Geometry Nodes are evaluated anew each time), in interleaved rounds after a first render; the
ratio on / off is taken round by round and given as the median with its range.
Target: at most 1.02. Run with `tools/bench underwater_cost` (`--lake`: the lake only; `--sea`: the sea only).
"""

import statistics
import sys
import tempfile
import time

import harness

ROUNDS = 3
FRAMES = (1, 25)


def _scene(bpy, preset):
    scene = harness.clean_scene(width=256, height=144, samples=8)
    harness.set_world_color(scene, (0.45, 0.6, 0.8))
    api = harness.addon("api")
    if preset == "open_sea":
        water = api.add_water(scene, preset=preset, sea_wind_speed=15.0, wind_direction=(0.8, 0.6)).object
        harness.add_camera(scene, (0.0, 0.0, 3.0), (300.0, 1000.0, -87.0), lens=28.0)
    else:
        water = api.add_water(scene, preset=preset, size=60.0).object
        harness.add_camera(scene, (0.0, -20.0, 1.5), (0.0, 10.0, -2.0), lens=28.0)
    return scene, water


def _render_s(bpy, scene, path):
    start = time.perf_counter()
    for frame in FRAMES:
        scene.frame_set(frame)
        harness.render(scene, path)
    taken = time.perf_counter() - start
    print(f"  {len(FRAMES)} frames in {taken:.1f} s", flush=True)
    return taken


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    api = harness.addon("api")
    out = tempfile.mkdtemp(prefix="water_surface_bench_")
    print(
        f"\nBlender {bpy.app.version_string}; EEVEE 256 x 144, 8 samples, frames {FRAMES}, "
        f"{ROUNDS} rounds; ratio on / off: the median of the rounds' (their range)"
    )
    print("| water, camera | body made | volume samples on / off | on s | off s | on / off |")
    print("| --- | --- | --- | --- | --- | --- |")
    cases = (("open_sea", "3 m over a 15 m/s sea"), ("clear_lake", "1.5 m over the lake"))
    if "--lake" in sys.argv:  # the quick half: the lake's renders take seconds, the sea's a minute
        cases = cases[1:]
    elif "--sea" in sys.argv:  # the slow half alone
        cases = cases[:1]
    for preset, where in cases:
        scene, water = _scene(bpy, preset)
        body = harness.addon("water.underwater").find(water)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        made = len(body.evaluated_get(depsgraph).data.vertices) > 0
        samples_on = scene.eevee.volumetric_samples
        api.set_underwater(water, False, scene)
        samples_off = scene.eevee.volumetric_samples
        times = {True: [], False: []}
        for state in (True, False):  # a first render each, not counted
            api.set_underwater(water, state, scene)
            _render_s(bpy, scene, f"{out}/first.png")
        for _round in range(ROUNDS):
            for state in (True, False):
                api.set_underwater(water, state, scene)
                times[state].append(_render_s(bpy, scene, f"{out}/steady.png"))
        found = sorted(a / b for a, b in zip(times[True], times[False]))
        print(
            f"| {preset}, {where} | {'yes' if made else 'no'} | {samples_on} / {samples_off} | "
            f"{statistics.median(times[True]):.2f} | {statistics.median(times[False]):.2f} | "
            f"{statistics.median(found):.3f} ({found[0]:.3f}-{found[-1]:.3f}) |"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
