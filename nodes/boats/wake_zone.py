"""`Water Wake Zone`: where a wake can show, so the costly part runs only there.

A box round the track, its drift and the rings picks the points looked at (two compares a point
over the whole water); on those alone, the zone: within the Kelvin wedge round the chord from
the object back to the track's oldest point (wider by how far the track strays from the chord
and by how much longer it is), or in the rings' box (1); near the trail too (2). It is stored
once (`wake_zone`) for `Water Wake` to read (its height and foam) and remove: its nearest-point
searches run only inside it.
"""

from ..physics import KELVIN_TAN, KELVIN_ZONE_TAN
from ..spec import GroupSpec, Node, Socket, math, vmath
from .wake_foam import SPREAD
from .wake_parts import box_test, merge, named, sample, store

NAME = "Water Wake Zone"
# How far across its line, per second of Foam Fade, the trail's foam can reach (`_band_nodes`).
FOAM_REACH = 4.23 * SPREAD


def _chord_nodes():
    """The track's ends: which is the newest, the oldest point, and the chord back to it from the object."""
    nodes = {
        "z_position": Node("GeometryNodeInputPosition", 38),
        "z_p_flat": vmath("MULTIPLY", 39, "on the plane", b=(1.0, 1.0, 0.0)),
        "z_t_position": Node("GeometryNodeInputPosition", 39, label="track position"),
        "z_t_time": named("wake_time", "FLOAT", 39),
        "kept": Node("GeometryNodeJoinGeometry", 40, label="track and its drift"),
        "spread_far": math("MULTIPLY_ADD", 41, "trail's spread: 0.2 m/s x Foam Fade + 2 m", b=0.2, c=2.0),
        "t_count": Node("GeometryNodeAttributeDomainSize", 40, {"component": "POINTCLOUD"}, label="points"),
        "last_index": math("SUBTRACT", 41, "the last point's index", b=1.0),
        # Which end is the newest: Join Geometry's order is not the links' order, so asked of
        # the points' times (1: the last point is the newest, 0: the first).
        "ord_first_t": sample("FLOAT", 42, "the first point's time"),
        "ord_last_t": sample("FLOAT", 42, "the last point's time"),
        "ord_up": math("GREATER_THAN", 43, "newest last"),
        "ord_dir": math("MULTIPLY_ADD", 44, "towards the newer: +1 or -1", b=2.0, c=-1.0),
        "ord_newest": math("MULTIPLY", 44, "the newest's index"),
        "ord_oldest": math("SUBTRACT", 45, "the oldest's index"),
        "oldest": sample("FLOAT_VECTOR", 46, "the oldest point"),
        "chord": vmath("SUBTRACT", 43, "chord: back to the oldest"),
        "chord_len": vmath("LENGTH", 44, "chord's length"),
        "chord_dir": vmath("NORMALIZE", 44, "chord's direction"),
    }
    links = (
        ("input:Track", "t_count:Geometry"),
        ("t_count:Point Count", "last_index:#0"),
        ("input:Track", "oldest:Geometry"),
        ("z_t_position:Position", "oldest:Value"),
        ("input:Track", "ord_first_t:Geometry"),
        ("z_t_time:Attribute", "ord_first_t:Value"),
        ("input:Track", "ord_last_t:Geometry"),
        ("z_t_time:Attribute", "ord_last_t:Value"),
        ("last_index:Value", "ord_last_t:Index"),
        ("ord_last_t:Value", "ord_up:#0"),
        ("ord_first_t:Value", "ord_up:#1"),
        ("ord_up:Value", "ord_dir:#0"),
        ("ord_up:Value", "ord_newest:#0"),
        ("last_index:Value", "ord_newest:#1"),
        ("last_index:Value", "ord_oldest:#0"),
        ("ord_newest:Value", "ord_oldest:#1"),
        ("ord_oldest:Value", "oldest:Index"),
        ("oldest:Value", "chord:#0"),
        ("input:Last", "chord:#1"),
        ("chord:Vector", "chord_len:#0"),
        ("chord:Vector", "chord_dir:#0"),
        ("input:Track", "kept:Geometry"),
        ("input:Trail", "kept:Geometry"),
        ("input:Foam Fade", "spread_far:#0"),
        ("z_position:Position", "z_p_flat:#0"),
    )
    return nodes, links


