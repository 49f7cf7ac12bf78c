"""Renders the open sea: with whitecaps and a floating boat-like object (out/open_sea.png), and
meeting a low sandy island (out/open_sea_shore.png: the bed through the shallows, shore foam,
caustics); and the sea states (out/open_sea_states.png): 5, 15 and 25 m/s (columns) from 3 m and
from 40 m up (rows), each with the boat (`tools/demo sea states`). The sky is the ocean demo's
generated image (`render_ocean.sky_world`); the seas are the `open_sea` preset at 15 and 6 m/s;
the boat (a hull and a cabin, joined) floats with `api.float_on_water`. Run with `tools/demo sea`
(`tools/demo sea shore`: the island only; `tools/demo --docs sea ...`: copied to docs/ too).
"""

import math
import struct
import sys
import tempfile
import time
import zlib

from demo_output import OUT, publish
from render_ocean import sky_world

import harness

SIZE = (640, 360)
# The sun lamp where the sky image has its sun (`render_ocean.SUN_DIRECTION`: straight ahead,
# 16.3 degrees up): the sea reflects both, so one elsewhere glitters where no sun is.
SKY_SUN = (73.7, 0.0, 180.0)


def boat(bpy):
    """A 6 m hull with a cabin, one object, origin at the waterline."""
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 0.0, 0.3))
    hull = bpy.context.active_object
    hull.scale = (6.0, 2.2, 1.2)
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(-0.8, 0.0, 1.3))
    cabin = bpy.context.active_object
    cabin.scale = (2.2, 1.6, 1.0)
    for obj in (hull, cabin):
        obj.select_set(True)
    bpy.context.view_layer.objects.active = hull
    bpy.ops.object.transform_apply(scale=True)
    bpy.ops.object.join()
    hull.data.materials.append(harness.lit_material("Boat", (0.6, 0.12, 0.08)))
    hull.name = "Boat"
    hull.location = (3.0, 16.0, 0.0)
    hull.rotation_euler = (0.0, 0.0, math.radians(35.0))
    return hull


def island(bpy):
    """A sandy cone 600 m across, its top 2 m out of the water, sloping 1 in 7 to 40 m deep."""
    bpy.ops.mesh.primitive_cone_add(vertices=96, radius1=300.0, radius2=0.0, depth=42.0)
    cone = bpy.context.active_object
    cone.name = "Island"
    cone.location = (-10.0, 50.0, -19.0)
    cone.data.materials.append(harness.lit_material("Sand", (0.8, 0.62, 0.38), roughness=0.9))
    return cone


def sunny_sea(bpy, sun_rotation, wind_speed, before_sea=None):
    """A scene with the generated sky, a sun (Euler angles in degrees) and the `open_sea` preset
    at `wind_speed`; `before_sea()` adds what the sea must find below it. Returns (scene, water)."""
    scene = harness.clean_scene(width=SIZE[0], height=SIZE[1], samples=8)
    sky_world(bpy, scene)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = [math.radians(angle) for angle in sun_rotation]
    scene.collection.objects.link(sun)
    if before_sea is not None:
        before_sea()  # the sea gathers the objects that reach below it when it is added
    added = harness.addon("api").add_water(
        scene,
        preset="open_sea",
        sea_wind_speed=wind_speed,
        wind_direction=(0.8, 0.6),
        caustics=1.0 if before_sea is not None else 0.0,  # on the shallows round an island
    )
    print(added.summary("open_sea"), flush=True)
    return scene, added.object


def render(bpy, scene, name, what):
    """Renders frame 60 to out/<name>.png; returns its path."""
    scene.frame_set(60)
    print(f"[{name}] {what}, {SIZE[0]} x {SIZE[1]}, Blender {bpy.app.version_string} ...", flush=True)
    harness.render(scene, OUT / f"{name}.png")
    return OUT / f"{name}.png"


STATES = (5.0, 15.0, 25.0)  # m/s: a gentle breeze, a near gale, a storm (Beaufort 3, 7, 10)
STATE_SIZE = (480, 270)
VIEWS = (((0.0, -4.0, 3.0), (6.0, 40.0, 0.0)), ((0.0, -70.0, 40.0), (12.0, 90.0, 0.0)))


def write_png(path, rgb):
    """An 8-bit RGB PNG of a float (H, W, 3) array, row 0 at the top."""
    import numpy as np

    data = (np.clip(rgb, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)
    raw = b"".join(b"\0" + row.tobytes() for row in data)

    def chunk(kind, body):
        return (
            struct.pack(">I", len(body))
            + kind
            + body
            + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
        )

    header = struct.pack(">IIBBBBB", data.shape[1], data.shape[0], 8, 2, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(
            b"\x89PNG\r\n\x1a\n"
            + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(raw))
            + chunk(b"IEND", b"")
        )


def sea_states(bpy):
    """The sea at each of STATES from each of VIEWS, with the boat, as one sheet (columns: the
    winds; rows: 3 m and 40 m up)."""
    import numpy as np

    tiles = {}
    for wind in STATES:
        scene, sea = sunny_sea(bpy, SKY_SUN, wind)
        scene.render.resolution_x, scene.render.resolution_y = STATE_SIZE
        harness.addon("api").float_on_water(boat(bpy), sea, tilt_damping=0.3)
        for row, (eye, target) in enumerate(VIEWS):
            camera = harness.add_camera(scene, eye, target, lens=28)
            camera.data.clip_end = 20000.0
            scene.camera = camera
            scene.frame_set(60)
            name = f"open_sea_{wind:g}_{eye[2]:g}m"
            print(f"[{name}] {wind:g} m/s from {eye[2]:g} m up ...", flush=True)
            tiles[row, wind] = harness.render(scene, OUT / f"{name}.png")[..., :3]
    sheet = np.concatenate(
        [np.concatenate([tiles[row, wind] for wind in STATES], axis=1) for row in range(len(VIEWS))], axis=0
    )
    write_png(OUT / "open_sea_states.png", sheet)


def main():
    start = time.monotonic()
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    OUT.mkdir(parents=True, exist_ok=True)
    if sys.argv[1:] == ["states"]:
        sea_states(bpy)
        publish(OUT / "open_sea_states.png", note=f"in {time.monotonic() - start:.0f} s")
        return 0
    # The open sea at 6 m/s round a sandy island, from 14 m up.
    scene, _sea = sunny_sea(bpy, (45.0, 0.0, 150.0), 6.0, before_sea=lambda: island(bpy))
    harness.add_camera(scene, (6.0, -2.0, 14.0), (-4.0, 34.0, 0.0), lens=30)
    shore = render(bpy, scene, "open_sea_shore", "open sea round an island")
    publish(shore, note=f"in {time.monotonic() - start:.0f} s")
    if sys.argv[1:] == ["shore"]:
        return 0
    # The open sea at 15 m/s with a boat floating on it, from 3 m up.
    scene, sea = sunny_sea(bpy, (70.0, 0.0, 180.0), 15.0)
    harness.addon("api").float_on_water(boat(bpy), sea, tilt_damping=0.3)
    harness.add_camera(scene, (0.0, -4.0, 3.0), (6.0, 40.0, 0.0), lens=28)
    publish(render(bpy, scene, "open_sea", "open sea"), note=f"in {time.monotonic() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
