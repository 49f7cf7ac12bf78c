"""What the lake's and the sea's shading share, so the two read the bed and the sun alike:
water's IOR, the surroundings' attribute names, the sun's input, the transmittance and the glint."""

import math as _math

from . import bump_uv
from .physics import WATER_IOR
from .spec import Node, Socket, attribute, math, vmath

LIT_FOAM_SINCE = (4, 5, 0)  # the first LTS whose EEVEE keeps traced refraction beside a diffuse closure
IOR = WATER_IOR

# The attributes the surroundings modifier stores on the water's points (all floats, per point).
DEPTH_ATTRIBUTE = "water_depth"  # metres straight down to the bed; 1000 where nothing is below
SHORE_ATTRIBUTE = "water_shore_distance"  # metres in the plane to the nearest waterline; 1000: none
FLAG_ATTRIBUTE = "water_surroundings"  # 1 where the modifier ran; an Attribute node reads 0 elsewhere

# The reference's default light, (-1, -1, -1) in XNA's Y-up world, is (-1, 1, -1) in Blender.
DEFAULT_SUN = (-0.57735, 0.57735, -0.57735)
SUN_DIRECTION_INPUT = Socket(
    "Sun Direction",
    "NodeSocketVector",
    DEFAULT_SUN,
    subtype="DIRECTION",
    tooltip="Direction sunlight travels; the material drives it from the scene's sun",
)
# The inputs `Water Surface Bump UV` takes from the enclosing group, by the same names.
BUMP_UV_INPUTS = tuple(socket.name for socket in bump_uv.SCROLL_INPUTS)


def transmittance_nodes():
    """Beer-Lambert: `T = exp(-Absorption * path)` ("transmit:Vector"), `path` = the refracted ray's
    way down to the bed. Needs a "geometry" node (Geometry); shared with the ocean shading.

    `cos_i = eye . N` with the geometric normal; Snell at IOR 1.33 gives
    `cos_t^2 = 1 - (1 - cos_i^2) / 1.33^2` and `path = depth / cos_t`; per channel
    `exp(-x)` is `(1 / e)^x`. With no `water_depth` attribute the depth reads 0, so `T = 1`.
    """
    nodes = {
        "depth": attribute(DEPTH_ATTRIBUTE, 14, "water_depth (m)"),
        "cos_i": vmath("DOT_PRODUCT", 15, "cos_i = eye . geometric normal"),
        "cos_i2": math("MULTIPLY", 16, "cos_i^2"),
        "cos_t2": math(
            "MULTIPLY_ADD", 17, f"cos_t^2 = 1 - (1 - cos_i^2) / {IOR}^2", b=1 / IOR**2, c=1 - 1 / IOR**2
        ),
        "inv_cos_t": math("INVERSE_SQRT", 18, "1 / cos_t"),
        "path": math("MULTIPLY", 19, "path = depth / cos_t"),
        "optical": vmath("SCALE", 20, "Absorption x path"),
        "optical_xyz": Node("ShaderNodeSeparateXYZ", 21, label="per channel"),
        **{f"transmit_{c}": math("POWER", 22, f"T.{c} = exp(-{c})", a=_math.exp(-1.0)) for c in "xyz"},
        "transmit": Node("ShaderNodeCombineXYZ", 23, label="T"),
    }
    links = [
        ("geometry:Incoming", "cos_i:#0"),
        ("geometry:True Normal", "cos_i:#1"),
        ("cos_i:Value", "cos_i2:#0"),
        ("cos_i:Value", "cos_i2:#1"),
        ("cos_i2:Value", "cos_t2:#0"),
        ("cos_t2:Value", "inv_cos_t:#0"),
        ("depth:Fac", "path:#0"),
        ("inv_cos_t:Value", "path:#1"),
        ("input:Absorption", "optical:#0"),
        ("path:Value", "optical:Scale"),
        ("optical:Vector", "optical_xyz:Vector"),
    ]
    for c in "xyz":
        links += [
            (f"optical_xyz:{c.upper()}", f"transmit_{c}:#1"),
            (f"transmit_{c}:Value", f"transmit:{c.upper()}"),
        ]
    return nodes, links


def glint_nodes(normal, power, column=15):
    """The sun's glint lobe `pow(max(dot(reflect(L, n), eye), 0), power)` ("glint_pow:Value"), L
    the group's `Sun Direction`, n the socket `normal`, `power` a socket; needs a "geometry"
    node. Shared with the ocean shading's glint view."""
    nodes = {
        "sun": vmath("NORMALIZE", column, "L"),
        "reflect": vmath("REFLECT", column + 1, "reflect(L, n)"),
        "glint_dot": vmath("DOT_PRODUCT", column + 2, ". eye"),
        "glint_max": math("MAXIMUM", column + 3, "max(, 0)", b=0.0),
        "glint_pow": math("POWER", column + 4, f"pow(, {power.partition(':')[2]})"),
    }
    links = [
        ("input:Sun Direction", "sun:#0"),
        ("sun:Vector", "reflect:#0"),
        (normal, "reflect:#1"),
        ("reflect:Vector", "glint_dot:#0"),
        ("geometry:Incoming", "glint_dot:#1"),
        ("glint_dot:Value", "glint_max:#0"),
        ("glint_max:Value", "glint_pow:#0"),
        (power, "glint_pow:#1"),
    ]
    return nodes, links