def _wedge_nodes():
    """How far the track and its drift stray from the chord: the wedge's width at the object and its span."""
    nodes = {
        # On the track and its drifted copy: how far they stray from the chord, and its span.
        "k_v": vmath("SUBTRACT", 45, "each point - the object"),
        "k_s": vmath("DOT_PRODUCT", 46, "along the chord"),
        "k_cross": vmath("CROSS_PRODUCT", 46, "across"),
        "k_d": vmath("LENGTH", 47, "off the chord"),
        "dev": Node("GeometryNodeAttributeStatistic", 48, {"domain": "POINT"}, label="strays at most"),
        "span": Node("GeometryNodeAttributeStatistic", 48, {"domain": "POINT"}, label="span along it"),
        "arc_extra": math("SUBTRACT", 45, "track's length - chord's"),
        "arc_extra_p": math("MAXIMUM", 46, "(> 0)", b=0.0),
        "beam_spread": math("ADD", 45, "beam + spread + 2 m"),
        "w0": math("MULTIPLY_ADD", 47, "strays + the extra length's wedge", b=KELVIN_TAN),
        "w1": math("ADD", 48, "the wedge's width at the object"),
        "ahead": math("MULTIPLY_ADD", 47, "L / 2 + beam + spread + 2 m", b=0.5),
        "s_lo": math("SUBTRACT", 49, "from ahead of the bow"),
        # Past the oldest point as far as its foam can reach (a young track's start, 4.23 s Foam
        # Fade across its line at most), so the box holds the foam band's end.
        "foam_spread": math("MULTIPLY_ADD", 45, "4.23 s x Foam Fade + 2 m", b=FOAM_REACH, c=2.0),
        "beam_foam": math("ADD", 46, "beam + that"),
        "s_hi": math("ADD", 49, "to past the oldest"),
        # A bent track's first arms reach past its oldest point along the chord (its heading
        # there turned from the chord's): by as much as it strays.
        "s_hi_bent": math("ADD", 50, "and its arms, bent"),
    }
    links = (
        ("z_t_position:Position", "k_v:#0"),
        ("input:Last", "k_v:#1"),
        ("k_v:Vector", "k_s:#0"),
        ("chord_dir:Vector", "k_s:#1"),
        ("k_v:Vector", "k_cross:#0"),
        ("chord_dir:Vector", "k_cross:#1"),
        ("k_cross:Vector", "k_d:#0"),
        ("kept:Geometry", "dev:Geometry"),
        ("k_d:Value", "dev:Attribute"),
        ("kept:Geometry", "span:Geometry"),
        ("k_s:Value", "span:Attribute"),
        ("input:Track Length", "arc_extra:#0"),
        ("chord_len:Value", "arc_extra:#1"),
        ("arc_extra:Value", "arc_extra_p:#0"),
        ("input:Beam", "beam_spread:#0"),
        ("spread_far:Value", "beam_spread:#1"),
        ("arc_extra_p:Value", "w0:#0"),
        ("dev:Max", "w0:#2"),
        ("w0:Value", "w1:#0"),
        ("beam_spread:Value", "w1:#1"),
        ("input:Length", "ahead:#0"),
        ("beam_spread:Value", "ahead:#2"),
        ("span:Min", "s_lo:#0"),
        ("ahead:Value", "s_lo:#1"),
        ("input:Foam Fade", "foam_spread:#0"),
        ("input:Beam", "beam_foam:#0"),
        ("foam_spread:Value", "beam_foam:#1"),
        ("span:Max", "s_hi:#0"),
        ("beam_foam:Value", "s_hi:#1"),
        ("s_hi:Value", "s_hi_bent:#0"),
        ("w0:Value", "s_hi_bent:#1"),
    )
    return nodes, links


