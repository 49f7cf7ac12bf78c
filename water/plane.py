"""A water plane: a mesh with UVs and its own water material."""

import bmesh
import bpy
from mathutils import Euler, Matrix, Vector

from .. import presets
from ..nodes.material import make_water_material
from ..presets import schema
from . import mirror
from .values import write_values


def new_water_mesh(name, size):
    """A square of edge `size` in the XY plane, centred, UVs 0..1 across it."""
    size = schema.clamp_values({"size": size})["size"]
    mesh = bpy.data.meshes.new(name)
    bm = bmesh.new()
    try:
        uv_layer = bm.loops.layers.uv.new("UVMap")
        half = size / 2
        verts = [bm.verts.new((x * half, y * half, 0.0)) for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        face = bm.faces.new(verts)
        for loop in face.loops:
            co = loop.vert.co
            loop[uv_layer].uv = (co.x / size + 0.5, co.y / size + 0.5)
        bm.to_mesh(mesh)
    finally:
        bm.free()
    return mesh


def dress_water(obj, scene, values):
    """Gives `obj` a new water material set to `values` (preset keys); returns the material."""
    material = make_water_material(name=obj.name, scene=scene)
    write_values(material, values)
    obj.data.materials.clear()
    obj.data.materials.append(material)
    return material


def resolve_values(preset="lake", **overrides):
    """A preset's values with `overrides` (preset keys) on top, all clamped.

    Raises PresetError for an unknown preset or key.
    """
    unknown = set(overrides) - set(schema.BY_KEY)
    if unknown:
        raise presets.PresetError(f"unknown water value(s): {', '.join(sorted(unknown))}")
    values = dict(presets.get(preset).values)
    values.update({k: v for k, v in overrides.items() if v is not None})
    return schema.clamp_values(values)


def add_water(
    scene=None,
    preset="lake",
    location=(0.0, 0.0, 0.0),
    rotation=(0.0, 0.0, 0.0),
    collection=None,
    mirror_setup=True,
    name="Water",
    **overrides,
):
    """Adds a water plane to `scene` (default: the context's) and returns (object, changes).

    `overrides` are preset keys (`size`, `wave_height`, ...) that replace the
    preset's values; every value is clamped into range. `changes` lists what
    the mirror set-up changed in the scene.
    """
    scene = scene or bpy.context.scene
    values = resolve_values(preset, **overrides)
    obj = bpy.data.objects.new(name, new_water_mesh(name, values["size"]))
    (collection or scene.collection).objects.link(obj)
    obj.matrix_world = Matrix.LocRotScale(Vector(location), Euler(rotation), None)
    dress_water(obj, scene, values)
    changes = mirror.setup_mirror(scene, obj) if mirror_setup else []
    return obj, changes
