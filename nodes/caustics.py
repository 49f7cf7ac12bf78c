"""`Water Surface Caustics`: the sun's light focused by the ripples onto what the water shows below.

Nested in `Water Surface`, which multiplies what its refraction shows by the `Factor` this group
returns (so the user's own materials are never touched, and EEVEE and Cycles get the same
pattern: see the README). Per pixel, in world space (`eye` = Geometry > Incoming, N = the
geometric normal, d = `water_depth`):

* the view ray bends into the water (Snell, IOR 1.33) and reaches the bed at `d / cos_v`
  along it (d taken as at most OFFSET_DEPTH here: the pattern has faded out by then, and the
  1000 m of "nothing below" would make the tile's texture filtering crawl); from there the
  sunlight came down along the sun's refracted direction `r_s`, so it crossed the surface
  `d / cos_s` back up along `r_s`. The sum of the two
  offsets, brought into the water's object space (Vector Transform) and divided by
  `water_uv_size` (metres per UV unit, stored by the surroundings), is the UV offset
  from this point of the surface to where the bed's light came through;
* there the caustic tile (`caustics_map.py`: light refracted through the bump map's own
  surface, mean 1) is read at the bump's scrolled, wind-aligned UV, divided by
  `Caustics Scale`, so the pattern moves with the ripples and stands still without wind;
* the contrast is `k = Caustics * Sun Lit * sun * fade_in(d) * exp(-d / FADE_DEPTH) * T_sun`,
  with `Sun Lit` 0 when no sun lights the scene (driven by the material) and `sun` 0 for a sun at
  or below the water's horizon, `fade_in` rising over the first
  FADE_IN metres (no focusing at the waterline or on dry ground) and `T_sun =
  exp(-Absorption * d / cos_s)` per channel, the sunlight the water lets through on its way
  down; `Factor = max(1 + k (c - 1), 0)`. It is 1 (no change) with Caustics 0, with no sun,
  without surroundings (d reads 0) and where nothing is below (d is 1000 m).

The tile's mean is 1, so the light is moved around, not added (exact for Caustics <= 1).
"""

import math as _math

from . import bump_uv, caustics_map, wind_frame
from .physics import WATER_IOR
from .spec import CAUSTICS_IMAGE, GroupSpec, Node, Socket, attribute, group_node, math, pass_inputs, vmath

NAME = "Water Surface Caustics"
VERSION = 1
IOR = WATER_IOR
FADE_IN = 0.3  # metres: the ripples need some depth to focus the light
FADE_DEPTH = 8.0  # metres: deeper, the lines blur and the pattern fades (1 / e at this depth)
MIN_COS = 0.05  # grazing rays: offsets capped at 20 depths
OFFSET_DEPTH = 3 * FADE_DEPTH  # metres: deeper beds are looked up as if this deep (the pattern is
# gone by then); huge offsets (1000 m where nothing is below) make the tile's filtering crawl
STRENGTH_MAX = 4.0
SCALE_RANGE = (0.05, 100.0)  # a script can set a socket past its limits: the group keeps to these
DEPTH_ATTRIBUTE = "water_depth"
UV_SIZE_ATTRIBUTE = "water_uv_size"

CAUSTICS_INPUT = Socket(
    "Caustics",
    "NodeSocketFloat",
    0.0,
    min=0.0,
    max=STRENGTH_MAX,
    tooltip="Sunlight focused by the ripples onto what lies under the water (0 = none; needs the "
    "surroundings and a sun; above 1 the pattern is clipped and adds light)",
)
CAUSTICS_SCALE_INPUT = Socket(
    "Caustics Scale",
    "NodeSocketFloat",
    1.0,
    min=SCALE_RANGE[0],
    max=SCALE_RANGE[1],
    tooltip="Size of the caustic pattern relative to the bump's ripples (2 = twice as large)",
)
SUN_LIT_INPUT = Socket(
    "Sun Lit",
    "NodeSocketFloat",
    1.0,
    min=0.0,
    max=1.0,
    subtype="FACTOR",
    tooltip="1 while the followed sun lights the scene, 0 without one (no caustics); the material "
    "drives it from the sun's render visibility",
)
INPUTS = (
    Socket("Vector", "NodeSocketVector", tooltip="The bump's scrolled, tiled UV here", hide_value=True),
    bump_uv.SCROLL_INPUTS[0],  # Wave Length
    bump_uv.SCROLL_INPUTS[1],  # Wind Direction
    Socket("Sun Direction", "NodeSocketVector", (0.0, 0.0, -1.0), subtype="DIRECTION"),
    Socket("Absorption", "NodeSocketColor", (0.0, 0.0, 0.0, 1.0)),
    CAUSTICS_INPUT,
    CAUSTICS_SCALE_INPUT,
    SUN_LIT_INPUT,
)


