"""The `Water Wake` group's nodes that place each water point in the track's frame.

Each water point in the wake's zone finds its point of the track, and so its place in the
track's frame: `x` metres behind the object along its track (turns included) and `y` across it.
It does so in a few reads whatever the track's length: a 48 x 48 grid over the zone's box knows
each of its points' nearest track point (`_guess_nodes`), and from its grid point's a water
point walks along the track to its own (`_walk`); no nearest-point search a water point, which
made the cost grow with the track. Part of `Water Wake`'s own description (`wake.py`), kept
apart for its length; it reads the nested `track_group` and `zone_group`.
"""

from ..spec import Node, math, vmath
from .wake_parts import clamped_sample, named, sample, store

# Each water point's point of the track, and of its drifted copy (the trail's foam), walked to.
TRACK_INDEX = "tw_i2:Result"
DRIFTED_INDEX = "dw_i1:Result"
GUESS_CELLS = 48  # the guess grid's points a side (48² nearest-point searches a frame)


def frame_nodes():
    """Each water point's place in the track's frame: behind (x), across (y), the speed and age
    there."""
    nodes = {
        "position": Node("GeometryNodeInputPosition", 13),
        "p_flat": vmath("MULTIPLY", 14, "on the plane", b=(1.0, 1.0, 0.0)),
        "t_position": Node("GeometryNodeInputPosition", 15, label="track position"),
        "t_time": named("wake_time", "FLOAT", 15),
        "t_speed": named("wake_speed", "FLOAT", 15),
        "t_arc": named("wake_arc", "FLOAT", 15),
        "t_heading": named("wake_heading", "FLOAT_VECTOR", 15),
        "at_position": sample("FLOAT_VECTOR", 16, "P"),
        # Worked out on the track's few points, not on each water point: g / U² and the
        # height scale (Kriebel and Seelig's, x Strength, faded by the point's age).
        "at_kscale": sample("FLOAT", 16, "its g / U²"),
        "at_amp": sample("FLOAT", 16, "its height scale"),
        "at_arc": sample("FLOAT", 16, "its distance come"),
        "at_heading": sample("FLOAT_VECTOR", 16, "its heading h"),
        "offset": vmath("SUBTRACT", 17, "v = p - P"),
        "along": vmath("DOT_PRODUCT", 18, "v . h"),
        "h_split": Node("ShaderNodeSeparateXYZ", 17, label="h"),
        "v_split": Node("ShaderNodeSeparateXYZ", 18, label="v"),
        "cross_a": math("MULTIPLY", 19, "v.x h.y"),
        "cross_b": math("MULTIPLY", 19, "v.y h.x"),
        "cross": math("SUBTRACT", 20, "v x h"),
        "y": math("ABSOLUTE", 21, "y: across the track"),
        "behind_arc": math("SUBTRACT", 19, "Arc - arc there"),
        "x": math("SUBTRACT", 20, "x: behind along the track"),
        "age": math("SUBTRACT", 19, "each track point's age"),
        "first_arc": Node(
            "GeometryNodeAttributeStatistic", 16, {"domain": "POINT"}, label="where the track begins"
        ),
        "track_length": math("SUBTRACT", 17, "track's length"),
    }
    links = (
        ("position:Position", "p_flat:#0"),
        *(
            link
            for key, source in (
                ("at_position", "t_position:Position"),
                ("at_kscale", "k_scale:Value"),
                ("at_amp", "amp:Value"),
                ("at_arc", "t_arc:Attribute"),
                ("at_heading", "t_heading:Attribute"),
            )
            for link in (
                ("track_group:Track", f"{key}:Geometry"),
                (source, f"{key}:Value"),
                (TRACK_INDEX, f"{key}:Index"),
            )
        ),
        ("p_flat:Vector", "offset:#0"),
        ("at_position:Value", "offset:#1"),
        ("offset:Vector", "along:#0"),
        ("at_heading:Value", "along:#1"),
        ("at_heading:Value", "h_split:Vector"),
        ("offset:Vector", "v_split:Vector"),
        ("v_split:X", "cross_a:#0"),
        ("h_split:Y", "cross_a:#1"),
        ("v_split:Y", "cross_b:#0"),
        ("h_split:X", "cross_b:#1"),
        ("cross_a:Value", "cross:#0"),
        ("cross_b:Value", "cross:#1"),
        ("cross:Value", "y:#0"),
        ("track_group:Arc", "behind_arc:#0"),
        ("at_arc:Value", "behind_arc:#1"),
        ("behind_arc:Value", "x:#0"),
        ("along:Value", "x:#1"),
        ("clock:Seconds", "age:#0"),
        ("t_time:Attribute", "age:#1"),
        ("track_group:Track", "first_arc:Geometry"),
        ("t_arc:Attribute", "first_arc:Attribute"),
        ("track_group:Arc", "track_length:#0"),
        ("first_arc:Min", "track_length:#1"),
    )
    return nodes, links


