"""`Water Waves`: the ocean's four summed sine waves as a Geometry Nodes modifier (SPEC 2).

For each point p of the mesh (object space, in the XY plane):
`arg_i = dot(D_i, p) / lambda_i + t * s_i`, `z += sum A_i sin(arg_i)`, and the
analytic normal `normalise(-sum d_i D_i.x, -sum d_i D_i.y, 1)` with
`d_i = A_i cos(arg_i) / lambda_i` is stored as the point attribute
`water_normal` for the ocean shader. `t` is the Scene Time node's seconds, so
the waves move in a plain render with no Python. `wave_math.py` is the same
maths in numpy.
"""

from .spec import GroupSpec, Node, Socket, math, vmath
from .wave_math import DEFAULT_WAVES, MIN_WAVELENGTH

NAME = "Water Waves"
VERSION = 2  # 2: scalar per-point maths (same results, faster)
NORMAL_ATTRIBUTE = "water_normal"
WAVE_COUNT = len(DEFAULT_WAVES)


def wave_inputs(number, wave):
    """The four modifier inputs of wave `number` (1-based), defaulting to the seeds' table."""
    return (
        Socket(
            f"Amplitude {number}",
            "NodeSocketFloat",
            wave.amplitude,
            min=0.0,
            max=100.0,
            subtype="DISTANCE",
            tooltip=f"Height of wave {number} above the rest level (0 removes the wave)",
        ),
        Socket(
            f"Wavelength {number}",
            "NodeSocketFloat",
            wave.wavelength,
            min=MIN_WAVELENGTH,
            max=10000.0,
            subtype="DISTANCE",
            tooltip=f"Length scale of wave {number}: its phase advances 1 radian per this distance",
        ),
        Socket(
            f"Speed {number}",
            "NodeSocketFloat",
            wave.speed,
            min=-100.0,
            max=100.0,
            tooltip=f"Phase speed of wave {number}, radians per second",
        ),
        Socket(
            f"Direction {number}",
            "NodeSocketVector",
            (*wave.direction, 0.0),
            subtype="XYZ",
            tooltip=f"Direction wave {number} travels against, in the XY plane (normalised)",
        ),
    )


def _wave_nodes(number, height, slope_x, slope_y):
    """Nodes and links of one wave, added onto the running sums `height`, `slope_x`, `slope_y`.

    What does not vary over the mesh is worked out once per wave: the wave
    vector k = D / lambda, -A k and the phase t s. Per point that leaves five
    scalar operations: arg = k.x p.x + k.y p.y + t s, h += A sin(arg) and
    (-slope) += cos(arg) (-A k). Returns (nodes, links, new sums).
    """
    w = f"w{number}"
    nodes = {
        f"{w}_flat": vmath("MULTIPLY", 2, f"D{number} in the plane", b=(1.0, 1.0, 0.0)),
        f"{w}_dir": vmath("NORMALIZE", 3, f"D{number}"),
        f"{w}_len": math("MAXIMUM", 3, f"lambda{number} (>= {MIN_WAVELENGTH})", b=MIN_WAVELENGTH),
        f"{w}_inv": math("DIVIDE", 4, f"1 / lambda{number}", a=1.0),
        f"{w}_k": vmath("SCALE", 5, f"k{number} = D / lambda"),
        f"{w}_minus_a": math("MULTIPLY", 5, f"-A{number}", b=-1.0),
        f"{w}_minus_ak": vmath("SCALE", 6, f"-A{number} k{number}"),
        f"{w}_k_xy": Node("ShaderNodeSeparateXYZ", 7, label=f"k{number}"),
        f"{w}_minus_ak_xy": Node("ShaderNodeSeparateXYZ", 7, label=f"-A{number} k{number}"),
        f"{w}_phase": math("MULTIPLY", 7, f"phase{number} = t s"),
        # Per point.
        f"{w}_arg_y": math("MULTIPLY_ADD", 8, f"k.y p.y + phase{number}"),
        f"{w}_arg": math("MULTIPLY_ADD", 9, f"arg{number} = k.x p.x + ..."),
        f"{w}_sin": math("SINE", 10, f"sin arg{number}"),
        f"{w}_cos": math("COSINE", 10, f"cos arg{number}"),
        f"{w}_h": math("MULTIPLY_ADD", 11, f"h += A{number} sin", c=0.0),
        f"{w}_nx": math("MULTIPLY_ADD", 11, "-slope.x += cos (-A k.x)", c=0.0),
        f"{w}_ny": math("MULTIPLY_ADD", 11, "-slope.y += cos (-A k.y)", c=0.0),
    }
    links = [
        (f"input:Direction {number}", f"{w}_flat:#0"),
        (f"{w}_flat:Vector", f"{w}_dir:#0"),
        (f"input:Wavelength {number}", f"{w}_len:#0"),
        (f"{w}_len:Value", f"{w}_inv:#1"),
        (f"{w}_dir:Vector", f"{w}_k:#0"),
        (f"{w}_inv:Value", f"{w}_k:Scale"),
        (f"input:Amplitude {number}", f"{w}_minus_a:#0"),
        (f"{w}_k:Vector", f"{w}_minus_ak:#0"),
        (f"{w}_minus_a:Value", f"{w}_minus_ak:Scale"),
        (f"{w}_k:Vector", f"{w}_k_xy:Vector"),
        (f"{w}_minus_ak:Vector", f"{w}_minus_ak_xy:Vector"),
        ("time:Seconds", f"{w}_phase:#0"),
        (f"input:Speed {number}", f"{w}_phase:#1"),
        (f"{w}_k_xy:Y", f"{w}_arg_y:#0"),
        ("p:Y", f"{w}_arg_y:#1"),
        (f"{w}_phase:Value", f"{w}_arg_y:#2"),
        (f"{w}_k_xy:X", f"{w}_arg:#0"),
        ("p:X", f"{w}_arg:#1"),
        (f"{w}_arg_y:Value", f"{w}_arg:#2"),
        (f"{w}_arg:Value", f"{w}_sin:#0"),
        (f"{w}_arg:Value", f"{w}_cos:#0"),
        (f"{w}_sin:Value", f"{w}_h:#0"),
        (f"input:Amplitude {number}", f"{w}_h:#1"),
        (f"{w}_cos:Value", f"{w}_nx:#0"),
        (f"{w}_minus_ak_xy:X", f"{w}_nx:#1"),
        (f"{w}_cos:Value", f"{w}_ny:#0"),
        (f"{w}_minus_ak_xy:Y", f"{w}_ny:#1"),
    ]
    # The first wave adds onto the constants' zero; later ones onto the sums so far.
    for key, running in ((f"{w}_h", height), (f"{w}_nx", slope_x), (f"{w}_ny", slope_y)):
        if running is not None:
            links.append((running, f"{key}:#2"))
    return nodes, links, (f"{w}_h:Value", f"{w}_nx:Value", f"{w}_ny:Value")


