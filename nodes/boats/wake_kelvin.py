"""`Water Wake Kelvin`: Kelvin's pattern behind a moving pressure patch, a field in the hull's frame.

The stationary-phase pattern of a source moving at speed U (deep water, `ω² = g k`). Waves
running at `θ` to the track stand still in the object's frame when `k = g / (U² cos² θ)`, with
phase `ψ = k (x cos θ - y sin θ)`; at `tan α = y / x` the phase is stationary where
`2 tan α tan² θ - tan θ + tan α = 0`: two waves (transverse and diverging) inside the wedge
`tan α < 1 / sqrt(8)` (19.47°), none outside it. Each adds `p̂(k) sqrt(2π / |ψ''|) cos(ψ ± π/4)`
(`+` transverse, `-` diverging; `|ψ''| = g x sec³ θ s / U²`, `s = sqrt(1 - 8 tan² α)`): the hull
a Gaussian pressure patch one `Length` long (Darmon, Benzaquen and Raphaël 2014), so it makes
waves about its own length best, `p̂(k) = (k L / 2π)² exp(1 - (k L / 2π)²)`. That is why above
a Froude number of about 0.5 the highest waves draw in towards the track (about `0.2 / Fr` rad,
as Rabaud and Moisy measured) while the wedge stays 19.47° wide. On the arms the two waves meet
and the stationary phase breaks down: `s` is taken as `sqrt(s² + ε²)`, `ε² = (4 U² / (g x))^(2/3)`
(Airy's scale), and the waves die out over `ε²` beyond. Waves shorter than four mesh cells
(`Detail`) are left out. `tests/test_wake_groups.py` holds it to `tools/wake_heights.py`'s numpy.
"""

from ..spec import GroupSpec, Node, Socket, math
from .wake_parts import merge

NAME = "Water Wake Kelvin"


def _wedge_nodes():
    """The wedge: tan α = y / x, its root s and the two stationary waves' tan θ."""
    nodes = {
        "x_pos": math("MAXIMUM", 22, "x (> 0)", b=1e-3),
        "tan_a": math("DIVIDE", 23, "tan α = y / x"),
        "t": math("MAXIMUM", 24, "tan α (> 0)", b=1e-4),
        "t2": math("MULTIPLY", 25, "tan² α"),
        "disc": math("MULTIPLY_ADD", 26, "1 - 8 tan² α: > 0 inside the wedge", b=-8.0, c=1.0),
        "disc_in": math("MAXIMUM", 27, "0 outside", b=0.0),
        "s": math("SQRT", 28, "s"),
        "one_s": math("ADD", 29, "1 + s", b=1.0),
        "two_t": math("MULTIPLY", 29, "2 tan α", b=2.0),
        "tau_t": math("DIVIDE", 30, "transverse: tan θ = 2 tan α / (1 + s)"),
        "four_t": math("MULTIPLY", 29, "4 tan α", b=4.0),
        "tau_d": math("DIVIDE", 30, "diverging: tan θ = (1 + s) / (4 tan α)"),
    }
    links = (
        ("input:X", "x_pos:#0"),
        ("input:Y", "tan_a:#0"),
        ("x_pos:Value", "tan_a:#1"),
        ("tan_a:Value", "t:#0"),
        ("t:Value", "t2:#0"),
        ("t:Value", "t2:#1"),
        ("t2:Value", "disc:#0"),
        ("disc:Value", "disc_in:#0"),
        ("disc_in:Value", "s:#0"),
        ("s:Value", "one_s:#0"),
        ("t:Value", "two_t:#0"),
        ("two_t:Value", "tau_t:#0"),
        ("one_s:Value", "tau_t:#1"),
        ("t:Value", "four_t:#0"),
        ("one_s:Value", "tau_d:#0"),
        ("four_t:Value", "tau_d:#1"),
    )
    return nodes, links


