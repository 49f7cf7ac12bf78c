"""What a water sees around it: a collection of objects, measured on a hidden cache object.

The measuring (`Water Surroundings`, `nodes/surroundings/surroundings.py`) is costly, so it runs
on a cache object per water, "<water> Surroundings", and not on the water, whose
modifier stack is evaluated again on every frame once it has waves. The cache:

* shares the water's mesh (the same points in the same order), is parented to the
  water with an identity parent inverse and transform (the same object space),
  and carries only `Water Surroundings`, seeing the collection: the depsgraph
  evaluates it again only when a surroundings object or the water moves;
* is hidden (`hide_viewport`, `hide_render`, `hide_select`): never drawn or
  rendered, still evaluated, in the viewport and in renders, as a dependency of
  the water, whose `Water Surroundings Sample` (after its waves) reads it through
  its `Cache` input;
* is linked into the water's collections, marked as the add-on's
  ("Surroundings Cache") and names its water (`WATER_KEY`); it is found through
  the water's sample modifier, else as a marked object parented to the water.
  It shares the water's mesh, and so its material; its material slots are linked
  to the object, empty, so `is_water` is False for it (the add-on's operators,
  panel and API never take it for a water). A slot the water gains later reads
  the mesh's material again until `ensure_surroundings` runs: `default_surroundings`
  leaves caches out by their mark in any case.

It is all data in the .blend: no Python at render time, the add-on need not be
enabled. Deleting the water leaves its cache unparented: the next
`ensure_surroundings` (any water) removes caches that lost their water;
`remove_surroundings` removes a water's cache and sample modifier.

By default the collection is the add-on's own "Surroundings of <water>",
filled with the mesh objects that reach below the water, and linked nowhere in
the scene: the cache's modifier input keeps it alive in the file, as light
linking's collections are kept, and the outliner stays the user's.

A collection that holds the water itself or its cache (directly, in a child
collection or through a collection instance), or another water that sees this
one, would make a dependency cycle: the add-on's own collection never takes
such objects (they are taken out again, with a note), and a user's collection
holding them is refused with `SurroundingsError`, never edited.
"""

import math

import bpy
from mathutils import Matrix, Vector

from ..nodes import SPECS
from ..nodes.builder import ensure_group
from ..nodes.ownership import is_local, is_original, mark, role_of
from ..nodes.surroundings import surroundings as spec
from ..nodes.surroundings import surroundings_sample as sample_spec
from ..presets import schema
from . import kind
from .editable import check_editable
from .errors import WaterError
from .float_constraints import RIG_KEY, floating_on
from .grid import max_resolution
from .mirror import rest_bounds
from .sea import open_sea
from .underwater import KEY as UNDERWATER_KEY
from .values import is_water
from .waves import amplitude_sum, input_ids, input_property, set_wave_input, wave_modifier

MODIFIER = spec.NAME  # on the cache
SAMPLE_MODIFIER = sample_spec.NAME  # on the water
INPUT = "Surroundings"
CACHE_INPUT = sample_spec.CACHE_INPUT
COLLECTION_ROLE = "Surroundings"
COLLECTION_VERSION = 1
CACHE_ROLE = "Surroundings Cache"
CACHE_VERSION = 1
WATER_KEY = "water_surface_surroundings"  # ID property of our collection and cache: the water's name
GRID_SPACING = 0.25  # metres: the grid finds a waterline within this


class SurroundingsError(WaterError, ValueError):
    """The surroundings cannot be set as asked (one line, says why)."""


def _nodes_modifier(obj, role):
    """`obj`'s Geometry Nodes modifier running the add-on's group `role`, or None (found by the
    group's mark, so a user's group with that name is theirs)."""
    if obj is None or obj.type != "MESH":
        return None
    for modifier in obj.modifiers:
        if modifier.type == "NODES" and modifier.node_group is not None:
            if role_of(modifier.node_group) == role:
                return modifier
    return None