def _band_nodes():
    """The trail foam's band: how far across its line and how far along the track the foam reaches."""
    nodes = {
        # The trail's foam, 0.7 exp(-age / Foam Fade) exp(-(d / w)²) with w = B / 3 + s age (s =
        # wake_foam.SPREAD, 0.25 m/s), is above 0.005 within 0.74 B + 4.23 s Foam Fade of its line
        # (at most, over its ages: (B / 3 + s F x) sqrt(ln 140 - x) is largest at x = 3.29), and only
        # while younger than ln(140) = 4.94 Foam Fades; the hull's within 0.75 B.
        "foam_m": math("MULTIPLY_ADD", 46, "trail's reach: 4.23 s x Foam Fade + 1 m", b=FOAM_REACH, c=1.0),
        "foam_b": math("MULTIPLY", 46, "0.75 B", b=0.75),
        "foam_mb": math("ADD", 47, "+ 0.75 B"),
        "fb_oldest_t": sample("FLOAT", 46, "the oldest point's time"),
        "fb_duration": math("SUBTRACT", 47, "the track's seconds"),
        "fb_duration_e": math("MAXIMUM", 48, "(> 0)", b=1e-3),
        "fb_ages": math("MULTIPLY", 47, "the foam's life: 4.94 Foam Fades", b=4.94),
        "fb_share": math("DIVIDE", 49, "its share of the track", clamp=True),
        "fb_len": math("MULTIPLY", 50, "as much of its length"),
        "fb_reach": math("ADD", 51, "from ahead of the bow"),
        "z_young": math("LESS_THAN", 54, "where the foam is young enough"),
        "z_band_young": math("MULTIPLY", 55, "near the trail, young"),
        "foam_w": math("ADD", 48, "+ strays: the trail's band"),
    }
    links = (
        ("input:Foam Fade", "foam_m:#0"),
        ("foam_m:Value", "foam_mb:#0"),
        ("input:Beam", "foam_b:#0"),
        ("foam_b:Value", "foam_mb:#1"),
        ("input:Track", "fb_oldest_t:Geometry"),
        ("z_t_time:Attribute", "fb_oldest_t:Value"),
        ("ord_oldest:Value", "fb_oldest_t:Index"),
        ("input:Time", "fb_duration:#0"),
        ("fb_oldest_t:Value", "fb_duration:#1"),
        ("fb_duration:Value", "fb_duration_e:#0"),
        ("input:Foam Fade", "fb_ages:#0"),
        ("fb_ages:Value", "fb_share:#0"),
        ("fb_duration_e:Value", "fb_share:#1"),
        ("fb_share:Value", "fb_len:#0"),
        ("input:Track Length", "fb_len:#1"),
        ("fb_len:Value", "fb_reach:#0"),
        ("ahead:Value", "fb_reach:#1"),
        ("z_s:Value", "z_young:#0"),
        ("fb_reach:Value", "z_young:#1"),
        ("z_band:Value", "z_band_young:#0"),
        ("z_young:Value", "z_band_young:#1"),
        ("foam_mb:Value", "foam_w:#0"),
        ("dev:Max", "foam_w:#1"),
    )
    return nodes, links


