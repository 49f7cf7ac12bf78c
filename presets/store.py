"""Preset files: read, validated and written as JSON. Plain Python (no bpy).

A preset file is `{"name": ..., "description": ..., "values": {key: value}}`
with the keys of `schema.FIELDS`. A file that cannot be used is skipped with
the reason; a value out of range is clamped; a missing value is the
reference's. Nothing in a preset is ever executed.
"""

import json
import re
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
    try:
        if path.stat().st_size > MAX_BYTES:
            raise PresetError(f"larger than {MAX_BYTES} bytes")
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError) as error:
        raise PresetError(f"cannot be read ({error})") from error
    except json.JSONDecodeError as error:
        raise PresetError(f"is not valid JSON ({error})") from error
    if not isinstance(data, dict):
        raise PresetError("must be a JSON object")
    name = data.get("name", path.stem.replace("_", " ").title())
    description = data.get("description", "")
    if not isinstance(name, str) or not name.strip():
        raise PresetError("'name' must be a non-empty string")
    if not isinstance(description, str):
        raise PresetError("'description' must be a string")
    clean, unknown = schema.check_values(data.get("values", {}))
    warnings = [f"{path.name}: unknown value '{key}' ignored" for key in unknown]
    warnings += [f"{path.name}: unknown entry '{key}' ignored" for key in data if key not in _ENTRIES]
    values = {**schema.defaults(), **clean}
    preset_id = (USER_PREFIX if user else "") + path.stem
    return Preset(preset_id, name.strip(), description, values, path, user), warnings


_ENTRIES = {"name", "description", "values"}


def load_dir(directory, user=False):
    """Every usable preset in `directory`, sorted by name, and the warnings.

    A broken file becomes a warning that names it; it never raises.
    """
    presets, warnings = [], []
    directory = Path(directory)
    if not directory.is_dir():
        return presets, warnings
    for path in sorted(directory.glob("*.json")):
        try:
            preset, notes = read_preset(path, user=user)
        except PresetError as error:
            warnings.append(f"skipped preset {path}: {error}")
            continue
        presets.append(preset)
        warnings += notes
    presets.sort(key=lambda p: (p.id != "lake", p.name.lower()))  # the reference first
    return presets, warnings


def slug(name):
    """A file stem for a preset name: lower case letters, digits and underscores."""
    stem = re.sub(r"[^a-z0-9]+", "_", name.strip().lower()).strip("_")
    if not stem:
        raise PresetError(f"'{name}' has no letters or digits to name a file with")
    return stem[:64]


def write_preset(directory, name, values, description=""):
    """Saves `values` (checked and clamped first) as preset `name`; returns its path."""
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
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / f"{slug(name)}.json"
    path.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    return path
