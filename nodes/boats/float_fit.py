"""`Water Float Fit`: where a floating object sits, fitted by one Geometry Nodes modifier.

The modifier is on the rig's pose (`water/boats/float_rig.py`), a hidden mesh whose own points are
the footprint's probes (in the anchor's own space, each with its weights for the fitted plane's
height and slopes, `WEIGHTS`, from `footprint_math.plane_weights`) and one triangle, the vertex
group `POSE_GROUP`. Each frame it:

* keeps the piece of the water's evaluated surface round the probes (the water's mesh as its
  modifiers leave it, in its own space: Object Info, Original, no copy): on an even grid (the
  lake's, the seeds' ocean's: `Grid Side` > 0) a block of `BLOCK` x `BLOCK` of the water's points
  round each probe, its cell and one more each way, taken by index with no pass over the water
  (its waves move its points up and down only); else the water's points within `Radius` metres
  of the anchor each way (a ray-cast tree of the whole sea's mesh costs 90 ms; a grid patch over
  the whole footprint's reach, 5,000 points, 1.3 ms a hull: BENCHMARKS, Floating cost);
* drops each probe onto it straight down or up in world Z, the nearer hit (as a Shrinkwrap
  constraint projecting both ways does), the probe left where it is when neither hits;
* fits the plane: its height at the anchor (`Height` added: the keel's depth and the draft) and
  its slopes along the anchor's X and Y, the weighted sums of the probes' world heights;
* lays the triangle on that plane over the anchor, its points' mean at that height and its normal
  the pose's Z axis (the tilt X by atan(slope y) then Y by -atan(slope x), Euler XYZ), and the
  probes where they hit.

The floating object copies the group's mean height (Copy Location) and orientation (Copy
Rotation): Blender makes a vertex group's orientation Z = the mean normal, X = Z x the target
object's Y axis, so the pose object is turned half a turn about Z (its Y is the world's -Y, and
X comes out along the plane's X): in the pose's own space, world (x, y, z) is (-x, -y, z).
"""

from ..spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Float Fit"
WEIGHTS = "water_float_weights"  # on the pose's points: the probe's (height, slope x, slope y) weights
POSE_GROUP = "Water Float Pose"  # the pose's triangle: the vertex group the object's constraints read
RAY_LENGTH = 1.0e6  # the water's units: a Shrinkwrap's rays reach without limit
BLOCK = 4  # on an even grid, the water's points a side kept round each probe: its cell, one more each way
BLOCK_FIRST = "water_float_block"  # on the probes, inside the group: their block's first point


def _raycast(column, label):
    return Node("GeometryNodeRaycast", column, {"data_type": "FLOAT"}, {"Ray Length": RAY_LENGTH}, label)


def _switch(kind, column, label):
    return Node("GeometryNodeSwitch", column, {"input_type": kind}, label=label)


