"""Runs the add-on the way users get it, inside bpy from PyPI.

Shared by the tests (`tests/conftest.py`) and the demo (`tools/render_demo.py`):
build the zip with Blender's own `blender_ext.py`, install it into a throw-away
user folder with `package_install_files`, and render scenes to numpy arrays.
`BLENDER_USER_RESOURCES` must be set before bpy is imported, so `start()`
is the only way in: nothing here imports bpy at module level.
"""

import glob
import importlib.util
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ADDON_ID = "water_surface"
ADDON_MODULE = f"bl_ext.user_default.{ADDON_ID}"


def blender_ext_script():
    """Path of Blender's `extension build/validate` command inside the bpy install."""
    spec = importlib.util.find_spec("bpy")
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError("bpy is not installed in this Python")
    bpy_dir = Path(list(spec.submodule_search_locations)[0])
    found = glob.glob(str(bpy_dir / "*" / "scripts/addons_core/bl_pkg/cli/blender_ext.py"))
    if not found:
        raise RuntimeError(f"blender_ext.py not found under {bpy_dir}")
    return Path(found[0])


def run_blender_ext(*args):
    """Runs `blender_ext.py` with this Python; returns the completed process."""
    return subprocess.run(
        [sys.executable, str(blender_ext_script()), *args],
        capture_output=True,
        text=True,
        check=False,
    )


def build_zip(out_dir, name=None):
    """Builds the extension zip from the repository root into `out_dir` (default name `water_surface.zip`)."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    zip_path = out_dir / (name or f"{ADDON_ID}.zip")
    proc = run_blender_ext("build", "--source-dir", str(ROOT), "--output-filepath", str(zip_path))
    if proc.returncode != 0 or not zip_path.exists():
        raise RuntimeError(f"extension build failed:\n{proc.stdout}\n{proc.stderr}")
    return zip_path


def manifest_version():
    """The add-on's version, as `blender_manifest.toml` gives it."""
    import tomllib

    return tomllib.loads((ROOT / "blender_manifest.toml").read_text(encoding="utf-8"))["version"]


def build_release(out_dir=None):
    """Builds the zip users install (`tools/build`): `<out_dir>/water_surface-<version>.zip`, validated.

    `out_dir` defaults to `dist/` in the repository. Blender's own `blender_ext.py build` makes it
    (only the add-on's files, as the manifest's `[build]` section says), then `blender_ext.py
    validate` checks the zip itself, as Blender does before installing it.
    """
    out_dir = Path(out_dir).resolve() if out_dir else ROOT / "dist"
    zip_path = build_zip(out_dir, name=f"{ADDON_ID}-{manifest_version()}.zip")
    proc = run_blender_ext("validate", str(zip_path))
    if proc.returncode != 0:
        zip_path.unlink()
        raise RuntimeError(f"the built zip does not validate:\n{proc.stdout}\n{proc.stderr}")
    return zip_path


def start(user_dir=None):
    """Points Blender at a fresh user folder, imports bpy and returns it."""
    if "bpy" in sys.modules:
        raise RuntimeError("harness.start() must run before bpy is imported")
    user_dir = user_dir or tempfile.mkdtemp(prefix="water_surface_user_")
    os.environ["BLENDER_USER_RESOURCES"] = str(user_dir)
    import bpy

    return bpy


def install(zip_path):
    """Installs and enables the built zip in the user_default repository."""
    import bpy

    result = bpy.ops.extensions.package_install_files(
        filepath=str(zip_path), repo="user_default", enable_on_install=True
    )
    if result != {"FINISHED"}:
        raise RuntimeError(f"installing {zip_path} returned {result}")
    return importlib.import_module(ADDON_MODULE)


def addon(submodule=None):
    """The installed add-on's package, or one of its modules (for its plain functions)."""
    return importlib.import_module(f"{ADDON_MODULE}.{submodule}" if submodule else ADDON_MODULE)