def _input(modifier, name):
    """A modifier input's value, None when the modifier or the input is missing."""
    if modifier is None or name not in input_ids(modifier):
        return None
    owner, path = input_property(modifier, name)
    return owner.path_resolve(path)


def is_cache(obj):
    """Whether `obj` is a surroundings cache the add-on made (its mark)."""
    return obj is not None and role_of(obj) == CACHE_ROLE


def surroundings_modifier(water):
    """The water's `Water Surroundings Sample` modifier (reading its cache), or None."""
    return _nodes_modifier(water, sample_spec.NAME)


def surroundings_cache(water):
    """The water's hidden cache object: the one its sample modifier reads, else a local marked
    cache parented to it; None when there is none. A cache parented to another object (the
    modifier copied onto a duplicate of the water) is not this water's."""
    if water is None or water.type != "MESH":
        return None
    cache = _input(surroundings_modifier(water), CACHE_INPUT)
    if is_cache(cache) and cache.parent == water:
        return cache
    return next((o for o in bpy.data.objects if is_cache(o) and is_original(o) and o.parent == water), None)


def surroundings_collection(water):
    """The collection the water's cache sees (`water` may be the cache itself), or None (no
    cache, none set, or deleted)."""
    cache = water if is_cache(water) else surroundings_cache(water)
    return _input(_nodes_modifier(cache, spec.NAME), INPUT)


def needed_resolution(size):
    """Vertices per side for a grid of edge `size` whose spacing is at most GRID_SPACING, so the
    grid finds a waterline within that (513 at the default 128 m); capped by the memory."""
    wanted = math.ceil(size / GRID_SPACING - 1e-9) + 1
    return max(schema.RESOLUTION.min, min(wanted, schema.RESOLUTION.max, max_resolution()))


def coarse_grid_note(water):
    """A sentence when `water`'s grid is too coarse to find a waterline within GRID_SPACING, else None.

    Points are added when water is added, never to an existing mesh, which may be the user's.
    The open sea's grid is graded out to the horizon, its middle spaced by the waves' cell: no note.
    """
    if kind.kind_of(water) == kind.OPEN_SEA:
        return None
    low, high = rest_bounds(water)
    size = float(max(high[0] - low[0], high[1] - low[1]))
    side = math.isqrt(len(water.data.vertices))
    needed = needed_resolution(size)
    if side >= needed:
        return None
    return (
        f"'{water.name}' has about {side} vertices a side; its waterline is found within "
        f"{GRID_SPACING:g} m with {needed}: add the water again with Resolution {needed}"
    )


def _objects_seen(collection, seen=None):
    """Every object `collection` makes Collection Info see: its own, its children's and those of
    the collections its objects instance."""
    seen = set() if seen is None else seen
    if collection is None or collection.as_pointer() in seen:
        return []
    seen.add(collection.as_pointer())
    found = []
    for obj in collection.all_objects:
        found.append(obj)
        if obj.instance_type == "COLLECTION" and obj.instance_collection is not None:
            found += _objects_seen(obj.instance_collection, seen)
    return found


def _sees(obj, water):
    """Whether `obj` itself is a water (or a water's cache) whose surroundings hold `water` or its
    cache (a cycle if `water` saw it)."""
    mine = {water, surroundings_cache(water)} - {None}
    if obj in mine:
        return False
    return any(o in mine for o in _objects_seen(surroundings_collection(obj)))


def _makes_cycle(obj, water, cache):
    """Whether `water` seeing `obj` would make a dependency cycle: `obj` is the water, its cache, a
    water seeing them, or an object floating on the water (its constraints read the water)."""
    return obj == water or obj == cache or _sees(obj, water) or floating_on(obj) == water


def _cycle_makers(water, collection):
    """The objects of `collection` that would make a dependency cycle for `water`."""
    cache = surroundings_cache(water)
    return [o for o in _objects_seen(collection) if _makes_cycle(o, water, cache)]


