"""Benchmark: the Water Surface material against a Principled BSDF water and an unlit plane.

Same scene, same run: each material's first render (mostly shader compilation)
and its steady render time, with the ratios to the Principled water. Targets:
steady at most 1.2x, compile at most 1.5x. Run with `tools/bench shader_cost`.
"""

import statistics
import sys
import tempfile
import time

import harness

STEADY_RENDERS = 3


def principled_water(bpy):
    material = bpy.data.materials.new("Principled Water")
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    bsdf = material.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Transmission Weight"].default_value = 1.0
    bsdf.inputs["Roughness"].default_value = 0.0
    bsdf.inputs["IOR"].default_value = 1.33
    material.use_raytrace_refraction = True
    return material


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(width=256, height=144, samples=8)
    harness.addon("engine").enable_ray_tracing(scene)
    harness.set_world_color(scene, (0.4, 0.6, 0.9))
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    scene.collection.objects.link(sun)
    harness.add_cube(
        scene, (0, 0, -1.2), size=2.0, material=harness.emission_material("Floor", (1, 0.1, 0.05))
    )
    harness.add_cube(
        scene, (1.5, 1.5, 0.8), size=1.0, material=harness.emission_material("Block", (0.1, 1, 0.1))
    )
    harness.add_camera(scene, (0, -6, 2.5), (0, 0, 0))
    bpy.ops.mesh.primitive_plane_add(size=8)
    plane = bpy.context.object
    materials = {
        "unlit emission plane": harness.emission_material("Unlit", (0.2, 0.3, 0.5)),
        "Principled BSDF water": principled_water(bpy),
        "Water Surface": harness.addon("nodes.material").make_water_material(scene=scene),
    }
    out = tempfile.mkdtemp(prefix="water_surface_bench_")
    plane.data.materials.append(harness.emission_material("Warm-up", (1, 1, 1)))
    harness.render(scene, f"{out}/warmup.png")  # compiles the world and the other objects once
    results = {}
    for name, material in materials.items():
        plane.data.materials[0] = material
        start = time.perf_counter()
        harness.render(scene, f"{out}/first.png")
        first = time.perf_counter() - start
        steady = []
        for _ in range(STEADY_RENDERS):
            start = time.perf_counter()
            harness.render(scene, f"{out}/steady.png")
            steady.append(time.perf_counter() - start)
        results[name] = (first, statistics.median(steady))
        print(f"{name}: first {first:.2f} s, steady {statistics.median(steady):.2f} s", flush=True)
    base_first, base_steady = results["Principled BSDF water"]
    print(f"\nBlender {bpy.app.version_string}, 256x144, 8 samples, screen-traced EEVEE")
    print("| material | first render s | steady render s | first / Principled | steady / Principled |")
    print("| --- | --- | --- | --- | --- |")
    for name, (first, steady) in results.items():
        print(
            f"| {name} | {first:.2f} | {steady:.2f} | {first / base_first:.2f} | {steady / base_steady:.2f} |"
        )
    water_first, water_steady = results["Water Surface"]
    ok = water_steady <= 1.2 * base_steady and water_first <= 1.5 * base_first
    print("targets (steady <= 1.2x, compile <= 1.5x):", "met" if ok else "NOT met")
    return 0


if __name__ == "__main__":
    sys.exit(main())