def feed(node, vector):
    """The links into a nested caustics group node `node`: `vector` (the bump's scrolled UV) and
    the enclosing group's inputs of the same names (the lake's and the ocean's have them all)."""
    return ((vector, f"{node}:Vector"), *pass_inputs(node, [socket.name for socket in INPUTS[1:]]))


def _view_nodes():
    """The view ray, refracted into the water and down to the bed (its depth capped for the offset)."""
    eta = 1.0 / IOR
    nodes = {
        "geometry": Node("ShaderNodeNewGeometry", 1),
        "depth": attribute(DEPTH_ATTRIBUTE, 1, "d = water_depth (m)"),
        "uv_size": attribute(UV_SIZE_ATTRIBUTE, 1, "water_uv_size (m)"),
        # The view ray, into the water and down to the bed.
        "view": vmath("SCALE", 2, "view ray = -eye", scale=-1.0),
        "r_v": vmath("REFRACT", 3, f"r_v = refract(view, N, 1/{IOR})", scale=eta),
        "cos_v_raw": vmath("DOT_PRODUCT", 4, "r_v . N"),
        "cos_v": math("MULTIPLY", 5, "cos_v = -(r_v . N)", b=-1.0),
        "cos_v_safe": math("MAXIMUM", 6, f"max(, {MIN_COS})", b=MIN_COS),
        "d_near": math("MINIMUM", 2, f"min(d, {OFFSET_DEPTH:g} m)", b=OFFSET_DEPTH),
        "along_v": math("DIVIDE", 7, "d / cos_v"),
        "to_bed": vmath("SCALE", 8, "to the bed"),
    }
    links = [
        ("geometry:Incoming", "view:#0"),
        ("view:Vector", "r_v:#0"),
        ("geometry:True Normal", "r_v:#1"),
        ("r_v:Vector", "cos_v_raw:#0"),
        ("geometry:True Normal", "cos_v_raw:#1"),
        ("cos_v_raw:Value", "cos_v:#0"),
        ("cos_v:Value", "cos_v_safe:#0"),
        ("depth:Fac", "d_near:#0"),
        ("d_near:Value", "along_v:#0"),
        ("cos_v_safe:Value", "along_v:#1"),
        ("r_v:Vector", "to_bed:#0"),
        ("along_v:Value", "to_bed:Scale"),
    ]
    return nodes, links


