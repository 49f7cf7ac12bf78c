"""Benchmark: the Water Surface material against a Principled BSDF water and an unlit plane.

Same scene, same run: each material's first render (mostly shader compilation)
and its steady render time, with the ratios to the Principled water. The water
is an 8 m grid over a sloping bed that rises through its surface on one side,
with its surroundings set through the API, so it carries the `water_depth` and
`water_shore_distance` attributes it has in use: the `tropical_shallows` preset
(Absorption, Scatter Color, Foam Width and Amount, Bump Layers 2) pays for its
colour by depth and its shore foam, beside the plain `lake` preset. Targets:
the default lake's steady render at most 1.1x the Principled water, `Bump
Layers` 4 at most 1.1x `Bump Layers` 1, `tropical_shallows` at most 1.1x
`lake`, compile at most 1.5x. With `--views`
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


def preset_material(scene, name, preset):
    """The add-on's lake material set to a preset's shader values."""
    material = lake_material(scene, name)
    harness.addon("water.values").write_values(material, harness.addon("presets").get(preset).values)
    return material


def water_with_surroundings(bpy, scene):
    """An 8 m water grid (0.25 m apart, as the add-on makes it for surroundings) over a bed plane
    tilted to rise through the surface at x = 2.4 m, its surroundings set through the API: the
    grid carries `water_depth` (up to 1.6 m over the bed) and `water_shore_distance`."""
    bed = harness.add_cube(
        scene,
        (0.0, 0.0, -0.6),
        size=1.0,
        material=harness.emission_material("Bed", (0.8, 0.7, 0.5)),
        name="Bed",
    )
    bed.scale = (12.0, 12.0, 0.02)
    bed.rotation_euler = (0.0, -0.25, 0.0)  # z = 0.25 x - 0.6: dry from x = 2.4 m
    mesh = harness.addon("water.plane").new_water_mesh("Bench Water", 8.0, 33)
    plane = bpy.data.objects.new("Bench Water", mesh)
    scene.collection.objects.link(plane)
    changes = harness.addon("api").set_surroundings(plane, scene=scene)
    print("surroundings: " + ", ".join(changes), flush=True)
    return plane


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
    plane = water_with_surroundings(bpy, scene)
    materials = {
        "unlit emission plane": harness.emission_material("Unlit", (0.2, 0.3, 0.5)),
        "Principled BSDF water": principled_water(bpy),
        "Water Surface (lake: Bump Layers 1)": lake_material(scene, "Lake"),
        "Water Surface, Bump Layers 4": lake_material(scene, "Layers 4", **{"Bump Layers": 4}),
        "Water Surface, lake preset": preset_material(scene, "Lake Preset", "lake"),
        "Water Surface, tropical_shallows preset": preset_material(scene, "Tropical", "tropical_shallows"),
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
    _preset_first, preset_steady = results["Water Surface, lake preset"]
    _tropical_first, tropical_steady = results["Water Surface, tropical_shallows preset"]
    print(f"tropical_shallows steady / lake preset steady: {tropical_steady / preset_steady:.2f}")
    checks = {
        "lake steady <= 1.1x Principled": lake_steady <= 1.1 * base_steady,
        "Bump Layers 4 steady <= 1.1x Bump Layers 1": layers_steady <= 1.1 * lake_steady,
        "tropical_shallows steady <= 1.1x lake": tropical_steady <= 1.1 * preset_steady,
        "lake first render <= 1.5x Principled": lake_first <= 1.5 * base_first,
    }
    for what, ok in checks.items():
        print(f"{what}: {'met' if ok else 'NOT met'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(views="--views" in sys.argv[1:]))
