"""Benchmark: the `open_sea` preset against Blender's Ocean modifier alone and the seeds' ocean.

Three waters with the same number of vertices (385 x 385), one in the scene at a time:

* `open_sea`: the preset at 12 m/s (Ocean modifier, `Water Sea Fade`, ocean shading with
  whitecaps) on its 20 km mesh that reaches the horizon;
* the Ocean modifier alone: the same modifier settings on an even grid one tile wide (how the
  modifier is used on its own), with a Principled BSDF water (transmission 1, roughness 0.05);
* the seeds' `ocean`: the four sines (`Water Waves`) and the ocean shading on an even grid one
  tile wide.

Per-frame evaluation: milliseconds to evaluate the object over 24 frames, in 15 interleaved
rounds. Steady render: EEVEE, 256 x 144, 8 samples, in 5 interleaved rounds after a first
render. Ratios are to the Ocean modifier alone, taken round by round (the two measured back to
back) and their median given with their range: on a shared machine a whole round runs slower
or faster by 10 to 20%, which a ratio of bests mixed into the figure. Run with
`tools/bench open_sea_cost`; `--breakdown` adds where the sea's render goes: the same sea under
the Principled water (its mesh's cost), with its caustics built in (`Caustics` 1, what the
preset had before they became a part), and the Ocean modifier alone casting no shadow (the
sea's water casts none, as the add-on sets it); `--modifiers` prints each of the sea's
modifiers' own time (`Modifier.execution_time`, 72 frames: the best and the median).
"""

import math
import statistics
import sys
import tempfile
import time

import harness

POINTS = 385
FRAMES = 24
EVAL_ROUNDS = 15
RENDER_ROUNDS = 5


def principled_water(bpy):
    material = bpy.data.materials.new("Principled Water")
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    bsdf = material.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.0, 0.2, 0.4, 1.0)
    bsdf.inputs["Transmission Weight"].default_value = 1.0
    bsdf.inputs["Roughness"].default_value = 0.05
    bsdf.inputs["IOR"].default_value = 1.33
    return material


def ocean_alone(bpy, scene, sea_ocean, tile):
    """An even grid one tile wide with a copy of the sea's Ocean modifier and a Principled water."""
    mesh = harness.addon("water.plane").new_water_mesh("Ocean Alone", float(tile), POINTS)
    obj = bpy.data.objects.new("Ocean Alone", mesh)
    scene.collection.objects.link(obj)
    modifier = obj.modifiers.new("Ocean", "OCEAN")
    harness.addon("water.sea.open_sea").copy_settings(sea_ocean, modifier)
    harness.addon("nodes.material").drive_clock(modifier, scene, prop="time")
    obj.data.materials.append(principled_water(bpy))
    return obj


def breakdown(bpy, scene, api, sea, alone):
    """Copies of the sea and of the modifier alone that take one thing apart each."""

    def copy(obj, name):
        twin = obj.copy()
        twin.data = obj.data.copy()
        twin.name = name
        scene.collection.objects.link(twin)
        return twin

    principled = copy(sea, "Sea Under Principled")
    principled.data.materials.clear()
    principled.data.materials.append(alone.data.materials[0])
    caustics = copy(sea, "Sea With Caustics")
    caustics.data.materials.clear()
    caustics.data.materials.append(sea.active_material.copy())
    api.write_values(caustics, {"caustics": 1.0})
    unshadowed = copy(alone, "Ocean Alone No Shadow")
    unshadowed.visible_shadow = False
    return {
        "open_sea's mesh under the Principled water": principled,
        "open_sea with its caustics built in (Caustics 1)": caustics,
        "Ocean modifier alone, casting no shadow": unshadowed,
    }


def modifier_times(bpy, scene, sea, show):
    """Prints each of the sea's modifiers' own evaluation time over 72 frames."""
    show(sea)
    times = {}
    for frame in range(1, 73):
        scene.frame_set(frame)
        evaluated = sea.evaluated_get(bpy.context.evaluated_depsgraph_get())
        for modifier in evaluated.modifiers:
            times.setdefault(modifier.name, []).append(modifier.execution_time * 1000.0)
    for name, found in times.items():
        print(f"{name}: best {min(found):.2f} ms, median {statistics.median(found):.2f} ms a frame")


