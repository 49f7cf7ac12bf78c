"""`Water Surroundings`: what lies around and under the water, measured on its hidden cache as
point attributes (SPEC 1).

The measuring is costly (two raycasts per point on the realized surroundings and a
proximity search), so it does not run on the water, whose stack is evaluated
again on every frame once it has waves. It runs on a hidden cache object, "<water>
Surroundings" (`water/surroundings.py`): it shares the water's mesh (the same
points in the same order), is parented to the water with an identity parent
inverse (the same object space), and has no waves. The depsgraph evaluates it
again only when what it depends on changes: its surroundings (Collection Info)
or its transform (the water's). The water itself runs the light `Water
Surroundings Sample` (`surroundings_sample.py`) after its waves: it reads the
cache's attributes point by point (Sample Index by Index) and moves the depth
with the waves.

`Water Surroundings` (on the cache) reads the objects of one collection (the
`Surroundings` input) through Collection Info in RELATIVE space, so they arrive in
its object space, the water's (the water plane is z = 0, its "down" is -Z), and
stores three float point attributes, in world metres:

* `water_depth`: from the point straight down (-Z) to the first
  surroundings surface, `FAR` (1000) where nothing is below, 0 on dry points.
* `water_shore_distance`: in the water's plane, to the nearest place where the
  surroundings cross the surface (a beach's waterline, a post's outline), `FAR`
  where nothing crosses, 0 on dry points.
* `water_surroundings`: 1 everywhere, so a shader knows the other two exist (a
  water without the modifier reads 0).
* `.water_height` (hidden): the signed height h of step 1.
* `.water_floor` (hidden): z - h / |scale.z|, the object-space height of what lies
  straight below (above, on dry points), `NO_FLOOR` (-1e30) where nothing does: the
  sample group's depth is (z - floor) |scale.z| at any z the waves lift the point to.
* `.water_uv_size` (hidden): object-space metres per UV unit, the grid's width over its UV
  map's span (measured here, once, not by the sample group on every frame).

Method, per water point p:

0. The surroundings are realized into one mesh. An object that is mirrored
   (negative determinant, its own or the water's, say a scale of -1) keeps its
   faces' winding when realized, so its normals would point inwards: each such
   object is marked on the instance domain (det = dot(cross(X, Y), Z) of its
   transform's axes; 4.2 has no Matrix Determinant node) and its faces flipped
   back. Collection Info separates the children for this, so a mirror set on an
   object inside a child collection or collection instance is not seen.
1. Two raycasts on that mesh: down (0, 0, -1) gives the depth; up (0, 0, 1)
   tells "dry": hitting a surface from behind (its normal along the ray) means
   p is under a beach or inside a closed object. The signed height h is
   +depth for wet points and -(distance up) for dry ones (h <= 0: dry). h is
   stored as `.water_height` (hidden), so the next steps read it back instead
   of casting the rays again, and `Water Surroundings Sample` can move it with
   the waves. An open shell (a hull with no deck) has
   nothing above the points inside it, so they count as wet.
2. Waterline samples, two kinds: (a) on each water-grid edge joining a wet and
   a dry vertex, the point where h, linearly interpolated, is 0 (this finds a
   beach's line even where its faces are few and large, to within the grid
   spacing); (b) on each surroundings edge crossing z = 0, its exact crossing
   (this finds a post thin enough to fall between grid points). Both are
   flattened onto z = 0.
3. Geometry Proximity (points) from p flattened: the XY offset to the nearest
   sample, scaled per axis by the water's scale, is the shore distance.

Object-space lengths become world metres with the water's own scale (Self
Object -> Object Info): `|scale.z|` along -Z, `|scale.xy|` in the plane. Nothing
here needs Python at render time: Collection Info makes the depsgraph
re-evaluate the cache whenever a surroundings object moves or deforms.
"""

from ..spec import GroupSpec, Node, Socket, math, vmath
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