# The patch: the water's surface round the anchor, in the water's own space.
_PATCH_NODES = {
    "water": Node("GeometryNodeObjectInfo", 1, {"transform_space": "ORIGINAL"}, label="the water"),
    "anchor": Node("GeometryNodeObjectInfo", 1, {"transform_space": "ORIGINAL"}, label="the anchor"),
    "w_inv": Node("FunctionNodeInvertMatrix", 2, label="world to the water's space"),
    "a_here": Node("FunctionNodeTransformPoint", 3, label="the anchor, in the water's space"),
    "scale": Node("ShaderNodeSeparateXYZ", 2, label="the water's scale"),
    "across": math("MAXIMUM", 3, "metres a unit across"),
    "across_e": math("MAXIMUM", 4, "(> 0)", b=1e-6),
    "radius": math("DIVIDE", 5, "Radius, in units"),
    "position": Node("GeometryNodeInputPosition", 2),
    "offset": vmath("SUBTRACT", 4, "p - the anchor"),
    "flat": vmath("MULTIPLY", 5, "across only", b=(1.0, 1.0, 0.0)),
    "size": vmath("ABSOLUTE", 6, "each way"),
    "inside": Node(
        "FunctionNodeCompare",
        7,
        {"data_type": "VECTOR", "mode": "ELEMENT", "operation": "LESS_THAN"},
        label="within Radius each way",
    ),
    "outside": Node("FunctionNodeBooleanMath", 8, {"operation": "NOT"}, label="outside"),
    "cut": Node("GeometryNodeDeleteGeometry", 9, {"domain": "POINT"}, label="the patch"),
    # On an even grid: round each probe a block of `BLOCK` x `BLOCK` of the water's points, its
    # cell and one more each way, taken by index (row x side + column).
    "g_probe": math("LESS_THAN", 6, "a probe (not the triangle)", b=0.5),
    "g_rel": vmath("SUBTRACT", 6, "the probe from the first point"),
    "g_rel_split": Node("ShaderNodeSeparateXYZ", 7, label="across"),
    "g_col_f": math("DIVIDE", 8, "in cells: column"),
    "g_row_f": math("DIVIDE", 8, "in cells: row"),
    "g_col_w": math("FLOOR", 9, "its cell's"),
    "g_row_w": math("FLOOR", 9, "its cell's"),
    "g_room": math("SUBTRACT", 8, "the last first column or row", b=BLOCK),
    "g_c": math("SUBTRACT", 10, "the block's first column", b=1.0),
    "g_r": math("SUBTRACT", 10, "the block's first row", b=1.0),
    "g_c_lo": math("MAXIMUM", 11, "on the water", b=0.0),
    "g_r_lo": math("MAXIMUM", 11, "on the water", b=0.0),
    "g_c0": math("MINIMUM", 12, ""),
    "g_r0": math("MINIMUM", 12, ""),
    "g_first": math("MULTIPLY_ADD", 13, "the block's first point: row x side + column"),
    "g_store": Node(
        "GeometryNodeStoreNamedAttribute",
        14,
        {"data_type": "FLOAT", "domain": "POINT"},
        {"Name": BLOCK_FIRST},
        "each probe's block",
    ),
    "g_block": Node(
        "GeometryNodeMeshGrid", 14, values={"Vertices X": BLOCK, "Vertices Y": BLOCK}, label="a block"
    ),
    "g_blocks": Node("GeometryNodeInstanceOnPoints", 15, label="a block a probe"),
    "g_real": Node("GeometryNodeRealizeInstances", 16, label="(as one mesh)"),
    "g_index": Node("GeometryNodeInputIndex", 15, label="its point"),
    "g_local": math("FLOORED_MODULO", 16, "in its block", b=BLOCK * BLOCK),
    "g_col_b": math("DIVIDE", 17, "its column", b=BLOCK),
    "g_col": math("FLOOR", 18, "(whole)"),
    "g_row": math("FLOORED_MODULO", 17, "its row", b=BLOCK),
    "g_base": Node(
        "GeometryNodeInputNamedAttribute",
        16,
        {"data_type": "FLOAT"},
        {"Name": BLOCK_FIRST},
        "the block's first",
    ),
    "g_at_row": math("MULTIPLY_ADD", 18, "+ row x side"),
    "g_i": math("ADD", 19, "+ column: the water's point"),
    "g_position": Node("GeometryNodeInputPosition", 19),
    "g_at": Node(
        "GeometryNodeSampleIndex", 20, {"data_type": "FLOAT_VECTOR", "domain": "POINT"}, label="where it is"
    ),
    "g_set": Node("GeometryNodeSetPosition", 21, label="the blocks, on the water"),
    "g_even": Node(
        "FunctionNodeCompare", 20, {"data_type": "INT", "operation": "GREATER_THAN"}, label="an even grid"
    ),
    "which": _switch("GEOMETRY", 22, "blocks or cut"),
    "surface": _switch("GEOMETRY", 23, "the patch, or the whole water"),
}

