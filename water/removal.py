"""Removing a water, and everything the add-on made for it that nothing else uses.

`remove_water` is Remove Water (operator, panel, API): it switches the water's Physical
Caustics off, lets the objects floating on it go, takes its surroundings (sample modifier,
cache, the add-on's collection), its mirror probe and its light linking off, lets go of the
scene settings its mirror set-up changed (`ledger.py`: back only when unchanged since and
needed by no other water), then removes the object, and its mesh and material when no one
else uses them, and the add-on's groups, images and sky world that nothing uses any more.

A water deleted the ordinary way (X, Delete) is only taken out of the scene: what the add-on
made for it still refers to it (its underwater body's modifier, the sun's light-linking
collection), so Blender keeps it, with its hidden children, and a camera under where it was still
sees its fog and waterline; a hull deleted so keeps its dry hole in the water. `remove_leftovers`
finds such waters (in no scene, held only by the add-on) and hulls and takes them apart as Remove
Water does, the scene settings their set-up changed put back by the same rule: `handlers.py` runs
it as soon as objects leave the scenes, and before every save.

Whether nothing uses a block is asked of its references (`users.unused`), not its user count,
which a saved file leaves too high (see `users.py`).
"""

import bpy

from ..nodes import bump_image, caustics_image, foam_image
from ..nodes.ownership import is_local, is_original, role_of
from ..nodes.sea import rough_fresnel_image
from . import kind, ledger, mirror, physical_caustics, sun_link, surroundings, underwater
from .boats import float_rig, floating, keep_out, wake
from .editable import check_editable
from .errors import WaterError
from .float_constraints import float_constraints, floating_on
from .users import unused
from .values import water_material

# The add-on's data kinds removed once nothing uses them (their marks say whose they are).
_OWN_KINDS = ("node_groups", "images", "worlds", "lightprobes", "actions")
# The generated images carry marks of their own (`nodes/packed_image.py`).
_IMAGE_KEYS = tuple(m.VERSION_KEY for m in (bump_image, caustics_image, foam_image, rough_fresnel_image))


class RemoveWaterError(WaterError, ValueError):
    """A water that cannot be removed (one line, says why)."""


def _let_floaters_go(water):
    """Removes the floating constraints of the objects floating on `water` (None: on no object any
    more, their water deleted)."""
    floaters = [
        obj
        for obj in bpy.data.objects
        if obj.constraints  # first: it costs nothing, and few objects have any
        and obj != water
        and is_local(obj)
        and float_constraints(obj)
        and floating_on(obj) == water
    ]
    changes = []
    for obj in floaters:  # releasing removes their rigs' objects: not while going through them
        changes += floating.release(obj)
    return changes


def _remove_lost_caches():
    """Removes the caches whose water was deleted, then the water's mesh they kept alive and its
    water materials when nothing else uses them (Blender would still save a material that an
    unsaved mesh counts as a user)."""
    meshes = [cache.data for cache in surroundings.lost_caches() if cache.data is not None]
    changes = surroundings.remove_lost_caches()
    for mesh in [m for m in meshes if m.users == 0]:
        materials = [m for m in mesh.materials if kind.shading_of(m) is not None]
        bpy.data.meshes.remove(mesh)
        for material in [m for m in unused(materials) if is_local(m)]:
            changes.append(f"removed material '{material.name}' (its water was deleted)")
            bpy.data.materials.remove(material)
    return changes


def _delete_probe(probe, why=""):
    """Removes a mirror probe object, and its data when nothing else uses it."""
    data = probe.data
    change = f"removed planar probe '{probe.name}'{why}"
    bpy.data.objects.remove(probe)
    if data is not None and data.users == 0:
        bpy.data.lightprobes.remove(data)
    return change


def _remove_probe(water):
    changes = []
    probe = mirror.find_probe(water)
    while probe is not None:
        changes.append(_delete_probe(probe))
        probe = mirror.find_probe(water)
    return changes


def _is_own(block):
    """Whether `block` is one the add-on made itself (by its mark), local."""
    if role_of(block) is not None:
        return is_original(block)
    keys = _IMAGE_KEYS if block.id_type == "IMAGE" else ()
    return any(role_of(block, key) is not None and is_original(block, key) for key in keys)


def _remove_unused_own_data():
    """Removes the add-on's own groups, images, worlds and probe data nothing uses any more,
    repeatedly (a group's removal frees the nested groups and images it used)."""
    removed = []
    while True:
        own = [(data_kind, b) for data_kind in _OWN_KINDS for b in getattr(bpy.data, data_kind) if _is_own(b)]
        free = set(unused([block for _data_kind, block in own]))
        found = [(data_kind, block) for data_kind, block in own if block in free]
        if not found:
            return removed
        for data_kind, block in found:
            removed.append(block.name)
            getattr(bpy.data, data_kind).remove(block)