NAME = "Water Surroundings"
VERSION = 3  # 2: keeps FLOOR_ATTRIBUTE for `Water Surroundings Sample`; 3: CACHE_UV_SIZE_ATTRIBUTE
UV_MAP = "UVMap"  # the water meshes' UV map (`water/grid.py`)
HEIGHT_ATTRIBUTE = ".water_height"  # signed height h (below), on the cache's geometry only
NO_FLOOR = -1.0e30  # `FLOOR_ATTRIBUTE` where nothing is below: any depth from it caps at FAR
MIRRORED_ATTRIBUTE = ".water_mirrored"  # on the realized surroundings only, never on the water
RAY_LENGTH = 1.0e6  # object units: rays reach everything in any sane scene


def _raycast(direction, column, label):
    values = {"Ray Direction": direction, "Ray Length": RAY_LENGTH}
    return Node("GeometryNodeRaycast", column, {"data_type": "FLOAT"}, values, label)


def _crossing(prefix, column, height_1, height_2, label):
    """Nodes and links giving, on an edge whose ends have heights h1, h2 (outputs named by
    `height_1`, `height_2`), whether h changes sign along it and the point where h = 0:
    `P1 + (P2 - P1) h1 / (h1 - h2)`. Returns (nodes, links, selection output, position output)."""
    c = prefix
    nodes = {
        f"{c}_up_1": compare("GREATER_THAN", column, "h1 > 0"),
        f"{c}_up_2": compare("GREATER_THAN", column, "h2 > 0"),
        f"{c}_diff": math("SUBTRACT", column, "h1 - h2"),
        f"{c}_cross": Node("FunctionNodeBooleanMath", column + 1, {"operation": "XOR"}, label=label),
        f"{c}_t": math("DIVIDE", column + 1, "t = h1 / (h1 - h2)"),
        f"{c}_edge": vmath("SUBTRACT", column + 1, "P2 - P1"),
        f"{c}_at": vmath("MULTIPLY_ADD", column + 2, "P1 + t (P2 - P1)"),
    }
    links = [
        (height_1, f"{c}_up_1:#0"),
        (height_2, f"{c}_up_2:#0"),
        (height_1, f"{c}_diff:#0"),
        (height_2, f"{c}_diff:#1"),
        (f"{c}_up_1:Result", f"{c}_cross:#0"),
        (f"{c}_up_2:Result", f"{c}_cross:#1"),
        (height_1, f"{c}_t:#0"),
        (f"{c}_diff:Value", f"{c}_t:#1"),
        (f"{c}_ends:Position 2", f"{c}_edge:#0"),
        (f"{c}_ends:Position 1", f"{c}_edge:#1"),
        (f"{c}_edge:Vector", f"{c}_at:#0"),
        (f"{c}_t:Value", f"{c}_at:#1"),
        (f"{c}_ends:Position 1", f"{c}_at:#2"),
    ]
    return nodes, links, f"{c}_cross:Boolean", f"{c}_at:Vector"


