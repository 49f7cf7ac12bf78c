"""Water Surface's Python API: the public surface for scripts, pipelines and pytest.

These wrap the same `water/*` functions the operators, the panel and the command
line call, so a script gets the same water as a click. Import it through the add-on's module,
whatever extension repository it was installed into::

    import importlib, addon_utils
    name = next(m.__name__ for m in addon_utils.modules() if m.__name__.rpartition(".")[2] == "water_surface")
    water_api = importlib.import_module(name + ".api")
    added = water_api.add_water(preset="windy_river", size=40)

Bad input raises a `WaterError`, the one base of the add-on's errors, each class naming what it is
about: PresetError (a value of the wrong type, NaN, an infinity), NotWaterError, KindError (the
water's kind does not allow it), NeedsRepairError, UnderwaterError, NoCameraError, WrongTypeError
(a scene that is no scene), AddWaterError, MirrorSetupError, SurroundingsError,
PhysicalCausticsError, FloatError, KeepOutError, WakeError, RemoveWaterError, OpenSeaError,
NotEditableError (linked or overridden data, never edited) or FileJobError, each with a one-line
message; nothing is left half made. Each keeps its builtin base too (ValueError, RuntimeError;
WrongTypeError a TypeError).
"""

from __future__ import annotations

import bpy

from . import presets as _presets
from .presets import PresetError
from .water import apply as _apply
from .water import camera_clip as _camera_clip
from .water import files as _files
from .water import kind as _kind
from .water import mirror as _mirror
from .water import physical_caustics as _physical_caustics
from .water import removal as _removal
from .water import surroundings as _surroundings
from .water import underwater as _underwater
from .water import values as _values
from .water import waves as _waves
from .water.boats import floating as _floating
from .water.boats import keep_out as _keep_out
from .water.boats import wake as _wake
from .water.boats.floating import FloatError
from .water.boats.keep_out import KeepOutError
from .water.boats.wake import WakeError
from .water.editable import NotEditableError
from .water.errors import (
    KindError,
    NeedsRepairError,
    NoCameraError,
    NotWaterError,
    UnderwaterError,
    WaterError,
    WrongTypeError,
)
from .water.files import FileJobError
from .water.mirror import MirrorSetupError
from .water.physical_caustics import PhysicalCausticsError
from .water.plane import AddedWater, AddWaterError
from .water.plane import add_water as _add_water
from .water.removal import RemoveWaterError
from .water.sea import open_sea as _open_sea
from .water.sea.open_sea import OpenSeaError
from .water.surroundings import SurroundingsError

__all__ = (
    "AddWaterError",
    "AddedWater",
    "FileJobError",
    "FloatError",
    "KeepOutError",
    "KindError",
    "MirrorSetupError",
    "NeedsRepairError",
    "NoCameraError",
    "NotEditableError",
    "NotWaterError",
    "OpenSeaError",
    "PhysicalCausticsError",
    "PresetError",
    "RemoveWaterError",
    "UnderwaterError",
    "WaterError",
    "WrongTypeError",
    "add_wake_source",
    "add_water",
    "add_water_to_file",
    "add_waves",
    "apply_preset",
    "bake",
    "extend_camera_clip",
    "float_on_water",
    "is_water",
    "keep_water_out",
    "kind_of",
    "let_water_in",
    "preset_ids",
    "read_values",
    "render_file",
    "remove_surroundings",
    "remove_wake_source",
    "remove_water",
    "set_physical_caustics",
    "set_surroundings",
    "set_swell",
    "set_underwater",
    "set_light_shafts",
    "setup_mirror",
    "stop_floating",
    "SurroundingsError",
    "WakeError",
    "switch_part",
    "write_values",
)


def add_water(
    scene: bpy.types.Scene | None = None,
    preset: str = "lake",
    location: tuple[float, float, float] = (0.0, 0.0, 0.0),
    rotation: tuple[float, float, float] = (0.0, 0.0, 0.0),
    collection: bpy.types.Collection | None = None,
    mirror_setup: bool = True,
    name: str = "Water",
    see_surroundings: bool = True,
    **values: object,
) -> AddedWater:
    """Adds water to `scene` (default: the context's) from `preset`, `values` (preset keys such
    as size, wave_height, waves) on top. Lake water gets the mirror set-up unless
    `mirror_setup` is False. Every water gets its surroundings collection (the objects reaching
    below it) and the points its waterline needs, unless `see_surroundings` is False.
    All or nothing: AddWaterError leaves no trace."""
    return _add_water(
        scene,
        preset=preset,
        location=location,
        rotation=rotation,
        collection=collection,
        mirror_setup=mirror_setup,
        name=name,
        see_surroundings=see_surroundings,
        **values,
    )


