"""The ocean's shading (SPEC section 2, pixel part), as two shader groups.

`Water Ocean Normal` perturbs the wave normal (the `water_normal` attribute the
`Water Waves` modifier stores, or the surface normal without it) by three taps
of the bump map and gives the direction the eye reflects into. The shade's "+ Traced Sky"
variant, every new material's, has the renderer reflect the world there with a Glossy closure, so
the sea shows whatever world the scene has now; at `Traced Sky` 0 the material looks the sky up
in that direction as the seeds do (the world's environment image, or its colour, as they were
when it was made) and hands it to `Water Ocean Shade`:
`F = dot(-eye, n) / 2 + 0.5`, `deep * F + sky * (1 - F) + pow(mean(sky), Glint Power)`,
unlit, as the seeds draw it. Where the mesh carries crest foam (the open sea's
`water_whitecaps`, `sea_fade.py`) whitecaps break out as white foam lit by the scene, in
compact patches metres across drawn out along a strong wind; past the sea's fade, where the flat far mesh
marks no crests, as many whitecaps are spread over the sea at random, so a gale's foam reaches
the horizon.

With the surroundings' attributes (`water_depth`, `water_shore_distance`, `water_surroundings`,
as on the lake), the lake's rules apply: the bed is seen through the water at
`T = exp(-Absorption x path)` (`water_surface.transmittance_nodes`), refracted and lit by the
caustics (`caustics.py`; a part, built in only while `Caustics` is above 0), and the deep colour
takes the rest, `deep (1 - T)`; the shore foam is
the lake's coverage, whichever of it and the whitecaps covers more. Without the attributes
`T` is 0 and the foam 0: the seeds' ocean exactly.
Two groups, because a shader group cannot hold the
world's image: the lookup sits between them in the material.
"""

from dataclasses import replace

from . import bump_uv, caustics, foam_map, rough_fresnel, sea_fade, underside, water_surface
from .bump_uv import TIME_INPUT
from .spec import (
    BUMP_IMAGE,
    ROUGH_FRESNEL_IMAGE,
    GroupSpec,
    Node,
    Part,
    Socket,
    attribute,
    group_node,
    math,
    pass_inputs,
    vmath,
)
from .water_waves import NORMAL_ATTRIBUTE

NORMAL_NAME = "Water Ocean Normal"
SHADE_NAME = "Water Ocean Shade"
DEEP_BLUE = (0.0, 0.2, 0.4, 1.0)
WHITECAPS_MAX = 4.0
# Which water a whitecap covers: round spots, one a cell of WHITECAP_BLOB_TILE metres along and
# across the wind, at random in it (Voronoi), each of its own size and its edge ragged by the
# foam tile (`_spots`): compact patches metres across, whole, as a breaking crest's foam is. (A
# read of the foam tile itself picked its three octaves' bubble middles: rows of dashes a pixel
# wide, 0.1 m^2 at the median, issue 58.) The foam tile, read at WHITECAP_TILE, laces them.
WHITECAP_BLOB_TILE = (12.0, 10.0)
WHITECAP_TILE = (12.0, 6.0)
# The foam drawn out along the wind by `Foam Streaks` a: the lace's tile (12 a, 6 / a) metres and
# the spots' cells a^0.42 longer and narrower, so from Beaufort 7 the whitecaps' foam lies in broad
# streaks along the wind (a typical piece 5 times as long as wide, 0.5 m or more across). The open
# sea drives a from its wind (`whitecap_math.streaks`).
STREAKS_INPUT = "Foam Streaks"
STREAKS_MAX = 8.0
BLOB_STRETCH_POWER = 0.42
WHITECAP_BLOB_SOFTNESS = 0.01
# f inside a whitecap: over 1 + SOFTNESS / 2 the lace leaves only its darkest few per cent open,
# so a whitecap stays one patch (a thinner lace split it into specks a pixel wide).
WHITECAP_FOAM = 1.2
LACE_COVER = min(1.0, WHITECAP_FOAM - foam_map.SOFTNESS / 2)
SPOT_RAG = 0.4  # a spot's edge: B (1 + e (R - 1/2)), R the foam tile read 37 by 53 m
# The crest's mark (1 on the crest, TRAIL_FADE^k k trail steps behind it) raised to MARK_POWER:
# the foam a crest leaves stays whole, shrinking a little as it ages (`sea_fade.py`).
MARK_POWER = 0.1
# The spots' share per share of the sea asked: 1 / (crest share x lace cover x how much more
# of the sea the crests and the foam they leave behind mark, seen from above), the last measured
# (tests/test_whitecaps.py).
WHITECAP_SEEN = 1.59
WHITECAP_BLOB_GAIN = 1.0 / (sea_fade.CREST_SHARE * LACE_COVER * WHITECAP_SEEN)


def _tile_read(key, tile, column, label, interpolation="Linear"):
    """Nodes reading the foam tile at (along, across) / `tile` metres: `{key}_tile:Color`."""
    return {
        f"{key}_u": math("DIVIDE", column, "along / length", b=tile[0]),
        f"{key}_v": math("DIVIDE", column, "across / width", b=tile[1]),
        f"{key}_uv": Node("ShaderNodeCombineXYZ", column + 1),
        f"{key}_tile": water_surface.foam_tile(column + 2, label, interpolation),
    }


def _spots(key, tile, column, label):
    """Nodes making an evenly spread value from round spots, one a (along, across) / `tile` cell:
    Voronoi's nearest-point distance d, as 1 - exp(-pi d^2) (even for points one a cell at
    random), so `{key}_even < s` covers s of the sea in compact spots. `{key}_even:Value`."""
    return {
        f"{key}_u": math("DIVIDE", column, "along / length", b=tile[0]),
        f"{key}_v": math("DIVIDE", column, "across / width", b=tile[1]),
        f"{key}_uv": Node("ShaderNodeCombineXYZ", column + 1),
        f"{key}_tile": Node(
            "ShaderNodeTexVoronoi",
            column + 2,
            {"voronoi_dimensions": "2D", "feature": "F1", "distance": "EUCLIDEAN"},
            {"Scale": 1.0, "Randomness": 1.0},
            label=label,
        ),
        f"{key}_size": math("MULTIPLY_ADD", column + 3, "its size: 1/2 + the cell's grey", b=1.0, c=0.5),
        f"{key}_rel": math("DIVIDE", column + 3, "d / size"),
        f"{key}_sq": math("POWER", column + 3, "d^2", b=2.0),
        f"{key}_neg": math("MULTIPLY", column + 3, "-pi d^2", b=-3.141592653589793),
        f"{key}_exp": math("EXPONENT", column + 3, "exp(-pi d^2)"),
        f"{key}_even": math("SUBTRACT", column + 3, "1 - exp(-pi d^2): even", a=1.0),
    }


def _spot_links(key):
    return (
        *_tile_links(key),
        (f"{key}_tile:Color", f"{key}_size:#0"),
        (f"{key}_tile:Distance", f"{key}_rel:#0"),
        (f"{key}_size:Value", f"{key}_rel:#1"),
        (f"{key}_rel:Value", f"{key}_sq:#0"),
        (f"{key}_sq:Value", f"{key}_neg:#0"),
        (f"{key}_neg:Value", f"{key}_exp:#0"),
        (f"{key}_exp:Value", f"{key}_even:#1"),
    )


def _bubble(label):
    """A whitecap's bubble from `share - B`: 0 outside, 1 inside, over WHITECAP_BLOB_SOFTNESS."""
    return Node(
        "ShaderNodeMapRange",
        30,
        {"interpolation_type": "LINEAR", "clamp": True},
        {1: -WHITECAP_BLOB_SOFTNESS / 2, 2: WHITECAP_BLOB_SOFTNESS / 2, 3: 0.0, 4: 1.0},
        label=label,
    )