def _update_matrices(scene):
    """Brings world matrices up to date: a script may have moved objects just before."""
    context = bpy.context
    layer = context.view_layer if context.scene == scene else next(iter(scene.view_layers), None)
    if layer is not None:
        layer.update()


def default_surroundings(water, scene):
    """The mesh objects of `scene` a water meets: their bounding box reaches below its surface
    (below the wave troughs' top, when it has waves) and overlaps its extent in its plane.

    Worked out in the water's object space, so a tilted or scaled water gets the same answer.
    Other waters are left out (two waters seeing each other would be a cycle), and so are the
    objects floating on this water (they read its surface: a cycle too), the floating rigs'
    poses and patches (they read a water's surface) and the
    surroundings caches: a cache shares its water's mesh, so it may read as a water (`is_water`)
    when its material slots are not its own; it is left out by its mark in any case.
    """
    _update_matrices(scene)
    to_water = water.matrix_world.inverted_safe()
    low, high = rest_bounds(water)
    waves = wave_modifier(water)
    top = high[2] + (amplitude_sum(waves) if waves is not None else open_sea.crest_height(water))
    found = []
    for obj in scene.objects:
        if obj == water or obj.type != "MESH" or is_cache(obj) or floating_on(obj) == water:
            continue
        if obj.get(RIG_KEY):  # a floating rig's pose (or older patch): it reads the water (a cycle)
            continue
        if obj.get(UNDERWATER_KEY):  # a water's underwater body: it reads the water (a cycle)
            continue
        if is_water(obj) or surroundings_modifier(obj) is not None:
            continue
        corners = [to_water @ (obj.matrix_world @ Vector(corner)) for corner in obj.bound_box]
        below = min(c.z for c in corners) < top
        overlaps = all(
            min(c[axis] for c in corners) <= high[axis] and max(c[axis] for c in corners) >= low[axis]
            for axis in (0, 1)
        )
        if below and overlaps:
            found.append(obj)
    return sorted(found, key=lambda o: o.name)


def _own_collection(water):
    """The add-on's collection made for `water`: the one its modifier sees, else one marked with
    its name; None when there is none."""
    current = surroundings_collection(water)
    if current is not None and role_of(current) == COLLECTION_ROLE and is_original(current):
        return current
    return next(
        (
            c
            for c in bpy.data.collections
            if role_of(c) == COLLECTION_ROLE and is_original(c) and c.get(WATER_KEY) == water.name
        ),
        None,
    )


def _names(objects):
    return ", ".join(f"'{o.name}'" for o in objects)


def _fill(collection, water, scene):
    """Makes our collection hold exactly the default surroundings; returns the changes in words."""
    changes = []
    wanted = default_surroundings(water, scene) if scene is not None else []
    cache = surroundings_cache(water)
    floaters = [o for o in collection.objects if floating_on(o) == water]
    cycles = [
        o
        for o in collection.objects
        if o not in wanted and o not in floaters and _makes_cycle(o, water, cache)
    ]
    stale = [o for o in collection.objects if o not in wanted and o not in cycles + floaters]
    for obj in floaters + cycles + stale:
        collection.objects.unlink(obj)
    if floaters:
        changes.append(f"left {_names(floaters)} out of '{collection.name}' (floating on the water: a cycle)")
    if cycles:
        changes.append(f"took {_names(cycles)} out of '{collection.name}' (it would see itself: a cycle)")
    if stale:
        changes.append(f"took {_names(stale)} out of '{collection.name}' (no longer below the water)")
    held = {o.as_pointer() for o in collection.objects}
    added = [o for o in wanted if o.as_pointer() not in held]
    for obj in added:
        collection.objects.link(obj)
    if added:
        changes.append(f"'{collection.name}' holds {_names(added)}")
    return changes


