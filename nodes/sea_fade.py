"""`Water Sea Fade`: the open sea's Geometry Nodes step after Blender's Ocean modifier.

The sea's mesh reaches the horizon with points ever further apart (`water/sea_mesh.py`). Far
out, the Ocean modifier's waves, sampled that sparsely, would turn into noise, and its tile,
seen many times across a row of pixels, into a visible repeat. So past `Fade Start` metres from
the sea's centre the displacement fades, reaching none at `Fade End`: the points go back to
their rest place (`water_rest`, stored in the mesh when it is made; the Ocean modifier keeps
it). The far sea is then flat and shaded by the bump alone, as a far sea looks.

Whitecaps break on the highest crests: those standing above the `Crest Share` quantile of the
heights in the un-faded middle, found every frame by bisection (a few Attribute Statistic passes),
so the share holds whatever the wind, spectrum, scale or seed (the Ocean modifier's heights are
far from a normal spread: a few waves near the peak carry most of them). There the point
attribute `water_whitecaps` is 1, fading with distance like the waves: the ocean shading scatters
whitecaps over these crests, as many as the wind raises (`ocean.py`).
"""

from .spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Sea Fade"
# 2: whitecaps from the crests' heights (were the Ocean modifier's own foam: blotches tens of
# metres across, a share of the sea that hardly followed the wind)
VERSION = 2
REST_ATTRIBUTE = "water_rest"
OCEAN_FOAM_ATTRIBUTE = "water_ocean_foam"  # the Ocean modifier's foam layer (version 1 read it)
WHITECAPS_ATTRIBUTE = "water_whitecaps"
CREST_SHARE = 0.5

# The threshold's bisection: from 2 standard deviations up or down by 1, then by half the last
# step each time: STEPS steps find it between 0 and 4 deviations, to 2 / 2^STEPS.
BISECTION_STEPS = 9
CREST_EDGE = 0.1  # deviations over which a point comes onto the crest


def _bisection():
    """Nodes and links that find T with mean(z > T) = Whitecap Share over the middle's points:
    each step measures the share above its T and moves T up (too much foam) or down by half the
    last step. Returns (nodes, links, the final T's socket)."""
    nodes, links = {}, []
    threshold, step = None, 2.0
    for i in range(BISECTION_STEPS):
        column = 7 + 2 * i
        nodes[f"over_{i}"] = math(
            "GREATER_THAN", column, f"z > T{i}", **({"b": 2.0} if threshold is None else {})
        )
        nodes[f"share_{i}"] = Node(
            "GeometryNodeAttributeStatistic",
            column,
            {"data_type": "FLOAT", "domain": "POINT"},
            label=f"share > T{i}",
        )
        nodes[f"more_{i}"] = math("GREATER_THAN", column + 1, "too much foam?")
        nodes[f"move_{i}"] = math("MULTIPLY_ADD", column + 1, f"+-{step / 2:g}", b=step, c=-step / 2)
        nodes[f"t_{i + 1}"] = math(
            "ADD", column + 1, f"T{i + 1}", **({"b": 2.0} if threshold is None else {})
        )
        links += [
            ("z:Value", f"over_{i}:#0"),
            ("input:Geometry", f"share_{i}:Geometry"),
            ("middle:Value", f"share_{i}:Selection"),
            (f"over_{i}:Value", f"share_{i}:Attribute"),
            (f"share_{i}:Mean", f"more_{i}:#0"),
            ("input:Crest Share", f"more_{i}:#1"),
            (f"more_{i}:Value", f"move_{i}:#0"),
            (f"move_{i}:Value", f"t_{i + 1}:#0"),
        ]
        if threshold is not None:
            links += [(threshold, f"over_{i}:#1"), (threshold, f"t_{i + 1}:#1")]
        threshold, step = f"t_{i + 1}:Value", step / 2
    return nodes, tuple(links), threshold


_BISECTION_NODES, _BISECTION_LINKS, _THRESHOLD = _bisection()

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
        Socket(
            "Crest Share",
            "NodeSocketFloat",
            CREST_SHARE,
            min=0.0,
            max=1.0,
            subtype="FACTOR",
            tooltip="Share of the sea (its highest crests) where whitecaps may break; how many do is "
            "the ocean shading's Whitecap Coverage",
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
        # The crest's height z in standard deviations of the middle's heights, this frame.
        "rise": Node("ShaderNodeSeparateXYZ", 3, label="displacement"),
        "middle": math("LESS_THAN", 3, "in the un-faded middle"),
        "stats": Node(
            "GeometryNodeAttributeStatistic",
            4,
            {"data_type": "FLOAT", "domain": "POINT"},
            label="heights in the middle",
        ),
        "spread": math("MAXIMUM", 5, "deviation (>= 1 mm)", b=0.001),
        "above": math("SUBTRACT", 5, "height - mean"),
        "z": math("DIVIDE", 6, "z = (height - mean) / deviation"),
        **_BISECTION_NODES,
        "crest_edge": math("ADD", 7 + 2 * BISECTION_STEPS, "threshold + edge", b=CREST_EDGE),
        "crest": Node(
            "ShaderNodeMapRange",
            8 + 2 * BISECTION_STEPS,
            {"data_type": "FLOAT", "interpolation_type": "LINEAR", "clamp": True},
            {"To Min": 0.0, "To Max": 1.0},
            label="on a crest",
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
        ("offset:Vector", "rise:Vector"),
        ("distance:Value", "middle:#0"),
        ("input:Fade Start", "middle:#1"),
        ("input:Geometry", "stats:Geometry"),
        ("middle:Value", "stats:Selection"),
        ("rise:Z", "stats:Attribute"),
        ("stats:Standard Deviation", "spread:#0"),
        ("rise:Z", "above:#0"),
        ("stats:Mean", "above:#1"),
        ("above:Value", "z:#0"),
        ("spread:Value", "z:#1"),
        *_BISECTION_LINKS,
        (_THRESHOLD, "crest_edge:#0"),
        ("z:Value", "crest:Value"),
        (_THRESHOLD, "crest:From Min"),
        ("crest_edge:Value", "crest:From Max"),
        ("crest:Result", "whitecaps:#0"),
        ("near:Result", "whitecaps:#1"),
        ("input:Geometry", "move:Geometry"),
        ("placed:Vector", "move:Position"),
        ("move:Geometry", "store:Geometry"),
        ("whitecaps:Value", "store:Value"),
        ("store:Geometry", "output:Geometry"),
    ),
    tree_type="GeometryNodeTree",
)
