"""`Water Underwater Shell` (Geometry Nodes, on a hidden child of the water): the closed body of
water `Water Underwater Fog` fills, and the waterline across the lens (docs/MODEL.md section 16).

The body is the water's evaluated surface (its waves, in its own space) lowered a millimetre, so
a ray meets the surface before the fog, and drawn down `Depth` metres (Extrude Mesh of all its
faces, flipped to face out); empty while the scene's camera is more than `Margin` above the
surface right over or under it (or beyond the water's edge, or deeper than `Depth`), so a camera
that never goes under pays for none of it (`camera_gate.py`). Against the surface where the
camera is, not its highest crest: a camera 3 m over a gale's sea, whose crests reach higher
elsewhere, is above the water. With it, the waterline across the lens: the ribbon of `Water
Meniscus` where the surface crosses the plane the camera's rays start on (`Near`, its Clip Start:
Cycles starts each ray there, EEVEE clips what is nearer, so the rays starting under the surface
see the water and those over it the air), `Meniscus` x `Near` thick, just beyond that plane, each
of its points moved in the plane up or down to the surface's height there.
"""

from ..spec import GroupSpec, Node, Socket, math, vmath
from .camera_gate import DEPTH, GATE_LINKS, GATE_NODES, MARGIN, placement_inputs

NAME = "Water Underwater Shell"
LOWER = 0.001  # metres (the water's units): the fog's top below the surface
REACH = 150.0  # metres along the water from the camera: c = 0.04 per metre keeps 0.25% over it
LINE_POINTS = 129  # along the waterline across the lens
LINE_SPAN = 3.0  # x Near either side of the view's centre: the width of a 6 mm lens' view
MENISCUS = 0.004  # x Near: the line's thickness, 5 pixels of a 1080-line frame through a 24 mm lens
DOWN_FROM = 500.0  # metres over a point the ray down to the surface starts (over any crest)


def _onto_surface(step, column):
    """Nodes moving each point of the waterline, in the plane of the lens, up or down to the
    surface under it: a ray down from over the point finds the surface's height h there; the
    point moves along the lens' upward direction v by (h - z) / v.z. Twice, as the move shifts
    the point across the water a little."""
    k = f"_{step}"
    return {
        "lift" + k: vmath("ADD", column, "over the point", b=(0.0, 0.0, DOWN_FROM)),
        "drop" + k: Node(
            "GeometryNodeRaycast",
            column + 1,
            values={"Ray Direction": (0.0, 0.0, -1.0), "Ray Length": 2.0 * DOWN_FROM},
            label="down to the surface",
        ),
        "hit_z" + k: Node("ShaderNodeSeparateXYZ", column + 2, label="the surface's height"),
        "gap" + k: math("SUBTRACT", column + 3, "h - z"),
        "along" + k: math("DIVIDE", column + 4, "/ v.z"),
        "move" + k: vmath("SCALE", column + 5, "along v"),
        "onto" + k: Node("GeometryNodeSetPosition", column + 6, label="onto the surface"),
    }


def _onto_links(step, before):
    k = f"_{step}"
    return (
        ("line_pos:Position", "lift" + k + ":#0"),
        ("water:Geometry", "drop" + k + ":Target Geometry"),
        ("lift" + k + ":Vector", "drop" + k + ":Source Position"),
        ("drop" + k + ":Hit Position", "hit_z" + k + ":Vector"),
        ("hit_z" + k + ":Z", "gap" + k + ":#0"),
        ("line_z:Z", "gap" + k + ":#1"),
        ("gap" + k + ":Value", "along" + k + ":#0"),
        ("v_z:Z", "along" + k + ":#1"),
        ("v:Vector", "move" + k + ":#0"),
        ("along" + k + ":Value", "move" + k + ":Scale"),
        (before, "onto" + k + ":Geometry"),
        ("move" + k + ":Vector", "onto" + k + ":Offset"),
    )