def _surroundings_nodes():
    """Step 0: the surroundings in the water's space, realized, mirrored objects' faces flipped back."""
    nodes = {
        # The surroundings, in the water's object space, and the water's own scale.
        "collection": Node(
            "GeometryNodeCollectionInfo",
            1,
            {"transform_space": "RELATIVE"},
            {"Separate Children": True},
            label="surroundings (water space)",
        ),
        "self": Node("GeometryNodeSelfObject", 1, label="the water"),
        "position": Node("GeometryNodeInputPosition", 1, label="p"),
        # 0. A mirrored instance (negative determinant) is realized with its faces' winding, so its
        #    normals point inside: flip its faces back. det = dot(cross(X, Y), Z) of its axes.
        "transform": Node("GeometryNodeInstanceTransform", 1, label="instance transform"),
        "axis_x": Node("FunctionNodeTransformDirection", 2, values={"Direction": (1.0, 0.0, 0.0)}, label="X"),
        "axis_y": Node("FunctionNodeTransformDirection", 2, values={"Direction": (0.0, 1.0, 0.0)}, label="Y"),
        "axis_z": Node("FunctionNodeTransformDirection", 2, values={"Direction": (0.0, 0.0, 1.0)}, label="Z"),
        "x_cross_y": vmath("CROSS_PRODUCT", 3, "X x Y"),
        "det": vmath("DOT_PRODUCT", 4, "det"),
        "is_mirrored": compare("LESS_THAN", 5, "det < 0"),
        "mark_mirrored": Node(
            "GeometryNodeStoreNamedAttribute",
            6,
            {"data_type": "BOOLEAN", "domain": "INSTANCE"},
            {"Name": MIRRORED_ATTRIBUTE},
            label="mark mirrored objects",
        ),
        "realize": Node("GeometryNodeRealizeInstances", 7, label="realize"),
        "mirrored": Node(
            "GeometryNodeInputNamedAttribute",
            7,
            {"data_type": "BOOLEAN"},
            {"Name": MIRRORED_ATTRIBUTE},
            label="mirrored",
        ),
        "unflip": Node("GeometryNodeFlipFaces", 8, label="surroundings mesh, normals out"),
    }
    links = [
        ("input:Surroundings", "collection:Collection"),
        ("transform:Transform", "axis_x:Transform"),
        ("transform:Transform", "axis_y:Transform"),
        ("transform:Transform", "axis_z:Transform"),
        ("axis_x:Direction", "x_cross_y:#0"),
        ("axis_y:Direction", "x_cross_y:#1"),
        ("x_cross_y:Vector", "det:#0"),
        ("axis_z:Direction", "det:#1"),
        ("det:Value", "is_mirrored:#0"),
        ("collection:Instances", "mark_mirrored:Geometry"),
        ("is_mirrored:Result", "mark_mirrored:Value"),
        ("mark_mirrored:Geometry", "realize:Geometry"),
        ("realize:Geometry", "unflip:Mesh"),
        ("mirrored:Attribute", "unflip:Selection"),
    ]
    return nodes, links


def _raycast_nodes():
    """Step 1: the water's scale, the two raycasts, and the signed height h kept for the steps after."""
    nodes = {
        "self_info": Node(
            "GeometryNodeObjectInfo", 2, {"transform_space": "ORIGINAL"}, label="water transform"
        ),
        "scale_abs": vmath("ABSOLUTE", 3, "|scale|"),
        "scale_xyz": Node("ShaderNodeSeparateXYZ", 4, label="|scale|"),
        # 1. Depth and dryness.
        "down": _raycast((0.0, 0.0, -1.0), 10, "ray down (-Z)"),
        "up": _raycast((0.0, 0.0, 1.0), 10, "ray up (+Z)"),
        "up_normal": Node("ShaderNodeSeparateXYZ", 11, label="normal hit going up"),
        "backface": compare("GREATER_THAN", 12, "hit from behind"),
        "dry": Node("FunctionNodeBooleanMath", 13, {"operation": "AND"}, label="dry: under or inside"),
        "depth_m": math("MULTIPLY", 12, "depth in metres"),
        "depth_cap": math("MINIMUM", 13, f"at most {FAR:g}", b=FAR),
        "depth": switch(14, f"depth, {FAR:g} if no hit", false=FAR),
        "above_m": math("MULTIPLY", 12, "distance up in metres"),
        "above": math("MULTIPLY", 13, "-(distance up)", b=-1.0),
        "h": switch(15, "signed height h"),
        "store_h": store(HEIGHT_ATTRIBUTE, 16, f"h, kept as '{HEIGHT_ATTRIBUTE}'"),
        "h_read": Node(
            "GeometryNodeInputNamedAttribute",
            16,
            {"data_type": "FLOAT"},
            {"Name": HEIGHT_ATTRIBUTE},
            label="h",
        ),
    }
    links = [
        ("self:Self Object", "self_info:Object"),
        ("self_info:Scale", "scale_abs:#0"),
        ("scale_abs:Vector", "scale_xyz:Vector"),
        # 1.
        ("unflip:Mesh", "down:Target Geometry"),
        ("position:Position", "down:Source Position"),
        ("unflip:Mesh", "up:Target Geometry"),
        ("position:Position", "up:Source Position"),
        ("up:Hit Normal", "up_normal:Vector"),
        ("up_normal:Z", "backface:#0"),
        ("up:Is Hit", "dry:#0"),
        ("backface:Result", "dry:#1"),
        ("down:Hit Distance", "depth_m:#0"),
        ("scale_xyz:Z", "depth_m:#1"),
        ("depth_m:Value", "depth_cap:#0"),
        ("down:Is Hit", "depth:Switch"),
        ("depth_cap:Value", "depth:True"),
        ("up:Hit Distance", "above_m:#0"),
        ("scale_xyz:Z", "above_m:#1"),
        ("above_m:Value", "above:#0"),
        ("dry:Boolean", "h:Switch"),
        ("depth:Output", "h:False"),
        ("above:Value", "h:True"),
        ("input:Geometry", "store_h:Geometry"),
        ("h:Output", "store_h:Value"),
    ]
    return nodes, links