def _corner_nodes():
    """The box round the zone's wedge: its four corners, ahead of the bow and past the oldest point."""
    nodes = {
        # The box round the zone: its wedge's four corners (ahead of the bow and past the
        # oldest point, each side of the chord) and a square round the object (a chord of no
        # length: a hull standing still).
        "tz_n": vmath("CROSS_PRODUCT", 50, "across the chord", b=(0.0, 0.0, 1.0)),
        "tz_far_w": math("MULTIPLY_ADD", 50, "the wedge's width past the oldest", b=KELVIN_ZONE_TAN),
        "tz_c_lo": vmath("SCALE", 51, "to ahead of the bow"),
        "tz_c_hi": vmath("SCALE", 51, "to past the oldest"),
        "tz_n_near": vmath("SCALE", 51, "half the width there"),
        "tz_n_far": vmath("SCALE", 51, "half the width there"),
        "tz_lo_at": vmath("ADD", 52, "ahead of the bow"),
        "tz_hi_at": vmath("ADD", 52, "past the oldest"),
        "tz_p1": vmath("ADD", 53, "corner"),
        "tz_p2": vmath("SUBTRACT", 53, "corner"),
        "tz_p3": vmath("ADD", 53, "corner"),
        "tz_p4": vmath("SUBTRACT", 53, "corner"),
    }
    links = (
        ("chord_dir:Vector", "tz_n:#0"),
        ("s_hi_bent:Value", "tz_far_w:#0"),
        ("w1:Value", "tz_far_w:#2"),
        ("chord_dir:Vector", "tz_c_lo:#0"),
        ("s_lo:Value", "tz_c_lo:Scale"),
        ("chord_dir:Vector", "tz_c_hi:#0"),
        ("s_hi_bent:Value", "tz_c_hi:Scale"),
        ("tz_n:Vector", "tz_n_near:#0"),
        ("w1:Value", "tz_n_near:Scale"),
        ("tz_n:Vector", "tz_n_far:#0"),
        ("tz_far_w:Value", "tz_n_far:Scale"),
        ("input:Last", "tz_lo_at:#0"),
        ("tz_c_lo:Vector", "tz_lo_at:#1"),
        ("input:Last", "tz_hi_at:#0"),
        ("tz_c_hi:Vector", "tz_hi_at:#1"),
        ("tz_lo_at:Vector", "tz_p1:#0"),
        ("tz_n_near:Vector", "tz_p1:#1"),
        ("tz_lo_at:Vector", "tz_p2:#0"),
        ("tz_n_near:Vector", "tz_p2:#1"),
        ("tz_hi_at:Vector", "tz_p3:#0"),
        ("tz_n_far:Vector", "tz_p3:#1"),
        ("tz_hi_at:Vector", "tz_p4:#0"),
        ("tz_n_far:Vector", "tz_p4:#1"),
    )
    return nodes, links


def _box_nodes():
    """The box round the zone: round its wedge's corners and a square round the object (a still hull)."""
    nodes = {
        "tz_r": math("ADD", 52, "round the object"),
        "tz_sq_lo": vmath("SUBTRACT", 53, "square's low corner"),
        "tz_sq_hi": vmath("ADD", 53, "square's high corner"),
        "tz_min_a": vmath("MINIMUM", 54, ""),
        "tz_min_b": vmath("MINIMUM", 54, ""),
        "tz_min_c": vmath("MINIMUM", 55, ""),
        "tz_low": vmath("MINIMUM", 56, "the box: low"),
        "tz_max_a": vmath("MAXIMUM", 54, ""),
        "tz_max_b": vmath("MAXIMUM", 54, ""),
        "tz_max_c": vmath("MAXIMUM", 55, ""),
        "tz_high": vmath("MAXIMUM", 56, "the box: high"),
    }
    links = (
        ("ahead:Value", "tz_r:#0"),
        ("w1:Value", "tz_r:#1"),
        ("input:Last", "tz_sq_lo:#0"),
        ("tz_r:Value", "tz_sq_lo:#1"),
        ("input:Last", "tz_sq_hi:#0"),
        ("tz_r:Value", "tz_sq_hi:#1"),
        ("tz_p1:Vector", "tz_min_a:#0"),
        ("tz_p2:Vector", "tz_min_a:#1"),
        ("tz_p3:Vector", "tz_min_b:#0"),
        ("tz_p4:Vector", "tz_min_b:#1"),
        ("tz_min_a:Vector", "tz_min_c:#0"),
        ("tz_min_b:Vector", "tz_min_c:#1"),
        ("tz_min_c:Vector", "tz_low:#0"),
        ("tz_sq_lo:Vector", "tz_low:#1"),
        ("tz_p1:Vector", "tz_max_a:#0"),
        ("tz_p2:Vector", "tz_max_a:#1"),
        ("tz_p3:Vector", "tz_max_b:#0"),
        ("tz_p4:Vector", "tz_max_b:#1"),
        ("tz_max_a:Vector", "tz_max_c:#0"),
        ("tz_max_b:Vector", "tz_max_c:#1"),
        ("tz_max_c:Vector", "tz_high:#0"),
        ("tz_sq_hi:Vector", "tz_high:#1"),
    )
    return nodes, links


