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

With the surroundings' point attributes (`water_depth`, `water_shore_distance`,
`water_surroundings`, stored by the surroundings modifier; an Attribute node reads 0
where a mesh has none), two additions, both nothing on a water without them:

* **colour by depth** (Beer-Lambert): what the refraction shows is multiplied per
  channel by `T = exp(-Absorption * path)`, `path = water_depth / cos_t` the way of the
  refracted view ray down to the bed (Snell at IOR 1.33 from `cos_i = eye . N`, N the
  geometric normal: `cos_t = sqrt(1 - (1 - cos_i^2) / 1.33^2)`), and the light the water
  scatters back, `Scatter Color * (1 - T)`, is emitted at the refraction's weight.
  Absorption 0 (the default) gives `T = 1`: the seeds' water exactly.
* **shore foam**: coverage `c = Foam Amount * flag * clamp((b + f - 1) / 0.25, 0, 1)`
  with `f = 1 - smoothstep(water_shore_distance / Foam Width)` (1 at the waterline,
  0 from Foam Width on) and `b` the foam tile (`foam_map.py`, values spread evenly over
  0..1) read at the bump's scrolled UV, so the foam drifts with the wind. The tile is
  thresholded at `1 - f`: near the waterline only the bubbles' middles stay open, further
  out only the lace remains, and from Foam Width on nothing. The foam is a white Diffuse
  BSDF at weight `c`, lit by the scene; everything else is weighted by `1 - c`. It lives in
  the nested group `Water Surface Foam Coverage`, which holds the foam image.

