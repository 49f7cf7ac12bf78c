"""`Water Wake`: the Kelvin wake and foam one moving object leaves on the water's mesh.

A simulation zone keeps the object's track: a point a frame where it was (in the water's own
space, flattened), with the time, its speed, its heading and the distance it had come by then
(`wake_time`, `wake_speed`, `wake_heading`, `wake_arc`); points older than `Keep` go. Each water
point finds the track's point nearest it, and so its place in the track's frame: `x` metres
behind the object along its track (turns included) and `y` across it.

Its height there is the stationary-phase Kelvin pattern of a source moving at the speed the
object had there (deep water, `ω² = g k`). Waves running at `θ` to the track stand still in the
object's frame when `k = g / (U² cos² θ)`; at `tan α = y / x` those that reach the point solve
`2 tan α tan² θ - tan θ + tan α = 0`: two of them (transverse and diverging) inside the wedge
`tan α < 1 / sqrt(8)` (19.47°), none outside it. Each adds `cos(k (x cos θ + y sin θ))`, made
smaller where it is short beside the hull (`exp(-0.05 k L)`) or shorter than four mesh cells
(`Detail`); the two grow where they meet at the wedge's arms (the cusp) and fade just beyond
it (the stationary-phase weight `s^(-1/2)` near the arms, `s = sqrt(1 - 8 tan² α)`, is
taken as `(s² + 0.01)^(-1/3)`: finite, and highest on the arms, as the Airy function there is).
The height scales as `Strength x Draft x Fr²` (`Fr = U / sqrt(g L)`), falls as
`sqrt(L / (L + r))` with distance and `exp(-age / Fade)` with time.

Foam (`water_wake_foam`, 0..1, the larger of this wake's and any before it): round the hull
where it moves through the water, and along the track behind it, drifting with `Drift`
(metres a second, downwind), spreading and fading with time.
"""

from .spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Wake"
FOAM_ATTRIBUTE = "water_wake_foam"
G = 9.81


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


def _sample(data_type, column, label):
    return Node("GeometryNodeSampleIndex", column, {"data_type": data_type, "domain": "POINT"}, label=label)


# The track's attributes, kept on its points.
TRACK = (
    ("wake_time", "FLOAT"),
    ("wake_speed", "FLOAT"),
    ("wake_arc", "FLOAT"),
    ("wake_heading", "FLOAT_VECTOR"),
)