def _waterline_nodes():
    """Step 2: the waterline's samples, on the grid's wet-to-dry edges and the surroundings' at z = 0."""
    nodes = {
        # 2a. Waterline on the water grid's edges (h read at both ends).
        "grid_ends": Node("GeometryNodeInputMeshEdgeVertices", 17, label="grid edge ends"),
        "grid_h1": Node("GeometryNodeSampleIndex", 18, {"data_type": "FLOAT", "domain": "POINT"}, label="h1"),
        "grid_h2": Node("GeometryNodeSampleIndex", 18, {"data_type": "FLOAT", "domain": "POINT"}, label="h2"),
        "grid_points": Node("GeometryNodeMeshToPoints", 22, {"mode": "EDGES"}, label="grid waterline"),
        # 2b. Waterline on the surroundings' edges (height = z).
        "sur_ends": Node("GeometryNodeInputMeshEdgeVertices", 17, label="surroundings edge ends"),
        "sur_z1": Node("ShaderNodeSeparateXYZ", 18, label="z1"),
        "sur_z2": Node("ShaderNodeSeparateXYZ", 18, label="z2"),
        "sur_points": Node("GeometryNodeMeshToPoints", 22, {"mode": "EDGES"}, label="surroundings waterline"),
    }
    links = [
        # 2a.
        ("store_h:Geometry", "grid_h1:Geometry"),
        ("h_read:Attribute", "grid_h1:Value"),
        ("grid_ends:Vertex Index 1", "grid_h1:Index"),
        ("store_h:Geometry", "grid_h2:Geometry"),
        ("h_read:Attribute", "grid_h2:Value"),
        ("grid_ends:Vertex Index 2", "grid_h2:Index"),
        ("store_h:Geometry", "grid_points:Mesh"),
        # 2b.
        ("sur_ends:Position 1", "sur_z1:Vector"),
        ("sur_ends:Position 2", "sur_z2:Vector"),
        ("unflip:Mesh", "sur_points:Mesh"),
    ]
    return nodes, links


