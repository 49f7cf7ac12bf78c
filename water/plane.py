"""A water plane: a grid with UVs, its own water material, and optionally waves."""

from dataclasses import dataclass, field

import bpy
import numpy as np
from mathutils import Euler, Matrix, Vector

from .. import presets
from ..nodes.material import make_water_material
from ..nodes.sea.ocean_material import make_ocean_material
from ..presets import schema
from . import camera_clip, kind, mirror, scene_state, surroundings, waves
from .apply import apply_values, light_shafts_refusal
from .editable import check_editable
from .errors import UnderwaterError, WaterError
from .grid import grid_mesh, max_resolution
from .sea import open_sea, sea_math
from .sea.sea_mesh import new_sea_mesh


def new_water_mesh(name, size, resolution=2):
    """A square grid of edge `size` in the XY plane, `resolution` vertices a side, UVs 0..1 across it
    (values already clamped where they entered, `resolve_values`)."""
    return grid_mesh(name, np.linspace(-size / 2, size / 2, int(resolution)), size)


def dress_water(obj, scene, values):
    """Gives `obj` a new material (lake or ocean shading) for `values`, and the waves if asked; the
    values themselves are set by `apply.apply_values`, the one path (see `add_water`)."""
    check_editable(obj, obj.data)
    if kind.kind_of_values(values) == kind.LAKE:
        material = make_water_material(name=obj.name, scene=scene)
    else:
        material = make_ocean_material(name=obj.name, scene=scene)
    obj.data.materials.clear()
    obj.data.materials.append(material)
    # Sunlight goes through water to what lies below (the seeds' refraction map saw the scene
    # without the water); a refraction closure would otherwise shadow the bed in both engines.
    # Cycles' physical caustics turn it back on (`physical_caustics.py`): they need the shadow.
    obj.visible_shadow = False
    if kind.kind_of_values(values) == kind.OPEN_SEA:
        open_sea.set_sea(obj, values, scene)
    elif values.get("waves"):
        waves.add_waves(obj)
    return material


def resolve_values(preset="lake", **overrides):
    """A preset's values with `overrides` (preset keys) on top, all clamped: the one place a new
    water's values enter (the operator, the API and the command line all come through here).

    Raises PresetError for an unknown preset or key, or a value of the wrong type, NaN or an
    infinity; UnderwaterError for Light Shafts with Underwater off.
    """
    unknown = set(overrides) - set(schema.BY_KEY)
    if unknown:
        raise presets.PresetError(f"unknown water value(s): {', '.join(sorted(unknown))}")
    given = {k: v for k, v in overrides.items() if v is not None}
    schema.check_types(given)
    values = dict(presets.get(preset).values)
    values.update(given)
    values = schema.clamp_values(values)
    why = light_shafts_refusal("the new water", values["light_shafts"], values["underwater"])
    if why is not None:  # as `apply_values` refuses them on a water, before anything is made
        raise UnderwaterError(why)
    return values


@dataclass
class AddedWater:
    """What `add_water` made: the object, its material, the values used, and in words
    what the mirror set-up changed (`changes`) and what was adjusted (`notes`)."""

    object: bpy.types.Object
    material: bpy.types.Material
    values: dict
    changes: list = field(default_factory=list)
    notes: list = field(default_factory=list)

    def summary(self, preset_name):
        """One line for a report or the command line."""
        text = f"added '{self.object.name}' ({preset_name}, {self.values['size']:g} m)"
        text += f" with material '{self.material.name}'"
        if not mirror.needs_mirror(self.object):
            text += "; the ocean reflects the world's sky, no mirror set-up needed"
        if self.changes:
            text += "; set-up: " + ", ".join(self.changes)
        return text


class AddWaterError(WaterError, RuntimeError):
    """Adding water failed; nothing it made is left behind."""