def _take_apart(water, scenes):
    """Everything but the object and its data: what the add-on added around `water`."""
    changes = []
    for scene in scenes:
        if physical_caustics.is_on(water):
            changes += physical_caustics.disable(water, scene)
    changes += _let_floaters_go(water)
    changes += surroundings.remove_surroundings(water)
    changes += _remove_probe(water)
    changes += underwater.remove(water)
    material = water_material(water)
    for scene in scenes:
        changes += mirror.release_mirror(scene, water)
    sun_link.release_everywhere(water)
    return changes, material


def _remove_object(water, material):
    changes = []
    mesh = water.data
    name = water.name
    bpy.data.objects.remove(water)
    changes.append(f"removed '{name}'")
    if mesh is not None and mesh.users == 0:
        bpy.data.meshes.remove(mesh)
    if material is not None and unused([material]) and material.library is None:
        bpy.data.materials.remove(material)
    removed = _remove_unused_own_data()
    if removed:
        changes.append(f"removed the add-on's unused {', '.join(removed)}")
    return changes


def remove_water(water, scene=None):
    """Removes `water` and everything the add-on made for it that nothing else uses; returns the
    changes in words. RemoveWaterError for an object that is not water; NotEditableError for
    linked or overridden water."""
    if water is None or water_material(water) is None:
        raise RemoveWaterError(f"'{getattr(water, 'name', water)}' is not a water object")
    check_editable(water)
    scenes = list(water.users_scene) or ([scene] if scene is not None else [])
    changes, material = _take_apart(water, scenes)
    return changes + _remove_object(water, material)


def _deleted(obj):
    """Whether `obj` is a water the user deleted: in no scene, kept alive only by the add-on's
    light linking (its collections, or a user's receiver collection it linked the water into) or
    the constraints of what floated on it (no fake user, no other collection of the user's)."""
    if not is_local(obj) or obj.use_fake_user or obj.users_scene or water_material(obj) is None:
        return False
    linked = sun_link.linked_by_add_on(obj)
    return all(sun_link.is_own_receivers(c) or c.name in linked for c in obj.users_collection)


def remove_leftovers():
    """Removes what the add-on made for waters the user deleted the ordinary way: the water kept
    alive by light linking, its cache, probe and surroundings collection, and the caches and
    probes whose water is gone; the scene settings set up for them go back as with Remove Water.
    Returns the changes in words."""
    changes = []
    in_scenes = {o for scene in bpy.data.scenes for o in scene.objects}  # once: `users_scene` walks them all
    for water in [o for o in bpy.data.objects if o not in in_scenes and _deleted(o)]:
        scenes = [scene for scene in bpy.data.scenes if _held_by(scene, water)]
        parts, material = _take_apart(water, scenes)
        changes += parts + _remove_object(water, material)
    changes += _remove_lost_caches()
    changes += _let_floaters_go(None)  # those whose water is gone altogether
    changes += keep_out.remove_lost_hulls()  # before the rigs: a water kept out of a hull holds it
    changes += wake.remove_lost_sources()  # so does a wake (its Source socket)
    changes += float_rig.remove_lost_rigs()  # those whose floating object is gone
    changes += underwater.remove_lost()
    for probe in [o for o in bpy.data.objects if mirror.is_lost_probe(o)]:
        changes.append(_delete_probe(probe, " (its water was deleted)"))
    removed = _remove_unused_own_data() if changes else []  # only what those leftovers kept alive
    if removed:
        changes.append(f"removed the add-on's unused {', '.join(removed)}")
    for data_kind in ("scenes", "objects", "lights", "materials"):
        for block in getattr(bpy.data, data_kind):
            if is_local(block) and ledger.LEDGER_KEY in block:
                ledger.prune(block, _holder_alive)
    return changes


def _held_by(scene, water):
    """Whether `scene` has settings the add-on changed for `water` (its mirror set-up or caustics)."""
    return any(
        ledger.held_paths(scene, ledger.holder(kind, water, stamp=False)) for kind in ("mirror", "caustics")
    )


def _holder_alive(holder):
    """Whether the water a ledger holder ("mirror:Water", "caustics:Water") names is still water."""
    water = ledger.holder_object(holder)
    return water is not None and water_material(water) is not None and not _deleted(water)
