"""The add-on's errors: one base, `WaterError`, so a script can catch every refusal of the API at
once (`except api.WaterError`), and the classes that name what a refusal is about when no module
of its own has one. Plain Python (no bpy): `presets/schema.py` builds its `PresetError` on it.

Every class of the add-on's keeps the builtin base it had (`ValueError` or `RuntimeError`) beside
`WaterError`, so code that caught those still does. Each message is one line.
"""


class WaterError(Exception):
    """The base of every error the add-on's API raises: what was asked cannot be done, and
    nothing was changed (a one-line message saying why)."""


class NotWaterError(WaterError, ValueError):
    """The object given is not water: no material the add-on made (`kind.refusal`'s words)."""


class KindError(WaterError, ValueError):
    """The water's kind does not allow what was asked (`kind.FEATURES`; `kind.refusal`'s words)."""


class NeedsRepairError(WaterError, ValueError):
    """The water's node group lost inputs or was replaced: Repair Water first."""


class UnderwaterError(WaterError, ValueError):
    """The water's underwater body cannot take what was asked (Light Shafts with Underwater off)."""


class NoCameraError(WaterError, ValueError):
    """The scene has no camera to work with (Extend Camera Clip)."""


class WrongTypeError(WaterError, TypeError):
    """An argument of the wrong type (a scene's name where the scene itself belongs)."""
