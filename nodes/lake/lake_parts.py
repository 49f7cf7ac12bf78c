"""The lake group's helpers (`water_surface.py`): its debug views, the bump's layers, the closures'
weights and the depth colour, apart so the group's own module stays short enough to read."""

from .. import underside
from ..spec import BUMP_IMAGE, Node, group_node, math, vmath
from ..surface_parts import transmittance_nodes

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


# Seed 001's layers after the first: (UV scale, scroll speed), both relative to layer 1.
LAYERS = ((2.0, 2.0), (4.0, 1.0), (8.0, 0.5))


def layer_nodes():
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


def final_weight_nodes(any_view):
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


def emission_nodes():
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


def underside_nodes():
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


def weight_nodes():
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
    for more_nodes, more_links in (final_weight_nodes(previous), emission_nodes(), underside_nodes()):
        assert not set(more_nodes) & set(nodes), set(more_nodes) & set(nodes)  # one key, one node
        nodes, links = nodes | more_nodes, links + list(more_links)
    return nodes, links


def depth_nodes():
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
