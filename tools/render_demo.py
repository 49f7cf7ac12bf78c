"""The main job: renders the demo images with the add-on installed from its zip.

A lake after the seeds' test scene, turned Z-up: a sky, the 128 x 128 water at
height 0 added with the add-on's own operator, a white glossy sphere on the
right, a rock cube scaled 4 on the left, a floor below the water and a sun for
the glint. Writes out/demo.png (the final view, with the reflection-only and
refraction-only views as insets, as the seeds' test draws its two maps) and
out/demo_frames.png (a strip of frames a second apart: the water moves).

Then the same lake at the shore, out/demo_shore.png: the sphere, the rock, the
sky and the suns again, but the floor is a sandy bed rising through the surface
on the right into a beach, a short pier's posts stand in the shallows, and the
water is the `tropical_shallows` preset. The bed and the posts are made before
the water, so adding it gathers them as its surroundings: the water colours by
depth (Beer-Lambert), foams along the waterline and around what stands in it, and
the sun's caustics play on the sand under it. Its insets are the transmittance, foam and
caustics views (Debug View 6, 7 and 8).

With `tools/demo --docs` all three are copied to docs/ too (`demo_output.publish`).
Run through `tools/demo` (`tools/demo shore` renders only the shore image;
`--preview` renders it small and quick, to out/ only, for looking at a change).
"""

import math
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from demo_output import OUT, publish

import harness

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

SHORE_PRESET = "tropical_shallows"
PREVIEW_PERCENT = 50  # `--preview`: the shore image at half size, PREVIEW_SAMPLES samples
PREVIEW_SAMPLES = 4
# The beach: the waterline runs from (5, -6) away to the right (about (14, 24)); `inland` is the distance
# inland, across it. The bed rises gently under the shallows, more steeply in the deep.
SHORE_POINT = (5.0, -6.0)
SHORE_INLAND = (0.958, -0.288)  # unit normal to the waterline, pointing up the beach
BED_SIZE = 140.0  # more than the water: depth is measured under every point of it
BED_VERTICES = 141  # 1 m apart: the slopes are gentle, and the renders pay for every vertex
PIER_XS = (-0.5, 1.5, 3.5, 5.5)  # posts in two rows, from the shallows up to the waterline
PIER_YS = (-3.6, -2.4)
POST_RADIUS = 0.15
POST_TOP = 1.3
# Higher and steeper than the lake's camera: the water shows more of what is under it (the
# seeds' Fresnel gives the refraction dot(eye, n)), so the colour by depth reads.
SHORE_CAMERA = ((0.0, -16.0, 6.0), (1.5, 8.0, 0.0), 30.0)
SHORE_FILL = 2.2  # the backlit beach needs more of the light from behind the camera


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


def sand_material(bpy):
    """Rough sand: mottled grains, fine bumps, darker and smoother where it is wet (below z = 0.15)."""
    material, bsdf = _new_material(bpy, "Sand")
    nodes, links = material.node_tree.nodes, material.node_tree.links
    coords = nodes.new("ShaderNodeTexCoord")
    noise = nodes.new("ShaderNodeTexNoise")
    noise.inputs["Scale"].default_value = 0.6
    noise.inputs["Detail"].default_value = 6.0
    grains = nodes.new("ShaderNodeTexNoise")
    grains.inputs["Scale"].default_value = 40.0
    grains.inputs["Detail"].default_value = 2.0
    mottle = _ramp(nodes, [(0.3, (0.62, 0.5, 0.33)), (0.7, (0.86, 0.73, 0.5))])
    split = nodes.new("ShaderNodeSeparateXYZ")
    wet = nodes.new("ShaderNodeMapRange")  # 1 below the waterline, 0 from 0.15 m above it
    wet.inputs["From Min"].default_value = 0.15
    wet.inputs["From Max"].default_value = 0.0
    darken = nodes.new("ShaderNodeMix")
    darken.data_type = "RGBA"
    darken.blend_type = "MULTIPLY"
    darken.inputs["B"].default_value = (0.6, 0.58, 0.55, 1.0)
    roughness = nodes.new("ShaderNodeMapRange")
    roughness.inputs["To Min"].default_value = 0.95
    roughness.inputs["To Max"].default_value = 0.55
    bump = nodes.new("ShaderNodeBump")
    bump.inputs["Strength"].default_value = 0.25
    bump.inputs["Distance"].default_value = 0.02
    links.new(coords.outputs["Object"], noise.inputs["Vector"])
    links.new(coords.outputs["Object"], grains.inputs["Vector"])
    links.new(noise.outputs["Fac"], mottle.inputs["Fac"])
    links.new(coords.outputs["Object"], split.inputs["Vector"])
    links.new(split.outputs["Z"], wet.inputs["Value"])
    links.new(wet.outputs["Result"], darken.inputs["Factor"])
    links.new(mottle.outputs["Color"], darken.inputs["A"])
    links.new(wet.outputs["Result"], roughness.inputs["Value"])
    links.new(grains.outputs["Fac"], bump.inputs["Height"])
    links.new(darken.outputs["Result"], bsdf.inputs["Base Color"])
    links.new(roughness.outputs["Result"], bsdf.inputs["Roughness"])
    links.new(bump.outputs["Normal"], bsdf.inputs["Normal"])
    return material


