"""Benchmark: what a floating object costs the open sea's evaluation per frame.

The `open_sea` preset (12 m/s, an 8 s swell, 385 x 385 points) alone, with one empty on a
Shrinkwrap constraint onto it (how objects floated by their origin before: Blender builds the
sea's ray-cast tree each frame), with a 25 x 6 x 4 m hull floating by its footprint (its rig, an
anchor and a pose whose modifier fits the plane, `water/boats/float_rig.py`), and with ten of
them. Milliseconds a frame over 24 frames (`frame_set`), in 5 interleaved rounds; ratios to the
water alone, round by round, median and range. Run with `tools/bench float_cost`;
`tools/bench float_cost --water=lake` (a 300 m lake at 0.5 m with its waves) or `--water=ocean`
(the seeds' ocean) for the others.
"""

import statistics
import sys
import tempfile
import time

import harness

FRAMES = 24
ROUNDS = 5


def hull(bpy, scene, at=(14.0, -9.0)):
    mesh = bpy.data.meshes.new("Hull")
    corners = [(x, y, z) for x in (-12.5, 12.5) for y in (-3.0, 3.0) for z in (-2.0, 2.0)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh.from_pydata(corners, [], faces)
    obj = bpy.data.objects.new("Hull", mesh)
    obj.location, obj.rotation_euler = (*at, 6.0), (0.0, 0.0, 0.6)
    scene.collection.objects.link(obj)
    return obj


def per_frame_ms(scene):
    start = time.perf_counter()
    for frame in range(1, FRAMES + 1):
        scene.frame_set(frame)
    return (time.perf_counter() - start) * 1000.0 / FRAMES


WATERS = ("open_sea", "lake", "ocean")  # `--water=lake`: the lake with its waves; `ocean`: the seeds'


def _water(api, scene, kind):
    if kind == "open_sea":
        return api.add_water(
            scene, preset="open_sea", sea_swell_height=3.0, sea_swell_period=8.0, see_surroundings=False
        ).object
    # 300 m at 0.5 m: about as many points as the open sea's (361,201 against 148,225 inside).
    water = api.add_water(scene, preset=kind, size=300.0, resolution=601, see_surroundings=False).object
    if kind == "lake":
        api.add_waves(water)
    return water


def main():
    asked = [arg.split("=", 1)[1] for arg in sys.argv if arg.startswith("--water=")]
    kind = asked[0] if asked else "open_sea"
    assert kind in WATERS, f"--water= is one of {WATERS}"
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(width=64, height=36, samples=1)
    api = harness.addon("api")
    sea = _water(api, scene, kind)
    probe = bpy.data.objects.new("Origin Float", None)
    scene.collection.objects.link(probe)
    wrap = probe.constraints.new("SHRINKWRAP")
    wrap.target, wrap.shrinkwrap_type, wrap.project_axis = sea, "PROJECT", "NEG_Z"
    wrap.use_project_opposite = True
    fleet = []  # each hull and its rig
    for index in range(10):
        before = {o for o in bpy.data.objects if o.get("water_surface_float_rig")}
        boat = hull(bpy, scene, at=(14.0 - 40.0 * (index % 5), -9.0 + 30.0 * (index // 5)))
        api.float_on_water(boat, sea, draft=1.5, wake=False)
        rig = [o for o in bpy.data.objects if o.get("water_surface_float_rig") and o not in before]
        fleet.append([boat, *rig])
    cases = {
        "the water alone": (),
        "+ one Shrinkwrap onto it (floating by the origin)": (probe,),
        "+ a hull floating by its footprint (its rig: an anchor and a pose)": tuple(fleet[0]),
        "+ ten hulls floating by their footprints": tuple(o for boat in fleet for o in boat),
    }
    extras = [probe, *(o for boat in fleet for o in boat)]
    times = {name: [] for name in cases}
    for _round in range(ROUNDS):
        for name, shown in cases.items():
            for obj in extras:
                obj.hide_viewport = obj not in shown
            times[name].append(per_frame_ms(scene))
    base = times["the water alone"]
    print(f"\nBlender {bpy.app.version_string}; {kind}; {FRAMES} frames, {ROUNDS} rounds")
    print("| case | ms/frame (median) | / the water alone (median, range) |")
    print("| --- | --- | --- |")
    for name, found in times.items():
        ratios = sorted(t / b for t, b in zip(found, base))
        print(
            f"| {name} | {statistics.median(found):.1f} | "
            f"{statistics.median(ratios):.2f} ({ratios[0]:.2f}-{ratios[-1]:.2f}) |"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
