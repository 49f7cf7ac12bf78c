"""`Water Wake Foam`: foam round a moving hull and along its drifted trail.

Round the hull where it moves through the water, and along the track behind it, drifted with
`Drift` (metres a second, downwind: `Water Wake` drifts the track's points, the `Trail`),
spreading (SPREAD) and fading with time; the larger of this wake's and that of any wake before it
(`water_wake_foam`), a field the wake stores. The material breaks it into patches and lace
(`wake_foam_cover.py`).
"""

from ..spec import GroupSpec, Node, Socket, math, vmath
from .wake_parts import FOAM_ATTRIBUTE, clamped_sample, merge, named, sample

NAME = "Water Wake Foam"
# m/s: how fast the trail's foam spreads across it (was 0.1: it hardly widened behind the boat)
SPREAD = 0.25


def _segment_distance(n, column):
    """Nodes of the distance from `p_flat` to the segment between two points (`_segment_links`
    wires them): `{n}_dist`."""
    return {
        n + "_d": vmath("SUBTRACT", column, "the segment"),
        n + "_w": vmath("SUBTRACT", column, "p - its start"),
        n + "_wd": vmath("DOT_PRODUCT", column + 1, "along it"),
        n + "_dd": vmath("DOT_PRODUCT", column + 1, "its length²"),
        n + "_dd_e": math("ADD", column + 2, "never 0", b=1e-9),
        n + "_t": math("DIVIDE", column + 3, "t, within it", clamp=True),
        n + "_foot": vmath("MULTIPLY_ADD", column + 4, "the foot"),
        n + "_dist": math("ADD", column + 5, "distance", b=0.0),
        n + "_len": vmath("DISTANCE", column + 5, "p to the foot"),
    }


def _segment_links(n, start, end):
    return (
        (end, n + "_d:#0"),
        (start, n + "_d:#1"),
        ("input:Position", n + "_w:#0"),
        (start, n + "_w:#1"),
        (n + "_w:Vector", n + "_wd:#0"),
        (n + "_d:Vector", n + "_wd:#1"),
        (n + "_d:Vector", n + "_dd:#0"),
        (n + "_d:Vector", n + "_dd:#1"),
        (n + "_dd:Value", n + "_dd_e:#0"),
        (n + "_wd:Value", n + "_t:#0"),
        (n + "_dd_e:Value", n + "_t:#1"),
        (n + "_d:Vector", n + "_foot:#0"),
        (n + "_t:Value", n + "_foot:#1"),
        (start, n + "_foot:#2"),
        ("input:Position", n + "_len:#0"),
        (n + "_foot:Vector", n + "_len:#1"),
        (n + "_len:Value", n + "_dist:#0"),
    )


def _hull_foam_nodes():
    """Foam round the hull: within half its beam of the segment from stern to bow, while it moves."""
    nodes = {
        # Round the hull: within half its beam of the segment from stern to bow, and a little more.
        "half_length": math("MULTIPLY", 22, "L / 2", b=0.5),
        # The distance to the segment from stern to bow, worked out: a few operations a point.
        "neg_half": math("MULTIPLY", 23, "-L / 2", b=-1.0),
        "h_v": vmath("SUBTRACT", 23, "p - where it is"),
        "h_s": vmath("DOT_PRODUCT", 24, "along its heading"),
        "h_s_c": Node("ShaderNodeClamp", 25, label="within the hull's length"),
        "h_proj": vmath("SCALE", 26, "nearest point on its line"),
        "h_perp": vmath("SUBTRACT", 26, "from it to p"),
        "hull_distance": vmath("LENGTH", 27, "distance to the hull's line"),
        "half_beam": math("MULTIPLY", 25, "B / 2", b=0.5),
        "past_hull": math("SUBTRACT", 27, "past its side"),
        "foam_width": math("MULTIPLY", 26, "foam's width: B / 4", b=0.25),
        "hull_foam_r": math("DIVIDE", 28, "in widths"),
        "hull_foam_c": math("SUBTRACT", 29, "1 - that", a=1.0),
        "moving": math("MULTIPLY", 29, "moving: U / 1 m/s", b=1.0),
        "moving_c": Node("ShaderNodeClamp", 30, label="0..1"),
        "hull_foam_cl": Node("ShaderNodeClamp", 30, label="0..1"),
        "hull_foam": math("MULTIPLY", 31, "foam round the hull"),
    }
    links = (
        ("input:Length", "half_length:#0"),
        ("half_length:Value", "neg_half:#0"),
        ("input:Position", "h_v:#0"),
        ("input:Last", "h_v:#1"),
        ("h_v:Vector", "h_s:#0"),
        ("input:Heading", "h_s:#1"),
        ("h_s:Value", "h_s_c:Value"),
        ("neg_half:Value", "h_s_c:Min"),
        ("half_length:Value", "h_s_c:Max"),
        ("input:Heading", "h_proj:#0"),
        ("h_s_c:Result", "h_proj:Scale"),
        ("h_v:Vector", "h_perp:#0"),
        ("h_proj:Vector", "h_perp:#1"),
        ("h_perp:Vector", "hull_distance:#0"),
        ("input:Beam", "half_beam:#0"),
        ("hull_distance:Value", "past_hull:#0"),
        ("half_beam:Value", "past_hull:#1"),
        ("input:Beam", "foam_width:#0"),
        ("past_hull:Value", "hull_foam_r:#0"),
        ("foam_width:Value", "hull_foam_r:#1"),
        ("hull_foam_r:Value", "hull_foam_c:#1"),
        ("input:Speed", "moving:#0"),
        ("moving:Value", "moving_c:Value"),
        ("hull_foam_c:Value", "hull_foam_cl:Value"),
        ("hull_foam_cl:Result", "hull_foam:#0"),
        ("moving_c:Result", "hull_foam:#1"),
    )
    return nodes, links