def _tile_links(key):
    return (
        ("cap_along:Value", f"{key}_u:#0"),
        ("cap_across:Value", f"{key}_v:#0"),
        (f"{key}_u:Value", f"{key}_uv:X"),
        (f"{key}_v:Value", f"{key}_uv:Y"),
        (f"{key}_uv:Vector", f"{key}_tile:Vector"),
    )


FOAM_WHITE = (0.85, 0.87, 0.88)


# The three taps' slopes at Bump Strength 1, along the grid's x and y: mean squares and their
# mean product (measured straight down at 5 cm a pixel on the open sea, six 12.8 m patches). The
# seeds read the second tap at (v, u) without swapping its tilt, so its ripples mirror the
# first's across the diagonal and the slopes lean along it (correlation 0.53).
BUMP_SLOPE_COVARIANCE = ((0.01287, 0.00700), (0.00700, 0.01368))


def _inverse_square_root(matrix):
    """M with M C M = I for a symmetric positive 2x2 C: the slopes, multiplied by M, have unit
    mean squares and no correlation."""
    (a, b), (_b, d) = matrix
    half_trace, root = (a + d) / 2, ((a - d) ** 2 / 4 + b * b) ** 0.5
    values = (half_trace + root, half_trace - root)
    # Eigenvectors (b, l - a); for b = 0 the axes themselves.
    vectors = [
        (b, value - a) if b else ((1.0, 0.0) if i == 0 else (0.0, 1.0)) for i, value in enumerate(values)
    ]
    result = [[0.0, 0.0], [0.0, 0.0]]
    for value, (x, y) in zip(values, vectors, strict=True):
        length = (x * x + y * y) ** 0.5
        x, y = x / length, y / length
        for i, p in enumerate((x, y)):
            for j, q in enumerate((x, y)):
                result[i][j] += p * q / value**0.5
    return result


WHITEN = _inverse_square_root(BUMP_SLOPE_COVARIANCE)


# The far sea's whitecaps: past the sea's fade the mesh marks no crests, so there the shade picks
# bubbles of the share the crests and the foam they leave would cover, s x crest share x seen,
# that is the share asked over the lace's cover, everywhere: the same foam on average, to the
# horizon. A group left undriven (the seeds' ocean) fades only past FADE_NEVER metres.
FADE_START_INPUT = "Fade Start"
FADE_END_INPUT = "Fade End"
FADE_NEVER = 1.0e6
FAR_CAP_GAIN = 1.0 / LACE_COVER
# The far bubbles are where either of two reads of the tile, B and B2, is low (min(B, B2) < t,
# t = 1 - sqrt(1 - share)): one read alone repeats every tile width across the wind, long
# parallel stripes seen from high up; B2's tile is drawn other ways (along and across the wind,
# no simple ratio to B's), so the two together repeat nowhere in sight.
FAR_SECOND_READ = (1.27, 0.79)
PICK_TILE = (37.0, 53.0)  # metres across and along the wind: no multiple of the other reads

UNRESOLVED_SLOPE = "Unresolved Slope"
# Toksvig's measure on the three reads (`rough_fresnel.py`): a read of averaged normals is shorter,
# 1 - |2c - 1|^2; its mean over the taps, from the floor of a sharp read to the whole tile's,
# is the share r of the slopes lost; they were (k_along^2 + k_across^2) / 2 each way, times the
# taps' own mean square where they are combined as the seeds do (Even Slopes 0).
_LOST_SCALE = (rough_fresnel.LOST_FULL - rough_fresnel.LOST_FLOOR) ** -1
_UNRESOLVED_NODES = {
    **{f"off_{i}": vmath("ADD", 9, f"tap {i} - 0.5", b=(-0.5, -0.5, -0.5)) for i in (1, 2, 3)},
    **{f"len_{i}": vmath("DOT_PRODUCT", 10, f"|tap {i} - 0.5|^2") for i in (1, 2, 3)},
    "len_12": math("ADD", 11),
    "len_123": math("ADD", 12, "sum of |tap - 0.5|^2"),
    "lost_share": math(
        "MULTIPLY_ADD",
        13,
        "r: share of the slopes lost",
        clamp=True,
        b=-4.0 / 3.0 * _LOST_SCALE,
        c=(1.0 - rough_fresnel.LOST_FLOOR) * _LOST_SCALE,
    ),
    "k2_along": math("MULTIPLY", 11, "k_along^2"),
    "k2_across": math("MULTIPLY", 11, "k_across^2"),
    "k2_sum": math("ADD", 12),
    "even_share": math(
        "MULTIPLY_ADD",
        12,
        "half the taps' mean square",
        b=(1.0 - rough_fresnel.SEEDS_SLOPE_VARIANCE) / 2.0,
        c=rough_fresnel.SEEDS_SLOPE_VARIANCE / 2.0,
    ),
    "full_slope": math("MULTIPLY", 13, "the bump's mean square slope each way"),
    "lost_slope": math("MULTIPLY", 14, "lost mean square slope"),
}
_UNRESOLVED_LINKS = (
    *((f"tap_{i}:Color", f"off_{i}:#0") for i in (1, 2, 3)),
    *((f"off_{i}:Vector", f"len_{i}:#0") for i in (1, 2, 3)),
    *((f"off_{i}:Vector", f"len_{i}:#1") for i in (1, 2, 3)),
    ("len_1:Value", "len_12:#0"),
    ("len_2:Value", "len_12:#1"),
    ("len_12:Value", "len_123:#0"),
    ("len_3:Value", "len_123:#1"),
    ("len_123:Value", "lost_share:#0"),
    ("k_along:Value", "k2_along:#0"),
    ("k_along:Value", "k2_along:#1"),
    ("k_across:Value", "k2_across:#0"),
    ("k_across:Value", "k2_across:#1"),
    ("k2_along:Value", "k2_sum:#0"),
    ("k2_across:Value", "k2_sum:#1"),
    ("input:Even Slopes", "even_share:#0"),
    ("k2_sum:Value", "full_slope:#0"),
    ("even_share:Value", "full_slope:#1"),
    ("lost_share:Value", "lost_slope:#0"),
    ("full_slope:Value", "lost_slope:#1"),
    ("lost_slope:Value", f"output:{UNRESOLVED_SLOPE}"),
)


def _tap(key, column):
    return Node("ShaderNodeTexImage", column, {"extension": "REPEAT", "image": BUMP_IMAGE}, label=key)


