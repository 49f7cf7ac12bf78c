"""Node groups written as data: sockets, nodes and links, with no bpy in sight.

A `GroupSpec` is the single source of truth for one node group; `builder.py`
turns any of them into a node tree. Keeping the description plain data lets
tests read it without Blender and keeps the builder generic.

Links name sockets as "node:Socket Name" or, where names repeat (a Math node's
two "Value" inputs), by position: "node:#1". The group's own input and output
nodes are "input" and "output".
"""

from dataclasses import dataclass, field, replace

# Stands for the image a group is built with (`ensure_group(..., image=...)`), in node props.
BUMP_IMAGE = "<bump image>"
# Stands for the add-on's foam tile (`ensure_group(..., foam=...)`, default: `foam_image.py`'s own).
FOAM_IMAGE = "<foam image>"
# Stands for the add-on's caustic tile (`caustics_image.py`'s own).
CAUSTICS_IMAGE = "<caustics image>"
# Stands for the add-on's rough Fresnel table (`rough_fresnel_image.py`'s own).
ROUGH_FRESNEL_IMAGE = "<rough fresnel image>"


@dataclass(frozen=True)
class Socket:
    """One interface socket of a group."""

    name: str
    kind: str  # NodeSocketFloat, NodeSocketInt, NodeSocketVector, NodeSocketColor, NodeSocketShader
    default: object = None
    min: float | None = None
    max: float | None = None
    subtype: str | None = None
    tooltip: str = ""
    hide_value: bool = False


@dataclass(frozen=True)
class Node:
    """One node: its type, the column it sits in, its properties and unlinked input values."""

    type: str
    column: int
    props: dict = field(default_factory=dict)
    values: dict = field(default_factory=dict)
    label: str = ""
    group: str | None = None  # for ShaderNodeGroup: the name of the nested group
    # Blender versions the node is built in: from `since` (inclusive) to `before` (exclusive).
    # Links to a node that is not built are not made either.
    since: tuple | None = None
    before: tuple | None = None
    part: str | None = None  # the optional `Part` it belongs to (None: every variant has it)
    # A zone's output node (Simulation Output): its state items, (socket type, name) in order.
    items: tuple = ()
    # A zone's input node (Simulation Input): the key of the output node it pairs with.
    pair: str | None = None


@dataclass(frozen=True)
class Part:
    """An optional part of a group (depth colour, foam, caustics): its nodes are built only into
    the variants that have it (`GroupSpec.variant`), so a part that is off costs nothing at render
    time. A shader input cannot switch code off: a part whose strength is 0 is still computed.
    """

    name: str  # what its nodes carry in `Node.part`, and the API's word for it
    label: str  # in a variant's name ("Water Surface + Caustics") and the panel
    switch: str  # the group input that turns it on: on while above 0 (any channel of a colour)
    on_value: object  # the switch's value when the panel turns the part on from 0
    # Without it, what its outputs stood for: {node key: {input: value}} on the nodes they fed ...
    off_values: dict = field(default_factory=dict)
    # ... and the links that take the place of its nodes (around a closure it adds).
    off_links: tuple = ()


@dataclass(frozen=True)
class GroupSpec:
    name: str
    version: int
    description: str
    inputs: tuple
    outputs: tuple
    nodes: dict
    links: tuple
    tree_type: str = "ShaderNodeTree"
    # Specs of nested groups this description carries itself (found before the shared `SPECS`).
    includes: tuple = ()
    parts: tuple = ()  # its optional `Part`s; `variant` builds the description with some of them

    def variant(self, on):
        """This description with only the parts named in `on` (the others' nodes and links gone,
        their off values and links in place), named after them: "Water Surface" with none,
        "Water Surface + Depth + Caustics" with two."""
        on = frozenset(on)
        unknown = on - {part.name for part in self.parts}
        if unknown:
            raise ValueError(f"'{self.name}' has no part {', '.join(sorted(unknown))}")
        off = [part for part in self.parts if part.name not in on]
        dropped = {part.name for part in off}
        nodes = {key: node for key, node in self.nodes.items() if node.part not in dropped}
        for part in off:
            for key, values in part.off_values.items():
                nodes[key] = replace(nodes[key], values={**nodes[key].values, **values})
        kept = {*nodes, "input", "output"}
        links = tuple(
            link for link in self.links if all(end.partition(":")[0] in kept for end in link)
        ) + tuple(link for part in off for link in part.off_links)
        name = self.name + "".join(f" + {part.label}" for part in self.parts if part.name in on)
        return replace(self, name=name, nodes=nodes, links=links)

    def part_nodes(self, name):
        """Keys of the nodes of the part `name`."""
        return [key for key, node in self.nodes.items() if node.part == name]

    def nested_groups(self):
        """Names of the groups this one uses, which must be built first."""
        return [node.group for node in self.nodes.values() if node.group]

    def slots(self, placeholder):
        """Keys of the nodes with `placeholder` (`BUMP_IMAGE`, `FOAM_IMAGE`, `CAUSTICS_IMAGE`, ...) among
        their properties."""
        return [key for key, node in self.nodes.items() if placeholder in node.props.values()]


def math(operation, column, label="", clamp=False, **values):
    """A scalar Math node; `values` map input positions ("a", "b", "c") to constants."""
    index = {"a": 0, "b": 1, "c": 2}
    props = {"operation": operation, "use_clamp": clamp}
    return Node("ShaderNodeMath", column, props, {index[k]: v for k, v in values.items()}, label)


def vmath(operation, column, label="", **values):
    """A Vector Math node; `values` map "a", "b", "c" or "scale" to constants."""
    index = {"a": 0, "b": 1, "c": 2, "scale": "Scale"}
    props = {"operation": operation}
    return Node("ShaderNodeVectorMath", column, props, {index[k]: v for k, v in values.items()}, label)


def attribute(name, column, label=""):
    """An Attribute node reading the geometry attribute `name` (0 where the mesh has none)."""
    return Node(
        "ShaderNodeAttribute",
        column,
        {"attribute_type": "GEOMETRY", "attribute_name": name},
        label=label or name,
    )


def group_node(name, column, label=""):
    """A node that uses another group described here."""
    return Node("ShaderNodeGroup", column, label=label or name, group=name)


def pass_inputs(node, names):
    """Links from the group's own inputs to the inputs of the same names on `node` (a nested group)."""
    return tuple((f"input:{name}", f"{node}:{name}") for name in names)
