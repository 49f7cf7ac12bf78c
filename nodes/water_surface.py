"""`Water Surface`: the lake water of SPEC section 1 as one EEVEE/Cycles shader group.

Per pixel (Blender is Z-up; `eye` is Geometry > Incoming, pointing at the camera):

* the bump map is sampled (mirror extension) at the scrolling, wind-aligned UV
  of `Water Surface Bump UV`; with **Bump Layers** N > 1 also at seed 001's finer
  layers (UV scale x2, x4, x8, scrolling at x2, x1, x0.5 the first layer's
  speed: seed 001's x2, x4, x2, x1 of a base speed of Wind Force / 2), the
  first N samples averaged; the mean is decoded to a tangent-space normal
  `t = 2 * bump - 1` whose X/Y lie in the wind frame, and rotated back into UV space;
* **Wave Height** scales the normal's tilt for the reflection and refraction
  closures. The seeds shift their screen-space lookups by
  `waveHeight * (bump.rg - 0.5) * 2`; EEVEE traces rays instead of looking up
  a texture, so the same wobble comes from tilting the closure normal by the
  same amount: its X/Y become `Wave Height * t.xy` (0 = a flat mirror), and a
  ray reflected off it moves on screen in proportion, as the lookup did.
* **Bump Strength** does the same for the normal `n` used by Fresnel and glint;
* `F = clamp(dot(eye, n), 0, 1)`, and the surface is
  `(1 - Dull Blend) * ((1 - F) * reflection + F * refraction) + Dull Blend * Dull Color`
  (dull colour unlit, as in the seeds) plus the glint
  `Sun Color * Specular Strength * pow(max(dot(reflect(L, n), eye), 0), Specular Power)`
  (seed 003: a coloured light multiplies its highlight).

Reflection is a sharp Glossy BSDF and refraction a Refraction BSDF (IOR 1.33):
EEVEE's ray tracing supplies what the seeds' reflection and refraction maps
held, and Cycles traces them. Neither closure adds a Fresnel of its own, so the
seeds' two lerps are closure weights: the glossy's colour is
`(1 - Dull Blend) * (1 - F)`, the refraction's `(1 - Dull Blend) * F` (exact with
the Material Output's Thickness at 0: see `material.py`), and one emission
carries the dull colour and the glint. The debug views only change these three
weights, so they cost no extra closures.
"""

from . import bump_uv, wind_frame
from .spec import BUMP_IMAGE, GroupSpec, Node, Socket, group_node, math, vmath

NAME = "Water Surface"
VERSION = 2
MAX_BUMP_LAYERS = 4

DEBUG_VIEWS = (
    (0, "FINAL", "Final", "The finished water"),
    (1, "REFLECTION", "Reflection", "The reflection closure alone"),
    (2, "REFRACTION", "Refraction", "The refraction closure alone"),
    (3, "FRESNEL", "Fresnel", "F as unlit grey"),
    (4, "NORMAL", "Bump Normal", "The bump normal n * 0.5 + 0.5, unlit"),
    (5, "GLINT", "Glint", "The sun glint alone, unlit, in the sun's colour"),
)

# The reference's default light, (-1, -1, -1) in XNA's Y-up world, is (-1, 1, -1) in Blender.
DEFAULT_SUN = (-0.57735, 0.57735, -0.57735)

