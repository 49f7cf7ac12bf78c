"""`Water Underside`: the one rule for a water surface seen from below (docs/MODEL.md section 15).

Both shadings, the lake's (`lake/water_surface.py`) and the ocean's (`sea/ocean_shade.py`), take from it
what they show on a backface (Geometry > Backfacing), so Snell's window is worked out once:

* the normal turned to face the eye, `n · sign(I · n)` (`I` Geometry > Incoming; a mesh's own
  normal comes turned on a backface, a normal worked out in the shader, as the waves', does not);
* the reflected weight `F`: Blender's Fresnel node at water's IOR (`physics.WATER_IOR`) on that
  normal. It takes `1 / IOR` on a backface and gives 1 past the critical angle,
  `asin(1 / IOR)` = 48.75° (total internal reflection), so the water below shows outside the
  window;
* the refracted weight `1 - F`: the sky, refracted, inside the window.

What each shading does with them (which closures they weight) stays its own: see MODEL section 15.
On the top side the same outputs are water's own Fresnel (the normal is `n` itself, the node takes
the IOR): the ocean shading's `Water Fresnel` reads its `Refracted`, `1 - R`, there.
"""

from .physics import WATER_IOR
from .spec import GroupSpec, Node, Socket, math, vmath

NAME = "Water Underside"
VERSION = 1

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description="Seen from below: the normal turned to face the eye, and the Fresnel weights of "
    "Snell's window (reflected F, refracted 1 - F) at water's IOR",
    inputs=(
        Socket(
            "Normal",
            "NodeSocketVector",
            tooltip="The shading normal, world space (either way round)",
            hide_value=True,
        ),
    ),
    outputs=(
        Socket("Normal", "NodeSocketVector", tooltip="The normal turned to face the eye: n · sign(I · n)"),
        Socket(
            "Reflected",
            "NodeSocketFloat",
            tooltip="F: the share reflected back down (1 past the critical angle)",
        ),
        Socket("Refracted", "NodeSocketFloat", tooltip="1 - F: the share of the sky seen through"),
    ),
    nodes={
        "geometry": Node("ShaderNodeNewGeometry", 1),
        "facing": vmath("DOT_PRODUCT", 2, "I . n"),
        "sign": math("SIGN", 3, "its sign"),
        "turned": vmath("SCALE", 4, "n, facing the eye"),
        "fresnel": Node("ShaderNodeFresnel", 5, values={"IOR": WATER_IOR}, label="Fresnel from below"),
        "clear": math("SUBTRACT", 6, "1 - F", a=1.0),
    },
    links=(
        ("geometry:Incoming", "facing:#0"),
        ("input:Normal", "facing:#1"),
        ("facing:Value", "sign:#0"),
        ("input:Normal", "turned:#0"),
        ("sign:Value", "turned:Scale"),
        ("turned:Vector", "fresnel:Normal"),
        ("fresnel:Fac", "clear:#1"),
        ("turned:Vector", "output:Normal"),
        ("fresnel:Fac", "output:Reflected"),
        ("clear:Value", "output:Refracted"),
    ),
)
