"""The main job: renders the demo scene with the add-on installed from its zip.

Run through `tools/demo`, which sets up the venv first.
"""

import sys
import tempfile
from pathlib import Path

import harness

OUT = harness.ROOT / "out"


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(width=480, height=270, samples=16)
    harness.set_world_color(scene, (0.35, 0.55, 0.85))
    harness.add_cube(scene, (0, 0, 0.5), material=harness.emission_material("Glow", (1, 0.6, 0.2), 2))
    harness.add_camera(scene, (5, -6, 3), (0, 0, 0.5))
    print(f"rendering the demo with Blender {bpy.app.version_string} ...", flush=True)
    harness.render(scene, OUT / "demo.png")
    print(f"wrote {Path(OUT / 'demo.png')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