def leave_out(water, obj):
    """Takes `obj`, which is to float on `water`, out of the water's surroundings; returns the
    changes. The add-on's own collection lets it go (with a note); a user's collection holding it
    is never edited: SurroundingsError says to take it out first."""
    collection = surroundings_collection(water)
    if collection is None or obj not in _objects_seen(collection):
        return []
    if collection == _own_collection(water) and obj.name in collection.objects:
        collection.objects.unlink(obj)
        cache = surroundings_cache(water)
        if cache is not None:
            _refresh(water, cache)
        return [
            f"left '{obj.name}' out of '{collection.name}' (what floats on a water is not its surroundings)"
        ]
    raise SurroundingsError(
        f"'{obj.name}' is in '{collection.name}', which '{water.name}' sees as its surroundings: "
        "take it out of that collection first (floating on the water it shapes would be a dependency cycle)"
    )


def _place(water, modifier):
    """Moves the modifier after `Water Waves` (or the open sea's fade), so it measures the
    displaced surface."""
    sea = open_sea.sea_modifiers(water)
    waves = sea[1] if sea is not None else wave_modifier(water)
    if waves is None:
        return []
    index = list(water.modifiers).index
    if index(modifier) > index(waves):
        return []
    water.modifiers.move(index(modifier), len(water.modifiers) - 1)
    return [f"modifier '{modifier.name}' moved after '{waves.name}'"]


def _ensure_cache(water):
    """The water's cache (made, or reused and put back in shape) with its `Water Surroundings`
    modifier; returns (cache, modifier, changes)."""
    changes = []
    cache = surroundings_cache(water)
    if cache is None:
        cache = bpy.data.objects.new(f"{water.name} Surroundings", water.data)
        mark(cache, CACHE_ROLE, CACHE_VERSION)
        changes.append(f"made hidden object '{cache.name}'")
    if cache.data != water.data:
        cache.data = water.data
    cache[WATER_KEY] = water.name
    if cache.parent != water:
        cache.parent = water
    identity = Matrix.Identity(4)
    if cache.matrix_parent_inverse != identity:
        cache.matrix_parent_inverse = identity
    if cache.matrix_basis != identity:
        cache.matrix_basis = identity
    for flag in ("hide_viewport", "hide_render", "hide_select"):
        if not getattr(cache, flag):
            setattr(cache, flag, True)
    for slot in cache.material_slots:  # no material of its own: not taken for a water (`is_water`)
        if slot.link != "OBJECT" or slot.material is not None:
            slot.link = "OBJECT"
            slot.material = None
    for collection in water.users_collection:
        if cache.name not in collection.objects and is_local(collection):
            collection.objects.link(cache)
    modifier = _nodes_modifier(cache, spec.NAME)
    if modifier is None:
        modifier = cache.modifiers.new(MODIFIER, "NODES")
    modifier.node_group = ensure_group(SPECS[spec.NAME], SPECS)
    return cache, modifier, changes


def _ensure_modifier(water, cache):
    """The water's sample modifier (added or reused, after the waves) reading `cache`. A
    `Water Surroundings` modifier on the water itself (the group measuring on every frame) is
    removed: the cache measures now."""
    changes = []
    for old in [m for m in water.modifiers if m.type == "NODES" and m.node_group is not None]:
        if role_of(old.node_group) == spec.NAME:
            changes.append(f"removed modifier '{old.name}' (the cache measures now)")
            water.modifiers.remove(old)
    modifier = surroundings_modifier(water)
    if modifier is None:
        modifier = water.modifiers.new(SAMPLE_MODIFIER, "NODES")
        changes.append(f"added modifier '{modifier.name}'")
    modifier.node_group = ensure_group(SPECS[sample_spec.NAME], SPECS)
    if _input(modifier, CACHE_INPUT) != cache:
        set_wave_input(modifier, CACHE_INPUT, cache)
    return modifier, changes + _place(water, modifier)


def _set_input(water, modifier, collection):
    """Makes the cache's `modifier` see `collection`."""
    if _input(modifier, INPUT) == collection:
        return []
    set_wave_input(modifier, INPUT, collection)
    return [f"sees '{collection.name}'" if collection is not None else "sees nothing"]


