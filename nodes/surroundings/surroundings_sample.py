"""`Water Surroundings Sample` (on the water, after `Water Waves` or the open sea's fade): what
lies around and under the water, read point by point from its cache, where `Water Surroundings`
(`surroundings.py`) measured it (SPEC 1). Per point i:

* From the `Cache` object (Object Info, ORIGINAL: its own space, the water's),
  Sample Index at i of the floor (`.water_floor`) and `water_shore_distance`
  (Named Attribute fields evaluated on the cache).
* `water_depth` = clamp((z now - floor) |scale.z|, 0, FAR): the rest depth plus the
  lift, exact for `Water Waves`, which only move points along the water's Z (the open
  sea's chop also moves them sideways: the floor is the one under the rest place); FAR
  where nothing is below. The shore distance as sampled, the flag 1, and
  `water_uv_size`, the cache's `.water_uv_size` at point 0.
* When the cache is missing, unmeasured (its `water_surroundings` at point 0 is not 1),
  has another point count, or is not where the water is (a duplicated water still
  pointing at the original's cache), the water reads "nothing there": FAR, FAR and
  a flag of 0. These checks are single values, so they cost nothing per point.
"""

from ..spec import GroupSpec, Node, Socket, math, vmath
from . import surroundings
from .surroundings_parts import (
    CACHE_UV_SIZE_ATTRIBUTE,
    DEPTH_ATTRIBUTE,
    FAR,
    FLAG_ATTRIBUTE,
    FLOOR_ATTRIBUTE,
    SHORE_ATTRIBUTE,
    compare,
    store,
    switch,
)

NAME = "Water Surroundings Sample"
VERSION = 3  # 2: stores UV_SIZE_ATTRIBUTE for the caustics' parallax; 3: per UV unit
CACHE_INPUT = "Cache"
UV_SIZE_ATTRIBUTE = "water_uv_size"  # object-space metres per UV unit (the lake's rest width)


def _sample(data_type, column, label):
    return Node("GeometryNodeSampleIndex", column, {"data_type": data_type, "domain": "POINT"}, label=label)


def _read(name, column, label):
    return Node("GeometryNodeInputNamedAttribute", column, {"data_type": "FLOAT"}, {"Name": name}, label)


def _sample_input_nodes():
    """What the sample group reads: the cache (transform, attributes), the water's transform, both counts."""
    nodes = {
        "cache": Node(
            "GeometryNodeObjectInfo", 1, {"transform_space": "ORIGINAL"}, label="cache (water space)"
        ),
        "index": Node("GeometryNodeInputIndex", 1, label="i"),
        "position": Node("GeometryNodeInputPosition", 1, label="p now"),
        "self": Node("GeometryNodeSelfObject", 1, label="the water"),
        "self_info": Node(
            "GeometryNodeObjectInfo", 2, {"transform_space": "ORIGINAL"}, label="water transform"
        ),
        "now_xyz": Node("ShaderNodeSeparateXYZ", 2, label="p now"),
        "floor_read": _read(FLOOR_ATTRIBUTE, 2, "floor z"),
        "shore_read": _read(SHORE_ATTRIBUTE, 2, SHORE_ATTRIBUTE),
        "flag_read": _read(FLAG_ATTRIBUTE, 2, FLAG_ATTRIBUTE),
        "scale_abs": vmath("ABSOLUTE", 2, "|scale|"),
        "cache_count": Node(
            "GeometryNodeAttributeDomainSize", 2, {"component": "MESH"}, label="cache points"
        ),
        "water_count": Node(
            "GeometryNodeAttributeDomainSize", 2, {"component": "MESH"}, label="water points"
        ),
    }
    links = [
        ("input:Cache", "cache:Object"),
        ("self:Self Object", "self_info:Object"),
        ("position:Position", "now_xyz:Vector"),
        ("cache:Scale", "scale_abs:#0"),
        ("scale_abs:Vector", "scale_xyz:Vector"),
        ("cache:Geometry", "cache_count:Geometry"),
        ("input:Geometry", "water_count:Geometry"),
    ]
    return nodes, links