def _build():
    nodes = {
        "position": Node("GeometryNodeInputPosition", 1, label="position"),
        "p": Node("ShaderNodeSeparateXYZ", 2, label="p"),
        "time": Node("GeometryNodeInputSceneTime", 1, label="t (scene seconds)"),
    }
    links = [("position:Position", "p:Vector")]
    sums = (None, None, None)
    for number in range(1, WAVE_COUNT + 1):
        wave_nodes, wave_links, sums = _wave_nodes(number, *sums)
        nodes.update(wave_nodes)
        links += wave_links
    height, minus_slope_x, minus_slope_y = sums
    nodes.update(
        {
            "normal_raw": Node("ShaderNodeCombineXYZ", 12, values={"Z": 1.0}, label="(-dh/dx, -dh/dy, 1)"),
            "normal": vmath("NORMALIZE", 13, "analytic normal"),
            "store": Node(
                "GeometryNodeStoreNamedAttribute",
                14,
                {"data_type": "FLOAT_VECTOR", "domain": "POINT"},
                {"Name": NORMAL_ATTRIBUTE},
                label=f"store '{NORMAL_ATTRIBUTE}'",
            ),
            "lift": Node("ShaderNodeCombineXYZ", 14, label="(0, 0, sum h)"),
            "move": Node("GeometryNodeSetPosition", 15, label="lift the points"),
        }
    )
    links += [
        (minus_slope_x, "normal_raw:X"),
        (minus_slope_y, "normal_raw:Y"),
        ("normal_raw:Vector", "normal:#0"),
        ("input:Geometry", "store:Geometry"),
        ("normal:Vector", "store:Value"),
        (height, "lift:Z"),
        ("store:Geometry", "move:Geometry"),
        ("lift:Vector", "move:Offset"),
        ("move:Geometry", "output:Geometry"),
    ]
    return nodes, tuple(links)


_NODES, _LINKS = _build()

INPUTS = (
    Socket("Geometry", "NodeSocketGeometry"),
    *(socket for i, wave in enumerate(DEFAULT_WAVES, 1) for socket in wave_inputs(i, wave)),
)

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description="Four summed sine waves lift the mesh; their analytic normal is stored as 'water_normal'",
    inputs=INPUTS,
    outputs=(Socket("Geometry", "NodeSocketGeometry"),),
    nodes=_NODES,
    links=_LINKS,
    tree_type="GeometryNodeTree",
)