INPUTS = (
    Socket(
        "Wave Height",
        "NodeSocketFloat",
        0.3,
        min=0.0,
        max=10.0,
        tooltip="How far the bump tilts the reflection and refraction (0 = flat mirror)",
    ),
    *bump_uv.SCROLL_INPUTS,
    Socket(
        "Bump Layers",
        "NodeSocketInt",
        1,
        min=1,
        max=MAX_BUMP_LAYERS,
        tooltip="How many bump layers are averaged (seed 001): each finer, scrolling at its own speed",
    ),
    Socket(
        "Dull Color",
        "NodeSocketColor",
        (0.3, 0.3, 0.5, 1.0),
        tooltip="Unlit tint that makes the water look murky",
    ),
    Socket(
        "Dull Blend",
        "NodeSocketFloat",
        0.2,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
        tooltip="Share of the dull colour in the final colour",
    ),
    Socket(
        "Specular Power",
        "NodeSocketFloat",
        256.0,
        min=1.0,
        max=4096.0,
        tooltip="Sharpness of the sun glint (higher = smaller highlight)",
    ),
    Socket(
        "Specular Strength",
        "NodeSocketFloat",
        1.0,
        min=0.0,
        max=100.0,
        tooltip="Brightness of the sun glint (0 = none)",
    ),
    Socket(
        "Sun Direction",
        "NodeSocketVector",
        DEFAULT_SUN,
        subtype="DIRECTION",
        tooltip="Direction sunlight travels; the material drives it from the scene's sun",
    ),
    Socket(
        "Sun Color",
        "NodeSocketColor",
        (1.0, 1.0, 1.0, 1.0),
        tooltip="Colour of the glint; the material drives it from the followed sun's colour",
    ),
    Socket(
        "Bump Strength",
        "NodeSocketFloat",
        1.0,
        min=0.0,
        max=10.0,
        tooltip="How much the bump tilts the normal used for Fresnel and glint (0 = flat)",
    ),
    Socket(
        "Debug View",
        "NodeSocketInt",
        0,
        min=0,
        max=5,
        tooltip="0 final, 1 reflection, 2 refraction, 3 Fresnel F, 4 bump normal, 5 glint",
    ),
)


# Seed 001's layers after the first: (UV scale, scroll speed), both relative to layer 1.
LAYERS = ((2.0, 2.0), (4.0, 1.0), (8.0, 0.5))


def _layer_nodes():
    """Layers 2-4, sampled at `scale * uv1 + (speed - scale) * scroll`, each counted once reached.

    Returns the nodes, the links, and the sockets of the weighted sum and of the layer count.
    """
    nodes, links = {}, []
    total, count = "bump:Color", None
    for k, (scale, speed) in enumerate(LAYERS, start=2):
        nodes |= {
            f"scroll_{k}": vmath("SCALE", 2, f"scroll x {speed - scale:g}", scale=speed - scale),
            f"uv_{k}": vmath("MULTIPLY_ADD", 3, f"layer {k}: uv x {scale:g} + scroll", b=(scale,) * 3),
            f"bump_{k}": Node(
                "ShaderNodeTexImage",
                4,
                {"extension": "MIRROR", "image": BUMP_IMAGE},
                label=f"bump layer {k}",
            ),
            f"on_{k}": math("GREATER_THAN", 4, f"Bump Layers >= {k}", b=k - 0.5),
            f"sum_{k}": vmath("MULTIPLY_ADD", 5, f"+ layer {k} if on"),
            f"count_{k}": math("ADD", 5, "layers averaged", a=1.0) if count is None else math("ADD", 5, "+1"),
        }
        links += [
            ("bump_uv:Scroll", f"scroll_{k}:#0"),
            ("bump_uv:Vector", f"uv_{k}:#0"),
            (f"scroll_{k}:Vector", f"uv_{k}:#2"),
            (f"uv_{k}:Vector", f"bump_{k}:Vector"),
            ("input:Bump Layers", f"on_{k}:#0"),
            (f"bump_{k}:Color", f"sum_{k}:#0"),
            (f"on_{k}:Value", f"sum_{k}:#1"),
            (total, f"sum_{k}:#2"),
            (f"on_{k}:Value", f"count_{k}:#1"),
        ]
        if count is not None:
            links.append((count, f"count_{k}:#0"))
        total, count = f"sum_{k}:Vector", f"count_{k}:Value"
    nodes["mean"] = vmath("DIVIDE", 6, "mean of the layers")
    links += [(total, "mean:#0"), (count, "mean:#1")]
    return nodes, links


