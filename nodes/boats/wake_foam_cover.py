"""`Water Wake Foam Cover`: how much of the water the wakes' foam covers, read in the material.

The wake stores a smooth foam amount on the water's points (`water_wake_foam`, 0..1: 1 round the
hull, thinning and fading along the trail). Drawn as it is, that is one white band with straight
edges. Real wake foam is solid where it is fresh and breaks into patches and lace as it ages and
spreads, so the material thresholds a pattern by it, the rule the shore foam and the whitecaps
follow (`foam_coverage.foam_breakup`): `clamp((b + k g - 1) / SOFTNESS)`, `k = 1 + SOFTNESS` so
that fresh foam (g = 1) covers all of the water and thin foam only the pattern's peaks.

`g = max(0, (f^P - c) / (1 - c))`, `c = FLOOR^P`: the amount raised to P < 1, so the foam the wake
keeps thin (its tails across the trail and its fading) still shows, as lace: 1 / sqrt(P) as wide
(its Gaussian `exp(-(d / w)^2)` becomes `exp(-(d / (w / sqrt P))^2)`) and fading 1 / P as slowly
(`exp(-age / F)` becomes `exp(-age / (F / P))`); 0 at FLOOR, where the wake's zone stops storing
foam, so no edge shows there.

`b = LACE lace + (1 - LACE) middles`, two reads of the add-on's foam tile in the water's own space:
its lace FINE metres across, and the tile's bubble middles (1 - the tile) PATCH metres across and
turned by TURN, which gather the lace into patches metres across; the middles weigh more, so
thinning foam parts into patches rather than one web of lace. The two sizes share no multiple and the
second read is turned, so neither repeats along a trail. Closest reads: the threshold cuts the
pattern sharp anyway, and a filtered read costs software EEVEE dearly at grazing views (issue
57 point 1).
"""

from .. import foam_map
from ..foam_coverage import foam_breakup, foam_tile
from ..spec import GroupSpec, Node, Socket, attribute, math, vmath
from .wake_parts import FOAM_ATTRIBUTE

NAME = "Water Wake Foam Cover"
FINE = 11.0  # metres: the lace's read of the tile (its bubbles 2.2, 0.85 and 0.35 m across)
PATCH = 37.0  # metres: the patches' read (bubbles 7.4 and 2.8 m across)
TURN = 0.5  # radians: the patches' read turned about z
LACE = 0.35  # the lace's weight in b (the middles' 0.65)
POWER = 0.35  # P: thin foam shows 1.7 times as wide, fading 2.9 times as slowly
FLOOR = 0.005  # the amount where the wake's zone stops storing foam (`wake_zone.py`)
CUT = FLOOR**POWER  # c
GAIN = 1.0 + foam_map.SOFTNESS  # k: fresh foam (g = 1) covers everything

SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="The wakes' foam cover: solid where fresh, patches and lace where thin (the foam "
    "tile thresholded by water_wake_foam)",
    inputs=(),
    outputs=(
        Socket("Cover", "NodeSocketFloat", tooltip="Share of the water the wakes' foam covers, 0 to 1"),
    ),
    nodes={
        "amount": attribute(FOAM_ATTRIBUTE, 0, f"f: {FOAM_ATTRIBUTE}"),
        "raised": math("POWER", 1, f"f^{POWER:g}", b=POWER),
        "g": math(
            "MULTIPLY_ADD",
            2,
            f"g = (f^P - {CUT:.3f}) / {1 - CUT:.3f}",
            clamp=True,
            b=1.0 / (1.0 - CUT),
            c=-CUT / (1.0 - CUT),
        ),
        "kg": math("MULTIPLY", 3, f"k g = {GAIN:g} g", b=GAIN),
        "where": Node("ShaderNodeTexCoord", 0, label="the water's own space"),
        "fine_uv": vmath("SCALE", 1, f"/ {FINE:g} m", scale=1.0 / FINE),
        "patch_uv": Node(
            "ShaderNodeMapping",
            1,
            {"vector_type": "POINT"},
            {"Rotation": (0.0, 0.0, TURN), "Scale": (1.0 / PATCH,) * 3},
            label=f"/ {PATCH:g} m, turned {TURN:g} rad",
        ),
        "fine": foam_tile(2, "foam tile: lace", "Closest"),
        "patch": foam_tile(2, "foam tile: patches", "Closest"),
        "middles": math("SUBTRACT", 3, "1 - tile: bubble middles", a=1.0),
        "lace": math("MULTIPLY", 3, f"{LACE:g} lace", b=LACE),
        "b": math("MULTIPLY_ADD", 4, f"b = {LACE:g} lace + {1 - LACE:g} middles", b=1.0 - LACE),
        "sum": math("ADD", 6, "b + k g"),
        "cover": foam_breakup(7, "wake foam: "),
    },
    links=(
        ("amount:Fac", "raised:#0"),
        ("raised:Value", "g:#0"),
        ("g:Value", "kg:#0"),
        ("where:Object", "fine_uv:Vector"),
        ("where:Object", "patch_uv:Vector"),
        ("fine_uv:Vector", "fine:Vector"),
        ("patch_uv:Vector", "patch:Vector"),
        ("patch:Color", "middles:#1"),
        ("fine:Color", "lace:#0"),
        ("middles:Value", "b:#0"),
        ("lace:Value", "b:#2"),
        ("b:Value", "sum:#0"),
        ("kg:Value", "sum:#1"),
        ("sum:Value", "cover:Value"),
        ("cover:Result", "output:Cover"),
    ),
)
