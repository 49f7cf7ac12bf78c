"""Under the water: the water between a camera below the surface and what it sees (docs/MODEL.md
section 16).

Three groups, made for each water by `water/underwater.py`:

* `Water Underwater Fog` (a shader): light crossing d metres of water keeps `exp(-c d)` of itself
  per channel, `c` the water's `Absorption` (per metre, the one that colours it from above), and
  the water scatters in `L (1 - exp(-c d))`, `L` what the water shows from above where it is
  deepest (the lake's `Scatter Color`, the ocean's `Deep Color`): a volume absorbing `c` per
  channel and emitting `c L` per metre does exactly that, in Cycles and in EEVEE. Its density
  is `c` only for camera rays: a ray that has crossed the surface from above is the surface
  shader's (its own `exp(-Absorption x path)`), and probes, reflections and shadows see none
  of it. Its `Light Shafts` (0 by default: no scatter closure, no cost) makes a share `b` of
  that `c` a forward Volume Scatter instead of absorption (c stays what it was): the sunlight
  the water scatters towards the eye, what is left of it at each depth (`exp(-c depth /
  cos_s)`, the water's level its body's origin: the fog is not seen by shadow rays), its
  shadow rays crossing the caustic light's sheet, so the shafts come patterned by the caustics;
* `Water Underwater Shell` (Geometry Nodes, on a hidden child of the water): the closed body of
  water the fog fills, the water's evaluated surface (its waves, in its own space) lowered a
  millimetre, so a ray meets the surface before the fog, and drawn down `Depth` metres
  (Extrude Mesh of all its faces, flipped to face out); empty while the scene's camera is more
  than `Margin` above the surface right over or under it (or beyond the water's edge, or deeper
  than `Depth`), so a camera that never goes under pays for none of it. Against the surface
  where the camera is, not its highest crest: a camera 3 m over a gale's sea, whose crests
  reach higher elsewhere, is above the water. With it, the waterline across the lens: the
  ribbon of `Water Meniscus` where the surface crosses the plane the camera's rays start on
  (`Near`, its Clip Start: Cycles starts each ray there, EEVEE clips what is nearer, so the rays
  starting under the surface see the water and those over it the air), `Meniscus` x `Near`
  thick, just beyond that plane, each of its points moved in the plane up or down to the
  surface's height there;
* `Water Meniscus` (a shader): the ribbon's dark line, a little of what is behind showing.
"""

from .spec import GroupSpec, Node, Socket, math, vmath

FOG_NAME = "Water Underwater Fog"
SHELL_NAME = "Water Underwater Shell"
LOWER = 0.001  # metres (the water's units): the fog's top below the surface
DEPTH = 200.0  # metres of water under the surface the fog fills by default
REACH = 150.0  # metres along the water from the camera: c = 0.04 per metre keeps 0.25% over it
MENISCUS_NAME = "Water Meniscus"
LINE_POINTS = 129  # along the waterline across the lens
LINE_SPAN = 3.0  # x Near either side of the view's centre: the width of a 6 mm lens' view
MENISCUS = 0.004  # x Near: the line's thickness, 5 pixels of a 1080-line frame through a 24 mm lens
DOWN_FROM = 500.0  # metres over a point the ray down to the surface starts (over any crest)
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


def _absorb(channel, column):
    """A Volume Absorption taking only `channel` (0 red, 1 green, 2 blue), its density linked."""
    colour = [1.0, 1.0, 1.0]
    colour[channel] = 0.0
    label = f"absorbs {'RGB'[channel]}"
    return Node("ShaderNodeVolumeAbsorption", column, values={"Color": tuple(colour)}, label=label)


# Light Shafts: water scatters forward (Petzold's measured phase functions, g about 0.9), so the
# sunlight it scatters towards the eye is brightest looking towards the sun: Henyey-Greenstein's g.
SHAFTS_ANISOTROPY = 0.85