def remove_water(water: bpy.types.Object, scene: bpy.types.Scene | None = None) -> list[str]:
    """Removes `water` and everything the add-on made for it that nothing else uses: its probe,
    surroundings, light linking, floating constraints on other objects, Physical Caustics, and
    the scene settings its set-up changed (put back only when unchanged since and needed by no
    other water). Returns the changes in words; RemoveWaterError for an object that is not water."""
    return _removal.remove_water(water, scene or bpy.context.scene)


def is_water(obj: bpy.types.Object | None) -> bool:
    """Whether `obj` has a material the add-on made (lake or ocean shading)."""
    return _values.is_water(obj)


def kind_of(obj: bpy.types.Object | None) -> str | None:
    """ "lake", "ocean" (the four-sine ocean's shading) or "open_sea" for a water, None otherwise."""
    return _kind.kind_of(obj)


def setup_mirror(water: bpy.types.Object, scene: bpy.types.Scene | None = None) -> list[str]:
    """Sets the scene up so lake `water` shows a true mirror; returns what changed, in words.
    Ocean shading reflects the world's sky: it gets only the render engine (from Workbench) and
    EEVEE's ray tracing, no probe."""
    return _mirror.setup_mirror(scene or bpy.context.scene, water)


def add_waves(water: bpy.types.Object) -> bpy.types.NodesModifier:
    """Adds (or finds) the four-sine `Water Waves` modifier and refits the mirror probe to it.
    NotWaterError for an object that is not water, KindError for an open sea (its waves are its
    Ocean modifier)."""
    _apply.check_allowed(water, "waves")
    modifier = _waves.add_waves(water)
    _mirror.fit_probe(water)
    return modifier


def set_surroundings(
    water: bpy.types.Object,
    collection: bpy.types.Collection | None = None,
    scene: bpy.types.Scene | None = None,
) -> list[str]:
    """Makes `water` measure depth and shore foam against `collection`'s objects, or, with None,
    against the add-on's own collection gathered again from the objects reaching below it.
    Returns what changed; SurroundingsError for a collection holding the water itself."""
    return _surroundings.ensure_surroundings(water, scene or bpy.context.scene, collection=collection)


def remove_surroundings(water: bpy.types.Object) -> list[str]:
    """Takes the surroundings off `water` (its sample modifier, its cache, the add-on's own
    collection; a collection of yours is left alone), e.g. to apply its other modifiers.
    Returns what changed."""
    return _surroundings.remove_surroundings(water)


def set_physical_caustics(
    water: bpy.types.Object, enable: bool = True, scene: bpy.types.Scene | None = None
) -> list[str]:
    """Switches Cycles' own caustics (manifold next-event estimation) on for lake `water`, or off
    again, putting back what was changed. Returns the changes; PhysicalCausticsError says why not."""
    scene = scene or bpy.context.scene
    if enable:
        return _physical_caustics.enable(water, scene)
    return _physical_caustics.disable(water, scene)


def float_on_water(
    obj: bpy.types.Object,
    water: bpy.types.Object | None = None,
    tilt_damping: float = 0.0,
    scene: bpy.types.Scene | None = None,
    draft: float | None = None,
    length: float | None = None,
    beam: float | None = None,
    wake: bool = True,
) -> list[str]:
    """Makes `obj` ride `water` (default: the water below or above its origin) by its footprint,
    with constraints and drivers (no Python at render): its heave from the water's mean height
    under it, `draft` metres of it below the waterline (None: a third of its height), its pitch
    and roll from the plane fitted to the surface over `length` x `beam` metres (None: its
    bounds'), less by `tilt_damping` (0..1); with `wake`, it leaves a wake as it moves (see
    `add_wake_source`; stopping takes it off). Floating it again takes new values and where it is
    now. FloatError when there is no water or a size is out of range; returns the changes in
    words."""
    scene = scene or bpy.context.scene
    water = _floating.water_for(obj, scene, FloatError, water, floating_first=False)
    return _floating.float_on_water(obj, water, tilt_damping, draft, length, beam, scene, wake)