def ratios(values, bases):
    """'median (low-high)' of the round-by-round ratios of `values` to `bases`."""
    found = sorted(v / b for v, b in zip(values, bases))
    return f"{statistics.median(found):.2f} ({found[0]:.2f}-{found[-1]:.2f})"


def evaluation_ms(bpy, scene, obj):
    """Milliseconds a frame to evaluate `obj` (its mesh read back) over FRAMES frames."""
    start = time.perf_counter()
    for frame in range(1, FRAMES + 1):
        scene.frame_set(frame)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        len(obj.evaluated_get(depsgraph).data.vertices)
    return (time.perf_counter() - start) * 1000.0 / FRAMES


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(width=256, height=144, samples=8)
    harness.set_world_color(scene, (0.45, 0.6, 0.8))
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.rotation_euler = (math.radians(50.0), 0.0, math.radians(30.0))
    scene.collection.objects.link(sun)
    api = harness.addon("api")
    sea = api.add_water(scene, preset="open_sea", name="Open Sea").object
    sea_ocean, _fade = harness.addon("water.sea.open_sea").sea_modifiers(sea)
    tile = sea_ocean.spatial_size
    seeds = api.add_water(
        scene, preset="ocean", size=float(tile), resolution=POINTS, name="Seeds Ocean"
    ).object
    alone = ocean_alone(bpy, scene, sea_ocean, tile)
    waters = {
        "Ocean modifier alone + Principled water": alone,
        "open_sea (Ocean modifier + fade + ocean shading)": sea,
        "seeds' ocean (Water Waves + ocean shading)": seeds,
    }
    if "--breakdown" in sys.argv:
        waters |= breakdown(bpy, scene, api, sea, alone)
    counts = {name: len(obj.data.vertices) for name, obj in waters.items()}
    harness.add_camera(scene, (0.0, -20.0, 8.0), (0.0, 60.0, 0.0), lens=28.0)

    def show(chosen):
        for obj in waters.values():
            obj.hide_render = obj.hide_viewport = obj is not chosen

    if "--modifiers" in sys.argv:
        modifier_times(bpy, scene, sea, show)
    evaluation = {name: [] for name in waters}
    for _round in range(EVAL_ROUNDS):
        for name, obj in waters.items():
            show(obj)
            evaluation[name].append(evaluation_ms(bpy, scene, obj))
    out = tempfile.mkdtemp(prefix="water_surface_bench_")
    first, steady = {}, {name: [] for name in waters}
    scene.frame_set(12)
    for name, obj in waters.items():
        show(obj)
        start = time.perf_counter()
        harness.render(scene, f"{out}/first.png")
        first[name] = time.perf_counter() - start
    for _round in range(RENDER_ROUNDS):
        for name, obj in waters.items():
            show(obj)
            harness.render(scene, f"{out}/switch.png")
            start = time.perf_counter()
            harness.render(scene, f"{out}/steady.png")
            steady[name].append(time.perf_counter() - start)
    base = "Ocean modifier alone + Principled water"
    print(
        f"\nBlender {bpy.app.version_string}; {FRAMES} frames, {EVAL_ROUNDS} rounds; renders 256 x 144, "
        f"8 samples, {RENDER_ROUNDS} rounds; ratios: the median of the rounds' (their range)"
    )
    print(
        "| water | vertices | ms/frame (median) | / Ocean alone | first render s | steady render s "
        "| / Ocean alone |"
    )
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for name in waters:
        evaluated = ratios(evaluation[name], evaluation[base])
        rendered = ratios(steady[name], steady[base])
        print(
            f"| {name} | {counts[name]} | {statistics.median(evaluation[name]):.1f} | {evaluated} | "
            f"{first[name]:.2f} | {statistics.median(steady[name]):.2f} | {rendered} |"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