def _sunlit(channel, column):
    """Nodes for one channel (0 red, 1 green, 2 blue): the sunlight kept at this depth
    `exp(-c path)` scattered by `b` (`be`), and the absorption `c - b exp(-c path)` that keeps
    the fog's extinction `c` (a Volume Scatter's colour is its share of the extinction too)."""
    rgb = "RGB"[channel]
    return {
        f"cp_{rgb}": math("MULTIPLY", column, f"{rgb}: c x path"),
        f"kept_{rgb}": math("EXPONENT", column + 1, f"{rgb}: exp(-c path)"),
        f"be_{rgb}": math("MULTIPLY", column + 2, f"{rgb}: b exp(-c path)"),
        f"k_{rgb}": math("SUBTRACT", column + 3, f"{rgb} absorbed: c - b exp(-c path)"),
    }


def _sunlit_links(channel):
    rgb = "RGB"[channel]
    name = ("Red", "Green", "Blue")[channel]
    lower = "rgb"[channel]
    return (
        (f"c:{name}", f"cp_{rgb}:#0"),
        ("neg_path:Value", f"cp_{rgb}:#1"),
        (f"cp_{rgb}:Value", f"kept_{rgb}:#0"),
        ("b:Value", f"be_{rgb}:#0"),
        (f"kept_{rgb}:Value", f"be_{rgb}:#1"),
        (f"c_{lower}:Value", f"k_{rgb}:#0"),
        (f"be_{rgb}:Value", f"k_{rgb}:#1"),
        (f"k_{rgb}:Value", f"a_{lower}:Density"),
        (f"be_{rgb}:Value", f"lit:{name}"),
    )


