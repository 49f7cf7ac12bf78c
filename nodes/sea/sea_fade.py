"""`Water Sea Fade`: the open sea's Geometry Nodes step after Blender's Ocean modifier.

The sea's mesh reaches the horizon with points ever further apart (`water/sea/sea_mesh.py`). Far
out, the Ocean modifier's waves, sampled that sparsely, would turn into noise, and its tile,
seen many times across a row of pixels, into a visible repeat. So past `Fade Start` metres from
the sea's centre the displacement fades, reaching none at `Fade End`: the points go back to
their rest place (`water_rest`, stored in the mesh when it is made; the Ocean modifier keeps
it). The far sea is then flat and shaded by the bump alone, as a far sea looks.

Whitecaps break on the highest crests: those standing above the `Crest Share` quantile of the
heights in the un-faded middle, found every frame by bisection (a few Attribute Statistic passes),
so the share holds whatever the wind, spectrum, scale or seed (the Ocean modifier's heights are
far from a normal spread: a few waves near the peak carry most of them). There the point
attribute `water_whitecaps` is 1, fading with distance like the waves (`water_crest` keeps the
crests before the foam they leave behind is added): the ocean shading scatters whitecaps over
these crests, as many as the wind raises, and past the fade as many again where it marks none
(`ocean_shade.py`).
"""

from ..spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Sea Fade"
# 2: whitecaps from the crests' heights (were the Ocean modifier's own foam: blotches tens of
# metres across, a share of the sea that hardly followed the wind); 3: the crests stored once
# where the sea is not flat, and the trail reads them (it evaluated them again per step, over
# every point: a third of the sea's evaluation beyond the Ocean modifier's); 4: the UV map follows
# the points where they are drawn (it kept their rest place: on a crest folded over, a sliver of a
# triangle spans metres of it, and software EEVEE's mipmapped bump reads there took minutes, issue
# 57 point 1)
VERSION = 4
CREST_ATTRIBUTE = "water_crest"  # the crests (0 to 1) before their trail, stored for it to read
REST_ATTRIBUTE = "water_rest"
OCEAN_FOAM_ATTRIBUTE = "water_ocean_foam"  # the Ocean modifier's foam layer (version 1 read it)
WHITECAPS_ATTRIBUTE = "water_whitecaps"
CREST_SHARE = 0.5
UV_MAP = "UVMap"
UV_METRES = 128.0  # UV = position / UV_METRES + 0.5: the seeds' ocean plane, the bump's taps tile the same

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
            ("middle_points:Selection", f"share_{i}:Geometry"),
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

# The trail: a crest's foam stays behind it and fades. A point the crest left k steps ago is
# marked where the crest stands now, k Trail Steps downwind; it keeps TRAIL_FADE^k of the mark.
# The sea's mesh is a grid (`water/grid.py`: index = row x n + column) evenly spaced in its
# middle, so "k steps downwind" is an index offset: no search.
TRAIL_STEPS = 3
TRAIL_SECONDS = 0.5
TRAIL_FADE = 0.6  # per step: about a second and a half to a fifth


def _trail():
    """Nodes and links: the crest mark, or the faded marks of the crests that passed, whichever
    is more. Returns (nodes, links, the result's socket)."""
    column = 9 + 2 * BISECTION_STEPS
    nodes = {
        "count": Node("GeometryNodeAttributeDomainSize", column, {"component": "MESH"}, label="points"),
        "side": math("SQRT", column, "n = points a side"),
        "side_round": math("ROUND", column + 1, "n"),
        "middle_index": math("MULTIPLY_ADD", column + 1, "(points - 1) / 2: the centre", b=0.5, c=-0.5),
        "next_index": math("ADD", column + 2, "its neighbour", b=1.0),
        "at_middle": Node(
            "GeometryNodeSampleIndex",
            column + 2,
            {"data_type": "FLOAT_VECTOR", "domain": "POINT"},
            label="rest",
        ),
        "at_next": Node(
            "GeometryNodeSampleIndex",
            column + 2,
            {"data_type": "FLOAT_VECTOR", "domain": "POINT"},
            label="rest",
        ),
        "spacing": vmath("DISTANCE", column + 3, "the middle's spacing"),
        "step_split": Node("ShaderNodeSeparateXYZ", column + 3, label="Trail Step"),
        "cols": math("DIVIDE", column + 4, "columns"),
        "rows": math("DIVIDE", column + 4, "rows"),
        "cols_round": math("ROUND", column + 5, "columns"),
        "rows_round": math("ROUND", column + 5, "rows"),
        "shift": math("MULTIPLY_ADD", column + 6, "index shift: rows n + columns"),
        "index": Node("GeometryNodeInputIndex", column + 6),
    }
    links = [
        ("input:Geometry", "count:Geometry"),
        ("count:Point Count", "side:#0"),
        ("side:Value", "side_round:#0"),
        ("count:Point Count", "middle_index:#0"),
        ("middle_index:Value", "next_index:#0"),
        ("input:Geometry", "at_middle:Geometry"),
        ("rest:Attribute", "at_middle:Value"),
        ("middle_index:Value", "at_middle:Index"),
        ("input:Geometry", "at_next:Geometry"),
        ("rest:Attribute", "at_next:Value"),
        ("next_index:Value", "at_next:Index"),
        ("at_middle:Value", "spacing:#0"),
        ("at_next:Value", "spacing:#1"),
        ("input:Trail Step", "step_split:Vector"),
        ("step_split:X", "cols:#0"),
        ("spacing:Value", "cols:#1"),
        ("step_split:Y", "rows:#0"),
        ("spacing:Value", "rows:#1"),
        ("cols:Value", "cols_round:#0"),
        ("rows:Value", "rows_round:#0"),
        ("rows_round:Value", "shift:#0"),
        ("side_round:Value", "shift:#1"),
        ("cols_round:Value", "shift:#2"),
    ]
    kept = "crest_read:Attribute"
    for k in range(1, TRAIL_STEPS + 1):
        nodes[f"trail_index_{k}"] = math("MULTIPLY_ADD", column + 7, f"index + {k} shift", a=float(k))
        nodes[f"trail_mark_{k}"] = Node(
            "GeometryNodeSampleIndex",
            column + 8,
            {"data_type": "FLOAT", "domain": "POINT", "clamp": True},
            label=f"the mark {k} steps downwind",
        )
        nodes[f"trail_fade_{k}"] = math("MULTIPLY", column + 9, f"x {TRAIL_FADE:g}^{k}", b=TRAIL_FADE**k)
        nodes[f"trail_{k}"] = math("MAXIMUM", column + 10, "the more")
        links += [
            ("shift:Value", f"trail_index_{k}:#1"),
            ("index:Index", f"trail_index_{k}:#2"),
            ("crests:Geometry", f"trail_mark_{k}:Geometry"),
            ("crest_read:Attribute", f"trail_mark_{k}:Value"),
            (f"trail_index_{k}:Value", f"trail_mark_{k}:Index"),
            (f"trail_mark_{k}:Value", f"trail_fade_{k}:#0"),
            (kept, f"trail_{k}:#0"),
            (f"trail_fade_{k}:Value", f"trail_{k}:#1"),
        ]
        kept = f"trail_{k}:Value"
    return nodes, tuple(links), kept