def _weight_nodes():
    """The closure weights and the emission colour for the final picture and each debug view.

    Final: glossy `(1 - Dull Blend) (1 - F)`, refraction `(1 - Dull Blend) F`,
    emission `Dull Blend * Dull Color + glint`. View 1 or 2: that closure at
    weight 1 alone. Views 3-5: only the emission, showing F, the normal colour
    or the glint. Any other number shows the final picture.
    """
    nodes, links = {}, []
    previous = None
    for number in range(1, 6):
        nodes[f"is_{number}"] = math("COMPARE", 17, f"view == {number}", b=float(number), c=0.5)
        links.append(("input:Debug View", f"is_{number}:#0"))
        if previous is not None:
            nodes[f"any_{number}"] = math("ADD", 18, "a debug view")
            links += [(previous, f"any_{number}:#0"), (f"is_{number}:Value", f"any_{number}:#1")]
            previous = f"any_{number}:Value"
        else:
            previous = "is_1:Value"
    nodes |= {
        "is_final": math("SUBTRACT", 19, "final view", a=1.0),
        "clear": math("SUBTRACT", 19, "1 - Dull Blend", a=1.0),
        "keep": math("MULTIPLY", 20, "final x (1 - Dull Blend)"),
        "one_minus_f": math("SUBTRACT", 20, "1 - F", a=1.0),
        "w_reflect": math("MULTIPLY_ADD", 21, "reflection weight"),
        "w_refract": math("MULTIPLY_ADD", 21, "refraction weight"),
        "dull_part": vmath("SCALE", 19, "Dull Blend x Dull Color"),
        "lit": vmath("ADD", 20, "+ glint"),
        "e_final": vmath("SCALE", 21, "if final"),
        "e_f": vmath("MULTIPLY_ADD", 22, "+ F if view 3"),
        "e_n": vmath("MULTIPLY_ADD", 22, "+ normal if view 4"),
        "e_glint": vmath("MULTIPLY_ADD", 22, "+ glint if view 5"),
    }
    links += [
        (previous, "is_final:#1"),
        ("input:Dull Blend", "clear:#1"),
        ("is_final:Value", "keep:#0"),
        ("clear:Value", "keep:#1"),
        ("fresnel:Value", "one_minus_f:#1"),
        ("keep:Value", "w_reflect:#0"),
        ("one_minus_f:Value", "w_reflect:#1"),
        ("is_1:Value", "w_reflect:#2"),
        ("keep:Value", "w_refract:#0"),
        ("fresnel:Value", "w_refract:#1"),
        ("is_2:Value", "w_refract:#2"),
        ("input:Dull Color", "dull_part:#0"),
        ("input:Dull Blend", "dull_part:Scale"),
        ("dull_part:Vector", "lit:#0"),
        ("glint_color:Vector", "lit:#1"),
        ("lit:Vector", "e_final:#0"),
        ("is_final:Value", "e_final:Scale"),
        ("fresnel:Value", "e_f:#0"),
        ("is_3:Value", "e_f:#1"),
        ("e_final:Vector", "e_f:#2"),
        ("normal_colour:Vector", "e_n:#0"),
        ("is_4:Value", "e_n:#1"),
        ("e_f:Vector", "e_n:#2"),
        ("glint_color:Vector", "e_glint:#0"),
        ("is_5:Value", "e_glint:#1"),
        ("e_n:Vector", "e_glint:#2"),
    ]
    return nodes, links


