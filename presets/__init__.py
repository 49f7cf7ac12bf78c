"""Water presets: JSON data, validated when read, never executed.

Built-in presets ship as `presets/*.json`; the user's live under
`extension_path_user(<add-on>, path="presets")`. A broken file is skipped with
a warning on the console and never stops the add-on.
"""

import sys

from . import schema, store
from .schema import PresetError
from .store import PresetExistsError, PresetGoneError

ADDON_PACKAGE = __package__.rpartition(".")[0]

_presets = []  # the loaded presets, built-in first
_enum_items = []  # kept alive: Blender does not copy the strings of dynamic enum items


def user_dir(create=True):
    """Where the user's presets are saved (outside the add-on's folder).

    The one part of presets that needs Blender: imported here, so schema, store and the rest
    import and are tested without it."""
    import bpy

    return bpy.utils.extension_path_user(ADDON_PACKAGE, path="presets", create=create)


def warn(message):
    print(f"Water Surface: {message}", file=sys.stderr)


def reload():
    """Reads every preset again; returns the warnings (also printed)."""
    builtin, warnings = store.load_dir(store.BUILTIN_DIR)
    try:
        user, user_warnings = store.load_dir(user_dir(), user=True)
    except OSError as error:  # an unwritable user folder must not stop the add-on
        user, user_warnings = [], [f"cannot read user presets: {error}"]
    _presets[:] = builtin + user
    _enum_items[:] = [
        (
            p.id,
            p.name + (" (user)" if p.user else ""),
            p.description or p.name,
            "USER" if p.user else "NONE",
            i,
        )
        for i, p in enumerate(_presets)
    ]
    for message in warnings + user_warnings:
        warn(message)
    return warnings + user_warnings


def all_presets():
    if not _presets:
        reload()
    return list(_presets)


def get(preset_id):
    """The preset with `preset_id`; PresetError naming the known ones otherwise."""
    for preset in all_presets():
        if preset.id == preset_id:
            return preset
    known = ", ".join(p.id for p in _presets)
    raise PresetError(f"no preset '{preset_id}' (known: {known})")


def enum_items(_self=None, _context=None):
    """Items for an EnumProperty listing every preset, the reference lake first."""
    if not _enum_items:
        reload()
    return _enum_items


def save_user_preset(name, values, overwrite=False):
    """Writes a user preset and reloads; returns its id.

    An existing preset of that name is replaced only with `overwrite`
    (store.PresetExistsError otherwise), so a user's preset is never lost unasked.
    """
    path = store.write_preset(user_dir(), name, values, overwrite=overwrite)
    reload()
    return store.USER_PREFIX + path.stem


def remove_user_preset(preset_id):
    """Deletes a user preset's file and reloads; built-in presets cannot be removed.

    The list is reloaded also when deleting fails, so a preset whose file is gone
    already (store.PresetGoneError) leaves the list with the error.
    """
    preset = get(preset_id)
    if not preset.user:
        raise PresetError(f"'{preset.name}' is built in and cannot be removed")
    try:
        store.remove_preset(preset.path)
    finally:
        reload()


__all__ = (
    "PresetError",
    "PresetExistsError",
    "PresetGoneError",
    "schema",
    "store",
    "user_dir",
    "reload",
    "all_presets",
    "get",
    "enum_items",
)


def register():
    reload()


def unregister():
    _presets.clear()
    _enum_items.clear()