def _arms_nodes():
    """The roots' scales (4 cells, L / 2π), Airy's width on the arms, the fall beyond them and the sum."""
    nodes = {
        "four_cells": math("MULTIPLY", 22, "4 cells", b=4.0),
        "sum": math("ADD", 40, "both waves"),
        "l_2pi": math("DIVIDE", 22, "L / 2π", b=2.0 * 3.141592653589793),
        "x_amp": math("MAXIMUM", 23, "x, past the hull's first quarter"),
        "l_quarter": math("MULTIPLY", 22, "L / 4", b=0.25),
        "kx": math("MULTIPLY", 24, "g x / U²"),
        "a_kx": math("DIVIDE", 25, "4 U² / (g x)", a=4.0),
        "eps2": math("POWER", 26, "ε²", b=2.0 / 3.0),
        "s2_eff": math("ADD", 28, "s² + ε²"),
        "s_eff": math("SQRT", 29, "s, finite on the arms"),
        "sp_base": math("MULTIPLY", 30, "g x / U² x s"),
        "beyond": math("MINIMUM", 27, "how far outside (< 0)", b=0.0),
        "beyond_s": math("DIVIDE", 28, "/ ε²"),
        "outside": math("EXPONENT", 29, "fades just beyond the arms"),
        # The stationary phase breaks down on the arms, where the two waves meet (s = 0): there
        # the sum is Airy's, its size falling as (g x / U²)^(-1/3). s is taken as
        # sqrt(s² + ε²), ε² = (4 U² / (g x))^(2/3), and the waves die out beyond the arms over ε².
        "e1": math("MULTIPLY", 41, "the pattern"),
    }
    links = (
        ("input:Detail", "four_cells:#0"),
        ("t_term:Value", "sum:#0"),
        ("d_term:Value", "sum:#1"),
        ("input:Length", "l_2pi:#0"),
        ("input:Length", "l_quarter:#0"),
        ("x_pos:Value", "x_amp:#0"),
        ("l_quarter:Value", "x_amp:#1"),
        ("input:K", "kx:#0"),
        ("x_amp:Value", "kx:#1"),
        ("kx:Value", "a_kx:#1"),
        ("a_kx:Value", "eps2:#0"),
        ("disc_in:Value", "s2_eff:#0"),
        ("eps2:Value", "s2_eff:#1"),
        ("s2_eff:Value", "s_eff:#0"),
        ("kx:Value", "sp_base:#0"),
        ("s_eff:Value", "sp_base:#1"),
        ("disc:Value", "beyond:#0"),
        ("beyond:Value", "beyond_s:#0"),
        ("eps2:Value", "beyond_s:#1"),
        ("beyond_s:Value", "outside:#0"),
        ("sum:Value", "e1:#0"),
        ("outside:Value", "e1:#1"),
        ("e1:Value", "output:Pattern"),
    )
    return nodes, links


def _root_wave(tag, tau, sign, column):
    """One stationary wave's shape: k = g / (U² cos² θ) and cos(ψ ± π/4)."""
    n = f"{tag}_"
    nodes = {
        n + "tau2": math("MULTIPLY", column, f"{tag}: tan² θ"),
        n + "q2": math("ADD", column + 1, "1 + tan² θ = 1 / cos² θ", b=1.0),
        n + "q": math("SQRT", column + 2, "1 / cos θ"),
        n + "k": math("MULTIPLY", column + 2, "k = g / (U² cos² θ)"),
        n + "y_tau": math("MULTIPLY", column, "y tan θ"),
        n + "path": math("SUBTRACT", column + 1, "x - y tan θ"),
        n + "phase_a": math("MULTIPLY", column + 3, "(x - y tan θ) / cos θ"),
        n + "phase": math(
            "MULTIPLY_ADD", column + 4, "k (x cos θ - y sin θ) ± π/4", c=sign * 3.141592653589793 / 4.0
        ),
        n + "wave": math("COSINE", column + 5, "cos"),
    }
    links = (
        (tau, n + "tau2:#0"),
        (tau, n + "tau2:#1"),
        (n + "tau2:Value", n + "q2:#0"),
        (n + "q2:Value", n + "q:#0"),
        (n + "q2:Value", n + "k:#0"),
        ("input:K", n + "k:#1"),
        ("input:Y", n + "y_tau:#0"),
        (tau, n + "y_tau:#1"),
        ("x_pos:Value", n + "path:#0"),
        (n + "y_tau:Value", n + "path:#1"),
        (n + "path:Value", n + "phase_a:#0"),
        (n + "q:Value", n + "phase_a:#1"),
        (n + "phase_a:Value", n + "phase:#0"),
        ("input:K", n + "phase:#1"),
        (n + "phase:Value", n + "wave:#0"),
    )
    return nodes, links


