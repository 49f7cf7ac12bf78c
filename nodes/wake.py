"""`Water Wake`: the Kelvin wake and foam one moving object leaves on the water's mesh.

A simulation zone keeps the object's track: a point a frame where it was (in the water's own
space, flattened), with the time, its speed, its heading and the distance it had come by then
(`wake_time`, `wake_speed`, `wake_heading`, `wake_arc`); points older than `Keep` go. Each water
point in the wake's zone (`_zone_nodes`: the others are left as they are) finds its point of the
track, and so its place in the track's frame: `x` metres behind the object along its track
(turns included) and `y` across it. It does so in a few reads whatever the track's length: a
48 x 48 grid over the zone's box knows each of its points' nearest track point
(`_guess_nodes`), and from its grid point's a water point walks along the track to its own
(`_walk`); no nearest-point search a water point, which made the cost grow with the track.

Its height there is the stationary-phase Kelvin pattern of a source moving at the speed the
object had there (deep water, `ω² = g k`). Waves running at `θ` to the track stand still in the
object's frame when `k = g / (U² cos² θ)`, with phase `ψ = k (x cos θ - y sin θ)`; at
`tan α = y / x` the phase is stationary where `2 tan α tan² θ - tan θ + tan α = 0`: two waves
(transverse and diverging) inside the wedge `tan α < 1 / sqrt(8)` (19.47°), none outside it.
Each adds `p̂(k) sqrt(2π / |ψ''|) cos(ψ ± π/4)` (`+` transverse, `-` diverging; `|ψ''| = g x
sec³ θ s / U²`, `s = sqrt(1 - 8 tan² α)`): the hull a Gaussian pressure patch one `Length` long
(Darmon, Benzaquen and Raphaël 2014), so it makes waves about its own length best,
`p̂(k) = (k L / 2π)² exp(1 - (k L / 2π)²)`. That is why above a Froude number of about 0.5 the
highest waves draw in towards the track (about `0.2 / Fr` rad, as Rabaud and Moisy measured)
while the wedge stays 19.47° wide. On the arms the two waves meet and the stationary phase
breaks down: `s` is taken as `sqrt(s² + ε²)`, `ε² = (4 U² / (g x))^(2/3)` (Airy's scale), and
the waves die out over `ε²` beyond. Waves shorter than four mesh cells (`Detail`) are left out.
The height is Kriebel and Seelig's (2005) highest wave one hull length across, which grows
with speed, length and draft against the water's `Depth` (`_height_nodes`), over the
pattern's own height there; it grows in from the hull back over half its length and fades
as `exp(-age / Fade)`. `tests/test_wake.py` compares it over the whole patch
behind the hull with the integral itself (`tools/kelvin_model.py`).

Lengths come in metres (`Length`, `Beam`, `Draft`, `Detail`, `Drift`) and g in m/s²: the group
reads them in the water's own units through its scale (`_units_nodes`), so a scaled water makes
the same wake in metres.

Rings: where the object's origin crosses the water's rest level downwards, a ring: waves twice
its beam long, whose envelope runs out at their group speed (`ω² = g k + (σ/ρ) k³`: gravity
and capillary), fading over 4 s and spreading as the ring grows.

Foam (`water_wake_foam`, 0..1, the larger of this wake's and any before it): round the hull
where it moves through the water, and along the track behind it, drifting with `Drift`
(metres a second, downwind), spreading and fading with time.
"""

from .physics import KELVIN_TAN, KELVIN_ZONE_TAN, SURFACE_TENSION, G
from .spec import GroupSpec, Node, Socket, math, nest, vmath
from .water_waves import NORMAL_ATTRIBUTE

NAME = "Water Wake"
FOAM_ATTRIBUTE = "water_wake_foam"


def _named(name, data_type, column, label=""):
    return Node(
        "GeometryNodeInputNamedAttribute", column, {"data_type": data_type}, {"Name": name}, label or name
    )


def _store(name, data_type, column):
    return Node(
        "GeometryNodeStoreNamedAttribute",
        column,
        {"data_type": data_type, "domain": "POINT"},
        {"Name": name},
        f"store {name}",
    )


def _box_test(keys, column, box):
    """Three nodes (keys: above, below, both): a point above a box's low corner and below its
    high corner, each axis at once (A: the point, B: the corner; "both:Boolean" the answer)."""
    above, below, both = keys
    return {
        above: Node(
            "FunctionNodeCompare",
            column,
            {"data_type": "VECTOR", "mode": "ELEMENT", "operation": "GREATER_THAN"},
            label=f"above {box}'s low corner",
        ),
        below: Node(
            "FunctionNodeCompare",
            column,
            {"data_type": "VECTOR", "mode": "ELEMENT", "operation": "LESS_THAN"},
            label=f"below {box}'s high corner",
        ),
        both: Node("FunctionNodeBooleanMath", column + 1, {"operation": "AND"}, label=f"inside {box}"),
    }


def _sample(data_type, column, label):
    return Node("GeometryNodeSampleIndex", column, {"data_type": data_type, "domain": "POINT"}, label=label)


def _merge(*parts):
    """One description of parts, each (nodes, links): their nodes in order (one key, one node) and
    their links one after the other."""
    nodes, links = {}, []
    for more_nodes, more_links in parts:
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes |= more_nodes
        links += more_links
    return nodes, links


def _track_zone_nodes():
    """The track's simulation zone and what it follows: the object, flat on the water, and the clocks."""
    nodes = {
        "source": Node(
            "GeometryNodeObjectInfo",
            1,
            {"transform_space": "RELATIVE"},
            label="the object, in the water's space",
        ),
        "flat": vmath("MULTIPLY", 2, "on the water's plane", b=(1.0, 1.0, 0.0)),
        "clock": Node("GeometryNodeInputSceneTime", 1, label="seconds"),
        "track_clock": Node("GeometryNodeInputSceneTime", 1, label="seconds"),
        "sim_in": Node(
            "GeometryNodeSimulationInput",
            3,
            values={"Heading": (1.0, 0.0, 0.0)},
            pair="sim_out",
            label="track so far",
        ),
        "sim_out": Node(
            "GeometryNodeSimulationOutput",
            12,
            items=(
                ("GEOMETRY", "Track"),
                ("VECTOR", "Last"),
                ("FLOAT", "Arc"),
                ("VECTOR", "Heading"),
                ("FLOAT", "Started"),
                ("FLOAT", "Speed"),
                ("GEOMETRY", "Rings"),
                ("FLOAT", "Last Z"),
            ),
            values={"Started": 1.0},
            label="track",
        ),
    }
    links = (
        ("input:Source", "source:Object"),
        ("source:Location", "flat:#0"),
        ("flat:Vector", "sim_in:Last"),
    )
    return nodes, links


def _track_step_nodes():
    """This step: how far the object moved, its speed, distance come and heading, stored on a new point."""
    nodes = {
        "step": vmath("SUBTRACT", 4, "moved this step"),
        "step_length": vmath("LENGTH", 5, "metres this step"),
        "moved": math("MULTIPLY", 6, "0 on the first step"),
        "dt": math("MAXIMUM", 5, "step time", b=1e-4),
        "speed": math("DIVIDE", 7, "speed U"),
        "arc": math("ADD", 7, "distance come"),
        "direction": vmath("NORMALIZE", 5, "heading this step"),
        "turned": math("GREATER_THAN", 6, "moved at all", b=1e-4),
        "heading": Node("ShaderNodeMix", 7, {"data_type": "VECTOR"}, label="new heading, or the last"),
        "point": Node("GeometryNodePoints", 8, values={"Count": 1}, label="where it is"),
        "store_time": _store("wake_time", "FLOAT", 8),
        "store_speed": _store("wake_speed", "FLOAT", 9),
        "store_arc": _store("wake_arc", "FLOAT", 9),
        "store_heading": _store("wake_heading", "FLOAT_VECTOR", 10),
    }
    links = (
        ("flat:Vector", "step:#0"),
        ("sim_in:Last", "step:#1"),
        ("step:Vector", "step_length:#0"),
        ("step_length:Value", "moved:#0"),
        ("sim_in:Started", "moved:#1"),
        ("sim_in:Delta Time", "dt:#0"),
        ("moved:Value", "speed:#0"),
        ("dt:Value", "speed:#1"),
        ("sim_in:Arc", "arc:#0"),
        ("moved:Value", "arc:#1"),
        ("step:Vector", "direction:#0"),
        ("moved:Value", "turned:#0"),
        ("turned:Value", "heading:Factor"),
        ("sim_in:Heading", "heading:A"),
        ("direction:Vector", "heading:B"),
        ("flat:Vector", "point:Position"),
        ("point:Points", "store_time:Geometry"),
        ("track_clock:Seconds", "store_time:Value"),
        ("store_time:Geometry", "store_speed:Geometry"),
        ("speed:Value", "store_speed:Value"),
        ("store_speed:Geometry", "store_arc:Geometry"),
        ("arc:Value", "store_arc:Value"),
        ("store_arc:Geometry", "store_heading:Geometry"),
        ("heading:Result", "store_heading:Value"),
    )
    return nodes, links


def _track_keep_nodes():
    """The track kept: the new point joined to the old ones, those older than Keep dropped."""
    nodes = {
        "join": Node("GeometryNodeJoinGeometry", 11, label="track + this point"),
        "old_time": _named("wake_time", "FLOAT", 10, "when each point was"),
        "point_age": math("SUBTRACT", 11, "age"),
        "too_old": math("GREATER_THAN", 12, "older than Keep"),
        "drop": Node("GeometryNodeDeleteGeometry", 12, {"domain": "POINT"}, label="drop the old"),
    }
    links = (
        ("store_heading:Geometry", "join:Geometry"),
        ("sim_in:Track", "join:Geometry"),
        ("join:Geometry", "drop:Geometry"),
        ("track_clock:Seconds", "point_age:#0"),
        ("old_time:Attribute", "point_age:#1"),
        ("point_age:Value", "too_old:#0"),
        ("input:Keep", "too_old:#1"),
        ("too_old:Value", "drop:Selection"),
        ("drop:Geometry", "sim_out:Track"),
        ("flat:Vector", "sim_out:Last"),
        ("arc:Value", "sim_out:Arc"),
        ("heading:Result", "sim_out:Heading"),
        ("speed:Value", "sim_out:Speed"),
    )
    return nodes, links