def _sample_valid_nodes():
    """The cache's floor and shore distance at each point, and whether the cache is valid for this water."""
    nodes = {
        "floor": _sample("FLOAT", 3, "floor z at i"),
        "shore": _sample("FLOAT", 3, "shore distance at i"),
        "flag": _sample("FLOAT", 3, "flag at point 0: one value"),
        "scale_xyz": Node("ShaderNodeSeparateXYZ", 3, label="|scale|"),
        "same_count": Node(
            "FunctionNodeCompare", 3, {"data_type": "INT", "operation": "EQUAL"}, label="same points"
        ),
        "moved_location": vmath("DISTANCE", 3, "cache vs water location"),
        "moved_rotation": vmath("DISTANCE", 3, "cache vs water rotation"),
        "moved_scale": vmath("DISTANCE", 3, "cache vs water scale"),
        "moved_1": math("ADD", 4, "moved"),
        "moved": math("ADD", 5, "moved"),
        "in_place": compare("LESS_THAN", 6, "cache where the water is", b=1.0e-3),
        "has_flag": compare("GREATER_THAN", 4, "cache measured", b=0.5),
        "valid_1": Node("FunctionNodeBooleanMath", 5, {"operation": "AND"}, label="valid"),
        "valid": Node("FunctionNodeBooleanMath", 7, {"operation": "AND"}, label="valid"),
    }
    links = [
        ("cache_count:Point Count", "same_count:#0"),
        ("water_count:Point Count", "same_count:#1"),
        ("cache:Location", "moved_location:#0"),
        ("self_info:Location", "moved_location:#1"),
        ("cache:Rotation", "moved_rotation:#0"),
        ("self_info:Rotation", "moved_rotation:#1"),
        ("cache:Scale", "moved_scale:#0"),
        ("self_info:Scale", "moved_scale:#1"),
        ("moved_location:Value", "moved_1:#0"),
        ("moved_rotation:Value", "moved_1:#1"),
        ("moved_1:Value", "moved:#0"),
        ("moved_scale:Value", "moved:#1"),
        ("moved:Value", "in_place:#0"),
        # Index left at 0: a single value, so the checks and switches cost nothing per point.
        ("cache:Geometry", "flag:Geometry"),
        ("flag_read:Attribute", "flag:Value"),
        ("flag:Value", "has_flag:#0"),
        ("has_flag:Result", "valid_1:#0"),
        ("same_count:Result", "valid_1:#1"),
        ("valid_1:Boolean", "valid:#0"),
        ("in_place:Result", "valid:#1"),
    ]
    for key, field in (("floor", "floor_read:Attribute"), ("shore", "shore_read:Attribute")):
        links += [
            ("cache:Geometry", f"{key}:Geometry"),
            (field, f"{key}:Value"),
            ("index:Index", f"{key}:Index"),
        ]
    return nodes, links


def _sample_store_nodes():
    """The depth from the floor to where the waves lift the point, FAR without a valid cache; stored."""
    nodes = {
        "above_floor": math("SUBTRACT", 4, "z now - floor z"),
        "depth_m": math("MULTIPLY", 5, "in metres"),
        "wet": math("MAXIMUM", 6, "at least 0", b=0.0),
        "capped": math("MINIMUM", 7, f"at most {FAR:g}", b=FAR),
        "depth_valid": switch(9, f"depth, {FAR:g} without a cache", false=FAR),
        "shore_valid": switch(9, f"shore distance, {FAR:g} without a cache", false=FAR),
        "flag_valid": switch(9, "flag: 1, 0 without a cache", false=0.0, true=1.0),
        "store_depth": store(DEPTH_ATTRIBUTE, 10, f"store '{DEPTH_ATTRIBUTE}'"),
        "store_shore": store(SHORE_ATTRIBUTE, 11, f"store '{SHORE_ATTRIBUTE}'"),
        "store_flag": store(FLAG_ATTRIBUTE, 12, f"store '{FLAG_ATTRIBUTE}'"),
        # Metres per UV unit, so the shader turns metres into UV: measured by the cache (the
        # two groups are built together), one value, read at point 0.
        "uv_size_read": _read(CACHE_UV_SIZE_ATTRIBUTE, 2, "metres per UV unit (cache)"),
        "uv_size": _sample("FLOAT", 3, "at point 0: one value"),
        "store_uv_size": store(UV_SIZE_ATTRIBUTE, 13, f"store '{UV_SIZE_ATTRIBUTE}'"),
    }
    links = [
        ("now_xyz:Z", "above_floor:#0"),
        ("floor:Value", "above_floor:#1"),
        ("above_floor:Value", "depth_m:#0"),
        ("scale_xyz:Z", "depth_m:#1"),
        ("depth_m:Value", "wet:#0"),
        ("wet:Value", "capped:#0"),
        ("valid:Boolean", "depth_valid:Switch"),
        ("capped:Value", "depth_valid:True"),
        ("valid:Boolean", "shore_valid:Switch"),
        ("shore:Value", "shore_valid:True"),
        ("valid:Boolean", "flag_valid:Switch"),
        ("input:Geometry", "store_depth:Geometry"),
        ("depth_valid:Output", "store_depth:Value"),
        ("store_depth:Geometry", "store_shore:Geometry"),
        ("shore_valid:Output", "store_shore:Value"),
        ("store_shore:Geometry", "store_flag:Geometry"),
        ("flag_valid:Output", "store_flag:Value"),
        ("cache:Geometry", "uv_size:Geometry"),
        ("uv_size_read:Attribute", "uv_size:Value"),
        ("store_flag:Geometry", "store_uv_size:Geometry"),
        ("uv_size:Value", "store_uv_size:Value"),
        ("store_uv_size:Geometry", "output:Geometry"),
    ]
    return nodes, links


def _build():
    """`Water Surroundings Sample`'s nodes and links: the cache read point by point, if valid."""
    nodes, links = {}, []
    for more_nodes, more_links in (_sample_input_nodes(), _sample_valid_nodes(), _sample_store_nodes()):
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes, links = nodes | more_nodes, links + list(more_links)
    return nodes, tuple(links)


_NODES, _LINKS = _build()

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description=(
        f"Reads '{DEPTH_ATTRIBUTE}', '{SHORE_ATTRIBUTE}' and '{FLAG_ATTRIBUTE}' from the water's "
        f"surroundings cache (its '{surroundings.NAME}' modifier), point by point, the depth following "
        f"the waves; stores '{UV_SIZE_ATTRIBUTE}', metres per UV unit"
    ),
    inputs=(
        Socket("Geometry", "NodeSocketGeometry"),
        Socket(
            CACHE_INPUT,
            "NodeSocketObject",
            tooltip="The water's hidden surroundings cache: its mesh, measured by its own modifier",
        ),
    ),
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes=_NODES,
    links=_LINKS,
    tree_type="GeometryNodeTree",
)
