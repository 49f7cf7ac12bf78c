"""Names and small node makers both surroundings groups share: the attributes `Water Surroundings`
stores on the cache and `Water Surroundings Sample` reads from it onto the water."""

from ..spec import Node

FLOOR_ATTRIBUTE = ".water_floor"  # z of what is below (object units), on the cache's geometry only
DEPTH_ATTRIBUTE = "water_depth"
SHORE_ATTRIBUTE = "water_shore_distance"
FLAG_ATTRIBUTE = "water_surroundings"
CACHE_UV_SIZE_ATTRIBUTE = ".water_uv_size"  # object-space metres per UV unit, measured once on the cache
FAR = 1000.0  # metres: "nothing there"


def compare(operation, column, label, b=0.0):
    """A float Compare node against the constant `b` (input 1 is the float B)."""
    return Node("FunctionNodeCompare", column, {"data_type": "FLOAT", "operation": operation}, {1: b}, label)


def switch(column, label, false=None, true=None):
    """A float Switch; `false`/`true` are constants for the unlinked side."""
    values = {k: v for k, v in (("False", false), ("True", true)) if v is not None}
    return Node("GeometryNodeSwitch", column, {"input_type": "FLOAT"}, values, label)


def store(name, column, label):
    props = {"data_type": "FLOAT", "domain": "POINT"}
    return Node("GeometryNodeStoreNamedAttribute", column, props, {"Name": name}, label)