_PATCH_LINKS = (
    ("input:Water", "water:Object"),
    ("input:Anchor", "anchor:Object"),
    ("water:Transform", "w_inv:Matrix"),
    ("anchor:Location", "a_here:Vector"),
    ("w_inv:Matrix", "a_here:Transform"),
    ("water:Scale", "scale:Vector"),
    ("scale:X", "across:#0"),
    ("scale:Y", "across:#1"),
    ("across:Value", "across_e:#0"),
    ("input:Radius", "radius:#0"),
    ("across_e:Value", "radius:#1"),
    ("position:Position", "offset:#0"),
    ("a_here:Vector", "offset:#1"),
    ("offset:Vector", "flat:#0"),
    ("flat:Vector", "size:#0"),
    ("size:Vector", "inside:A"),
    ("radius:Value", "inside:B"),
    ("inside:Result", "outside:Boolean"),
    ("water:Geometry", "cut:Geometry"),
    ("outside:Boolean", "cut:Selection"),
    ("group:Attribute", "g_probe:#0"),
    ("q:Vector", "g_rel:#0"),
    ("input:Grid Corner", "g_rel:#1"),
    ("g_rel:Vector", "g_rel_split:Vector"),
    ("g_rel_split:X", "g_col_f:#0"),
    ("input:Grid Cell", "g_col_f:#1"),
    ("g_rel_split:Y", "g_row_f:#0"),
    ("input:Grid Cell", "g_row_f:#1"),
    ("g_col_f:Value", "g_col_w:#0"),
    ("g_row_f:Value", "g_row_w:#0"),
    ("input:Grid Side", "g_room:#0"),
    ("g_col_w:Value", "g_c:#0"),
    ("g_row_w:Value", "g_r:#0"),
    ("g_c:Value", "g_c_lo:#0"),
    ("g_r:Value", "g_r_lo:#0"),
    ("g_c_lo:Value", "g_c0:#0"),
    ("g_room:Value", "g_c0:#1"),
    ("g_r_lo:Value", "g_r0:#0"),
    ("g_room:Value", "g_r0:#1"),
    ("g_r0:Value", "g_first:#0"),
    ("input:Grid Side", "g_first:#1"),
    ("g_c0:Value", "g_first:#2"),
    ("input:Geometry", "g_store:Geometry"),
    ("g_first:Value", "g_store:Value"),
    ("g_store:Geometry", "g_blocks:Points"),
    ("g_probe:Value", "g_blocks:Selection"),
    ("g_block:Mesh", "g_blocks:Instance"),
    ("g_blocks:Instances", "g_real:Geometry"),
    ("g_index:Index", "g_local:#0"),
    ("g_local:Value", "g_col_b:#0"),
    ("g_col_b:Value", "g_col:#0"),
    ("g_local:Value", "g_row:#0"),
    ("g_row:Value", "g_at_row:#0"),
    ("input:Grid Side", "g_at_row:#1"),
    ("g_base:Attribute", "g_at_row:#2"),
    ("g_at_row:Value", "g_i:#0"),
    ("g_col:Value", "g_i:#1"),
    ("water:Geometry", "g_at:Geometry"),
    ("g_position:Position", "g_at:Value"),
    ("g_i:Value", "g_at:Index"),
    ("g_real:Geometry", "g_set:Geometry"),
    ("g_at:Value", "g_set:Position"),
    ("input:Grid Side", "g_even:A"),
    ("g_even:Result", "which:Switch"),
    ("cut:Geometry", "which:False"),
    ("g_set:Geometry", "which:True"),
    ("input:On Patch", "surface:Switch"),
    ("water:Geometry", "surface:False"),
    ("which:Output", "surface:True"),
)

