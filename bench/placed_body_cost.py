"""Benchmark: what the body made for every placement costs a camera beside a water (issue 57 point 5).

A collection instance may place a water anywhere, and Geometry Nodes sees only where the water
stands itself, so while the camera is over none of it (and under none) its underwater body and
caustic light are made anyway, each placement's shader shutting them while the camera is over its
level (docs/MODEL.md section 16, "Placed by instances"). This is what that costs an ordinary water
the camera is beside: a 10 m `clear_lake` pond with caustics, a bed 2 m down, a lawn around it
(four boxes, their tops 5 cm over the water), a sun, the camera on the lawn 9 m from the pond's
middle, 1.7 m up. Rendered with the bodies' `Every Placement` on (as made) and off (nothing made
there, as before), in interleaved rounds after a first render each; the ratio on / off is taken
round by round and given as the median with its range, and the two renders' largest difference.
EEVEE 256 x 144, 8 samples; `--cycles`: Cycles, 32 samples.
Run with `tools/bench placed_body_cost`.
"""

import statistics
import sys
import tempfile
import time

import harness

ROUNDS = 3
POND = 10.0


def _scene(bpy, cycles):
    scene = harness.clean_scene(engine="CYCLES" if cycles else None, width=256, height=144, samples=8)
    scene.cycles.samples = 32
    harness.set_world_color(scene, (0.45, 0.6, 0.8))
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (0.6, 0.2, 0.0)
    scene.collection.objects.link(sun)
    water = harness.addon("api").add_water(scene, preset="clear_lake", size=POND, caustics=1.0).object
    grass = harness.lit_material("Lawn", (0.2, 0.45, 0.15))
    bed = harness.lit_material("Bed", (0.7, 0.65, 0.5))
    bpy.ops.mesh.primitive_plane_add(size=POND + 1.0, location=(0.0, 0.0, -2.0))
    bpy.context.object.data.materials.append(bed)
    side, reach = POND / 2, 40.0
    for x, y, sx, sy in (
        (0.0, side + reach / 2, 2 * (side + reach), reach),
        (0.0, -side - reach / 2, 2 * (side + reach), reach),
        (side + reach / 2, 0.0, reach, POND),
        (-side - reach / 2, 0.0, reach, POND),
    ):
        cube = harness.add_cube(scene, (x, y, -1.45), size=1.0, material=grass, name="Lawn")
        cube.scale = (sx, sy, 3.0)
    harness.addon("api").set_surroundings(water)
    harness.add_camera(scene, (0.0, -9.0, 1.7), (0.0, 0.0, -0.5), lens=28.0)
    return scene, water


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    import numpy as np

    cycles = "--cycles" in sys.argv
    scene, water = _scene(bpy, cycles)
    underwater = harness.addon("water.underwater")
    waves = harness.addon("water.waves")
    parts = [underwater.find(water, role) for role in (underwater.ROLE, underwater.LIGHT_ROLE)]
    out = tempfile.mkdtemp(prefix="water_surface_bench_")

    def state(on):
        for part in parts:
            waves.set_wave_input(part.modifiers[0], "Every Placement", on)

    def made():
        depsgraph = bpy.context.evaluated_depsgraph_get()
        return [len(part.evaluated_get(depsgraph).data.vertices) for part in parts]

    def render_s(path):
        start = time.perf_counter()
        pixels = harness.render(scene, path, exr=True)
        taken = time.perf_counter() - start
        print(f"  {taken:.2f} s", flush=True)
        return taken, pixels

    times, pixels, counts = {True: [], False: []}, {}, {}
    for on in (True, False):  # a first render each, not counted
        state(on)
        counts[on] = made()
        render_s(f"{out}/first.exr")
    for _round in range(ROUNDS):
        for on in (True, False):
            state(on)
            taken, pixels[on] = render_s(f"{out}/steady_{on}.exr")
            times[on].append(taken)
    found = sorted(a / b for a, b in zip(times[True], times[False]))
    engine = "Cycles 256 x 144, 32 samples" if cycles else "EEVEE 256 x 144, 8 samples"
    print(f"\nBlender {bpy.app.version_string}; {engine}, {ROUNDS} rounds; on / off: median (range)")
    print("| vertices made on / off (body, light) | on s | off s | on / off | largest difference |")
    print("| --- | --- | --- | --- | --- |")
    print(
        f"| {counts[True]} / {counts[False]} | {statistics.median(times[True]):.2f} | "
        f"{statistics.median(times[False]):.2f} | {statistics.median(found):.3f} "
        f"({found[0]:.3f}-{found[-1]:.3f}) | {np.abs(pixels[True] - pixels[False]).max():.4f} |"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
