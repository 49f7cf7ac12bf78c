"""`Water Wake`: the Kelvin wake and foam one moving object leaves on the water's mesh.

Its nested groups, each a module of its own: `Water Wake Track` keeps the object's track (a
simulation zone: a point a frame, its time, speed, heading and distance come) and its rings;
`Water Wake Zone` marks the points a wake can reach, the only ones worked on. Each of those finds
its point of the track and its place in the track's frame (`wake_frame.py`): `x` behind the
object along its track, `y` across it. Its height there is `Water Wake Kelvin`'s pattern for the
speed the object had there, scaled by `Water Wake Height` (Kriebel and Seelig's (2005) highest
wave one hull length across) over the pattern's own height; it grows in from the hull back over
half its length and fades as `exp(-age / Fade)`. `tests/test_wake.py` compares it over the
whole patch behind the hull with the integral itself (`tools/kelvin_model.py`). Where the
object drops in, `Water Wake Ring`'s ring; `Water Wake Foam`'s foam round the hull and along
its drifted trail (`water_wake_foam`, 0..1, the larger of this wake's and any before it), and
white on its crests where they are steep enough to break (`_foam_nodes`).

Lengths come in metres (`Length`, `Beam`, `Draft`, `Detail`, `Drift`) and g in m/s²: the group
reads them in the water's own units through its scale (`_units_nodes`), so a scaled water makes
the same wake in metres.
"""

from ..physics import G
from ..spec import GroupSpec, Node, Socket, math, vmath
from ..water_waves import NORMAL_ATTRIBUTE
from . import wake_foam, wake_height, wake_kelvin, wake_ring, wake_track, wake_zone
from .wake_frame import DRIFTED_INDEX, frame_nodes, walk_nodes
from .wake_parts import DEPTH_DEFAULT, FOAM_ATTRIBUTE, merge, named, sample, store

NAME = "Water Wake"
SHADING_NORMAL = NORMAL_ATTRIBUTE  # the normal the seeds' ocean shades with
# Its crests break white where they are steep: ak, the wake's height a over the water before it
# times the cusp waves' wavenumber k = 1.5 g / U² at the fastest the hull ran over its kept track
# (the longest waves it made: a hull slowing down does not make its old waves steeper), from
# BREAK_ONSET to all white at BREAK_FULL (a Stokes wave cannot be steeper than ak 0.44; real
# crests spill well before it).
CUSP_K = 1.5
BREAK_ONSET = 0.25
BREAK_FULL = 0.35


