"""Whether the add-on may edit a data-block: never linked, overridden or missing library data.

Edits to data linked from a library live only in memory and vanish when the
file is reloaded, so every operator refuses them with a message saying what to do.
"""

import os

from .errors import WaterError

_KINDS = {"NODETREE": "Node group", "LIGHT": "Light", "MESH": "Mesh", "OBJECT": "Object"}
_FIX = "make it local (Object > Relations > Make Local) or edit it in its library"


class NotEditableError(WaterError, ValueError):
    """A data-block the add-on would edit comes from a library."""


def _library_name(library):
    if library is None:
        return "a library"
    path = library.filepath or library.name
    return os.path.basename(path.replace("\\", "/")) or library.name


def describe(id_data):
    """How a data-block is named in messages: its kind and name ("Material 'Water'")."""
    kind = _KINDS.get(getattr(id_data, "id_type", ""), getattr(id_data, "id_type", "Data").title())
    return f"{kind} '{id_data.name}'"


def why_not_editable(*ids):
    """Why the first of `ids` that cannot be edited cannot be, or None when all can (None ids are skipped)."""
    for id_data in ids:
        if id_data is None:
            continue
        if getattr(id_data, "is_missing", False):
            return (
                f"{describe(id_data)} is missing from its library "
                f"{_library_name(id_data.library)}: find the library (File > External Data) or remove it"
            )
        if id_data.library is not None:
            return f"{describe(id_data)} is linked from {_library_name(id_data.library)}: {_FIX}"
        override = id_data.override_library
        if override is not None:
            reference = override.reference
            source = _library_name(reference.library if reference is not None else None)
            return f"{describe(id_data)} is a library override of {source}: {_FIX}"
    return None


def check_editable(*ids):
    """Raises NotEditableError saying why when one of `ids` cannot be edited."""
    why = why_not_editable(*ids)
    if why is not None:
        raise NotEditableError(why)