def _track_nodes():
    """The simulation zone: one point a step where the object is, the old ones dropped."""
    nodes, links = _merge(_track_zone_nodes(), _track_step_nodes(), _track_keep_nodes())
    return nodes, tuple(links)


def _ring_spawn_nodes():
    """Ring points, in the track's zone: where the object's origin drops below the rest level, kept 12 s."""
    nodes = {
        "src_split": Node("ShaderNodeSeparateXYZ", 2, label="its height"),
        "was_above": math("GREATER_THAN", 4, "above the water before", b=0.0),
        "now_below": math("LESS_THAN", 4, "at or below it now", b=1e-4),
        "crossed": math("MULTIPLY", 5, "crossed"),
        "entered": math("MULTIPLY", 6, "entered (not on the first step)"),
        "ring_point": Node("GeometryNodePoints", 8, label="a ring where it entered"),
        "store_ring": _store("wake_ring_time", "FLOAT", 9),
        "rings_join": Node("GeometryNodeJoinGeometry", 11, label="rings + this one"),
        "ring_time_old": _named("wake_ring_time", "FLOAT", 10, "when each ring began"),
        "ring_age_old": math("SUBTRACT", 11, "ring's age"),
        "ring_gone": math("GREATER_THAN", 12, "older than 12 s", b=12.0),
        "rings_drop": Node("GeometryNodeDeleteGeometry", 12, {"domain": "POINT"}, label="drop old rings"),
    }
    links = (
        ("source:Location", "src_split:Vector"),
        ("src_split:Z", "sim_in:Last Z"),
        ("sim_in:Last Z", "was_above:#0"),
        ("src_split:Z", "now_below:#0"),
        ("was_above:Value", "crossed:#0"),
        ("now_below:Value", "crossed:#1"),
        ("crossed:Value", "entered:#0"),
        ("sim_in:Started", "entered:#1"),
        ("entered:Value", "ring_point:Count"),
        ("flat:Vector", "ring_point:Position"),
        ("ring_point:Points", "store_ring:Geometry"),
        ("track_clock:Seconds", "store_ring:Value"),
        ("store_ring:Geometry", "rings_join:Geometry"),
        ("sim_in:Rings", "rings_join:Geometry"),
        ("rings_join:Geometry", "rings_drop:Geometry"),
        ("track_clock:Seconds", "ring_age_old:#0"),
        ("ring_time_old:Attribute", "ring_age_old:#1"),
        ("ring_age_old:Value", "ring_gone:#0"),
        ("ring_gone:Value", "rings_drop:Selection"),
        ("rings_drop:Geometry", "sim_out:Rings"),
        ("src_split:Z", "sim_out:Last Z"),
    )
    return nodes, links


def _ring_nearest_nodes():
    """Each water point's nearest ring: its centre, its age and whether there is any."""
    nodes = {
        # Each water point and the nearest ring.
        "ring_nearest": Node("GeometryNodeSampleNearest", 15, {"domain": "POINT"}, label="nearest ring"),
        "ring_position": Node("GeometryNodeInputPosition", 15, label="ring position"),
        "ring_time": _named("wake_ring_time", "FLOAT", 15),
        "ring_at": _sample("FLOAT_VECTOR", 16, "its centre"),
        "ring_began": _sample("FLOAT", 16, "when it began"),
        "ring_count": Node("GeometryNodeAttributeDomainSize", 16, {"component": "POINTCLOUD"}, label="rings"),
        "has_rings": Node("FunctionNodeCompare", 17, {"data_type": "INT", "operation": "GREATER_THAN"}),
        "ring_r": vmath("DISTANCE", 17, "r"),
        "ring_age": math("SUBTRACT", 17, "its age"),
    }
    links = (
        ("sim_out:Rings", "ring_nearest:Geometry"),
        ("p_flat:Vector", "ring_nearest:Sample Position"),
        ("sim_out:Rings", "ring_at:Geometry"),
        ("ring_position:Position", "ring_at:Value"),
        ("ring_nearest:Index", "ring_at:Index"),
        ("sim_out:Rings", "ring_began:Geometry"),
        ("ring_time:Attribute", "ring_began:Value"),
        ("ring_nearest:Index", "ring_began:Index"),
        ("sim_out:Rings", "ring_count:Geometry"),
        ("ring_count:Point Count", "has_rings:A"),
        ("p_flat:Vector", "ring_r:#0"),
        ("ring_at:Value", "ring_r:#1"),
        ("clock:Seconds", "ring_age:#0"),
        ("ring_began:Value", "ring_age:#1"),
    )
    return nodes, links


def _ring_wave_nodes():
    """The ring's waves: λ = 2 B, ω and the group speed (`ω² = g k + (σ/ρ) k³`), the front's envelope."""
    nodes = {
        "ring_lambda": math("MULTIPLY", 22, "λ = 2 B", b=2.0),
        "ring_k": math("DIVIDE", 23, "k = 2π / λ", a=2.0 * 3.141592653589793),
        "ring_k2": math("MULTIPLY", 24, "k²"),
        "ring_sk2": math("MULTIPLY_ADD", 25, "g + (σ/ρ) k²", b=SURFACE_TENSION, c=G),
        "ring_w2": math("MULTIPLY", 26, "ω² = k (g + (σ/ρ) k²)"),
        "ring_w": math("SQRT", 27, "ω"),
        "ring_cg_num": math("MULTIPLY_ADD", 25, "g + 3 (σ/ρ) k²", b=3.0 * SURFACE_TENSION, c=G),
        "ring_cg_den": math("MULTIPLY", 28, "2 ω", b=2.0),
        "ring_cg": math("DIVIDE", 29, "group speed dω/dk"),
        "ring_front": math("MULTIPLY", 30, "front: group speed x age"),
        "ring_dr": math("SUBTRACT", 31, "r - front"),
        "ring_dr_l": math("DIVIDE", 32, "in wavelengths"),
        "ring_dr2": math("MULTIPLY", 33, "²"),
        "ring_dr2n": math("MULTIPLY", 34, "-", b=-1.0),
        "ring_env": math("EXPONENT", 35, "envelope round the front"),
    }
    links = (
        ("input:Beam", "ring_lambda:#0"),
        ("ring_lambda:Value", "ring_k:#1"),
        ("ring_k:Value", "ring_k2:#0"),
        ("ring_k:Value", "ring_k2:#1"),
        ("ring_k2:Value", "ring_sk2:#0"),
        ("ring_k:Value", "ring_w2:#0"),
        ("ring_sk2:Value", "ring_w2:#1"),
        ("ring_w2:Value", "ring_w:#0"),
        ("ring_k2:Value", "ring_cg_num:#0"),
        ("ring_w:Value", "ring_cg_den:#0"),
        ("ring_cg_num:Value", "ring_cg:#0"),
        ("ring_cg_den:Value", "ring_cg:#1"),
        ("ring_cg:Value", "ring_front:#0"),
        ("ring_age:Value", "ring_front:#1"),
        ("ring_r:Value", "ring_dr:#0"),
        ("ring_front:Value", "ring_dr:#1"),
        ("ring_dr:Value", "ring_dr_l:#0"),
        ("ring_lambda:Value", "ring_dr_l:#1"),
        ("ring_dr_l:Value", "ring_dr2:#0"),
        ("ring_dr_l:Value", "ring_dr2:#1"),
        ("ring_dr2:Value", "ring_dr2n:#0"),
        ("ring_dr2n:Value", "ring_env:#0"),
    )
    return nodes, links


def _ring_height_nodes():
    """The ring's height (phase, spreading, fading, size x Strength), 0 with no ring, added to the wake."""
    nodes = {
        "ring_kr": math("MULTIPLY", 31, "k r"),
        "ring_wt": math("MULTIPLY", 31, "ω t"),
        "ring_phase": math("SUBTRACT", 32, "k r - ω t"),
        "ring_wave": math("COSINE", 33, "cos"),
        "ring_rl": math("ADD", 31, "front + λ"),
        "ring_spread": math("DIVIDE", 32, "λ / (front + λ)"),
        "ring_spread_s": math("SQRT", 33, "spreading"),
        "ring_fade_s": math("DIVIDE", 31, "age / 4 s", b=4.0),
        "ring_fade_n": math("MULTIPLY", 32, "-", b=-1.0),
        "ring_fade": math("EXPONENT", 33, "fading"),
        "ring_size": math("MULTIPLY", 31, "0.3 B", b=0.3),
        "ring_a1": math("MULTIPLY", 36, ""),
        "ring_a2": math("MULTIPLY", 37, ""),
        "ring_a3": math("MULTIPLY", 38, ""),
        "ring_a4": math("MULTIPLY", 39, ""),
        "ring_a5": math("MULTIPLY", 40, "x Strength"),
        # A switch on one value: with no ring, the ring's field is never evaluated.
        "ring": Node(
            "GeometryNodeSwitch", 41, {"input_type": "FLOAT"}, {"False": 0.0}, "ring height, if any"
        ),
        "total": math("ADD", 47, "wake + ring"),
    }
    links = (
        ("ring_k:Value", "ring_kr:#0"),
        ("ring_r:Value", "ring_kr:#1"),
        ("ring_w:Value", "ring_wt:#0"),
        ("ring_age:Value", "ring_wt:#1"),
        ("ring_kr:Value", "ring_phase:#0"),
        ("ring_wt:Value", "ring_phase:#1"),
        ("ring_phase:Value", "ring_wave:#0"),
        ("ring_front:Value", "ring_rl:#0"),
        ("ring_lambda:Value", "ring_rl:#1"),
        ("ring_lambda:Value", "ring_spread:#0"),
        ("ring_rl:Value", "ring_spread:#1"),
        ("ring_spread:Value", "ring_spread_s:#0"),
        ("ring_age:Value", "ring_fade_s:#0"),
        ("ring_fade_s:Value", "ring_fade_n:#0"),
        ("ring_fade_n:Value", "ring_fade:#0"),
        ("input:Beam", "ring_size:#0"),
        ("ring_env:Value", "ring_a1:#0"),
        ("ring_wave:Value", "ring_a1:#1"),
        ("ring_a1:Value", "ring_a2:#0"),
        ("ring_spread_s:Value", "ring_a2:#1"),
        ("ring_a2:Value", "ring_a3:#0"),
        ("ring_fade:Value", "ring_a3:#1"),
        ("ring_a3:Value", "ring_a4:#0"),
        ("ring_size:Value", "ring_a4:#1"),
        ("ring_a4:Value", "ring_a5:#0"),
        ("input:Strength", "ring_a5:#1"),
        ("ring_a5:Value", "ring:True"),
        ("has_rings:Result", "ring:Switch"),
        ("eta:Value", "total:#0"),
        ("ring:Output", "total:#1"),
    )
    return nodes, links


