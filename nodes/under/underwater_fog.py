"""`Water Underwater Fog` (a shader): the water between a camera under the surface and what it
sees (docs/MODEL.md section 16).

Light crossing d metres of water keeps `exp(-c d)` of itself per channel, `c` the water's
`Absorption` (per metre, the one that colours it from above), and the water scatters in
`L (1 - exp(-c d))`, `L` what the water shows from above where it is deepest (the lake's `Scatter
Color`, the ocean's `Deep Color`): a volume absorbing `c` per channel and emitting `c L` per metre
does exactly that, in Cycles and in EEVEE. Its density is `c` only for camera rays: a ray that
has crossed the surface from above is the surface shader's (its own `exp(-Absorption x path)`),
and probes, reflections and shadows see none of it. Its `Light Shafts` (0 by default: no scatter
closure, no cost) makes a share `b` of that `c` a forward Volume Scatter instead of absorption (c
stays what it was): the sunlight the water scatters towards the eye, what is left of it at each
depth (`exp(-c depth / cos_s)`, the water's level its body's origin: the fog is not seen by
shadow rays), its shadow rays crossing the caustic light's sheet, so the shafts come patterned
by the caustics.
"""

from ..spec import GroupSpec, Node, Socket, math, vmath
from .camera_gate import EACH_PLACEMENT, MARGIN, placement_gate, placement_links

NAME = "Water Underwater Fog"


def _absorb(channel, column):
    """A Volume Absorption taking only `channel` (0 red, 1 green, 2 blue), its density linked."""
    colour = [1.0, 1.0, 1.0]
    colour[channel] = 0.0
    label = f"absorbs {'RGB'[channel]}"
    return Node("ShaderNodeVolumeAbsorption", column, values={"Color": tuple(colour)}, label=label)


# Light Shafts: water scatters forward (Petzold's measured phase functions, g about 0.9), so the
# sunlight it scatters towards the eye is brightest looking towards the sun: Henyey-Greenstein's g.
SHAFTS_ANISOTROPY = 0.85


def _sunlit(channel, column):
    """Nodes for one channel (0 red, 1 green, 2 blue): the sunlight kept at this depth
    `exp(-c path)` scattered by `b` (`be`), and the absorption `c - b exp(-c path)` that keeps
    the fog's extinction `c` (a Volume Scatter's colour is its share of the extinction too)."""
    rgb = "RGB"[channel]
    return {
        f"cp_{rgb}": math("MULTIPLY", column, f"{rgb}: c x path"),
        f"kept_{rgb}": math("EXPONENT", column + 1, f"{rgb}: exp(-c path)"),
        f"be_{rgb}": math("MULTIPLY", column + 2, f"{rgb}: b exp(-c path)"),
        f"k_{rgb}": math("SUBTRACT", column + 3, f"{rgb} absorbed: c - b exp(-c path)"),
    }


def _sunlit_links(channel):
    rgb = "RGB"[channel]
    name = ("Red", "Green", "Blue")[channel]
    lower = "rgb"[channel]
    return (
        (f"c:{name}", f"cp_{rgb}:#0"),
        ("neg_path:Value", f"cp_{rgb}:#1"),
        (f"cp_{rgb}:Value", f"kept_{rgb}:#0"),
        ("b:Value", f"be_{rgb}:#0"),
        (f"kept_{rgb}:Value", f"be_{rgb}:#1"),
        (f"c_{lower}:Value", f"k_{rgb}:#0"),
        (f"be_{rgb}:Value", f"k_{rgb}:#1"),
        (f"k_{rgb}:Value", f"a_{lower}:Density"),
        (f"be_{rgb}:Value", f"lit:{name}"),
    )


