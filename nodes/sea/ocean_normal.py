"""`Water Ocean Normal`: the seeds' ocean normal from three reads of the bump tile, and the
share of the slopes its mipmaps averaged away (`Unresolved Slope`), for `Water Ocean Shade`."""

from ..bump_uv import TIME_INPUT
from ..footprint_cap import capped
from ..spec import BUMP_IMAGE, GroupSpec, Node, Socket, math, vmath
from ..water_waves import NORMAL_ATTRIBUTE
from . import rough_fresnel
from .ocean_parts import UNRESOLVED_SLOPE
from .sea_fade import UV_METRES

NORMAL_NAME = "Water Ocean Normal"


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


# The finest tap repeats 3.1 Tex Stretch times a UV unit (UV_METRES): its tiles per metre, for
# `footprint_cap`, which scales the scrolled UV where a pixel sees the sea edge-on.
_CAP_NODES, _CAP_LINKS = capped("uv", 5, "uv_free:Vector", "finest_tiles:Value")
_CAP_NODES["finest_tiles"] = math("MULTIPLY", 4, "finest tap's tiles a metre", b=3.1 / UV_METRES)
_CAP_LINKS = (("input:Tex Stretch", "finest_tiles:#0"), *_CAP_LINKS)


def _tap(key, column):
    return Node("ShaderNodeTexImage", column, {"extension": "REPEAT", "image": BUMP_IMAGE}, label=key)


NORMAL_SPEC = GroupSpec(
    name=NORMAL_NAME,
    # 2: a mesh without the attribute transforms +Z, never a zero vector: EEVEE before 5.x
    # normalises it into NaN, and the NaN, even weighted by 0, turned the whole ocean black.
    # 3: the slopes scale apart along and across the wind (the open sea's Cox and Munk slopes).
    # 4: `Unresolved Slope`, the slopes the taps' mipmaps averaged away (`rough_fresnel.py`).
    # 5: the taps' UV capped where a pixel sees the sea edge-on (`footprint_cap.py`).
    version=5,
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
        "uv_free": vmath("ADD", 4, "scrolled uv"),
        **_CAP_NODES,
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
        ("coords:UV", "uv_free:#0"),
        ("drift_v:Vector", "uv_free:#1"),
        *_CAP_LINKS,
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