def _ring_nodes():
    """Rings: where the object enters the water (its origin crossing the water's rest level
    downwards), a ring point; each water point takes the nearest ring's waves, `λ` = twice the
    beam long, their envelope running out at the group speed of `ω² = g k + (σ/ρ) k³`."""
    nodes, links = _merge(
        _ring_spawn_nodes(), _ring_nearest_nodes(), _ring_wave_nodes(), _ring_height_nodes()
    )
    return nodes, tuple(links)


def _frame_nodes():
    """Each water point's place in the track's frame: behind (x), across (y), the speed and age
    there."""
    nodes = {
        "position": Node("GeometryNodeInputPosition", 13),
        "p_flat": vmath("MULTIPLY", 14, "on the plane", b=(1.0, 1.0, 0.0)),
        "t_position": Node("GeometryNodeInputPosition", 15, label="track position"),
        "t_time": _named("wake_time", "FLOAT", 15),
        "t_speed": _named("wake_speed", "FLOAT", 15),
        "t_arc": _named("wake_arc", "FLOAT", 15),
        "t_heading": _named("wake_heading", "FLOAT_VECTOR", 15),
        "at_position": _sample("FLOAT_VECTOR", 16, "P"),
        # Worked out on the track's few points, not on each water point: g / U² and the
        # height scale (Kriebel and Seelig's, x Strength, faded by the point's age).
        "at_kscale": _sample("FLOAT", 16, "its g / U²"),
        "at_amp": _sample("FLOAT", 16, "its height scale"),
        "at_arc": _sample("FLOAT", 16, "its distance come"),
        "at_heading": _sample("FLOAT_VECTOR", 16, "its heading h"),
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
                ("sim_out:Track", f"{key}:Geometry"),
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
        ("sim_out:Arc", "behind_arc:#0"),
        ("at_arc:Value", "behind_arc:#1"),
        ("behind_arc:Value", "x:#0"),
        ("along:Value", "x:#1"),
        ("clock:Seconds", "age:#0"),
        ("t_time:Attribute", "age:#1"),
        ("sim_out:Track", "first_arc:Geometry"),
        ("t_arc:Attribute", "first_arc:Attribute"),
        ("sim_out:Arc", "track_length:#0"),
        ("first_arc:Min", "track_length:#1"),
    )
    return nodes, links


def _walk(tag, geometry, start, steps, column):
    """Nodes that find the point of a polyline (`geometry`'s points in order of time, `ord_dir`
    the way to the newer) whose
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
        n + "_at": _clamped_sample("FLOAT_VECTOR", c, f"step {step}: its point P"),
        n + "_newer_i": math("ADD", c, "the newer one"),
        n + "_newer": _clamped_sample("FLOAT_VECTOR", c + 1, "the newer point"),
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
        n + "_new_at": _clamped_sample("FLOAT_VECTOR", c + 7, "its point"),
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
        ("ord_dir:Value", n + "_newer_i:#1"),
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
        ("ord_dir:Value", n + "_step:#1"),
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


GUESS_CELLS = 48  # the guess grid's points a side (48² nearest-point searches a frame)


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
        "gg_store": _store("wake_guess", "FLOAT", 51),
        "gg_read": _named("wake_guess", "FLOAT", 51, "each grid point's"),
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
        "gg_guess": _sample("FLOAT", 54, "the first guess"),
    }
    links = [
        ("gg_index:Index", "gg_col:#0"),
        ("gg_index:Index", "gg_row_f:#0"),
        ("gg_row_f:Value", "gg_row:#0"),
        ("gg_col:Value", "gg_cr:X"),
        ("gg_row:Value", "gg_cr:Y"),
        ("tz_high:Vector", "gg_extent:#0"),
        ("tz_low:Vector", "gg_extent:#1"),
        ("gg_extent:Vector", "gg_ext_split:Vector"),
        ("gg_ext_split:X", "gg_ext:#0"),
        ("gg_ext_split:Y", "gg_ext:#1"),
        ("gg_ext:Value", "gg_cell_f:#0"),
        ("gg_cell_f:Value", "gg_cell:#0"),
        ("tz_low:Vector", "gg_low:#0"),
        ("gg_cr:Vector", "gg_at:#0"),
        ("gg_cell:Value", "gg_at:#1"),
        ("gg_low:Vector", "gg_at:#2"),
        ("gg_at:Vector", "gg_points:Position"),
        ("sim_out:Track", "gg_nearest:Geometry"),
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


# Each water point's point of the track, and of its drifted copy (the trail's foam), walked to.
TRACK_INDEX = "tw_i2:Result"
DRIFTED_INDEX = "dw_i1:Result"


def _walks():
    nodes, links = _guess_nodes()
    more_nodes, more_links = _walk("tw", "sim_out:Track", "gg_guess:Value", 2, 15)
    nodes |= more_nodes
    links += more_links
    more_nodes, more_links = _walk("dw", "drifted:Geometry", TRACK_INDEX, 1, 19)
    return nodes | more_nodes, links + more_links


def _root_wave(tag, tau, sign, column):
    """One stationary wave's shape: k = g / (U² cos² θ) and cos(ψ ± π/4)."""
    n = f"{tag}_"
    nodes = {
        n + "tau2": math("MULTIPLY", column, f"{tag}: tan² θ"),
        n + "q2": math("ADD", column + 1, "1 + tan² θ = 1 / cos² θ", b=1.0),
        n + "q": math("SQRT", column + 2, "1 / cos θ"),
        n + "k": math("MULTIPLY", column + 2, "k = g / (U² cos² θ)"),
        n + "y_tau": math("MULTIPLY", column, "y tan θ"),
        n + "path": math("SUBTRACT", column + 1, "x - y tan θ"),
        n + "phase_a": math("MULTIPLY", column + 3, "(x - y tan θ) / cos θ"),
        n + "phase": math(
            "MULTIPLY_ADD", column + 4, "k (x cos θ - y sin θ) ± π/4", c=sign * 3.141592653589793 / 4.0
        ),
        n + "wave": math("COSINE", column + 5, "cos"),
    }
    links = (
        (tau, n + "tau2:#0"),
        (tau, n + "tau2:#1"),
        (n + "tau2:Value", n + "q2:#0"),
        (n + "q2:Value", n + "q:#0"),
        (n + "q2:Value", n + "k:#0"),
        ("at_kscale:Value", n + "k:#1"),
        ("y:Value", n + "y_tau:#0"),
        (tau, n + "y_tau:#1"),
        ("x_pos:Value", n + "path:#0"),
        (n + "y_tau:Value", n + "path:#1"),
        (n + "path:Value", n + "phase_a:#0"),
        (n + "q:Value", n + "phase_a:#1"),
        (n + "phase_a:Value", n + "phase:#0"),
        ("at_kscale:Value", n + "phase:#1"),
        (n + "phase:Value", n + "wave:#0"),
    )
    return nodes, links


def _root_size(tag, column):
    """One stationary wave's size (the hull's share p̂(k), sqrt(2π / |ψ''|), the mesh's weight) x its shape."""
    n = f"{tag}_"
    nodes = {
        # The hull's share of waves k long: (k L / 2π)² exp(1 - (k L / 2π)²), 1 at λ = L.
        n + "kl": math("MULTIPLY", column + 3, "k L / 2π"),
        n + "kl2": math("MULTIPLY", column + 4, "(k L / 2π)²"),
        n + "spec_arg": math("SUBTRACT", column + 5, "1 - (k L / 2π)²", a=1.0),
        n + "spec_exp": math("EXPONENT", column + 6, "exp"),
        n + "spec": math("MULTIPLY", column + 7, "p̂(k): the hull's share"),
        # |ψ''| = g/U² x sec³ θ x s (s the wedge's root): the wave's stationary-phase size.
        n + "q3": math("MULTIPLY", column + 3, "sec³ θ"),
        n + "curv": math("MULTIPLY", column + 4, "|ψ''|"),
        n + "sp2": math("DIVIDE", column + 5, "2π / |ψ''|", a=2.0 * 3.141592653589793),
        n + "sp": math("SQRT", column + 6, "sqrt(2π / |ψ''|)"),
        n + "lambda": math("DIVIDE", column + 3, "wavelength", a=2.0 * 3.141592653589793),
        n + "mesh": math("DIVIDE", column + 4, "wavelength / 4 cells"),
        n + "mesh_w": Node(
            "ShaderNodeMapRange",
            column + 5,
            {"clamp": True},
            {"From Min": 0.5, "From Max": 1.0, "To Min": 0.0, "To Max": 1.0},
            label="the mesh can hold it",
        ),
        n + "size": math("MULTIPLY", column + 8, "p̂ x sqrt(2π / |ψ''|)"),
        n + "weight": math("MULTIPLY", column + 9, "where the mesh holds it"),
        n + "term": math("MULTIPLY", column + 10, f"{tag} term"),
    }
    links = (
        (n + "k:Value", n + "kl:#0"),
        ("l_2pi:Value", n + "kl:#1"),
        (n + "kl:Value", n + "kl2:#0"),
        (n + "kl:Value", n + "kl2:#1"),
        (n + "kl2:Value", n + "spec_arg:#1"),
        (n + "spec_arg:Value", n + "spec_exp:#0"),
        (n + "kl2:Value", n + "spec:#0"),
        (n + "spec_exp:Value", n + "spec:#1"),
        (n + "q2:Value", n + "q3:#0"),
        (n + "q:Value", n + "q3:#1"),
        (n + "q3:Value", n + "curv:#0"),
        ("sp_base:Value", n + "curv:#1"),
        (n + "curv:Value", n + "sp2:#1"),
        (n + "sp2:Value", n + "sp:#0"),
        (n + "k:Value", n + "lambda:#1"),
        (n + "lambda:Value", n + "mesh:#0"),
        ("four_cells:Value", n + "mesh:#1"),
        (n + "mesh:Value", n + "mesh_w:Value"),
        (n + "spec:Value", n + "size:#0"),
        (n + "sp:Value", n + "size:#1"),
        (n + "size:Value", n + "weight:#0"),
        (n + "mesh_w:Result", n + "weight:#1"),
        (n + "weight:Value", n + "term:#0"),
        (n + "wave:Value", n + "term:#1"),
    )
    return nodes, links