FOG_SPEC = GroupSpec(
    name=FOG_NAME,
    version=3,  # 3: Each Placement (a collection instance's placements, each its own camera gate)
    description="The water between a camera under the surface and what it sees: exp(-c d) kept, "
    "L (1 - exp(-c d)) scattered in, per channel; with Light Shafts, the sunlight it scatters",
    inputs=(
        Socket(
            "Absorption",
            "NodeSocketColor",
            (0.0, 0.0, 0.0, 1.0),
            tooltip="c: what the water absorbs per metre, per channel (the water's own Absorption)",
        ),
        Socket(
            "Scatter Color",
            "NodeSocketColor",
            (0.0, 0.0, 0.0, 1.0),
            tooltip="L: the colour far water takes (the lake's Scatter Color, the ocean's Deep Color)",
        ),
        Socket(
            "Light Shafts",
            "NodeSocketFloat",
            0.0,
            min=0.0,
            max=1.0,
            subtype="FACTOR",
            tooltip="How much of what the water takes from the light it scatters instead (b = this x "
            "its least c per metre, the rest absorbed): the sun's light shafts, patterned by the "
            "caustics. 0: none, and no cost",
        ),
        Socket(
            "Sun Direction",
            "NodeSocketVector",
            (0.0, 0.0, -1.0),
            subtype="DIRECTION",
            tooltip="Where the sunlight goes (the water's own Sun Direction): the shafts' light is "
            "what is left of it at each depth",
        ),
        EACH_PLACEMENT,
    ),
    outputs=(Socket("Volume", "NodeSocketShader"),),
    nodes={
        "path_rays": Node("ShaderNodeLightPath", 0),
        **placement_gate(-4, MARGIN),
        "open": math("SUBTRACT", 0, "1 - shut", a=1.0),
        "path": math("MULTIPLY", 1, "camera rays, this placement's"),
        "c": Node("ShaderNodeSeparateColor", 1, label="c per channel"),
        # b: the share of c scattered, the same in every channel (scattering hardly varies with colour).
        "c_least": math("MINIMUM", 1, "least c"),
        "c_least_all": math("MINIMUM", 2, "least c of three"),
        "b_raw": math("MULTIPLY", 3, "b = Light Shafts x least c"),
        "b": math("MULTIPLY", 4, "b: camera rays only"),
        # The sunlight's way down to here: depth under the water's level / cos of the refracted sun.
        "here": Node("ShaderNodeNewGeometry", 1),
        "level": Node("ShaderNodeObjectInfo", 1, label="the water's level (the body's origin)"),
        "here_xyz": Node("ShaderNodeSeparateXYZ", 2),
        "level_xyz": Node("ShaderNodeSeparateXYZ", 2),
        "depth_raw": math("SUBTRACT", 3, "depth = level - z"),
        "depth": math("MAXIMUM", 4, "at least 0", b=0.0),
        "sun": vmath("NORMALIZE", 2, "L"),
        "r_s": vmath("REFRACT", 3, "r_s = refract(L, up, 1/1.333)", b=(0.0, 0.0, 1.0), scale=1.0 / 1.333),
        "r_s_xyz": Node("ShaderNodeSeparateXYZ", 4),
        "cos_s": math("MULTIPLY", 5, "cos_s = -r_s.z", b=-1.0),
        "cos_s_safe": math("MAXIMUM", 6, "max(, 0.05)", b=0.05),
        "sun_path": math("DIVIDE", 6, "path = depth / cos_s"),
        "neg_path": math("MULTIPLY", 7, "-path", b=-1.0),
        "c_r": math("MULTIPLY", 2, "red: camera rays only"),
        "c_g": math("MULTIPLY", 2, "green: camera rays only"),
        "c_b": math("MULTIPLY", 2, "blue: camera rays only"),
        **_sunlit(0, 8),
        **_sunlit(1, 8),
        **_sunlit(2, 8),
        "a_r": _absorb(0, 12),
        "a_g": _absorb(1, 12),
        "a_b": _absorb(2, 12),
        "lit": Node("ShaderNodeCombineColor", 12, label="b exp(-c path) per channel"),
        "shafts": Node(
            "ShaderNodeVolumeScatter",
            13,
            values={"Density": 1.0, "Anisotropy": SHAFTS_ANISOTROPY},
            label="sunlight scattered (forward)",
        ),
        "cl": vmath("MULTIPLY", 2, "c L: emitted per metre"),
        "glow": Node("ShaderNodeEmission", 3, label="scattered in"),
        "rg": Node("ShaderNodeAddShader", 13),
        "rgb": Node("ShaderNodeAddShader", 14),
        "lit_all": Node("ShaderNodeAddShader", 15),
        "all": Node("ShaderNodeAddShader", 16),
    },
    links=(
        *placement_links(),
        ("shut:Value", "open:#1"),
        ("path_rays:Is Camera Ray", "path:#0"),
        ("open:Value", "path:#1"),
        ("input:Absorption", "c:Color"),
        ("c:Red", "c_least:#0"),
        ("c:Green", "c_least:#1"),
        ("c_least:Value", "c_least_all:#0"),
        ("c:Blue", "c_least_all:#1"),
        ("input:Light Shafts", "b_raw:#0"),
        ("c_least_all:Value", "b_raw:#1"),
        ("b_raw:Value", "b:#0"),
        ("path:Value", "b:#1"),
        ("here:Position", "here_xyz:Vector"),
        ("level:Location", "level_xyz:Vector"),
        ("level_xyz:Z", "depth_raw:#0"),
        ("here_xyz:Z", "depth_raw:#1"),
        ("depth_raw:Value", "depth:#0"),
        ("input:Sun Direction", "sun:#0"),
        ("sun:Vector", "r_s:#0"),
        ("r_s:Vector", "r_s_xyz:Vector"),
        ("r_s_xyz:Z", "cos_s:#0"),
        ("cos_s:Value", "cos_s_safe:#0"),
        ("depth:Value", "sun_path:#0"),
        ("cos_s_safe:Value", "sun_path:#1"),
        ("sun_path:Value", "neg_path:#0"),
        ("c:Red", "c_r:#0"),
        ("c:Green", "c_g:#0"),
        ("c:Blue", "c_b:#0"),
        ("path:Value", "c_r:#1"),
        ("path:Value", "c_g:#1"),
        ("path:Value", "c_b:#1"),
        *_sunlit_links(0),
        *_sunlit_links(1),
        *_sunlit_links(2),
        ("lit:Color", "shafts:Color"),
        ("input:Absorption", "cl:#0"),
        ("input:Scatter Color", "cl:#1"),
        ("cl:Vector", "glow:Color"),
        ("path:Value", "glow:Strength"),
        ("a_r:Volume", "rg:#0"),
        ("a_g:Volume", "rg:#1"),
        ("rg:Shader", "rgb:#0"),
        ("a_b:Volume", "rgb:#1"),
        ("rgb:Shader", "lit_all:#0"),
        ("shafts:Volume", "lit_all:#1"),
        ("lit_all:Shader", "all:#0"),
        ("glow:Emission", "all:#1"),
        ("all:Shader", "output:Volume"),
    ),
)