def _sun_nodes():
    """The sunlight, refracted in, and back up from the bed to where it came through: the offset in UV."""
    eta = 1.0 / IOR
    nodes = {
        # The sunlight, into the water; back up from the bed to where it came through.
        "sun": vmath("NORMALIZE", 2, "L"),
        "r_s": vmath("REFRACT", 3, f"r_s = refract(L, N, 1/{IOR})", scale=eta),
        "sun_up_raw": vmath("DOT_PRODUCT", 3, "L . N"),
        "sun_up": math("MULTIPLY", 4, "sun height = -(L . N)", b=-1.0),
        "sun_on": Node(
            "ShaderNodeMapRange",
            5,
            {"interpolation_type": "SMOOTHSTEP", "clamp": True},
            {1: 0.0, 2: 0.1, 3: 0.0, 4: 1.0},
            label="sun above the horizon",
        ),
        "cos_s_raw": vmath("DOT_PRODUCT", 4, "r_s . N"),
        "cos_s": math("MULTIPLY", 5, "cos_s = -(r_s . N)", b=-1.0),
        "cos_s_safe": math("MAXIMUM", 6, f"max(, {MIN_COS})", b=MIN_COS),
        "along_s": math("DIVIDE", 7, "d / cos_s"),
        "sun_path": math("DIVIDE", 7, "sunlight's way down: d / cos_s"),
        "back_s": math("MULTIPLY", 8, "back up: -d / cos_s", b=-1.0),
        "from_sun": vmath("SCALE", 9, "back along r_s"),
        "offset": vmath("ADD", 10, "bed point's light came through here + offset"),
        "offset_object": Node(
            "ShaderNodeVectorTransform",
            11,
            {"vector_type": "VECTOR", "convert_from": "WORLD", "convert_to": "OBJECT"},
            label="in the water's space",
        ),
        "per_uv": math("DIVIDE", 11, "1 / water_uv_size (0 without)", a=1.0),
        "offset_uv": vmath("SCALE", 12, "in UV"),
    }
    links = [
        ("input:Sun Direction", "sun:#0"),
        ("sun:Vector", "r_s:#0"),
        ("geometry:True Normal", "r_s:#1"),
        ("sun:Vector", "sun_up_raw:#0"),
        ("geometry:True Normal", "sun_up_raw:#1"),
        ("sun_up_raw:Value", "sun_up:#0"),
        ("sun_up:Value", "sun_on:Value"),
        ("r_s:Vector", "cos_s_raw:#0"),
        ("geometry:True Normal", "cos_s_raw:#1"),
        ("cos_s_raw:Value", "cos_s:#0"),
        ("cos_s:Value", "cos_s_safe:#0"),
        ("d_near:Value", "along_s:#0"),
        ("cos_s_safe:Value", "along_s:#1"),
        ("depth:Fac", "sun_path:#0"),
        ("cos_s_safe:Value", "sun_path:#1"),
        ("along_s:Value", "back_s:#0"),
        ("r_s:Vector", "from_sun:#0"),
        ("back_s:Value", "from_sun:Scale"),
        ("to_bed:Vector", "offset:#0"),
        ("from_sun:Vector", "offset:#1"),
        ("offset:Vector", "offset_object:Vector"),
        ("uv_size:Fac", "per_uv:#1"),
        ("offset_object:Vector", "offset_uv:#0"),
        ("per_uv:Value", "offset_uv:Scale"),
    ]
    return nodes, links


def _tile_nodes():
    """The offset in the bump's wind frame and tiling, and the caustic tile read there."""
    nodes = {
        # Into the bump's wind frame and tiling, as `Water Surface Bump UV` does.
        "frame": group_node(wind_frame.NAME, 11),
        "du": vmath("DOT_PRODUCT", 13, "offset . p"),
        "dv": vmath("DOT_PRODUCT", 13, "offset . w"),
        "duv": Node("ShaderNodeCombineXYZ", 14, label="wind-frame offset"),
        "per_length": math("DIVIDE", 14, "1 / Wave Length", a=1.0),
        "duv_tiled": vmath("SCALE", 15, "/ Wave Length"),
        "at": vmath("ADD", 16, "bump UV + offset"),
        "scale_safe": Node(
            "ShaderNodeClamp",
            15,
            {"clamp_type": "MINMAX"},
            {"Min": SCALE_RANGE[0], "Max": SCALE_RANGE[1]},
            label="Caustics Scale, kept in range",
        ),
        "per_scale": math("DIVIDE", 16, "1 / Caustics Scale", a=1.0),
        "scaled": vmath("SCALE", 17, "/ Caustics Scale"),
        "tile": Node(
            "ShaderNodeTexImage",
            18,
            {"extension": "MIRROR", "interpolation": "Linear", "image": CAUSTICS_IMAGE},
            label="caustic tile (mirror, as the bump)",
        ),
        "c_minus_1": math(
            "MULTIPLY_ADD", 19, f"c - 1 = tile x {caustics_map.PEAK:g} - 1", b=caustics_map.PEAK, c=-1.0
        ),
    }
    links = [
        ("input:Wind Direction", "frame:Wind Direction"),
        ("offset_uv:Vector", "du:#0"),
        ("frame:Across", "du:#1"),
        ("offset_uv:Vector", "dv:#0"),
        ("frame:Wind", "dv:#1"),
        ("du:Value", "duv:X"),
        ("dv:Value", "duv:Y"),
        ("input:Wave Length", "per_length:#1"),
        ("duv:Vector", "duv_tiled:#0"),
        ("per_length:Value", "duv_tiled:Scale"),
        ("input:Vector", "at:#0"),
        ("duv_tiled:Vector", "at:#1"),
        ("input:Caustics Scale", "scale_safe:Value"),
        ("scale_safe:Result", "per_scale:#1"),
        ("at:Vector", "scaled:#0"),
        ("per_scale:Value", "scaled:Scale"),
        ("scaled:Vector", "tile:Vector"),
        ("tile:Color", "c_minus_1:#0"),
    ]
    return nodes, links


