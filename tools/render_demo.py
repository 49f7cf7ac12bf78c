"""The main job: renders the demo images with the add-on installed from its zip.

A lake after the seeds' test scene, turned Z-up: a sky, the 128 x 128 water at
height 0 added with the add-on's own operator, a white glossy sphere on the
right, a rock cube scaled 4 on the left, a floor below the water and a sun for
the glint. Writes out/demo.png (the final view, with the reflection-only and
refraction-only views as insets, as the seeds' test draws its two maps) and
out/demo_frames.png (a strip of frames a second apart: the water moves), and
copies both to docs/. Run through `tools/demo`.
"""

import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import harness

OUT = harness.ROOT / "out"
DOCS = harness.ROOT / "docs"

MAIN_SIZE = (640, 360)
SAMPLES = 16
INSET_SCALE = 4  # an inset is 1/4 of the main image's width and height
INSET_MARGIN = 8
BORDER = 2
BORDER_COLOR = (0.95, 0.95, 0.95)
STRIP_SIZE = (320, 180)
STRIP_SAMPLES = 8  # software EEVEE's time is mostly per sample; small frames need fewer
STRIP_TIMES = (0.0, 1.0, 2.0, 3.0)  # seconds on the scene clock
STRIP_GAP = 4

SKY_ZENITH = (0.06, 0.2, 0.58)
SKY_HORIZON = (0.5, 0.64, 0.82)
SKY_GROUND = (0.35, 0.4, 0.45)  # below the horizon: only seen past the water's far edge


class Progress:
    """Numbered progress lines with the seconds since the start, flushed at once."""

    def __init__(self, total):
        self.total = total
        self.step = 0
        self.start = time.monotonic()

    def elapsed(self):
        return time.monotonic() - self.start

    def __call__(self, what):
        self.step += 1
        print(f"[{self.step}/{self.total}] {what} ... ({self.elapsed():.0f} s so far)", flush=True)


# --- materials -------------------------------------------------------------


def _new_material(bpy, name):
    """A material with its default Principled BSDF (node use is implicit from Blender 5.0)."""
    material = bpy.data.materials.new(name)
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    return material, material.node_tree.nodes["Principled BSDF"]


def _ramp(nodes, stops):
    """A Color Ramp node with `stops` as (position, rgb) pairs."""
    ramp = nodes.new("ShaderNodeValToRGB")
    elements = ramp.color_ramp.elements
    while len(elements) < len(stops):
        elements.new(0.5)
    for element, (position, color) in zip(elements, stops):
        element.position = position
        element.color = (*color, 1.0)
    return ramp


