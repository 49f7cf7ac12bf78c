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
VERSION = 1
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


def _wave_nodes(number):
    """Nodes and links of one wave: its height h and its slope d * D.

    What does not vary over the mesh is worked out once per wave: the wave
    vector k = D / lambda, A k and the phase t s. Per point that leaves
    arg = dot(k, p) + t s, h = A sin(arg) and slope = cos(arg) A k.
    """
    w = f"w{number}"
    column = 2
    nodes = {
        f"{w}_flat": vmath("MULTIPLY", column, f"D{number} in the plane", b=(1.0, 1.0, 0.0)),
        f"{w}_dir": vmath("NORMALIZE", column + 1, f"D{number}"),
        f"{w}_len": math("MAXIMUM", column + 1, f"lambda{number} (>= {MIN_WAVELENGTH})", b=MIN_WAVELENGTH),
        f"{w}_inv": math("DIVIDE", column + 2, f"1 / lambda{number}", a=1.0),
        f"{w}_k": vmath("SCALE", column + 3, f"k{number} = D / lambda"),
        f"{w}_ak": vmath("SCALE", column + 4, f"A{number} k{number}"),
        f"{w}_time": math("MULTIPLY", column + 3, f"t * s{number}"),
        f"{w}_dot": vmath("DOT_PRODUCT", column + 5, f"dot(k{number}, p)"),
        f"{w}_arg": math("ADD", column + 6, f"arg{number}"),
        f"{w}_sin": math("SINE", column + 7, f"sin arg{number}"),
        f"{w}_cos": math("COSINE", column + 7, f"cos arg{number}"),
        f"{w}_h": math("MULTIPLY", column + 8, f"h{number} = A sin"),
        f"{w}_slope": vmath("SCALE", column + 8, f"d{number} D{number} = cos * A k"),
    }
    links = [
        (f"input:Direction {number}", f"{w}_flat:#0"),
        (f"{w}_flat:Vector", f"{w}_dir:#0"),
        (f"input:Wavelength {number}", f"{w}_len:#0"),
        (f"{w}_len:Value", f"{w}_inv:#1"),
        (f"{w}_dir:Vector", f"{w}_k:#0"),
        (f"{w}_inv:Value", f"{w}_k:Scale"),
        (f"{w}_k:Vector", f"{w}_ak:#0"),
        (f"input:Amplitude {number}", f"{w}_ak:Scale"),
        ("time:Seconds", f"{w}_time:#0"),
        (f"input:Speed {number}", f"{w}_time:#1"),
        ("position:Position", f"{w}_dot:#0"),
        (f"{w}_k:Vector", f"{w}_dot:#1"),
        (f"{w}_dot:Value", f"{w}_arg:#0"),
        (f"{w}_time:Value", f"{w}_arg:#1"),
        (f"{w}_arg:Value", f"{w}_sin:#0"),
        (f"{w}_arg:Value", f"{w}_cos:#0"),
        (f"{w}_sin:Value", f"{w}_h:#0"),
        (f"input:Amplitude {number}", f"{w}_h:#1"),
        (f"{w}_ak:Vector", f"{w}_slope:#0"),
        (f"{w}_cos:Value", f"{w}_slope:Scale"),
    ]
    return nodes, links


def _build():
    nodes = {
        "position": Node("GeometryNodeInputPosition", 1, label="p"),
        "time": Node("GeometryNodeInputSceneTime", 1, label="t (scene seconds)"),
    }
    links = []
    for number in range(1, WAVE_COUNT + 1):
        wave_nodes, wave_links = _wave_nodes(number)
        nodes.update(wave_nodes)
        links += wave_links
    # Sum the heights and the slopes, wave after wave.
    height, slope = "w1_h:Value", "w1_slope:Vector"
    for number in range(2, WAVE_COUNT + 1):
        nodes[f"sum_h{number}"] = math("ADD", 11, f"h1 + .. + h{number}")
        nodes[f"sum_s{number}"] = vmath("ADD", 11, f"slope 1 .. {number}")
        links += [
            (height, f"sum_h{number}:#0"),
            (f"w{number}_h:Value", f"sum_h{number}:#1"),
            (slope, f"sum_s{number}:#0"),
            (f"w{number}_slope:Vector", f"sum_s{number}:#1"),
        ]
        height, slope = f"sum_h{number}:Value", f"sum_s{number}:Vector"
    nodes.update(
        {
            "normal_raw": vmath(
                "MULTIPLY_ADD", 12, "(-dev.x, -dev.y, 1)", b=(-1.0, -1.0, 0.0), c=(0, 0, 1.0)
            ),
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
        (slope, "normal_raw:#0"),
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