def add_water(
    scene=None,
    preset="lake",
    location=(0.0, 0.0, 0.0),
    rotation=(0.0, 0.0, 0.0),
    collection=None,
    mirror_setup=True,
    name="Water",
    matrix=None,
    see_surroundings=True,
    **overrides,
):
    """Adds a water plane to `scene` (default: the context's); the one way water is added.

    `overrides` are preset keys (`size`, `wave_height`, `resolution`, `waves`,
    `shading`, ...) that replace the preset's values; every value is clamped
    into range. `matrix` (a 4x4 world matrix) wins over `location` and `rotation`.
    With `see_surroundings` (the default) the water gets its surroundings
    (`surroundings.py`): its own collection holding the mesh objects that reach
    below it (empty when there are none), measured by its cache; when something
    is below a lake, its grid gets the points the waterline needs (the open sea's
    graded grid stays as it is). Without it nothing
    is added and the lake stays one quad (the panel's Surroundings button adds
    them later).
    Atomic: on any failure everything it made is removed and `AddWaterError`
    (one line) is raised; PresetError for an unknown preset or value (of the wrong type, NaN,
    an infinity), UnderwaterError for Light Shafts with Underwater off, before anything is made.
    """
    scene = scene or bpy.context.scene
    values = resolve_values(preset, **overrides)
    notes = []
    sea = kind.kind_of_values(values) == kind.OPEN_SEA
    note = open_sea.sea_memory_note() if sea else None
    notes += [note] if note else []
    if values["resolution"] > max_resolution():
        values["resolution"] = max_resolution()
        notes.append(f"resolution lowered to {values['resolution']}: the free memory holds no more")
    before = _snapshot(scene)
    try:
        check_editable(scene, collection or scene.collection)
        obj = bpy.data.objects.new(name, _new_mesh(name, values))
        (collection or scene.collection).objects.link(obj)
        if matrix is None:
            matrix = Matrix.LocRotScale(Vector(location), Euler(rotation), None)
        obj.matrix_world = matrix
        # The open sea's graded grid is its own (its even middle is the waves' cell): kept as it is.
        if see_surroundings and not sea and surroundings.default_surroundings(obj, scene):
            notes += _densify_for_surroundings(obj, values)
        material = dress_water(obj, scene, values)
        changes = surroundings.ensure_surroundings(obj, scene) if see_surroundings else []
        # The one path every entry point takes: shader values, parts, underwater body, light
        # shafts, whitecaps, caustic light (`apply.py`).
        changes += apply_values(obj, values, scene)
        changes += mirror.setup_mirror(scene, obj) if mirror_setup else []
    except Exception as error:
        _roll_back(scene, before)
        message = str(error).strip().splitlines()[-1] if str(error).strip() else type(error).__name__
        raise AddWaterError(f"adding water failed, nothing was added: {message}") from error
    note = camera_clip.clip_note(scene, obj)
    notes += [note] if note else []
    return AddedWater(obj, material, values, changes, notes)


def _new_mesh(name, values):
    """The lake's even grid, or the open sea's grid that reaches the horizon."""
    if kind.kind_of_values(values) == kind.OPEN_SEA:
        values["shading"] = "ocean"
        wind = values["sea_wind_speed"]
        reach = sea_math.FADE_END_TILES * sea_math.tile_size(wind)  # the waves' whole extent
        return new_sea_mesh(name, values["size"], values["resolution"], sea_math.cell_size(wind), reach)
    return new_water_mesh(name, values["size"], values["resolution"])


def _densify_for_surroundings(obj, values):
    """A grid fine enough to find the waterline of the objects reaching below the new water."""
    needed = surroundings.needed_resolution(values["size"])
    if values["resolution"] >= needed:
        return []
    old = obj.data
    obj.data = new_water_mesh(old.name, values["size"], needed)
    bpy.data.meshes.remove(old)
    values["resolution"] = needed
    return [f"resolution raised to {needed} so the waterline of what stands in the water is found"]


# What adding water can create; removed again, newest kinds first, when it fails.
_KINDS = ("objects", "meshes", "materials", "node_groups", "images", "lightprobes", "worlds", "collections")


def _snapshot(scene):
    ids = {data_kind: {b.as_pointer() for b in getattr(bpy.data, data_kind)} for data_kind in _KINDS}
    return ids, scene_state.snapshot(scene)


def _roll_back(scene, before):
    """Removes every data-block made since `before` and puts every scene setting back."""
    ids, settings = before
    scene_state.restore(scene, settings)  # first: the world it may point back from is still there
    for data_kind in _KINDS:
        blocks = getattr(bpy.data, data_kind)
        for block in [b for b in blocks if b.as_pointer() not in ids[data_kind]]:
            blocks.remove(block)