def stop_floating(obj: bpy.types.Object) -> list[str]:
    """Removes what `float_on_water` added; returns the changes in words."""
    return _floating.stop_floating(obj)


def keep_water_out(obj: bpy.types.Object, water: bpy.types.Object | None = None) -> list[str]:
    """Makes `water` (default: the water `obj` floats on, else the water below or above its origin)
    invisible inside `obj`, a hull: within its outline at the heights the water meets it, wherever
    it moves and rocks, in EEVEE and Cycles, by nodes in the water's material (no Python at
    render). Again: made anew from its shape now. KeepOutError when there is no water or `obj`
    encloses nothing; returns the changes in words."""
    water = _floating.water_for(obj, bpy.context.scene, KeepOutError, water)
    return _keep_out.keep_water_out(obj, water)


def let_water_in(obj: bpy.types.Object, water: bpy.types.Object | None = None) -> list[str]:
    """Takes `keep_water_out` off (`water`, default: every water kept out of `obj`); returns the
    changes in words."""
    return _keep_out.let_water_in(obj, water)


def add_wake_source(
    obj: bpy.types.Object, water: bpy.types.Object | None = None, strength: float = 1.0
) -> list[str]:
    """Makes `obj` leave a Kelvin wake and foam on `water` (default: the water it floats on, else
    the water below or above its origin) as it moves: in the water's evaluated mesh (a `Water
    Wake` modifier whose simulation zone keeps its track), the foam as `water_wake_foam`.
    `strength` scales the waves' height. Again: its sizes brought up to date. WakeError when
    there is no water; returns the changes in words."""
    water = _floating.water_for(obj, bpy.context.scene, WakeError, water)
    return _wake.add_wake_source(obj, water, strength)


def remove_wake_source(obj: bpy.types.Object, water: bpy.types.Object | None = None) -> list[str]:
    """Takes `obj`'s wake off `water` (default: off every water); returns the changes in words."""
    return _wake.remove_wake_source(obj, water)


def bake(water: bpy.types.Object, scene: bpy.types.Scene | None = None) -> list[str]:
    """Bakes the wakes of `water` over the scene's frame range, so frames rendered apart (a farm)
    equal one run from the start: packed into the .blend from 4.3; on 4.2 into the folder
    "//<file>_water_bakes" beside the saved .blend (save first). Bake again after changing the
    moving objects' animation. WakeError with no wake or, on 4.2, an unsaved file; returns the
    changes in words."""
    return _wake.bake(water, scene or bpy.context.scene)


def read_values(water: bpy.types.Object) -> dict:
    """Every value `write_values` sets, keyed as in presets: the shader values (ocean shading: the
    keys it shares with the lake's, the bump's scroll, absorption, foam and caustics),
    `underwater`, `light_shafts` and, on an open sea, `whitecaps`; a preset saved from them
    restores the water. NotWaterError for an object that is not water."""
    return _apply.read_water(water)


def write_values(water: bpy.types.Object, values: dict) -> None:
    """Sets the water's values from preset keys as a preset does (`apply_preset`): the shader
    values (ocean shading: those it shares with the lake's; a part whose value crosses 0 comes in
    or goes out), `underwater`, `light_shafts`, an open sea's `whitecaps`, and the caustic light
    that follows Caustics. Each value is clamped into range; the keys made when adding (size,
    resolution, waves, shading, the sea's) and unknown keys are left alone.

    Refused before anything changes: PresetError for a value of the wrong type, NaN or an
    infinity (naming the key); UnderwaterError for Light Shafts with Underwater off;
    NotWaterError, NotEditableError for linked or overridden water, NeedsRepairError.
    """
    _apply.apply_values(water, values)


def switch_part(water: bpy.types.Object, part: str, on: bool = True) -> list[str]:
    """Turns an optional part of a water's shading on or off: on a lake "depth" (colour by depth),
    "foam" (shore foam) or "caustics"; on the ocean shading (the seeds' ocean, the open sea)
    "caustics". A part that is off is not in the shader at all, so it costs nothing;
    `write_values` does the same when a switch (Absorption, Foam Amount, Caustics) crosses 0.
    Returns what it did, in words.

    KindError (a ValueError) for another word; NotWaterError, NotEditableError for linked water,
    NeedsRepairError.
    """
    material = _apply.check_water(water)
    return _values.switch_part(material, part, on) + _underwater.fit_light(water)