_LAYER_NODES, _LAYER_LINKS = _layer_nodes()
_WEIGHT_NODES, _WEIGHT_LINKS = _weight_nodes()

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description="Lake water: bump, Fresnel blend of reflection and refraction, dull tint, sun glint",
    inputs=INPUTS,
    outputs=(Socket("Shader", "NodeSocketShader"),),
    nodes={
        # Sample the bump layers at the scrolled UVs, average, decode, rotate out of the wind frame.
        "bump_uv": group_node(bump_uv.NAME, 1),
        "bump": Node(
            "ShaderNodeTexImage",
            4,
            {"extension": "MIRROR", "image": BUMP_IMAGE},
            label="bump layer 1 (mirror)",
        ),
        **_LAYER_NODES,
        "frame": group_node(wind_frame.NAME, 6),
        "decode": vmath("MULTIPLY_ADD", 7, "t = 2 * bump - 1", b=(2.0, 2.0, 2.0), c=(-1.0, -1.0, -1.0)),
        "t": Node("ShaderNodeSeparateXYZ", 8, label="t"),
        "w": Node("ShaderNodeSeparateXYZ", 8, label="w"),
        "tx_wy": math("MULTIPLY", 9, "t.x * w.y"),
        "ty_wy": math("MULTIPLY", 9, "t.y * w.y"),
        "minus_wx": math("MULTIPLY", 9, "-w.x", b=-1.0),
        "uv_x": math("MULTIPLY_ADD", 10, "t.x p.x + t.y w.x"),
        "uv_y": math("MULTIPLY_ADD", 10, "t.x p.y + t.y w.y"),
        # Tilt by Wave Height (closures) and by Bump Strength (Fresnel, glint).
        "h_x": math("MULTIPLY", 11, "x * Wave Height"),
        "h_y": math("MULTIPLY", 11, "y * Wave Height"),
        "s_x": math("MULTIPLY", 11, "x * Bump Strength"),
        "s_y": math("MULTIPLY", 11, "y * Bump Strength"),
        "tilt_h": Node("ShaderNodeCombineXYZ", 12, label="closure tilt"),
        "tilt_s": Node("ShaderNodeCombineXYZ", 12, label="bump tilt"),
        "encode_h": vmath("MULTIPLY_ADD", 13, "to colour", b=(0.5, 0.5, 0.5), c=(0.5, 0.5, 0.5)),
        "encode_s": vmath("MULTIPLY_ADD", 13, "to colour", b=(0.5, 0.5, 0.5), c=(0.5, 0.5, 0.5)),
        "normal_h": Node("ShaderNodeNormalMap", 14, label="closure normal"),
        "normal_s": Node("ShaderNodeNormalMap", 14, label="n"),
        # Fresnel: F = clamp(dot(eye, n), 0, 1).
        "geometry": Node("ShaderNodeNewGeometry", 14),
        "eye_dot_n": vmath("DOT_PRODUCT", 15, "eye . n"),
        "fresnel": math("MULTIPLY", 16, "F = clamp(eye . n)", clamp=True, b=1.0),
        "normal_colour": vmath("MULTIPLY_ADD", 16, "n * 0.5 + 0.5", b=(0.5, 0.5, 0.5), c=(0.5, 0.5, 0.5)),
        # Glint: Sun Color * Specular Strength * pow(max(dot(reflect(L, n), eye), 0), Specular Power).
        "sun": vmath("NORMALIZE", 15, "L"),
        "reflect": vmath("REFLECT", 16, "reflect(L, n)"),
        "glint_dot": vmath("DOT_PRODUCT", 17, ". eye"),
        "glint_max": math("MAXIMUM", 18, "max(, 0)", b=0.0),
        "glint_pow": math("POWER", 19, "pow(, Specular Power)"),
        "glint": math("MULTIPLY", 20, "* Specular Strength"),
        "glint_color": vmath("SCALE", 21, "* Sun Color"),
        **_WEIGHT_NODES,
        # The closures, weighted, and the one emission.
        "glossy": Node(
            "ShaderNodeBsdfAnisotropic",
            23,
            {"distribution": "GGX"},
            {"Roughness": 0.0},
            label="reflection",
        ),
        "refraction": Node(
            "ShaderNodeBsdfRefraction",
            23,
            {"distribution": "GGX"},
            {"Roughness": 0.0, "IOR": 1.33},
            label="refraction",
        ),
        "emission": Node("ShaderNodeEmission", 23, values={"Strength": 1.0}, label="dull colour + glint"),
        "closures": Node("ShaderNodeAddShader", 24, label="reflection + refraction"),
        "final": Node("ShaderNodeAddShader", 25, label="+ emission"),
    },
    links=(
        ("input:Wave Length", "bump_uv:Wave Length"),
        ("input:Wind Direction", "bump_uv:Wind Direction"),
        ("input:Wind Force", "bump_uv:Wind Force"),
        ("input:Time", "bump_uv:Time"),
        ("bump_uv:Vector", "bump:Vector"),
        *_LAYER_LINKS,
        ("input:Wind Direction", "frame:Wind Direction"),
        ("mean:Vector", "decode:#0"),
        ("decode:Vector", "t:Vector"),
        ("frame:Wind", "w:Vector"),
        ("t:X", "tx_wy:#0"),
        ("w:Y", "tx_wy:#1"),
        ("t:Y", "ty_wy:#0"),
        ("w:Y", "ty_wy:#1"),
        ("w:X", "minus_wx:#0"),
        ("t:Y", "uv_x:#0"),
        ("w:X", "uv_x:#1"),
        ("tx_wy:Value", "uv_x:#2"),
        ("t:X", "uv_y:#0"),
        ("minus_wx:Value", "uv_y:#1"),
        ("ty_wy:Value", "uv_y:#2"),
        ("uv_x:Value", "h_x:#0"),
        ("input:Wave Height", "h_x:#1"),
        ("uv_y:Value", "h_y:#0"),
        ("input:Wave Height", "h_y:#1"),
        ("uv_x:Value", "s_x:#0"),
        ("input:Bump Strength", "s_x:#1"),
        ("uv_y:Value", "s_y:#0"),
        ("input:Bump Strength", "s_y:#1"),
        ("h_x:Value", "tilt_h:X"),
        ("h_y:Value", "tilt_h:Y"),
        ("t:Z", "tilt_h:Z"),
        ("s_x:Value", "tilt_s:X"),
        ("s_y:Value", "tilt_s:Y"),
        ("t:Z", "tilt_s:Z"),
        ("tilt_h:Vector", "encode_h:#0"),
        ("tilt_s:Vector", "encode_s:#0"),
        ("encode_h:Vector", "normal_h:Color"),
        ("encode_s:Vector", "normal_s:Color"),
        ("geometry:Incoming", "eye_dot_n:#0"),
        ("normal_s:Normal", "eye_dot_n:#1"),
        ("eye_dot_n:Value", "fresnel:#0"),
        ("normal_s:Normal", "normal_colour:#0"),
        ("input:Sun Direction", "sun:#0"),
        ("sun:Vector", "reflect:#0"),
        ("normal_s:Normal", "reflect:#1"),
        ("reflect:Vector", "glint_dot:#0"),
        ("geometry:Incoming", "glint_dot:#1"),
        ("glint_dot:Value", "glint_max:#0"),
        ("glint_max:Value", "glint_pow:#0"),
        ("input:Specular Power", "glint_pow:#1"),
        ("glint_pow:Value", "glint:#0"),
        ("input:Specular Strength", "glint:#1"),
        ("input:Sun Color", "glint_color:#0"),
        ("glint:Value", "glint_color:Scale"),
        *_WEIGHT_LINKS,
        ("normal_h:Normal", "glossy:Normal"),
        ("normal_h:Normal", "refraction:Normal"),
        ("w_reflect:Value", "glossy:Color"),
        ("w_refract:Value", "refraction:Color"),
        ("e_glint:Vector", "emission:Color"),
        ("glossy:BSDF", "closures:#0"),
        ("refraction:BSDF", "closures:#1"),
        ("closures:Shader", "final:#0"),
        ("emission:Emission", "final:#1"),
        ("final:Shader", "output:Shader"),
    ),
)