NORMAL_SPEC = GroupSpec(
    name=NORMAL_NAME,
    # 2: a mesh without the attribute transforms +Z, never a zero vector: EEVEE before 5.x
    # normalises it into NaN, and the NaN, even weighted by 0, turned the whole ocean black.
    # 3: the slopes scale apart along and across the wind (the open sea's Cox and Munk slopes).
    # 4: `Unresolved Slope`, the slopes the taps' mipmaps averaged away (`rough_fresnel.py`).
    version=4,
    description="Wave normal plus three bump taps; the direction the eye reflects into",
    inputs=(
        Socket(
            "Bump Strength",
            "NodeSocketFloat",
            0.5,
            min=0.0,
            max=10.0,
            tooltip="Tilt of the three bump taps (the seeds' 0.5)",
        ),
        Socket(
            "Tex Stretch",
            "NodeSocketFloat",
            4.0,
            min=0.001,
            max=1000.0,
            tooltip="Bump taps per UV unit (the seeds' 4)",
        ),
        TIME_INPUT,
        Socket(
            "Wind Direction",
            "NodeSocketVector",
            (1.0, 0.0, 0.0),
            tooltip="The way the wind blows (x, y; the open sea drives it from its Ocean modifier): "
            "the bump's slopes along and across it scale apart",
        ),
        Socket(
            "Even Slopes",
            "NodeSocketFloat",
            0.0,
            min=0.0,
            max=1.0,
            subtype="FACTOR",
            tooltip="1: the taps' slopes made the same in every direction, a mean square of 1 each "
            "way, before the wind scales them (the open sea); 0: combined as the seeds do",
        ),
        Socket(
            "Slope Along Wind",
            "NodeSocketFloat",
            1.0,
            min=0.0,
            max=10.0,
            tooltip="The bump's slopes along the wind, times Bump Strength (the open sea drives it "
            "from the wind speed, as Cox and Munk measured the sea's slopes)",
        ),
        Socket(
            "Slope Across Wind",
            "NodeSocketFloat",
            1.0,
            min=0.0,
            max=10.0,
            tooltip="The bump's slopes across the wind, times Bump Strength",
        ),
    ),
    outputs=(
        Socket("Normal", "NodeSocketVector", tooltip="Shading normal n, world space"),
        Socket("Reflection", "NodeSocketVector", tooltip="reflect(eye, n): where the sky is looked up"),
        Socket(
            UNRESOLVED_SLOPE,
            "NodeSocketFloat",
            tooltip="Mean square slope each way the bump's reads lost to averaging (EEVEE's mipmaps "
            "far off; about 0 in Cycles): the shade gives back what those slopes reflect",
        ),
    ),
    nodes={
        # The wave normal, world space; the surface's own where the mesh has no attribute.
        "attribute": Node(
            "ShaderNodeAttribute", 1, {"attribute_name": NORMAL_ATTRIBUTE}, label="wave normal"
        ),
        "geometry": Node("ShaderNodeNewGeometry", 1),
        "coords": Node("ShaderNodeTexCoord", 1),
        "safe": vmath("MULTIPLY_ADD", 2, "attribute, or +Z without it", a=(0.0, 0.0, 1.0)),
        "to_world": Node(
            "ShaderNodeVectorTransform",
            2,
            {"vector_type": "NORMAL", "convert_from": "OBJECT", "convert_to": "WORLD"},
        ),
        "has_length": vmath("LENGTH", 2, "|attribute|"),
        "has": math("GREATER_THAN", 3, "stored?", b=0.5),
        "hasnt": math("SUBTRACT", 4, "1 - stored", a=1.0),
        "wave_part": vmath("SCALE", 5, "stored normal"),
        "geo_part": vmath("SCALE", 5, "surface normal"),
        "wave_sum": vmath("ADD", 6),
        "N": vmath("NORMALIZE", 7, "N"),
        # Three taps at the scrolled UV: uv + t / 50 * (-1, 0).
        "drift": math("MULTIPLY", 2, "-t / 50", b=-1.0 / 50.0),
        "drift_v": Node("ShaderNodeCombineXYZ", 3, label="(-t / 50, 0)"),
        "uv": vmath("ADD", 4, "scrolled uv"),
        "uv_split": Node("ShaderNodeSeparateXYZ", 5),
        "uv_swap": Node("ShaderNodeCombineXYZ", 6, label="uv.yx"),
        "stretch_2": math("MULTIPLY", 5, "1.8 stretch", b=1.8),
        "stretch_3": math("MULTIPLY", 5, "3.1 stretch", b=3.1),
        "uv_1": vmath("SCALE", 7, "stretch * uv"),
        "uv_2": vmath("SCALE", 7, "1.8 stretch * uv.yx"),
        "uv_3": vmath("SCALE", 7, "3.1 stretch * uv"),
        "tap_1": _tap("tap 1", 8),
        "tap_2": _tap("tap 2", 8),
        "tap_3": _tap("tap 3", 8),
        "sum_12": vmath("ADD", 9),
        "sum_123": vmath("ADD", 10),
        "centre": vmath("ADD", 11, "sum of (tap - 0.5)", b=(-1.5, -1.5, -1.5)),
        # The taps' tilt in the wind's frame, scaled along and across it, and back:
        # along = m . w, across = m . w_perp, each x Bump Strength x its Slope input.
        "m": Node("ShaderNodeSeparateXYZ", 11, label="m"),
        # Even slopes: m.xy + Even Slopes x (WHITEN - I) m.xy.
        "my_m12": math("MULTIPLY", 11, "m.y M12", b=WHITEN[0][1]),
        "mx_m12": math("MULTIPLY", 11, "m.x M12", b=WHITEN[0][1]),
        "dx": math("MULTIPLY_ADD", 12, "(M11 - 1) m.x + M12 m.y", b=WHITEN[0][0] - 1.0),
        "dy": math("MULTIPLY_ADD", 12, "(M22 - 1) m.y + M12 m.x", b=WHITEN[1][1] - 1.0),
        "ex": math("MULTIPLY_ADD", 12, "even x"),
        "ey": math("MULTIPLY_ADD", 12, "even y"),
        "wind": vmath("NORMALIZE", 9, "w"),
        "w": Node("ShaderNodeSeparateXYZ", 10, label="w"),
        "k_along": math("MULTIPLY", 10, "Bump Strength x Slope Along"),
        "k_across": math("MULTIPLY", 10, "Bump Strength x Slope Across"),
        "mx_wx": math("MULTIPLY", 12, "m.x w.x"),
        "along": math("MULTIPLY_ADD", 13, "m . w"),
        "my_wx": math("MULTIPLY", 12, "m.y w.x"),
        "mx_wy": math("MULTIPLY", 12, "m.x w.y"),
        "across": math("SUBTRACT", 13, "m . w_perp"),
        "along_s": math("MULTIPLY", 14, "along, scaled"),
        "across_s": math("MULTIPLY", 14, "across, scaled"),
        "minus_wy": math("MULTIPLY", 11, "-w.y", b=-1.0),
        "a_wx": math("MULTIPLY", 15, "along w.x"),
        "a_wy": math("MULTIPLY", 15, "along w.y"),
        "tilt_x": math("MULTIPLY_ADD", 16, "x = along w.x - across w.y"),
        "tilt_y": math("MULTIPLY_ADD", 16, "y = along w.y + across w.x"),
        "tilt": Node("ShaderNodeCombineXYZ", 17, label="tilt"),
        "t": vmath("NORMALIZE", 13, "tangent-space normal"),
        "t_split": Node("ShaderNodeSeparateXYZ", 14),
        # A tangent frame on the wave: B along +X, T = N x B.
        "N_split": Node("ShaderNodeSeparateXYZ", 8),
        "x_on_N": vmath("SCALE", 9, "N.x N"),
        "B_raw": vmath("SUBTRACT", 10, "X - N.x N", a=(1.0, 0.0, 0.0)),
        "B": vmath("NORMALIZE", 11, "B"),
        "T": vmath("CROSS_PRODUCT", 12, "T = N x B"),
        "along_B": vmath("SCALE", 15, "t.x B"),
        "along_T": vmath("SCALE", 15, "t.y T"),
        "along_N": vmath("SCALE", 15, "t.z N"),
        "n_BT": vmath("ADD", 16),
        "n_raw": vmath("ADD", 17),
        "n": vmath("NORMALIZE", 18, "n"),
        "eye": vmath("SCALE", 18, "eye = -incoming", scale=-1.0),
        "reflect": vmath("REFLECT", 19, "reflect(eye, n)"),
        **_UNRESOLVED_NODES,
    },
    links=(
        ("hasnt:Value", "safe:#1"),
        ("attribute:Vector", "safe:#2"),
        ("safe:Vector", "to_world:Vector"),
        ("attribute:Vector", "has_length:#0"),
        ("has_length:Value", "has:#0"),
        ("has:Value", "hasnt:#1"),
        ("to_world:Vector", "wave_part:#0"),
        ("has:Value", "wave_part:Scale"),
        ("geometry:Normal", "geo_part:#0"),
        ("hasnt:Value", "geo_part:Scale"),
        ("wave_part:Vector", "wave_sum:#0"),
        ("geo_part:Vector", "wave_sum:#1"),
        ("wave_sum:Vector", "N:#0"),
        ("input:Time", "drift:#0"),
        ("drift:Value", "drift_v:X"),
        ("coords:UV", "uv:#0"),
        ("drift_v:Vector", "uv:#1"),
        ("uv:Vector", "uv_split:Vector"),
        ("uv_split:Y", "uv_swap:X"),
        ("uv_split:X", "uv_swap:Y"),
        ("input:Tex Stretch", "stretch_2:#0"),
        ("input:Tex Stretch", "stretch_3:#0"),
        ("uv:Vector", "uv_1:#0"),
        ("input:Tex Stretch", "uv_1:Scale"),
        ("uv_swap:Vector", "uv_2:#0"),
        ("stretch_2:Value", "uv_2:Scale"),
        ("uv:Vector", "uv_3:#0"),
        ("stretch_3:Value", "uv_3:Scale"),
        ("uv_1:Vector", "tap_1:Vector"),
        ("uv_2:Vector", "tap_2:Vector"),
        ("uv_3:Vector", "tap_3:Vector"),
        ("tap_1:Color", "sum_12:#0"),
        ("tap_2:Color", "sum_12:#1"),
        ("sum_12:Vector", "sum_123:#0"),
        ("tap_3:Color", "sum_123:#1"),
        ("sum_123:Vector", "centre:#0"),
        ("centre:Vector", "m:Vector"),
        ("input:Wind Direction", "wind:#0"),
        ("wind:Vector", "w:Vector"),
        ("input:Bump Strength", "k_along:#0"),
        ("input:Slope Along Wind", "k_along:#1"),
        ("input:Bump Strength", "k_across:#0"),
        ("input:Slope Across Wind", "k_across:#1"),
        ("m:Y", "my_m12:#0"),
        ("m:X", "mx_m12:#0"),
        ("m:X", "dx:#0"),
        ("my_m12:Value", "dx:#2"),
        ("m:Y", "dy:#0"),
        ("mx_m12:Value", "dy:#2"),
        ("dx:Value", "ex:#0"),
        ("input:Even Slopes", "ex:#1"),
        ("m:X", "ex:#2"),
        ("dy:Value", "ey:#0"),
        ("input:Even Slopes", "ey:#1"),
        ("m:Y", "ey:#2"),
        ("ex:Value", "mx_wx:#0"),
        ("w:X", "mx_wx:#1"),
        ("ey:Value", "along:#0"),
        ("w:Y", "along:#1"),
        ("mx_wx:Value", "along:#2"),
        ("ey:Value", "my_wx:#0"),
        ("w:X", "my_wx:#1"),
        ("ex:Value", "mx_wy:#0"),
        ("w:Y", "mx_wy:#1"),
        ("my_wx:Value", "across:#0"),
        ("mx_wy:Value", "across:#1"),
        ("along:Value", "along_s:#0"),
        ("k_along:Value", "along_s:#1"),
        ("across:Value", "across_s:#0"),
        ("k_across:Value", "across_s:#1"),
        ("w:Y", "minus_wy:#0"),
        ("along_s:Value", "a_wx:#0"),
        ("w:X", "a_wx:#1"),
        ("along_s:Value", "a_wy:#0"),
        ("w:Y", "a_wy:#1"),
        ("across_s:Value", "tilt_x:#0"),
        ("minus_wy:Value", "tilt_x:#1"),
        ("a_wx:Value", "tilt_x:#2"),
        ("across_s:Value", "tilt_y:#0"),
        ("w:X", "tilt_y:#1"),
        ("a_wy:Value", "tilt_y:#2"),
        ("tilt_x:Value", "tilt:X"),
        ("tilt_y:Value", "tilt:Y"),
        ("m:Z", "tilt:Z"),
        ("tilt:Vector", "t:#0"),
        ("t:Vector", "t_split:Vector"),
        ("N:Vector", "N_split:Vector"),
        ("N:Vector", "x_on_N:#0"),
        ("N_split:X", "x_on_N:Scale"),
        ("x_on_N:Vector", "B_raw:#1"),
        ("B_raw:Vector", "B:#0"),
        ("N:Vector", "T:#0"),
        ("B:Vector", "T:#1"),
        ("B:Vector", "along_B:#0"),
        ("t_split:X", "along_B:Scale"),
        ("T:Vector", "along_T:#0"),
        ("t_split:Y", "along_T:Scale"),
        ("N:Vector", "along_N:#0"),
        ("t_split:Z", "along_N:Scale"),
        ("along_B:Vector", "n_BT:#0"),
        ("along_T:Vector", "n_BT:#1"),
        ("n_BT:Vector", "n_raw:#0"),
        ("along_N:Vector", "n_raw:#1"),
        ("n_raw:Vector", "n:#0"),
        ("geometry:Incoming", "eye:#0"),
        ("eye:Vector", "reflect:#0"),
        ("n:Vector", "reflect:#1"),
        ("n:Vector", "output:Normal"),
        ("reflect:Vector", "output:Reflection"),
        *_UNRESOLVED_LINKS,
    ),
)