def _point_nodes():
    """Each point's zone: 1 in the wedge or the rings' box, 2 near the trail too."""
    nodes = {
        # Each point in the box.
        "z_v": vmath("SUBTRACT", 50, "p - the object"),
        "z_s": vmath("DOT_PRODUCT", 51, "along the chord"),
        "z_cross": vmath("CROSS_PRODUCT", 51, "across"),
        "z_d": vmath("LENGTH", 52, "off the chord"),
        "z_sc": math("MAXIMUM", 52, "behind (> 0)", b=0.0),
        # tan 20.8°: the arms' Airy tail fades a little beyond 19.47°.
        "z_w": math("MULTIPLY_ADD", 53, "the wedge's width here", b=KELVIN_ZONE_TAN),
        "z_in_w": math("LESS_THAN", 54, "within it"),
        "z_after": math("GREATER_THAN", 54, "not ahead of the bow"),
        "z_before": math("LESS_THAN", 54, "not past the oldest"),
        "z_k1": math("MULTIPLY", 55, ""),
        "z_kelvin": math("MULTIPLY", 56, "in the wedge"),
        **box_test(("r_above", "r_below", "r_in"), 53, "the rings' box"),
        "z_waves": math("MAXIMUM", 57, "waves here: 1"),
        "z_band": math("LESS_THAN", 54, "near the trail"),
        "z_foam": math("MULTIPLY", 57, "foam here: 1 more"),
        "zone": math("ADD", 58, "zone: 0, 1 or 2"),
    }
    links = (
        ("z_p_flat:Vector", "z_v:#0"),
        ("input:Last", "z_v:#1"),
        ("z_v:Vector", "z_s:#0"),
        ("chord_dir:Vector", "z_s:#1"),
        ("z_v:Vector", "z_cross:#0"),
        ("chord_dir:Vector", "z_cross:#1"),
        ("z_cross:Vector", "z_d:#0"),
        ("z_s:Value", "z_sc:#0"),
        ("z_sc:Value", "z_w:#0"),
        ("w1:Value", "z_w:#2"),
        ("z_d:Value", "z_in_w:#0"),
        ("z_w:Value", "z_in_w:#1"),
        ("z_s:Value", "z_after:#0"),
        ("s_lo:Value", "z_after:#1"),
        ("z_s:Value", "z_before:#0"),
        ("s_hi_bent:Value", "z_before:#1"),
        ("z_in_w:Value", "z_k1:#0"),
        ("z_after:Value", "z_k1:#1"),
        ("z_k1:Value", "z_kelvin:#0"),
        ("z_before:Value", "z_kelvin:#1"),
        ("z_p_flat:Vector", "r_above:A"),
        ("input:Rings Low", "r_above:B"),
        ("z_p_flat:Vector", "r_below:A"),
        ("input:Rings High", "r_below:B"),
        ("r_above:Result", "r_in:#0"),
        ("r_below:Result", "r_in:#1"),
        ("z_kelvin:Value", "z_waves:#0"),
        ("r_in:Boolean", "z_waves:#1"),
        ("z_d:Value", "z_band:#0"),
        ("foam_w:Value", "z_band:#1"),
        ("z_band_young:Value", "z_foam:#0"),
        ("z_kelvin:Value", "z_foam:#1"),
        ("z_waves:Value", "zone:#0"),
        ("z_foam:Value", "zone:#1"),
    )
    return nodes, links