def _trail_line_nodes():
    """The trail (the track drifted downwind, `Trail`): each water point's distance to its line."""
    nodes = {
        "d_position": Node("GeometryNodeInputPosition", 20),
        "d_at_position": sample("FLOAT_VECTOR", 21, "where it drifted to"),
        # The trail's width and weight are worked out on the track's points, then sampled.
        "d_at_width": sample("FLOAT", 21, "its width"),
        "d_at_weight": sample("FLOAT", 21, "its weight"),
        # The distance to the drifted track's line, not to its nearest point: a track point a
        # frame lies metres apart at speed, and the trail would break into dots.
        "d_distance": math("MINIMUM", 22, "distance to the trail's line"),
        **_segment_distance("d_back", 21),
        **_segment_distance("d_ahead", 21),
        "d_i_back": math("SUBTRACT", 20, "the point before", b=1.0),
        "d_i_ahead": math("ADD", 20, "the point after", b=1.0),
        "d_back_end": clamped_sample("FLOAT_VECTOR", 21, "the point before it"),
        "d_ahead_end": clamped_sample("FLOAT_VECTOR", 21, "the point after it"),
    }
    links = (
        ("input:Trail", "d_at_position:Geometry"),
        ("d_position:Position", "d_at_position:Value"),
        ("input:Foot", "d_at_position:Index"),
        ("input:Trail", "d_at_width:Geometry"),
        ("d_width:Value", "d_at_width:Value"),
        ("input:Foot", "d_at_width:Index"),
        ("input:Trail", "d_at_weight:Geometry"),
        ("trail_foam_full:Value", "d_at_weight:Value"),
        ("input:Foot", "d_at_weight:Index"),
        ("input:Foot", "d_i_back:#0"),
        ("input:Foot", "d_i_ahead:#0"),
        *(
            link
            for end, index in (("d_back_end", "d_i_back"), ("d_ahead_end", "d_i_ahead"))
            for link in (
                ("input:Trail", f"{end}:Geometry"),
                ("d_position:Position", f"{end}:Value"),
                (f"{index}:Value", f"{end}:Index"),
            )
        ),
        *_segment_links("d_back", "d_at_position:Value", "d_back_end:Value"),
        *_segment_links("d_ahead", "d_at_position:Value", "d_ahead_end:Value"),
        ("d_back_dist:Value", "d_distance:#0"),
        ("d_ahead_dist:Value", "d_distance:#1"),
    )
    return nodes, links


