"""Benchmark: what the open sea's whitecaps cost, the sea with them against the same sea without.

Three copies of the `open_sea` preset at 15 m/s (385 x 385 points, the same seed and wind), each
in a scene of its own (copies of one scene: the same camera, sun, world and render settings). A
sea hidden in a shared scene is still evaluated each frame (its surroundings and drivers pull it
in), so hiding would measure every sea at once:

* whitecaps: the preset as it is;
* `whitecaps` 0: the preset key at 0. It only zeroes the ocean shading's `Whitecaps` input:
  `Water Sea Fade` still finds the crests and their trail each frame, and the shading still
  works the spots, the lace and the far whitecaps out (they are always built in);
* no foam work: the sea with nothing the whitecaps need. Its fade modifier runs a copy of
  `Water Sea Fade` in which the Set Position takes the group's input geometry (not the crests'
  stored one) and the UV store takes the moved geometry (not the whitecaps' stored one). Every
  node the output no longer needs is removed: the crests' store, the middle's statistics, the nine
  bisection passes and the trail's three reads. Its material's ocean shade is a copy whose foam
  cover takes no whitecaps (the link into `foam_cover`'s first input removed; the shore foam
  stays), so EEVEE compiles none of their nodes. The bench checks that this sea's points are
  where the whitecaps sea's are, and that it stores no `water_whitecaps`.

Per-frame evaluation: milliseconds to evaluate the sea (its mesh read back) over 24 frames, in
EVAL_ROUNDS interleaved rounds, with the fade modifier's own `execution_time` beside it. Steady
render: EEVEE, 192 x 108, 2 samples, from 12 m up over the sea with a sun 15 degrees up behind
the camera (whitecaps in view), in RENDER_ROUNDS interleaved rounds after a first render. Ratios
are to the sea with no foam work, taken round by round (the two measured back to back), their
median given with their range, as `open_sea_cost.py` does. Run with `tools/bench whitecap_cost`.
"""

import math
import statistics
import sys
import tempfile
import time

import harness

WIND = 15.0
FRAMES = 24
EVAL_ROUNDS = 9
RENDER_ROUNDS = 4


def fade_without_foam(group):
    """A copy of `Water Sea Fade` with the crests and their trail taken out (the docstring)."""
    copy = group.copy()
    copy.name = f"{group.name} (no foam work)"
    nodes, links = copy.nodes, copy.links
    start = next(node for node in nodes if node.type == "GROUP_INPUT")
    end = next(node for node in nodes if node.type == "GROUP_OUTPUT")
    links.new(start.outputs["Geometry"], nodes["move"].inputs["Geometry"])
    links.new(nodes["move"].outputs["Geometry"], nodes["store_uv"].inputs["Geometry"])
    needed, todo = set(), [end]
    while todo:
        node = todo.pop()
        if node.name not in needed:
            needed.add(node.name)
            todo += [link.from_node for link in links if link.to_node == node]
    for node in [node for node in nodes if node.name not in needed]:
        nodes.remove(node)
    return copy


def shade_without_whitecaps(material):
    """The material's ocean shade swapped for a copy whose foam cover takes no whitecaps."""
    _normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(material)
    tree = shade.node_tree.copy()
    tree.name = f"{shade.node_tree.name} (no whitecaps)"
    shade.node_tree = tree
    cover = tree.nodes["foam_cover"].inputs[0]
    for link in [link for link in tree.links if link.to_socket == cover]:
        tree.links.remove(link)
    cover.default_value = 0.0