def wood_material(bpy):
    """Weathered wood: brown grain running along the post (noise stretched in Z), rough."""
    material, bsdf = _new_material(bpy, "Wood")
    nodes, links = material.node_tree.nodes, material.node_tree.links
    coords = nodes.new("ShaderNodeTexCoord")
    stretch = nodes.new("ShaderNodeVectorMath")
    stretch.operation = "MULTIPLY"
    stretch.inputs[1].default_value = (12.0, 12.0, 0.6)
    grain = nodes.new("ShaderNodeTexNoise")
    grain.inputs["Scale"].default_value = 2.0
    grain.inputs["Detail"].default_value = 8.0
    color = _ramp(nodes, [(0.35, (0.14, 0.09, 0.05)), (0.65, (0.36, 0.25, 0.15))])
    bump = nodes.new("ShaderNodeBump")
    bump.inputs["Strength"].default_value = 0.4
    bump.inputs["Distance"].default_value = 0.01
    links.new(coords.outputs["Object"], stretch.inputs[0])
    links.new(stretch.outputs["Vector"], grain.inputs["Vector"])
    links.new(grain.outputs["Fac"], color.inputs["Fac"])
    links.new(grain.outputs["Fac"], bump.inputs["Height"])
    links.new(color.outputs["Color"], bsdf.inputs["Base Color"])
    links.new(bump.outputs["Normal"], bsdf.inputs["Normal"])
    bsdf.inputs["Roughness"].default_value = 0.8
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


def add_water(bpy, preset="lake"):
    """The seeds' lake through the add-on's own operator (it also runs the mirror set-up, and
    gathers what reaches below the water as its surroundings)."""
    result = bpy.ops.object.water_add(preset=preset, size=128, location=(0.0, 0.0, 0.0))
    if result != {"FINISHED"}:
        raise RuntimeError(f"object.water_add returned {result}")
    return bpy.context.active_object


def add_props(bpy, scene, floor=True):
    """Sphere on the right, rock cube on the left (both partly under water) and the floor."""
    bpy.ops.mesh.primitive_uv_sphere_add(radius=2.0, location=(5.0, 6.0, 1.2), segments=64, ring_count=32)
    bpy.ops.object.shade_smooth()
    bpy.context.object.name = "Sphere"
    bpy.context.object.data.materials.append(glossy_material(bpy, "White Gloss", (0.9, 0.9, 0.9), 0.08))
    rock = harness.add_cube(scene, (-5.0, 7.0, 1.2), size=1.0, material=rock_material(bpy), name="Rock")
    rock.scale = (4.0, 4.0, 4.0)
    rock.rotation_euler = (0.0, 0.0, 0.35)
    if not floor:
        return
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


