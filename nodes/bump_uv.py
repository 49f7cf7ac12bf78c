"""`Water Surface Bump UV`: where the bump map is sampled (SPEC 1, step 1).

`uv' = (dot(uv, p), dot(uv, w))`, then `uv'.y += Time * Wind Force`, then
`uv' /= Wave Length`. Nested in the `Water Surface` group, which samples its
bump map there. `Scroll` is the scroll alone in the same tiled units,
`(0, Time * Wind Force / Wave Length)`, so that the extra bump layers (seed 001:
finer tilings that scroll at other speeds) can be made from these two outputs.
"""

from . import wind_frame
from .spec import GroupSpec, Node, Socket, group_node, math, vmath

NAME = "Water Surface Bump UV"

# The clock input of every shader group that moves (the ocean's too).
TIME_INPUT = Socket(
    "Time",
    "NodeSocketFloat",
    0.0,
    subtype="TIME_ABSOLUTE",
    tooltip="Seconds; the material drives it from the scene clock",
)

# Shared with the `Water Surface` group, whose inputs they also are.
SCROLL_INPUTS = (
    Socket(
        "Wave Length",
        "NodeSocketFloat",
        0.1,
        min=0.001,
        max=100.0,
        subtype="DISTANCE",
        tooltip="Bump tile size in UV units: the bump repeats 1 / Wave Length times across the plane",
    ),
    Socket(
        "Wind Direction",
        "NodeSocketVector",
        (0.0, 1.0, 0.0),
        subtype="XYZ",
        tooltip="Direction the bump scrolls in (X and Y); zero means +Y",
    ),
    Socket(
        "Wind Force",
        "NodeSocketFloat",
        0.02,
        min=0.0,
        max=10.0,
        tooltip="Scroll speed in UV units per second, before tiling",
    ),
    TIME_INPUT,
)

SPEC = GroupSpec(
    name=NAME,
    version=2,
    description="Scrolling, wind-aligned, tiled UV for the water bump map",
    inputs=SCROLL_INPUTS,
    outputs=(
        Socket("Vector", "NodeSocketVector", tooltip="UV at which to sample the bump map"),
        Socket("Scroll", "NodeSocketVector", tooltip="The scroll alone, in the same tiled units"),
    ),
    nodes={
        "coords": Node("ShaderNodeTexCoord", 1),
        "frame": group_node(wind_frame.NAME, 1),
        "u": vmath("DOT_PRODUCT", 2, "u' = uv . p"),
        "v": vmath("DOT_PRODUCT", 2, "v' = uv . w"),
        "scroll": math("MULTIPLY", 2, "Time * Wind Force"),
        "v_scrolled": math("ADD", 3, "v' + scroll"),
        "uv_wind": Node("ShaderNodeCombineXYZ", 4, label="wind-frame UV"),
        "tiled": vmath("DIVIDE", 5, "/ Wave Length"),
        "length_xyz": Node("ShaderNodeCombineXYZ", 4, label="(L, L, 1)", values={"Z": 1.0}),
        "scroll_xyz": Node("ShaderNodeCombineXYZ", 4, label="(0, scroll, 0)"),
        "scroll_tiled": vmath("DIVIDE", 5, "scroll / Wave Length"),
    },
    links=(
        ("input:Wind Direction", "frame:Wind Direction"),
        ("coords:UV", "u:#0"),
        ("frame:Across", "u:#1"),
        ("coords:UV", "v:#0"),
        ("frame:Wind", "v:#1"),
        ("input:Time", "scroll:#0"),
        ("input:Wind Force", "scroll:#1"),
        ("v:Value", "v_scrolled:#0"),
        ("scroll:Value", "v_scrolled:#1"),
        ("u:Value", "uv_wind:X"),
        ("v_scrolled:Value", "uv_wind:Y"),
        ("input:Wave Length", "length_xyz:X"),
        ("input:Wave Length", "length_xyz:Y"),
        ("uv_wind:Vector", "tiled:#0"),
        ("length_xyz:Vector", "tiled:#1"),
        ("tiled:Vector", "output:Vector"),
        ("scroll:Value", "scroll_xyz:Y"),
        ("scroll_xyz:Vector", "scroll_tiled:#0"),
        ("length_xyz:Vector", "scroll_tiled:#1"),
        ("scroll_tiled:Vector", "output:Scroll"),
    ),
)