def point_data(scene, obj):
    """(positions, whether it stores `water_whitecaps`) of the evaluated sea."""
    import numpy as np

    mesh = obj.evaluated_get(scene.view_layers[0].depsgraph).data
    position = np.zeros(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", position)
    return position, "water_whitecaps" in mesh.attributes


def ratios(values, bases):
    """'median (low-high)' of the round-by-round ratios of `values` to `bases`."""
    found = sorted(v / b for v, b in zip(values, bases))
    return f"{statistics.median(found):.2f} ({found[0]:.2f}-{found[-1]:.2f})"


def evaluation_ms(scene, obj, fade_name):
    """(ms a frame to evaluate `obj`, the only sea in `scene`, over FRAMES frames, the fade's median
    execution_time in ms)."""
    fade_times = []
    start = time.perf_counter()
    for frame in range(1, FRAMES + 1):
        scene.frame_set(frame)
        evaluated = obj.evaluated_get(scene.view_layers[0].depsgraph)
        len(evaluated.data.vertices)
        fade_times.append(evaluated.modifiers[fade_name].execution_time * 1000.0)
    return (time.perf_counter() - start) * 1000.0 / FRAMES, statistics.median(fade_times)


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(width=192, height=108, samples=2)
    harness.set_world_color(scene, (0.45, 0.6, 0.8))
    look = (0.6, 0.8)
    from mathutils import Vector

    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 4.0
    up = math.radians(15.0)
    to_sun = (-look[0] * math.cos(up), -look[1] * math.cos(up), math.sin(up))
    sun.rotation_euler = Vector(to_sun).to_track_quat("Z", "Y").to_euler()
    scene.collection.objects.link(sun)
    harness.add_camera(scene, (2.0, -5.0, 12.0), (2.0 + 60.0 * look[0], -5.0 + 60.0 * look[1], 0.0))
    api = harness.addon("api")
    open_sea = harness.addon("water.sea.open_sea")
    scenes = {"Whitecaps": scene, "Whitecaps 0": scene.copy(), "No Foam Work": scene.copy()}

    def sea(name):
        scenes[name].name = name
        return api.add_water(
            scenes[name], preset="open_sea", sea_wind_speed=WIND, wind_direction=(0.8, 0.6), name=name
        ).object

    on = sea("Whitecaps")
    key_off = sea("Whitecaps 0")
    api.write_values(key_off, {"whitecaps": 0.0})
    bare = sea("No Foam Work")
    api.write_values(bare, {"whitecaps": 0.0})
    bare.active_material = bare.active_material.copy()
    shade_without_whitecaps(bare.active_material)
    _ocean, bare_fade = open_sea.sea_modifiers(bare)
    bare_fade.node_group = fade_without_foam(bare_fade.node_group)
    waters = {
        "whitecaps (the `open_sea` preset)": on,
        "`whitecaps` 0 (the preset key)": key_off,
        "no foam work (fade without crests and trail, shade without whitecaps)": bare,
    }
    base = "no foam work (fade without crests and trail, shade without whitecaps)"
    fade_names = {name: open_sea.sea_modifiers(obj)[1].name for name, obj in waters.items()}
    home = {name: obj.users_scene[0] for name, obj in waters.items()}
    for own in home.values():
        own.frame_set(12)
    on_points, on_stores = point_data(home[next(iter(waters))], on)
    bare_points, bare_stores = point_data(home[base], bare)
    moved = float(abs(on_points - bare_points).max())
    print(
        f"no foam work: points within {moved:.2e} m of the whitecaps sea's; "
        f"stores water_whitecaps: {bare_stores}"
    )
    if moved > 1e-4 or bare_stores or not on_stores:
        print("the sea without foam work is not the same sea: the comparison is off")
        return 1

    evaluation = {name: [] for name in waters}
    fade = {name: [] for name in waters}
    for _round in range(EVAL_ROUNDS):
        for name, obj in waters.items():
            total, own = evaluation_ms(home[name], obj, fade_names[name])
            evaluation[name].append(total)
            fade[name].append(own)
    out = tempfile.mkdtemp(prefix="water_surface_bench_")
    first, steady = {}, {name: [] for name in waters}
    for name in waters:
        home[name].frame_set(40)
        start = time.perf_counter()
        harness.render(home[name], f"{out}/first.png")
        first[name] = time.perf_counter() - start
    for _round in range(RENDER_ROUNDS):
        for name in waters:
            harness.render(home[name], f"{out}/switch.png")
            start = time.perf_counter()
            harness.render(home[name], f"{out}/steady.png")
            steady[name].append(time.perf_counter() - start)
    print(
        f"\nBlender {bpy.app.version_string}; open_sea at {WIND:g} m/s, {len(on.data.vertices)} points; "
        f"{FRAMES} frames, {EVAL_ROUNDS} rounds; renders 192 x 108, 2 samples, {RENDER_ROUNDS} rounds; "
        "ratios: the median of the rounds' (their range)"
    )
    print(
        "| sea | ms/frame (median) | / no foam work | fade ms (median) | first render s "
        "| steady render s | / no foam work |"
    )
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for name in waters:
        print(
            f"| {name} | {statistics.median(evaluation[name]):.1f} | "
            f"{ratios(evaluation[name], evaluation[base])} | {statistics.median(fade[name]):.2f} | "
            f"{first[name]:.2f} | {statistics.median(steady[name]):.2f} | "
            f"{ratios(steady[name], steady[base])} |"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
