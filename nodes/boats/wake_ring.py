"""`Water Wake Ring`: the ring of waves an object leaves where it drops into the water.

Waves twice its beam long (`λ = 2 B`), whose envelope runs out at their group speed
(`ω² = g k + (σ/ρ) k³`: gravity and capillary), spreading as the ring grows and fading over 4 s.
A field of a water point's distance from where the object went in and the seconds since
(`Water Wake Track` keeps the ring points, `Water Wake` finds each point's nearest).
"""

from ..physics import SURFACE_TENSION, G
from ..spec import GroupSpec, Socket, math
from .wake_parts import merge

NAME = "Water Wake Ring"


def _wave_nodes():
    """The ring's waves: λ = 2 B, ω and the group speed (`ω² = g k + (σ/ρ) k³`), the front's envelope."""
    nodes = {
        "ring_lambda": math("MULTIPLY", 22, "λ = 2 B", b=2.0),
        "ring_k": math("DIVIDE", 23, "k = 2π / λ", a=2.0 * 3.141592653589793),
        "ring_k2": math("MULTIPLY", 24, "k²"),
        "ring_sk2": math("MULTIPLY_ADD", 25, "g + (σ/ρ) k²", b=SURFACE_TENSION, c=G),
        "ring_w2": math("MULTIPLY", 26, "ω² = k (g + (σ/ρ) k²)"),
        "ring_w": math("SQRT", 27, "ω"),
        "ring_cg_num": math("MULTIPLY_ADD", 25, "g + 3 (σ/ρ) k²", b=3.0 * SURFACE_TENSION, c=G),
        "ring_cg_den": math("MULTIPLY", 28, "2 ω", b=2.0),
        "ring_cg": math("DIVIDE", 29, "group speed dω/dk"),
        "ring_front": math("MULTIPLY", 30, "front: group speed x age"),
        "ring_dr": math("SUBTRACT", 31, "r - front"),
        "ring_dr_l": math("DIVIDE", 32, "in wavelengths"),
        "ring_dr2": math("MULTIPLY", 33, "²"),
        "ring_dr2n": math("MULTIPLY", 34, "-", b=-1.0),
        "ring_env": math("EXPONENT", 35, "envelope round the front"),
    }
    links = (
        ("input:Beam", "ring_lambda:#0"),
        ("ring_lambda:Value", "ring_k:#1"),
        ("ring_k:Value", "ring_k2:#0"),
        ("ring_k:Value", "ring_k2:#1"),
        ("ring_k2:Value", "ring_sk2:#0"),
        ("ring_k:Value", "ring_w2:#0"),
        ("ring_sk2:Value", "ring_w2:#1"),
        ("ring_w2:Value", "ring_w:#0"),
        ("ring_k2:Value", "ring_cg_num:#0"),
        ("ring_w:Value", "ring_cg_den:#0"),
        ("ring_cg_num:Value", "ring_cg:#0"),
        ("ring_cg_den:Value", "ring_cg:#1"),
        ("ring_cg:Value", "ring_front:#0"),
        ("input:Age", "ring_front:#1"),
        ("input:R", "ring_dr:#0"),
        ("ring_front:Value", "ring_dr:#1"),
        ("ring_dr:Value", "ring_dr_l:#0"),
        ("ring_lambda:Value", "ring_dr_l:#1"),
        ("ring_dr_l:Value", "ring_dr2:#0"),
        ("ring_dr_l:Value", "ring_dr2:#1"),
        ("ring_dr2:Value", "ring_dr2n:#0"),
        ("ring_dr2n:Value", "ring_env:#0"),
    )
    return nodes, links