def bed_height(x, y):
    """The sandy bed's height (numpy arrays): a beach rising gently out of the water on the right,
    the shallows sloping 1 in 10 for 12 m, then the deep dropping 1 in 3 to 6 m, with a wavy
    waterline and low sand ripples."""
    inland = (x - SHORE_POINT[0]) * SHORE_INLAND[0] + (y - SHORE_POINT[1]) * SHORE_INLAND[1]
    inland = inland + 1.2 * np.sin(y / 4.0) + 0.6 * np.sin(y / 1.7 + 1.0)  # a wavy waterline
    shallows = 0.1 * inland
    deep = -1.2 + 0.33 * (inland + 12.0)
    # A smooth minimum of the two slopes (1 m of rounding), then the beach levelling off at 1.2 m.
    z = -np.logaddexp(-shallows / 0.3, -deep / 0.3) * 0.3
    z = np.minimum(z, 1.2 - 0.8 * np.exp(-np.maximum(inland, 0.0) / 6.0))
    z = np.maximum(z, -6.0)
    return z + 0.04 * np.sin(x * 1.3 + y * 0.4) * np.sin(y * 0.9 - x * 0.2)


def add_beach(bpy, scene):
    """The sandy bed as a displaced grid covering the whole water."""
    mesh = harness.addon("water.plane").new_water_mesh("Beach", BED_SIZE, BED_VERTICES)
    co = np.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3)
    co[:, 2] = bed_height(co[:, 0], co[:, 1])
    mesh.vertices.foreach_set("co", co.ravel())
    mesh.update()
    mesh.materials.append(sand_material(bpy))
    beach = bpy.data.objects.new("Beach", mesh)
    scene.collection.objects.link(beach)
    return beach


def add_posts(bpy, scene):
    """A short pier's posts: wooden cylinders from the sand up to POST_TOP, in two rows."""
    import bmesh

    wood = wood_material(bpy)
    posts = []
    for row, y in enumerate(PIER_YS):
        for column, x in enumerate(PIER_XS):
            mesh = bpy.data.meshes.new("Post")
            bm = bmesh.new()
            bottom = float(bed_height(np.array(x), np.array(y))) - 1.0  # sunk a metre into the sand
            bmesh.ops.create_cone(
                bm,
                cap_ends=True,
                segments=24,
                radius1=POST_RADIUS,
                radius2=POST_RADIUS,
                depth=POST_TOP - bottom,
            )
            bm.to_mesh(mesh)
            bm.free()
            for polygon in mesh.polygons:
                polygon.use_smooth = len(polygon.vertices) == 4  # smooth sides, flat caps
            mesh.materials.append(wood)
            post = bpy.data.objects.new(f"Post {row}.{column}", mesh)
            # A little lean, as old posts have.
            post.location = (x, y, (POST_TOP + bottom) / 2)
            post.rotation_euler = (0.03 * math.sin(3 * x + y), 0.03 * math.cos(2 * x - y), 0.0)
            scene.collection.objects.link(post)
            posts.append(post)
    return posts


def build_shore_scene(bpy, width, height, samples):
    """The demo's lake at the shore: the bed and posts first, so the water gathers them."""
    scene = harness.clean_scene(width=width, height=height, samples=samples)
    add_sky(bpy, scene)
    add_sun(bpy, scene)
    add_props(bpy, scene, floor=False)
    add_beach(bpy, scene)
    add_posts(bpy, scene)
    water = add_water(bpy, preset=SHORE_PRESET)
    add_fill(bpy, scene).data.energy = SHORE_FILL
    harness.add_camera(scene, *SHORE_CAMERA)
    return scene, water


# --- images ----------------------------------------------------------------