def _ring_nodes():
    """Each water point's nearest ring (its centre, its age, whether there is any) and its height
    (`Water Wake Ring`) added to the wake's."""
    nodes = {
        # Each water point and the nearest ring.
        "ring_nearest": Node("GeometryNodeSampleNearest", 15, {"domain": "POINT"}, label="nearest ring"),
        "ring_position": Node("GeometryNodeInputPosition", 15, label="ring position"),
        "ring_time": named("wake_ring_time", "FLOAT", 15),
        "ring_at": sample("FLOAT_VECTOR", 16, "its centre"),
        "ring_began": sample("FLOAT", 16, "when it began"),
        "ring_count": Node("GeometryNodeAttributeDomainSize", 16, {"component": "POINTCLOUD"}, label="rings"),
        "has_rings": Node("FunctionNodeCompare", 17, {"data_type": "INT", "operation": "GREATER_THAN"}),
        "ring_r": vmath("DISTANCE", 17, "r"),
        "ring_age": math("SUBTRACT", 17, "its age"),
        # A switch on one value: with no ring, the ring's field is never evaluated.
        "ring": Node(
            "GeometryNodeSwitch", 41, {"input_type": "FLOAT"}, {"False": 0.0}, "ring height, if any"
        ),
        "total": math("ADD", 47, "wake + ring"),
    }
    links = (
        ("track_group:Rings", "ring_nearest:Geometry"),
        ("p_flat:Vector", "ring_nearest:Sample Position"),
        ("track_group:Rings", "ring_at:Geometry"),
        ("ring_position:Position", "ring_at:Value"),
        ("ring_nearest:Index", "ring_at:Index"),
        ("track_group:Rings", "ring_began:Geometry"),
        ("ring_time:Attribute", "ring_began:Value"),
        ("ring_nearest:Index", "ring_began:Index"),
        ("track_group:Rings", "ring_count:Geometry"),
        ("ring_count:Point Count", "has_rings:A"),
        ("p_flat:Vector", "ring_r:#0"),
        ("ring_at:Value", "ring_r:#1"),
        ("clock:Seconds", "ring_age:#0"),
        ("ring_began:Value", "ring_age:#1"),
        ("ring_group:Height", "ring:True"),
        ("has_rings:Result", "ring:Switch"),
        ("eta:Value", "total:#0"),
        ("ring:Output", "total:#1"),
    )
    return nodes, links


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
        ("length_u:Value", "gl:#1"),
        ("u2:Value", "fr2:#0"),
        ("gl:Value", "fr2:#1"),
        ("age:Value", "age_s:#0"),
        ("input:Fade", "age_s:#1"),
        ("age_s:Value", "age_neg:#0"),
        ("age_neg:Value", "fade:#0"),
        ("length_u:Value", "half_l:#0"),
        ("x:Value", "ramp:Value"),
        ("half_l:Value", "ramp:From Max"),
        ("track_length:Value", "in_track_x:#0"),
        ("detail_u:Value", "in_track_x:#1"),
        ("x:Value", "in_track:#0"),
        ("in_track_x:Value", "in_track:#1"),
        ("g_u:Value", "k_scale:#0"),
        ("g_u:Value", "gl:#0"),
    ]
    return nodes, links


