"""Benchmark: the Water Surface material against a Principled BSDF water and an unlit plane.

Same scene, same run: each material's first render (mostly shader compilation)
and its steady render time, with the ratios to the Principled water. Targets:
the default lake's steady render at most 1.1x the Principled water, `Bump
Layers` 4 at most 1.1x `Bump Layers` 1, compile at most 1.5x. With `--views`
it also renders each debug view of the lake, which shows where the time goes
(a view keeps one closure or only the emission). Run with `tools/bench shader_cost`.
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


def lake_material(scene, name, **inputs):
    """The add-on's lake material with some group inputs changed."""
    module = harness.addon("nodes.material")
    material = module.make_water_material(name, scene=scene)
    node = module.water_node(material)
    for socket, value in inputs.items():
        node.inputs[socket].default_value = value
    return material


def main(views=False):
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
        "Water Surface (lake: Bump Layers 1)": lake_material(scene, "Lake"),
        "Water Surface, Bump Layers 4": lake_material(scene, "Layers 4", **{"Bump Layers": 4}),
    }
    if views:
        names = {1: "reflection only", 2: "refraction only", 3: "F only", 4: "normal only", 5: "glint only"}
        for number, label in names.items():
            materials[f"lake, Debug View {number} ({label})"] = lake_material(
                scene, f"View {number}", **{"Debug View": number}
            )
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
    lake_first, lake_steady = results["Water Surface (lake: Bump Layers 1)"]
    _layers_first, layers_steady = results["Water Surface, Bump Layers 4"]
    checks = {
        "lake steady <= 1.1x Principled": lake_steady <= 1.1 * base_steady,
        "Bump Layers 4 steady <= 1.1x Bump Layers 1": layers_steady <= 1.1 * lake_steady,
        "lake first render <= 1.5x Principled": lake_first <= 1.5 * base_first,
    }
    for what, ok in checks.items():
        print(f"{what}: {'met' if ok else 'NOT met'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(views="--views" in sys.argv[1:]))