def _root(tag, tau, sign, column):
    """One stationary wave (tan θ from `tau`, a "node:socket"): its term, the stationary-phase
    share `p̂(k) sqrt(2π / |ψ''|)` x `cos(ψ ± π/4)` (`sign`: +1 transverse, -1 diverging), made
    smaller where it is shorter than four mesh cells (`Detail`)."""
    nodes, links = _merge(_root_wave(tag, tau, sign, column), _root_size(tag, column))
    return nodes, tuple(links)


def _kelvin_scale_nodes():
    """The pattern's scales: g / U², Fr², the fading with age and the ramp from the hull back."""
    nodes = {
        "u": math("MAXIMUM", 22, "U (> 0.2 m/s)", b=0.2),
        "u2": math("MULTIPLY", 23, "U²"),
        "k_scale": math("DIVIDE", 24, "g / U²", a=G),
        "fr2": math("DIVIDE", 24, "Fr² = U² / (g L)"),
        "gl": math("MULTIPLY", 23, "g L", a=G),
        "age_s": math("DIVIDE", 23, "age / Fade"),
        "age_neg": math("MULTIPLY", 24, "-", b=-1.0),
        "fade": math("EXPONENT", 25, "exp(-age / Fade)"),
        "half_l": math("MULTIPLY", 22, "L / 2", b=0.5),
        "ramp": Node(
            "ShaderNodeMapRange",
            24,
            {"clamp": True, "interpolation_type": "SMOOTHSTEP"},
            label="from the hull back",
        ),
        "in_track": math("LESS_THAN", 22, "not behind where it began"),
        "in_track_x": math("ADD", 21, "track's length + 1 cell"),
    }
    links = [
        ("t_speed:Attribute", "u:#0"),
        ("u:Value", "u2:#0"),
        ("u:Value", "u2:#1"),
        ("u2:Value", "k_scale:#1"),
        ("input:Length", "gl:#1"),
        ("u2:Value", "fr2:#0"),
        ("gl:Value", "fr2:#1"),
        ("age:Value", "age_s:#0"),
        ("input:Fade", "age_s:#1"),
        ("age_s:Value", "age_neg:#0"),
        ("age_neg:Value", "fade:#0"),
        ("input:Length", "half_l:#0"),
        ("x:Value", "ramp:Value"),
        ("half_l:Value", "ramp:From Max"),
        ("track_length:Value", "in_track_x:#0"),
        ("input:Detail", "in_track_x:#1"),
        ("x:Value", "in_track:#0"),
        ("in_track_x:Value", "in_track:#1"),
    ]
    return nodes, links


def _kelvin_set_nodes():
    """The height set: the pattern x its scales, lifted, on the points of the zone and the rings' box."""
    nodes = {
        "kelvin": Node("GeometryNodeGroup", 30, label="Kelvin's pattern", group=KELVIN_NAME),
        "e3": math("MULTIPLY", 43, ""),
        "amp": math("MULTIPLY", 27, "faded height scale"),
        "e6": math("MULTIPLY", 46, ""),
        "eta": math("MULTIPLY", 47, "height"),
        "lift": Node("ShaderNodeCombineXYZ", 48, label="up by the height"),
        # Only the points near the track are computed (a field is evaluated only where its
        # node's selection holds): the box round the zone (`_zone_nodes`) and the rings' box,
        # wider by how far a ring runs out in its 12 s. Two compares a point.
        "ring_box": Node("GeometryNodeBoundBox", 41, label="the rings' box"),
        "ring_reach": math("MULTIPLY_ADD", 41, "a ring's reach: group speed x 12 s + 2 λ", b=12.0),
        "ring_twice": math("MULTIPLY", 40, "2 λ", b=2.0),
        "ring_none": math("MULTIPLY_ADD", 42, "none: far below zero", b=1e7, c=-1e7),
        "ring_margin": math("ADD", 43, "ring margin"),
        "ring_low": vmath("SUBTRACT", 44, "rings' low corner"),
        "ring_high": vmath("ADD", 44, "rings' high corner"),
        "set": Node("GeometryNodeSetPosition", 49, label="the wake"),
    }
    links = [
        ("x:Value", "kelvin:X"),
        ("y:Value", "kelvin:Y"),
        ("at_kscale:Value", "kelvin:K"),
        ("input:Length", "kelvin:Length"),
        ("input:Detail", "kelvin:Detail"),
        ("kelvin:Pattern", "e3:#0"),
        ("at_amp:Value", "e3:#1"),
        ("strength:Value", "amp:#0"),
        ("fade:Value", "amp:#1"),
        ("e3:Value", "e6:#0"),
        ("ramp:Result", "e6:#1"),
        ("e6:Value", "eta:#0"),
        ("in_track:Value", "eta:#1"),
        ("total:Value", "lift:Z"),
        ("store_zone:Geometry", "set:Geometry"),
        ("lift:Vector", "set:Offset"),
        ("sim_out:Rings", "ring_box:Geometry"),
        ("ring_lambda:Value", "ring_twice:#0"),
        ("ring_cg:Value", "ring_reach:#0"),
        ("ring_twice:Value", "ring_reach:#2"),
        ("has_rings:Result", "ring_none:#0"),
        ("ring_reach:Value", "ring_margin:#0"),
        ("ring_none:Value", "ring_margin:#1"),
        ("ring_box:Min", "ring_low:#0"),
        ("ring_margin:Value", "ring_low:#1"),
        ("ring_box:Max", "ring_high:#0"),
        ("ring_margin:Value", "ring_high:#1"),
        ("in_wake:Value", "set:Selection"),
    ]
    return nodes, links


def _kelvin_nodes():
    """The height: Kelvin's pattern (`KELVIN_SPEC`) x its size, faded, grown in from the hull."""
    nodes, links = _merge(_kelvin_scale_nodes(), _kelvin_set_nodes())
    return nodes, tuple(links)


def _pattern_wedge_nodes():
    """The wedge: tan α = y / x, its root s and the two stationary waves' tan θ."""
    nodes = {
        "x_pos": math("MAXIMUM", 22, "x (> 0)", b=1e-3),
        "tan_a": math("DIVIDE", 23, "tan α = y / x"),
        "t": math("MAXIMUM", 24, "tan α (> 0)", b=1e-4),
        "t2": math("MULTIPLY", 25, "tan² α"),
        "disc": math("MULTIPLY_ADD", 26, "1 - 8 tan² α: > 0 inside the wedge", b=-8.0, c=1.0),
        "disc_in": math("MAXIMUM", 27, "0 outside", b=0.0),
        "s": math("SQRT", 28, "s"),
        "one_s": math("ADD", 29, "1 + s", b=1.0),
        "two_t": math("MULTIPLY", 29, "2 tan α", b=2.0),
        "tau_t": math("DIVIDE", 30, "transverse: tan θ = 2 tan α / (1 + s)"),
        "four_t": math("MULTIPLY", 29, "4 tan α", b=4.0),
        "tau_d": math("DIVIDE", 30, "diverging: tan θ = (1 + s) / (4 tan α)"),
    }
    links = [
        ("input:X", "x_pos:#0"),
        ("input:Y", "tan_a:#0"),
        ("x_pos:Value", "tan_a:#1"),
        ("tan_a:Value", "t:#0"),
        ("t:Value", "t2:#0"),
        ("t:Value", "t2:#1"),
        ("t2:Value", "disc:#0"),
        ("disc:Value", "disc_in:#0"),
        ("disc_in:Value", "s:#0"),
        ("s:Value", "one_s:#0"),
        ("t:Value", "two_t:#0"),
        ("two_t:Value", "tau_t:#0"),
        ("one_s:Value", "tau_t:#1"),
        ("t:Value", "four_t:#0"),
        ("one_s:Value", "tau_d:#0"),
        ("four_t:Value", "tau_d:#1"),
    ]
    return nodes, links