def _kelvin_set_nodes():
    """The height set: the pattern x its scales, lifted, on the points of the zone and the rings' box."""
    nodes = {
        "kelvin": Node("GeometryNodeGroup", 30, label="Kelvin's pattern", group=wake_kelvin.NAME),
        "e3": math("MULTIPLY", 43, ""),
        "amp": math("MULTIPLY", 27, "faded height scale"),
        "e6": math("MULTIPLY", 46, ""),
        "eta": math("MULTIPLY", 47, "height"),
        "lift": Node("ShaderNodeCombineXYZ", 48, label="up by the height"),
        # Only the points near the track are computed (a field is evaluated only where its
        # node's selection holds): the box round the zone (`Water Wake Zone`) and the rings' box,
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
        ("length_u:Value", "kelvin:Length"),
        ("detail_u:Value", "kelvin:Detail"),
        ("kelvin:Pattern", "e3:#0"),
        ("at_amp:Value", "e3:#1"),
        ("height_group:Height", "amp:#0"),
        ("fade:Value", "amp:#1"),
        ("e3:Value", "e6:#0"),
        ("ramp:Result", "e6:#1"),
        ("e6:Value", "eta:#0"),
        ("in_track:Value", "eta:#1"),
        ("total:Value", "lift:Z"),
        ("zone_group:Geometry", "set:Geometry"),
        ("lift:Vector", "set:Offset"),
        ("track_group:Rings", "ring_box:Geometry"),
        ("ring_group:Wavelength", "ring_twice:#0"),
        ("ring_group:Group Speed", "ring_reach:#0"),
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


def _normal_nodes():
    """Where the shading reads a stored normal (`Water Waves`' analytic `water_normal`, the
    seeds' ocean) rather than the mesh's, that normal is the mesh's where the wake moved it,
    so the wake's waves show in the light too; with `Shading Normal` off it is never worked out."""
    nodes = {
        "mesh_normal": Node("GeometryNodeInputNormal", 50, label="the mesh's normal, the wake's in it"),
        "store_normal": store(SHADING_NORMAL, "FLOAT_VECTOR", 50),
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


def _foam_nodes():
    """The track drifted downwind by each point's age (the foam's trail, `Water Wake Foam`'s and
    the zone's), and the foam stored where the zone has foam."""
    nodes = {
        "t_age": math("SUBTRACT", 17, "each track point's age"),
        "drift": vmath("SCALE", 18, "drifted downwind"),
        "drift_flat": vmath("MULTIPLY", 18, "on the plane", b=(1.0, 1.0, 0.0)),
        "drifted": Node("GeometryNodeSetPosition", 19, label="track, drifted"),
        "store_foam": store(FOAM_ATTRIBUTE, "FLOAT", 50),
        # Breaking crests: the height the wake gave each point of its zone (its place now less the
        # one it came with, read by index: a few ns a point, the pattern not worked out again),
        # times k at the fastest it ran; white from BREAK_ONSET to BREAK_FULL, over the foam.
        "c_index": Node("GeometryNodeInputIndex", 50, label="the point"),
        "c_before": sample("FLOAT_VECTOR", 51, "where it was before the wake"),
        "c_position": Node("GeometryNodeInputPosition", 50, label="where it is now"),
        "c_lift": vmath("SUBTRACT", 52, "the wake's lift"),
        "c_height": Node("ShaderNodeSeparateXYZ", 53, label="a"),
        "c_speeds": named("wake_speed", "FLOAT", 48, "the track's speeds"),
        "c_fastest": Node("GeometryNodeAttributeStatistic", 49, {"domain": "POINT"}, label="the fastest"),
        "c_u": math("MAXIMUM", 50, "U (> 0.2 m/s)", b=0.2),
        "c_u2": math("MULTIPLY", 51, "U²"),
        "c_k": math("DIVIDE", 52, "g / U²"),
        "c_cusp": math("MULTIPLY", 53, f"k = {CUSP_K:g} g / U²", b=CUSP_K),
        "c_ak": math("MULTIPLY", 54, "ak"),
        "c_break": Node(
            "ShaderNodeMapRange",
            55,
            {"clamp": True, "interpolation_type": "LINEAR"},
            {1: BREAK_ONSET, 2: BREAK_FULL, 3: 0.0, 4: 1.0},
            label=f"breaking: ak {BREAK_ONSET:g} to {BREAK_FULL:g}",
        ),
        "c_foam_now": named(FOAM_ATTRIBUTE, "FLOAT", 55, "the foam stored"),
        "c_foam": math("MAXIMUM", 56, "and the crests'"),
        "store_crests": store(FOAM_ATTRIBUTE, "FLOAT", 57),
    }
    links = (
        ("input:Geometry", "c_before:Geometry"),
        ("c_position:Position", "c_before:Value"),
        ("c_index:Index", "c_before:Index"),
        ("c_position:Position", "c_lift:#0"),
        ("c_before:Value", "c_lift:#1"),
        ("c_lift:Vector", "c_height:Vector"),
        ("track_group:Track", "c_fastest:Geometry"),
        ("c_speeds:Attribute", "c_fastest:Attribute"),
        ("c_fastest:Max", "c_u:#0"),
        ("c_u:Value", "c_u2:#0"),
        ("c_u:Value", "c_u2:#1"),
        ("g_u:Value", "c_k:#0"),
        ("c_u2:Value", "c_k:#1"),
        ("c_k:Value", "c_cusp:#0"),
        ("c_height:Z", "c_ak:#0"),
        ("c_cusp:Value", "c_ak:#1"),
        ("c_ak:Value", "c_break:Value"),
        ("c_foam_now:Attribute", "c_foam:#0"),
        ("c_break:Result", "c_foam:#1"),
        ("store_foam:Geometry", "store_crests:Geometry"),
        ("in_wake:Value", "store_crests:Selection"),
        ("c_foam:Value", "store_crests:Value"),
        ("clock:Seconds", "t_age:#0"),
        ("t_time:Attribute", "t_age:#1"),
        ("drift_u:Vector", "drift:#0"),
        ("t_age:Value", "drift:Scale"),
        ("drift:Vector", "drift_flat:#0"),
        ("track_group:Track", "drifted:Geometry"),
        ("drift_flat:Vector", "drifted:Offset"),
        ("normal_switch:Output", "store_foam:Geometry"),
        ("in_foam:Value", "store_foam:Selection"),
        ("foam_group:Foam", "store_foam:Value"),
    )
    return nodes, links


def _zone_read_nodes():
    """The zone `Water Wake Zone` stored, read by the height and the foam, then removed."""
    nodes = {
        "zone_read": named("wake_zone", "FLOAT", 59, "the zone"),
        "in_wake": math("GREATER_THAN", 60, "waves here", b=0.5),
        "in_foam": math("GREATER_THAN", 60, "foam here", b=1.5),
        "drop_zone": Node("GeometryNodeRemoveAttribute", 62, values={"Name": "wake_zone"}, label="zone gone"),
    }
    links = (
        ("zone_read:Attribute", "in_wake:#0"),
        ("zone_read:Attribute", "in_foam:#0"),
        ("store_crests:Geometry", "drop_zone:Geometry"),
        ("drop_zone:Geometry", "output:Geometry"),
    )
    return nodes, links


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


# What each nested group is fed: {its node: {its input: the source}}.
FEEDS = {
    "height_group": {
        "Fr²": "fr2:Value",
        "Draft": "draft_u:Value",
        "Depth": "depth_u:Value",
        "Length": "length_up:Value",
        "Strength": "input:Strength",
    },
    "ring_group": {
        "R": "ring_r:Value",
        "Age": "ring_age:Value",
        "Beam": "beam_u:Value",
        "G": "g_u:Value",
        "Strength": "input:Strength",
    },
    "foam_group": {
        "Position": "p_flat:Vector",
        "Trail": "drifted:Geometry",
        "Foot": DRIFTED_INDEX,
        "Time": "clock:Seconds",
        "Last": "track_group:Last",
        "Heading": "track_group:Heading",
        "Speed": "track_group:Speed",
        "Length": "length_u:Value",
        "Beam": "beam_u:Value",
        "Foam Fade": "input:Foam Fade",
    },
    "zone_group": {
        "Geometry": "input:Geometry",
        "Track": "track_group:Track",
        "Trail": "drifted:Geometry",
        "Rings Low": "ring_low:Vector",
        "Rings High": "ring_high:Vector",
        "Last": "track_group:Last",
        "Time": "clock:Seconds",
        "Track Length": "track_length:Value",
        "Length": "length_u:Value",
        "Beam": "beam_u:Value",
        "Foam Fade": "input:Foam Fade",
    },
    "track_group": {"Source": "input:Source", "Keep": "input:Keep"},
}


def _nested_nodes():
    """The nested groups' nodes (each its group's name as its label) and what feeds them."""
    nodes = {
        key: Node("GeometryNodeGroup", column, label=spec.name, group=spec.name)
        for key, spec, column in (
            ("height_group", wake_height.SPEC, 30),
            ("ring_group", wake_ring.SPEC, 30),
            ("foam_group", wake_foam.SPEC, 32),
            ("zone_group", wake_zone.SPEC, 40),
            ("track_group", wake_track.SPEC, 6),
        )
    }
    links = tuple(
        (source, f"{key}:{socket}") for key, feeds in FEEDS.items() for socket, source in feeds.items()
    )
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


_NODES, _LINKS = merge(
    ({"clock": Node("GeometryNodeInputSceneTime", 1, label="seconds")}, ()),  # read by every age
    _ring_nodes(),
    frame_nodes(),
    _kelvin_scale_nodes(),
    _kelvin_set_nodes(),
    _normal_nodes(),
    _foam_nodes(),
    _zone_read_nodes(),
    walk_nodes(),
    _units_nodes(),
    _nested_nodes(),
)
SPEC = GroupSpec(
    name=NAME,
    version=12,  # 12: steep crests break white (CUSP_K, BREAK_ONSET, BREAK_FULL)
    includes=(
        wake_kelvin.SPEC,
        wake_height.SPEC,
        wake_ring.SPEC,
        wake_foam.SPEC,
        wake_zone.SPEC,
        wake_track.SPEC,
    ),
    description="The Kelvin wake, rings and foam of one moving object (its track kept by a simulation zone)",
    tree_type="GeometryNodeTree",
    inputs=INPUTS,
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes=_NODES,
    links=_LINKS,
)