SEA_ABSORPTION = (0.4, 0.08, 0.04, 1.0)  # per metre: clear sea water, red gone first


def _shade_input(name):
    """The lake's input `name`, shared with the ocean (the same meaning, the same preset key)."""
    return next(socket for socket in water_surface.INPUTS if socket.name == name)


SHADE_INPUTS = (
    Socket("Normal", "NodeSocketVector", (0.0, 0.0, 1.0), hide_value=True, tooltip="Shading normal n"),
    Socket("Sky", "NodeSocketColor", (0.5, 0.7, 1.0, 1.0), tooltip="The sky seen in the reflected direction"),
    Socket(
        "Deep Color",
        "NodeSocketColor",
        DEEP_BLUE,
        tooltip="Colour of the deep water (the seeds' deep blue); with the surroundings, what the "
        "water scatters back where it hides the bed",
    ),
    Socket(
        "Glint Power",
        "NodeSocketFloat",
        30.0,
        min=1.0,
        max=1000.0,
        tooltip="The glint is mean(sky) to this power: only the brightest sky glints",
    ),
    Socket(
        "Foam",
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        hide_value=True,
        tooltip="The crest's foam here, 0 to 1 (the open sea's `water_whitecaps`; 0 where the mesh has none)",
    ),
    Socket(
        "Whitecap Coverage",
        "NodeSocketFloat",
        0.02,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
        tooltip="Share of the sea whitecaps cover at Whitecaps 1 (the open sea drives it from its wind, as "
        "Monahan and O'Muircheartaigh measured the sea's whitecaps)",
    ),
    Socket(
        "Whitecaps",
        "NodeSocketFloat",
        1.0,
        min=0.0,
        max=WHITECAPS_MAX,
        tooltip="Whitecaps on the crests, white foam lit by the scene: 1 as many as nature has for the "
        "wind (Monahan), 0 none, 2 more",
    ),
    Socket(
        STREAKS_INPUT,
        "NodeSocketFloat",
        1.0,
        min=1.0,
        max=STREAKS_MAX,
        tooltip="How far the wind draws the foam's lace out along itself: 1 bubbles, more long streaks "
        "(the open sea drives it from its wind: streaks from 12 m/s, Beaufort 6 and up)",
    ),
    # The surroundings (depth colour, shore foam, caustics), as on the lake: nothing without them.
    *bump_uv.SCROLL_INPUTS,  # Wave Length, Wind Direction, Wind Force, Time
    Socket(
        "Absorption",
        "NodeSocketColor",
        SEA_ABSORPTION,
        tooltip="How much of each colour the water absorbs per metre seen through it (needs the "
        "surroundings' depth): where it lets the bed through, the bed shows instead of Deep Color",
    ),
    _shade_input("Foam Width"),
    _shade_input("Foam Amount"),
    _shade_input("Sun Direction"),
    caustics.CAUSTICS_INPUT,
    caustics.CAUSTICS_SCALE_INPUT,
    caustics.SUN_LIT_INPUT,
    Socket(
        "Debug View",
        "NodeSocketInt",
        0,
        min=0,
        max=8,
        tooltip="0 final, 3 Fresnel F, 4 shading normal (world), 5 sun glint, 6 transmittance, "
        "7 foam and whitecaps, 8 caustics, each unlit (1 and 2: the final picture)",
    ),
    Socket(
        "Water Fresnel",
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
        tooltip="1: water's own reflectance from its refractive index (2% looking straight down, a mirror "
        "at grazing: the open sea); 0: the seeds' ocean Fresnel (never under half a mirror)",
    ),
    Socket(
        "Traced Sky",
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
        tooltip="1: the renderer reflects the world the scene has now, whatever it is (an image, Sky "
        "Texture, a gradient), and the sun's own glint, as on the lake; 0: the Sky input (the world's "
        "image or colour looked up as the seeds do, as it was when the water was added)",
    ),
    Socket(
        UNRESOLVED_SLOPE,
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        hide_value=True,
        tooltip="Mean square slope each way the bump's reads lost (Water Ocean Normal's): with Water "
        "Fresnel, the far sea reflects what those slopes would (water's mean reflectance over them, a "
        "rougher mirror), not a flat mirror",
    ),
    Socket(
        FADE_START_INPUT,
        "NodeSocketFloat",
        FADE_NEVER,
        min=0.0,
        hide_value=True,
        tooltip="Metres from the sea's centre where its waves, and the crests marked on them, start to "
        "fade (the sea's Water Sea Fade, driven): past it whitecaps are spread over the flat far sea, "
        "as many as the crests would carry",
    ),
    Socket(
        FADE_END_INPUT,
        "NodeSocketFloat",
        FADE_NEVER + 1.0,
        min=0.0,
        hide_value=True,
        tooltip="Metres from the sea's centre where its waves are gone (Water Sea Fade's, driven)",
    ),
)
TRACED_SKY = "Traced Sky"
# The traced sky's roughness: the ripples finer than a pixel. Sharp (0), EEVEE draws a sun lamp's
# highlight four times as bright as Cycles over the shallows and white over what should be sand.
TRACED_ROUGHNESS = 0.05
# The ocean's debug views: the lake's numbers for what the ocean shading has (1 and 2, the lake's
# closures alone, show the final picture here).
DEBUG_VIEWS = (
    (3, "F, grey"),
    (4, "shading normal n * 0.5 + 0.5 (world space)"),
    (5, "sun glint: pow(max(reflect(L, n) . eye, 0), Glint Power)"),
    (6, "transmittance T (0 without surroundings)"),
    (7, "foam: whitecaps and shore foam"),
    (8, "caustic factor"),
)
# The traced sky: a sharp Glossy closure at (1 - F) in place of the Sky input's colour. Built
# only into the group's "+ Traced Sky" variant (every new material's: issue 38, the world live).
# The caustics on the bed (`caustics.py`): built only into the "+ Caustics" variants, while
# Caustics is above 0. Without them the bed is lit by the factor 1 (no caustics), as the lake's.
PARTS = (
    Part(
        "traced_sky",
        "Traced Sky",
        TRACED_SKY,
        1.0,
        off_links=(("water_shader:Shader", "mix:#1"),),
    ),
    Part(
        "caustics",
        "Caustics",
        caustics.CAUSTICS_INPUT.name,
        1.0,
        off_values={"lit_bed": {"Scale": 1.0}, "view_8": {0: (1.0, 1.0, 1.0)}},
    ),
)