def _pattern_arms_nodes():
    """The roots' scales (4 cells, L / 2π), Airy's width on the arms, the fall beyond them and the sum."""
    nodes = {
        "four_cells": math("MULTIPLY", 22, "4 cells", b=4.0),
        "sum": math("ADD", 40, "both waves"),
        "l_2pi": math("DIVIDE", 22, "L / 2π", b=2.0 * 3.141592653589793),
        "x_amp": math("MAXIMUM", 23, "x, past the hull's first quarter"),
        "l_quarter": math("MULTIPLY", 22, "L / 4", b=0.25),
        "kx": math("MULTIPLY", 24, "g x / U²"),
        "a_kx": math("DIVIDE", 25, "4 U² / (g x)", a=4.0),
        "eps2": math("POWER", 26, "ε²", b=2.0 / 3.0),
        "s2_eff": math("ADD", 28, "s² + ε²"),
        "s_eff": math("SQRT", 29, "s, finite on the arms"),
        "sp_base": math("MULTIPLY", 30, "g x / U² x s"),
        "beyond": math("MINIMUM", 27, "how far outside (< 0)", b=0.0),
        "beyond_s": math("DIVIDE", 28, "/ ε²"),
        "outside": math("EXPONENT", 29, "fades just beyond the arms"),
        # The stationary phase breaks down on the arms, where the two waves meet (s = 0): there
        # the sum is Airy's, its size falling as (g x / U²)^(-1/3). s is taken as
        # sqrt(s² + ε²), ε² = (4 U² / (g x))^(2/3), and the waves die out beyond the arms over ε².
        "e1": math("MULTIPLY", 41, "the pattern"),
    }
    links = [
        ("input:Detail", "four_cells:#0"),
        ("t_term:Value", "sum:#0"),
        ("d_term:Value", "sum:#1"),
        ("input:Length", "l_2pi:#0"),
        ("input:Length", "l_quarter:#0"),
        ("x_pos:Value", "x_amp:#0"),
        ("l_quarter:Value", "x_amp:#1"),
        ("input:K", "kx:#0"),
        ("x_amp:Value", "kx:#1"),
        ("kx:Value", "a_kx:#1"),
        ("a_kx:Value", "eps2:#0"),
        ("disc_in:Value", "s2_eff:#0"),
        ("eps2:Value", "s2_eff:#1"),
        ("s2_eff:Value", "s_eff:#0"),
        ("kx:Value", "sp_base:#0"),
        ("s_eff:Value", "sp_base:#1"),
        ("disc:Value", "beyond:#0"),
        ("beyond:Value", "beyond_s:#0"),
        ("eps2:Value", "beyond_s:#1"),
        ("beyond_s:Value", "outside:#0"),
        ("sum:Value", "e1:#0"),
        ("outside:Value", "e1:#1"),
        ("e1:Value", "output:Pattern"),
    ]
    return nodes, links


def _pattern_nodes():
    """Kelvin's pattern inside its group: the two stationary waves inside the wedge (the roots
    of `2 t τ² - τ + t = 0`), Airy's width on the arms and the fall beyond them."""
    nodes, links = _merge(_pattern_wedge_nodes(), _pattern_arms_nodes())
    for tag, tau, sign in (("t", "tau_t:Value", 1.0), ("d", "tau_d:Value", -1.0)):
        more_nodes, more_links = _root(tag, tau, sign, 31)
        nodes |= more_nodes
        links += [tuple(RENAMED.get(end, end) for end in link) for link in more_links]
    return nodes, tuple(links)


# Inside the pattern's group, what the wake's group feeds it.
RENAMED = {"x:Value": "input:X", "y:Value": "input:Y", "at_kscale:Value": "input:K"}
KELVIN_NAME = "Water Wake Kelvin"
KELVIN_SPEC = GroupSpec(
    name=KELVIN_NAME,
    version=1,
    description="Kelvin's pattern behind a moving pressure patch: the two stationary waves, the "
    "wedge and Airy's arms (a field, in the hull's frame)",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("X", "NodeSocketFloat", 1.0, tooltip="Distance behind the hull, along its track"),
        Socket("Y", "NodeSocketFloat", 0.0, tooltip="Distance across the track, either side (≥ 0)"),
        Socket("K", "NodeSocketFloat", 1.0, tooltip="g / U²: the transverse waves' wavenumber"),
        Socket("Length", "NodeSocketFloat", 1.0, tooltip="The hull's length: it makes waves this long best"),
        Socket("Detail", "NodeSocketFloat", 0.0, tooltip="A mesh cell: waves shorter than four are left out"),
    ),
    outputs=(Socket("Pattern", "NodeSocketFloat", tooltip="The height, before its size and fading"),),
    nodes=_pattern_nodes()[0],
    links=_pattern_nodes()[1],
)


# Kriebel and Seelig (2005, "An empirical model for ship-generated waves"): the highest wave a
# hull leaves at `y` across its track, `g H / U² = β (F* - 0.1)² (y / L)^(-1/3)`, with the
# Froude number raised by the draft `T` against the depth `d`, `F* = F exp(α T / d)`,
# `α = 2.35 (1 - Cb)`. Cb (the hull's block coefficient) is taken as a small craft's 0.6; β
# (1 for a hull whose bow is half its length, about 1.6 a third, 4 a quarter) is `Strength`.
# Their data reach F* 0.5: F* and F are each held there, so the height grows with speed and
# draft up to it and no further (faster hulls plane; their waves break).
KS_ALPHA = 2.35 * (1.0 - 0.6)
KS_F_LOW, KS_F_HIGH = 0.1, 0.5
# The group's own pattern's crest-to-trough height one hull length across, by Froude number:
# ln N = c0 + c1 / Fr + c2 / Fr² + c3 / Fr⁴ + c4 ln Fr, Fr in 0.25..3 (tools/wake_heights.py
# fits it, within 5%). The height scale is Kriebel and Seelig's height at y = L over N.
PATTERN_HEIGHT = (-2.587192, 2.640087, -0.540814, -0.015939, -0.123133)
PATTERN_FROUDE = (0.25, 3.0)
DEPTH_DEFAULT = 10.0  # m: the Depth socket's default
SHADING_NORMAL = NORMAL_ATTRIBUTE  # the normal the seeds' ocean shades with


def _height_nodes():
    """The height scale, worked out on the track's points: Kriebel and Seelig's highest wave a
    hull length across (`H / L = β (F_c - 0.1)² min(F, 0.5)²`, `F_c = min(F e, 0.5)`,
    `e = exp(α T / d)`), over the pattern's own height there (`N(Fr)`), x Strength."""
    c0, c1, c2, c3, c4 = PATTERN_HEIGHT
    nodes = {
        "fr": math("SQRT", 25, "Fr"),
        "td": math("DIVIDE", 24, "T / d"),
        "td_a": math("MULTIPLY", 25, "α T / d", b=KS_ALPHA),
        "ks_e": math("EXPONENT", 26, "e = exp(α T / d)"),
        "fstar": math("MULTIPLY", 26, "F* = F e"),
        "fc": math("MINIMUM", 27, "F*, held at 0.5", b=KS_F_HIGH),
        "excess": math("SUBTRACT", 28, "F* - 0.1", b=KS_F_LOW),
        "excess_in": math("MAXIMUM", 29, "(> 0)", b=0.0),
        "excess2": math("MULTIPLY", 30, "(F* - 0.1)²"),
        "fv": math("MINIMUM", 28, "F, held at 0.5", b=KS_F_HIGH),
        "fv2": math("MULTIPLY", 29, "F² = U² / (g L)"),
        "h_per_l": math("MULTIPLY", 31, "g H / U² x U² / (g L) = H / L"),
        "h_ks": math("MULTIPLY", 32, "H at y = L (units up)"),
        "fr_in": math("MAXIMUM", 26, "Fr, 0.25 ..", b=PATTERN_FROUDE[0]),
        "fr_c": math("MINIMUM", 27, ".. 3", b=PATTERN_FROUDE[1]),
        "inv": math("DIVIDE", 28, "1 / Fr", a=1.0),
        "inv2": math("MULTIPLY", 29, "1 / Fr²"),
        "inv4": math("MULTIPLY", 30, "1 / Fr⁴"),
        "ln_fr": math("LOGARITHM", 28, "ln Fr", b=2.718281828459045),
        "n1": math("MULTIPLY_ADD", 29, "c0 + c1 / Fr", b=c1, c=c0),
        "n2": math("MULTIPLY_ADD", 30, "+ c2 / Fr²", b=c2),
        "n3": math("MULTIPLY_ADD", 31, "+ c3 / Fr⁴", b=c3),
        "n4": math("MULTIPLY_ADD", 32, "+ c4 ln Fr: ln N", b=c4),
        "n": math("EXPONENT", 33, "N: the pattern's height at y = L"),
        "height": math("DIVIDE", 34, "height scale: H / N"),
        "strength": math("MULTIPLY", 35, "x Strength (β)"),
    }
    links = (
        ("fr2:Value", "fr:#0"),
        ("input:Draft", "td:#0"),
        ("depth_u:Value", "td:#1"),
        ("td:Value", "td_a:#0"),
        ("td_a:Value", "ks_e:#0"),
        ("fr:Value", "fstar:#0"),
        ("ks_e:Value", "fstar:#1"),
        ("fstar:Value", "fc:#0"),
        ("fc:Value", "excess:#0"),
        ("excess:Value", "excess_in:#0"),
        ("excess_in:Value", "excess2:#0"),
        ("excess_in:Value", "excess2:#1"),
        ("fr:Value", "fv:#0"),
        ("fv:Value", "fv2:#0"),
        ("fv:Value", "fv2:#1"),
        ("excess2:Value", "h_per_l:#0"),
        ("fv2:Value", "h_per_l:#1"),
        ("h_per_l:Value", "h_ks:#0"),
        ("length_up:Value", "h_ks:#1"),
        ("fr:Value", "fr_in:#0"),
        ("fr_in:Value", "fr_c:#0"),
        ("fr_c:Value", "inv:#1"),
        ("inv:Value", "inv2:#0"),
        ("inv:Value", "inv2:#1"),
        ("inv2:Value", "inv4:#0"),
        ("inv2:Value", "inv4:#1"),
        ("fr_c:Value", "ln_fr:#0"),
        ("inv:Value", "n1:#0"),
        ("inv2:Value", "n2:#0"),
        ("n1:Value", "n2:#2"),
        ("inv4:Value", "n3:#0"),
        ("n2:Value", "n3:#2"),
        ("ln_fr:Value", "n4:#0"),
        ("n3:Value", "n4:#2"),
        ("n4:Value", "n:#0"),
        ("h_ks:Value", "height:#0"),
        ("n:Value", "height:#1"),
        ("height:Value", "strength:#0"),
        ("input:Strength", "strength:#1"),
    )
    return nodes, links


