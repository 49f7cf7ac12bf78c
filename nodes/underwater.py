"""Under the water: the water between a camera below the surface and what it sees (docs/MODEL.md
section 16).

Two groups, made for each water by `water/underwater.py`:

* `Water Underwater Fog` (a shader): light crossing d metres of water keeps `exp(-c d)` of itself
  per channel, `c` the water's `Absorption` (per metre, the one that colours it from above), and
  the water scatters in `L (1 - exp(-c d))`, `L` what the water shows from above where it is
  deepest (the lake's `Scatter Color`, the ocean's `Deep Color`): a volume absorbing `c` per
  channel and emitting `c L` per metre does exactly that, in Cycles and in EEVEE. Its density
  is `c` only for camera rays: a ray that has crossed the surface from above is the surface
  shader's (its own `exp(-Absorption x path)`), and probes, reflections and shadows see none
  of it;
* `Water Underwater Shell` (Geometry Nodes, on a hidden child of the water): the closed body of
  water the fog fills, the water's evaluated surface (its waves, in its own space) lowered a
  millimetre, so a ray meets the surface before the fog, and drawn down `Depth` metres
  (Extrude Mesh of all its faces, flipped to face out); empty while the scene's camera is more
  than `Margin` above the surface right over or under it (or beyond the water's edge, or deeper
  than `Depth`), so a camera that never goes under pays for none of it. Against the surface
  where the camera is, not its highest crest: a camera 3 m over a gale's sea, whose crests
  reach higher elsewhere, is above the water.
"""

from .spec import GroupSpec, Node, Socket, math, vmath

FOG_NAME = "Water Underwater Fog"
SHELL_NAME = "Water Underwater Shell"
LOWER = 0.001  # metres (the water's units): the fog's top below the surface
DEPTH = 200.0  # metres of water under the surface the fog fills by default
REACH = 150.0  # metres along the water from the camera: c = 0.04 per metre keeps 0.25% over it
MARGIN = 1.0  # metres over the surface under it within which the camera may see the water


def _absorb(channel, column):
    """A Volume Absorption taking only `channel` (0 red, 1 green, 2 blue), its density linked."""
    colour = [1.0, 1.0, 1.0]
    colour[channel] = 0.0
    label = f"absorbs {'RGB'[channel]}"
    return Node("ShaderNodeVolumeAbsorption", column, values={"Color": tuple(colour)}, label=label)


FOG_SPEC = GroupSpec(
    name=FOG_NAME,
    version=1,
    description="The water between a camera under the surface and what it sees: exp(-c d) kept, "
    "L (1 - exp(-c d)) scattered in, per channel",
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
    ),
    outputs=(Socket("Volume", "NodeSocketShader"),),
    nodes={
        "path": Node("ShaderNodeLightPath", 1),
        "c": Node("ShaderNodeSeparateColor", 1, label="c per channel"),
        "c_r": math("MULTIPLY", 2, "red: camera rays only"),
        "c_g": math("MULTIPLY", 2, "green: camera rays only"),
        "c_b": math("MULTIPLY", 2, "blue: camera rays only"),
        "a_r": _absorb(0, 3),
        "a_g": _absorb(1, 3),
        "a_b": _absorb(2, 3),
        "cl": vmath("MULTIPLY", 2, "c L: emitted per metre"),
        "glow": Node("ShaderNodeEmission", 3, label="scattered in"),
        "rg": Node("ShaderNodeAddShader", 4),
        "rgb": Node("ShaderNodeAddShader", 5),
        "all": Node("ShaderNodeAddShader", 6),
    },
    links=(
        ("input:Absorption", "c:Color"),
        ("c:Red", "c_r:#0"),
        ("c:Green", "c_g:#0"),
        ("c:Blue", "c_b:#0"),
        ("path:Is Camera Ray", "c_r:#1"),
        ("path:Is Camera Ray", "c_g:#1"),
        ("path:Is Camera Ray", "c_b:#1"),
        ("c_r:Value", "a_r:Density"),
        ("c_g:Value", "a_g:Density"),
        ("c_b:Value", "a_b:Density"),
        ("input:Absorption", "cl:#0"),
        ("input:Scatter Color", "cl:#1"),
        ("cl:Vector", "glow:Color"),
        ("path:Is Camera Ray", "glow:Strength"),
        ("a_r:Volume", "rg:#0"),
        ("a_g:Volume", "rg:#1"),
        ("rg:Shader", "rgb:#0"),
        ("a_b:Volume", "rgb:#1"),
        ("rgb:Shader", "all:#0"),
        ("glow:Emission", "all:#1"),
        ("all:Shader", "output:Volume"),
    ),
)


SHELL_SPEC = GroupSpec(
    name=SHELL_NAME,
    version=2,
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
        "made": Node("GeometryNodeSwitch", 14, {"input_type": "GEOMETRY"}, label="none while well above"),
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
        ("beyond:Result", "near:Selection"),
        ("near:Geometry", "lower:Geometry"),
        ("input:Depth", "depth:#0"),
        ("depth:Value", "down:Z"),
        ("lower:Geometry", "body:Mesh"),
        ("down:Vector", "body:Offset"),
        ("body:Mesh", "out:Mesh"),
        ("lower:Geometry", "closed:Geometry"),
        ("out:Mesh", "closed:Geometry"),
        ("closed:Geometry", "fog:Geometry"),
        ("input:Material", "fog:Material"),
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
        ("above:Result", "made:Switch"),
        ("fog:Geometry", "made:False"),
        ("made:Output", "output:Geometry"),
    ),
)