Reflection is a sharp Glossy BSDF and refraction a Refraction BSDF (IOR 1.33):
EEVEE's ray tracing supplies what the seeds' reflection and refraction maps
held, and Cycles traces them. Neither closure adds a Fresnel of its own, so the
seeds' two lerps are closure weights: the glossy's colour is
`(1 - Dull Blend) * (1 - F)`, the refraction's `(1 - Dull Blend) * F` (exact with
the Material Output's Thickness at 0: see `material.py`), and one emission
carries the dull colour, the glint and the scattered light. The debug views only
change these weights (and the foam's), so they cost no extra closures: view 2 is the
refraction as seen through the water (`T` and the scatter included), so the final
picture stays the composition of the views; 6 shows `T` and 7 the foam coverage, unlit.

All of the above is the top side. Seen from below (Geometry > Backfacing) the weights are
physics alone, the one rule the ocean shares (`underside.py`, `Water Underside`): the glossy's
the Fresnel node's value F at IOR 1.33 (it takes 1 / IOR on a backface and gives 1 past the
critical angle), the refraction's 1 - F, so the sky shows through Snell's window and the water
below is mirrored outside it; the same two closures, no emission from below.
"""

from dataclasses import replace as _replace

from .. import bump_uv, caustics, foam_coverage, wind_frame
from ..foam_coverage import FOAM_AMOUNT_INPUT, FOAM_WIDTH_INPUT
from ..spec import BUMP_IMAGE, GroupSpec, Node, Part, Socket, group_node, math, pass_inputs, vmath
from ..surface_parts import BUMP_UV_INPUTS, IOR, LIT_FOAM_SINCE, SUN_DIRECTION_INPUT, glint_nodes
from .lake_parts import DEBUG_VIEWS, depth_nodes, layer_nodes, weight_nodes

NAME = "Water Surface"
VERSION = 7  # 4: caustics; 5: depth colour, foam and caustics only in the variants that use them;
# 6: the underside (Snell's window); 7: its weights from the one `Water Underside` group
MAX_BUMP_LAYERS = 4

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
    SUN_DIRECTION_INPUT,
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
        max=len(DEBUG_VIEWS) - 1,
        tooltip="0 final, 1 reflection, 2 refraction, 3 Fresnel F, 4 bump normal, 5 glint, "
        "6 transmittance, 7 foam, 8 caustics",
    ),
    Socket(
        "Absorption",
        "NodeSocketColor",
        (0.0, 0.0, 0.0, 1.0),
        tooltip="How much of each colour the water absorbs per metre seen through it "
        "(needs the surroundings' depth; black = clear, as the seeds' water)",
    ),
    Socket(
        "Scatter Color",
        "NodeSocketColor",
        (0.0, 0.05, 0.06, 1.0),
        tooltip="Light scattered back by the water in place of what it absorbs (shows only with Absorption)",
    ),
    FOAM_WIDTH_INPUT,
    FOAM_AMOUNT_INPUT,
    caustics.CAUSTICS_INPUT,
    caustics.CAUSTICS_SCALE_INPUT,
    caustics.SUN_LIT_INPUT,
)
# Caustics, Foam Amount and Absorption at 0 (the default) computes none of them.
PARTS = (
    Part(
        "depth",
        "Depth",
        "Absorption",
        (0.45, 0.09, 0.06),
        off_values={
            "through": {0: (1.0, 1.0, 1.0)},
            "e_scatter": {0: (0.0, 0.0, 0.0)},
            "e_transmit": {0: (1.0, 1.0, 1.0)},
        },
    ),
    Part(
        "foam",
        "Foam",
        "Foam Amount",
        0.5,
        off_values={"foam_clear": {1: 0.0}, "foam_weight": {1: 0.0}, "e_foam": {0: (0.0, 0.0, 0.0)}},
        off_links=(("final:Shader", "output:Shader"),),
    ),
    Part(
        "caustics",
        "Caustics",
        "Caustics",
        1.0,
        off_values={"through": {1: (1.0, 1.0, 1.0)}, "e_caustics": {0: (1.0, 1.0, 1.0)}},
    ),
)
ALL_PARTS = frozenset(part.name for part in PARTS)


def _in_part(name, nodes):
    return {key: _replace(node, part=name) for key, node in nodes.items()}


_LAYER_NODES, _LAYER_LINKS = layer_nodes()
_WEIGHT_NODES, _WEIGHT_LINKS = weight_nodes()
_DEPTH_NODES, _DEPTH_LINKS = depth_nodes()
_GLINT_NODES, _GLINT_LINKS = glint_nodes("normal_s:Normal", "input:Specular Power")

FULL_SPEC = GroupSpec(
    name=NAME,
    version=VERSION,
    description="Lake water: bump, Fresnel blend of reflection and refraction, dull tint, sun glint, "
    "colour by depth, shore foam",
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
        **_GLINT_NODES,
        "glint": math("MULTIPLY", 20, "* Specular Strength"),
        "glint_color": vmath("SCALE", 21, "* Sun Color"),
        **_in_part("depth", _DEPTH_NODES),
        # Shore foam: its coverage, read at the bump's scrolled UV (so it drifts with the wind).
        "foam": _replace(group_node(foam_coverage.NAME, 13, "foam coverage c"), part="foam"),
        # Caustics: the factor on what the refraction shows (`caustics.py`).
        "caustics": _replace(group_node(caustics.NAME, 13, "caustic factor"), part="caustics"),
        **_WEIGHT_NODES,
        # The closures, weighted, the one emission and the foam.
        "glossy": Node(
            "ShaderNodeBsdfAnisotropic",
            26,
            {"distribution": "GGX"},
            {"Roughness": 0.0},
            label="reflection",
        ),
        "refraction": Node(
            "ShaderNodeBsdfRefraction",
            26,
            {"distribution": "GGX"},
            {"Roughness": 0.0, "IOR": IOR},
            label="refraction",
        ),
        "emission": Node("ShaderNodeEmission", 26, values={"Strength": 1.0}, label="dull colour + glint"),
        # Lit foam from 4.5. EEVEE in 4.2 drops the traced refraction of a material that also has a
        # diffuse closure (measured: what lies under the water vanishes), so there the foam is
        # unlit white in the emission instead.
        "foam_bsdf": Node(
            "ShaderNodeBsdfDiffuse",
            26,
            values={"Roughness": 0.0},
            label="foam: white, lit",
            since=LIT_FOAM_SINCE,
            part="foam",
        ),
        "foam_glow": Node(
            "ShaderNodeVectorMath",
            25,
            {"operation": "ADD"},
            label="+ foam, unlit (before 4.5)",
            before=LIT_FOAM_SINCE,
        ),
        "closures": Node("ShaderNodeAddShader", 27, label="reflection + refraction"),
        "final": Node("ShaderNodeAddShader", 28, label="+ emission"),
        "with_foam": Node("ShaderNodeAddShader", 29, label="+ foam", part="foam"),
    },
    includes=(foam_coverage.SPEC,),
    parts=PARTS,
    links=(
        *pass_inputs("bump_uv", BUMP_UV_INPUTS),
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
        *_GLINT_LINKS,
        ("glint_pow:Value", "glint:#0"),
        ("input:Specular Strength", "glint:#1"),
        ("input:Sun Color", "glint_color:#0"),
        ("glint:Value", "glint_color:Scale"),
        *_DEPTH_LINKS,
        *foam_coverage.foam_feed("foam", "bump_uv:Vector"),
        *caustics.feed("caustics", "bump_uv:Vector"),
        *_WEIGHT_LINKS,
        ("normal_h:Normal", "glossy:Normal"),
        ("normal_h:Normal", "refraction:Normal"),
        ("w_reflect_s:Result", "glossy:Color"),
        ("refract_s:Result", "refraction:Color"),
        ("e_above:Vector", "emission:Color"),
        # Before 4.5 (no diffuse closure) the emission carries the foam too: this replaces the link above.
        ("e_above:Vector", "foam_glow:#0"),
        ("foam_weight:Value", "foam_glow:#1"),
        ("foam_glow:Vector", "emission:Color"),
        ("foam_weight:Value", "foam_bsdf:Color"),
        ("glossy:BSDF", "closures:#0"),
        ("refraction:BSDF", "closures:#1"),
        ("closures:Shader", "final:#0"),
        ("emission:Emission", "final:#1"),
        ("final:Shader", "with_foam:#0"),
        ("foam_bsdf:BSDF", "with_foam:#1"),
        ("with_foam:Shader", "output:Shader"),
    ),
)

# The group every lake starts with (no part on): the one in `SPECS`, and the role old files'
# `Water Surface` groups had (`material.retire_legacy_groups`).
SPEC = FULL_SPEC.variant(())


def spec_with(parts):
    """The description of the lake group with the parts named in `parts` (`PARTS`) built in."""
    return FULL_SPEC.variant(parts)
