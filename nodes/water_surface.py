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

import math as _math
from dataclasses import replace as _replace

from . import bump_uv, caustics, foam_map, underside, wind_frame
from .physics import WATER_IOR
from .spec import (
    BUMP_IMAGE,
    FOAM_IMAGE,
    GroupSpec,
    Node,
    Part,
    Socket,
    attribute,
    group_node,
    math,
    pass_inputs,
    vmath,
)

NAME = "Water Surface"
VERSION = 7  # 4: caustics; 5: depth colour, foam and caustics only in the variants that use them;
# 6: the underside (Snell's window); 7: its weights from the one `Water Underside` group
LIT_FOAM_SINCE = (4, 5, 0)  # the first LTS whose EEVEE keeps traced refraction beside a diffuse closure
MAX_BUMP_LAYERS = 4
FOAM_NAME = "Water Surface Foam Coverage"
IOR = WATER_IOR

# The attributes the surroundings modifier stores on the water's points (all floats, per point).
DEPTH_ATTRIBUTE = "water_depth"  # metres straight down to the bed; 1000 where nothing is below
SHORE_ATTRIBUTE = "water_shore_distance"  # metres in the plane to the nearest waterline; 1000: none
FLAG_ATTRIBUTE = "water_surroundings"  # 1 where the modifier ran; an Attribute node reads 0 elsewhere

DEBUG_VIEWS = (
    (0, "FINAL", "Final", "The finished water"),
    (1, "REFLECTION", "Reflection", "The reflection closure alone"),
    (2, "REFRACTION", "Refraction", "The refraction closure alone"),
    (3, "FRESNEL", "Fresnel", "F as unlit grey"),
    (4, "NORMAL", "Bump Normal", "The bump normal n * 0.5 + 0.5, unlit"),
    (5, "GLINT", "Glint", "The sun glint alone, unlit, in the sun's colour"),
    (6, "TRANSMITTANCE", "Transmittance", "T = exp(-Absorption x path) per channel, unlit"),
    (7, "FOAM", "Foam", "The foam coverage as unlit grey"),
    (8, "CAUSTICS", "Caustics", "The caustic factor on what is seen through the water, unlit"),
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
    Socket(
        "Foam Width",
        "NodeSocketFloat",
        1.0,
        min=0.01,
        max=100.0,
        subtype="DISTANCE",
        tooltip="How far from the waterline the shore foam reaches, in metres",
    ),
    Socket(
        "Foam Amount",
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
        tooltip="Shore and contact foam, lit by the scene (0 = none; needs the surroundings)",
    ),
    caustics.CAUSTICS_INPUT,
    caustics.CAUSTICS_SCALE_INPUT,
    caustics.SUN_LIT_INPUT,
)

FOAM_INPUTS = (
    Socket("Vector", "NodeSocketVector", tooltip="Where the foam tile is read", hide_value=True),
    *(socket for socket in INPUTS if socket.name in ("Foam Width", "Foam Amount")),
)
# The inputs `Water Surface Bump UV` takes from the enclosing group, by the same names.
BUMP_UV_INPUTS = tuple(socket.name for socket in bump_uv.SCROLL_INPUTS)


def foam_feed(node, vector):
    """The links into a nested foam coverage node `node`: `vector` (where the tile is read) and
    the enclosing group's Foam Width and Foam Amount."""
    return ((vector, f"{node}:Vector"), *pass_inputs(node, [socket.name for socket in FOAM_INPUTS[1:]]))


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


