"""Preset files: read, validated and written as JSON. Plain Python (no bpy).

A preset file is `{"name": ..., "description": ..., "values": {key: value}}`
with the keys of `schema.FIELDS`. A file that cannot be used is skipped with
the reason; a value out of range is clamped; a missing value is the
reference's. Nothing in a preset is ever executed, and no file (huge, deeply
nested, a FIFO, a device) can hang or stop the reader. Saving never writes
through a symlink nor replaces a preset unasked.
"""

import codecs
import json
import os
import re
import secrets
import stat
from dataclasses import dataclass
from pathlib import Path

from . import schema
from .schema import PresetError

BUILTIN_DIR = Path(__file__).resolve().parent
USER_PREFIX = "user:"
MAX_BYTES = 64 * 1024  # a preset is a few hundred bytes; refuse anything absurd


@dataclass(frozen=True)
class Preset:
    id: str  # the file's stem; user presets are prefixed "user:"
    name: str
    description: str
    values: dict  # every field, validated
    path: Path
    user: bool


def read_preset(path, user=False):
    """The preset in `path` and the warnings it raised; PresetError when unusable."""
    path = Path(path)
    data = _parse(_read_text(path))
    if not isinstance(data, dict):
        raise PresetError("must be a JSON object")
    name = _text(data, "name", path.stem.replace("_", " ").title(), "a non-empty string")
    description = _text(data, "description", "", "a string")
    if not name.strip():
        raise PresetError("'name' must be a non-empty string")
    try:
        clean, unknown = schema.check_values(data.get("values", {}))
    except OverflowError as error:  # an integer too large for a float
        raise PresetError(f"holds a number out of range ({error})") from error
    warnings = [f"{path.name}: unknown value '{key}' ignored" for key in unknown]
    warnings += [f"{path.name}: unknown entry '{key}' ignored" for key in data if key not in _ENTRIES]
    values = {**schema.defaults(), **clean}
    preset_id = (USER_PREFIX if user else "") + path.stem
    return Preset(preset_id, name.strip(), description, values, path, user), warnings


def _read_text(path):
    """The file's text, read without blocking and at most MAX_BYTES + 1 bytes.

    Only a regular file is read: a FIFO would block Blender and a device such
    as /dev/zero never ends, also behind a symlink. O_NONBLOCK lets the open
    of a FIFO return so that fstat can refuse it.
    """
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(path, flags)
    except OSError as error:
        raise PresetError(f"cannot be read ({error.strerror or error})") from error
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise PresetError("is not a regular file")
        data = _read_capped(fd)
    except OSError as error:
        raise PresetError(f"cannot be read ({error.strerror or error})") from error
    finally:
        os.close(fd)
    try:
        return data.decode("utf-8-sig")  # a byte-order mark (Windows editors) is not part of the JSON
    except UnicodeDecodeError as error:
        start = error.start + (len(codecs.BOM_UTF8) if data.startswith(codecs.BOM_UTF8) else 0)
        raise PresetError(f"is not UTF-8 text ({error.reason} at byte {start})") from error


def _read_capped(fd):
    """Up to MAX_BYTES bytes from `fd`; PresetError when the file holds more."""
    chunks, size = [], 0
    while size <= MAX_BYTES:
        chunk = os.read(fd, MAX_BYTES + 1 - size)
        if not chunk:
            break
        chunks.append(chunk)
        size += len(chunk)
    if size > MAX_BYTES:
        raise PresetError(f"larger than {MAX_BYTES} bytes")
    return b"".join(chunks)


def _parse(text):
    """JSON data from `text`; every way parsing can fail is a PresetError.

    Besides bad syntax, json raises ValueError for integers over Python's digit
    limit and RecursionError for deep nesting.
    """
    try:
        return json.loads(text)
    except json.JSONDecodeError as error:
        raise PresetError(f"is not valid JSON ({error})") from error
    except RecursionError as error:
        raise PresetError("is not valid JSON (nested too deeply)") from error
    except ValueError as error:  # the only other ValueError json raises
        raise PresetError("is not valid JSON (a number has too many digits)") from error
    except Exception as error:  # a preset must never stop the add-on
        raise PresetError(f"is not valid JSON ({type(error).__name__}: {_printable(str(error))})") from error


def _text(data, key, default, kind):
    """A string entry of the preset; Blender cannot take a lone surrogate (UTF-16 half) in a name."""
    value = data.get(key, default)
    if not isinstance(value, str):
        raise PresetError(f"'{key}' must be {kind}")
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as error:
        raise PresetError(f"'{key}' is not valid text") from error
    return value


