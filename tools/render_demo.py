"""The main job: renders the demo scene with the add-on installed from its zip.

A lake after the seeds' test scene (Z-up): sky, 128 x 128 water at height 0, a
white glossy sphere on the right, a cube scaled 4 on the left, a floor below
the water, and a sun for the glint. Run through `tools/demo`.
"""

import sys
import tempfile

import harness

OUT = harness.ROOT / "out"


def _glossy(bpy, name, color, roughness):
    material = bpy.data.materials.new(name)
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    bsdf = material.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*color, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    return material


def build_scene(bpy):
    scene = harness.clean_scene(width=640, height=360, samples=16)
    harness.addon("engine").enable_ray_tracing(scene)
    harness.set_world_color(scene, (0.25, 0.45, 0.85), strength=1.0)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (1.2, 0.0, 0.6)
    scene.collection.objects.link(sun)
    water = harness.addon("nodes.material").make_water_material("Lake", scene=scene)
    bpy.ops.mesh.primitive_plane_add(size=128)
    bpy.context.object.name = "Water"
    bpy.context.object.data.materials.append(water)
    bpy.ops.mesh.primitive_uv_sphere_add(radius=2.0, location=(6, 10, 2.5), segments=48, ring_count=24)
    bpy.ops.object.shade_smooth()
    bpy.context.object.data.materials.append(_glossy(bpy, "White Gloss", (0.9, 0.9, 0.9), 0.05))
    rock = harness.add_cube(
        scene, (-7, 14, 1.0), size=1.0, material=_glossy(bpy, "Rock", (0.35, 0.3, 0.25), 0.8)
    )
    rock.scale = (4, 4, 4)
    floor_material = _glossy(bpy, "Floor", (0.5, 0.45, 0.3), 0.9)
    harness.add_cube(scene, (0, 0, -3.0), size=1.0, material=floor_material).scale = (128, 128, 1)
    harness.add_camera(scene, (0, -14, 5), (0, 10, 0), lens=30)
    return scene


def main():
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene = build_scene(bpy)
    print(
        f"rendering the demo with Blender {bpy.app.version_string} (software EEVEE: about a minute) ...",
        flush=True,
    )
    harness.render(scene, OUT / "demo.png")
    print(f"wrote {OUT / 'demo.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
