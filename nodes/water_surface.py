"""`Water Surface`: the lake water of SPEC section 1 as one EEVEE/Cycles shader group.

Per pixel (Blender is Z-up; `eye` is Geometry > Incoming, pointing at the camera):

* the bump map is sampled (mirror extension) at the scrolling, wind-aligned UV
  of `Water Surface Bump UV`, decoded to a tangent-space normal
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
  (dull colour unlit, as in the seeds) plus the white glint
  `Specular Strength * pow(max(dot(reflect(L, n), eye), 0), Specular Power)`.

Reflection is a sharp Glossy BSDF and refraction a Refraction BSDF (IOR 1.33):
EEVEE's ray tracing supplies what the seeds' reflection and refraction maps
held, and Cycles traces them. Neither closure adds a Fresnel of its own, so the
Mix Shaders are the seeds' lerps exactly (with the Material Output's Thickness
at 0: see `material.py`).
"""

from . import bump_uv, wind_frame
from .spec import BUMP_IMAGE, GroupSpec, Node, Socket, group_node, math, vmath

NAME = "Water Surface"
VERSION = 1

DEBUG_VIEWS = (
    (0, "FINAL", "Final", "The finished water"),
    (1, "REFLECTION", "Reflection", "The reflection closure alone"),
    (2, "REFRACTION", "Refraction", "The refraction closure alone"),
    (3, "FRESNEL", "Fresnel", "F as unlit grey"),
    (4, "NORMAL", "Bump Normal", "The bump normal n * 0.5 + 0.5, unlit"),
    (5, "GLINT", "Glint", "The sun glint alone, unlit grey"),
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


def _debug_nodes():
    """Mix Shaders that swap the output for one debug view when `Debug View` equals its number."""
    views = {
        1: "glossy:BSDF",
        2: "refraction:BSDF",
        3: "view_f:Emission",
        4: "view_n:Emission",
        5: "view_glint:Emission",
    }
    nodes, links, previous = {}, [], "final:Shader"
    for number, source in views.items():
        nodes[f"is_{number}"] = math("COMPARE", 18 + number, f"view == {number}", b=float(number), c=0.5)
        nodes[f"show_{number}"] = Node("ShaderNodeMixShader", 19 + number, label=f"debug view {number}")
        links += [
            ("input:Debug View", f"is_{number}:#0"),
            (f"is_{number}:Value", f"show_{number}:Fac"),
            (previous, f"show_{number}:#1"),
            (source, f"show_{number}:#2"),
        ]
        previous = f"show_{number}:Shader"
    links.append((previous, "output:Shader"))
    return nodes, links


_DEBUG_NODES, _DEBUG_LINKS = _debug_nodes()

SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description="Lake water: bump, Fresnel blend of reflection and refraction, dull tint, sun glint",
    inputs=INPUTS,
    outputs=(Socket("Shader", "NodeSocketShader"),),
    nodes={
        # Sample the bump at the scrolled UV, decode it, rotate it from the wind frame back into UV space.
        "bump_uv": group_node(bump_uv.NAME, 1),
        "bump": Node(
            "ShaderNodeTexImage",
            2,
            {"extension": "MIRROR", "image": BUMP_IMAGE},
            label="bump map (mirror)",
        ),
        "frame": group_node(wind_frame.NAME, 2),
        "decode": vmath("MULTIPLY_ADD", 3, "t = 2 * bump - 1", b=(2.0, 2.0, 2.0), c=(-1.0, -1.0, -1.0)),
        "t": Node("ShaderNodeSeparateXYZ", 4, label="t"),
        "w": Node("ShaderNodeSeparateXYZ", 4, label="w"),
        "tx_wy": math("MULTIPLY", 5, "t.x * w.y"),
        "ty_wy": math("MULTIPLY", 5, "t.y * w.y"),
        "minus_wx": math("MULTIPLY", 5, "-w.x", b=-1.0),
        "uv_x": math("MULTIPLY_ADD", 6, "t.x p.x + t.y w.x"),
        "uv_y": math("MULTIPLY_ADD", 6, "t.x p.y + t.y w.y"),
        # Tilt by Wave Height (closures) and by Bump Strength (Fresnel, glint).
        "h_x": math("MULTIPLY", 7, "x * Wave Height"),
        "h_y": math("MULTIPLY", 7, "y * Wave Height"),
        "s_x": math("MULTIPLY", 7, "x * Bump Strength"),
        "s_y": math("MULTIPLY", 7, "y * Bump Strength"),
        "tilt_h": Node("ShaderNodeCombineXYZ", 8, label="closure tilt"),
        "tilt_s": Node("ShaderNodeCombineXYZ", 8, label="bump tilt"),
        "encode_h": vmath("MULTIPLY_ADD", 9, "to colour", b=(0.5, 0.5, 0.5), c=(0.5, 0.5, 0.5)),
        "encode_s": vmath("MULTIPLY_ADD", 9, "to colour", b=(0.5, 0.5, 0.5), c=(0.5, 0.5, 0.5)),
        "normal_h": Node("ShaderNodeNormalMap", 10, label="closure normal"),
        "normal_s": Node("ShaderNodeNormalMap", 10, label="n"),
        # Fresnel: F = clamp(dot(eye, n), 0, 1).
        "geometry": Node("ShaderNodeNewGeometry", 10),
        "eye_dot_n": vmath("DOT_PRODUCT", 11, "eye . n"),
        "fresnel": math("MULTIPLY", 12, "F = clamp(eye . n)", clamp=True, b=1.0),
        # Glint: Specular Strength * pow(max(dot(reflect(L, n), eye), 0), Specular Power).
        "sun": vmath("NORMALIZE", 11, "L"),
        "reflect": vmath("REFLECT", 12, "reflect(L, n)"),
        "glint_dot": vmath("DOT_PRODUCT", 13, ". eye"),
        "glint_max": math("MAXIMUM", 14, "max(, 0)", b=0.0),
        "glint_pow": math("POWER", 15, "pow(, Specular Power)"),
        "glint": math("MULTIPLY", 16, "* Specular Strength"),
        # Closures and the seeds' two lerps, then the additive glint.
        "glossy": Node(
            "ShaderNodeBsdfAnisotropic",
            13,
            {"distribution": "GGX"},
            {"Color": (1.0, 1.0, 1.0, 1.0), "Roughness": 0.0},
            label="reflection",
        ),
        "refraction": Node(
            "ShaderNodeBsdfRefraction",
            13,
            {"distribution": "GGX"},
            {"Color": (1.0, 1.0, 1.0, 1.0), "Roughness": 0.0, "IOR": 1.33},
            label="refraction",
        ),
        "lerp_fresnel": Node("ShaderNodeMixShader", 14, label="lerp(reflection, refraction, F)"),
        "dull": Node("ShaderNodeEmission", 14, values={"Strength": 1.0}, label="dull colour"),
        "lerp_dull": Node("ShaderNodeMixShader", 15, label="lerp(, dull, Dull Blend)"),
        "glint_light": Node("ShaderNodeEmission", 17, values={"Color": (1.0, 1.0, 1.0, 1.0)}, label="glint"),
        "final": Node("ShaderNodeAddShader", 18, label="+ glint"),
        # Debug views: unlit F, bump normal and glint.
        "view_f": Node("ShaderNodeEmission", 17, values={"Strength": 1.0}, label="view 3: F"),
        "normal_colour": vmath("MULTIPLY_ADD", 17, "n * 0.5 + 0.5", b=(0.5, 0.5, 0.5), c=(0.5, 0.5, 0.5)),
        "view_n": Node("ShaderNodeEmission", 18, values={"Strength": 1.0}, label="view 4: normal"),
        "view_glint": Node("ShaderNodeEmission", 17, values={"Strength": 1.0}, label="view 5: glint"),
        **_DEBUG_NODES,
    },
    links=(
        ("input:Wave Length", "bump_uv:Wave Length"),
        ("input:Wind Direction", "bump_uv:Wind Direction"),
        ("input:Wind Force", "bump_uv:Wind Force"),
        ("input:Time", "bump_uv:Time"),
        ("bump_uv:Vector", "bump:Vector"),
        ("input:Wind Direction", "frame:Wind Direction"),
        ("bump:Color", "decode:#0"),
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
        ("normal_h:Normal", "glossy:Normal"),
        ("normal_h:Normal", "refraction:Normal"),
        ("fresnel:Value", "lerp_fresnel:Fac"),
        ("glossy:BSDF", "lerp_fresnel:#1"),
        ("refraction:BSDF", "lerp_fresnel:#2"),
        ("input:Dull Color", "dull:Color"),
        ("input:Dull Blend", "lerp_dull:Fac"),
        ("lerp_fresnel:Shader", "lerp_dull:#1"),
        ("dull:Emission", "lerp_dull:#2"),
        ("glint:Value", "glint_light:Strength"),
        ("lerp_dull:Shader", "final:#0"),
        ("glint_light:Emission", "final:#1"),
        ("fresnel:Value", "view_f:Color"),
        ("normal_s:Normal", "normal_colour:#0"),
        ("normal_colour:Vector", "view_n:Color"),
        ("glint:Value", "view_glint:Color"),
        *_DEBUG_LINKS,
    ),
)