def _store_nodes():
    """The zone stored on the points in either box (two compares a point), and what the wake reads."""
    nodes = {
        "all_low": vmath("MINIMUM", 57, "both boxes: low"),
        "all_high": vmath("MAXIMUM", 57, "both boxes: high"),
        "low_split": Node("ShaderNodeSeparateXYZ", 57, label="low"),
        "high_split": Node("ShaderNodeSeparateXYZ", 57, label="high"),
        "low_xy": Node("ShaderNodeCombineXYZ", 58, values={"Z": -1e9}, label="low, any height"),
        "high_xy": Node("ShaderNodeCombineXYZ", 58, values={"Z": 1e9}, label="high, any height"),
        **box_test(("above_low", "below_high", "near_track"), 58, "the box"),
        "store_zone": store("wake_zone", "FLOAT", 59),
    }
    links = (
        ("tz_low:Vector", "all_low:#0"),
        ("input:Rings Low", "all_low:#1"),
        ("tz_high:Vector", "all_high:#0"),
        ("input:Rings High", "all_high:#1"),
        ("all_low:Vector", "low_split:Vector"),
        ("all_high:Vector", "high_split:Vector"),
        ("low_split:X", "low_xy:X"),
        ("low_split:Y", "low_xy:Y"),
        ("high_split:X", "high_xy:X"),
        ("high_split:Y", "high_xy:Y"),
        ("z_position:Position", "above_low:A"),
        ("low_xy:Vector", "above_low:B"),
        ("z_position:Position", "below_high:A"),
        ("high_xy:Vector", "below_high:B"),
        ("above_low:Result", "near_track:#0"),
        ("below_high:Result", "near_track:#1"),
        ("input:Geometry", "store_zone:Geometry"),
        ("near_track:Boolean", "store_zone:Selection"),
        ("zone:Value", "store_zone:Value"),
        ("store_zone:Geometry", "output:Geometry"),
        ("ord_dir:Value", "output:Newer"),
        ("tz_low:Vector", "output:Low"),
        ("tz_high:Vector", "output:High"),
    )
    return nodes, links


_NODES, _LINKS = merge(
    _chord_nodes(),
    _wedge_nodes(),
    _band_nodes(),
    _corner_nodes(),
    _box_nodes(),
    _point_nodes(),
    _store_nodes(),
)
SPEC = GroupSpec(
    name=NAME,
    version=2,  # 2: the box and band hold the trail's foam spreading at wake_foam.SPREAD
    description="Where a wake can show: the Kelvin wedge round the track (its chord, how far it strays, "
    "how much longer it is), the rings' box and the foam's band, stored as wake_zone (0 none, "
    "1 waves, 2 waves and foam) on the points in the box round them, the others left as they are",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("Geometry", "NodeSocketGeometry", tooltip="The water"),
        Socket("Track", "NodeSocketGeometry", tooltip="The track's points (wake_time)"),
        Socket("Trail", "NodeSocketGeometry", tooltip="The track's points, drifted"),
        Socket("Rings Low", "NodeSocketVector", tooltip="The rings' box: low corner"),
        Socket("Rings High", "NodeSocketVector", tooltip="The rings' box: high corner"),
        Socket("Last", "NodeSocketVector", tooltip="Where the object is, on the plane"),
        Socket("Time", "NodeSocketFloat", 0.0, tooltip="Seconds now"),
        Socket("Track Length", "NodeSocketFloat", 0.0, tooltip="The track's length along it"),
        Socket("Length", "NodeSocketFloat", 10.0, tooltip="The hull's length"),
        Socket("Beam", "NodeSocketFloat", 3.0, tooltip="Its width"),
        Socket("Foam Fade", "NodeSocketFloat", 6.0, tooltip="Seconds over which the foam fades to a third"),
    ),
    outputs=(
        Socket("Geometry", "NodeSocketGeometry", tooltip="The water, wake_zone stored in the box"),
        Socket("Newer", "NodeSocketFloat", tooltip="+1 when the track's newest point is its last, else -1"),
        Socket("Low", "NodeSocketVector", tooltip="The box round the zone's wedge: low corner"),
        Socket("High", "NodeSocketVector", tooltip="Its high corner"),
    ),
    nodes=_NODES,
    links=_LINKS,
)