SPEC = GroupSpec(
    name=NAME,
    version=3,  # 3: Each Placement (a collection instance's placements, each its own camera gate)
    description="The water between a camera under the surface and what it sees: exp(-c d) kept, "
    "L (1 - exp(-c d)) scattered in, per channel; with Light Shafts, the sunlight it scatters",
    inputs=(
        Socket(
            "Absorption",
            "NodeSocketColor",
            (0.0, 0.0, 0.0, 1.0),
            tooltip="c: what the water absorbs per metre, per channel (the water's own Absorption)",
        ),
        Socket(
            "Scatter Color",
            "NodeSocketColor",
            (0.0, 0.0, 0.0, 1.0),
            tooltip="L: the colour far water takes (the lake's Scatter Color, the ocean's Deep Color)",
        ),
        Socket(
            "Light Shafts",
            "NodeSocketFloat",
            0.0,
            min=0.0,
            max=1.0,
            subtype="FACTOR",
            tooltip="How much of what the water takes from the light it scatters instead (b = this x "
            "its least c per metre, the rest absorbed): the sun's light shafts, patterned by the "
            "caustics. 0: none, and no cost",
        ),
        Socket(
            "Sun Direction",
            "NodeSocketVector",
            (0.0, 0.0, -1.0),
            subtype="DIRECTION",
            tooltip="Where the sunlight goes (the water's own Sun Direction): the shafts' light is "
            "what is left of it at each depth",
        ),
        EACH_PLACEMENT,
    ),
    outputs=(Socket("Volume", "NodeSocketShader"),),
    nodes={
        "path_rays": Node("ShaderNodeLightPath", 0),
        **placement_gate(-4, MARGIN),
        "open": math("SUBTRACT", 0, "1 - shut", a=1.0),
        "path": math("MULTIPLY", 1, "camera rays, this placement's"),
        "c": Node("ShaderNodeSeparateColor", 1, label="c per channel"),
        # b: the share of c scattered, the same in every channel (scattering hardly varies with colour).
        "c_least": math("MINIMUM", 1, "least c"),
        "c_least_all": math("MINIMUM", 2, "least c of three"),
        "b_raw": math("MULTIPLY", 3, "b = Light Shafts x least c"),
        "b": math("MULTIPLY", 4, "b: camera rays only"),
        # The sunlight's way down to here: depth under the water's level / cos of the refracted sun.
        "here": Node("ShaderNodeNewGeometry", 1),
        "level": Node("ShaderNodeObjectInfo", 1, label="the water's level (the body's origin)"),
        "here_xyz": Node("ShaderNodeSeparateXYZ", 2),
        "level_xyz": Node("ShaderNodeSeparateXYZ", 2),
        "depth_raw": math("SUBTRACT", 3, "depth = level - z"),
        "depth": math("MAXIMUM", 4, "at least 0", b=0.0),
        "sun": vmath("NORMALIZE", 2, "L"),
        "r_s": vmath("REFRACT", 3, "r_s = refract(L, up, 1/1.333)", b=(0.0, 0.0, 1.0), scale=1.0 / 1.333),
        "r_s_xyz": Node("ShaderNodeSeparateXYZ", 4),
        "cos_s": math("MULTIPLY", 5, "cos_s = -r_s.z", b=-1.0),
        "cos_s_safe": math("MAXIMUM", 6, "max(, 0.05)", b=0.05),
        "sun_path": math("DIVIDE", 6, "path = depth / cos_s"),
        "neg_path": math("MULTIPLY", 7, "-path", b=-1.0),
        "c_r": math("MULTIPLY", 2, "red: camera rays only"),
        "c_g": math("MULTIPLY", 2, "green: camera rays only"),
        "c_b": math("MULTIPLY", 2, "blue: camera rays only"),
        **_sunlit(0, 8),
        **_sunlit(1, 8),
        **_sunlit(2, 8),
        "a_r": _absorb(0, 12),
        "a_g": _absorb(1, 12),
        "a_b": _absorb(2, 12),
        "lit": Node("ShaderNodeCombineColor", 12, label="b exp(-c path) per channel"),
        "shafts": Node(
            "ShaderNodeVolumeScatter",
            13,
            values={"Density": 1.0, "Anisotropy": SHAFTS_ANISOTROPY},
            label="sunlight scattered (forward)",
        ),
        "cl": vmath("MULTIPLY", 2, "c L: emitted per metre"),
        "glow": Node("ShaderNodeEmission", 3, label="scattered in"),
        "rg": Node("ShaderNodeAddShader", 13),
        "rgb": Node("ShaderNodeAddShader", 14),
        "lit_all": Node("ShaderNodeAddShader", 15),
        "all": Node("ShaderNodeAddShader", 16),
    },
    links=(
        *placement_links(),
        ("shut:Value", "open:#1"),
        ("path_rays:Is Camera Ray", "path:#0"),
        ("open:Value", "path:#1"),
        ("input:Absorption", "c:Color"),
        ("c:Red", "c_least:#0"),
        ("c:Green", "c_least:#1"),
        ("c_least:Value", "c_least_all:#0"),
        ("c:Blue", "c_least_all:#1"),
        ("input:Light Shafts", "b_raw:#0"),
        ("c_least_all:Value", "b_raw:#1"),
        ("b_raw:Value", "b:#0"),
        ("path:Value", "b:#1"),
        ("here:Position", "here_xyz:Vector"),
        ("level:Location", "level_xyz:Vector"),
        ("level_xyz:Z", "depth_raw:#0"),
        ("here_xyz:Z", "depth_raw:#1"),
        ("depth_raw:Value", "depth:#0"),
        ("input:Sun Direction", "sun:#0"),
        ("sun:Vector", "r_s:#0"),
        ("r_s:Vector", "r_s_xyz:Vector"),
        ("r_s_xyz:Z", "cos_s:#0"),
        ("cos_s:Value", "cos_s_safe:#0"),
        ("depth:Value", "sun_path:#0"),
        ("cos_s_safe:Value", "sun_path:#1"),
        ("sun_path:Value", "neg_path:#0"),
        ("c:Red", "c_r:#0"),
        ("c:Green", "c_g:#0"),
        ("c:Blue", "c_b:#0"),
        ("path:Value", "c_r:#1"),
        ("path:Value", "c_g:#1"),
        ("path:Value", "c_b:#1"),
        *_sunlit_links(0),
        *_sunlit_links(1),
        *_sunlit_links(2),
        ("lit:Color", "shafts:Color"),
        ("input:Absorption", "cl:#0"),
        ("input:Scatter Color", "cl:#1"),
        ("cl:Vector", "glow:Color"),
        ("path:Value", "glow:Strength"),
        ("a_r:Volume", "rg:#0"),
        ("a_g:Volume", "rg:#1"),
        ("rg:Shader", "rgb:#0"),
        ("a_b:Volume", "rgb:#1"),
        ("rgb:Shader", "lit_all:#0"),
        ("shafts:Volume", "lit_all:#1"),
        ("lit_all:Shader", "all:#0"),
        ("glow:Emission", "all:#1"),
        ("all:Shader", "output:Volume"),
    ),
)