def _walk(tag, geometry, start, steps, column):
    """Nodes that find the point of a polyline (`geometry`'s points in order of time, the zone's
    `Newer` the way to the newer) whose
    segment a water point `p_flat` lies across, from the index `start` ("node:socket"), in
    `steps` steps: each takes the segment to the newer point, `d`, and moves the index by
    `(p - P) . d / |d|²` segments, rounded and kept within the points, if that point is
    nearer. A few Sample Index reads a point instead of a nearest-point search (0.34 µs a point
    on a 30 s track, BENCHMARKS): the cost no longer follows the track's length.
    `{tag}_i{steps}:Result` is the index found."""
    nodes = {
        f"{tag}_count": Node(
            "GeometryNodeAttributeDomainSize", column, {"component": "POINTCLOUD"}, label="points"
        ),
        f"{tag}_last": math("SUBTRACT", column + 1, "the oldest's index", b=1.0),
        f"{tag}_where": Node("GeometryNodeInputPosition", column),
    }
    links = [
        (geometry, f"{tag}_count:Geometry"),
        (f"{tag}_count:Point Count", f"{tag}_last:#0"),
    ]
    index = start
    for step in range(1, steps + 1):
        nodes |= _walk_step_nodes(tag, step, column + 2 + 6 * (step - 1))
        links += _walk_step_links(tag, geometry, index, step)
        index = f"{tag}_i{step}:Result"
    return nodes, links


def _walk_step_nodes(tag, step, c):
    """One step of `_walk`, its nodes (from column `c`): the index moved along the segment, if nearer."""
    n = f"{tag}_{step}"
    return {
        n + "_at": clamped_sample("FLOAT_VECTOR", c, f"step {step}: its point P"),
        n + "_newer_i": math("ADD", c, "the newer one"),
        n + "_newer": clamped_sample("FLOAT_VECTOR", c + 1, "the newer point"),
        n + "_d": vmath("SUBTRACT", c + 2, "d: the segment to it"),
        n + "_v": vmath("SUBTRACT", c + 2, "p - P"),
        n + "_vd": vmath("DOT_PRODUCT", c + 3, "(p - P) . d"),
        n + "_dd": vmath("DOT_PRODUCT", c + 3, "|d|²"),
        n + "_dd_e": math("ADD", c + 4, "never 0", b=1e-9),
        n + "_t": math("DIVIDE", c + 4, "segments towards the newer"),
        n + "_step": math("MULTIPLY", c + 5, "indices towards the newer"),
        n + "_moved": math("ADD", c + 5, "index + that"),
        n + "_round": math("ROUND", c + 5, "a point's index"),
        n + "_low": math("MAXIMUM", c + 6, "within the points", b=0.0),
        n + "_new": math("MINIMUM", c + 6, "the index stepped to"),
        # Kept only if nearer: beyond a bend's centre the step would lead away.
        n + "_new_at": clamped_sample("FLOAT_VECTOR", c + 7, "its point"),
        n + "_new_d": vmath("DISTANCE", c + 8, "p to it"),
        n + "_old_d": vmath("LENGTH", c + 8, "p to P"),
        n + "_nearer": math("LESS_THAN", c + 9, "nearer"),
        f"{tag}_i{step}": Node(
            "ShaderNodeMix", c + 10, {"data_type": "FLOAT"}, label=f"index after step {step}"
        ),
    }


