"""Whether the camera is under the water: the gates the underwater groups share.

Two rules. In Geometry Nodes (`GATE_NODES`, the body's and the caustic sheet's): the camera
against the surface right over or under it in the water's own space. In a shader
(`placement_gate`, the fog's and the caustic light's): the camera against the water's level in
each placement's space, for the body made for every placement of a collection instance.
"""

from ..spec import Node, Socket, math, vmath

DEPTH = 200.0  # metres of water under the surface the fog fills by default
MARGIN = 1.0  # metres over the surface under it within which the camera may see the water
DOWN_REACH = 100000.0  # metres under the camera the ray looking for water under it reaches


def placement_gate(column, margin):
    """Shader nodes giving `shut`: 1 where the group's `Each Placement` is on and the camera is
    more than `margin` over the water's level (z 0) in the space of the object being shaded, 0
    elsewhere. Per placement: a collection instance gives each of its placements its own object
    transform at render time (the camera's place, Vector Transform from Camera to Object space, is
    worked out in each), where Geometry Nodes sees only the original's (docs/MODEL.md section 16,
    "Placed by instances"). Needs an input `Each Placement`; links from `placement_links()`."""
    return {
        "cam_here": Node(
            "ShaderNodeVectorTransform",
            column,
            {"vector_type": "POINT", "convert_from": "CAMERA", "convert_to": "OBJECT"},
            {"Vector": (0.0, 0.0, 0.0)},
            "the camera, in this placement's space",
        ),
        "cam_here_xyz": Node("ShaderNodeSeparateXYZ", column + 1),
        "cam_over": math("GREATER_THAN", column + 2, f"over the level + {margin:g}", b=margin),
        "shut": math("MULTIPLY", column + 3, "shut: Each Placement, camera over"),
    }


def placement_links():
    return (
        ("cam_here:Vector", "cam_here_xyz:Vector"),
        ("cam_here_xyz:Z", "cam_over:#0"),
        ("cam_over:Value", "shut:#0"),
        ("input:Each Placement", "shut:#1"),
    )


EACH_PLACEMENT = Socket(
    "Each Placement",
    "NodeSocketFloat",
    0.0,
    min=0.0,
    max=1.0,
    subtype="FACTOR",
    tooltip="1 for the body made for every placement of the water (the camera beside the water as "
    "it stands in its own place: it may be under one placed by a collection instance): each "
    "placement shows it only while the camera is no higher than its level (+ Margin)",
)