# The probes: each point of the pose's own mesh, in the anchor's space, dropped onto the patch.
_DROP_NODES = {
    "p": Node("GeometryNodeInputPosition", 2, label="a probe, in the anchor's space"),
    "p_world": Node("FunctionNodeTransformPoint", 3, label="in the world"),
    "q": Node("FunctionNodeTransformPoint", 4, label="in the water's space"),
    "down_d": Node("FunctionNodeTransformDirection", 3, values={"Direction": (0.0, 0.0, -1.0)}, label="down"),
    "down_n": vmath("NORMALIZE", 4, "down, in the water's space"),
    "up_n": vmath("SCALE", 5, "up", scale=-1.0),
    "down": _raycast(17, "straight down"),
    "up": _raycast(17, "straight up"),
    "up_nearer": Node(
        "FunctionNodeCompare", 18, {"data_type": "FLOAT", "operation": "LESS_THAN"}, label="up nearer"
    ),
    "down_missed": Node("FunctionNodeBooleanMath", 18, {"operation": "NOT"}, label="down missed"),
    "up_wins_d": Node("FunctionNodeBooleanMath", 19, {"operation": "OR"}, label="down missed or up nearer"),
    "up_wins": Node("FunctionNodeBooleanMath", 20, {"operation": "AND"}, label="up hit and wins"),
    "hit": _switch("VECTOR", 21, "the nearer hit"),
    "any": Node("FunctionNodeBooleanMath", 20, {"operation": "OR"}, label="a hit"),
    "hit_world": Node("FunctionNodeTransformPoint", 22, label="in the world"),
    "hit_z": Node("ShaderNodeSeparateXYZ", 23, label="its height"),
    "p_world_xyz": Node("ShaderNodeSeparateXYZ", 4, label="the probe in the world"),
    "z": _switch("FLOAT", 24, "the height it drops to (or stays at)"),
}

_DROP_LINKS = (
    ("p:Position", "p_world:Vector"),
    ("anchor:Transform", "p_world:Transform"),
    ("p_world:Vector", "q:Vector"),
    ("w_inv:Matrix", "q:Transform"),
    ("w_inv:Matrix", "down_d:Transform"),
    ("down_d:Direction", "down_n:Vector"),
    ("down_n:Vector", "up_n:Vector"),
    ("surface:Output", "down:Target Geometry"),
    ("q:Vector", "down:Source Position"),
    ("down_n:Vector", "down:Ray Direction"),
    ("surface:Output", "up:Target Geometry"),
    ("q:Vector", "up:Source Position"),
    ("up_n:Vector", "up:Ray Direction"),
    ("up:Hit Distance", "up_nearer:A"),
    ("down:Hit Distance", "up_nearer:B"),
    ("down:Is Hit", "down_missed:Boolean"),
    ("down_missed:Boolean", "up_wins_d:#0"),
    ("up_nearer:Result", "up_wins_d:#1"),
    ("up:Is Hit", "up_wins:#0"),
    ("up_wins_d:Boolean", "up_wins:#1"),
    ("up_wins:Boolean", "hit:Switch"),
    ("down:Hit Position", "hit:False"),
    ("up:Hit Position", "hit:True"),
    ("down:Is Hit", "any:#0"),
    ("up:Is Hit", "any:#1"),
    ("hit:Output", "hit_world:Vector"),
    ("water:Transform", "hit_world:Transform"),
    ("hit_world:Vector", "hit_z:Vector"),
    ("p_world:Vector", "p_world_xyz:Vector"),
    ("any:Boolean", "z:Switch"),
    ("p_world_xyz:Z", "z:False"),
    ("hit_z:Z", "z:True"),
)

# The fit: the weighted sums of the probes' heights, and the triangle laid on the plane.
_FIT_NODES = {
    "weights": Node(
        "GeometryNodeInputNamedAttribute", 23, {"data_type": "FLOAT_VECTOR"}, {"Name": WEIGHTS}, "weights"
    ),
    "weighted": vmath("SCALE", 25, "weights x height"),
    "sums": Node(
        "GeometryNodeAttributeStatistic",
        26,
        {"data_type": "FLOAT_VECTOR", "domain": "POINT"},
        label="height, slope x, slope y",
    ),
    "plane": Node("ShaderNodeSeparateXYZ", 27, label="the plane"),
    "height": math("ADD", 28, "+ Height: where the origin sits"),
    "k": math("MULTIPLY_ADD", 28, "1 + slope x²", c=1.0),
    "k_root": math("SQRT", 29, "its root"),
    "gy": math("MULTIPLY", 30, "slope y x the root"),
    "group": Node(
        "GeometryNodeInputNamedAttribute", 23, {"data_type": "FLOAT"}, {"Name": POSE_GROUP}, "the triangle"
    ),
    "is_pose": math("GREATER_THAN", 24, "in the group", b=0.5),
    "t": Node("GeometryNodeInputPosition", 27, label="the triangle's own point"),
    "t_xyz": Node("ShaderNodeSeparateXYZ", 28, label=""),
    "rise_x": math("MULTIPLY", 29, "x slope x"),
    "rise": math("MULTIPLY_ADD", 31, "+ y slope y root"),
    "t_z": math("SUBTRACT", 32, "height - rise: normal (-sx, -sy root, 1)"),
    "anchor_xyz": Node("ShaderNodeSeparateXYZ", 4, label="the anchor"),
    "t_x": math("SUBTRACT", 29, "over the anchor (half a turn)"),
    "t_y": math("SUBTRACT", 29, "over the anchor (half a turn)"),
    "t_at": Node("ShaderNodeCombineXYZ", 33, label="on the plane, in the pose's space"),
    "probe_x": math("MULTIPLY", 25, "(half a turn)", b=-1.0),
    "probe_y": math("MULTIPLY", 25, "(half a turn)", b=-1.0),
    "probe_at": Node("ShaderNodeCombineXYZ", 26, label="the probe where it dropped, in the pose's space"),
    "where": _switch("VECTOR", 34, "triangle or probe"),
    "set": Node("GeometryNodeSetPosition", 35, label="the pose"),
}

