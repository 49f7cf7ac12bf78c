"""`Water Wake Height`: the Kelvin pattern's scale, so the wake is as high as Kriebel and Seelig say.

Worked out on the track's few points (not on each water point): their highest wave one hull
length across, which grows with speed, length and draft against the water's `Depth`, over the
pattern's own height there (`N(Fr)`, `tools/wake_heights.py`), x `Strength`.
"""

from ..spec import GroupSpec, Socket, math
from .wake_parts import DEPTH_DEFAULT

NAME = "Water Wake Height"

# Kriebel and Seelig (2005, "An empirical model for ship-generated waves"): the highest wave a
# hull leaves at `y` across its track, `g H / U² = β (F* - 0.1)² (y / L)^(-1/3)`, with the
# Froude number raised by the draft `T` against the depth `d`, `F* = F exp(α T / d)`,
# `α = 2.35 (1 - Cb)`. Cb (the hull's block coefficient) is taken as a small craft's 0.6; β
# (1 for a hull whose bow is half its length, about 1.6 a third, 4 a quarter) is `Strength`.
# Their data reach F* 0.5: F* and F are each held there, so the height grows with speed and
# draft up to it and no further (faster hulls plane; their waves break).
KS_ALPHA = 2.35 * (1.0 - 0.6)
KS_F_LOW, KS_F_HIGH = 0.1, 0.5
# The group's own pattern's crest-to-trough height one hull length across, by Froude number:
# ln N = c0 + c1 / Fr + c2 / Fr² + c3 / Fr⁴ + c4 ln Fr, Fr in 0.25..3 (tools/wake_heights.py
# fits it, within 5%). The height scale is Kriebel and Seelig's height at y = L over N.
PATTERN_HEIGHT = (-2.587192, 2.640087, -0.540814, -0.015939, -0.123133)
PATTERN_FROUDE = (0.25, 3.0)


def _height_nodes():
    """Kriebel and Seelig's highest wave a hull length across (`H / L = β (F_c - 0.1)² min(F, 0.5)²`,
    `F_c = min(F e, 0.5)`, `e = exp(α T / d)`), over the pattern's own height there (`N(Fr)`),
    x Strength."""
    c0, c1, c2, c3, c4 = PATTERN_HEIGHT
    nodes = {
        "fr": math("SQRT", 25, "Fr"),
        "td": math("DIVIDE", 24, "T / d"),
        "td_a": math("MULTIPLY", 25, "α T / d", b=KS_ALPHA),
        "ks_e": math("EXPONENT", 26, "e = exp(α T / d)"),
        "fstar": math("MULTIPLY", 26, "F* = F e"),
        "fc": math("MINIMUM", 27, "F*, held at 0.5", b=KS_F_HIGH),
        "excess": math("SUBTRACT", 28, "F* - 0.1", b=KS_F_LOW),
        "excess_in": math("MAXIMUM", 29, "(> 0)", b=0.0),
        "excess2": math("MULTIPLY", 30, "(F* - 0.1)²"),
        "fv": math("MINIMUM", 28, "F, held at 0.5", b=KS_F_HIGH),
        "fv2": math("MULTIPLY", 29, "F² = U² / (g L)"),
        "h_per_l": math("MULTIPLY", 31, "g H / U² x U² / (g L) = H / L"),
        "h_ks": math("MULTIPLY", 32, "H at y = L (units up)"),
        "fr_in": math("MAXIMUM", 26, "Fr, 0.25 ..", b=PATTERN_FROUDE[0]),
        "fr_c": math("MINIMUM", 27, ".. 3", b=PATTERN_FROUDE[1]),
        "inv": math("DIVIDE", 28, "1 / Fr", a=1.0),
        "inv2": math("MULTIPLY", 29, "1 / Fr²"),
        "inv4": math("MULTIPLY", 30, "1 / Fr⁴"),
        "ln_fr": math("LOGARITHM", 28, "ln Fr", b=2.718281828459045),
        "n1": math("MULTIPLY_ADD", 29, "c0 + c1 / Fr", b=c1, c=c0),
        "n2": math("MULTIPLY_ADD", 30, "+ c2 / Fr²", b=c2),
        "n3": math("MULTIPLY_ADD", 31, "+ c3 / Fr⁴", b=c3),
        "n4": math("MULTIPLY_ADD", 32, "+ c4 ln Fr: ln N", b=c4),
        "n": math("EXPONENT", 33, "N: the pattern's height at y = L"),
        "height": math("DIVIDE", 34, "height scale: H / N"),
        "strength": math("MULTIPLY", 35, "x Strength (β)"),
    }
    links = (
        ("input:Fr²", "fr:#0"),
        ("input:Draft", "td:#0"),
        ("input:Depth", "td:#1"),
        ("td:Value", "td_a:#0"),
        ("td_a:Value", "ks_e:#0"),
        ("fr:Value", "fstar:#0"),
        ("ks_e:Value", "fstar:#1"),
        ("fstar:Value", "fc:#0"),
        ("fc:Value", "excess:#0"),
        ("excess:Value", "excess_in:#0"),
        ("excess_in:Value", "excess2:#0"),
        ("excess_in:Value", "excess2:#1"),
        ("fr:Value", "fv:#0"),
        ("fv:Value", "fv2:#0"),
        ("fv:Value", "fv2:#1"),
        ("excess2:Value", "h_per_l:#0"),
        ("fv2:Value", "h_per_l:#1"),
        ("h_per_l:Value", "h_ks:#0"),
        ("input:Length", "h_ks:#1"),
        ("fr:Value", "fr_in:#0"),
        ("fr_in:Value", "fr_c:#0"),
        ("fr_c:Value", "inv:#1"),
        ("inv:Value", "inv2:#0"),
        ("inv:Value", "inv2:#1"),
        ("inv2:Value", "inv4:#0"),
        ("inv2:Value", "inv4:#1"),
        ("fr_c:Value", "ln_fr:#0"),
        ("inv:Value", "n1:#0"),
        ("inv2:Value", "n2:#0"),
        ("n1:Value", "n2:#2"),
        ("inv4:Value", "n3:#0"),
        ("n2:Value", "n3:#2"),
        ("ln_fr:Value", "n4:#0"),
        ("n3:Value", "n4:#2"),
        ("n4:Value", "n:#0"),
        ("h_ks:Value", "height:#0"),
        ("n:Value", "height:#1"),
        ("height:Value", "strength:#0"),
        ("input:Strength", "strength:#1"),
        ("strength:Value", "output:Height"),
    )
    return nodes, links


_NODES, _LINKS = _height_nodes()
SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="Kriebel and Seelig's highest wave a hull length across, over the Kelvin "
    "pattern's own height there: the pattern's scale",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("Fr²", "NodeSocketFloat", 0.25, tooltip="U² / (g L): the hull's Froude number, squared"),
        Socket("Draft", "NodeSocketFloat", 0.5, tooltip="How deep the hull sits (as Depth)"),
        Socket("Depth", "NodeSocketFloat", DEPTH_DEFAULT, tooltip="The water's depth (as Draft)"),
        Socket("Length", "NodeSocketFloat", 1.0, tooltip="The hull's length, in the height's units"),
        Socket("Strength", "NodeSocketFloat", 1.0, tooltip="Kriebel and Seelig's β"),
    ),
    outputs=(Socket("Height", "NodeSocketFloat", tooltip="The pattern's scale"),),
    nodes=_NODES,
    links=_LINKS,
)