def _track_nodes():
    """The simulation zone: one point a step where the object is, the old ones dropped."""
    nodes = {
        "source": Node(
            "GeometryNodeObjectInfo",
            1,
            {"transform_space": "RELATIVE"},
            label="the object, in the water's space",
        ),
        "flat": vmath("MULTIPLY", 2, "on the water's plane", b=(1.0, 1.0, 0.0)),
        "clock": Node("GeometryNodeInputSceneTime", 1, label="seconds"),
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
            ),
            values={"Started": 1.0},
            label="track",
        ),
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
        "join": Node("GeometryNodeJoinGeometry", 11, label="track + this point"),
        "old_time": _named("wake_time", "FLOAT", 10, "when each point was"),
        "point_age": math("SUBTRACT", 11, "age"),
        "too_old": math("GREATER_THAN", 12, "older than Keep"),
        "drop": Node("GeometryNodeDeleteGeometry", 12, {"domain": "POINT"}, label="drop the old"),
    }
    links = (
        ("input:Source", "source:Object"),
        ("source:Location", "flat:#0"),
        ("flat:Vector", "sim_in:Last"),
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
        ("clock:Seconds", "store_time:Value"),
        ("store_time:Geometry", "store_speed:Geometry"),
        ("speed:Value", "store_speed:Value"),
        ("store_speed:Geometry", "store_arc:Geometry"),
        ("arc:Value", "store_arc:Value"),
        ("store_arc:Geometry", "store_heading:Geometry"),
        ("heading:Result", "store_heading:Value"),
        ("store_heading:Geometry", "join:Geometry"),
        ("sim_in:Track", "join:Geometry"),
        ("join:Geometry", "drop:Geometry"),
        ("clock:Seconds", "point_age:#0"),
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


def _frame_nodes():
    """Each water point's place in the track's frame: behind (x), across (y), the speed and age
    there."""
    nodes = {
        "position": Node("GeometryNodeInputPosition", 13),
        "p_flat": vmath("MULTIPLY", 14, "on the plane", b=(1.0, 1.0, 0.0)),
        "nearest": Node("GeometryNodeSampleNearest", 15, {"domain": "POINT"}, label="nearest track point"),
        "t_position": Node("GeometryNodeInputPosition", 15, label="track position"),
        "t_time": _named("wake_time", "FLOAT", 15),
        "t_speed": _named("wake_speed", "FLOAT", 15),
        "t_arc": _named("wake_arc", "FLOAT", 15),
        "t_heading": _named("wake_heading", "FLOAT_VECTOR", 15),
        "at_position": _sample("FLOAT_VECTOR", 16, "P"),
        "at_time": _sample("FLOAT", 16, "its time"),
        "at_speed": _sample("FLOAT", 16, "its speed"),
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
        "age": math("SUBTRACT", 19, "age there"),
        "first_arc": Node(
            "GeometryNodeAttributeStatistic", 16, {"domain": "POINT"}, label="where the track begins"
        ),
        "track_length": math("SUBTRACT", 17, "track's length"),
    }
    links = (
        ("position:Position", "p_flat:#0"),
        ("sim_out:Track", "nearest:Geometry"),
        ("p_flat:Vector", "nearest:Sample Position"),
        *(
            link
            for key, source in (
                ("at_position", "t_position:Position"),
                ("at_time", "t_time:Attribute"),
                ("at_speed", "t_speed:Attribute"),
                ("at_arc", "t_arc:Attribute"),
                ("at_heading", "t_heading:Attribute"),
            )
            for link in (
                ("sim_out:Track", f"{key}:Geometry"),
                (source, f"{key}:Value"),
                ("nearest:Index", f"{key}:Index"),
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
        ("at_time:Value", "age:#1"),
        ("sim_out:Track", "first_arc:Geometry"),
        ("t_arc:Attribute", "first_arc:Attribute"),
        ("sim_out:Arc", "track_length:#0"),
        ("first_arc:Min", "track_length:#1"),
    )
    return nodes, links


def _root(tag, tau, column):
    """One stationary wave (tan θ from `tau`, a "node:socket"): its weighted cosine term."""
    n = f"{tag}_"
    nodes = {
        n + "tau2": math("MULTIPLY", column, f"{tag}: tan² θ"),
        n + "q2": math("ADD", column + 1, "1 + tan² θ = 1 / cos² θ", b=1.0),
        n + "q": math("SQRT", column + 2, "1 / cos θ"),
        n + "k": math("MULTIPLY", column + 2, "k = g / (U² cos² θ)"),
        n + "y_tau": math("MULTIPLY", column, "y tan θ"),
        n + "path": math("ADD", column + 1, "x + y tan θ"),
        n + "phase_a": math("MULTIPLY", column + 3, "(x + y tan θ) / cos θ"),
        n + "phase": math("MULTIPLY", column + 4, "k (x cos θ + y sin θ)"),
        n + "wave": math("COSINE", column + 5, "cos(phase)"),
        n + "kl": math("MULTIPLY", column + 3, "k L"),
        n + "hull": math("MULTIPLY", column + 4, "-0.05 k L", b=-0.05),
        n + "hull_w": math("EXPONENT", column + 5, "short beside the hull: less"),
        n + "lambda": math("DIVIDE", column + 3, "wavelength", a=2.0 * 3.141592653589793),
        n + "mesh": math("DIVIDE", column + 4, "wavelength / 4 cells"),
        n + "mesh_w": Node(
            "ShaderNodeMapRange",
            column + 5,
            {"clamp": True},
            {"From Min": 0.5, "From Max": 1.0, "To Min": 0.0, "To Max": 1.0},
            label="the mesh can hold it",
        ),
        n + "weight": math("MULTIPLY", column + 6, "weights"),
        n + "term": math("MULTIPLY", column + 7, f"{tag} term"),
    }
    links = (
        (tau, n + "tau2:#0"),
        (tau, n + "tau2:#1"),
        (n + "tau2:Value", n + "q2:#0"),
        (n + "q2:Value", n + "q:#0"),
        (n + "q2:Value", n + "k:#0"),
        ("k_scale:Value", n + "k:#1"),
        ("y:Value", n + "y_tau:#0"),
        (tau, n + "y_tau:#1"),
        ("x_pos:Value", n + "path:#0"),
        (n + "y_tau:Value", n + "path:#1"),
        (n + "path:Value", n + "phase_a:#0"),
        (n + "q:Value", n + "phase_a:#1"),
        (n + "phase_a:Value", n + "phase:#0"),
        ("k_scale:Value", n + "phase:#1"),
        (n + "phase:Value", n + "wave:#0"),
        (n + "k:Value", n + "kl:#0"),
        ("input:Length", n + "kl:#1"),
        (n + "kl:Value", n + "hull:#0"),
        (n + "hull:Value", n + "hull_w:#0"),
        (n + "k:Value", n + "lambda:#1"),
        (n + "lambda:Value", n + "mesh:#0"),
        ("four_cells:Value", n + "mesh:#1"),
        (n + "mesh:Value", n + "mesh_w:Value"),
        (n + "hull_w:Value", n + "weight:#0"),
        (n + "mesh_w:Result", n + "weight:#1"),
        (n + "weight:Value", n + "term:#0"),
        (n + "wave:Value", n + "term:#1"),
    )
    return nodes, links


def _kelvin_nodes():
    """The height: the two stationary waves, the wedge, the size and the fading."""
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
        "u": math("MAXIMUM", 22, "U (> 0.2 m/s)", b=0.2),
        "u2": math("MULTIPLY", 23, "U²"),
        "k_scale": math("DIVIDE", 24, "g / U²", a=G),
        "four_cells": math("MULTIPLY", 22, "4 cells", b=4.0),
        "sum": math("ADD", 40, "both waves"),
        "cusp_base": math("ADD", 28, "s² + 0.01", b=0.01),
        "cusp": math("POWER", 29, "higher at the arms", b=-1.0 / 3.0),
        "beyond": math("MINIMUM", 27, "how far outside (< 0)", b=0.0),
        "beyond_s": math("DIVIDE", 28, "/ 0.04", b=0.04),
        "outside": math("EXPONENT", 29, "fades just beyond the arms"),
        "fr2": math("DIVIDE", 24, "Fr² = U² / (g L)"),
        "gl": math("MULTIPLY", 23, "g L", a=G),
        "height": math("MULTIPLY", 25, "Draft x Fr²"),
        "strength": math("MULTIPLY", 26, "x Strength"),
        "r2_x": math("MULTIPLY", 23, "x²"),
        "r2": math("MULTIPLY_ADD", 24, "x² + y²"),
        "r": math("SQRT", 25, "r"),
        "l_r": math("ADD", 26, "L + r"),
        "l_over": math("DIVIDE", 27, "L / (L + r)"),
        "decay": math("SQRT", 28, "sqrt(L / (L + r))"),
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
        "e1": math("MULTIPLY", 41, ""),
        "e2": math("MULTIPLY", 42, ""),
        "e3": math("MULTIPLY", 43, ""),
        "e4": math("MULTIPLY", 44, ""),
        "e5": math("MULTIPLY", 45, ""),
        "e6": math("MULTIPLY", 46, ""),
        "eta": math("MULTIPLY", 47, "height"),
        "lift": Node("ShaderNodeCombineXYZ", 48, label="up by the height"),
        # Only the points near the track are computed (a field is evaluated only where its
        # node's selection holds): its box, wider by the wedge at its far end, the beam, 2 m and
        # the foam's drift.
        "box": Node("GeometryNodeBoundBox", 40, label="the track's box"),
        "wedge_width": math("MULTIPLY", 40, "track's length x tan 19.5°", b=0.3536),
        "margin_b": math("ADD", 41, "+ beam"),
        "drift_speed": vmath("LENGTH", 40, "drift speed"),
        "drift_far": math("MULTIPLY", 41, "x Keep"),
        "margin_d": math("ADD", 42, "+ drift"),
        "margin": math("ADD", 43, "+ 2 m", b=2.0),
        "low": vmath("SUBTRACT", 44, "box's low corner - margin"),
        "high": vmath("ADD", 44, "box's high corner + margin"),
        "above_low": vmath("SUBTRACT", 45, "p - low"),
        "below_high": vmath("SUBTRACT", 45, "high - p"),
        "least": vmath("MINIMUM", 46, "the nearer side, per axis"),
        "least_split": Node("ShaderNodeSeparateXYZ", 47, label="per axis"),
        "least_xy": math("MINIMUM", 48, "x, y"),
        "least_xyz": math("MINIMUM", 48, "and z"),
        "near_track": math("GREATER_THAN", 49, "inside the box", b=0.0),
        "set": Node("GeometryNodeSetPosition", 49, label="the wake"),
    }
    links = [
        ("x:Value", "x_pos:#0"),
        ("y:Value", "tan_a:#0"),
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
        ("at_speed:Value", "u:#0"),
        ("u:Value", "u2:#0"),
        ("u:Value", "u2:#1"),
        ("u2:Value", "k_scale:#1"),
        ("input:Detail", "four_cells:#0"),
        ("t_term:Value", "sum:#0"),
        ("d_term:Value", "sum:#1"),
        ("disc_in:Value", "cusp_base:#0"),
        ("cusp_base:Value", "cusp:#0"),
        ("disc:Value", "beyond:#0"),
        ("beyond:Value", "beyond_s:#0"),
        ("beyond_s:Value", "outside:#0"),
        ("input:Length", "gl:#1"),
        ("u2:Value", "fr2:#0"),
        ("gl:Value", "fr2:#1"),
        ("input:Draft", "height:#0"),
        ("fr2:Value", "height:#1"),
        ("height:Value", "strength:#0"),
        ("input:Strength", "strength:#1"),
        ("x:Value", "r2_x:#0"),
        ("x:Value", "r2_x:#1"),
        ("y:Value", "r2:#0"),
        ("y:Value", "r2:#1"),
        ("r2_x:Value", "r2:#2"),
        ("r2:Value", "r:#0"),
        ("input:Length", "l_r:#0"),
        ("r:Value", "l_r:#1"),
        ("input:Length", "l_over:#0"),
        ("l_r:Value", "l_over:#1"),
        ("l_over:Value", "decay:#0"),
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
        ("sum:Value", "e1:#0"),
        ("cusp:Value", "e1:#1"),
        ("e1:Value", "e2:#0"),
        ("outside:Value", "e2:#1"),
        ("e2:Value", "e3:#0"),
        ("strength:Value", "e3:#1"),
        ("e3:Value", "e4:#0"),
        ("decay:Value", "e4:#1"),
        ("e4:Value", "e5:#0"),
        ("fade:Value", "e5:#1"),
        ("e5:Value", "e6:#0"),
        ("ramp:Result", "e6:#1"),
        ("e6:Value", "eta:#0"),
        ("in_track:Value", "eta:#1"),
        ("eta:Value", "lift:Z"),
        ("input:Geometry", "set:Geometry"),
        ("lift:Vector", "set:Offset"),
        ("sim_out:Track", "box:Geometry"),
        ("track_length:Value", "wedge_width:#0"),
        ("wedge_width:Value", "margin_b:#0"),
        ("input:Beam", "margin_b:#1"),
        ("input:Drift", "drift_speed:#0"),
        ("drift_speed:Value", "drift_far:#0"),
        ("input:Keep", "drift_far:#1"),
        ("margin_b:Value", "margin_d:#0"),
        ("drift_far:Value", "margin_d:#1"),
        ("margin_d:Value", "margin:#0"),
        ("box:Min", "low:#0"),
        ("margin:Value", "low:#1"),
        ("box:Max", "high:#0"),
        ("margin:Value", "high:#1"),
        ("p_flat:Vector", "above_low:#0"),
        ("low:Vector", "above_low:#1"),
        ("high:Vector", "below_high:#0"),
        ("p_flat:Vector", "below_high:#1"),
        ("above_low:Vector", "least:#0"),
        ("below_high:Vector", "least:#1"),
        ("least:Vector", "least_split:Vector"),
        ("least_split:X", "least_xy:#0"),
        ("least_split:Y", "least_xy:#1"),
        ("least_xy:Value", "least_xyz:#0"),
        ("least_split:Z", "least_xyz:#1"),
        ("least_xyz:Value", "near_track:#0"),
        ("near_track:Value", "set:Selection"),
    ]
    for tag, tau in (("t", "tau_t:Value"), ("d", "tau_d:Value")):
        more_nodes, more_links = _root(tag, tau, 31)
        nodes |= more_nodes
        links += more_links
    return nodes, tuple(links)


def _foam_nodes():
    """Foam round the hull as it moves, and along its track, drifting, spreading and fading."""
    nodes = {
        # Round the hull: within half its beam of the segment from stern to bow, and a little more.
        "half_length": math("MULTIPLY", 22, "L / 2", b=0.5),
        "bow_offset": vmath("SCALE", 23, "h L / 2"),
        "bow": vmath("ADD", 24, "bow"),
        "stern": vmath("SUBTRACT", 24, "stern"),
        "hull_line": Node("GeometryNodeCurvePrimitiveLine", 25, label="the hull's line"),
        "hull_edge": Node("GeometryNodeCurveToMesh", 26, label="as an edge"),
        "hull_distance": Node(
            "GeometryNodeProximity", 27, {"target_element": "EDGES"}, label="distance to the hull's line"
        ),
        "half_beam": math("MULTIPLY", 25, "B / 2", b=0.5),
        "past_hull": math("SUBTRACT", 27, "past its side"),
        "foam_width": math("MULTIPLY", 26, "foam's width: B / 4", b=0.25),
        "hull_foam_r": math("DIVIDE", 28, "in widths"),
        "hull_foam_c": math("SUBTRACT", 29, "1 - that", a=1.0),
        "moving": math("MULTIPLY", 29, "moving: U / 1 m/s", b=1.0),
        "moving_c": Node("ShaderNodeClamp", 30, label="0..1"),
        "hull_foam_cl": Node("ShaderNodeClamp", 30, label="0..1"),
        "hull_foam": math("MULTIPLY", 31, "foam round the hull"),
        # Behind: the track's points moved downwind by their age.
        "t_age": math("SUBTRACT", 17, "each track point's age"),
        "drift": vmath("SCALE", 18, "drifted downwind"),
        "drift_flat": vmath("MULTIPLY", 18, "on the plane", b=(1.0, 1.0, 0.0)),
        "drifted": Node("GeometryNodeSetPosition", 19, label="track, drifted"),
        "d_nearest": Node(
            "GeometryNodeSampleNearest", 20, {"domain": "POINT"}, label="nearest drifted point"
        ),
        "d_position": Node("GeometryNodeInputPosition", 20),
        "d_at_position": _sample("FLOAT_VECTOR", 21, "where it drifted to"),
        "d_at_time": _sample("FLOAT", 21, "its time"),
        "d_at_speed": _sample("FLOAT", 21, "its speed"),
        "d_distance": vmath("DISTANCE", 22, "distance"),
        "d_age": math("SUBTRACT", 22, "its age"),
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
        "d_f1": math("MULTIPLY", 29, ""),
        "trail_foam_full": math("MULTIPLY", 30, "foam along the track"),
        "trail_foam": math("MULTIPLY", 31, "x 0.7: thinner than at the hull", b=0.7),
        "foam_here": math("MAXIMUM", 32, "this wake's foam"),
        "foam_before": _named(FOAM_ATTRIBUTE, "FLOAT", 32, "foam of wakes before"),
        "foam": math("MAXIMUM", 33, "any wake's foam"),
        "store_foam": _store(FOAM_ATTRIBUTE, "FLOAT", 50),
    }
    links = (
        ("input:Length", "half_length:#0"),
        ("sim_out:Heading", "bow_offset:#0"),
        ("half_length:Value", "bow_offset:Scale"),
        ("sim_out:Last", "bow:#0"),
        ("bow_offset:Vector", "bow:#1"),
        ("sim_out:Last", "stern:#0"),
        ("bow_offset:Vector", "stern:#1"),
        ("stern:Vector", "hull_line:Start"),
        ("bow:Vector", "hull_line:End"),
        ("hull_line:Curve", "hull_edge:Curve"),
        ("hull_edge:Mesh", "hull_distance:Geometry"),
        ("p_flat:Vector", "hull_distance:Sample Position"),
        ("input:Beam", "half_beam:#0"),
        ("hull_distance:Distance", "past_hull:#0"),
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
        ("clock:Seconds", "t_age:#0"),
        ("t_time:Attribute", "t_age:#1"),
        ("input:Drift", "drift:#0"),
        ("t_age:Value", "drift:Scale"),
        ("drift:Vector", "drift_flat:#0"),
        ("sim_out:Track", "drifted:Geometry"),
        ("drift_flat:Vector", "drifted:Offset"),
        ("drifted:Geometry", "d_nearest:Geometry"),
        ("p_flat:Vector", "d_nearest:Sample Position"),
        ("drifted:Geometry", "d_at_position:Geometry"),
        ("d_position:Position", "d_at_position:Value"),
        ("d_nearest:Index", "d_at_position:Index"),
        ("drifted:Geometry", "d_at_time:Geometry"),
        ("t_time:Attribute", "d_at_time:Value"),
        ("d_nearest:Index", "d_at_time:Index"),
        ("drifted:Geometry", "d_at_speed:Geometry"),
        ("t_speed:Attribute", "d_at_speed:Value"),
        ("d_nearest:Index", "d_at_speed:Index"),
        ("p_flat:Vector", "d_distance:#0"),
        ("d_at_position:Value", "d_distance:#1"),
        ("clock:Seconds", "d_age:#0"),
        ("d_at_time:Value", "d_age:#1"),
        ("d_age:Value", "d_spread:#0"),
        ("input:Beam", "third_beam:#0"),
        ("third_beam:Value", "d_width:#0"),
        ("d_spread:Value", "d_width:#1"),
        ("d_distance:Value", "d_ratio:#0"),
        ("d_width:Value", "d_ratio:#1"),
        ("d_ratio:Value", "d_ratio2:#0"),
        ("d_ratio:Value", "d_ratio2:#1"),
        ("d_ratio2:Value", "d_gauss:#0"),
        ("d_gauss:Value", "d_shape:#0"),
        ("d_age:Value", "d_age_s:#0"),
        ("input:Foam Fade", "d_age_s:#1"),
        ("d_age_s:Value", "d_age_n:#0"),
        ("d_age_n:Value", "d_fade:#0"),
        ("d_at_speed:Value", "d_moving:#0"),
        ("d_moving:Value", "d_moving_c:Value"),
        ("d_shape:Value", "d_f1:#0"),
        ("d_fade:Value", "d_f1:#1"),
        ("d_f1:Value", "trail_foam_full:#0"),
        ("d_moving_c:Result", "trail_foam_full:#1"),
        ("trail_foam_full:Value", "trail_foam:#0"),
        ("hull_foam:Value", "foam_here:#0"),
        ("trail_foam:Value", "foam_here:#1"),
        ("foam_before:Attribute", "foam:#0"),
        ("foam_here:Value", "foam:#1"),
        ("set:Geometry", "store_foam:Geometry"),
        ("near_track:Value", "store_foam:Selection"),
        ("foam:Value", "store_foam:Value"),
        ("store_foam:Geometry", "output:Geometry"),
    )
    return nodes, links


def _spec():
    nodes, links = {}, []
    for part in (_track_nodes, _frame_nodes, _kelvin_nodes, _foam_nodes):
        more_nodes, more_links = part()
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes |= more_nodes
        links += more_links
    return GroupSpec(
        name=NAME,
        version=1,
        description="The Kelvin wake and foam of one moving object (its track kept by a simulation zone)",
        tree_type="GeometryNodeTree",
        inputs=(
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
            Socket(
                "Beam", "NodeSocketFloat", 3.0, 0.01, 500.0, "DISTANCE", "The hull's width at the waterline"
            ),
            Socket("Draft", "NodeSocketFloat", 0.5, 0.0, 100.0, "DISTANCE", "How deep the hull sits"),
            Socket(
                "Strength",
                "NodeSocketFloat",
                1.0,
                0.0,
                10.0,
                tooltip="Wake height, x the Draft x the Froude number²",
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
            Socket(
                "Keep", "NodeSocketFloat", 30.0, 0.1, 600.0, None, "Seconds of track kept (the wake's length)"
            ),
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
        ),
        outputs=(Socket("Geometry", "NodeSocketGeometry"),),
        nodes=nodes,
        links=tuple(links),
    )


SPEC = _spec()
