"""Whole-file jobs for pipelines: add water to a saved `.blend`, render one frame of one.

Used by the command line (`blender -c water_surface ...`) and callable from any
`bpy` script. Errors are `FileJobError` with one line that says what to fix.
"""

from pathlib import Path

import bpy

from ..presets import PresetError
from .plane import add_water, resolve_values

IMAGE_FORMATS = {".png": "PNG", ".exr": "OPEN_EXR", ".jpg": "JPEG", ".jpeg": "JPEG", ".tif": "TIFF"}


class FileJobError(RuntimeError):
    """A file job that cannot run: a missing file, a bad path or value."""


def _open(path):
    path = Path(path)
    if not path.is_file():
        raise FileJobError(f"no such .blend file: {path}")
    try:
        bpy.ops.wm.open_mainfile(filepath=str(path.resolve()), load_ui=False)
    except RuntimeError as error:
        raise FileJobError(f"cannot open {path}: {str(error).strip().splitlines()[-1]}") from error


def _scene(name):
    if name is None:
        return bpy.context.scene
    scene = bpy.data.scenes.get(name)
    if scene is None:
        raise FileJobError(f"no scene '{name}' (scenes: {', '.join(s.name for s in bpy.data.scenes)})")
    return scene


def _output_folder(path):
    path = Path(path)
    if not path.parent.is_dir():
        raise FileJobError(f"folder does not exist: {path.parent}")
    return path.resolve()


def add_water_to_file(source, target, scene=None, preset="lake", mirror_setup=True, **values):
    """Opens `source`, adds water to its scene, saves as `target`; returns what it did, in words."""
    target = _output_folder(target)
    if target.suffix != ".blend":
        raise FileJobError(f"the output must be a .blend file, not {target.name}")
    try:
        resolve_values(preset, **values)  # a bad preset or value fails before the file is read
    except PresetError as error:
        raise FileJobError(str(error)) from error
    _open(source)
    scene = _scene(scene)
    try:
        water, changes = add_water(scene, preset=preset, mirror_setup=mirror_setup, **values)
    except PresetError as error:
        raise FileJobError(str(error)) from error
    bpy.ops.wm.save_as_mainfile(filepath=str(target))
    done = f"added '{water.name}' ({preset}, {water.dimensions.x:g} m) to scene '{scene.name}'"
    if changes:
        done += "; mirror set-up: " + ", ".join(changes)
    return f"{done}; saved {target}"


def render_file(source, target, scene=None, frame=None, samples=None):
    """Opens `source` and renders one frame of its scene to `target` (.png, .exr, .jpg, .tif)."""
    target = _output_folder(target)
    file_format = IMAGE_FORMATS.get(target.suffix.lower())
    if file_format is None:
        raise FileJobError(f"unknown image type '{target.suffix}' (use {', '.join(IMAGE_FORMATS)})")
    _open(source)
    scene = _scene(scene)
    if scene.camera is None:
        raise FileJobError(f"scene '{scene.name}' has no camera to render from")
    if frame is not None:
        scene.frame_set(frame)
    if samples is not None:
        if samples < 1:
            raise FileJobError(f"samples must be at least 1, not {samples}")
        scene.eevee.taa_render_samples = samples
        scene.cycles.samples = samples
    scene.render.image_settings.file_format = file_format
    scene.render.filepath = str(target)
    scene.render.use_file_extension = False
    with bpy.context.temp_override(scene=scene):
        bpy.ops.render.render(write_still=True, scene=scene.name)
    return f"rendered scene '{scene.name}' frame {scene.frame_current} to {target}"