_T_NODES, _T_LINKS = water_surface.transmittance_nodes()


def _debug_nodes():
    """Each debug view's value as an unlit emission, mixed over the final picture while a view
    from 3 to 8 is asked; any other number shows the final picture."""
    values = {
        3: "F:Value",
        4: "normal_colour:Vector",
        5: "glint_pow:Value",
        6: "t_seen:Vector",
        7: "foam_cover:Value",
        8: "caustics:Factor",
    }
    nodes = {
        "normal_colour": vmath("MULTIPLY_ADD", 30, "n * 0.5 + 0.5", b=(0.5, 0.5, 0.5), c=(0.5, 0.5, 0.5)),
        "debug_emit": Node("ShaderNodeEmission", 35, values={"Strength": 1.0}, label="debug view, unlit"),
        "debug_or_final": Node("ShaderNodeMixShader", 36, label="final, or a debug view"),
    }
    links = [
        ("input:Normal", "normal_colour:#0"),
    ]
    glint, glint_links = water_surface.glint_nodes("input:Normal", "input:Glint Power", column=30)
    nodes |= glint
    links += glint_links
    colour, any_view = None, None
    for number, source in values.items():
        nodes[f"is_{number}"] = math("COMPARE", 33, f"view == {number}", b=float(number), c=0.5)
        nodes[f"view_{number}"] = vmath("MULTIPLY_ADD", 34, f"+ view {number}")
        links += [
            ("input:Debug View", f"is_{number}:#0"),
            (source, f"view_{number}:#0"),
            (f"is_{number}:Value", f"view_{number}:#1"),
        ]
        if colour is not None:
            links.append((colour, f"view_{number}:#2"))
            nodes[f"any_{number}"] = math("ADD", 34, "a debug view")
            links += [(any_view, f"any_{number}:#0"), (f"is_{number}:Value", f"any_{number}:#1")]
            any_view = f"any_{number}:Value"
        else:
            any_view = f"is_{number}:Value"
        colour = f"view_{number}:Vector"
    links += [
        (colour, "debug_emit:Color"),
        (any_view, "debug_or_final:Fac"),
        ("sides:Shader", "debug_or_final:#1"),
        ("debug_emit:Emission", "debug_or_final:#2"),
        ("debug_or_final:Shader", "output:Shader"),
    ]
    return nodes, tuple(links)


_DEBUG_NODES, _DEBUG_LINKS = _debug_nodes()

