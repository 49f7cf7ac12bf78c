"""Every frame of the gale shot renders within 4 times the median (issue 57 point 1).

`open_sea` at 25 m/s, wind (0.8, 0.6), a camera 3 m over the rest level looking far out, 160 x 90,
one sample, EEVEE (software on a machine without a GPU): frames 150-250 (`--first`, `--last`),
each frame's CPU seconds in one process after a first render that compiles the shader, then the
median, the slowest and its ratio to the median. Frame 201 never finished before the sea's UV map
followed the drawn points and the whitecaps' lace was read nearest-texel (`tests/test_no_hang.py`).
Run with `tools/bench gale_frames` (`tools/bench gale_frames --wind=15 --riding`: 15 m/s, the
camera 3 m over the surface under it, as `tests/test_sea_band.py` places it).
"""

import argparse
import statistics
import sys
import tempfile
import time

import harness


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--first", type=int, default=150)
    parser.add_argument("--last", type=int, default=250)
    parser.add_argument("--wind", type=float, default=25.0)
    parser.add_argument("--riding", action="store_true", help="3 m over the surface under the camera")
    args = parser.parse_args(sys.argv[1:])

    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(width=160, height=90, samples=1)
    harness.set_world_color(scene, (0.45, 0.6, 0.8), 1.0)
    water = (
        harness.addon("api")
        .add_water(scene, preset="open_sea", sea_wind_speed=args.wind, wind_direction=(0.8, 0.6))
        .object
    )
    camera = harness.add_camera(scene, (0.0, 0.0, 3.0), (300.0, 1000.0, -87.0), lens=28.0)
    camera.data.clip_end = 30000.0
    scene.camera = camera
    out = tempfile.mkdtemp(prefix="water_surface_gale_")

    def render(frame):
        scene.frame_set(frame)
        if args.riding:
            camera.location.z = harness.surface_below(water, 0.0, 0.0) + 3.0
            bpy.context.view_layer.update()
        start = time.process_time()
        harness.render(scene, f"{out}/gale_{frame}.png")
        return time.process_time() - start

    render(args.first)  # compiles the shader
    seconds = {}
    for frame in range(args.first, args.last + 1):
        seconds[frame] = render(frame)
        print(f"frame {frame}: {seconds[frame]:.1f} s CPU", flush=True)
    median = statistics.median(seconds.values())
    slowest = max(seconds, key=seconds.get)
    print(
        f"{args.wind:g} m/s, {'riding' if args.riding else 'rest level'}, frames {args.first}-{args.last}: "
        f"median {median:.1f} s CPU, slowest frame {slowest} {seconds[slowest]:.1f} s "
        f"({seconds[slowest] / median:.2f}x the median; target at most 4x)"
    )


if __name__ == "__main__":
    main()