def glossy_material(bpy, name, color, roughness):
    """A plain Principled BSDF: the seeds' white sphere with a sharp highlight."""
    material, bsdf = _new_material(bpy, name)
    bsdf.inputs["Base Color"].default_value = (*color, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    return material


def rock_material(bpy):
    """A procedural rock (the seeds' cube is rock-textured): mottled noise, Voronoi cracks, bumped."""
    material, bsdf = _new_material(bpy, "Rock")
    nodes, links = material.node_tree.nodes, material.node_tree.links
    coords = nodes.new("ShaderNodeTexCoord")
    noise = nodes.new("ShaderNodeTexNoise")
    noise.inputs["Scale"].default_value = 6.0
    noise.inputs["Detail"].default_value = 10.0
    noise.inputs["Roughness"].default_value = 0.6
    cracks = nodes.new("ShaderNodeTexVoronoi")
    cracks.feature = "DISTANCE_TO_EDGE"
    cracks.inputs["Scale"].default_value = 3.0
    cracks.inputs["Randomness"].default_value = 0.8
    mottle = _ramp(nodes, [(0.35, (0.16, 0.14, 0.12)), (0.65, (0.5, 0.46, 0.4))])
    crack_ramp = _ramp(nodes, [(0.0, (0.2, 0.2, 0.2)), (0.025, (1.0, 1.0, 1.0))])
    color = nodes.new("ShaderNodeMix")
    color.data_type = "RGBA"
    color.blend_type = "MULTIPLY"
    color.inputs["Factor"].default_value = 1.0
    height = nodes.new("ShaderNodeMath")
    height.operation = "MULTIPLY_ADD"
    height.inputs[1].default_value = 0.5
    bump = nodes.new("ShaderNodeBump")
    bump.inputs["Strength"].default_value = 0.7
    bump.inputs["Distance"].default_value = 0.05
    links.new(coords.outputs["Object"], noise.inputs["Vector"])
    links.new(coords.outputs["Object"], cracks.inputs["Vector"])
    links.new(noise.outputs["Fac"], mottle.inputs["Fac"])
    links.new(cracks.outputs["Distance"], crack_ramp.inputs["Fac"])
    links.new(mottle.outputs["Color"], color.inputs["A"])
    links.new(crack_ramp.outputs["Color"], color.inputs["B"])
    links.new(noise.outputs["Fac"], height.inputs[0])
    links.new(crack_ramp.outputs["Color"], height.inputs[2])
    links.new(height.outputs["Value"], bump.inputs["Height"])
    links.new(color.outputs["Result"], bsdf.inputs["Base Color"])
    links.new(bump.outputs["Normal"], bsdf.inputs["Normal"])
    bsdf.inputs["Roughness"].default_value = 0.55
    return material


def floor_material(bpy):
    """Sandy tiles: a pattern that shows the refraction's wobble under the water."""
    material, bsdf = _new_material(bpy, "Floor")
    nodes, links = material.node_tree.nodes, material.node_tree.links
    coords = nodes.new("ShaderNodeTexCoord")
    checker = nodes.new("ShaderNodeTexChecker")
    checker.inputs["Scale"].default_value = 0.5
    checker.inputs["Color1"].default_value = (0.55, 0.48, 0.33, 1.0)
    checker.inputs["Color2"].default_value = (0.3, 0.25, 0.17, 1.0)
    links.new(coords.outputs["Object"], checker.inputs["Vector"])
    links.new(checker.outputs["Color"], bsdf.inputs["Base Color"])
    bsdf.inputs["Roughness"].default_value = 0.9
    return material


# --- scene -----------------------------------------------------------------


def add_sky(bpy, scene):
    """A world whose colour runs from the horizon to the zenith: what the water mirrors most."""
    world = harness.set_world_color(scene, SKY_HORIZON)
    nodes, links = world.node_tree.nodes, world.node_tree.links
    coords = nodes.new("ShaderNodeTexCoord")
    split = nodes.new("ShaderNodeSeparateXYZ")
    ramp = _ramp(nodes, [(0.0, SKY_GROUND), (0.5, SKY_HORIZON), (0.7, SKY_ZENITH)])
    # The view direction's height (-1..1) mapped to 0..1 for the ramp.
    to_unit = nodes.new("ShaderNodeMapRange")
    to_unit.inputs["From Min"].default_value = -1.0
    links.new(coords.outputs["Generated"], split.inputs["Vector"])
    links.new(split.outputs["Z"], to_unit.inputs["Value"])
    links.new(to_unit.outputs["Result"], ramp.inputs["Fac"])
    links.new(ramp.outputs["Color"], nodes["Background"].inputs["Color"])
    return world


def add_sun(bpy, scene):
    """A low sun straight ahead: its glint lies on the water between the sphere and the cube."""
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 4.0
    sun.data.angle = 0.02
    sun.rotation_euler = (-1.33, 0.0, -0.04)
    scene.collection.objects.link(sun)
    return sun


def add_fill(bpy, scene):
    """A shadowless sun from behind the camera: the backlit sphere and cube read and mirror clearly.

    Added after the water, so the glint stays bound to the low sun ahead.
    """
    fill = bpy.data.objects.new("Fill", bpy.data.lights.new("Fill", "SUN"))
    fill.data.energy = 1.5
    fill.data.use_shadow = False
    fill.rotation_euler = (0.9, 0.0, -0.5)
    scene.collection.objects.link(fill)
    return fill


def add_water(bpy):
    """The seeds' lake through the add-on's own operator (it also runs the mirror set-up)."""
    result = bpy.ops.object.water_surface_add(size=128, location=(0.0, 0.0, 0.0))
    if result != {"FINISHED"}:
        raise RuntimeError(f"object.water_surface_add returned {result}")
    return bpy.context.active_object


def add_props(bpy, scene):
    """Sphere on the right, rock cube on the left (both partly under water) and the floor."""
    bpy.ops.mesh.primitive_uv_sphere_add(radius=2.0, location=(5.0, 6.0, 1.2), segments=64, ring_count=32)
    bpy.ops.object.shade_smooth()
    bpy.context.object.name = "Sphere"
    bpy.context.object.data.materials.append(glossy_material(bpy, "White Gloss", (0.9, 0.9, 0.9), 0.08))
    rock = harness.add_cube(scene, (-5.0, 7.0, 1.2), size=1.0, material=rock_material(bpy), name="Rock")
    rock.scale = (4.0, 4.0, 4.0)
    rock.rotation_euler = (0.0, 0.0, 0.35)
    bpy.ops.mesh.primitive_plane_add(size=128, location=(0.0, 0.0, -2.0))
    bpy.context.object.name = "Floor"
    bpy.context.object.data.materials.append(floor_material(bpy))


def build_scene(bpy):
    """The whole demo scene, seen by the main camera; returns (scene, water, strip camera)."""
    scene = harness.clean_scene(width=MAIN_SIZE[0], height=MAIN_SIZE[1], samples=SAMPLES)
    add_sky(bpy, scene)
    add_sun(bpy, scene)  # before the water: the operator binds the glint to the scene's first sun
    add_props(bpy, scene)
    water = add_water(bpy)
    add_fill(bpy, scene)
    strip_camera = harness.add_camera(scene, (2.0, -5.0, 2.2), (4.0, 6.0, 0.2), lens=30)
    strip_camera.name = "Strip Camera"
    harness.add_camera(scene, (0.0, -14.0, 4.0), (0.0, 8.0, 0.5), lens=32)  # the last added is active
    return scene, water, strip_camera


# --- images ----------------------------------------------------------------

# A 3 x 5 pixel font for the labels: each glyph is five rows of three bits.
_FONT = {
    "A": "010101111101101",
    "C": "011100100100011",
    "E": "111100110100111",
    "F": "111100110100100",
    "I": "111010010010111",
    "L": "100100100100111",
    "N": "101111111111101",
    "O": "010101101101010",
    "R": "110101110101101",
    "S": "011100010001110",
    "T": "111010010010010",
    "0": "111101101101111",
    "1": "010110010010111",
    "2": "110001010100111",
    "3": "110001010001110",
    "4": "101101111001001",
    "5": "111100110001110",
    "6": "011100111101111",
    "7": "111001010010010",
    "8": "111101111101111",
    "9": "111101111001110",
    ".": "000000000000010",
    " ": "000000000000000",
}


def draw_label(image, text, x, y, scale=2, color=(1.0, 1.0, 1.0)):
    """Writes `text` at (x, y) (top-left, row 0 at the top) on a dark box, in place."""
    width = (4 * len(text) + 1) * scale
    image[y : y + 7 * scale, x : x + width, :3] *= 0.35
    for index, char in enumerate(text.upper()):
        bits = np.array([int(b) for b in _FONT[char]], dtype=bool).reshape(5, 3)
        glyph = np.kron(bits, np.ones((scale, scale), dtype=bool))
        top, left = y + scale, x + (4 * index + 1) * scale
        image[top : top + 5 * scale, left : left + 3 * scale, :3][glyph] = color


def shrink(pixels, factor):
    """Box-filters (H, W, 4) pixels down by an integer factor: a clean, unaliased inset."""
    height, width = pixels.shape[0] // factor, pixels.shape[1] // factor
    cropped = pixels[: height * factor, : width * factor]
    return cropped.reshape(height, factor, width, factor, -1).mean(axis=(1, 3))


def paste(image, small, x, y, label):
    """Puts `small` into `image` at (x, y) inside a thin border, with its label."""
    height, width = small.shape[:2]
    image[y - BORDER : y + height + BORDER, x - BORDER : x + width + BORDER, :3] = BORDER_COLOR
    image[y : y + height, x : x + width] = small
    draw_label(image, label, x + 3, y + 3)


def compose_insets(main, reflection, refraction):
    """The main view with the reflection and refraction views as insets in the sky, top right."""
    image = main.copy()
    height, width = reflection.shape[:2]
    y = INSET_MARGIN
    right = image.shape[1] - INSET_MARGIN - width
    paste(image, refraction, right, y, "refraction")
    paste(image, reflection, right - INSET_MARGIN - width, y, "reflection")
    return image


def tile_strip(frames, labels):
    """Frames side by side with a white gap between them, each labelled with its time."""
    height, width = frames[0].shape[:2]
    strip = np.ones((height, len(frames) * (width + STRIP_GAP) - STRIP_GAP, 4), dtype=np.float32)
    for index, (frame, label) in enumerate(zip(frames, labels)):
        left = index * (width + STRIP_GAP)
        strip[:, left : left + width] = frame
        draw_label(strip, label, left + 4, 4)
    return strip


def save_png(bpy, pixels, path):
    """Saves display-space pixels (H, W, 4), top row first, as an 8-bit PNG through a bpy image."""
    height, width = pixels.shape[:2]
    image = bpy.data.images.new(Path(path).stem, width, height, alpha=True, float_buffer=False)
    try:
        flat = np.clip(pixels, 0.0, 1.0).astype(np.float32)
        flat[..., 3] = 1.0
        image.pixels.foreach_set(flat[::-1].ravel())  # bpy images are bottom row first
        image.filepath_raw = str(path)
        image.file_format = "PNG"
        image.save()
    finally:
        bpy.data.images.remove(image)
    return path


# --- renders ---------------------------------------------------------------


def render_views(scene, water, work, progress):
    """The final view, then the reflection-only and refraction-only views (Debug View 1 and 2)."""
    debug = harness.addon("nodes.material").water_node(water.active_material).inputs["Debug View"]
    progress(f"main view, {MAIN_SIZE[0]} x {MAIN_SIZE[1]}")
    main = harness.render(scene, work / "main.png")
    # The insets are rendered at half size and box-filtered down by 2 more: a quarter of the width.
    scene.render.resolution_percentage = 100 * 2 // INSET_SCALE
    views = {}
    try:
        for number, name in ((1, "reflection"), (2, "refraction")):
            progress(f"{name} only (Debug View {number})")
            debug.default_value = number
            views[name] = shrink(harness.render(scene, work / f"{name}.png"), 2)
    finally:
        debug.default_value = 0
        scene.render.resolution_percentage = 100
    return compose_insets(main, views["reflection"], views["refraction"])


def render_strip(scene, camera, work, progress):
    """Frames STRIP_TIMES apart from a closer camera: the bump scrolls with the scene's clock.

    The lake's own wind (0.02 plane-UV/s, 2.6 m/s on the 128 m plane) moves the
    ripples about a fifth of a wave per second, which shows from close by, so
    the strip keeps the preset's values.
    """
    scene.camera = camera
    scene.render.resolution_x, scene.render.resolution_y = STRIP_SIZE
    scene.eevee.taa_render_samples = STRIP_SAMPLES
    fps = scene.render.fps / scene.render.fps_base
    frames, labels = [], []
    for seconds in STRIP_TIMES:
        frame = round(seconds * fps)
        progress(f"frame {frame} (t = {seconds:.1f} s), {STRIP_SIZE[0]} x {STRIP_SIZE[1]}")
        scene.frame_set(frame)  # the water's clock is a driver on the frame
        frames.append(harness.render(scene, work / f"frame_{frame:03d}.png"))
        labels.append(f"{seconds:.1f} s")
    return tile_strip(frames, labels)


def main():
    progress = Progress(total=3 + len(STRIP_TIMES))
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    scene, water, strip_camera = build_scene(bpy)
    print(
        f"rendering the demo with Blender {bpy.app.version_string} (software EEVEE: a few minutes)",
        flush=True,
    )
    OUT.mkdir(parents=True, exist_ok=True)
    DOCS.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="water_surface_demo_") as tmp:
        work = Path(tmp)
        demo = save_png(bpy, render_views(scene, water, work, progress), OUT / "demo.png")
        strip = save_png(bpy, render_strip(scene, strip_camera, work, progress), OUT / "demo_frames.png")
    for path in (demo, strip):
        shutil.copyfile(path, DOCS / path.name)
        print(f"wrote {path} and {DOCS / path.name}", flush=True)
    print(f"done in {progress.elapsed():.0f} s", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
