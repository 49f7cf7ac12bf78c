"""`Water Float Patch`: the piece of a water's evaluated surface round one floating object.

A floating object's probes (`water/float_rig.py`) drop onto its patch instead of the whole water:
a Shrinkwrap constraint makes a ray-cast tree of its target's mesh every frame, 150,000 points on
the open sea (about 90 ms, BENCHMARKS), a few hundred here. The patch object has the water's
transform (Copy Transforms), so it works in the water's own space: the water's mesh as its
modifiers leave it (Object Info, Original: no copy), less the points farther across than
`Radius` metres from the anchor (which moves as the object does before it floats, so no cycle).
Points, not faces: a face's centre and area would cost a pass over the faces (1.27x the sea
alone for one hull, 3.5x for ten, against 1.04x and 1.27x).
"""

from .spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Float Patch"

_NODES = {
    "water": Node("GeometryNodeObjectInfo", 1, {"transform_space": "ORIGINAL"}, label="the water's surface"),
    "anchor": Node(
        "GeometryNodeObjectInfo", 1, {"transform_space": "RELATIVE"}, label="the anchor, in its space"
    ),
    "self": Node("GeometryNodeSelfObject", 0, label="the patch (the water's transform)"),
    "self_info": Node("GeometryNodeObjectInfo", 1, {"transform_space": "ORIGINAL"}, label="its scale"),
    "scale": Node("ShaderNodeSeparateXYZ", 2, label="scale"),
    "across": math("MAXIMUM", 3, "metres a unit across"),
    "across_e": math("MAXIMUM", 4, "(> 0)", b=1e-6),
    "radius": math("DIVIDE", 5, "Radius, in units"),
    "position": Node("GeometryNodeInputPosition", 2),
    "offset": vmath("SUBTRACT", 3, "p - the anchor"),
    "flat": vmath("MULTIPLY", 4, "across only", b=(1.0, 1.0, 0.0)),
    "size": vmath("ABSOLUTE", 5, "each way"),
    "inside": Node(
        "FunctionNodeCompare",
        6,
        {"data_type": "VECTOR", "mode": "ELEMENT", "operation": "LESS_THAN"},
        label="within Radius each way",
    ),
    "outside": Node("FunctionNodeBooleanMath", 7, {"operation": "NOT"}, label="outside"),
    "cut": Node("GeometryNodeDeleteGeometry", 8, {"domain": "POINT"}, label="the patch"),
}

_LINKS = (
    ("input:Water", "water:Object"),
    ("input:Anchor", "anchor:Object"),
    ("self:Self Object", "self_info:Object"),
    ("self_info:Scale", "scale:Vector"),
    ("scale:X", "across:#0"),
    ("scale:Y", "across:#1"),
    ("across:Value", "across_e:#0"),
    ("input:Radius", "radius:#0"),
    ("across_e:Value", "radius:#1"),
    ("position:Position", "offset:#0"),
    ("anchor:Location", "offset:#1"),
    ("offset:Vector", "flat:#0"),
    ("flat:Vector", "size:#0"),
    ("size:Vector", "inside:A"),
    ("radius:Value", "inside:B"),
    ("inside:Result", "outside:Boolean"),
    ("water:Geometry", "cut:Geometry"),
    ("outside:Boolean", "cut:Selection"),
    ("cut:Geometry", "output:Geometry"),
)

SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="The water's evaluated surface within Radius of a floating object's anchor",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("Geometry", "NodeSocketGeometry"),
        Socket("Water", "NodeSocketObject", tooltip="The water the object floats on"),
        Socket("Anchor", "NodeSocketObject", tooltip="The floating rig's anchor"),
        Socket(
            "Radius",
            "NodeSocketFloat",
            10.0,
            0.01,
            10000.0,
            "DISTANCE",
            "How far across from the anchor the surface is kept, each way (metres)",
        ),
    ),
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes=_NODES,
    links=_LINKS,
)
