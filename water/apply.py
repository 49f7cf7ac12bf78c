"""The one path a set of values (preset keys) takes into a water, and the one way they are read
back: Add Water (once the new water's mesh and material are made), the preset operator,
`apply_preset`, `write_values`, `set_underwater`, `set_light_shafts`, the panel's Underwater
button and the command line (through `add_water`) all call `apply_values`; `read_values` and
Save Water Preset call `read_water`, which returns every key `apply_values` applies, so a saved
preset restores the water.

`apply_values` refuses first, before anything changes: an object that is no water
(`NotWaterError`), linked data (`NotEditableError`), a water needing repair (`NeedsRepairError`),
a scene that is no scene (`WrongTypeError`), a value of the wrong type, NaN or an infinity
(`PresetError` naming the key), Light Shafts without Underwater (`UnderwaterError`). Then it
clamps, sets the shader values (a part whose switch crosses 0 comes in or goes out), and applies
each key of `value_keys.WATER_KEYS` the water's kind allows (`_STEPS`: the underwater body, the
light shafts, the open sea's whitecaps), and last fits the caustic light to the Caustics it now
has. Which key goes where is `value_keys.py`'s table.
"""

import bpy

from .. import presets
from ..presets import schema
from . import kind, underwater
from .editable import check_editable
from .errors import KindError, NeedsRepairError, NotWaterError, UnderwaterError, WrongTypeError
from .repair import needs_repair
from .sea import open_sea
from .value_keys import WATER_KEYS
from .values import read_values as read_shader_values
from .values import set_values, water_material


def subject(water):
    """How a water is named in a message: `'Lake'`."""
    return f"'{getattr(water, 'name', water)}'"


def check_allowed(water, feature, error=KindError):
    """Raises NotWaterError when `water` is no water, `error` (kind.refusal's words) when its kind
    does not allow `feature` (`kind.FEATURES`)."""
    why = kind.refusal(water, feature, subject=subject(water))
    if why is not None:
        raise (NotWaterError if kind.kind_of(water) is None else error)(why)


def check_water(water, feature="shader_parts"):
    """The water's material, after the refusals every change of a water shares: no water or a kind
    without `feature`, linked or overridden data (NotEditableError), a water needing repair."""
    check_allowed(water, feature)
    material = water_material(water)
    check_editable(water, material)
    problem = needs_repair(material)
    if problem:
        raise NeedsRepairError(problem)
    return material


def scene_for(water, scene):
    """`scene`, or with None the water's: the context's when the water is in it, else the first
    that holds it. WrongTypeError for anything that is no scene (its name, say), before anything
    changes."""
    if scene is not None:
        if not isinstance(scene, bpy.types.Scene):
            named = f" '{scene}': pass bpy.data.scenes['{scene}']" if isinstance(scene, str) else ""
            raise WrongTypeError(f"scene must be a Scene, not {type(scene).__name__}{named}")
        return scene
    current = bpy.context.scene
    users = tuple(getattr(water, "users_scene", ()))
    if current is not None and (current in users or not users):
        return current
    return users[0] if users else current


def checked(values):
    """The known keys of `values` checked and clamped (unknown keys left out): PresetError naming
    the key for a value of the wrong type, NaN or an infinity."""
    schema.check_types(values)
    return schema.clamp_values({key: value for key, value in values.items() if key in schema.BY_KEY})


def light_shafts_refusal(name, share, underwater_on, fog_has_them=True):
    """Why Light Shafts `share` cannot be given to the water `name` (quoted), one line, or None:
    they are a value of the underwater body's fog, so they need Underwater on, and a fog made
    before Light Shafts takes them only when made again."""
    if share <= 0.0:
        return None
    if not underwater_on:
        return f"{name} has no light shafts to set: Underwater is off (switch it on, or give underwater true)"
    if not fog_has_them:
        return f"{name} has no light shafts to set: its underwater fog has none (switch Underwater off, on)"
    return None


def _fog_has_light_shafts(water):
    node = underwater.fog_node(water)
    return node is not None and node.inputs.get("Light Shafts") is not None


def _switch_underwater(water, on, scene):
    return underwater.switch(water, scene, on)


def _set_light_shafts(water, share, _scene):
    if underwater.find(water) is None or share == underwater.light_shafts(water):
        return []
    return underwater.set_light_shafts(water, share)


def _set_whitecaps(water, value, _scene):
    socket = open_sea.whitecaps_input(water_material(water))
    if socket is not None:
        socket.default_value = value
    return []


# One step per key of `value_keys.WATER_KEYS`, in the order they run (the body before its fog's
# light shafts); `tests/plain/test_values_keys.py` holds these keys to the table.
_STEPS = {
    "underwater": _switch_underwater,
    "light_shafts": _set_light_shafts,
    "whitecaps": _set_whitecaps,
}


def _read_whitecaps(_water, material):
    socket = open_sea.whitecaps_input(material)
    return None if socket is None else float(socket.default_value)


# One reader per key of `value_keys.WATER_KEYS` (None: the water has no such value to read).
_READERS = {
    "underwater": lambda water, _material: underwater.find(water) is not None,
    "light_shafts": lambda water, _material: float(underwater.light_shafts(water)),
    "whitecaps": _read_whitecaps,
}


def apply_values(water, values, scene=None):
    """Sets `values` (preset keys) on the existing water `water`: the one function every entry
    point calls (see the module's docstring). Keys made only when adding (`value_keys.ADDING_KEYS`:
    size, resolution, waves, shading, the sea's) and unknown keys are left alone; a key the
    water's kind has not (a lake socket on the ocean shading, whitecaps on a lake) is skipped, as
    a preset holds every key. Returns what changed beyond the values, in words (the underwater
    body, the caustic light, the light shafts). All refusals come before any change."""
    scene = scene_for(water, scene)
    material = check_water(water)
    clean = checked(values)
    own = {key: clean[key] for key in _STEPS if key in clean and kind.allows(water, WATER_KEYS[key])}
    on = own.get("underwater", underwater.find(water) is not None)
    fog_ok = ("underwater" in own and underwater.find(water) is None) or _fog_has_light_shafts(water)
    why = light_shafts_refusal(subject(water), own.get("light_shafts", 0.0), on, fog_ok)
    if why is not None:
        raise UnderwaterError(why)
    changes = []
    set_values(material, clean)  # the shader keys; parts fitted to them
    for key, step in _STEPS.items():
        if key in own:
            changes += step(water, own[key], scene)
    return changes + underwater.fit_light(water, scene)  # the caustic light follows Caustics


def apply_preset(water, preset, scene=None):
    """Applies the preset with id `preset` to `water` (`apply_values`); returns what changed.
    PresetError for an unknown preset, a water whose kind takes no presets (ocean shading) or a
    preset that builds its own mesh and shading; NotWaterError for an object that is no water."""
    chosen = presets.get(preset)
    check_allowed(water, "presets", error=presets.PresetError)
    why = kind.preset_refusal(chosen.name, chosen.values)
    if why is not None:
        raise presets.PresetError(why)
    return apply_values(water, chosen.values, scene)  # checked and clamped again: a no-op for a preset


def read_water(water):
    """Every key `apply_values` applies, as `water` holds it: the shader values its shading has
    (an input its group lacks is left out, as on a water needing repair), and each key of
    `value_keys.WATER_KEYS` its kind has. NotWaterError for an object that is no water."""
    check_allowed(water, "shader_parts")
    material = water_material(water)
    values = read_shader_values(material)
    for key, reader in _READERS.items():
        value = reader(water, material) if kind.allows(water, WATER_KEYS[key]) else None
        if value is not None:
            values[key] = value
    return values
