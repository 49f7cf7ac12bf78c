"""Benchmark: what `Light Shafts` and the caustic light cost a camera under the water (issue 40
point 5).

The scene of tests/test_caustic_light.py (a camera 0.8 m under the default lake with caustics,
a white cube on a white bed 3 m down, a sun 55 degrees high), 160 x 120, Cycles 32 samples
(`--eevee`: EEVEE 8), rendered with Light Shafts 1 ("on"), with 0 ("off"), with the fog's scatter
taken out of its group ("no scatter": the fog before Light Shafts) and with 0 and the caustic
light hidden ("no light"), in interleaved rounds after a first render each; the ratios are taken
round by round and given as the median with their range. Run with `tools/bench light_shafts_cost`.
"""

import statistics
import sys
import tempfile
import time

import harness

ROUNDS = 3


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    sys.path.insert(0, str(harness.ROOT / "tests"))
    from test_caustic_light import _build

    eevee = "--eevee" in sys.argv
    scene, added, _camera = _build(harness.addon("engine").eevee_engine_id() if eevee else "CYCLES")
    scene.render.resolution_x, scene.render.resolution_y = 160, 120
    scene.cycles.samples = 32
    scene.eevee.taa_render_samples = 8
    underwater = harness.addon("water.underwater")
    light = underwater.find(added.object, underwater.LIGHT_ROLE)
    api = harness.addon("api")
    group = bpy.data.node_groups[harness.addon("nodes.under.underwater_fog").NAME]
    scatter_link = next(link for link in group.links if link.from_node.name == "shafts")
    to_socket = scatter_link.to_socket
    out = tempfile.mkdtemp(prefix="water_surface_bench_")

    def state(name):
        api.set_light_shafts(added.object, 1.0 if name == "on" else 0.0)
        light.hide_render = name == "no light"
        linked = any(link.from_node.name == "shafts" for link in group.links)
        if name == "none" and linked:
            group.links.remove(next(link for link in group.links if link.from_node.name == "shafts"))
        elif name != "none" and not linked:
            group.links.new(group.nodes["shafts"].outputs[0], to_socket)

    def render_s():
        start = time.perf_counter()
        harness.render(scene, f"{out}/shafts.png")
        return time.perf_counter() - start

    names = ("on", "off", "none", "no light")
    times = {name: [] for name in names}
    for name in names:  # a first render each, not counted
        state(name)
        render_s()
    for _round in range(ROUNDS):
        for name in names:
            state(name)
            times[name].append(render_s())
            print(f"  {name}: {times[name][-1]:.1f} s", flush=True)

    def ratio(a, b):
        found = sorted(x / y for x, y in zip(times[a], times[b]))
        return f"{statistics.median(found):.2f} ({found[0]:.2f}-{found[-1]:.2f})"

    engine = "EEVEE 8" if eevee else "Cycles 32"
    print(f"\nBlender {bpy.app.version_string}; {engine} samples, 160 x 120, {ROUNDS} rounds")
    print("| on s | off s | no scatter s | no light s | on / off | off / no scatter | off / no light |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    seconds = " | ".join(f"{statistics.median(times[name]):.1f}" for name in names)
    print(f"| {seconds} | {ratio('on', 'off')} | {ratio('off', 'none')} | {ratio('off', 'no light')} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