def _shore_nodes():
    """Step 3: the shore distance to the nearest sample, then the depth and the flag, stored."""
    nodes = {
        # 3. Shore distance.
        "samples": Node("GeometryNodeJoinGeometry", 23, label="waterline samples"),
        "flat": vmath("MULTIPLY", 23, "(x, y, 0)", b=(1.0, 1.0, 0.0)),
        "flatten": Node("GeometryNodeSetPosition", 24, label="onto z = 0"),
        "nearest": Node("GeometryNodeProximity", 25, {"target_element": "POINTS"}, label="nearest sample"),
        "offset": vmath("SUBTRACT", 26, "offset to it"),
        "offset_m": vmath("MULTIPLY", 27, "in metres"),
        "distance": vmath("LENGTH", 28, "distance"),
        "distance_cap": math("MINIMUM", 29, f"at most {FAR:g}", b=FAR),
        "shore_or_far": switch(30, f"{FAR:g} if no samples", false=FAR),
        "is_dry": compare("LESS_EQUAL", 30, "dry: h <= 0"),
        "shore": switch(31, "0 on dry points", true=0.0),
        "store_shore": store(SHORE_ATTRIBUTE, 32, f"store '{SHORE_ATTRIBUTE}'"),
        "depth_final": math("MAXIMUM", 32, "depth: h, 0 if dry", b=0.0),
        "store_depth": store(DEPTH_ATTRIBUTE, 33, f"store '{DEPTH_ATTRIBUTE}'"),
        "store_flag": Node(
            "GeometryNodeStoreNamedAttribute",
            34,
            {"data_type": "FLOAT", "domain": "POINT"},
            {"Name": FLAG_ATTRIBUTE, "Value": 1.0},
            label=f"store '{FLAG_ATTRIBUTE}' = 1",
        ),
    }
    links = [
        # 3.
        ("grid_points:Points", "samples:Geometry"),
        ("sur_points:Points", "samples:Geometry"),
        ("position:Position", "flat:#0"),
        ("samples:Geometry", "flatten:Geometry"),
        ("flat:Vector", "flatten:Position"),
        ("flatten:Geometry", "nearest:Target"),
        ("flat:Vector", "nearest:Source Position"),
        ("nearest:Position", "offset:#0"),
        ("flat:Vector", "offset:#1"),
        ("offset:Vector", "offset_m:#0"),
        ("scale_abs:Vector", "offset_m:#1"),
        ("offset_m:Vector", "distance:#0"),
        ("distance:Value", "distance_cap:#0"),
        ("nearest:Is Valid", "shore_or_far:Switch"),
        ("distance_cap:Value", "shore_or_far:True"),
        ("h_read:Attribute", "is_dry:#0"),
        ("is_dry:Result", "shore:Switch"),
        ("shore_or_far:Output", "shore:False"),
        ("store_h:Geometry", "store_shore:Geometry"),
        ("shore:Output", "store_shore:Value"),
        ("h_read:Attribute", "depth_final:#0"),
        ("store_shore:Geometry", "store_depth:Geometry"),
        ("depth_final:Value", "store_depth:Value"),
        ("store_depth:Geometry", "store_flag:Geometry"),
    ]
    return nodes, links


