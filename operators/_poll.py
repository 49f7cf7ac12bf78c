"""Shared `poll` checks: each says why an operator cannot run (`poll_message_set`), as
Node Wrangler's `nw_check` does, so a greyed-out button explains itself and
`bpy.ops` raises a RuntimeError that carries the message.

Linked, overridden or missing library data is refused: edits to it live only in
memory and vanish when the file is reloaded.
"""

from ..water import kind
from ..water.editable import why_not_editable
from ..water.repair import needs_repair
from ..water.values import water_material

NOT_WATER = "The active object is not water (no Water Surface material)"


def refuse(cls, message):
    """Sets the poll message of `cls`; returns False for `poll` to return."""
    cls.poll_message_set(message)
    return False


def _repair_first(problem):
    return f"{problem}: repair it first (Repair Water in the Water panel)"


def scene_editable(cls, context):
    """The scene and its active collection can take new objects."""
    scene = context.scene
    if scene is None:
        return refuse(cls, "There is no scene")
    collection = getattr(context, "collection", None)  # where the new object goes
    why = why_not_editable(scene, collection if collection is not scene.collection else None)
    if why is not None:
        return refuse(cls, why)
    return True


def water_allowing(cls, context, feature, editable=True):
    """The active object is water whose kind allows `feature` (`kind.FEATURES`), not needing
    repair, and (when `editable`) all local: the object, its mesh, the material and its groups.
    """
    obj = context.active_object
    why = kind.refusal(obj, feature)
    if why is not None:
        return refuse(cls, why)
    material = water_material(obj)
    if editable:
        groups = [n.node_tree for n in material.node_tree.nodes if n.type == "GROUP" and n.node_tree]
        why = why_not_editable(obj, obj.data, material, *groups)
        if why is not None:
            return refuse(cls, why)
    problem = needs_repair(material)
    if problem is not None:
        return refuse(cls, _repair_first(problem))
    return True


def any_water(cls, context, feature=None):
    """The active object is water (any kind, or, given `feature`, one whose kind allows it:
    `kind.FEATURES`) that may be edited; it may need repair."""
    obj = context.active_object
    why = kind.refusal(obj, feature) if feature is not None else None
    if water_material(obj) is None or why is not None:
        return refuse(cls, why or NOT_WATER)
    why = why_not_editable(obj, obj.data)
    if why is not None:
        return refuse(cls, why)
    return True


def selected_water_allowing(cls, context, feature, nothing):
    """What Float, Keep Water Out and Add Wake ask: objects that are not water are selected
    (`nothing` says what to select otherwise), whichever object is active, with at most one water
    selected or active (`selected_waters`), which they then act on and whose kind must allow
    `feature` (`kind.FEATURES`). A water picked by where an object is gets the same refusal when
    the operator runs (`floating.water_for`, then the water function)."""
    if all(water_material(obj) is not None for obj in context.selected_objects):
        return refuse(cls, nothing)
    chosen = selected_waters(context)
    if len(chosen) > 1:
        return refuse(cls, "Select one water at most: the other objects act on it")
    why = kind.refusal(chosen[0], feature, subject=f"'{chosen[0].name}'") if chosen else None
    return refuse(cls, why) if why is not None else True


def selected_waters(context):
    """The selected water objects, the active one included."""
    selected = list(context.selected_objects)
    if context.active_object is not None and context.active_object not in selected:
        selected.append(context.active_object)
    return [obj for obj in selected if water_material(obj) is not None]


def selected_water(cls, context):
    """At least one water is selected (or active), and every selected water and the scene may be edited."""
    waters = selected_waters(context)
    if not waters:
        return refuse(cls, "Select a water object (one with a Water Surface material) first")
    why = why_not_editable(context.scene)
    if why is not None:
        return refuse(cls, why)
    for obj in waters:
        material = water_material(obj)
        why = why_not_editable(obj, material)
        if why is not None:
            return refuse(cls, why)
        problem = needs_repair(material)
        if problem is not None:
            return refuse(cls, _repair_first(problem))
    return True


def broken_water(cls, context):
    """The active object is water needing repair (its kind allows it), with a local material."""
    why = kind.refusal(context.active_object, "repair")
    if why is not None:
        return refuse(cls, why)
    material = water_material(context.active_object)
    why = why_not_editable(material)
    if why is not None:
        return refuse(cls, why)
    if needs_repair(material) is None:
        return refuse(cls, f"'{material.name}' needs no repair")
    return True
