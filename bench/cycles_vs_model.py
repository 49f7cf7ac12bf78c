"""How far Cycles is from the reference model with the same `Water Surface` group.

Renders the test lake in Cycles: the F view against numpy's dot(eye, up) (flat
water), and the final view against the model's composition of the reflection,
refraction, F and glint views. Run with `tools/bench cycles_vs_model`.
"""

import sys
import tempfile

import numpy as np
from reference_models import lake_composition, lake_fresnel

import harness

SAMPLES = 64


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = harness.clean_scene(engine="CYCLES", width=128, height=72, samples=SAMPLES)
    scene.cycles.device = "CPU"
    scene.cycles.use_denoising = False
    harness.set_world_color(scene, (0.4, 0.6, 0.9))
    material = harness.addon("nodes.material").make_water_material(scene=scene)
    node = harness.addon("nodes.material").water_node(material)
    bpy.ops.mesh.primitive_plane_add(size=8)
    bpy.context.object.data.materials.append(material)
    floor = harness.emission_material("Floor", (1, 0.1, 0.05))
    harness.add_cube(scene, (0, 0, -1.2), size=2.0, material=floor)
    camera = harness.add_camera(scene, (0, -6, 2.5), (0, 0, 0))
    out = tempfile.mkdtemp(prefix="water_surface_cycles_")

    origin, directions = harness.pixel_rays(scene, camera)
    hits, ok = harness.hit_plane_z(origin, directions)
    mask = ok & (np.abs(hits[..., 0]) < 3.7) & (np.abs(hits[..., 1]) < 3.7)
    expected_f = lake_fresnel(origin - hits)

    node.inputs["Bump Strength"].default_value = 0.0
    node.inputs["Debug View"].default_value = 3
    f_flat = harness.render(scene, f"{out}/f.exr", exr=True)[..., 0]
    print(f"F view (flat) vs dot(eye, up): mean |error| {np.abs(f_flat - expected_f)[mask].mean():.4f}")

    node.inputs["Bump Strength"].default_value = 1.0
    views = {}
    for number in (0, 1, 2, 3, 5):
        node.inputs["Debug View"].default_value = number
        views[number] = harness.render(scene, f"{out}/v{number}.exr", exr=True)[..., :3]
    # The lake's defaults, SPEC section 1: dull colour (0.3, 0.3, 0.5) at 0.2.
    model = lake_composition(views[1], views[2], views[3][..., :1], 0.2, (0.3, 0.3, 0.5), views[5])
    error = np.abs(views[0] - model)[mask]
    scale = np.abs(views[0])[mask].mean()
    print(
        f"final vs composition of views ({SAMPLES} samples): mean |error| {error.mean():.4f} "
        f"({100 * error.mean() / scale:.1f}% of the mean value {scale:.3f})"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