FULL_SHADE_SPEC = GroupSpec(
    name=SHADE_NAME,
    # 2: whitecaps; 3: depth colour, shore foam and caustics from the surroundings; 4: the traced
    # sky and the debug views; 5: whitecaps broken up by the foam tile, as the shore's foam; 6: the
    # caustics an optional part (`PARTS`: older groups have them built in, `retire_legacy_shades`);
    # 7: seen from below, Snell's window (it was clear); 8: its normal and weights from the one
    # `Water Underside` group; 9: `Water Fresnel` (water's own reflectance, from the same group);
    # 10: `Foam Streaks` (the lace drawn out along the wind: streaks in a gale, not cells); 11: from
    # below, the deep water reflected outside Snell's window is its Deep Color (was a glossy, which
    # EEVEE fills with the world); 12: `Unresolved Slope` (with Water Fresnel: water's mean
    # reflectance over the slopes EEVEE's mipmaps averaged away, `rough_fresnel.py`, and a mirror
    # as much rougher); past the sea's fade (`Fade Start`, `Fade End`), whitecaps where the mesh
    # marks no crests (the far sea was bare: at 25 m/s a band 40 m up); 13: the far whitecaps from
    # two reads of the tile (one alone repeated across the wind: stripes from high up); 14: the
    # lace read nearest-texel (a mipmapped read hung software EEVEE on folded crests); 15: whitecaps
    # are compact spots (Voronoi), whole, drawn out a^0.42 (were the foam tile's bubble middles:
    # dashes a pixel wide)
    version=15,
    description="Ocean colour: deep blue and the reflected sky by the ocean Fresnel, plus the glint; "
    "white lit foam on the crests; with the surroundings, the bed seen through shallow water, "
    "shore foam and caustics",
    inputs=SHADE_INPUTS,
    outputs=(Socket("Shader", "NodeSocketShader"),),
    nodes={
        "geometry": Node("ShaderNodeNewGeometry", 1),
        "cos": vmath("DOT_PRODUCT", 2, "dot(-eye, n)"),
        "F_seeds": math("MULTIPLY_ADD", 3, "the seeds' F = dot / 2 + 0.5", b=0.5, c=0.5),
        # Water's own (`Water Fresnel`): F = 1 - R, R Fresnel's reflectance at water's IOR, from the
        # one `Water Underside` group (on the top side its facing normal is n itself).
        "F_towards": math("SUBTRACT", 3, "water's 1 - R - the seeds'"),
        # Where the bump's slopes were averaged away, R over them: R(c, s) - R(c, 0) from the table
        # at (|cos|, s), s the lost rms slope (with Water Fresnel only: the seeds' stay the seeds').
        "unresolved": math("MULTIPLY", 1, "lost slope^2 x Water Fresnel"),
        "rough_slope": math("SQRT", 1, "s"),
        "rough_v": math(
            "MULTIPLY_ADD",
            2,
            "table row",
            b=(rough_fresnel.SIZE - 1) / (rough_fresnel.SIZE * rough_fresnel.SLOPE_MAX),
            c=0.5 / rough_fresnel.SIZE,
        ),
        "abs_cos": math("ABSOLUTE", 2, "|cos|"),
        "rough_u": math(
            "MULTIPLY_ADD",
            2,
            "table column",
            b=(rough_fresnel.SIZE - 1) / rough_fresnel.SIZE,
            c=0.5 / rough_fresnel.SIZE,
        ),
        "rough_uv": Node("ShaderNodeCombineXYZ", 2, label="(|cos|, s) in the table"),
        "rough_table": Node(
            "ShaderNodeTexImage",
            3,
            {"extension": "EXTEND", "interpolation": "Linear", "image": ROUGH_FRESNEL_IMAGE},
            label="R(c, s) - R(c, 0)",
        ),
        "rough_refracted": math("SUBTRACT", 3, "1 - R over the lost slopes"),
        # The mirror as much rougher: GGX alpha^2 = alpha_0^2 + 2 s^2 (roughness = sqrt(alpha)).
        "rough_alpha": Node(
            "ShaderNodeMath",
            4,
            {"operation": "MULTIPLY_ADD"},
            {1: 2.0, 2: TRACED_ROUGHNESS**4},
            label="alpha^2",
            part="traced_sky",
        ),
        "rough_mirror": Node(
            "ShaderNodeMath", 5, {"operation": "POWER"}, {1: 0.25}, label="roughness", part="traced_sky"
        ),
        "F": math("MULTIPLY_ADD", 3, "F: the seeds' or water's (Water Fresnel)"),
        "one_minus_F": math("SUBTRACT", 4, "1 - F", a=1.0),
        # Through the water: T = exp(-Absorption x path) where the surroundings are measured, else 0
        # (the seeds' ocean, all deep colour); the bed shows at T, the deep colour at 1 - T.
        **_T_NODES,
        "flag": attribute(water_surface.FLAG_ATTRIBUTE, 14, "water_surroundings (1 = measured)"),
        "t_seen": vmath("SCALE", 24, "T, 0 without surroundings"),
        "hidden": vmath("SUBTRACT", 25, "1 - T", a=(1.0, 1.0, 1.0)),
        "deep_hides": vmath("MULTIPLY", 26, "deep x (1 - T)"),
        "deep": vmath("SCALE", 27, "deep (1 - T) F"),
        "looked_up": math("SUBTRACT", 4, "1 - Traced Sky", a=1.0),
        "sky_share": math("MULTIPLY", 5, "(1 - F) x looked up"),
        "sky": vmath("SCALE", 5, "sky * (1 - F)"),
        "mean": vmath("DOT_PRODUCT", 5, "mean(sky)", b=(1 / 3, 1 / 3, 1 / 3)),
        "glint_raw": math("POWER", 6, "pow(mean, Glint Power)"),
        "glint": math("MULTIPLY", 6, "x looked up"),
        "glint_v": Node("ShaderNodeCombineXYZ", 7, label="glint (white)"),
        # The traced sky (part "traced_sky"): the world reflected by the renderer at (1 - F).
        "mirror_share": Node(
            "ShaderNodeMath", 5, {"operation": "MULTIPLY"}, label="(1 - F) x Traced Sky", part="traced_sky"
        ),
        # Multiscatter: rougher far off, a single-scatter lobe would lose light at grazing.
        "mirror": Node(
            "ShaderNodeBsdfAnisotropic",
            30,
            {"distribution": "MULTI_GGX"},
            {"Roughness": TRACED_ROUGHNESS},
            label="the world reflected",
            part="traced_sky",
        ),
        "with_mirror": Node("ShaderNodeAddShader", 32, label="+ reflection", part="traced_sky"),
        "water": vmath("ADD", 28),
        "color": vmath("ADD", 29, "colour"),
        "emit": Node("ShaderNodeEmission", 30, values={"Strength": 1.0}, label="unlit"),
        # The bed, refracted, at F T x the caustic factor (`caustics.py`).
        "bump_uv": group_node(bump_uv.NAME, 12, "scrolled bump UV (foam, caustics)"),
        "caustics": replace(group_node(caustics.NAME, 24, "caustic factor"), part="caustics"),
        "lit_bed": vmath("SCALE", 25, "T x caustics"),
        "seen": vmath("SCALE", 28, "F T x caustics"),
        "refraction": Node(
            "ShaderNodeBsdfRefraction",
            30,
            {"distribution": "GGX"},
            {"Roughness": 0.0, "IOR": water_surface.IOR},
            label="the bed, refracted",
        ),
        "water_shader": Node("ShaderNodeAddShader", 31, label="unlit + refraction"),
        # Foam: whitecaps or shore foam (the lake's coverage), whichever covers more; white, lit.
        # Whitecaps break on the crests the sea's fade marks (`water_whitecaps`, the Foam input):
        # there spots B (`_spots`: B < s covers s of the sea) of the share the wind asks for, and
        # inside them the foam tile, read fine, laces the foam as on the shore,
        # clamp((b + f - 1) / SOFTNESS) with f = WHITECAP_FOAM. Both follow where the water came
        # from (`water_rest`: the foam rides with the chop), drawn out along the wind.
        "rest": attribute(sea_fade.REST_ATTRIBUTE, 24, "water_rest (where the water came from)"),
        "wind_w": vmath("NORMALIZE", 24, "w"),
        "wind_across": vmath("CROSS_PRODUCT", 25, "z x w: across the wind", a=(0.0, 0.0, 1.0)),
        "cap_along": vmath("DOT_PRODUCT", 26, "along the wind (m)"),
        "cap_across": vmath("DOT_PRODUCT", 26, "across the wind (m)"),
        **_spots("blob", WHITECAP_BLOB_TILE, 27, "spots B (which whitecaps)"),
        # Closest: a mipmapped read of the lace, on a crest folded over in front of the camera,
        # took software EEVEE minutes a frame (issue 57 point 1); the lace is cut sharp by the
        # breakup's threshold anyway.
        **_tile_read("lace", WHITECAP_TILE, 27, "foam tile b (their lace)", "Closest"),
        "lace_length": math("MULTIPLY", 26, "12 a: drawn out along the wind", b=WHITECAP_TILE[0]),
        "lace_width": math("DIVIDE", 26, "6 / a: narrowed across it", a=WHITECAP_TILE[1]),
        # Which whitecaps, by a^0.42 only: drawn out as far as their lace, one would run for
        # hundreds of metres (over 500 m^2 at 15 m/s).
        "blob_stretch": math("POWER", 25, "a^0.42", b=BLOB_STRETCH_POWER),
        "blob_length": math("MULTIPLY", 26, "12 a^0.42: drawn out along the wind", b=WHITECAP_BLOB_TILE[0]),
        "blob_width": math("DIVIDE", 26, "10 / a^0.42: narrowed across it", a=WHITECAP_BLOB_TILE[1]),
        "cap_share": math("MULTIPLY", 27, "Whitecaps x Whitecap Coverage"),
        "blob_share": math("MULTIPLY", 28, "s: bubbles' share", b=WHITECAP_BLOB_GAIN),
        # Each spot's edge ragged by the tile R, metres-wide wobbles: B (1 + e (R - 1/2)).
        "blob_rag": math("MULTIPLY_ADD", 28, "1 + e (R - 1/2)", b=SPOT_RAG, c=1.0 - SPOT_RAG / 2),
        "blob_ragged": math("MULTIPLY", 28, "B ragged"),
        "blob_gap": math("SUBTRACT", 29, "s - B"),
        "blob": _bubble("a whitecap's bubble"),
        "mark_lift": math("POWER", 30, f"mark^{MARK_POWER:g}: whole where marked", b=MARK_POWER),
        "mark_share": math("MULTIPLY", 29, "s x mark^g: aged whitecaps shrink"),
        "fade_distance": vmath("LENGTH", 25, "distance from the sea's centre"),
        "fade_near": Node(
            "ShaderNodeMapRange",
            26,
            {"interpolation_type": "SMOOTHSTEP", "clamp": True},
            {3: 1.0, 4: 0.0},
            label="near: 1 where the crests are marked, 0 past the fade",
        ),
        # The mesh's mark faded by `near` (as the waves): whole again, and then either the crests'
        # whitecaps or the far ones, by a third read of the tile R (near > R: the crests'), so
        # both stay whole whitecaps where the sea fades, in those shares.
        "near_floor": math("MAXIMUM", 27, "near (>= 0.001)", b=0.001),
        "crest_whole": math("DIVIDE", 28, "the crest's mark, unfaded", clamp=True),
        "pick_u": math("DIVIDE", 27, "across / 37 m", b=PICK_TILE[0]),
        "pick_v": math("DIVIDE", 27, "along / 53 m", b=PICK_TILE[1]),
        "pick_uv": Node("ShaderNodeCombineXYZ", 28),
        "pick_tile": water_surface.foam_tile(29, "foam tile R (crests' or far whitecaps)", "Closest"),
        "crests_here": math("GREATER_THAN", 30, "near > R: the crests' whitecaps"),
        "caps_change": math("SUBTRACT", 31, "crests' - far"),
        "far_share": math("MULTIPLY", 28, "far bubbles' share", b=FAR_CAP_GAIN, clamp=True),
        "far_keep": math("SUBTRACT", 28, "1 - share", a=1.0),
        "far_root": math("SQRT", 28, "sqrt(1 - share)"),
        "far_cut": math("SUBTRACT", 29, "t = 1 - sqrt(1 - share)", a=1.0),
        "far_length": math("MULTIPLY", 26, "B2's length", b=FAR_SECOND_READ[0]),
        "far_width": math("MULTIPLY", 26, "B2's width", b=FAR_SECOND_READ[1]),
        **_spots("far2", WHITECAP_BLOB_TILE, 27, "spots B2 (far whitecaps, second read)"),
        "far_either": math("MINIMUM", 29, "min(B, B2)"),
        "far_gap": math("SUBTRACT", 29, "t - min(B, B2)"),
        "far_blob": _bubble("a far whitecap's bubble"),
        "caps": math("MULTIPLY_ADD", 31, "the crests' or the far whitecaps"),
        # No share, no whitecap: the bubble's soft edge would otherwise keep a few.
        "some": math("MULTIPLY", 30, "any share?", clamp=True, b=1.0 / WHITECAP_BLOB_SOFTNESS),
        "on_some": math("MULTIPLY", 31, "x any share"),
        "crest": math("MULTIPLY", 32, "f", b=WHITECAP_FOAM),
        "cap_sum": math("ADD", 32, "b + f"),
        "cover": water_surface.foam_breakup(32, "whitecaps: "),
        "shore_foam": group_node(water_surface.FOAM_NAME, 28, "shore foam coverage"),
        "foam_cover": math("MAXIMUM", 30, "foam cover"),
        # Lit from 4.5; EEVEE in 4.2 drops the traced refraction beside a diffuse closure, so there
        # the foam is unlit white, as on the lake.
        "foam_bsdf": Node(
            "ShaderNodeBsdfDiffuse",
            31,
            values={"Color": (*FOAM_WHITE, 1.0)},
            label="white foam, lit",
            since=water_surface.LIT_FOAM_SINCE,
        ),
        "foam_glow": Node(
            "ShaderNodeEmission",
            31,
            values={"Color": (*FOAM_WHITE, 1.0), "Strength": 1.0},
            label="white foam, unlit (before 4.5)",
            before=water_surface.LIT_FOAM_SINCE,
        ),
        "mix": Node("ShaderNodeMixShader", 32, label="water or foam"),
        # Seen from below by the camera, physics alone (its unlit colour is what the eye sees from
        # above, not a lamp over the bed), the one rule of `Water Underside`: the sky refracted
        # inside Snell's window at 1 - F, the water below reflected outside it at F, on the normal
        # turned to face the eye (the waves' worked-out normal is not turned on a backface). The
        # water below is deep (the ocean shading's): what it sends up is its far colour, the Deep
        # Color the underwater fog fades to, so the reflection is that colour at F, unlit, the
        # same in EEVEE (whose glossy would show the world's sky there) and Cycles. To every
        # other ray (the bed's light bounces in Cycles) it stays clear, as EEVEE lights the bed:
        # the two engines show the same shallows.
        "underside": group_node(underside.NAME, 30, "from below: n facing the eye, F, 1 - F"),
        "under_deep": vmath("SCALE", 30, "the deep water's colour at F"),
        "under_mirror": Node("ShaderNodeEmission", 31, label="from below: the deep water reflected"),
        "under_sky": Node(
            "ShaderNodeBsdfRefraction",
            31,
            {"distribution": "GGX"},
            {"Roughness": 0.0, "IOR": water_surface.IOR},
            label="from below: the sky refracted",
        ),
        "see_through": Node("ShaderNodeAddShader", 32, label="from below"),
        "light_path": Node("ShaderNodeLightPath", 31),
        "clear": Node("ShaderNodeBsdfTransparent", 32, label="from below, to other rays: clear"),
        "under_camera": Node("ShaderNodeMixShader", 33, label="the camera's view, or clear"),
        "sides": Node("ShaderNodeMixShader", 33, label="above or below"),
        **_DEBUG_NODES,
    },
    includes=(water_surface.FOAM_SPEC,),
    parts=PARTS,
    links=(
        ("geometry:Incoming", "cos:#0"),
        ("input:Normal", "cos:#1"),
        ("cos:Value", "F_seeds:#0"),
        (f"input:{UNRESOLVED_SLOPE}", "unresolved:#0"),
        ("input:Water Fresnel", "unresolved:#1"),
        ("unresolved:Value", "rough_slope:#0"),
        ("rough_slope:Value", "rough_v:#0"),
        ("cos:Value", "abs_cos:#0"),
        ("abs_cos:Value", "rough_u:#0"),
        ("rough_u:Value", "rough_uv:X"),
        ("rough_v:Value", "rough_uv:Y"),
        ("rough_uv:Vector", "rough_table:Vector"),
        ("underside:Refracted", "rough_refracted:#0"),
        ("rough_table:Color", "rough_refracted:#1"),
        ("rough_refracted:Value", "F_towards:#0"),
        ("unresolved:Value", "rough_alpha:#0"),
        ("rough_alpha:Value", "rough_mirror:#0"),
        ("rough_mirror:Value", "mirror:Roughness"),
        ("F_seeds:Value", "F_towards:#1"),
        ("F_towards:Value", "F:#0"),
        ("input:Water Fresnel", "F:#1"),
        ("F_seeds:Value", "F:#2"),
        ("F:Value", "one_minus_F:#1"),
        *_T_LINKS,
        ("transmit:Vector", "t_seen:#0"),
        ("flag:Fac", "t_seen:Scale"),
        ("t_seen:Vector", "hidden:#1"),
        ("input:Deep Color", "deep_hides:#0"),
        ("hidden:Vector", "deep_hides:#1"),
        ("deep_hides:Vector", "deep:#0"),
        ("F:Value", "deep:Scale"),
        ("input:Traced Sky", "looked_up:#1"),
        ("one_minus_F:Value", "sky_share:#0"),
        ("looked_up:Value", "sky_share:#1"),
        ("input:Sky", "sky:#0"),
        ("sky_share:Value", "sky:Scale"),
        ("input:Sky", "mean:#0"),
        ("mean:Value", "glint_raw:#0"),
        ("input:Glint Power", "glint_raw:#1"),
        ("glint_raw:Value", "glint:#0"),
        ("looked_up:Value", "glint:#1"),
        ("one_minus_F:Value", "mirror_share:#0"),
        ("input:Traced Sky", "mirror_share:#1"),
        ("mirror_share:Value", "mirror:Color"),
        ("input:Normal", "mirror:Normal"),
        ("water_shader:Shader", "with_mirror:#0"),
        ("mirror:BSDF", "with_mirror:#1"),
        ("glint:Value", "glint_v:X"),
        ("glint:Value", "glint_v:Y"),
        ("glint:Value", "glint_v:Z"),
        ("deep:Vector", "water:#0"),
        ("sky:Vector", "water:#1"),
        ("water:Vector", "color:#0"),
        ("glint_v:Vector", "color:#1"),
        ("color:Vector", "emit:Color"),
        *pass_inputs("bump_uv", water_surface.BUMP_UV_INPUTS),
        *caustics.feed("caustics", "bump_uv:Vector"),
        ("t_seen:Vector", "lit_bed:#0"),
        ("caustics:Factor", "lit_bed:Scale"),
        ("lit_bed:Vector", "seen:#0"),
        ("F:Value", "seen:Scale"),
        ("seen:Vector", "refraction:Color"),
        ("input:Normal", "refraction:Normal"),
        ("emit:Emission", "water_shader:#0"),
        ("refraction:BSDF", "water_shader:#1"),
        ("input:Wind Direction", "wind_w:#0"),
        ("wind_w:Vector", "wind_across:#1"),
        ("rest:Vector", "cap_along:#0"),
        ("wind_w:Vector", "cap_along:#1"),
        ("rest:Vector", "cap_across:#0"),
        ("wind_across:Vector", "cap_across:#1"),
        *_spot_links("blob"),
        *_tile_links("lace"),
        (f"input:{STREAKS_INPUT}", "lace_length:#0"),
        (f"input:{STREAKS_INPUT}", "lace_width:#1"),
        ("lace_length:Value", "lace_u:#1"),
        ("lace_width:Value", "lace_v:#1"),
        (f"input:{STREAKS_INPUT}", "blob_stretch:#0"),
        ("blob_stretch:Value", "blob_length:#0"),
        ("blob_stretch:Value", "blob_width:#1"),
        ("blob_length:Value", "blob_u:#1"),
        ("blob_width:Value", "blob_v:#1"),
        ("input:Whitecaps", "cap_share:#0"),
        ("input:Whitecap Coverage", "cap_share:#1"),
        ("cap_share:Value", "blob_share:#0"),
        ("mark_share:Value", "blob_gap:#0"),
        ("pick_tile:Color", "blob_rag:#0"),
        ("blob_even:Value", "blob_ragged:#1"),
        ("blob_rag:Value", "blob_ragged:#0"),
        ("blob_ragged:Value", "blob_gap:#1"),
        ("blob_gap:Value", "blob:Value"),
        ("crest_whole:Value", "mark_lift:#0"),
        ("blob_share:Value", "mark_share:#0"),
        ("mark_lift:Value", "mark_share:#1"),
        ("blob_share:Value", "some:#0"),
        ("rest:Vector", "fade_distance:#0"),
        ("fade_distance:Value", "fade_near:Value"),
        (f"input:{FADE_START_INPUT}", "fade_near:From Min"),
        (f"input:{FADE_END_INPUT}", "fade_near:From Max"),
        ("fade_near:Result", "near_floor:#0"),
        ("input:Foam", "crest_whole:#0"),
        ("near_floor:Value", "crest_whole:#1"),
        ("cap_across:Value", "pick_u:#0"),
        ("cap_along:Value", "pick_v:#0"),
        ("pick_u:Value", "pick_uv:X"),
        ("pick_v:Value", "pick_uv:Y"),
        ("pick_uv:Vector", "pick_tile:Vector"),
        ("fade_near:Result", "crests_here:#0"),
        ("pick_tile:Color", "crests_here:#1"),
        ("cap_share:Value", "far_share:#0"),
        ("far_share:Value", "far_keep:#1"),
        ("far_keep:Value", "far_root:#0"),
        ("far_root:Value", "far_cut:#1"),
        ("blob_length:Value", "far_length:#0"),
        ("blob_width:Value", "far_width:#0"),
        *_spot_links("far2"),
        ("far_length:Value", "far2_u:#1"),
        ("far_width:Value", "far2_v:#1"),
        ("blob_even:Value", "far_either:#0"),
        ("far2_even:Value", "far_either:#1"),
        ("far_cut:Value", "far_gap:#0"),
        ("far_either:Value", "far_gap:#1"),
        ("far_gap:Value", "far_blob:Value"),
        ("blob:Result", "caps_change:#0"),
        ("far_blob:Result", "caps_change:#1"),
        ("caps_change:Value", "caps:#0"),
        ("crests_here:Value", "caps:#1"),
        ("far_blob:Result", "caps:#2"),
        ("caps:Value", "on_some:#0"),
        ("some:Value", "on_some:#1"),
        ("on_some:Value", "crest:#0"),
        ("lace_tile:Color", "cap_sum:#0"),
        ("crest:Value", "cap_sum:#1"),
        ("cap_sum:Value", "cover:Value"),
        *water_surface.foam_feed("shore_foam", "bump_uv:Vector"),
        ("cover:Result", "foam_cover:#0"),
        ("shore_foam:Coverage", "foam_cover:#1"),
        ("foam_cover:Value", "mix:Fac"),
        ("with_mirror:Shader", "mix:#1"),
        ("foam_bsdf:BSDF", "mix:#2"),
        ("foam_glow:Emission", "mix:#2"),
        ("geometry:Backfacing", "sides:Fac"),
        ("mix:Shader", "sides:#1"),
        ("input:Normal", "underside:Normal"),
        ("input:Deep Color", "under_deep:#0"),
        ("underside:Reflected", "under_deep:Scale"),
        ("under_deep:Vector", "under_mirror:Color"),
        ("underside:Refracted", "under_sky:Color"),
        ("underside:Normal", "under_sky:Normal"),
        ("under_mirror:Emission", "see_through:#0"),
        ("under_sky:BSDF", "see_through:#1"),
        ("light_path:Is Camera Ray", "under_camera:Fac"),
        ("clear:BSDF", "under_camera:#1"),
        ("see_through:Shader", "under_camera:#2"),
        ("under_camera:Shader", "sides:#2"),
        *_DEBUG_LINKS,
    ),
)

# The shade that looks the Sky input up (the seeds' ocean, and what version 3 and older built):
# the one in `SPECS`, so older groups upgrade in place to it.
SHADE_SPEC = FULL_SHADE_SPEC.variant(())