# A 3 x 5 pixel font for the labels: each glyph is five rows of three bits.
_FONT = {
    "A": "010101111101101",
    "C": "011100100100011",
    "D": "110101101101110",
    "E": "111100110100111",
    "F": "111100110100100",
    "H": "101101111101101",
    "I": "111010010010111",
    "L": "100100100100111",
    "M": "101111101101101",
    "N": "101111111111101",
    "O": "010101101101010",
    "P": "110101110100100",
    "R": "110101110101101",
    "S": "011100010001110",
    "T": "111010010010010",
    "U": "101101101101111",
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


def compose_insets(main, insets):
    """The main view with `insets` ((label, pixels), the last rightmost) in the sky, top right."""
    image = main.copy()
    right = image.shape[1]
    for label, small in reversed(insets):
        right -= INSET_MARGIN + small.shape[1]
        paste(image, small, right, INSET_MARGIN, label)
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


def render_views(scene, water, work, progress, views=((1, "reflection"), (2, "refraction"))):
    """The final view, then `views` (debug view number, label) as insets: by default the
    reflection-only and refraction-only views (Debug View 1 and 2)."""
    debug = harness.addon("nodes.material").water_node(water.active_material).inputs["Debug View"]
    scale = scene.render.resolution_percentage
    width, height = (
        round(size * scale / 100) for size in (scene.render.resolution_x, scene.render.resolution_y)
    )
    progress(f"main view, {width} x {height}")
    main = harness.render(scene, work / "main.png")
    # The insets are rendered at half size and box-filtered down by 2 more: a quarter of the width.
    scene.render.resolution_percentage = scale * 2 // INSET_SCALE
    insets = []
    try:
        for number, name in views:
            progress(f"{name} only (Debug View {number})")
            debug.default_value = number
            insets.append((name, shrink(harness.render(scene, work / f"{name}.png"), 2)))
    finally:
        debug.default_value = 0
        scene.render.resolution_percentage = scale
    return compose_insets(main, insets)


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


SHORE_VIEWS = ((6, "depth"), (7, "foam"), (8, "caustics"))  # T, foam coverage, caustic factor: unlit


def render_shore(bpy, work, progress, preview=False):
    """The shore image: the final view with the depth (transmittance), foam and caustics views as
    insets (the preview: the final view alone)."""
    samples = PREVIEW_SAMPLES if preview else SAMPLES
    scene, water = build_shore_scene(bpy, *MAIN_SIZE, samples)
    if preview:
        scene.render.resolution_percentage = PREVIEW_PERCENT
    return render_views(scene, water, work, progress, views=() if preview else SHORE_VIEWS)


def main(argv=()):
    """`shore`: only the shore image; `--preview`: only the shore image, small and quick, to out/
    only; the pictures go to docs/ too when `tools/demo --docs` asked (`demo_output.publish`)."""
    preview = "--preview" in argv
    lake = not preview and "shore" not in argv
    views = 1 + (0 if preview else len(SHORE_VIEWS))
    progress = Progress(total=views + (3 + len(STRIP_TIMES) if lake else 0))
    bpy = harness.start()
    harness.install(harness.build_zip(tempfile.mkdtemp(prefix="water_surface_dist_")))
    print(
        f"rendering the demo with Blender {bpy.app.version_string} (software EEVEE: a few minutes)",
        flush=True,
    )
    OUT.mkdir(parents=True, exist_ok=True)
    written = []
    with tempfile.TemporaryDirectory(prefix="water_surface_demo_") as tmp:
        work = Path(tmp)
        if lake:
            scene, water, strip_camera = build_scene(bpy)
            written.append(save_png(bpy, render_views(scene, water, work, progress), OUT / "demo.png"))
            strip = render_strip(scene, strip_camera, work, progress)
            written.append(save_png(bpy, strip, OUT / "demo_frames.png"))
            print(f"the lake took {progress.elapsed():.0f} s", flush=True)
        shore_start = progress.elapsed()
        name = "demo_shore_preview.png" if preview else "demo_shore.png"
        shore = save_png(bpy, render_shore(bpy, work, progress, preview=preview), OUT / name)
        print(f"the shore took {progress.elapsed() - shore_start:.0f} s", flush=True)
    if preview:
        publish(shore, docs=False, note="(a preview: never copied to docs/)")
    else:
        written.append(shore)
    for path in written:
        publish(path)
    print(f"done in {progress.elapsed():.0f} s", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