def _normal_nodes():
    """Where the shading reads a stored normal (`Water Waves`' analytic `water_normal`, the
    seeds' ocean) rather than the mesh's, that normal is the mesh's where the wake moved it,
    so the wake's waves show in the light too; with `Shading Normal` off it is never worked out."""
    nodes = {
        "mesh_normal": Node("GeometryNodeInputNormal", 50, label="the mesh's normal, the wake's in it"),
        "store_normal": _store(SHADING_NORMAL, "FLOAT_VECTOR", 50),
        "normal_switch": Node(
            "GeometryNodeSwitch", 51, {"input_type": "GEOMETRY"}, label="the shading's normal too?"
        ),
    }
    links = (
        ("set:Geometry", "store_normal:Geometry"),
        ("in_wake:Value", "store_normal:Selection"),
        ("mesh_normal:Normal", "store_normal:Value"),
        ("input:Shading Normal", "normal_switch:Switch"),
        ("set:Geometry", "normal_switch:False"),
        ("store_normal:Geometry", "normal_switch:True"),
    )
    return nodes, links


def _interface(name, description, inputs, outputs):
    """The sockets of a part carved out by `nest` (which fills its nodes and links)."""
    return GroupSpec(
        name=name,
        version=1,
        description=description,
        tree_type="GeometryNodeTree",
        inputs=inputs,
        outputs=outputs,
        nodes={},
        links=(),
    )


HEIGHT_INTERFACE = _interface(
    "Water Wake Height",
    "Kriebel and Seelig's highest wave a hull length across, over the Kelvin "
    "pattern's own height there: the pattern's scale",
    (
        Socket("Fr²", "NodeSocketFloat", 0.25, tooltip="U² / (g L): the hull's Froude number, squared"),
        Socket("Draft", "NodeSocketFloat", 0.5, tooltip="How deep the hull sits (as Depth)"),
        Socket("Depth", "NodeSocketFloat", DEPTH_DEFAULT, tooltip="The water's depth (as Draft)"),
        Socket("Length", "NodeSocketFloat", 1.0, tooltip="The hull's length, in the height's units"),
        Socket("Strength", "NodeSocketFloat", 1.0, tooltip="Kriebel and Seelig's β"),
    ),
    (Socket("Height", "NodeSocketFloat", tooltip="The pattern's scale"),),
)
HEIGHT_CROSSINGS = (
    {
        "fr2:Value": "Fr²",
        "draft_u:Value": "Draft",
        "depth_u:Value": "Depth",
        "length_up:Value": "Length",
        "input:Strength": "Strength",
    },
    {"strength:Value": "Height"},
)
RING_KEYS = (
    *("ring_lambda", "ring_k", "ring_k2", "ring_sk2", "ring_w2", "ring_w", "ring_cg_num"),
    *("ring_cg_den", "ring_cg", "ring_front", "ring_dr", "ring_dr_l", "ring_dr2", "ring_dr2n"),
    *("ring_env", "ring_kr", "ring_wt", "ring_phase", "ring_wave", "ring_rl", "ring_spread"),
    *("ring_spread_s", "ring_fade_s", "ring_fade_n", "ring_fade", "ring_size"),
    *("ring_a1", "ring_a2", "ring_a3", "ring_a4", "ring_a5"),
)
RING_INTERFACE = _interface(
    "Water Wake Ring",
    "The ring of waves an object leaves where it drops in: waves twice its beam long "
    "round a front running out at their group speed, spreading and fading",
    (
        Socket("R", "NodeSocketFloat", 0.0, tooltip="Distance from where it dropped in"),
        Socket("Age", "NodeSocketFloat", 0.0, tooltip="Seconds since"),
        Socket("Beam", "NodeSocketFloat", 1.0, tooltip="Its width: the waves are twice as long"),
        Socket("G", "NodeSocketFloat", G, tooltip="g, in the water's units"),
        Socket("Strength", "NodeSocketFloat", 1.0, tooltip="x the height"),
    ),
    (
        Socket("Height", "NodeSocketFloat", tooltip="The ring's height here"),
        Socket("Wavelength", "NodeSocketFloat", tooltip="Its waves' length, λ = 2 x Beam"),
        Socket("Group Speed", "NodeSocketFloat", tooltip="dω/dk, ω² = g k + (σ/ρ) k³"),
    ),
)
RING_CROSSINGS = (
    {
        "ring_r:Value": "R",
        "ring_age:Value": "Age",
        "beam_u:Value": "Beam",
        "g_u:Value": "G",
        "input:Strength": "Strength",
    },
    {"ring_a5:Value": "Height", "ring_lambda:Value": "Wavelength", "ring_cg:Value": "Group Speed"},
)

RING_SPAWN_KEYS = (
    *("src_split", "was_above", "now_below", "crossed", "entered", "ring_point", "store_ring"),
    *("rings_join", "ring_time_old", "ring_age_old", "ring_gone", "rings_drop"),
)
TRACK_INTERFACE = _interface(
    "Water Wake Track",
    "Where an object has been: a point a step (its time, speed, distance come and "
    "heading), those older than Keep dropped; and a ring point where it dropped into the water",
    (
        Socket("Source", "NodeSocketObject", tooltip="The object followed"),
        Socket("Keep", "NodeSocketFloat", 30.0, tooltip="Seconds of track kept"),
    ),
    (
        Socket(
            "Track",
            "NodeSocketGeometry",
            tooltip="A point a step: wake_time, wake_speed, wake_arc, wake_heading",
        ),
        Socket("Rings", "NodeSocketGeometry", tooltip="A point where it dropped in (wake_ring_time), 12 s"),
        Socket("Arc", "NodeSocketFloat", tooltip="The distance it has come"),
        Socket("Heading", "NodeSocketVector", tooltip="Its heading on the plane"),
        Socket("Last", "NodeSocketVector", tooltip="Where it is, on the plane"),
        Socket("Speed", "NodeSocketFloat", tooltip="Its speed this step"),
    ),
)
TRACK_CROSSINGS = (
    {"input:Source": "Source", "input:Keep": "Keep"},
    {f"sim_out:{name}": name for name in ("Track", "Rings", "Arc", "Heading", "Last", "Speed")},
)