def _trail_foam_nodes():
    """The trail's foam (its width, shape and fading), and this wake's or any before's where more."""
    nodes = {
        "f_time": named("wake_time", "FLOAT", 17, "when each was"),
        "f_speed": named("wake_speed", "FLOAT", 17, "its speed then"),
        "d_age": math("SUBTRACT", 18, "each track point's age"),
        "d_spread": math("MULTIPLY", 23, "SPREAD x age", b=SPREAD),
        "third_beam": math("MULTIPLY", 23, "B / 3", b=1.0 / 3.0),
        "d_width": math("ADD", 24, "B / 3 + spread"),
        "d_ratio": math("DIVIDE", 25, "in widths"),
        "d_ratio2": math("MULTIPLY", 26, "²"),
        "d_gauss": math("MULTIPLY", 27, "-", b=-1.0),
        "d_shape": math("EXPONENT", 28, "across the trail"),
        "d_age_s": math("DIVIDE", 23, "age / Foam Fade"),
        "d_age_n": math("MULTIPLY", 24, "-", b=-1.0),
        "d_fade": math("EXPONENT", 25, "fading"),
        "d_moving": math("MULTIPLY", 24, "moving then", b=1.0),
        "d_moving_c": Node("ShaderNodeClamp", 25, label="0..1"),
        "d_f1": math("MULTIPLY", 26, "fading x moving then"),
        "trail_foam_full": math("MULTIPLY", 27, "x 0.7: thinner than at the hull", b=0.7),
        "trail_foam": math("MULTIPLY", 31, "foam along the track"),
        "foam_here": math("MAXIMUM", 32, "this wake's foam"),
        "foam_before": named(FOAM_ATTRIBUTE, "FLOAT", 32, "foam of wakes before"),
        "foam": math("MAXIMUM", 33, "any wake's foam"),
    }
    links = (
        ("input:Time", "d_age:#0"),
        ("f_time:Attribute", "d_age:#1"),
        ("d_age:Value", "d_spread:#0"),
        ("input:Beam", "third_beam:#0"),
        ("third_beam:Value", "d_width:#0"),
        ("d_spread:Value", "d_width:#1"),
        ("d_distance:Value", "d_ratio:#0"),
        ("d_at_width:Value", "d_ratio:#1"),
        ("d_ratio:Value", "d_ratio2:#0"),
        ("d_ratio:Value", "d_ratio2:#1"),
        ("d_ratio2:Value", "d_gauss:#0"),
        ("d_gauss:Value", "d_shape:#0"),
        ("d_age:Value", "d_age_s:#0"),
        ("input:Foam Fade", "d_age_s:#1"),
        ("d_age_s:Value", "d_age_n:#0"),
        ("d_age_n:Value", "d_fade:#0"),
        ("f_speed:Attribute", "d_moving:#0"),
        ("d_moving:Value", "d_moving_c:Value"),
        ("d_fade:Value", "d_f1:#0"),
        ("d_moving_c:Result", "d_f1:#1"),
        ("d_f1:Value", "trail_foam_full:#0"),
        ("d_shape:Value", "trail_foam:#0"),
        ("d_at_weight:Value", "trail_foam:#1"),
        ("hull_foam:Value", "foam_here:#0"),
        ("trail_foam:Value", "foam_here:#1"),
        ("foam_before:Attribute", "foam:#0"),
        ("foam_here:Value", "foam:#1"),
        ("foam:Value", "output:Foam"),
    )
    return nodes, links


_NODES, _LINKS = merge(_hull_foam_nodes(), _trail_line_nodes(), _trail_foam_nodes())
SPEC = GroupSpec(
    name=NAME,
    version=2,  # 2: the trail spreads 0.25 m/s, not 0.1
    description="Foam round a moving hull and along its drifted trail, widening and fading with "
    "age, over the foam of wakes before",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("Position", "NodeSocketVector", tooltip="The water point, on the plane"),
        Socket("Trail", "NodeSocketGeometry", tooltip="The track's points, drifted (wake_time, wake_speed)"),
        Socket("Foot", "NodeSocketInt", 0, tooltip="The trail's point nearest along it"),
        Socket("Time", "NodeSocketFloat", 0.0, tooltip="Seconds now"),
        Socket("Last", "NodeSocketVector", tooltip="Where the hull is, on the plane"),
        Socket("Heading", "NodeSocketVector", (1.0, 0.0, 0.0), tooltip="Its heading"),
        Socket("Speed", "NodeSocketFloat", 0.0, tooltip="Its speed now"),
        Socket("Length", "NodeSocketFloat", 10.0, tooltip="The hull's length"),
        Socket("Beam", "NodeSocketFloat", 3.0, tooltip="Its width"),
        Socket("Foam Fade", "NodeSocketFloat", 6.0, tooltip="Seconds over which the foam fades to a third"),
    ),
    outputs=(
        Socket("Foam", "NodeSocketFloat", tooltip=f"This wake's foam or, where more, '{FOAM_ATTRIBUTE}'"),
    ),
    nodes=_NODES,
    links=_LINKS,
)