def _final_weight_nodes(any_view):
    """From above: the reflection and refraction weights of the final picture (or views 1, 2 alone)."""
    nodes = {
        "is_final": math("SUBTRACT", 19, "final view", a=1.0),
        "foam_clear": math("SUBTRACT", 19, "1 - foam", a=1.0),
        "clear": math("SUBTRACT", 19, "1 - Dull Blend", a=1.0),
        "final_share": math("MULTIPLY", 20, "final x (1 - foam)"),
        "foam_weight": math("MULTIPLY", 20, "foam if final"),
        "keep": math("MULTIPLY", 21, "x (1 - Dull Blend)"),
        "one_minus_f": math("SUBTRACT", 20, "1 - F", a=1.0),
        "w_reflect": math("MULTIPLY_ADD", 22, "reflection weight"),
        "w_refract": math("MULTIPLY_ADD", 22, "refraction weight"),
        "through": vmath("MULTIPLY", 22, "T x caustics"),
        "refract_color": vmath("SCALE", 23, "T x caustics x refraction weight"),
    }
    links = [
        (any_view, "is_final:#1"),
        ("foam:Coverage", "foam_clear:#1"),
        ("input:Dull Blend", "clear:#1"),
        ("is_final:Value", "final_share:#0"),
        ("foam_clear:Value", "final_share:#1"),
        ("is_final:Value", "foam_weight:#0"),
        ("foam:Coverage", "foam_weight:#1"),
        ("final_share:Value", "keep:#0"),
        ("clear:Value", "keep:#1"),
        ("fresnel:Value", "one_minus_f:#1"),
        ("keep:Value", "w_reflect:#0"),
        ("one_minus_f:Value", "w_reflect:#1"),
        ("is_1:Value", "w_reflect:#2"),
        ("keep:Value", "w_refract:#0"),
        ("fresnel:Value", "w_refract:#1"),
        ("is_2:Value", "w_refract:#2"),
        ("transmit:Vector", "through:#0"),
        ("caustics:Factor", "through:#1"),
        ("through:Vector", "refract_color:#0"),
        ("w_refract:Value", "refract_color:Scale"),
    ]
    return nodes, links


def _emission_nodes():
    """The emission: the dull colour and glint of the final picture, or what debug views 3-8 show."""
    nodes = {
        "dull_part": vmath("SCALE", 19, "Dull Blend x Dull Color"),
        "lit": vmath("ADD", 20, "+ glint"),
        "e_final": vmath("SCALE", 22, "if final, x (1 - foam)"),
        "e_f": vmath("MULTIPLY_ADD", 23, "+ F if view 3"),
        "e_n": vmath("MULTIPLY_ADD", 23, "+ normal if view 4"),
        "e_glint": vmath("MULTIPLY_ADD", 23, "+ glint if view 5"),
        "e_scatter": vmath("MULTIPLY_ADD", 24, "+ scatter x refraction weight"),
        "e_transmit": vmath("MULTIPLY_ADD", 24, "+ T if view 6"),
        "e_foam": vmath("MULTIPLY_ADD", 24, "+ foam if view 7"),
        "e_caustics": vmath("MULTIPLY_ADD", 25, "+ caustics if view 8"),
    }
    links = [
        ("input:Dull Color", "dull_part:#0"),
        ("input:Dull Blend", "dull_part:Scale"),
        ("dull_part:Vector", "lit:#0"),
        ("glint_color:Vector", "lit:#1"),
        ("lit:Vector", "e_final:#0"),
        ("final_share:Value", "e_final:Scale"),
        ("fresnel:Value", "e_f:#0"),
        ("is_3:Value", "e_f:#1"),
        ("e_final:Vector", "e_f:#2"),
        ("normal_colour:Vector", "e_n:#0"),
        ("is_4:Value", "e_n:#1"),
        ("e_f:Vector", "e_n:#2"),
        ("glint_color:Vector", "e_glint:#0"),
        ("is_5:Value", "e_glint:#1"),
        ("e_n:Vector", "e_glint:#2"),
        ("scatter:Vector", "e_scatter:#0"),
        ("w_refract:Value", "e_scatter:#1"),
        ("e_glint:Vector", "e_scatter:#2"),
        ("transmit:Vector", "e_transmit:#0"),
        ("is_6:Value", "e_transmit:#1"),
        ("e_scatter:Vector", "e_transmit:#2"),
        ("foam:Coverage", "e_foam:#0"),
        ("is_7:Value", "e_foam:#1"),
        ("e_transmit:Vector", "e_foam:#2"),
        ("caustics:Factor", "e_caustics:#0"),
        ("is_8:Value", "e_caustics:#1"),
        ("e_foam:Vector", "e_caustics:#2"),
    ]
    return nodes, links


