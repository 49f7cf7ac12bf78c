"""`Water Wake Track`: where an object has been, kept by a simulation zone.

A point a frame where it was (in the water's own space, flattened), with the time, its speed,
its heading and the distance it had come by then (`wake_time`, `wake_speed`, `wake_heading`,
`wake_arc`); points older than `Keep` go. Where the object's origin crosses the water's rest
level downwards, a ring point too (`wake_ring_time`), kept 12 s.
"""

from ..spec import GroupSpec, Node, Socket, math, vmath
from .wake_parts import merge, named, store

NAME = "Water Wake Track"


def _zone_nodes():
    """The track's simulation zone and what it follows: the object, flat on the water, and the clock."""
    nodes = {
        "source": Node(
            "GeometryNodeObjectInfo",
            1,
            {"transform_space": "RELATIVE"},
            label="the object, in the water's space",
        ),
        "flat": vmath("MULTIPLY", 2, "on the water's plane", b=(1.0, 1.0, 0.0)),
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


def _step_nodes():
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
        "store_time": store("wake_time", "FLOAT", 8),
        "store_speed": store("wake_speed", "FLOAT", 9),
        "store_arc": store("wake_arc", "FLOAT", 9),
        "store_heading": store("wake_heading", "FLOAT_VECTOR", 10),
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


def _keep_nodes():
    """The track kept: the new point joined to the old ones, those older than Keep dropped."""
    nodes = {
        "join": Node("GeometryNodeJoinGeometry", 11, label="track + this point"),
        "old_time": named("wake_time", "FLOAT", 10, "when each point was"),
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


def _ring_spawn_nodes():
    """Ring points, in the track's zone: where the object's origin drops below the rest level, kept 12 s."""
    nodes = {
        "src_split": Node("ShaderNodeSeparateXYZ", 2, label="its height"),
        "was_above": math("GREATER_THAN", 4, "above the water before", b=0.0),
        "now_below": math("LESS_THAN", 4, "at or below it now", b=1e-4),
        "crossed": math("MULTIPLY", 5, "crossed"),
        "entered": math("MULTIPLY", 6, "entered (not on the first step)"),
        "ring_point": Node("GeometryNodePoints", 8, label="a ring where it entered"),
        "store_ring": store("wake_ring_time", "FLOAT", 9),
        "rings_join": Node("GeometryNodeJoinGeometry", 11, label="rings + this one"),
        "ring_time_old": named("wake_ring_time", "FLOAT", 10, "when each ring began"),
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


def _outputs():
    """What the wake reads of the zone: its state after this step."""
    names = ("Track", "Rings", "Arc", "Heading", "Last", "Speed")
    return {}, tuple((f"sim_out:{name}", f"output:{name}") for name in names)


_NODES, _LINKS = merge(_zone_nodes(), _step_nodes(), _keep_nodes(), _ring_spawn_nodes(), _outputs())
SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="Where an object has been: a point a step (its time, speed, distance come and "
    "heading), those older than Keep dropped; and a ring point where it dropped into the water",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("Source", "NodeSocketObject", tooltip="The object followed"),
        Socket("Keep", "NodeSocketFloat", 30.0, tooltip="Seconds of track kept"),
    ),
    outputs=(
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
    nodes=_NODES,
    links=_LINKS,
)