def _height_nodes():
    """The ring's height: its phase, spreading and fading, x its size (0.3 B) and Strength."""
    nodes = {
        "ring_kr": math("MULTIPLY", 31, "k r"),
        "ring_wt": math("MULTIPLY", 31, "ω t"),
        "ring_phase": math("SUBTRACT", 32, "k r - ω t"),
        "ring_wave": math("COSINE", 33, "cos"),
        "ring_rl": math("ADD", 31, "front + λ"),
        "ring_spread": math("DIVIDE", 32, "λ / (front + λ)"),
        "ring_spread_s": math("SQRT", 33, "spreading"),
        "ring_fade_s": math("DIVIDE", 31, "age / 4 s", b=4.0),
        "ring_fade_n": math("MULTIPLY", 32, "-", b=-1.0),
        "ring_fade": math("EXPONENT", 33, "fading"),
        "ring_size": math("MULTIPLY", 31, "0.3 B", b=0.3),
        "ring_a1": math("MULTIPLY", 36, ""),
        "ring_a2": math("MULTIPLY", 37, ""),
        "ring_a3": math("MULTIPLY", 38, ""),
        "ring_a4": math("MULTIPLY", 39, ""),
        "ring_a5": math("MULTIPLY", 40, "x Strength"),
    }
    links = (
        ("ring_k:Value", "ring_kr:#0"),
        ("input:R", "ring_kr:#1"),
        ("ring_w:Value", "ring_wt:#0"),
        ("input:Age", "ring_wt:#1"),
        ("ring_kr:Value", "ring_phase:#0"),
        ("ring_wt:Value", "ring_phase:#1"),
        ("ring_phase:Value", "ring_wave:#0"),
        ("ring_front:Value", "ring_rl:#0"),
        ("ring_lambda:Value", "ring_rl:#1"),
        ("ring_lambda:Value", "ring_spread:#0"),
        ("ring_rl:Value", "ring_spread:#1"),
        ("ring_spread:Value", "ring_spread_s:#0"),
        ("input:Age", "ring_fade_s:#0"),
        ("ring_fade_s:Value", "ring_fade_n:#0"),
        ("ring_fade_n:Value", "ring_fade:#0"),
        ("input:Beam", "ring_size:#0"),
        ("ring_env:Value", "ring_a1:#0"),
        ("ring_wave:Value", "ring_a1:#1"),
        ("ring_a1:Value", "ring_a2:#0"),
        ("ring_spread_s:Value", "ring_a2:#1"),
        ("ring_a2:Value", "ring_a3:#0"),
        ("ring_fade:Value", "ring_a3:#1"),
        ("ring_a3:Value", "ring_a4:#0"),
        ("ring_size:Value", "ring_a4:#1"),
        ("ring_a4:Value", "ring_a5:#0"),
        ("input:Strength", "ring_a5:#1"),
        # g in the water's units: the dispersion's gravity.
        ("input:G", "ring_sk2:#2"),
        ("input:G", "ring_cg_num:#2"),
        ("ring_a5:Value", "output:Height"),
        ("ring_lambda:Value", "output:Wavelength"),
        ("ring_cg:Value", "output:Group Speed"),
    )
    return nodes, links


_NODES, _LINKS = merge(_wave_nodes(), _height_nodes())
SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="The ring of waves an object leaves where it drops in: waves twice its beam long "
    "round a front running out at their group speed, spreading and fading",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("R", "NodeSocketFloat", 0.0, tooltip="Distance from where it dropped in"),
        Socket("Age", "NodeSocketFloat", 0.0, tooltip="Seconds since"),
        Socket("Beam", "NodeSocketFloat", 1.0, tooltip="Its width: the waves are twice as long"),
        Socket("G", "NodeSocketFloat", G, tooltip="g, in the water's units"),
        Socket("Strength", "NodeSocketFloat", 1.0, tooltip="x the height"),
    ),
    outputs=(
        Socket("Height", "NodeSocketFloat", tooltip="The ring's height here"),
        Socket("Wavelength", "NodeSocketFloat", tooltip="Its waves' length, λ = 2 x Beam"),
        Socket("Group Speed", "NodeSocketFloat", tooltip="dω/dk, ω² = g k + (σ/ρ) k³"),
    ),
    nodes=_NODES,
    links=_LINKS,
)