def _underside_nodes():
    """From below (a backface): `Water Underside`'s Fresnel weights alone, and no emission; either
    side picked."""
    nodes = {
        # From below (a backface): physics alone, the one rule of `Water Underside` (F reflected,
        # 1 - F refracted), weighting the same two closures: the refraction shows the sky inside
        # Snell's window and the reflection the water below outside it; no dull colour, glint or
        # colour by depth (they are the view from above).
        "underside": group_node(underside.NAME, 21, "from below: F, 1 - F"),
        "under_reflect": math("MULTIPLY", 22, "from below: reflection"),
        "under_refract": math("MULTIPLY", 23, "from below: refraction"),
        "w_reflect_s": Node(
            "ShaderNodeMix", 24, {"data_type": "FLOAT"}, label="reflection weight, either side"
        ),
        "refract_s": Node(
            "ShaderNodeMix", 24, {"data_type": "VECTOR"}, label="refraction colour, either side"
        ),
        "above": math("SUBTRACT", 25, "1 on the top side", a=1.0),
        "e_above": vmath("SCALE", 26, "emission from above only"),
    }
    links = [
        ("normal_h:Normal", "underside:Normal"),
        ("underside:Reflected", "under_reflect:#0"),
        ("final_share:Value", "under_reflect:#1"),
        ("underside:Refracted", "under_refract:#0"),
        ("final_share:Value", "under_refract:#1"),
        ("geometry:Backfacing", "w_reflect_s:Factor"),
        ("w_reflect:Value", "w_reflect_s:A"),
        ("under_reflect:Value", "w_reflect_s:B"),
        ("geometry:Backfacing", "refract_s:Factor"),
        ("refract_color:Vector", "refract_s:A"),
        ("under_refract:Value", "refract_s:B"),
        ("geometry:Backfacing", "above:#1"),
        ("e_caustics:Vector", "e_above:#0"),
        ("above:Value", "e_above:Scale"),
    ]
    return nodes, links


def _weight_nodes():
    """The closure weights and the emission colour for the final picture and each debug view.

    Final: with foam coverage `c`, glossy `(1 - c)(1 - Dull Blend)(1 - F)`, refraction
    `(1 - c)(1 - Dull Blend) F` times the transmittance `T`, emission
    `(1 - c)(Dull Blend * Dull Color + glint)` plus the scattered light
    `Scatter Color (1 - T)` at the refraction's weight, and the foam's white diffuse at `c`.
    View 1 or 2: that closure at weight 1 alone (view 2 with its `T` and scatter, so the
    final picture stays the composition of the views). Views 3-7: only the emission,
    showing F, the normal colour, the glint, `T` or `c`. Any other number shows the final picture.
    """
    # Which debug view: a compare a number, and whether any is (the final picture where none is).
    nodes, links = {}, []
    previous = None
    for number in range(1, len(DEBUG_VIEWS)):
        nodes[f"is_{number}"] = math("COMPARE", 17, f"view == {number}", b=float(number), c=0.5)
        links.append(("input:Debug View", f"is_{number}:#0"))
        if previous is not None:
            nodes[f"any_{number}"] = math("ADD", 18, "a debug view")
            links += [(previous, f"any_{number}:#0"), (f"is_{number}:Value", f"any_{number}:#1")]
            previous = f"any_{number}:Value"
        else:
            previous = "is_1:Value"
    for more_nodes, more_links in (_final_weight_nodes(previous), _emission_nodes(), _underside_nodes()):
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes, links = nodes | more_nodes, links + list(more_links)
    return nodes, links


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