# The waterline across the lens: where the surface crosses the plane the camera's rays start on
# (its Clip Start; Cycles starts each ray there, and EEVEE clips what is nearer), a thin ribbon
# just beyond it along that line, seen by the camera alone. In the water's space: f the camera's
# forward direction, h = f x z (level, across the view), v = h x f (up the lens).
_MENISCUS_NODES = {
    "fwd_world": Node(
        "FunctionNodeTransformDirection", 3, values={"Direction": (0.0, 0.0, -1.0)}, label="where it looks"
    ),
    "fwd_local": Node("FunctionNodeTransformDirection", 4, label="in the water's space"),
    "f": vmath("NORMALIZE", 5, "f"),
    "across": vmath("CROSS_PRODUCT", 6, "f x z", b=(0.0, 0.0, 1.0)),
    "h": vmath("NORMALIZE", 7, "h: level, across the view"),
    "up_lens": vmath("CROSS_PRODUCT", 8, "h x f"),
    "v": vmath("NORMALIZE", 9, "v: up the lens"),
    "v_z": Node("ShaderNodeSeparateXYZ", 10, label="v.z"),
    "lens_at": math("MULTIPLY", 5, "just past Clip Start", b=1.01),
    "ahead": vmath("SCALE", 6, "to the lens"),
    "centre": vmath("ADD", 7, "the lens' centre"),
    "span": math("MULTIPLY", 5, "half its width", b=LINE_SPAN),
    "half": vmath("SCALE", 8, "half across"),
    "start": vmath("SUBTRACT", 9, "its left end"),
    "spacing": math("MULTIPLY", 6, "between points", b=2.0 * LINE_SPAN / (LINE_POINTS - 1)),
    "step": vmath("SCALE", 9, "one step across"),
    "line": Node("GeometryNodeMeshLine", 10, values={"Count": LINE_POINTS}, label="across the lens"),
    "line_pos": Node("GeometryNodeInputPosition", 10),
    "line_z": Node("ShaderNodeSeparateXYZ", 11, label="z"),
    **_onto_surface(1, 11),
    **_onto_surface(2, 18),
    "missed": Node("FunctionNodeBooleanMath", 25, {"operation": "NOT"}, label="no surface under it"),
    "steep": math("ABSOLUTE", 11, "|v.z|"),
    "level": Node(
        "FunctionNodeCompare",
        12,
        {"data_type": "FLOAT", "operation": "LESS_THAN"},
        {1: 0.05},
        "looking straight up or down",
    ),
    "drop_it": Node("FunctionNodeBooleanMath", 26, {"operation": "OR"}),
    "on_water": Node("GeometryNodeDeleteGeometry", 27, {"domain": "POINT"}, label="the line on the water"),
    "thick": math("MULTIPLY", 5, "thickness"),
    "half_thick": math("MULTIPLY", 6, "half up", b=0.5),
    "raise": vmath("SCALE", 10, "half up the lens"),
    "centred": Node("GeometryNodeSetPosition", 28, label="centred on the line"),
    "minus_thick": math("MULTIPLY", 6, "all the way down", b=-1.0),
    "band": vmath("SCALE", 10, "down the lens"),
    "ribbon": Node("GeometryNodeExtrudeMesh", 29, {"mode": "EDGES"}, label="a ribbon"),
    "meniscus": Node("GeometryNodeSetMaterial", 30, label="the meniscus"),
    "all": Node("GeometryNodeJoinGeometry", 31, label="body and meniscus"),
}

_MENISCUS_LINKS = (
    ("cam:Transform", "fwd_world:Transform"),
    ("fwd_world:Direction", "fwd_local:Direction"),
    ("w_inv:Matrix", "fwd_local:Transform"),
    ("fwd_local:Direction", "f:Vector"),
    ("f:Vector", "across:#0"),
    ("across:Vector", "h:Vector"),
    ("h:Vector", "up_lens:#0"),
    ("f:Vector", "up_lens:#1"),
    ("up_lens:Vector", "v:Vector"),
    ("v:Vector", "v_z:Vector"),
    ("input:Near", "lens_at:#0"),
    ("f:Vector", "ahead:#0"),
    ("lens_at:Value", "ahead:Scale"),
    ("here:Vector", "centre:#0"),
    ("ahead:Vector", "centre:#1"),
    ("input:Near", "span:#0"),
    ("h:Vector", "half:#0"),
    ("span:Value", "half:Scale"),
    ("centre:Vector", "start:#0"),
    ("half:Vector", "start:#1"),
    ("input:Near", "spacing:#0"),
    ("h:Vector", "step:#0"),
    ("spacing:Value", "step:Scale"),
    ("start:Vector", "line:Start Location"),
    ("step:Vector", "line:Offset"),
    ("line_pos:Position", "line_z:Vector"),
    *_onto_links(1, "line:Mesh"),
    *_onto_links(2, "onto_1:Geometry"),
    ("drop_2:Is Hit", "missed:#0"),
    ("v_z:Z", "steep:#0"),
    ("steep:Value", "level:A"),
    ("missed:Boolean", "drop_it:#0"),
    ("level:Result", "drop_it:#1"),
    ("onto_2:Geometry", "on_water:Geometry"),
    ("drop_it:Boolean", "on_water:Selection"),
    ("input:Near", "thick:#0"),
    ("input:Meniscus", "thick:#1"),
    ("thick:Value", "half_thick:#0"),
    ("v:Vector", "raise:#0"),
    ("half_thick:Value", "raise:Scale"),
    ("on_water:Geometry", "centred:Geometry"),
    ("raise:Vector", "centred:Offset"),
    ("thick:Value", "minus_thick:#0"),
    ("v:Vector", "band:#0"),
    ("minus_thick:Value", "band:Scale"),
    ("centred:Geometry", "ribbon:Mesh"),
    ("band:Vector", "ribbon:Offset"),
    ("ribbon:Mesh", "meniscus:Geometry"),
    ("input:Meniscus Material", "meniscus:Material"),
    ("placed:Boolean", "line_here:Switch"),
    ("meniscus:Geometry", "line_here:False"),
    ("fog:Geometry", "all:Geometry"),
    ("line_here:Output", "all:Geometry"),
)


