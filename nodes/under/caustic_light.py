"""`Water Caustic Light`: the ripples' caustic pattern as the shadow the surface casts, so the sun
lights everything under the water in moving lines, seen from below (issue 40 point 5).

The shader of a sheet just under the surface that only shadow rays meet (the `Water Caustic
Sheet` of `caustic_sheet.py`, made while the camera is under the water): where a shadow ray from
anything under the water crosses it, the sunlight keeps `T = min(F / (1 + k), 1)` per channel.
`F = 1 + k (c - 1)` is the caustics group's own factor at this point of the surface (the same
tile, scrolled with the bump, the same contrast `k` from `Caustics`, the sun, the bed's depth and
the sunlight's absorption: `caustics.py`), read with no view offset: the shadow ray crosses the
surface where the light it stands for came through. A shadow can only take light away, so the
bright lines (c = 2 and more) get the whole sun and the rest less: the mean is darker than
above by about `k / (1 + k)` of the pattern's dark share (measured in docs/BENCHMARKS.md). With
`Caustics` 0, or no sun, T is 1: no shadow at all.

From above, what the water shows below already carries the pattern (the water shader's factor),
so the sheet is made only while the camera is under the water: nothing is patterned twice. A
sheet made for every placement of the water (`Each Placement` 1: the camera beside the water as
it stands itself, maybe under a collection instance's placement of it) lets all the sunlight
through in each placement whose level the camera is over (`camera_gate.placement_gate`).
"""

from .. import bump_uv, caustics
from ..spec import GroupSpec, Node, Socket, group_node, math, pass_inputs, vmath
from .camera_gate import EACH_PLACEMENT, placement_gate, placement_links

NAME = "Water Caustic Light"
VERSION = 2  # 2: Each Placement (a collection instance's placements, each its own camera gate)

INPUTS = (*bump_uv.SCROLL_INPUTS, *caustics.INPUTS[3:])  # the lake's and the ocean's names


def _nodes():
    view_nodes, _ = caustics._view_nodes()
    sun_nodes, sun_links = caustics._sun_nodes()
    tile_nodes, tile_links = caustics._tile_nodes()
    contrast_nodes, contrast_links = caustics._contrast_nodes()
    kept = {key: view_nodes[key] for key in ("geometry", "depth", "uv_size", "d_near")}
    nodes = {
        **kept,
        **sun_nodes,
        **tile_nodes,
        **contrast_nodes,
        "bump_uv": group_node(bump_uv.NAME, 12, "scrolled bump UV"),
        "facing": vmath("DOT_PRODUCT", 2, "N . up", b=(0.0, 0.0, 1.0)),
        "flip": math("SIGN", 3, "+1 facing up, -1 down"),
        "up_n": vmath("SCALE", 4, "N, facing up"),
        "k_1": math("ADD", 22, "1 + k", b=1.0),
        "gain": math("DIVIDE", 23, "1 / (1 + k)", a=1.0),
        "t": vmath("SCALE", 24, "F / (1 + k)"),
        "t_max": vmath("MINIMUM", 25, "at most 1: a shadow only takes light away", b=(1.0, 1.0, 1.0)),
        **placement_gate(22, 0.0),
        "t_here": vmath("MAXIMUM", 26, "all of it where this placement's camera is over it"),
        "shadow": Node("ShaderNodeBsdfTransparent", 27, label="sunlight let through"),
    }
    # No view offset: the shadow ray crosses the surface where its light came through.
    dropped = {("to_bed:Vector", "offset:#0"), ("from_sun:Vector", "offset:#1"), ("input:Vector", "at:#0")}
    links = [link for link in (*sun_links, *tile_links, *contrast_links) if link not in dropped]
    links = [link for link in links if link != ("factor:Vector", "output:Factor")]
    # Cycles turns a surface's normal to face the ray, and a shadow ray comes from below: the
    # surface's normal, turned up again.
    links = [("up_n:Vector" if a == "geometry:True Normal" else a, b) for a, b in links]
    links += [
        *pass_inputs("bump_uv", [socket.name for socket in bump_uv.SCROLL_INPUTS]),
        ("depth:Fac", "d_near:#0"),
        ("geometry:True Normal", "facing:#0"),
        ("facing:Value", "flip:#0"),
        ("geometry:True Normal", "up_n:#0"),
        ("flip:Value", "up_n:Scale"),
        ("bump_uv:Vector", "at:#0"),
        ("k:Value", "k_1:#0"),
        ("k_1:Value", "gain:#1"),
        ("factor:Vector", "t:#0"),
        ("gain:Value", "t:Scale"),
        ("t:Vector", "t_max:#0"),
        *placement_links(),
        ("t_max:Vector", "t_here:#0"),
        ("shut:Value", "t_here:#1"),
        ("t_here:Vector", "shadow:Color"),
        ("shadow:BSDF", "output:Shadow"),
    ]
    return nodes, tuple(links)


_NODES, _LINKS = _nodes()

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description="The caustic pattern as the shadow the surface casts on what lies under it: the "
    "sunlight let through a sheet just under the surface",
    inputs=(*INPUTS, EACH_PLACEMENT),
    outputs=(Socket("Shadow", "NodeSocketShader", tooltip="A transparent shader: the sunlight let through"),),
    nodes=_NODES,
    links=_LINKS,
)
