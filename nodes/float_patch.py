"""`Water Float Patch`: the piece of a water's evaluated surface round one floating object.

A floating object's probes (`water/boats/float_rig.py`) drop onto its patch instead of the whole water:
a Shrinkwrap constraint makes a ray-cast tree of its target's mesh every frame, 150,000 points on
the open sea (about 90 ms, BENCHMARKS), a few hundred here. The patch object has the water's
transform (Copy Transforms), so it works in the water's own space: the water's mesh as its
modifiers leave it (Object Info, Original: no copy), less the points farther across than
`Radius` metres from the anchor (which moves as the object does before it floats, so no cycle).
Points, not faces: a face's centre and area would cost a pass over the faces (docs/BENCHMARKS.md,
Floating cost). On an even grid (the lake's and the
seeds' ocean's) even the pass over the points is saved: the patch is a grid of its own whose
points read the water's by index.
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
    # On an even grid (the lake's, the seeds' ocean's: `Grid Side` > 0) no pass over the water
    # at all: a grid `Patch Side` points a side whose points take the water's own, by index
    # (row x side + column), from the water's row and column under the anchor.
    "g_patch": Node("GeometryNodeMeshGrid", 2, label="the patch's grid"),
    "g_index": Node("GeometryNodeInputIndex", 2, label="its point"),
    "g_p_f": math("DIVIDE", 3, "its column"),
    "g_p": math("FLOOR", 4, "(whole)"),
    "g_q": math("FLOORED_MODULO", 3, "its row"),
    "g_rel": vmath("SUBTRACT", 3, "the anchor from the first point"),
    "g_rel_split": Node("ShaderNodeSeparateXYZ", 4, label="across"),
    "g_col_f": math("DIVIDE", 5, "in cells: column"),
    "g_row_f": math("DIVIDE", 5, "in cells: row"),
    "g_half": math("MULTIPLY", 4, "half the patch", b=0.5),
    "g_half_f": math("FLOOR", 5, "(whole)"),
    "g_c": math("SUBTRACT", 6, "the patch's first column"),
    "g_r": math("SUBTRACT", 6, "the patch's first row"),
    "g_room": math("SUBTRACT", 5, "the last first column or row"),
    "g_c_lo": math("MAXIMUM", 7, "on the water", b=0.0),
    "g_r_lo": math("MAXIMUM", 7, "on the water", b=0.0),
    "g_c0": math("MINIMUM", 8, ""),
    "g_r0": math("MINIMUM", 8, ""),
    "g_c0_r": math("ROUND", 9, "(whole)"),
    "g_r0_r": math("ROUND", 9, "(whole)"),
    "g_col": math("ADD", 10, "the water's column"),
    "g_row": math("ADD", 10, "the water's row"),
    "g_i": math("MULTIPLY_ADD", 11, "the water's point: row x side + column"),
    "g_position": Node("GeometryNodeInputPosition", 11),
    "g_at": Node(
        "GeometryNodeSampleIndex", 12, {"data_type": "FLOAT_VECTOR", "domain": "POINT"}, label="where it is"
    ),
    "g_set": Node("GeometryNodeSetPosition", 13, label="the patch, on the grid"),
    "g_even": Node(
        "FunctionNodeCompare", 12, {"data_type": "INT", "operation": "GREATER_THAN"}, label="an even grid"
    ),
    "which": Node("GeometryNodeSwitch", 14, {"input_type": "GEOMETRY"}, label="grid or cut"),
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
    ("input:Patch Side", "g_patch:Vertices X"),
    ("input:Patch Side", "g_patch:Vertices Y"),
    ("g_index:Index", "g_p_f:#0"),
    ("input:Patch Side", "g_p_f:#1"),
    ("g_p_f:Value", "g_p:#0"),
    ("g_index:Index", "g_q:#0"),
    ("input:Patch Side", "g_q:#1"),
    ("anchor:Location", "g_rel:#0"),
    ("input:Grid Corner", "g_rel:#1"),
    ("g_rel:Vector", "g_rel_split:Vector"),
    ("g_rel_split:X", "g_col_f:#0"),
    ("input:Grid Cell", "g_col_f:#1"),
    ("g_rel_split:Y", "g_row_f:#0"),
    ("input:Grid Cell", "g_row_f:#1"),
    ("input:Patch Side", "g_half:#0"),
    ("g_half:Value", "g_half_f:#0"),
    ("g_col_f:Value", "g_c:#0"),
    ("g_half_f:Value", "g_c:#1"),
    ("g_row_f:Value", "g_r:#0"),
    ("g_half_f:Value", "g_r:#1"),
    ("input:Grid Side", "g_room:#0"),
    ("input:Patch Side", "g_room:#1"),
    ("g_c:Value", "g_c_lo:#0"),
    ("g_r:Value", "g_r_lo:#0"),
    ("g_c_lo:Value", "g_c0:#0"),
    ("g_room:Value", "g_c0:#1"),
    ("g_r_lo:Value", "g_r0:#0"),
    ("g_room:Value", "g_r0:#1"),
    ("g_c0:Value", "g_c0_r:#0"),
    ("g_r0:Value", "g_r0_r:#0"),
    ("g_c0_r:Value", "g_col:#0"),
    ("g_p:Value", "g_col:#1"),
    ("g_r0_r:Value", "g_row:#0"),
    ("g_q:Value", "g_row:#1"),
    ("g_row:Value", "g_i:#0"),
    ("input:Grid Side", "g_i:#1"),
    ("g_col:Value", "g_i:#2"),
    ("water:Geometry", "g_at:Geometry"),
    ("g_position:Position", "g_at:Value"),
    ("g_i:Value", "g_at:Index"),
    ("g_patch:Mesh", "g_set:Geometry"),
    ("g_at:Value", "g_set:Position"),
    ("input:Grid Side", "g_even:A"),
    ("g_even:Result", "which:Switch"),
    ("cut:Geometry", "which:False"),
    ("g_set:Geometry", "which:True"),
    ("which:Output", "output:Geometry"),
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
        Socket(
            "Grid Side",
            "NodeSocketInt",
            0,
            0,
            100000,
            tooltip="The water's points a side, if an even grid (else 0)",
        ),
        Socket(
            "Grid Corner", "NodeSocketVector", (0.0, 0.0, 0.0), tooltip="Its first point, in its own space"
        ),
        Socket(
            "Grid Cell", "NodeSocketFloat", 1.0, 1e-6, 1e6, tooltip="Its points' spacing, in its own space"
        ),
        Socket(
            "Patch Side", "NodeSocketInt", 2, 2, 100000, tooltip="The patch's points a side, on an even grid"
        ),
    ),
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes=_NODES,
    links=_LINKS,
)
