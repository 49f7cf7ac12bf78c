"""Keeps the followed sun's own highlight off the water, so its only highlight is the seeds' glint.

A sun lamp puts its own mirror highlight (hundreds of times the glint) into the
water's sharp glossy closure. Blender's light linking excludes the water from
the sun's receivers: the sun still lights and shadows everything else, and its
light on other objects is still mirrored in the water. Cycles honours light
linking on every supported Blender; EEVEE from 4.3 on. EEVEE in 4.2 ignores
it, so there the lamp's highlight stays (see the README for the figure).
"""

import bpy

from ..nodes.ownership import is_local, is_original, mark

OWNER_KEY = "water_surface_light_linking"  # marks a receiver collection the add-on made
# On a water: the names of the user's receiver collections the add-on linked it into (so a water
# the user deletes is known to be held only by the add-on's doing there).
LINKED_KEY = "water_surface_linked_into"


def linked_by_add_on(water):
    """Names of the user's receiver collections the add-on linked `water` into."""
    names = water.get(LINKED_KEY)
    return [str(name) for name in names] if names is not None else []


def _note_linked(water, collection, linked):
    names = [name for name in linked_by_add_on(water) if name != collection.name]
    water[LINKED_KEY] = names + [collection.name] if linked else names


def eevee_honours_light_linking():
    """Whether this Blender's EEVEE applies light linking (4.3 and later)."""
    return bpy.app.version >= (4, 3, 0)


def _entry(collection, obj):
    """The collection's light-linking entry for `obj`, or None.

    `collection_objects` runs parallel to `objects` (an entry names no object of its own).
    """
    for index, member in enumerate(collection.objects):
        if member == obj:
            return collection.collection_objects[index]
    return None


def exclude_water(water, sun):
    """Takes `water` out of the light `sun` gives; returns what changed, in words (empty if nothing).

    Uses the sun's receiver collection when it has one (the user's light linking
    stays as it was, with the water added as excluded), else a new one marked as the add-on's.
    """
    if sun is None or sun.type != "LIGHT":
        return []
    if sun.library is not None or sun.override_library is not None:
        return [f"'{sun.name}' is linked from a library: its own highlight stays on '{water.name}'"]
    linking = sun.light_linking
    collection = linking.receiver_collection
    changes = []
    if collection is None:
        collection = bpy.data.collections.new(f"Light Linking for {sun.name}")
        collection[OWNER_KEY] = True
        mark(collection, "Light Linking", 1)
        linking.receiver_collection = collection
        changes.append(f"'{sun.name}' given the receiver collection '{collection.name}'")
    elif collection.library is not None:
        return [f"the receivers of '{sun.name}' are linked: its own highlight stays on '{water.name}'"]
    entry = _entry(collection, water)
    if entry is None:
        collection.objects.link(water)
        entry = _entry(collection, water)
        if not is_own_receivers(collection):
            _note_linked(water, collection, True)
    if entry.light_linking.link_state == "EXCLUDE" and not changes:
        return []
    entry.light_linking.link_state = "EXCLUDE"
    changes.append(f"'{sun.name}' no longer lights '{water.name}' (light linking), so the glint shows")
    if not eevee_honours_light_linking():
        changes.append("EEVEE in Blender 4.2 ignores light linking: the lamp's highlight stays there")
    return changes


def release_water(water, sun):
    """Undoes `exclude_water`: the water leaves the sun's receivers (an emptied one of ours goes)."""
    if sun is None or sun.type != "LIGHT" or not is_local(sun):
        return
    collection = sun.light_linking.receiver_collection
    if collection is None or collection.library is not None or _entry(collection, water) is None:
        return
    collection.objects.unlink(water)
    if collection.name in linked_by_add_on(water):
        _note_linked(water, collection, False)
    if is_own_receivers(collection) and not collection.objects and not collection.children:
        sun.light_linking.receiver_collection = None
        if collection.users == 0:
            bpy.data.collections.remove(collection)


def is_own_receivers(collection):
    """Whether `collection` is a receiver collection the add-on made (not a user's copy of one)."""
    return bool(collection.get(OWNER_KEY)) and is_original(collection)


def release_everywhere(water):
    """Takes `water` out of every light's receivers (an emptied one of ours goes with it)."""
    for obj in [o for o in bpy.data.objects if o.type == "LIGHT"]:
        release_water(water, obj)
