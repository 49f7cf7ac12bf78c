"""`Water Caustic Sheet` (Geometry Nodes, on a hidden child of the water): a copy of the water's
surface just under it, whose material is `Water Caustic Light` (`caustic_light.py`), made only
while the camera is under the water."""

from ..spec import GroupSpec, Node, Socket
from .camera_gate import DEPTH, GATE_LINKS, GATE_NODES, placement_inputs

NAME = "Water Caustic Sheet"
SHEET_DROP = 0.01  # metres (the water's units): the sheet under the surface, which it never shadows

SPEC = GroupSpec(
    name=NAME,
    version=3,  # 2: Every Placement (a sheet for collection instances' placements); 3: no rays from high up
    description="A copy of a water's surface just under it, for the caustic light (`Water Caustic "
    "Light`); made only while the camera is under the water",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("Geometry", "NodeSocketGeometry"),
        Socket("Water", "NodeSocketObject", tooltip="The water whose surface the sheet copies"),
        Socket("Material", "NodeSocketMaterial", tooltip="The water's caustic light"),
        Socket(
            "Depth",
            "NodeSocketFloat",
            DEPTH,
            min=0.01,
            tooltip="How far under the surface the camera may be and still have the sheet made",
        ),
        Socket(
            "Margin",
            "NodeSocketFloat",
            0.0,
            min=0.0,
            tooltip="The sheet is made while the camera is no higher than this over the surface; "
            "above it the water shader draws the caustics on what it shows below",
        ),
        *placement_inputs("caustic light"),
    ),
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes={
        "water": Node("GeometryNodeObjectInfo", 1, {"transform_space": "ORIGINAL"}, label="the water"),
        "lower": Node(
            "GeometryNodeSetPosition",
            2,
            values={"Offset": (0.0, 0.0, -SHEET_DROP)},
            label=f"{SHEET_DROP * 100:g} cm under",
        ),
        "light": Node("GeometryNodeSetMaterial", 3),
        **GATE_NODES,
        # Software EEVEE draws the sheet's shader into the sun's shadow maps even where every
        # placement shuts it (3 times the render, bench/placed_body_cost.py): for every placement
        # only while the camera is also no higher than the water's own level (+ Margin), so a
        # camera on a shore over it pays nothing.
        "here_xyz": Node("ShaderNodeSeparateXYZ", 4, label="the camera's height here"),
        "low": Node("FunctionNodeCompare", 5, {"data_type": "FLOAT", "operation": "LESS_EQUAL"}, label="low"),
        "every": Node("FunctionNodeBooleanMath", 8, {"operation": "AND"}, label="Every Placement, low"),
        "made": Node("GeometryNodeSwitch", 8, {"input_type": "GEOMETRY"}, label="none while above"),
    },
    links=(
        ("input:Water", "water:Object"),
        ("water:Geometry", "lower:Geometry"),
        ("lower:Geometry", "light:Geometry"),
        ("which:Output", "light:Material"),
        ("here:Vector", "here_xyz:Vector"),
        ("here_xyz:Z", "low:A"),
        ("input:Margin", "low:B"),
        ("input:Every Placement", "every:#0"),
        ("low:Result", "every:#1"),
        *GATE_LINKS,
        ("hidden:Boolean", "made:Switch"),
        ("light:Geometry", "made:False"),
        ("made:Output", "output:Geometry"),
    ),
)