def _walk_step_links(tag, geometry, index, step):
    """One step of `_walk`, its links: from the index `index` ("node:socket") it starts at."""
    n = f"{tag}_{step}"
    return [
        (geometry, n + "_at:Geometry"),
        (f"{tag}_where:Position", n + "_at:Value"),
        (index, n + "_at:Index"),
        (index, n + "_newer_i:#0"),
        ("zone_group:Newer", n + "_newer_i:#1"),
        (geometry, n + "_newer:Geometry"),
        (f"{tag}_where:Position", n + "_newer:Value"),
        (n + "_newer_i:Value", n + "_newer:Index"),
        (n + "_newer:Value", n + "_d:#0"),
        (n + "_at:Value", n + "_d:#1"),
        ("p_flat:Vector", n + "_v:#0"),
        (n + "_at:Value", n + "_v:#1"),
        (n + "_v:Vector", n + "_vd:#0"),
        (n + "_d:Vector", n + "_vd:#1"),
        (n + "_d:Vector", n + "_dd:#0"),
        (n + "_d:Vector", n + "_dd:#1"),
        (n + "_dd:Value", n + "_dd_e:#0"),
        (n + "_vd:Value", n + "_t:#0"),
        (n + "_dd_e:Value", n + "_t:#1"),
        (index, n + "_moved:#0"),
        (n + "_t:Value", n + "_step:#0"),
        ("zone_group:Newer", n + "_step:#1"),
        (n + "_step:Value", n + "_moved:#1"),
        (n + "_moved:Value", n + "_round:#0"),
        (n + "_round:Value", n + "_low:#0"),
        (n + "_low:Value", n + "_new:#0"),
        (f"{tag}_last:Value", n + "_new:#1"),
        (geometry, n + "_new_at:Geometry"),
        (f"{tag}_where:Position", n + "_new_at:Value"),
        (n + "_new:Value", n + "_new_at:Index"),
        ("p_flat:Vector", n + "_new_d:#0"),
        (n + "_new_at:Value", n + "_new_d:#1"),
        (n + "_v:Vector", n + "_old_d:#0"),
        (n + "_new_d:Value", n + "_nearer:#0"),
        (n + "_old_d:Value", n + "_nearer:#1"),
        (n + "_nearer:Value", f"{tag}_i{step}:Factor"),
        (index, f"{tag}_i{step}:A"),
        (n + "_new:Value", f"{tag}_i{step}:B"),
    ]