def _printable(text):
    """`text` on one line: a warning names a hostile file or key without breaking the console."""
    return text if text.isprintable() else ascii(text)[1:-1]


_ENTRIES = {"name", "description", "values"}


def load_dir(directory, user=False):
    """Every usable preset in `directory`, sorted by name, and the warnings.

    A broken file becomes one warning that names it; no file can make it raise,
    so a hostile user folder cannot stop the add-on from enabling.
    """
    presets, warnings = [], []
    directory = Path(directory)
    try:
        paths = sorted(directory.glob("*.json")) if directory.is_dir() else []
    except OSError as error:
        return presets, [f"cannot list presets in {_printable(str(directory))}: {error}"]
    for path in paths:
        try:
            preset, notes = _load_one(path, user)
        except Exception as error:  # PresetError, or a case nobody foresaw
            reason = error if isinstance(error, PresetError) else f"{type(error).__name__}: {error}"
            warnings.append(_printable(f"skipped preset {path}: {reason}"))
            continue
        presets.append(preset)
        warnings += [_printable(note) for note in notes]
    presets.sort(key=lambda p: (p.id != "lake", p.name.lower()))  # the reference first
    return presets, warnings


def _load_one(path, user):
    """read_preset, refusing a file name Blender cannot show (not valid UTF-8)."""
    try:
        path.stem.encode("utf-8")
    except UnicodeEncodeError as error:
        raise PresetError("its file name is not valid UTF-8") from error
    return read_preset(path, user=user)


def slug(name):
    """A file stem for a preset name: lower case letters, digits and underscores."""
    stem = re.sub(r"[^a-z0-9]+", "_", name.strip().lower()).strip("_")
    if not stem:
        raise PresetError(f"'{name}' has no letters or digits to name a file with")
    return stem[:64]


class PresetExistsError(PresetError):
    """Saving would replace a preset the user already has."""


def write_preset(directory, name, values, description="", overwrite=False):
    """Saves `values` (checked and clamped first) as preset `name`; returns its path.

    Refuses to replace an existing preset unless `overwrite`, and never writes
    through a symlink. The file is written whole to a temporary file and moved
    into place, so a crash never leaves half a preset.
    """
    if not isinstance(name, str) or not name.strip():
        raise PresetError("a preset needs a name")
    clean, unknown = schema.check_values(dict(values))
    if unknown:
        raise PresetError(f"unknown values: {', '.join(sorted(unknown))}")
    data = {
        "name": name.strip(),
        "description": description,
        "values": {key: list(v) if isinstance(v, tuple) else v for key, v in clean.items()},
    }
    directory = Path(directory)
    path = directory / f"{slug(name)}.json"
    directory.mkdir(parents=True, exist_ok=True)
    _check_target(path, overwrite)
    _write_atomic(path, (json.dumps(data, indent=2) + "\n").encode("utf-8"))
    return path


def _check_target(path, overwrite):
    """PresetError unless `path` may be (re)written as a preset."""
    if os.path.islink(path):
        raise PresetError(f"{path} is a symbolic link: not writing through it (remove it to save here)")
    if not os.path.lexists(path):
        return
    if not stat.S_ISREG(os.lstat(path).st_mode):
        raise PresetError(f"{path} exists and is not a regular file")
    if not overwrite:
        raise PresetExistsError(f"preset '{path.stem}' already exists ({path}): pass overwrite to replace it")


class PresetGoneError(PresetError):
    """The preset's file is no longer there (deleted or moved outside Blender)."""


def remove_preset(path):
    """Deletes the preset file `path` (a symbolic link itself, never its target).

    PresetGoneError when the file is gone already, PresetError when it cannot be
    deleted; each one line that names the file.
    """
    path = Path(path)
    try:
        path.unlink()
    except FileNotFoundError as error:
        raise PresetGoneError(
            f"its file {path} is gone already (deleted or moved outside Blender)"
        ) from error
    except OSError as error:
        raise PresetError(f"cannot delete {path} ({error.strerror or error})") from error


def _write_atomic(path, data):
    """Writes `data` to a new temporary file beside `path`, then renames it over `path`.

    O_EXCL makes sure the temporary file is a new one of ours, not a link
    planted in its place; os.replace swaps the name, never following a link.
    """
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
    temp = path.with_name(f".{path.stem}-{secrets.token_hex(8)}.tmp")
    fd = os.open(temp, flags, 0o666)
    try:
        try:
            view = memoryview(data)
            while view:
                view = view[os.write(fd, view) :]
            os.fsync(fd)
        finally:
            os.close(fd)
        os.replace(temp, path)
    except BaseException:
        temp.unlink(missing_ok=True)
        raise
