"""Whole-file jobs for pipelines: add water to a saved `.blend`, render frames of one.

Used by the command line (`blender -c water_surface ...`) and callable from any
`bpy` script. Errors are `FileJobError` with one line that says what to fix.

Each job opens its `.blend` in place of the caller's open file; with
`keep_session=True` (the default) the caller's session is put back afterwards,
also when the job fails. The session is saved as a copy in a temporary folder
just before the job opens its file, and reopened afterwards, so it comes back
with its unsaved changes. What is and is not the same afterwards:

* the same: everything a `.blend` holds - objects, meshes, materials, scenes,
  the current frame, the active scene and object, selection - including changes
  that were never saved;
* reopened from the copy (whenever Blender cannot vouch that the saved file
  equals the session: it had never been saved, it has unsaved changes, the file
  on disk changed during the job, or Blender runs in the background, where
  `bpy.data.is_dirty` misses changes made by scripts): `bpy.data.filepath` is
  the copy's path (`<temp>/<name>.blend`, or `untitled.blend` for a session that
  was never saved; the copy is deleted), not the session's own, so save with
  `bpy.ops.wm.save_as_mainfile(filepath=...)`; `bpy.data.is_dirty` may differ;
  relative (`//`) file paths of images, libraries, sounds, ... are remapped to
  stay valid, but other `//` paths (a scene's render output) then resolve against
  the temporary folder;
* a saved session with no unsaved changes, in Blender's interface, is reopened
  from its own file: `bpy.data.filepath` stays the same;
* never the same: Python references to data-blocks taken before the job (look
  them up again by name), the undo history, data-blocks with no users (dropped,
  as on every save), unsaved pixels of images that are not packed, and
  `load_post` handlers run once more. In Blender's interface, the job's and the
  copy's paths may appear among the recent files.

The command line passes `keep_session=False`: its session is thrown away.
"""

import functools
import inspect
import os
import re
import shutil
import stat
import tempfile
from numbers import Integral
from pathlib import Path

import bpy

from .boats import wake
from .errors import WaterError
from .plane import add_water, resolve_values

IMAGE_FORMATS = {".png": "PNG", ".exr": "OPEN_EXR", ".jpg": "JPEG", ".jpeg": "JPEG", ".tif": "TIFF"}


class FileJobError(WaterError, RuntimeError):
    """A file job that cannot run: a missing file, a bad path or value."""


