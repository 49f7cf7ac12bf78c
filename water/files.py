"""Whole-file jobs for pipelines: add water to a saved `.blend`, render frames of one.

Used by the command line (`blender -c water_surface ...`) and callable from any
`bpy` script. Errors are `FileJobError` with one line that says what to fix.
"""

import re
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


def frame_path(target, frame):
    """`target` for one frame, as `blender -b -o` names it: each run of `#` becomes the
    zero-padded frame number; without `#`, four digits go before the extension."""
    target = Path(target)
    if "#" in target.name:
        name = re.sub(r"#+", lambda run: f"{frame:0{len(run.group())}d}", target.name)
    else:
        name = f"{target.stem}{frame:04d}{target.suffix}"
    return target.with_name(name)


def parse_frames(text):
    """ "7" or "1-48" as a list of frame numbers; FileJobError when it is neither."""
    match = re.fullmatch(r"\s*(-?\d+)\s*(?:-\s*(-?\d+)\s*)?", text or "")
    if match is None:
        raise FileJobError(f"--frames takes N or FIRST-LAST, not '{text}'")
    first = int(match.group(1))
    last = int(match.group(2)) if match.group(2) is not None else first
    if last < first:
        raise FileJobError(f"--frames {text}: the last frame comes before the first")
    for frame in (first, last):
        if not MIN_FRAME <= frame <= MAX_FRAME:
            raise FileJobError(f"frame {frame} is outside Blender's range {MIN_FRAME}..{MAX_FRAME}")
    return list(range(first, last + 1))


MIN_FRAME, MAX_FRAME = -1048574, 1048574  # Blender's MINAFRAME and MAXFRAME


def render_file(source, target, scene=None, frame=None, samples=None, frames=None, progress=print):
    """Opens `source` and renders frames of its scene to `target` (.png, .exr, .jpg, .tif).

    `frames`, a list of frame numbers, renders each to `frame_path(target, n)`, one
    `progress` line a frame, as a farm worker would (each frame from the file's own
    state: nothing carries over from the frame before). Otherwise one frame
    (`frame`, default the file's current one) is written to `target` as named.
    """
    target = _output_folder(target)
    file_format = IMAGE_FORMATS.get(target.suffix.lower())
    if file_format is None:
        raise FileJobError(f"unknown image type '{target.suffix}' (use {', '.join(IMAGE_FORMATS)})")
    if samples is not None and samples < 1:
        raise FileJobError(f"samples must be at least 1, not {samples}")
    for number in frames or ([frame] if frame is not None else []):
        if not MIN_FRAME <= number <= MAX_FRAME:
            raise FileJobError(f"frame {number} is outside Blender's range {MIN_FRAME}..{MAX_FRAME}")
    _open(source)
    scene = _scene(scene)
    if scene.camera is None:
        raise FileJobError(f"scene '{scene.name}' has no camera to render from")
    if samples is not None:
        scene.eevee.taa_render_samples = samples
        scene.cycles.samples = samples
    scene.render.image_settings.file_format = file_format
    scene.render.use_file_extension = False
    if not frames:
        if frame is not None:
            scene.frame_set(frame)
        _render_still(scene, target)
        return f"rendered scene '{scene.name}' frame {scene.frame_current} to {target}"
    for done, number in enumerate(frames, start=1):
        path = frame_path(target, number)
        scene.frame_set(number)
        _render_still(scene, path)
        progress(f"water_surface: frame {number} ({done}/{len(frames)}) rendered to {path}")
    first = frame_path(target, frames[0])
    return f"rendered scene '{scene.name}' frames {frames[0]}-{frames[-1]} ({first.name}, ...)"


def _render_still(scene, path):
    scene.render.filepath = str(path)
    try:
        with bpy.context.temp_override(scene=scene):
            bpy.ops.render.render(write_still=True, scene=scene.name)
    except RuntimeError as error:  # one line and a non-zero exit for the farm, not a traceback
        message = str(error).strip().splitlines()[-1] if str(error).strip() else "render failed"
        raise FileJobError(f"frame {scene.frame_current}: {message}") from error
    if not Path(path).is_file():
        raise FileJobError(f"frame {scene.frame_current}: nothing was written to {path}")
