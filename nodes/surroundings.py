"""`Water Surroundings` and `Water Surroundings Sample`: what lies around and under the water,
as point attributes (SPEC 1).

The measuring is costly (two raycasts per point on the realized surroundings and a
proximity search), so it does not run on the water, whose stack is evaluated
again on every frame once it has waves. It runs on a hidden cache object, "<water>
Surroundings" (`water/surroundings.py`): it shares the water's mesh (the same
points in the same order), is parented to the water with an identity parent
inverse (the same object space), and has no waves. The depsgraph evaluates it
again only when what it depends on changes: its surroundings (Collection Info)
or its transform (the water's). The water itself runs the light `Water
Surroundings Sample` after its waves: it reads the cache's attributes point by
point (Sample Index by Index) and moves the depth with the waves.

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

`Water Surroundings Sample` (on the water, after `Water Waves` or the open sea's fade), per
point i:

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

from .spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Surroundings"
VERSION = 3  # 2: keeps FLOOR_ATTRIBUTE for `Water Surroundings Sample`; 3: CACHE_UV_SIZE_ATTRIBUTE
SAMPLE_NAME = "Water Surroundings Sample"
SAMPLE_VERSION = 3  # 2: stores UV_SIZE_ATTRIBUTE for the caustics' parallax; 3: per UV unit
UV_MAP = "UVMap"  # the water meshes' UV map (`water/grid.py`)
CACHE_INPUT = "Cache"
HEIGHT_ATTRIBUTE = ".water_height"  # signed height h (below), on the cache's geometry only
FLOOR_ATTRIBUTE = ".water_floor"  # z of what is below (object units), on the cache's geometry only
NO_FLOOR = -1.0e30  # `FLOOR_ATTRIBUTE` where nothing is below: any depth from it caps at FAR
DEPTH_ATTRIBUTE = "water_depth"
SHORE_ATTRIBUTE = "water_shore_distance"
FLAG_ATTRIBUTE = "water_surroundings"
UV_SIZE_ATTRIBUTE = "water_uv_size"  # object-space metres per UV unit (the lake's rest width)
CACHE_UV_SIZE_ATTRIBUTE = ".water_uv_size"  # the same, measured once on the cache
MIRRORED_ATTRIBUTE = ".water_mirrored"  # on the realized surroundings only, never on the water
FAR = 1000.0  # metres: "nothing there"
RAY_LENGTH = 1.0e6  # object units: rays reach everything in any sane scene


def _compare(operation, column, label, b=0.0):
    """A float Compare node against the constant `b` (input 1 is the float B)."""
    return Node("FunctionNodeCompare", column, {"data_type": "FLOAT", "operation": operation}, {1: b}, label)


def _switch(column, label, false=None, true=None):
    """A float Switch; `false`/`true` are constants for the unlinked side."""
    values = {k: v for k, v in (("False", false), ("True", true)) if v is not None}
    return Node("GeometryNodeSwitch", column, {"input_type": "FLOAT"}, values, label)


def _store(name, column, label):
    props = {"data_type": "FLOAT", "domain": "POINT"}
    return Node("GeometryNodeStoreNamedAttribute", column, props, {"Name": name}, label)


def _raycast(direction, column, label):
    values = {"Ray Direction": direction, "Ray Length": RAY_LENGTH}
    return Node("GeometryNodeRaycast", column, {"data_type": "FLOAT"}, values, label)


def _crossing(prefix, column, height_1, height_2, label):
    """Nodes and links giving, on an edge whose ends have heights h1, h2 (outputs named by
    `height_1`, `height_2`), whether h changes sign along it and the point where h = 0:
    `P1 + (P2 - P1) h1 / (h1 - h2)`. Returns (nodes, links, selection output, position output)."""
    c = prefix
    nodes = {
        f"{c}_up_1": _compare("GREATER_THAN", column, "h1 > 0"),
        f"{c}_up_2": _compare("GREATER_THAN", column, "h2 > 0"),
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
        "is_mirrored": _compare("LESS_THAN", 5, "det < 0"),
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
        "backface": _compare("GREATER_THAN", 12, "hit from behind"),
        "dry": Node("FunctionNodeBooleanMath", 13, {"operation": "AND"}, label="dry: under or inside"),
        "depth_m": math("MULTIPLY", 12, "depth in metres"),
        "depth_cap": math("MINIMUM", 13, f"at most {FAR:g}", b=FAR),
        "depth": _switch(14, f"depth, {FAR:g} if no hit", false=FAR),
        "above_m": math("MULTIPLY", 12, "distance up in metres"),
        "above": math("MULTIPLY", 13, "-(distance up)", b=-1.0),
        "h": _switch(15, "signed height h"),
        "store_h": _store(HEIGHT_ATTRIBUTE, 16, f"h, kept as '{HEIGHT_ATTRIBUTE}'"),
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
        "shore_or_far": _switch(30, f"{FAR:g} if no samples", false=FAR),
        "is_dry": _compare("LESS_EQUAL", 30, "dry: h <= 0"),
        "shore": _switch(31, "0 on dry points", true=0.0),
        "store_shore": _store(SHORE_ATTRIBUTE, 32, f"store '{SHORE_ATTRIBUTE}'"),
        "depth_final": math("MAXIMUM", 32, "depth: h, 0 if dry", b=0.0),
        "store_depth": _store(DEPTH_ATTRIBUTE, 33, f"store '{DEPTH_ATTRIBUTE}'"),
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
        "has_floor": _compare("LESS_THAN", 31, f"something below: h < {FAR:g}", b=FAR),
        "floor_z": math("SUBTRACT", 32, "floor z = z - h"),
        "floor": _switch(33, f"floor z, {NO_FLOOR:g} if nothing below", false=NO_FLOOR),
        "store_floor": _store(FLOOR_ATTRIBUTE, 35, f"store '{FLOOR_ATTRIBUTE}'"),
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
        "has_uv": _compare("GREATER_THAN", 33, "has UVs", b=1.0e-6),
        "span": _switch(34, "span, 1 without UVs", false=1.0),
        "per_uv": math("DIVIDE", 35, "metres per UV unit"),
        "store_uv_size": _store(CACHE_UV_SIZE_ATTRIBUTE, 36, f"store '{CACHE_UV_SIZE_ATTRIBUTE}'"),
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
        "in_place": _compare("LESS_THAN", 6, "cache where the water is", b=1.0e-3),
        "has_flag": _compare("GREATER_THAN", 4, "cache measured", b=0.5),
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
        "depth_valid": _switch(9, f"depth, {FAR:g} without a cache", false=FAR),
        "shore_valid": _switch(9, f"shore distance, {FAR:g} without a cache", false=FAR),
        "flag_valid": _switch(9, "flag: 1, 0 without a cache", false=0.0, true=1.0),
        "store_depth": _store(DEPTH_ATTRIBUTE, 10, f"store '{DEPTH_ATTRIBUTE}'"),
        "store_shore": _store(SHORE_ATTRIBUTE, 11, f"store '{SHORE_ATTRIBUTE}'"),
        "store_flag": _store(FLAG_ATTRIBUTE, 12, f"store '{FLAG_ATTRIBUTE}'"),
        # Metres per UV unit, so the shader turns metres into UV: measured by the cache (the
        # two groups are built together), one value, read at point 0.
        "uv_size_read": _read(CACHE_UV_SIZE_ATTRIBUTE, 2, "metres per UV unit (cache)"),
        "uv_size": _sample("FLOAT", 3, "at point 0: one value"),
        "store_uv_size": _store(UV_SIZE_ATTRIBUTE, 13, f"store '{UV_SIZE_ATTRIBUTE}'"),
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


def _build_sample():
    """`Water Surroundings Sample`'s nodes and links: the cache read point by point, if valid."""
    nodes, links = {}, []
    for more_nodes, more_links in (_sample_input_nodes(), _sample_valid_nodes(), _sample_store_nodes()):
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes, links = nodes | more_nodes, links + list(more_links)
    return nodes, tuple(links)


_SAMPLE_NODES, _SAMPLE_LINKS = _build_sample()

SAMPLE_SPEC = GroupSpec(
    name=SAMPLE_NAME,
    version=SAMPLE_VERSION,
    description=(
        f"Reads '{DEPTH_ATTRIBUTE}', '{SHORE_ATTRIBUTE}' and '{FLAG_ATTRIBUTE}' from the water's "
        f"surroundings cache (its '{NAME}' modifier), point by point, the depth following the waves; "
        f"stores '{UV_SIZE_ATTRIBUTE}', metres per UV unit"
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
    nodes=_SAMPLE_NODES,
    links=_SAMPLE_LINKS,
    tree_type="GeometryNodeTree",
)
