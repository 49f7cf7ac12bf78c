"""`Water Sea Fade`: the open sea's Geometry Nodes step after Blender's Ocean modifier.

The sea's mesh reaches the horizon with points ever further apart (`water/sea_mesh.py`). Far
out, the Ocean modifier's waves, sampled that sparsely, would turn into noise, and its tile,
seen many times across a row of pixels, into a visible repeat. So past `Fade Start` metres from
the sea's centre the displacement fades, reaching none at `Fade End`: the points go back to
their rest place (`water_rest`, stored in the mesh when it is made; the Ocean modifier keeps
it). The far sea is then flat and shaded by the bump alone, as a far sea looks.

The modifier's foam (its `water_ocean_foam` corner colour) fades the same way and is stored
as the point attribute `water_whitecaps`, which the ocean shading turns into white foam.
"""

from .spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Sea Fade"
VERSION = 1
REST_ATTRIBUTE = "water_rest"
OCEAN_FOAM_ATTRIBUTE = "water_ocean_foam"  # the Ocean modifier's foam layer
WHITECAPS_ATTRIBUTE = "water_whitecaps"

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description="Fades the Ocean modifier's waves and foam out with distance; stores 'water_whitecaps'",
    inputs=(
        Socket("Geometry", "NodeSocketGeometry"),
        Socket(
            "Fade Start",
            "NodeSocketFloat",
            200.0,
            min=0.0,
            max=100000.0,
            subtype="DISTANCE",
            tooltip="Distance from the sea's centre where its waves start to flatten out",
        ),
        Socket(
            "Fade End",
            "NodeSocketFloat",
            600.0,
            min=0.0,
            max=100000.0,
            subtype="DISTANCE",
            tooltip="Distance from the sea's centre past which the sea is flat (shaded by the bump only)",
        ),
    ),
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes={
        "rest": Node(
            "GeometryNodeInputNamedAttribute",
            1,
            {"data_type": "FLOAT_VECTOR"},
            {"Name": REST_ATTRIBUTE},
            label="rest place",
        ),
        "position": Node("GeometryNodeInputPosition", 1),
        "foam": Node(
            "GeometryNodeInputNamedAttribute",
            1,
            {"data_type": "FLOAT"},
            {"Name": OCEAN_FOAM_ATTRIBUTE},
            label="Ocean modifier's foam",
        ),
        "distance": vmath("LENGTH", 2, "distance from the centre"),
        "end": math("MAXIMUM", 2, "end >= start + 1 mm"),
        "start_plus": math("ADD", 1, "start + 1 mm", b=0.001),
        "near": Node(
            "ShaderNodeMapRange",
            3,
            {"data_type": "FLOAT", "interpolation_type": "SMOOTHSTEP", "clamp": True},
            {"To Min": 1.0, "To Max": 0.0},
            label="1 near, 0 far",
        ),
        "offset": vmath("SUBTRACT", 2, "displacement"),
        "kept": vmath("SCALE", 4, "displacement kept"),
        "placed": vmath("ADD", 5, "rest + kept"),
        "whitecaps": math("MULTIPLY", 4, "foam faded"),
        "move": Node("GeometryNodeSetPosition", 6),
        "store": Node(
            "GeometryNodeStoreNamedAttribute",
            7,
            {"data_type": "FLOAT", "domain": "POINT"},
            {"Name": WHITECAPS_ATTRIBUTE},
            label=f"store '{WHITECAPS_ATTRIBUTE}'",
        ),
    },
    links=(
        ("rest:Attribute", "distance:#0"),
        ("input:Fade Start", "start_plus:#0"),
        ("start_plus:Value", "end:#0"),
        ("input:Fade End", "end:#1"),
        ("distance:Value", "near:Value"),
        ("input:Fade Start", "near:From Min"),
        ("end:Value", "near:From Max"),
        ("position:Position", "offset:#0"),
        ("rest:Attribute", "offset:#1"),
        ("offset:Vector", "kept:#0"),
        ("near:Result", "kept:Scale"),
        ("rest:Attribute", "placed:#0"),
        ("kept:Vector", "placed:#1"),
        ("foam:Attribute", "whitecaps:#0"),
        ("near:Result", "whitecaps:#1"),
        ("input:Geometry", "move:Geometry"),
        ("placed:Vector", "move:Position"),
        ("move:Geometry", "store:Geometry"),
        ("whitecaps:Value", "store:Value"),
        ("store:Geometry", "output:Geometry"),
    ),
    tree_type="GeometryNodeTree",
)