FOAM_INTERFACE = _interface(
    "Water Wake Foam",
    "Foam round a moving hull and along its drifted trail, widening and fading with "
    "age, over the foam of wakes before",
    (
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
    (Socket("Foam", "NodeSocketFloat", tooltip=f"This wake's foam or, where more, '{FOAM_ATTRIBUTE}'"),),
)
FOAM_CROSSINGS = (
    {
        "p_flat:Vector": "Position",
        "drifted:Geometry": "Trail",
        DRIFTED_INDEX: "Foot",
        "clock:Seconds": "Time",
        "sim_out:Last": "Last",
        "sim_out:Heading": "Heading",
        "sim_out:Speed": "Speed",
        "length_u:Value": "Length",
        "beam_u:Value": "Beam",
        "input:Foam Fade": "Foam Fade",
    },
    {"foam:Value": "Foam"},
)
FOAM_OUTSIDE = ("t_age", "drift", "drift_flat", "drifted", "store_foam")  # the drift feeds the walk too

ZONE_INTERFACE = _interface(
    "Water Wake Zone",
    "Where a wake can show: the Kelvin wedge round the track (its chord, how far it strays, "
    "how much longer it is), the rings' box and the foam's band, stored as wake_zone (0 none, "
    "1 waves, 2 waves and foam) on the points in the box round them, the others left as they are",
    (
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
    (
        Socket("Geometry", "NodeSocketGeometry", tooltip="The water, wake_zone stored in the box"),
        Socket("Newer", "NodeSocketFloat", tooltip="+1 when the track's newest point is its last, else -1"),
        Socket("Low", "NodeSocketVector", tooltip="The box round the zone's wedge: low corner"),
        Socket("High", "NodeSocketVector", tooltip="Its high corner"),
    ),
)
ZONE_CROSSINGS = (
    {
        "input:Geometry": "Geometry",
        "sim_out:Track": "Track",
        "drifted:Geometry": "Trail",
        "ring_low:Vector": "Rings Low",
        "ring_high:Vector": "Rings High",
        "sim_out:Last": "Last",
        "clock:Seconds": "Time",
        "track_length:Value": "Track Length",
        "length_u:Value": "Length",
        "beam_u:Value": "Beam",
        "input:Foam Fade": "Foam Fade",
    },
    {
        "store_zone:Geometry": "Geometry",
        "ord_dir:Value": "Newer",
        "tz_low:Vector": "Low",
        "tz_high:Vector": "High",
    },
)
ZONE_READERS = ("zone_read", "in_wake", "in_foam", "drop_zone")  # the zone's readers stay outside it


def _clamped_sample(data_type, column, label):
    """A Sample Index that reads the first or last point past either end (a track's ends)."""
    return Node(
        "GeometryNodeSampleIndex",
        column,
        {"data_type": data_type, "domain": "POINT", "clamp": True},
        label=label,
    )


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
        ("p_flat:Vector", n + "_w:#0"),
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
        ("p_flat:Vector", n + "_len:#0"),
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
        ("p_flat:Vector", "h_v:#0"),
        ("sim_out:Last", "h_v:#1"),
        ("h_v:Vector", "h_s:#0"),
        ("sim_out:Heading", "h_s:#1"),
        ("h_s:Value", "h_s_c:Value"),
        ("neg_half:Value", "h_s_c:Min"),
        ("half_length:Value", "h_s_c:Max"),
        ("sim_out:Heading", "h_proj:#0"),
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
        ("sim_out:Speed", "moving:#0"),
        ("moving:Value", "moving_c:Value"),
        ("hull_foam_c:Value", "hull_foam_cl:Value"),
        ("hull_foam_cl:Result", "hull_foam:#0"),
        ("moving_c:Result", "hull_foam:#1"),
    )
    return nodes, links


def _trail_line_nodes():
    """The trail: the track drifted downwind, and each water point's distance to its line."""
    nodes = {
        # Behind: the track's points moved downwind by their age.
        "t_age": math("SUBTRACT", 17, "each track point's age"),
        "drift": vmath("SCALE", 18, "drifted downwind"),
        "drift_flat": vmath("MULTIPLY", 18, "on the plane", b=(1.0, 1.0, 0.0)),
        "drifted": Node("GeometryNodeSetPosition", 19, label="track, drifted"),
        "d_position": Node("GeometryNodeInputPosition", 20),
        "d_at_position": _sample("FLOAT_VECTOR", 21, "where it drifted to"),
        # The trail's width and weight are worked out on the track's points, then sampled.
        "d_at_width": _sample("FLOAT", 21, "its width"),
        "d_at_weight": _sample("FLOAT", 21, "its weight"),
        # The distance to the drifted track's line, not to its nearest point: a track point a
        # frame lies metres apart at speed, and the trail would break into dots.
        "d_distance": math("MINIMUM", 22, "distance to the trail's line"),
        **_segment_distance("d_back", 21),
        **_segment_distance("d_ahead", 21),
        "d_i_back": math("SUBTRACT", 20, "the point before", b=1.0),
        "d_i_ahead": math("ADD", 20, "the point after", b=1.0),
        "d_back_end": _clamped_sample("FLOAT_VECTOR", 21, "the point before it"),
        "d_ahead_end": _clamped_sample("FLOAT_VECTOR", 21, "the point after it"),
    }
    links = (
        ("clock:Seconds", "t_age:#0"),
        ("t_time:Attribute", "t_age:#1"),
        ("input:Drift", "drift:#0"),
        ("t_age:Value", "drift:Scale"),
        ("drift:Vector", "drift_flat:#0"),
        ("sim_out:Track", "drifted:Geometry"),
        ("drift_flat:Vector", "drifted:Offset"),
        ("drifted:Geometry", "d_at_position:Geometry"),
        ("d_position:Position", "d_at_position:Value"),
        (DRIFTED_INDEX, "d_at_position:Index"),
        ("drifted:Geometry", "d_at_width:Geometry"),
        ("d_width:Value", "d_at_width:Value"),
        (DRIFTED_INDEX, "d_at_width:Index"),
        ("drifted:Geometry", "d_at_weight:Geometry"),
        ("trail_foam_full:Value", "d_at_weight:Value"),
        (DRIFTED_INDEX, "d_at_weight:Index"),
        (DRIFTED_INDEX, "d_i_back:#0"),
        (DRIFTED_INDEX, "d_i_ahead:#0"),
        *(
            link
            for end, index in (("d_back_end", "d_i_back"), ("d_ahead_end", "d_i_ahead"))
            for link in (
                ("drifted:Geometry", f"{end}:Geometry"),
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
    """The trail's foam (its width, shape and fading) and the foam stored: this wake's or any before's."""
    nodes = {
        "f_time": _named("wake_time", "FLOAT", 17, "when each was"),
        "f_speed": _named("wake_speed", "FLOAT", 17, "its speed then"),
        "d_age": math("SUBTRACT", 18, "each track point's age"),
        "d_spread": math("MULTIPLY", 23, "0.1 m/s x age", b=0.1),
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
        "foam_before": _named(FOAM_ATTRIBUTE, "FLOAT", 32, "foam of wakes before"),
        "foam": math("MAXIMUM", 33, "any wake's foam"),
        "store_foam": _store(FOAM_ATTRIBUTE, "FLOAT", 50),
    }
    links = (
        ("clock:Seconds", "d_age:#0"),
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
        ("normal_switch:Output", "store_foam:Geometry"),
        ("in_foam:Value", "store_foam:Selection"),
        ("foam:Value", "store_foam:Value"),
        ("store_foam:Geometry", "drop_zone:Geometry"),
        ("drop_zone:Geometry", "output:Geometry"),
    )
    return nodes, links


def _foam_nodes():
    """Foam round the hull as it moves, and along its track, drifting, spreading and fading."""
    nodes, links = _merge(_hull_foam_nodes(), _trail_line_nodes(), _trail_foam_nodes())
    return nodes, tuple(links)


def _zone_chord_nodes():
    """The track's ends: which is the newest, the oldest point, and the chord back to it from the object."""
    nodes = {
        "z_position": Node("GeometryNodeInputPosition", 38),
        "z_p_flat": vmath("MULTIPLY", 39, "on the plane", b=(1.0, 1.0, 0.0)),
        "z_t_position": Node("GeometryNodeInputPosition", 39, label="track position"),
        "z_t_time": _named("wake_time", "FLOAT", 39),
        "kept": Node("GeometryNodeJoinGeometry", 40, label="track and its drift"),
        "spread_far": math("MULTIPLY_ADD", 41, "trail's spread: 0.2 m/s x Foam Fade + 2 m", b=0.2, c=2.0),
        "t_count": Node("GeometryNodeAttributeDomainSize", 40, {"component": "POINTCLOUD"}, label="points"),
        "last_index": math("SUBTRACT", 41, "the last point's index", b=1.0),
        # Which end is the newest: Join Geometry's order is not the links' order, so asked of
        # the points' times (1: the last point is the newest, 0: the first).
        "ord_first_t": _sample("FLOAT", 42, "the first point's time"),
        "ord_last_t": _sample("FLOAT", 42, "the last point's time"),
        "ord_up": math("GREATER_THAN", 43, "newest last"),
        "ord_dir": math("MULTIPLY_ADD", 44, "towards the newer: +1 or -1", b=2.0, c=-1.0),
        "ord_newest": math("MULTIPLY", 44, "the newest's index"),
        "ord_oldest": math("SUBTRACT", 45, "the oldest's index"),
        "oldest": _sample("FLOAT_VECTOR", 46, "the oldest point"),
        "chord": vmath("SUBTRACT", 43, "chord: back to the oldest"),
        "chord_len": vmath("LENGTH", 44, "chord's length"),
        "chord_dir": vmath("NORMALIZE", 44, "chord's direction"),
    }
    links = (
        ("sim_out:Track", "t_count:Geometry"),
        ("t_count:Point Count", "last_index:#0"),
        ("sim_out:Track", "oldest:Geometry"),
        ("z_t_position:Position", "oldest:Value"),
        ("sim_out:Track", "ord_first_t:Geometry"),
        ("z_t_time:Attribute", "ord_first_t:Value"),
        ("sim_out:Track", "ord_last_t:Geometry"),
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
        ("sim_out:Last", "chord:#1"),
        ("chord:Vector", "chord_len:#0"),
        ("chord:Vector", "chord_dir:#0"),
        ("sim_out:Track", "kept:Geometry"),
        ("drifted:Geometry", "kept:Geometry"),
        ("input:Foam Fade", "spread_far:#0"),
        ("z_position:Position", "z_p_flat:#0"),
    )
    return nodes, links


def _zone_wedge_nodes():
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
        "s_hi": math("ADD", 49, "to past the oldest"),
        # A bent track's first arms reach past its oldest point along the chord (its heading
        # there turned from the chord's): by as much as it strays.
        "s_hi_bent": math("ADD", 50, "and its arms, bent"),
    }
    links = (
        ("z_t_position:Position", "k_v:#0"),
        ("sim_out:Last", "k_v:#1"),
        ("k_v:Vector", "k_s:#0"),
        ("chord_dir:Vector", "k_s:#1"),
        ("k_v:Vector", "k_cross:#0"),
        ("chord_dir:Vector", "k_cross:#1"),
        ("k_cross:Vector", "k_d:#0"),
        ("kept:Geometry", "dev:Geometry"),
        ("k_d:Value", "dev:Attribute"),
        ("kept:Geometry", "span:Geometry"),
        ("k_s:Value", "span:Attribute"),
        ("track_length:Value", "arc_extra:#0"),
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
        ("span:Max", "s_hi:#0"),
        ("beam_spread:Value", "s_hi:#1"),
        ("s_hi:Value", "s_hi_bent:#0"),
        ("w0:Value", "s_hi_bent:#1"),
    )
    return nodes, links


def _zone_band_nodes():
    """The trail foam's band: how far across its line and how far along the track the foam reaches."""
    nodes = {
        # The trail's foam, 0.7 exp(-age / Foam Fade) exp(-(d / w)²) with w = B / 3 + 0.1 m/s x
        # age, is above 0.005 within 0.73 B + 0.42 m/s x Foam Fade of its line (at most, over its
        # ages), and only while younger than ln(140) = 4.94 Foam Fades; the hull's within 0.75 B.
        "foam_m": math("MULTIPLY_ADD", 46, "trail's reach: 0.42 m/s x Foam Fade + 1 m", b=0.42, c=1.0),
        "foam_b": math("MULTIPLY", 46, "0.75 B", b=0.75),
        "foam_mb": math("ADD", 47, "+ 0.75 B"),
        "fb_oldest_t": _sample("FLOAT", 46, "the oldest point's time"),
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
        ("sim_out:Track", "fb_oldest_t:Geometry"),
        ("z_t_time:Attribute", "fb_oldest_t:Value"),
        ("ord_oldest:Value", "fb_oldest_t:Index"),
        ("clock:Seconds", "fb_duration:#0"),
        ("fb_oldest_t:Value", "fb_duration:#1"),
        ("fb_duration:Value", "fb_duration_e:#0"),
        ("input:Foam Fade", "fb_ages:#0"),
        ("fb_ages:Value", "fb_share:#0"),
        ("fb_duration_e:Value", "fb_share:#1"),
        ("fb_share:Value", "fb_len:#0"),
        ("track_length:Value", "fb_len:#1"),
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


def _zone_corner_nodes():
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
        ("sim_out:Last", "tz_lo_at:#0"),
        ("tz_c_lo:Vector", "tz_lo_at:#1"),
        ("sim_out:Last", "tz_hi_at:#0"),
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


def _zone_box_nodes():
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
        ("sim_out:Last", "tz_sq_lo:#0"),
        ("tz_r:Value", "tz_sq_lo:#1"),
        ("sim_out:Last", "tz_sq_hi:#0"),
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


def _zone_point_nodes():
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
        **_box_test(("r_above", "r_below", "r_in"), 53, "the rings' box"),
        "z_waves": math("MAXIMUM", 57, "waves here: 1"),
        "z_band": math("LESS_THAN", 54, "near the trail"),
        "z_foam": math("MULTIPLY", 57, "foam here: 1 more"),
        "zone": math("ADD", 58, "zone: 0, 1 or 2"),
    }
    links = (
        ("z_p_flat:Vector", "z_v:#0"),
        ("sim_out:Last", "z_v:#1"),
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
        ("ring_low:Vector", "r_above:B"),
        ("z_p_flat:Vector", "r_below:A"),
        ("ring_high:Vector", "r_below:B"),
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


def _zone_store_nodes():
    """The zone stored on the points in either box (two compares a point), and its readers."""
    nodes = {
        "all_low": vmath("MINIMUM", 57, "both boxes: low"),
        "all_high": vmath("MAXIMUM", 57, "both boxes: high"),
        "low_split": Node("ShaderNodeSeparateXYZ", 57, label="low"),
        "high_split": Node("ShaderNodeSeparateXYZ", 57, label="high"),
        "low_xy": Node("ShaderNodeCombineXYZ", 58, values={"Z": -1e9}, label="low, any height"),
        "high_xy": Node("ShaderNodeCombineXYZ", 58, values={"Z": 1e9}, label="high, any height"),
        **_box_test(("above_low", "below_high", "near_track"), 58, "the box"),
        "store_zone": _store("wake_zone", "FLOAT", 59),
        "zone_read": _named("wake_zone", "FLOAT", 59, "the zone"),
        "in_wake": math("GREATER_THAN", 60, "waves here", b=0.5),
        "in_foam": math("GREATER_THAN", 60, "foam here", b=1.5),
        "drop_zone": Node("GeometryNodeRemoveAttribute", 62, values={"Name": "wake_zone"}, label="zone gone"),
    }
    links = (
        ("tz_low:Vector", "all_low:#0"),
        ("ring_low:Vector", "all_low:#1"),
        ("tz_high:Vector", "all_high:#0"),
        ("ring_high:Vector", "all_high:#1"),
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
        ("zone_read:Attribute", "in_wake:#0"),
        ("zone_read:Attribute", "in_foam:#0"),
    )
    return nodes, links


def _zone_nodes():
    """Where the wake is worked out. A box round the track, its drift and the rings picks the
    points looked at (two compares a point over the whole water); on those alone, the zone: within
    the Kelvin wedge round the chord from the object back to the track's oldest point (wider by
    how far the track strays from the chord and by how much longer it is), or in the rings' box
    (1); near the trail too (2). It is stored once (`wake_zone`), read by the height and the foam,
    and removed: the nearest-point searches, the costly part, run only inside it."""
    nodes, links = _merge(
        _zone_chord_nodes(),
        _zone_wedge_nodes(),
        _zone_band_nodes(),
        _zone_corner_nodes(),
        _zone_box_nodes(),
        _zone_point_nodes(),
        _zone_store_nodes(),
    )
    return nodes, tuple(links)


# The inputs in metres (and g), read through the water's scale: the group works in the water's
# own space, so on a water scaled 2 a metre is half a unit.
IN_UNITS = {
    "input:Length": "length_u:Value",
    "input:Beam": "beam_u:Value",
    "input:Draft": "draft_u:Value",
    "input:Depth": "depth_u:Value",
    "input:Detail": "detail_u:Value",
    "input:Drift": "drift_u:Vector",
}
G_SOCKETS = ("k_scale:#0", "gl:#0", "ring_sk2:#2", "ring_cg_num:#2")  # where g goes in


def _units_nodes():
    """Metres in the water's own units: divided by its scale across (its largest of X and Y) and,
    for the draft (a height), up."""
    nodes = {
        "self": Node("GeometryNodeSelfObject", 0, label="the water"),
        "self_info": Node("GeometryNodeObjectInfo", 1, {"transform_space": "ORIGINAL"}, label="its scale"),
        "self_scale": Node("ShaderNodeSeparateXYZ", 2, label="scale"),
        "across": math("MAXIMUM", 3, "metres a unit across"),
        "across_e": math("MAXIMUM", 4, "(> 0)", b=1e-6),
        "up_e": math("MAXIMUM", 4, "metres a unit up (> 0)", b=1e-6),
        "per_metre": math("DIVIDE", 5, "units a metre", a=1.0),
        "length_u": math("DIVIDE", 6, "Length, in units"),
        "beam_u": math("DIVIDE", 6, "Beam, in units"),
        "detail_u": math("DIVIDE", 6, "Detail, in units"),
        "draft_u": math("DIVIDE", 6, "Draft, in units up"),
        "depth_u": math("DIVIDE", 6, "Depth, in units up"),
        "length_up": math("DIVIDE", 6, "Length, in units up (a height's scale)"),
        "drift_u": vmath("SCALE", 6, "Drift, in units"),
        "g_u": math("DIVIDE", 6, "g, in units", a=G),
    }
    links = [
        ("self:Self Object", "self_info:Object"),
        ("self_info:Scale", "self_scale:Vector"),
        ("self_scale:X", "across:#0"),
        ("self_scale:Y", "across:#1"),
        ("across:Value", "across_e:#0"),
        ("self_scale:Z", "up_e:#0"),
        ("across_e:Value", "per_metre:#1"),
        ("input:Length", "length_u:#0"),
        ("input:Beam", "beam_u:#0"),
        ("input:Detail", "detail_u:#0"),
        ("input:Draft", "draft_u:#0"),
        ("input:Drift", "drift_u:#0"),
        ("per_metre:Value", "drift_u:Scale"),
        ("across_e:Value", "g_u:#1"),
    ]
    links += [("across_e:Value", f"{key}:#1") for key in ("length_u", "beam_u", "detail_u")]
    links += [("input:Depth", "depth_u:#0"), ("input:Length", "length_up:#0")]
    links += [("up_e:Value", f"{key}:#1") for key in ("draft_u", "depth_u", "length_up")]
    return nodes, links


# The group's inputs: lengths in metres (read in the water's units, `_units_nodes`), times in seconds.
INPUTS = (
    Socket("Geometry", "NodeSocketGeometry"),
    Socket(
        "Source",
        "NodeSocketObject",
        tooltip="The object that leaves the wake (a floating one: its rig's anchor)",
    ),
    Socket(
        "Length",
        "NodeSocketFloat",
        10.0,
        0.01,
        1000.0,
        "DISTANCE",
        "The hull's length at the waterline",
    ),
    Socket("Beam", "NodeSocketFloat", 3.0, 0.01, 500.0, "DISTANCE", "The hull's width at the waterline"),
    Socket("Draft", "NodeSocketFloat", 0.5, 0.0, 100.0, "DISTANCE", "How deep the hull sits"),
    Socket(
        "Depth",
        "NodeSocketFloat",
        DEPTH_DEFAULT,
        0.1,
        10000.0,
        "DISTANCE",
        "The water's depth under the hull: a hull sitting deep in shallow water makes higher waves",
    ),
    Socket(
        "Strength",
        "NodeSocketFloat",
        1.0,
        0.0,
        10.0,
        tooltip="Wake height x Kriebel and Seelig's (their β): 1 for a bow half the hull long, "
        "about 1.6 a third, 4 a quarter",
    ),
    Socket(
        "Detail",
        "NodeSocketFloat",
        0.25,
        0.001,
        100.0,
        "DISTANCE",
        "The water mesh's cell: waves shorter than four are left out",
    ),
    Socket("Keep", "NodeSocketFloat", 30.0, 0.1, 600.0, None, "Seconds of track kept (the wake's length)"),
    Socket(
        "Fade",
        "NodeSocketFloat",
        20.0,
        0.1,
        600.0,
        None,
        "Seconds over which the waves fade to a third",
    ),
    Socket(
        "Drift",
        "NodeSocketVector",
        (0.0, 0.0, 0.0),
        subtype="VELOCITY",
        tooltip="How the foam drifts, metres a second (downwind)",
    ),
    Socket(
        "Foam Fade",
        "NodeSocketFloat",
        6.0,
        0.1,
        600.0,
        None,
        "Seconds over which the foam fades to a third",
    ),
    Socket(
        "Shading Normal",
        "NodeSocketBool",
        False,
        tooltip=f"Also tilt the '{SHADING_NORMAL}' the shading reads (the seeds' ocean: its waves' "
        "own normal) by the wake, so the wake's waves show in its light",
    ),
)


def _spec():
    nodes, links = _merge(
        _track_nodes(),
        _ring_nodes(),
        _frame_nodes(),
        _kelvin_nodes(),
        _height_nodes(),
        _normal_nodes(),
        _foam_nodes(),
        _zone_nodes(),
        _walks(),
    )
    links = [(IN_UNITS.get(source, source), target) for source, target in links]
    links += [("g_u:Value", socket) for socket in G_SOCKETS]
    nodes, links = _merge((nodes, links), _units_nodes())
    nodes, links, height = nest(
        nodes, links, _height_nodes()[0], HEIGHT_INTERFACE, ("height_group", 30), *HEIGHT_CROSSINGS
    )
    nodes, links, ring = nest(nodes, links, RING_KEYS, RING_INTERFACE, ("ring_group", 30), *RING_CROSSINGS)
    foam_keys = [key for key in _foam_nodes()[0] if key not in FOAM_OUTSIDE]
    nodes, links, foam = nest(nodes, links, foam_keys, FOAM_INTERFACE, ("foam_group", 32), *FOAM_CROSSINGS)
    zone_keys = [key for key in _zone_nodes()[0] if key not in ZONE_READERS]
    nodes, links, zone = nest(nodes, links, zone_keys, ZONE_INTERFACE, ("zone_group", 40), *ZONE_CROSSINGS)
    track_keys = (*(key for key in _track_nodes()[0] if key != "clock"), *RING_SPAWN_KEYS)
    nodes, links, track = nest(
        nodes, links, track_keys, TRACK_INTERFACE, ("track_group", 6), *TRACK_CROSSINGS
    )
    return GroupSpec(
        name=NAME,
        version=11,
        includes=(KELVIN_SPEC, height, ring, foam, zone, track),
        description="The Kelvin wake, rings and foam of one moving object (its track kept by a "
        "simulation zone)",
        tree_type="GeometryNodeTree",
        inputs=INPUTS,
        outputs=(Socket("Geometry", "NodeSocketGeometry"),),
        nodes=nodes,
        links=tuple(links),
    )


SPEC = _spec()
HEIGHT_SPEC, RING_SPEC, FOAM_SPEC, ZONE_SPEC, TRACK_SPEC = SPEC.includes[1:]
