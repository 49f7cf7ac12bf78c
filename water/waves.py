"""The `Water Waves` modifier on a water object: add it, find it, read and set its inputs."""

from ..nodes import SPECS, water_waves
from ..nodes.builder import ensure_group
from ..nodes.ownership import role_of
from .editable import check_editable

MODIFIER = "Water Waves"


def wave_modifier(obj):
    """The object's Geometry Nodes modifier running the add-on's `Water Waves` group, or None.

    Found by the group's mark: a user's group named "Water Waves..." is theirs.
    """
    if obj is None or obj.type != "MESH":
        return None
    for modifier in obj.modifiers:
        if modifier.type == "NODES" and modifier.node_group is not None:
            if role_of(modifier.node_group) == water_waves.NAME:
                return modifier
    return None


def add_waves(obj):
    """Adds (or reuses) the wave modifier on `obj`; returns it."""
    check_editable(obj)
    modifier = wave_modifier(obj)
    if modifier is None:
        modifier = obj.modifiers.new(MODIFIER, "NODES")
        # Before the surroundings, which measure the displaced surface.
        later = [i for i, m in enumerate(obj.modifiers) if _role(m) == SURROUNDINGS_ROLE]
        if later:
            obj.modifiers.move(len(obj.modifiers) - 1, later[0])
    modifier.node_group = ensure_group(SPECS[water_waves.NAME], SPECS)
    return modifier


SURROUNDINGS_ROLE = "Water Surroundings Sample"  # the water's modifier reading its surroundings


def _role(modifier):
    group = modifier.node_group if modifier.type == "NODES" else None
    return role_of(group) if group is not None else None


def input_ids(modifier):
    """Input name -> identifier of the modifier's group (the key of `modifier[...]`)."""
    return {
        item.name: item.identifier
        for item in modifier.node_group.interface.items_tree
        if item.item_type == "SOCKET" and item.in_out == "INPUT" and item.socket_type != "NodeSocketGeometry"
    }


def input_property(modifier, name):
    """(owner, property path) of one modifier input, for `layout.prop` and for reading and writing.

    Blender 5 keeps modifier inputs in `modifier.properties.inputs.<id>.value`;
    4.2-4.5 keep them as ID properties, `modifier["<id>"]`.
    """
    identifier = input_ids(modifier)[name]
    interface = getattr(modifier, "properties", None)
    if interface is not None and hasattr(interface, "inputs"):
        return getattr(interface.inputs, identifier), "value"
    return modifier, f'["{identifier}"]'


def input_path(modifier, name):
    """The path from the object to one modifier input's value, for a driver's variable."""
    owner, path = input_property(modifier, name)
    return owner.path_from_id(path) if path == "value" else modifier.path_from_id() + path


def set_wave_input(modifier, name, value):
    """Sets one modifier input by name (e.g. "Amplitude 2") and refreshes the object."""
    owner, path = input_property(modifier, name)
    if path == "value":
        owner.value = value
    else:
        owner[input_ids(modifier)[name]] = value
    modifier.id_data.update_tag()


def get_wave_input(modifier, name):
    """One modifier input's value by name; vectors as tuples."""
    owner, path = input_property(modifier, name)
    value = owner.path_resolve(path)
    return tuple(value) if hasattr(value, "__len__") else value


def amplitude_sum(modifier):
    """The largest height the waves can reach above the rest level."""
    return sum(abs(get_wave_input(modifier, f"Amplitude {i}")) for i in range(1, water_waves.WAVE_COUNT + 1))