MENISCUS_SPEC = GroupSpec(
    name=MENISCUS_NAME,
    version=1,
    description="The thin line of water across the lens where it crosses the surface: dark, a "
    "little of what is behind showing through",
    inputs=(
        Socket("Color", "NodeSocketColor", (0.01, 0.015, 0.02, 1.0), tooltip="The line's own colour"),
        Socket(
            "Opacity",
            "NodeSocketFloat",
            0.85,
            min=0.0,
            max=1.0,
            subtype="FACTOR",
            tooltip="How much of what is behind the line it hides",
        ),
    ),
    outputs=(Socket("Shader", "NodeSocketShader"),),
    nodes={
        "clear": Node("ShaderNodeBsdfTransparent", 1),
        "line": Node("ShaderNodeEmission", 1, label="the line"),
        "mix": Node("ShaderNodeMixShader", 2),
    },
    links=(
        ("input:Color", "line:Color"),
        ("input:Opacity", "mix:Fac"),
        ("clear:BSDF", "mix:#1"),
        ("line:Emission", "mix:#2"),
        ("mix:Shader", "output:Shader"),
    ),
)


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


# Whether the camera is well above the water: the rule both the body and the caustic sheet are
# made by (needs a "water" Object Info node and the inputs Depth and Margin).
_GATE_NODES = {
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
    "off": Node("FunctionNodeBooleanMath", 8, {"operation": "AND"}, label="beside the water here"),
    "placed": Node("FunctionNodeBooleanMath", 9, {"operation": "AND"}, label="made for every placement"),
    "not_placed": Node("FunctionNodeBooleanMath", 10, {"operation": "NOT"}),
    "hidden": Node("FunctionNodeBooleanMath", 11, {"operation": "AND"}, label="well above, not placed"),
    "which": Node("GeometryNodeSwitch", 12, {"input_type": "MATERIAL"}, label="each placement's gate"),
}
_GATE_LINKS = (
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
    ("under:Max", "above:A"),
    ("water:Geometry", "look_down:Target Geometry"),
    ("here:Vector", "look_down:Source Position"),
    ("probe:Points", "over:Geometry"),
    ("look_down:Is Hit", "over:Attribute"),
    ("over:Max", "beside:A"),
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


def _placement_inputs(what):
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


SHELL_SPEC = GroupSpec(
    name=SHELL_NAME,
    version=4,  # 4: Every Placement (a body for collection instances' placements)
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
        *_placement_inputs("body"),
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
        **_GATE_NODES,
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
        *_GATE_LINKS,
        ("hidden:Boolean", "made:Switch"),
        *_MENISCUS_LINKS,
        ("all:Geometry", "made:False"),
        ("made:Output", "output:Geometry"),
    ),
)


SHEET_NAME = "Water Caustic Sheet"
SHEET_DROP = 0.01  # metres (the water's units): the sheet under the surface, which it never shadows

SHEET_SPEC = GroupSpec(
    name=SHEET_NAME,
    version=2,  # 2: Every Placement (a sheet for collection instances' placements)
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
        *_placement_inputs("caustic light"),
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
        **_GATE_NODES,
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
        *_GATE_LINKS,
        ("hidden:Boolean", "made:Switch"),
        ("light:Geometry", "made:False"),
        ("made:Output", "output:Geometry"),
    ),
)