def _depth_nodes():
    """The transmittance `T`, and the light the water scatters back, `Scatter Color * (1 - T)`."""
    nodes, links = transmittance_nodes()
    nodes |= {
        "one_minus_t": vmath("SUBTRACT", 24, "1 - T", a=(1.0, 1.0, 1.0)),
        "scatter": vmath("MULTIPLY", 25, "Scatter Color x (1 - T)"),
    }
    links += [
        ("transmit:Vector", "one_minus_t:#1"),
        ("input:Scatter Color", "scatter:#0"),
        ("one_minus_t:Vector", "scatter:#1"),
    ]
    return nodes, links


def foam_tile(column, label, interpolation="Linear"):
    """A read of the add-on's foam tile (equalised: its values evenly spread over 0..1)."""
    return Node(
        "ShaderNodeTexImage",
        column,
        {"extension": "REPEAT", "interpolation": interpolation, "image": FOAM_IMAGE},
        label=label,
    )


def foam_breakup(column, what=""):
    """The foam's rule, one for the shore and the whitecaps: the tile b thresholded by the foam f
    (fed to its Value as b + f), clamp((b + f - 1) / SOFTNESS): about f - SOFTNESS / 2 covered."""
    return Node(
        "ShaderNodeMapRange",
        column,
        {"interpolation_type": "LINEAR", "clamp": True},
        {1: 1.0, 2: 1.0 + foam_map.SOFTNESS, 3: 0.0, 4: 1.0},
        label=f"{what}clamp((b + f - 1) / {foam_map.SOFTNESS:g})",
    )


FOAM_SPEC = GroupSpec(
    name=FOAM_NAME,
    version=1,
    description="Shore foam coverage: falloff from the waterline, thresholded against the foam tile",
    inputs=FOAM_INPUTS,
    outputs=(Socket("Coverage", "NodeSocketFloat", tooltip="Share of the water covered by foam, 0 to 1"),),
    nodes={
        "flag": attribute(FLAG_ATTRIBUTE, 1, "water_surroundings (1 = measured)"),
        "shore": attribute(SHORE_ATTRIBUTE, 1, "water_shore_distance (m)"),
        "tile": foam_tile(1, "foam tile b"),
        # f = 1 - smoothstep(d / Foam Width): 1 at the waterline, 0 from Foam Width on.
        "falloff": Node(
            "ShaderNodeMapRange",
            2,
            {"interpolation_type": "SMOOTHSTEP", "clamp": True},
            {1: 0.0, 3: 1.0, 4: 0.0},
            label="f = 1 - smoothstep(d / Foam Width)",
        ),
        "sum": math("ADD", 3, "b + f"),
        # clamp((b + f - 1) / softness): the tile, thresholded at 1 - f.
        "breakup": foam_breakup(4),
        "amount": math("MULTIPLY", 5, "x Foam Amount"),
        "coverage": math("MULTIPLY", 6, "x surroundings flag", clamp=True),
    },
    links=(
        ("shore:Fac", "falloff:Value"),
        ("input:Foam Width", "falloff:From Max"),
        ("input:Vector", "tile:Vector"),
        ("tile:Color", "sum:#0"),
        ("falloff:Result", "sum:#1"),
        ("sum:Value", "breakup:Value"),
        ("breakup:Result", "amount:#0"),
        ("input:Foam Amount", "amount:#1"),
        ("amount:Value", "coverage:#0"),
        ("flag:Fac", "coverage:#1"),
        ("coverage:Value", "output:Coverage"),
    ),
)

# The optional parts: each is built only into the variants of the group that use it (the
# material's group is swapped when its switch crosses 0: `material.fit_parts`), so a lake with
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


_LAYER_NODES, _LAYER_LINKS = _layer_nodes()
_WEIGHT_NODES, _WEIGHT_LINKS = _weight_nodes()
_DEPTH_NODES, _DEPTH_LINKS = _depth_nodes()
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
        "foam": _replace(group_node(FOAM_NAME, 13, "foam coverage c"), part="foam"),
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
    includes=(FOAM_SPEC,),
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
        *foam_feed("foam", "bump_uv:Vector"),
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