def clean_scene(engine=None, width=128, height=72, samples=4):
    """An empty scene with the add-on still enabled, set to render small and exact."""
    import bpy

    bpy.ops.wm.read_homefile(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = engine or addon("engine").eevee_engine_id()
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.render.dither_intensity = 0.0
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.eevee.taa_render_samples = samples
    scene.cycles.samples = samples
    # EEVEE clears its whole shadow pool on every render: 0.25 s a render on llvmpipe at 512 MB
    # (the default, sized for 4K frames). The tests' frames, a few hundred pixels wide, use a
    # small part of 128 MB (2,048 pages of 128 x 128).
    if hasattr(scene.eevee, "shadow_pool_size"):
        scene.eevee.shadow_pool_size = "128"
    return scene


def render(scene, path, exr=False):
    """Renders `scene` to `path` and returns its pixels as float32 (H, W, 4), top row first.

    PNG gives display values (what a person sees); 32-bit EXR gives exact linear values.
    """
    import bpy

    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR" if exr else "PNG"
    settings.color_mode = "RGBA"
    settings.color_depth = "32" if exr else "8"
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    scene.render.filepath = str(path)
    scene.render.use_file_extension = False
    with bpy.context.temp_override(scene=scene):
        bpy.ops.render.render(write_still=True, scene=scene.name)
    return load_image(path)


def load_image(path):
    """An image file's pixels as float32 (H, W, 4), top row first."""
    import bpy
    import numpy as np

    image = bpy.data.images.load(str(path), check_existing=False)
    try:
        width, height = image.size
        pixels = np.empty(width * height * 4, dtype=np.float32)
        image.pixels.foreach_get(pixels)
    finally:
        bpy.data.images.remove(image)
    return pixels.reshape(height, width, 4)[::-1].copy()


def world_to_pixel(scene, camera, points):
    """Projects world points to (column, row) pixel coordinates, row 0 at the top."""
    import numpy as np
    from bpy_extras.object_utils import world_to_camera_view
    from mathutils import Vector

    scale = scene.render.resolution_percentage / 100
    width = scene.render.resolution_x * scale
    height = scene.render.resolution_y * scale
    out = []
    for point in points:
        ndc = world_to_camera_view(scene, camera, Vector(point))
        out.append((ndc.x * width, (1.0 - ndc.y) * height))
    return np.array(out)


def add_camera(scene, location, target, lens=35.0):
    """A camera at `location` looking at `target`, made the scene's camera."""
    import bpy
    from mathutils import Vector

    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    camera.data.lens = lens
    camera.data.clip_end = 1000.0
    scene.collection.objects.link(camera)
    camera.location = location
    direction = Vector(target) - Vector(location)
    camera.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    scene.camera = camera
    bpy.context.view_layer.update()  # so matrix_world is current for projections
    return camera


def lit_material(name, color, roughness=0.5):
    """A Principled BSDF material of `color` (RGB), lit by the scene."""
    import bpy

    material = bpy.data.materials.new(name)
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    bsdf = material.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*color[:3], 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    return material


def emission_material(name, color, strength=1.0):
    """An unlit material: renders exactly `color * strength`."""
    import bpy

    material = bpy.data.materials.new(name)
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*color[:3], 1.0)
    emission.inputs["Strength"].default_value = strength
    output = nodes.new("ShaderNodeOutputMaterial")
    material.node_tree.links.new(emission.outputs[0], output.inputs["Surface"])
    return material


def add_cube(scene, location, size=1.0, material=None, name="Cube"):
    """A cube mesh object of edge `size` at `location`, linked to `scene`."""
    import bmesh
    import bpy

    mesh = bpy.data.meshes.new(name)
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=size)
    bm.to_mesh(mesh)
    bm.free()
    if material is not None:
        mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    obj.location = location
    scene.collection.objects.link(obj)
    return obj


def add_box(scene, name, size, location=(0.0, 0.0, 0.0)):
    """A box mesh object `size` (x, y, z) across, centred on its origin at `location` (a hull)."""
    import bpy

    mesh = bpy.data.meshes.new(name)
    half = [s / 2.0 for s in size]
    corners = [
        (x, y, z) for x in (-half[0], half[0]) for y in (-half[1], half[1]) for z in (-half[2], half[2])
    ]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh.from_pydata(corners, [], faces)
    obj = bpy.data.objects.new(name, mesh)
    obj.location = location
    scene.collection.objects.link(obj)
    return obj