def _guess_nodes():
    """Each water point's first guess at its track point, for `_walk`: a grid of 48 x 48
    points over the wake's box finds its nearest track points (a search each, 2,304 a frame,
    whatever the water), and each water point reads its grid point's (a few operations):
    right at once on any track, however it bends, for the walk to finish."""
    n = float(GUESS_CELLS)
    nodes = {
        "gg_index": Node("GeometryNodeInputIndex", 44, label="grid point"),
        "gg_col": math("FLOORED_MODULO", 45, "its column", b=n),
        "gg_row_f": math("DIVIDE", 45, "its row", b=n),
        "gg_row": math("FLOOR", 46, "(whole)"),
        "gg_cr": Node("ShaderNodeCombineXYZ", 47, label="column, row"),
        "gg_extent": vmath("SUBTRACT", 44, "the box's size"),
        "gg_ext_split": Node("ShaderNodeSeparateXYZ", 45, label="size"),
        "gg_ext": math("MAXIMUM", 46, "its larger side"),
        "gg_cell_f": math("DIVIDE", 47, "a grid cell", b=n - 1.0),
        "gg_cell": math("MAXIMUM", 48, "(> 1 mm)", b=1e-3),
        "gg_low": vmath("MULTIPLY", 47, "the box's corner, flat", b=(1.0, 1.0, 0.0)),
        "gg_at": vmath("MULTIPLY_ADD", 48, "where the grid point is"),
        "gg_points": Node("GeometryNodePoints", 49, values={"Count": GUESS_CELLS**2}, label="guess grid"),
        "gg_where": Node("GeometryNodeInputPosition", 49),
        "gg_nearest": Node("GeometryNodeSampleNearest", 50, {"domain": "POINT"}, label="its nearest"),
        "gg_store": store("wake_guess", "FLOAT", 51),
        "gg_read": named("wake_guess", "FLOAT", 51, "each grid point's"),
        # Each water point's grid point.
        "gg_rel": vmath("SUBTRACT", 46, "p - the corner"),
        "gg_per_cell": math("DIVIDE", 47, "a cell's inverse", a=1.0),
        "gg_cells": vmath("SCALE", 48, "in cells"),
        "gg_half": vmath("ADD", 49, "+ half a cell", b=(0.5, 0.5, 0.0)),
        "gg_round": vmath("SNAP", 49, "the nearest grid point", b=(1.0, 1.0, 1.0)),
        "gg_clamp_lo": vmath("MAXIMUM", 50, "within the grid", b=(0.0, 0.0, 0.0)),
        "gg_clamp_hi": vmath("MINIMUM", 51, "", b=(n - 1.0, n - 1.0, 0.0)),
        "gg_split": Node("ShaderNodeSeparateXYZ", 52, label="column, row"),
        "gg_flat_index": math("MULTIPLY_ADD", 53, "its index", b=n),
        "gg_guess": sample("FLOAT", 54, "the first guess"),
    }
    links = [
        ("gg_index:Index", "gg_col:#0"),
        ("gg_index:Index", "gg_row_f:#0"),
        ("gg_row_f:Value", "gg_row:#0"),
        ("gg_col:Value", "gg_cr:X"),
        ("gg_row:Value", "gg_cr:Y"),
        ("zone_group:High", "gg_extent:#0"),
        ("zone_group:Low", "gg_extent:#1"),
        ("gg_extent:Vector", "gg_ext_split:Vector"),
        ("gg_ext_split:X", "gg_ext:#0"),
        ("gg_ext_split:Y", "gg_ext:#1"),
        ("gg_ext:Value", "gg_cell_f:#0"),
        ("gg_cell_f:Value", "gg_cell:#0"),
        ("zone_group:Low", "gg_low:#0"),
        ("gg_cr:Vector", "gg_at:#0"),
        ("gg_cell:Value", "gg_at:#1"),
        ("gg_low:Vector", "gg_at:#2"),
        ("gg_at:Vector", "gg_points:Position"),
        ("track_group:Track", "gg_nearest:Geometry"),
        ("gg_where:Position", "gg_nearest:Sample Position"),
        ("gg_points:Points", "gg_store:Geometry"),
        ("gg_nearest:Index", "gg_store:Value"),
        ("p_flat:Vector", "gg_rel:#0"),
        ("gg_low:Vector", "gg_rel:#1"),
        ("gg_cell:Value", "gg_per_cell:#1"),
        ("gg_rel:Vector", "gg_cells:#0"),
        ("gg_per_cell:Value", "gg_cells:Scale"),
        ("gg_cells:Vector", "gg_half:#0"),
        ("gg_half:Vector", "gg_round:#0"),
        ("gg_round:Vector", "gg_clamp_lo:#0"),
        ("gg_clamp_lo:Vector", "gg_clamp_hi:#0"),
        ("gg_clamp_hi:Vector", "gg_split:Vector"),
        ("gg_split:Y", "gg_flat_index:#0"),
        ("gg_split:X", "gg_flat_index:#2"),
        ("gg_store:Geometry", "gg_guess:Geometry"),
        ("gg_read:Attribute", "gg_guess:Value"),
        ("gg_flat_index:Value", "gg_guess:Index"),
    ]
    return nodes, links


def walk_nodes():
    """Each water point's point of the track (`TRACK_INDEX`) and of its drifted copy (`DRIFTED_INDEX`)."""
    nodes, links = _guess_nodes()
    more_nodes, more_links = _walk("tw", "track_group:Track", "gg_guess:Value", 2, 15)
    nodes |= more_nodes
    links += more_links
    more_nodes, more_links = _walk("dw", "drifted:Geometry", TRACK_INDEX, 1, 19)
    return nodes | more_nodes, links + more_links
