"""`Water Surface Wind Frame`: the wind direction as an orthonormal frame in the plane.

Shared by the bump scroll (which rotates UVs into this frame) and the water
shader (which rotates the sampled normal back out of it). A wind with no length
in the plane (under 1e-6) falls back to +Y instead of producing NaN or a vector
that is not unit (version 1 added +Y to a wind too short to normalise).
"""

from .spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Surface Wind Frame"

SPEC = GroupSpec(
    name=NAME,
    version=2,
    description="Wind direction in the XY plane, normalised, and its perpendicular",
    inputs=(
        Socket(
            "Wind Direction",
            "NodeSocketVector",
            (0.0, 1.0, 0.0),
            subtype="XYZ",
            tooltip="Direction the bump scrolls in (only X and Y count); zero means +Y",
        ),
    ),
    outputs=(
        Socket("Wind", "NodeSocketVector", tooltip="Unit wind direction w in the plane"),
        Socket("Across", "NodeSocketVector", tooltip="Unit perpendicular p = (w.y, -w.x)"),
    ),
    nodes={
        "flat": vmath("MULTIPLY", 1, "drop Z", b=(1.0, 1.0, 0.0)),
        "length": vmath("LENGTH", 2, "|wind|"),
        "has_wind": math("GREATER_THAN", 3, "|wind| > 0", b=1e-6),
        "no_wind": math("SUBTRACT", 4, "1 - has wind", a=1.0),
        "kept": vmath("SCALE", 4, "the wind, or 0 when too short to normalise"),
        "fallback": vmath("SCALE", 5, "+Y when no wind", a=(0.0, 1.0, 0.0)),
        "either": vmath("ADD", 6, "the wind or +Y"),
        "wind": vmath("NORMALIZE", 7, "w"),
        "split": Node("ShaderNodeSeparateXYZ", 8),
        "minus_x": math("MULTIPLY", 9, "-w.x", b=-1.0),
        "across": Node("ShaderNodeCombineXYZ", 10, label="p = (w.y, -w.x)"),
    },
    links=(
        ("input:Wind Direction", "flat:#0"),
        ("flat:Vector", "length:#0"),
        ("flat:Vector", "kept:#0"),
        ("length:Value", "has_wind:#0"),
        ("has_wind:Value", "kept:Scale"),
        ("has_wind:Value", "no_wind:#1"),
        ("no_wind:Value", "fallback:Scale"),
        ("kept:Vector", "either:#0"),
        ("fallback:Vector", "either:#1"),
        ("either:Vector", "wind:#0"),
        ("wind:Vector", "split:Vector"),
        ("split:X", "minus_x:#0"),
        ("split:Y", "across:X"),
        ("minus_x:Value", "across:Y"),
        ("wind:Vector", "output:Wind"),
        ("across:Vector", "output:Across"),
    ),
)