# Whether the camera is well above the water: the rule both the body and the caustic sheet are
# made by (needs a "water" Object Info node, an "every" Boolean Math (Every Placement) and the
# inputs Depth, Margin, Material and Placed Material).
GATE_NODES = {
    # The camera, in the water's own space, against the surface right over it: a ray cast up
    # from Margin under the camera meets the surface only if the camera is under it, or
    # less than Margin over it (a wave's crest under a camera 3 m up in a gale is not).
    "camera": Node("GeometryNodeInputActiveCamera", 1),
    "cam": Node("GeometryNodeObjectInfo", 2, {"transform_space": "ORIGINAL"}, label="the camera"),
    "w_inv": Node("FunctionNodeInvertMatrix", 2, label="world to the water's space"),
    "here": Node("FunctionNodeTransformPoint", 3, label="the camera, in the water's space"),
    "margin": Node("ShaderNodeCombineXYZ", 3, label="Margin down"),
    "below": vmath("SUBTRACT", 4, "Margin under the camera"),
    "probe": Node("GeometryNodePoints", 5, values={"Count": 1}, label="one point there"),
    "reach_up": math("ADD", 4, "Depth + Margin"),
    "up": Node(
        "GeometryNodeRaycast", 5, values={"Ray Direction": (0.0, 0.0, 1.0)}, label="up to the surface"
    ),
    "under": Node(
        "GeometryNodeAttributeStatistic",
        6,
        {"data_type": "FLOAT", "domain": "POINT"},
        label="under the surface (1) or not (0)",
    ),
    "above": Node(
        "FunctionNodeCompare", 7, {"data_type": "FLOAT", "operation": "LESS_THAN"}, {1: 0.5}, "well above"
    ),
    # Geometry Nodes sees the water where it stands itself: a collection instance placing it
    # elsewhere shares this one evaluation (docs/MODEL.md section 16, "Placed by instances"). A
    # camera over no water and under none here may be under a placement: the body is made for
    # every placement, each of which shows it only while the camera is down at its level.
    "look_down": Node(
        "GeometryNodeRaycast",
        5,
        values={"Ray Direction": (0.0, 0.0, -1.0), "Ray Length": DOWN_REACH},
        label="down to the surface",
    ),
    "over": Node(
        "GeometryNodeAttributeStatistic",
        6,
        {"data_type": "FLOAT", "domain": "POINT"},
        label="over the surface (1) or not (0)",
    ),
    "beside": Node(
        "FunctionNodeCompare", 7, {"data_type": "FLOAT", "operation": "LESS_THAN"}, {1: 0.5}, "over none"
    ),
    # A camera over the water's box, Margin over its top, is under none of it and over it where
    # its box is (a water's mesh fills its box: a grid): the rays' answer without them. Their
    # targets are only read when a Switch takes that side (Geometry Nodes evaluates lazily), so a
    # camera well above the water pays for a box, not for the water's ray tree (79 ms a frame on
    # the open sea's 148,225 points).
    "box": Node("GeometryNodeBoundBox", 3, label="the water's box"),
    "box_min": Node("ShaderNodeSeparateXYZ", 4),
    "box_max": Node("ShaderNodeSeparateXYZ", 4),
    "here_xyz": Node("ShaderNodeSeparateXYZ", 4),
    "top": math("ADD", 5, "top + Margin"),
    "high": Node(
        "FunctionNodeCompare", 6, {"data_type": "FLOAT", "operation": "GREATER_THAN"}, label="over the box"
    ),
    "x_from": Node("FunctionNodeCompare", 5, {"data_type": "FLOAT", "operation": "GREATER_EQUAL"}),
    "x_to": Node("FunctionNodeCompare", 5, {"data_type": "FLOAT", "operation": "LESS_EQUAL"}),
    "y_from": Node("FunctionNodeCompare", 5, {"data_type": "FLOAT", "operation": "GREATER_EQUAL"}),
    "y_to": Node("FunctionNodeCompare", 5, {"data_type": "FLOAT", "operation": "LESS_EQUAL"}),
    "in_x": Node("FunctionNodeBooleanMath", 6, {"operation": "AND"}),
    "in_y": Node("FunctionNodeBooleanMath", 6, {"operation": "AND"}),
    "in_box": Node("FunctionNodeBooleanMath", 7, {"operation": "AND"}, label="over the box"),
    "under_any": Node(
        "GeometryNodeSwitch", 7, {"input_type": "FLOAT"}, {"True": 0.0}, "under (the ray) or none (high)"
    ),
    "over_any": Node("GeometryNodeSwitch", 7, {"input_type": "FLOAT"}, label="over (the ray, or the box)"),
    "off": Node("FunctionNodeBooleanMath", 8, {"operation": "AND"}, label="beside the water here"),
    "placed": Node("FunctionNodeBooleanMath", 9, {"operation": "AND"}, label="made for every placement"),
    "not_placed": Node("FunctionNodeBooleanMath", 10, {"operation": "NOT"}),
    "hidden": Node("FunctionNodeBooleanMath", 11, {"operation": "AND"}, label="well above, not placed"),
    "which": Node("GeometryNodeSwitch", 12, {"input_type": "MATERIAL"}, label="each placement's gate"),
}
GATE_LINKS = (
    ("camera:Active Camera", "cam:Object"),
    ("water:Transform", "w_inv:Matrix"),
    ("w_inv:Matrix", "here:Transform"),
    ("cam:Location", "here:Vector"),
    ("input:Margin", "margin:Z"),
    ("here:Vector", "below:#0"),
    ("margin:Vector", "below:#1"),
    ("below:Vector", "probe:Position"),
    ("water:Geometry", "up:Target Geometry"),
    ("input:Depth", "reach_up:#0"),
    ("input:Margin", "reach_up:#1"),
    ("reach_up:Value", "up:Ray Length"),
    ("probe:Points", "under:Geometry"),
    ("up:Is Hit", "under:Attribute"),
    ("water:Geometry", "box:Geometry"),
    ("box:Min", "box_min:Vector"),
    ("box:Max", "box_max:Vector"),
    ("here:Vector", "here_xyz:Vector"),
    ("box_max:Z", "top:#0"),
    ("input:Margin", "top:#1"),
    ("here_xyz:Z", "high:A"),
    ("top:Value", "high:B"),
    ("here_xyz:X", "x_from:A"),
    ("box_min:X", "x_from:B"),
    ("here_xyz:X", "x_to:A"),
    ("box_max:X", "x_to:B"),
    ("here_xyz:Y", "y_from:A"),
    ("box_min:Y", "y_from:B"),
    ("here_xyz:Y", "y_to:A"),
    ("box_max:Y", "y_to:B"),
    ("x_from:Result", "in_x:#0"),
    ("x_to:Result", "in_x:#1"),
    ("y_from:Result", "in_y:#0"),
    ("y_to:Result", "in_y:#1"),
    ("in_x:Boolean", "in_box:#0"),
    ("in_y:Boolean", "in_box:#1"),
    ("high:Result", "under_any:Switch"),
    ("under:Max", "under_any:False"),
    ("under_any:Output", "above:A"),
    ("water:Geometry", "look_down:Target Geometry"),
    ("here:Vector", "look_down:Source Position"),
    ("probe:Points", "over:Geometry"),
    ("look_down:Is Hit", "over:Attribute"),
    ("high:Result", "over_any:Switch"),
    ("over:Max", "over_any:False"),
    ("in_box:Boolean", "over_any:True"),
    ("over_any:Output", "beside:A"),
    ("above:Result", "off:#0"),
    ("beside:Result", "off:#1"),
    ("off:Boolean", "placed:#0"),
    ("every:Boolean", "placed:#1"),
    ("placed:Boolean", "not_placed:#0"),
    ("above:Result", "hidden:#0"),
    ("not_placed:Boolean", "hidden:#1"),
    ("placed:Boolean", "which:Switch"),
    ("input:Material", "which:False"),
    ("input:Placed Material", "which:True"),
)


def placement_inputs(what):
    """The inputs of the body made for every placement (`what`: the fog, the caustic light)."""
    return (
        Socket(
            "Every Placement",
            "NodeSocketBool",
            False,
            tooltip="While the camera is beside the water as it stands here (over none of it, under "
            f"none), make the {what} anyway, with Placed Material: a collection instance may place "
            "the water over the camera elsewhere, and each placement gates it by the camera there. "
            "Off: nothing is made then (as before this input)",
        ),
        Socket(
            "Placed Material",
            "NodeSocketMaterial",
            tooltip=f"The {what} with its Each Placement on: shown only by the placements the camera "
            "is down at",
        ),
    )