_KINDS = (
    (stat.S_ISDIR, "a folder"),
    (stat.S_ISFIFO, "a FIFO"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


def _not_regular(path, mode):
    """FileJobError saying that `path` (of stat `mode`) is not a regular file, and what it is."""
    kind = next((name for test, name in _KINDS if test(mode)), "a file of another kind")
    return FileJobError(f"not a regular file ({kind}): {path}")


def _open(path):
    path = Path(path)
    try:
        mode = path.stat().st_mode  # through a symbolic link; never opens a FIFO (that blocks)
    except FileNotFoundError:  # also a dangling symbolic link
        raise FileJobError(f"no such .blend file: {path}") from None
    except (OSError, ValueError) as error:
        reason = getattr(error, "strerror", None) or error
        raise FileJobError(f"cannot read {path} ({reason})") from None
    if not stat.S_ISREG(mode):
        raise _not_regular(path, mode)
    if _kept is not None:
        _kept.take()
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


def _can_write(path, mode=os.W_OK):
    if os.access in os.supports_effective_ids:  # what open() checks, also under seteuid
        return os.access(path, mode, effective_ids=True)
    return os.access(path, mode)


def _output_folder(path):
    """`path` resolved, once its folder exists and may be written in; FileJobError if not."""
    path = Path(path)
    if not path.parent.is_dir():
        raise FileJobError(f"folder does not exist: {path.parent}")
    if not _can_write(path.parent, os.W_OK | os.X_OK):
        raise FileJobError(f"cannot write in folder {path.parent} (no permission)")
    return path.resolve()


def _output_file(path):
    """FileJobError when `path` (in a checked folder) is a folder or a file that may not be written."""
    if path.is_dir():
        raise FileJobError(f"the output is a folder, not a file: {path}")
    if path.exists() and not path.is_file():  # writing a FIFO blocks, a device is no image
        raise _not_regular(path, path.stat().st_mode)
    if path.exists() and not _can_write(path):
        raise FileJobError(f"cannot write over {path} (it is read-only)")
    return path


def _last_line(error, default):
    text = str(error).strip()
    return text.splitlines()[-1] if text else default


class _KeptSession:
    """The caller's open file while a job runs: `take` saves a copy before the job opens
    its own file, `restore` reopens the session afterwards (see the module's notes)."""

    def __init__(self):
        self.folder = None
        self.copy = None

    def take(self):
        if self.copy is not None:
            return
        self.path = bpy.data.filepath
        self.clean = bool(self.path) and not bpy.data.is_dirty and not bpy.app.background
        self.stat = _stat(self.path)
        folder = Path(tempfile.mkdtemp(prefix="water_surface_session_"))
        copy = folder / (Path(self.path).name if self.path else "untitled.blend")
        try:
            bpy.ops.wm.save_as_mainfile(filepath=str(copy), copy=True, relative_remap=True)
        except RuntimeError as error:
            shutil.rmtree(folder, ignore_errors=True)
            reason = _last_line(error, "saving failed")
            raise FileJobError(
                f"cannot keep a copy of the open file, so the job did not run: {reason}"
            ) from error
        self.folder, self.copy = folder, copy

    def restore(self):
        if self.copy is None:
            return
        own = self.clean and self.stat is not None and _stat(self.path) == self.stat
        for path in [self.path, self.copy] if own else [self.copy]:
            try:
                bpy.ops.wm.open_mainfile(filepath=str(path), load_ui=False)
            except RuntimeError as error:
                reason = _last_line(error, "opening failed")
                continue
            shutil.rmtree(self.folder, ignore_errors=True)
            return
        raise FileJobError(f"cannot reopen the open file from its copy {self.copy}: {reason}")


def _stat(path):
    try:
        stat = os.stat(path)
    except (OSError, ValueError):
        return None
    return stat.st_mtime_ns, stat.st_size


_kept = None  # the _KeptSession of the job running now, if it keeps the caller's session


def _keeps_session(job):
    """Runs `job` so that, with its `keep_session` true, the caller's session comes back after it."""
    signature = inspect.signature(job)

    @functools.wraps(job)
    def run(*args, **kwargs):
        global _kept
        try:
            keep = signature.bind(*args, **kwargs).arguments.get("keep_session", True)
        except TypeError:
            keep = False  # the job itself raises its TypeError before opening anything
        outer, _kept = _kept, _KeptSession() if keep else None
        try:
            return job(*args, **kwargs)
        finally:
            kept, _kept = _kept, outer
            if kept is not None:
                kept.restore()

    return run


@_keeps_session
def add_water_to_file(
    source,
    target,
    scene=None,
    preset="lake",
    mirror_setup=True,
    keep_session=True,
    see_surroundings=True,
    **values,
):
    """Opens `source`, adds water to its scene, saves as `target`; returns what it did, in words.

    `target` may be `source`. Nothing is opened when `target` cannot be written (a folder,
    a read-only file, a missing or read-only folder). `keep_session`: put the caller's open
    file back afterwards (see the module's notes).
    """
    target = _output_file(_output_folder(target))
    if target.suffix != ".blend":
        raise FileJobError(f"the output must be a .blend file, not {target.name}")
    try:
        resolve_values(preset, **values)  # a bad preset or value fails before the file is read
    except WaterError as error:  # PresetError, UnderwaterError
        raise FileJobError(str(error)) from error
    _open(source)
    scene = _scene(scene)
    try:
        added = add_water(
            scene, preset=preset, mirror_setup=mirror_setup, see_surroundings=see_surroundings, **values
        )
    except WaterError as error:  # PresetError, AddWaterError
        raise FileJobError(str(error)) from error
    try:
        bpy.ops.wm.save_as_mainfile(filepath=str(target))
    except RuntimeError as error:
        raise FileJobError(f"cannot save {target}: {_last_line(error, 'saving failed')}") from error
    notes = "".join(f"; {note}" for note in added.notes)
    return f"{added.summary(preset)} to scene '{scene.name}'{notes}; saved {target}"


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
    """ "7" or "1-48" as a list of frame numbers; FileJobError, one short line, when it is
    neither or a frame is outside Blender's range (also one of thousands of digits)."""
    pattern = r"\s*(-?[0-9]+)\s*(?:-\s*(-?[0-9]+)\s*)?"
    match = re.fullmatch(pattern, text, re.ASCII) if isinstance(text, str) else None
    if match is None:
        raise FileJobError(f"frames must be N or FIRST-LAST (e.g. 1-48), not {shown(text)}")
    first = _frame_number(match.group(1))
    last = _frame_number(match.group(2)) if match.group(2) is not None else first
    if last < first:
        raise FileJobError(f"frames {shown(text)}: the last frame comes before the first")
    return list(range(first, last + 1))


def _frame_number(digits):
    """The frame `digits` ("-12") name, within Blender's range, read without int()'s digit limit."""
    if len(digits.lstrip("-").lstrip("0")) > len(str(MAX_FRAME)):
        raise FileJobError(f"frame {shown(digits)} is outside Blender's range {MIN_FRAME}..{MAX_FRAME}")
    frame = int(digits)
    if not MIN_FRAME <= frame <= MAX_FRAME:
        raise FileJobError(f"frame {frame} is outside Blender's range {MIN_FRAME}..{MAX_FRAME}")
    return frame


def shown(text, limit=32):
    """`text` quoted for a one-line message (also the command line's): printable, and cut short
    when long (a number of thousands of digits is named by its first ones and its length)."""
    if not isinstance(text, str):
        return type(text).__name__
    cut = text[:limit]
    quoted = repr(cut) if cut.isprintable() else ascii(cut)
    return quoted if len(text) <= limit else f"{quoted[:-1]}...{quoted[-1]} ({len(text)} characters)"


MIN_FRAME, MAX_FRAME = -1048574, 1048574  # Blender's MINAFRAME and MAXFRAME


@_keeps_session
def render_file(
    source, target, scene=None, frame=None, samples=None, frames=None, progress=print, keep_session=True
):
    """Opens `source` and renders frames of its scene to `target` (.png, .exr, .jpg, .tif).

    `frames`, a list of frame numbers, renders each to `frame_path(target, n)`, one
    `progress` line a frame, as a farm worker would (each frame from the file's own
    state: nothing carries over from the frame before). Otherwise one frame
    (`frame`, default the file's current one) is written to `target` as named.
    Nothing is opened or rendered when an output cannot be written (a folder, a
    read-only file, a missing or read-only folder). `keep_session`: put the caller's
    open file back afterwards (see the module's notes).
    """
    target = _output_folder(target)
    file_format = IMAGE_FORMATS.get(target.suffix.lower())
    if file_format is None:
        raise FileJobError(f"unknown image type '{target.suffix}' (use {', '.join(IMAGE_FORMATS)})")
    numbers = {
        "samples": [samples] if samples is not None else [],
        "frame": [frame] if frame is not None else [],
    }
    numbers["frames"] = list(frames or [])
    for name, given in numbers.items():
        for value in [v for v in given if v is not None]:
            if isinstance(value, bool) or not isinstance(value, Integral):
                raise FileJobError(f"{name} must be whole numbers, not {shown(repr(value))}")
    if samples is not None and samples < 1:
        raise FileJobError(f"samples must be at least 1, not {samples}")
    for number in frames or ([frame] if frame is not None else []):
        if not MIN_FRAME <= number <= MAX_FRAME:
            raise FileJobError(f"frame {number} is outside Blender's range {MIN_FRAME}..{MAX_FRAME}")
    for path in [frame_path(target, number) for number in frames] if frames else [target]:
        _output_file(path)
    _open(source)
    scene = _scene(scene)
    if scene.camera is None:
        raise FileJobError(f"scene '{scene.name}' has no camera to render from")
    if samples is not None:
        scene.eevee.taa_render_samples = samples
        scene.cycles.samples = samples
    scene.render.image_settings.file_format = file_format
    scene.render.use_file_extension = False
    for water in scene.objects:
        for problem in wake.bake_problems(water, scene):
            progress(
                f"water_surface: {problem[0].lower()}{problem[1:]} (a frame rendered on its own shows it "
                "wrong: Bake Wake, or api.bake)"
            )
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