def _contrast_nodes():
    """The contrast (faded in and out with depth, x the sun's height, its T per channel) and the factor."""
    nodes = {
        # The contrast: fades in over the first FADE_IN m, out with depth, and with the sun's T.
        "fade_in": Node(
            "ShaderNodeMapRange",
            8,
            {"interpolation_type": "SMOOTHSTEP", "clamp": True},
            {1: 0.0, 2: FADE_IN, 3: 0.0, 4: 1.0},
            label=f"fade in over {FADE_IN:g} m",
        ),
        "fade_out": math("POWER", 8, f"exp(-d / {FADE_DEPTH:g})", a=_math.exp(-1.0 / FADE_DEPTH)),
        "strength": Node(
            "ShaderNodeClamp",
            7,
            {"clamp_type": "MINMAX"},
            {"Min": 0.0, "Max": STRENGTH_MAX},
            label="Caustics, kept in range",
        ),
        "lit": math("MULTIPLY", 8, "Caustics x Sun Lit"),
        "k_sun": math("MULTIPLY", 9, "x sun above the horizon"),
        "k_in": math("MULTIPLY", 10, "x fade in"),
        "k": math("MULTIPLY", 11, "x fade out"),
        "optical": vmath("SCALE", 9, "Absorption x d / cos_s"),
        "optical_xyz": Node("ShaderNodeSeparateXYZ", 10, label="per channel"),
        **{f"t_sun_{c}": math("POWER", 11, f"T_sun.{c}", a=_math.exp(-1.0)) for c in "xyz"},
        "t_sun": Node("ShaderNodeCombineXYZ", 12, label="T_sun"),
        "k_rgb": vmath("SCALE", 13, "k per channel"),
        "factor_raw": vmath("MULTIPLY_ADD", 20, "1 + k (c - 1)", c=(1.0, 1.0, 1.0)),
        "factor": vmath("MAXIMUM", 21, "at least 0", b=(0.0, 0.0, 0.0)),
    }
    links = [
        ("depth:Fac", "fade_in:Value"),
        ("depth:Fac", "fade_out:#1"),
        ("input:Caustics", "strength:Value"),
        ("strength:Result", "lit:#0"),
        ("input:Sun Lit", "lit:#1"),
        ("lit:Value", "k_sun:#0"),
        ("sun_on:Result", "k_sun:#1"),
        ("k_sun:Value", "k_in:#0"),
        ("fade_in:Result", "k_in:#1"),
        ("k_in:Value", "k:#0"),
        ("fade_out:Value", "k:#1"),
        ("input:Absorption", "optical:#0"),
        ("sun_path:Value", "optical:Scale"),
        ("optical:Vector", "optical_xyz:Vector"),
    ]
    for c in "xyz":
        links += [(f"optical_xyz:{c.upper()}", f"t_sun_{c}:#1"), (f"t_sun_{c}:Value", f"t_sun:{c.upper()}")]
    links += [
        ("t_sun:Vector", "k_rgb:#0"),
        ("k:Value", "k_rgb:Scale"),
        ("k_rgb:Vector", "factor_raw:#0"),
        ("c_minus_1:Value", "factor_raw:#1"),
        ("factor_raw:Vector", "factor:#0"),
        ("factor:Vector", "output:Factor"),
    ]
    return nodes, links


def _nodes():
    """The caustics' nodes and links: the ray to the bed, the sunlight back up, the tile read there."""
    nodes, links = {}, []
    for more_nodes, more_links in (_view_nodes(), _sun_nodes(), _tile_nodes(), _contrast_nodes()):
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes, links = nodes | more_nodes, links + list(more_links)
    return nodes, tuple(links)


_NODES, _LINKS = _nodes()

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description="Caustics: the caustic tile read where the bed's sunlight came through the surface; "
    "the factor on what the water shows below",
    inputs=INPUTS,
    outputs=(
        Socket(
            "Factor",
            "NodeSocketVector",
            tooltip="Per channel: what is seen through the water is multiplied by this (1 = no change)",
        ),
    ),
    nodes=_NODES,
    links=_LINKS,
)