def evaluated_points(obj, attribute):
    """(points (N, 3), the float point attribute `attribute` (N,), 0 where the mesh has none) of
    `obj` evaluated now, in its own space."""
    import bpy
    import numpy as np

    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    try:
        points = np.empty(len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", points)
        values = np.zeros(len(mesh.vertices))
        if attribute in mesh.attributes:
            mesh.attributes[attribute].data.foreach_get("value", values)
        return points.reshape(-1, 3), values
    finally:
        evaluated.to_mesh_clear()


def set_world_color(scene, color, strength=1.0):
    """A world of one flat colour (the sky), made if missing."""
    import bpy

    if scene.world is None:
        scene.world = bpy.data.worlds.new("World")
    world = scene.world
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    background = world.node_tree.nodes.get("Background")
    if background is None:
        world.node_tree.nodes.clear()
        background = world.node_tree.nodes.new("ShaderNodeBackground")
        output = world.node_tree.nodes.new("ShaderNodeOutputWorld")
        world.node_tree.links.new(background.outputs[0], output.inputs["Surface"])
    background.inputs["Color"].default_value = (*color[:3], 1.0)
    background.inputs["Strength"].default_value = strength
    # EEVEE bakes the world into its sphere probe on every render: 0.56 s of a 1.46 s render
    # of a plane on llvmpipe at 1024 (the default). A world of one colour is the same at any
    # resolution, so the smallest one is baked.
    if hasattr(world, "probe_resolution"):
        world.probe_resolution = "128"
    return world


def pixel_rays(scene, camera):
    """World-space ray origin and unit directions through every pixel centre, (H, W, 3), row 0 at the top."""
    import numpy as np

    scale = scene.render.resolution_percentage / 100
    width = int(scene.render.resolution_x * scale)
    height = int(scene.render.resolution_y * scale)
    frame = [
        np.array(c) for c in camera.data.view_frame(scene=scene)
    ]  # top-right, bottom-right, bottom-left, top-left
    top_right, _, bottom_left, top_left = frame
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    local = (
        top_left[None, None, :]
        + u[None, :, None] * (top_right - top_left)[None, None, :]
        + v[:, None, None] * (bottom_left - top_left)[None, None, :]
    )
    matrix = np.array(camera.matrix_world)
    directions = local @ matrix[:3, :3].T
    directions /= np.linalg.norm(directions, axis=-1, keepdims=True)
    origin = matrix[:3, 3]
    return origin, directions


def hit_plane_z(origin, directions, z=0.0):
    """Where rays meet the plane at height `z`: points (H, W, 3) and a mask of rays that reach it."""
    import numpy as np

    with np.errstate(divide="ignore", invalid="ignore"):
        t = (z - origin[2]) / directions[..., 2]
    hits = origin + t[..., None] * directions
    return hits, np.isfinite(t) & (t > 0)


def surface_below(water, x, y, depsgraph=None):
    """The world z of `water`'s evaluated surface under (x, y) (a ray cast down from 100 m over
    its origin), or None where no face is there: what a camera "h m up" over waves stands on."""
    import bpy
    from mathutils import Vector

    evaluated = water.evaluated_get(depsgraph or bpy.context.evaluated_depsgraph_get())
    inverse = evaluated.matrix_world.inverted()
    top = evaluated.matrix_world.translation.z + 100.0
    down = (inverse.to_3x3() @ Vector((0.0, 0.0, -1.0))).normalized()
    hit, location, _normal, _index = evaluated.ray_cast(inverse @ Vector((x, y, top)), down)
    return (evaluated.matrix_world @ location).z if hit else None


def blender_output(action):
    """(what Blender's C code prints on fd 1 and 2 while `action` runs, `action`'s result): how a
    test reads messages such as "Dependency cycle" that never reach Python."""
    import os
    import tempfile

    with tempfile.TemporaryFile(mode="w+b") as sink:
        saved = [os.dup(1), os.dup(2)]
        os.dup2(sink.fileno(), 1)
        os.dup2(sink.fileno(), 2)
        try:
            result = action()
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for fd in saved:
                os.close(fd)
        sink.seek(0)
        return sink.read().decode(errors="replace"), result


def reopen_without_add_on(path):
    """Disables the add-on, turns auto-run scripts off and opens the .blend `path`, as a render
    farm worker without the add-on would; returns the opened file's scene. (The test fixture
    `addon_disabled_afterwards` brings both back.)"""
    import addon_utils
    import bpy

    addon_utils.disable(ADDON_MODULE, default_set=True)
    bpy.context.preferences.filepaths.use_scripts_auto_execute = False
    bpy.ops.wm.open_mainfile(filepath=str(path), load_ui=False, use_scripts=False)
    return bpy.context.scene


def bat(*args):
    """Runs BAT's own command line (`bat ARGS`) in a fresh process; returns its exit status and output.

    BAT 2 works inside Blender through bpy (here the bpy module, with no add-on installed);
    BAT 1 (Python 3.11, Blender 4.x) reads the file itself.
    """
    code = (  # BAT 2 reads its arguments after "--", as in `blender -b --python-expr ... -- pack ...`
        "import sys; args = sys.argv[1:]; import bpy, blender_asset_tracer as bat; "
        "sys.argv = ['bat', *([] if bat.__version__.startswith('1.') else ['--']), *args]; "
        "from blender_asset_tracer import cli; cli.cli_main()"
    )
    return fresh_python("-c", code, *args)


def fresh_python(*args, tools=False):
    """Runs this Python (bpy's) on `args` in a process of its own, with Blender's default user
    resources (and tools/ importable where `tools`); returns its exit status and output."""
    env = {**os.environ}
    env.pop("BLENDER_USER_RESOURCES", None)
    if tools:
        env["PYTHONPATH"] = str(ROOT / "tools")
    done = subprocess.run(
        [sys.executable, *map(str, args)],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,
        check=False,
    )
    return done.returncode, done.stdout + done.stderr


def run_worker(*args):
    """`fresh_python(*args)` with tools/ importable (a farm worker); fails with its output when it fails."""
    status, output = fresh_python(*args, tools=True)
    assert status == 0, output[-4000:]