SPEC = GroupSpec(
    name=NAME,
    version=5,  # 4: Every Placement (a body for collection instances' placements); 5: no rays from high up
    description="The body of water under a water's surface, for its underwater fog; empty while the "
    "camera is well above the water",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("Geometry", "NodeSocketGeometry"),
        Socket("Water", "NodeSocketObject", tooltip="The water whose surface the body hangs from"),
        Socket("Material", "NodeSocketMaterial", tooltip="The water's underwater fog"),
        Socket(
            "Depth",
            "NodeSocketFloat",
            DEPTH,
            min=0.01,
            tooltip="How far below the surface the water reaches (the water's units): beyond, no fog",
        ),
        Socket(
            "Reach",
            "NodeSocketFloat",
            REACH,
            min=1.0,
            tooltip="How far from the camera, along the water, the body reaches (the water's units): "
            "past it the fog has hidden everything long before",
        ),
        Socket(
            "Margin",
            "NodeSocketFloat",
            MARGIN,
            min=0.0,
            tooltip="The body is made while the camera is no higher than this over the surface "
            "where it is; higher, it is not made at all and costs nothing",
        ),
        Socket(
            "Near",
            "NodeSocketFloat",
            0.1,
            min=0.0,
            tooltip="The camera's Clip Start (driven from the scene's camera): where its rays start, "
            "so where the waterline crosses the lens",
        ),
        Socket(
            "Meniscus",
            "NodeSocketFloat",
            MENISCUS,
            min=0.0,
            tooltip="The waterline's thickness across the lens, times Near (0: no line)",
        ),
        Socket("Meniscus Material", "NodeSocketMaterial", tooltip="The waterline's shader"),
        *placement_inputs("body"),
    ),
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes={
        "water": Node("GeometryNodeObjectInfo", 1, {"transform_space": "ORIGINAL"}, label="the water"),
        "face": Node("GeometryNodeInputPosition", 2),
        "flat_cam": vmath("SUBTRACT", 4, "from the camera"),
        "flat": vmath("MULTIPLY", 5, "along the water", b=(1.0, 1.0, 0.0)),
        "far": vmath("LENGTH", 6, "how far"),
        "beyond": Node(
            "FunctionNodeCompare", 7, {"data_type": "FLOAT", "operation": "GREATER_THAN"}, label="past Reach"
        ),
        "reach_here": Node("FunctionNodeBooleanMath", 8, {"operation": "AND"}, label="past Reach, here"),
        "near": Node("GeometryNodeDeleteGeometry", 8, {"domain": "FACE"}, label="the water within Reach"),
        "lower": Node(
            "GeometryNodeSetPosition", 9, values={"Offset": (0.0, 0.0, -LOWER)}, label="a mm under"
        ),
        "down": Node("ShaderNodeCombineXYZ", 2, label="straight down"),
        "depth": math("MULTIPLY", 1, "-Depth", b=-1.0),
        "body": Node("GeometryNodeExtrudeMesh", 10, {"mode": "FACES"}, {"Individual": False}, "drawn down"),
        "out": Node("GeometryNodeFlipFaces", 11, label="facing out"),
        "closed": Node("GeometryNodeJoinGeometry", 12, label="top and body"),
        "fog": Node("GeometryNodeSetMaterial", 13),
        **GATE_NODES,
        **_MENISCUS_NODES,
        "every": Node("FunctionNodeBooleanMath", 8, {"operation": "AND"}, {1: True}, "Every Placement"),
        "line_here": Node("GeometryNodeSwitch", 31, {"input_type": "GEOMETRY"}, label="no line when placed"),
        "made": Node("GeometryNodeSwitch", 32, {"input_type": "GEOMETRY"}, label="none while well above"),
    },
    links=(
        ("input:Water", "water:Object"),
        ("water:Geometry", "near:Geometry"),
        ("here:Vector", "flat_cam:#1"),
        ("face:Position", "flat_cam:#0"),
        ("flat_cam:Vector", "flat:#0"),
        ("flat:Vector", "far:Vector"),
        ("far:Value", "beyond:A"),
        ("input:Reach", "beyond:B"),
        ("input:Every Placement", "every:#0"),
        ("beyond:Result", "reach_here:#0"),
        ("not_placed:Boolean", "reach_here:#1"),
        ("reach_here:Boolean", "near:Selection"),
        ("near:Geometry", "lower:Geometry"),
        ("input:Depth", "depth:#0"),
        ("depth:Value", "down:Z"),
        ("lower:Geometry", "body:Mesh"),
        ("down:Vector", "body:Offset"),
        ("body:Mesh", "out:Mesh"),
        ("lower:Geometry", "closed:Geometry"),
        ("out:Mesh", "closed:Geometry"),
        ("closed:Geometry", "fog:Geometry"),
        ("which:Output", "fog:Material"),
        *GATE_LINKS,
        ("hidden:Boolean", "made:Switch"),
        *_MENISCUS_LINKS,
        ("all:Geometry", "made:False"),
        ("made:Output", "output:Geometry"),
    ),
)
