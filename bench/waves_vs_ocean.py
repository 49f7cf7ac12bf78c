"""Per-frame evaluation cost of the `Water Waves` modifier against Blender's Ocean modifier.

Both run on the same grid (256 x 256 and 1024 x 1024 vertices), one object in
the scene at a time, over the same frames. The Ocean modifier displaces the
grid (`geometry_mode = 'DISPLACE'`) with its default spectrum and resolution,
its spatial size set to the grid's and its Time driven by the frame (it is
still otherwise). Reported: milliseconds per frame, nanoseconds
per vertex, the ratio Ocean / Water Waves (above 1: Water Waves is faster) and
the memory Blender holds for the evaluated object (its allocator's count, MiB).
Run with `tools/bench waves_vs_ocean`.
"""

import os
import re
import sys
import tempfile
import time

import harness

SIZE = 128.0
FRAMES = 24
ROUNDS = 5  # interleaved; the fastest round counts (the least disturbed by other work)
GRIDS = (256, 1024)


def blender_mib(bpy):
    """Memory Blender's allocator holds now (`wm.memory_statistics`' "total memory len"), MiB.

    The operator prints from C (stdout and stderr), so its output is caught at the file descriptors.
    """
    saved = {fd: os.dup(fd) for fd in (1, 2)}
    with tempfile.TemporaryFile() as caught:
        sys.stdout.flush()
        sys.stderr.flush()
        for fd in saved:
            os.dup2(caught.fileno(), fd)
        try:
            bpy.ops.wm.memory_statistics()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            for fd, copy in saved.items():
                os.dup2(copy, fd)
                os.close(copy)
        caught.seek(0)
        text = caught.read().decode(errors="replace")
    megabytes = float(re.search(r"total memory len: ([0-9.]+) MB", text).group(1))
    return megabytes * 1e6 / 2**20


def measure(bpy, scene, obj, first_frame):
    """(ms per frame, MiB added) for `obj` alone in `scene`, evaluated frame after frame."""
    before = blender_mib(bpy)
    scene.collection.objects.link(obj)
    scene.frame_set(first_frame)  # first evaluation: caches, FFT plans, node tree compilation
    start = time.perf_counter()
    for frame in range(first_frame + 1, first_frame + FRAMES + 1):
        scene.frame_set(frame)
    per_frame = (time.perf_counter() - start) / FRAMES * 1000
    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    assert len(evaluated.data.vertices) == len(obj.data.vertices), "both keep the grid's vertices"
    added = blender_mib(bpy) - before  # the evaluated copy and the modifier's own data
    scene.collection.objects.unlink(obj)
    return per_frame, added


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    plane = harness.addon("water.plane")
    waves = harness.addon("water.waves")
    scene = harness.clean_scene()
    print(
        f"Blender {bpy.app.version_string}, {os.cpu_count()} CPUs: best of {ROUNDS} interleaved rounds "
        f"of {FRAMES} frames after a warm-up frame"
    )
    print(
        "| grid | vertices | Water Waves ms/frame | Ocean ms/frame | ns/vertex (waves, ocean) "
        "| Ocean / Water Waves | MiB (waves, ocean) |"
    )
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for n in GRIDS:
        mesh = plane.new_water_mesh(f"Grid {n}", SIZE, n)
        with_waves = bpy.data.objects.new(f"Waves {n}", mesh)
        waves.add_waves(with_waves)
        with_ocean = bpy.data.objects.new(f"Ocean {n}", mesh.copy())
        ocean = with_ocean.modifiers.new("Ocean", "OCEAN")
        ocean.geometry_mode = "DISPLACE"
        ocean.spatial_size = int(SIZE)
        # The Ocean modifier moves only when its Time is animated: seconds from the frame, as the waves.
        ocean.driver_add("time").driver.expression = f"frame / {scene.render.fps / scene.render.fps_base}"
        runs = {"waves": [], "ocean": []}
        for round_number in range(ROUNDS):
            first = 1 + round_number * (FRAMES + 1)
            runs["waves"].append(measure(bpy, scene, with_waves, first))
            runs["ocean"].append(measure(bpy, scene, with_ocean, first))
        waves_ms, ocean_ms = (min(ms for ms, _ in runs[key]) for key in ("waves", "ocean"))
        waves_mib, ocean_mib = (runs[key][0][1] for key in ("waves", "ocean"))
        vertices = n * n
        print(
            f"| {n} x {n} | {vertices} | {waves_ms:.1f} | {ocean_ms:.1f} "
            f"| {waves_ms * 1e6 / vertices:.1f}, {ocean_ms * 1e6 / vertices:.1f} "
            f"| {ocean_ms / waves_ms:.2f} | {waves_mib:.0f}, {ocean_mib:.0f} |",
            flush=True,
        )
    print(f"Ocean modifier: resolution {ocean.resolution}, spatial size {ocean.spatial_size}, DISPLACE")
    return 0


if __name__ == "__main__":
    sys.exit(main())