_FIT_LINKS = (
    ("weights:Attribute", "weighted:Vector"),
    ("z:Output", "weighted:Scale"),
    ("input:Geometry", "sums:Geometry"),
    ("weighted:Vector", "sums:Attribute"),
    ("sums:Sum", "plane:Vector"),
    ("plane:X", "height:#0"),
    ("input:Height", "height:#1"),
    ("plane:Y", "k:#0"),
    ("plane:Y", "k:#1"),
    ("k:Value", "k_root:#0"),
    ("plane:Z", "gy:#0"),
    ("k_root:Value", "gy:#1"),
    ("t:Position", "t_xyz:Vector"),
    ("t_xyz:X", "rise_x:#0"),
    ("plane:Y", "rise_x:#1"),
    ("t_xyz:Y", "rise:#0"),
    ("gy:Value", "rise:#1"),
    ("rise_x:Value", "rise:#2"),
    ("height:Value", "t_z:#0"),
    ("rise:Value", "t_z:#1"),
    ("anchor:Location", "anchor_xyz:Vector"),
    ("t_xyz:X", "t_x:#0"),
    ("anchor_xyz:X", "t_x:#1"),
    ("t_xyz:Y", "t_y:#0"),
    ("anchor_xyz:Y", "t_y:#1"),
    ("t_x:Value", "t_at:X"),
    ("t_y:Value", "t_at:Y"),
    ("t_z:Value", "t_at:Z"),
    ("p_world_xyz:X", "probe_x:#0"),
    ("p_world_xyz:Y", "probe_y:#0"),
    ("probe_x:Value", "probe_at:X"),
    ("probe_y:Value", "probe_at:Y"),
    ("z:Output", "probe_at:Z"),
    ("group:Attribute", "is_pose:#0"),
    ("is_pose:Value", "where:Switch"),
    ("probe_at:Vector", "where:False"),
    ("t_at:Vector", "where:True"),
    ("input:Geometry", "set:Geometry"),
    ("where:Output", "set:Position"),
    ("set:Geometry", "output:Geometry"),
)

SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="A floating object's pose: the plane fitted to the water's surface under its footprint",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("Geometry", "NodeSocketGeometry"),
        Socket("Water", "NodeSocketObject", tooltip="The water the object floats on"),
        Socket("Anchor", "NodeSocketObject", tooltip="The floating rig's anchor"),
        Socket(
            "Height",
            "NodeSocketFloat",
            0.0,
            -1e5,
            1e5,
            "DISTANCE",
            "Added to the plane's height at the anchor: where the object's origin sits (metres)",
        ),
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
            "On Patch",
            "NodeSocketBool",
            True,
            tooltip="Drop the probes onto the patch round the anchor (off: onto the whole water, slow)",
        ),
    ),
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes={**_PATCH_NODES, **_DROP_NODES, **_FIT_NODES},
    links=_PATCH_LINKS + _DROP_LINKS + _FIT_LINKS,
)