def lost_caches():
    """The add-on's caches whose water was deleted (no parent, read by no modifier)."""
    read = {
        _input(m, CACHE_INPUT)
        for o in bpy.data.objects
        if o.type == "MESH"
        for m in o.modifiers
        if m.type == "NODES" and m.node_group is not None and role_of(m.node_group) == sample_spec.NAME
    }
    return [
        o for o in bpy.data.objects if is_cache(o) and is_original(o) and o.parent is None and o not in read
    ]


def remove_lost_caches():
    """Removes the add-on's caches whose water was deleted; returns the changes."""
    lost = lost_caches()
    changes = [f"removed '{o.name}' (its water was deleted)" for o in lost]
    for obj in lost:
        bpy.data.objects.remove(obj)
    return changes


def _refresh(water, cache):
    water.update_tag()
    cache.update_tag()


def ensure_surroundings(water, scene, collection=None):
    """Gives `water` its surroundings: its cache (made or reused) seeing `collection`, or, when
    None, the add-on's own collection gathered again from `scene`, and the sample modifier
    (added or reused, after the waves) reading the cache.

    Returns what changed, in words. Raises SurroundingsError (or NotEditableError for linked
    water) with the reason; a user's collection is never edited.
    """
    if water is None or water.type != "MESH":
        raise SurroundingsError("surroundings need a mesh water object")
    if is_cache(water):
        raise SurroundingsError(f"'{water.name}' is a water's surroundings cache, not a water")
    why = kind.refusal(water, "surroundings", subject=f"'{water.name}'")
    if why is not None:
        raise SurroundingsError(why)
    check_editable(water)
    changes = []
    if collection is not None:
        cycles = _cycle_makers(water, collection)
        if cycles:
            raise SurroundingsError(
                f"collection '{collection.name}' holds {_names(cycles)}, which would make the water "
                "see itself (a dependency cycle): pick a collection without it"
            )
    else:
        collection = _own_collection(water)
        if collection is None:
            collection = bpy.data.collections.new(f"Surroundings of {water.name}")
            mark(collection, COLLECTION_ROLE, COLLECTION_VERSION)
            changes.append(f"made collection '{collection.name}'")
        collection[WATER_KEY] = water.name
        changes += _fill(collection, water, scene)
    changes += remove_lost_caches()
    cache, cache_modifier, cache_changes = _ensure_cache(water)
    modifier, modifier_changes = _ensure_modifier(water, cache)
    changes += cache_changes + modifier_changes + _set_input(water, cache_modifier, collection)
    _refresh(water, cache)
    return changes


def set_surroundings(water, collection):
    """Makes `water` see `collection` instead (None: nothing, all attributes 1000).

    Linked collections are fine, they are only read; linked water is refused. Returns the changes.
    """
    if collection is None:
        if water is None or water.type != "MESH":
            raise SurroundingsError("surroundings need a mesh water object")
        check_editable(water)
        cache, cache_modifier, changes = _ensure_cache(water)
        _modifier, modifier_changes = _ensure_modifier(water, cache)
        changes += modifier_changes + _set_input(water, cache_modifier, None)
        _refresh(water, cache)
        return changes
    return ensure_surroundings(water, None, collection)


def remove_surroundings(water):
    """Takes the surroundings off `water`: its sample modifier, its cache and the add-on's own
    collection made for it (a user's collection is left alone). Returns the changes."""
    if water is None or water.type != "MESH":
        return []
    check_editable(water)
    changes = []
    own = _own_collection(water)
    modifier = surroundings_modifier(water)
    if modifier is not None:
        changes.append(f"removed modifier '{modifier.name}'")
        water.modifiers.remove(modifier)
    cache = surroundings_cache(water)
    while cache is not None:
        changes.append(f"removed '{cache.name}'")
        bpy.data.objects.remove(cache)
        cache = surroundings_cache(water)
    if own is not None:
        changes.append(f"removed collection '{own.name}'")
        bpy.data.collections.remove(own)
    water.update_tag()
    return changes