_TRAIL_NODES, _TRAIL_LINKS, _TRAIL = _trail()

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
        Socket(
            "Trail Step",
            "NodeSocketVector",
            (0.0, 0.0, 0.0),
            subtype="TRANSLATION",
            tooltip=f"How far the crests run in {TRAIL_SECONDS:g} s (along the wind; the add-on sets it): "
            "the foam they leave behind fades over the next few such steps",
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
        # The statistics read the middle's points only (a twentieth of the sea's, or fewer).
        "middle_points": Node("GeometryNodeSeparateGeometry", 4, {"domain": "POINT"}, label="the middle"),
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
        **_TRAIL_NODES,
        "offset": vmath("SUBTRACT", 2, "displacement"),
        "kept": vmath("SCALE", 4, "displacement kept"),
        "placed": vmath("ADD", 5, "rest + kept"),
        "whitecaps": math("MULTIPLY", 4, "foam faded"),
        # The crests are computed once, and only where the sea is not flat (near > 0): the trail
        # reads them back at other points; far out the whitecaps stay 0 (a new attribute's).
        "waving": math("GREATER_THAN", 4, "not flat (near > 0)"),
        "crests": Node(
            "GeometryNodeStoreNamedAttribute",
            5,
            {"data_type": "FLOAT", "domain": "POINT"},
            {"Name": CREST_ATTRIBUTE},
            label=f"store the crests ('{CREST_ATTRIBUTE}')",
        ),
        "crest_read": Node(
            "GeometryNodeInputNamedAttribute",
            5,
            {"data_type": "FLOAT"},
            {"Name": CREST_ATTRIBUTE},
            label="the crests, stored",
        ),
        "move": Node("GeometryNodeSetPosition", 6),
        "store": Node(
            "GeometryNodeStoreNamedAttribute",
            7,
            {"data_type": "FLOAT", "domain": "POINT"},
            {"Name": WHITECAPS_ATTRIBUTE},
            label=f"store '{WHITECAPS_ATTRIBUTE}'",
        ),
        # The UV map where the points are drawn: its slope across the screen stays the surface's
        # own, however far the chop folds a crest over (the bump's reads, `ocean_normal.py`).
        "drawn_uv": vmath(
            "MULTIPLY_ADD",
            6,
            "position / UV_METRES + 0.5",
            b=(1.0 / UV_METRES, 1.0 / UV_METRES, 0.0),
            c=(0.5, 0.5, 0.0),
        ),
        "store_uv": Node(
            "GeometryNodeStoreNamedAttribute",
            8,
            {"data_type": "FLOAT2", "domain": "CORNER"},
            {"Name": UV_MAP},
            label=f"store '{UV_MAP}' where drawn",
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
        ("input:Geometry", "middle_points:Geometry"),
        ("middle:Value", "middle_points:Selection"),
        ("middle_points:Selection", "stats:Geometry"),
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
        *_TRAIL_LINKS,
        (_TRAIL, "whitecaps:#0"),
        ("near:Result", "whitecaps:#1"),
        ("near:Result", "waving:#0"),
        ("input:Geometry", "crests:Geometry"),
        ("waving:Value", "crests:Selection"),
        ("crest:Result", "crests:Value"),
        ("crests:Geometry", "move:Geometry"),
        ("placed:Vector", "move:Position"),
        ("move:Geometry", "store:Geometry"),
        ("waving:Value", "store:Selection"),
        ("whitecaps:Value", "store:Value"),
        ("placed:Vector", "drawn_uv:#0"),
        ("store:Geometry", "store_uv:Geometry"),
        ("drawn_uv:Vector", "store_uv:Value"),
        ("store_uv:Geometry", "output:Geometry"),
    ),
    tree_type="GeometryNodeTree",
)