def _root_size(tag, column):
    """One stationary wave's size (the hull's share p̂(k), sqrt(2π / |ψ''|), the mesh's weight) x its shape."""
    n = f"{tag}_"
    nodes = {
        # The hull's share of waves k long: (k L / 2π)² exp(1 - (k L / 2π)²), 1 at λ = L.
        n + "kl": math("MULTIPLY", column + 3, "k L / 2π"),
        n + "kl2": math("MULTIPLY", column + 4, "(k L / 2π)²"),
        n + "spec_arg": math("SUBTRACT", column + 5, "1 - (k L / 2π)²", a=1.0),
        n + "spec_exp": math("EXPONENT", column + 6, "exp"),
        n + "spec": math("MULTIPLY", column + 7, "p̂(k): the hull's share"),
        # |ψ''| = g/U² x sec³ θ x s (s the wedge's root): the wave's stationary-phase size.
        n + "q3": math("MULTIPLY", column + 3, "sec³ θ"),
        n + "curv": math("MULTIPLY", column + 4, "|ψ''|"),
        n + "sp2": math("DIVIDE", column + 5, "2π / |ψ''|", a=2.0 * 3.141592653589793),
        n + "sp": math("SQRT", column + 6, "sqrt(2π / |ψ''|)"),
        n + "lambda": math("DIVIDE", column + 3, "wavelength", a=2.0 * 3.141592653589793),
        n + "mesh": math("DIVIDE", column + 4, "wavelength / 4 cells"),
        n + "mesh_w": Node(
            "ShaderNodeMapRange",
            column + 5,
            {"clamp": True},
            {"From Min": 0.5, "From Max": 1.0, "To Min": 0.0, "To Max": 1.0},
            label="the mesh can hold it",
        ),
        n + "size": math("MULTIPLY", column + 8, "p̂ x sqrt(2π / |ψ''|)"),
        n + "weight": math("MULTIPLY", column + 9, "where the mesh holds it"),
        n + "term": math("MULTIPLY", column + 10, f"{tag} term"),
    }
    links = (
        (n + "k:Value", n + "kl:#0"),
        ("l_2pi:Value", n + "kl:#1"),
        (n + "kl:Value", n + "kl2:#0"),
        (n + "kl:Value", n + "kl2:#1"),
        (n + "kl2:Value", n + "spec_arg:#1"),
        (n + "spec_arg:Value", n + "spec_exp:#0"),
        (n + "kl2:Value", n + "spec:#0"),
        (n + "spec_exp:Value", n + "spec:#1"),
        (n + "q2:Value", n + "q3:#0"),
        (n + "q:Value", n + "q3:#1"),
        (n + "q3:Value", n + "curv:#0"),
        ("sp_base:Value", n + "curv:#1"),
        (n + "curv:Value", n + "sp2:#1"),
        (n + "sp2:Value", n + "sp:#0"),
        (n + "k:Value", n + "lambda:#1"),
        (n + "lambda:Value", n + "mesh:#0"),
        ("four_cells:Value", n + "mesh:#1"),
        (n + "mesh:Value", n + "mesh_w:Value"),
        (n + "spec:Value", n + "size:#0"),
        (n + "sp:Value", n + "size:#1"),
        (n + "size:Value", n + "weight:#0"),
        (n + "mesh_w:Result", n + "weight:#1"),
        (n + "weight:Value", n + "term:#0"),
        (n + "wave:Value", n + "term:#1"),
    )
    return nodes, links


def _pattern_nodes():
    """The two stationary waves inside the wedge (the roots of `2 t τ² - τ + t = 0`), each one's
    term the stationary-phase share `p̂(k) sqrt(2π / |ψ''|)` x `cos(ψ ± π/4)` (`+` transverse,
    `-` diverging), made smaller where it is shorter than four mesh cells; Airy's width on the
    arms and the fall beyond them."""
    roots = (("t", "tau_t:Value", 1.0), ("d", "tau_d:Value", -1.0))
    return merge(
        _wedge_nodes(),
        _arms_nodes(),
        *(part for tag, tau, sign in roots for part in (_root_wave(tag, tau, sign, 31), _root_size(tag, 31))),
    )


_NODES, _LINKS = _pattern_nodes()
SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="Kelvin's pattern behind a moving pressure patch: the two stationary waves, the "
    "wedge and Airy's arms (a field, in the hull's frame)",
    tree_type="GeometryNodeTree",
    inputs=(
        Socket("X", "NodeSocketFloat", 1.0, tooltip="Distance behind the hull, along its track"),
        Socket("Y", "NodeSocketFloat", 0.0, tooltip="Distance across the track, either side (≥ 0)"),
        Socket("K", "NodeSocketFloat", 1.0, tooltip="g / U²: the transverse waves' wavenumber"),
        Socket("Length", "NodeSocketFloat", 1.0, tooltip="The hull's length: it makes waves this long best"),
        Socket("Detail", "NodeSocketFloat", 0.0, tooltip="A mesh cell: waves shorter than four are left out"),
    ),
    outputs=(Socket("Pattern", "NodeSocketFloat", tooltip="The height, before its size and fading"),),
    nodes=_NODES,
    links=_LINKS,
)