def _floor_nodes():
    """Steps 4 and 5, for the sample group: the floor's height under each point and metres per UV unit."""
    nodes = {
        # 4. For the sample group: the floor's height under each point, in object units.
        "p_xyz": Node("ShaderNodeSeparateXYZ", 30, label="p"),
        "h_units": math("DIVIDE", 31, "h in object units"),
        "has_floor": compare("LESS_THAN", 31, f"something below: h < {FAR:g}", b=FAR),
        "floor_z": math("SUBTRACT", 32, "floor z = z - h"),
        "floor": switch(33, f"floor z, {NO_FLOOR:g} if nothing below", false=NO_FLOOR),
        "store_floor": store(FLOOR_ATTRIBUTE, 35, f"store '{FLOOR_ATTRIBUTE}'"),
        # 5. Metres per UV unit: the grid's width over its UV's span (the lake's UV runs 0..1
        #    across it, the open sea's 1 per 128 m); the width alone when the mesh has no UV_MAP.
        "bounds": Node("GeometryNodeBoundBox", 30, label="grid bounds"),
        "extent": vmath("SUBTRACT", 31, "max - min"),
        "extent_xyz": Node("ShaderNodeSeparateXYZ", 32, label="width"),
        "uv": Node(
            "GeometryNodeInputNamedAttribute",
            30,
            {"data_type": "FLOAT_VECTOR"},
            {"Name": UV_MAP},
            label=UV_MAP,
        ),
        "uv_stats": Node(
            "GeometryNodeAttributeStatistic",
            31,
            {"data_type": "FLOAT_VECTOR", "domain": "CORNER"},
            label="UV span",
        ),
        "uv_span": Node("ShaderNodeSeparateXYZ", 32, label="UV span"),
        "has_uv": compare("GREATER_THAN", 33, "has UVs", b=1.0e-6),
        "span": switch(34, "span, 1 without UVs", false=1.0),
        "per_uv": math("DIVIDE", 35, "metres per UV unit"),
        "store_uv_size": store(CACHE_UV_SIZE_ATTRIBUTE, 36, f"store '{CACHE_UV_SIZE_ATTRIBUTE}'"),
    }
    links = [
        ("position:Position", "p_xyz:Vector"),
        ("h_read:Attribute", "h_units:#0"),
        ("scale_xyz:Z", "h_units:#1"),
        ("h_read:Attribute", "has_floor:#0"),
        ("p_xyz:Z", "floor_z:#0"),
        ("h_units:Value", "floor_z:#1"),
        ("has_floor:Result", "floor:Switch"),
        ("floor_z:Value", "floor:True"),
        ("store_flag:Geometry", "store_floor:Geometry"),
        ("floor:Output", "store_floor:Value"),
        ("input:Geometry", "bounds:Geometry"),
        ("bounds:Max", "extent:#0"),
        ("bounds:Min", "extent:#1"),
        ("extent:Vector", "extent_xyz:Vector"),
        ("input:Geometry", "uv_stats:Geometry"),
        ("uv:Attribute", "uv_stats:Attribute"),
        ("uv_stats:Range", "uv_span:Vector"),
        ("uv_span:X", "has_uv:#0"),
        ("has_uv:Result", "span:Switch"),
        ("uv_span:X", "span:True"),
        ("extent_xyz:X", "per_uv:#0"),
        ("span:Output", "per_uv:#1"),
        ("store_floor:Geometry", "store_uv_size:Geometry"),
        ("per_uv:Value", "store_uv_size:Value"),
        ("store_uv_size:Geometry", "output:Geometry"),
    ]
    return nodes, links


def _build():
    """`Water Surroundings`' nodes and links: the steps of the module's Method, in order."""
    nodes, links = {}, []
    for more_nodes, more_links in (
        _surroundings_nodes(),
        _raycast_nodes(),
        _waterline_nodes(),
        _shore_nodes(),
        _floor_nodes(),
    ):
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes, links = nodes | more_nodes, links + list(more_links)
    for prefix, height_1, height_2, points, label in (
        ("grid", "grid_h1:Value", "grid_h2:Value", "grid_points", "wet to dry"),
        ("sur", "sur_z1:Z", "sur_z2:Z", "sur_points", "crosses z = 0"),
    ):
        crossing_nodes, crossing_links, selection, position = _crossing(prefix, 19, height_1, height_2, label)
        nodes.update(crossing_nodes)
        links += crossing_links
        links += [(selection, f"{points}:Selection"), (position, f"{points}:Position")]
    return nodes, tuple(links)


_NODES, _LINKS = _build()

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description=(
        f"Stores '{DEPTH_ATTRIBUTE}' and '{SHORE_ATTRIBUTE}' (world metres, {FAR:g} = nothing) "
        f"and '{FLAG_ATTRIBUTE}' = 1 from the objects of the Surroundings collection"
    ),
    inputs=(
        Socket("Geometry", "NodeSocketGeometry"),
        Socket(
            "Surroundings",
            "NodeSocketCollection",
            tooltip="Objects the water meets: beds, beaches, posts, hulls (never the water itself)",
        ),
    ),
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes=_NODES,
    links=_LINKS,
    tree_type="GeometryNodeTree",
)