def set_underwater(
    water: bpy.types.Object, on: bool = True, scene: bpy.types.Scene | None = None
) -> list[str]:
    """The `Underwater` switch (on for every new water; the preset key `underwater`): on, a camera
    under `water` sees through water, what is far fading into its own colour (its Absorption and
    Scatter Color, the ocean's Deep Color), by a hidden child `"<water> Underwater"` made only while
    the camera is near or under the surface; off, that child goes. Returns what it did, in words.

    Refused before anything changes: NotWaterError for an object that is not water,
    NotEditableError for linked water, PresetError for an `on` that is no bool, WrongTypeError for
    a `scene` that is no Scene (its name, say).
    """
    _apply.check_allowed(water, "underwater")
    return _apply.apply_values(water, {"underwater": on}, scene or bpy.context.scene)


def set_light_shafts(water: bpy.types.Object, share: float) -> list[str]:
    """`Light Shafts` (0 for every new water; the preset key `light_shafts`): under the water, the
    share (0..1, clamped) of what the water takes from the light that it scatters towards the eye
    rather than absorbs, so the sun's shafts show, patterned by the caustics. The water's
    extinction stays what it was; 0 costs nothing. Returns what it did, in words.

    Refused before anything changes: PresetError for a share that is no number, NaN or an
    infinity; UnderwaterError with Underwater off; NotWaterError for an object that is not water;
    NotEditableError for linked water.
    """
    _apply.check_allowed(water, "underwater")
    return _apply.apply_values(water, {"light_shafts": share})


def extend_camera_clip(
    water: bpy.types.Object, camera: bpy.types.Object | None = None, scene: bpy.types.Scene | None = None
) -> list[str]:
    """Moves the Clip End of `camera` (default: the scene's) past the farthest corner of `water`,
    so none of it is cut off (an open sea reaches kilometres; a camera sees 100 m by default).
    Returns the change in words, [] when it already sees all of it; NoCameraError without a camera."""
    return _camera_clip.extend_clip(scene or bpy.context.scene, water, camera)


def set_swell(
    water: bpy.types.Object,
    height: float | None = None,
    period: float | None = None,
    direction: tuple[float, float] | None = None,
    scene: bpy.types.Scene | None = None,
) -> str:
    """Sets the open sea's swell, as `sea_swell_height` (m, significant), `sea_swell_period` (s)
    and `sea_swell_direction` (x, y) do when adding it; values left out stay as they were, height
    0 removes it. Returns the change in words. OpenSeaError for water that is no open sea,
    PresetError for a value of the wrong type."""
    why = _kind.refusal(water, "swell", subject=f"'{getattr(water, 'name', water)}'")
    if why is not None:
        raise OpenSeaError(why)
    values = {"sea_swell_height": height, "sea_swell_period": period, "sea_swell_direction": direction}
    return _open_sea.change_swell(water, values, scene or bpy.context.scene)


def preset_ids() -> list[str]:
    """The ids of every preset, built-in first (user presets start with "user:")."""
    return [preset.id for preset in _presets.all_presets()]


def apply_preset(water: bpy.types.Object, preset: str) -> None:
    """Sets the lake water's values from a preset as `write_values` does, the same path the
    operator takes: shader values, `underwater`, `light_shafts` and the caustic light (its plane
    values are left alone).

    PresetError for an unknown preset, or water whose kind takes no presets (ocean shading), as
    the operator refuses it; NotWaterError, NotEditableError, NeedsRepairError.
    """
    _apply.apply_preset(water, preset)


def add_water_to_file(source: str, target: str, **options: object) -> str:
    """Opens the .blend `source`, adds water (as `add_water`), saves it as `target`; returns what it did."""
    return _files.add_water_to_file(source, target, **options)


def render_file(source: str, target: str, **options: object) -> str:
    """Renders frames of the .blend `source` to `target` (see `water.files.render_file`)."""
    return _files.render_file(source, target, **options)
