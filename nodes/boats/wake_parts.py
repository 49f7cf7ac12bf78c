"""Small node makers and names the wake's groups share (`wake.py` and its nested groups)."""

from ..spec import Node

FOAM_ATTRIBUTE = "water_wake_foam"  # the wakes' foam on the water's points, 0..1
DEPTH_DEFAULT = 10.0  # m: the Depth sockets' default


def named(name, data_type, column, label=""):
    """A Named Attribute node reading `name`."""
    return Node(
        "GeometryNodeInputNamedAttribute", column, {"data_type": data_type}, {"Name": name}, label or name
    )


def store(name, data_type, column):
    """A Store Named Attribute node writing `name` on the points."""
    return Node(
        "GeometryNodeStoreNamedAttribute",
        column,
        {"data_type": data_type, "domain": "POINT"},
        {"Name": name},
        f"store {name}",
    )


def box_test(keys, column, box):
    """Three nodes (keys: above, below, both): a point above a box's low corner and below its
    high corner, each axis at once (A: the point, B: the corner; "both:Boolean" the answer)."""
    above, below, both = keys
    return {
        above: Node(
            "FunctionNodeCompare",
            column,
            {"data_type": "VECTOR", "mode": "ELEMENT", "operation": "GREATER_THAN"},
            label=f"above {box}'s low corner",
        ),
        below: Node(
            "FunctionNodeCompare",
            column,
            {"data_type": "VECTOR", "mode": "ELEMENT", "operation": "LESS_THAN"},
            label=f"below {box}'s high corner",
        ),
        both: Node("FunctionNodeBooleanMath", column + 1, {"operation": "AND"}, label=f"inside {box}"),
    }


def sample(data_type, column, label):
    """A Sample Index node on the points."""
    return Node("GeometryNodeSampleIndex", column, {"data_type": data_type, "domain": "POINT"}, label=label)


def clamped_sample(data_type, column, label):
    """A Sample Index that reads the first or last point past either end (a track's ends)."""
    return Node(
        "GeometryNodeSampleIndex",
        column,
        {"data_type": data_type, "domain": "POINT", "clamp": True},
        label=label,
    )


def merge(*parts):
    """One description of parts, each (nodes, links): their nodes in order (one key, one node) and
    their links one after the other."""
    nodes, links = {}, []
    for more_nodes, more_links in parts:
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes |= more_nodes
        links += more_links
    return nodes, tuple(links)
