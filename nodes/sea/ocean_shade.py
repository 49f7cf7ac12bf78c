"""The ocean's shading (SPEC section 2, pixel part), as two shader groups.

`Water Ocean Normal` perturbs the wave normal (the `water_normal` attribute the
`Water Waves` modifier stores, or the surface normal without it) by three taps
of the bump map and gives the direction the eye reflects into. The shade's "+ Traced Sky"
variant, every new material's, has the renderer reflect the world there with a Glossy closure, so
the sea shows whatever world the scene has now; at `Traced Sky` 0 the material looks the sky up
in that direction as the seeds do (the world's environment image, or its colour, as they were
when it was made) and hands it to `Water Ocean Shade`:
`F = dot(-eye, n) / 2 + 0.5`, `deep * F + sky * (1 - F) + pow(mean(sky), Glint Power)`,
unlit, as the seeds draw it. Where the mesh carries crest foam (the open sea's
`water_whitecaps`, `sea_fade.py`) whitecaps break out as white foam lit by the scene, in
compact patches metres across drawn out along a strong wind; past the sea's fade, where the flat far mesh
marks no crests, as many whitecaps are spread over the sea at random, so a gale's foam reaches
the horizon.

With the surroundings' attributes (`water_depth`, `water_shore_distance`, `water_surroundings`,
as on the lake), the lake's rules apply: the bed is seen through the water at
`T = exp(-Absorption x path)` (`surface_parts.transmittance_nodes`), refracted and lit by the
caustics (`caustics.py`; a part, built in only while `Caustics` is above 0), and the deep colour
takes the rest, `deep (1 - T)`; the shore foam is
the lake's coverage, whichever of it and the whitecaps covers more. Without the attributes
`T` is 0 and the foam 0: the seeds' ocean exactly.
Two groups, because a shader group cannot hold the
world's image: the lookup sits between them in the material.
"""

from dataclasses import replace

from .. import bump_uv, caustics, foam_coverage, surface_parts, underside
from ..footprint_cap import capped
from ..spec import (
    ROUGH_FRESNEL_IMAGE,
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
from . import rough_fresnel, sea_fade
from .ocean_parts import (
    BLOB_STRETCH_POWER,
    FADE_END_INPUT,
    FADE_START_INPUT,
    FAR_CAP_GAIN,
    FAR_SECOND_READ,
    FOAM_WHITE,
    MARK_POWER,
    PICK_TILE,
    SHADE_INPUTS,
    SPOT_RAG,
    STREAKS_INPUT,
    UNRESOLVED_SLOPE,
    WHITECAP_BLOB_GAIN,
    WHITECAP_BLOB_SOFTNESS,
    WHITECAP_BLOB_TILE,
    WHITECAP_FOAM,
    WHITECAP_TILE,
    bubble,
    debug_nodes,
    spot_links,
    spots,
    tile_links,
    tile_read,
)

SHADE_NAME = "Water Ocean Shade"
TRACED_SKY = "Traced Sky"
# The traced sky's roughness: the ripples finer than a pixel. Sharp (0), EEVEE draws a sun lamp's
# highlight four times as bright as Cycles over the shallows and white over what should be sand.
TRACED_ROUGHNESS = 0.05
# The traced sky: a sharp Glossy closure at (1 - F) in place of the Sky input's colour. Built
# only into the group's "+ Traced Sky" variant (every new material's: issue 38, the world live).
# The caustics on the bed (`caustics.py`): built only into the "+ Caustics" variants, while
# Caustics is above 0. Without them the bed is lit by the factor 1 (no caustics), as the lake's.
PARTS = (
    Part(
        "traced_sky",
        "Traced Sky",
        TRACED_SKY,
        1.0,
        off_links=(("water_shader:Shader", "mix:#1"),),
    ),
    Part(
        "caustics",
        "Caustics",
        caustics.CAUSTICS_INPUT.name,
        1.0,
        off_values={"lit_bed": {"Scale": 1.0}, "view_8": {0: (1.0, 1.0, 1.0)}},
    ),
)

_T_NODES, _T_LINKS = surface_parts.transmittance_nodes()

_DEBUG_NODES, _DEBUG_LINKS = debug_nodes()

# The shore foam's and the caustics' reads at the scrolled bump UV, capped where a pixel sees the
# sea edge-on.
_CAP_NODES, _CAP_LINKS = capped("tile_uv", 13, "bump_uv:Vector", "bump_tiles:Value")


FULL_SHADE_SPEC = GroupSpec(
    name=SHADE_NAME,
    # 2: whitecaps; 3: depth colour, shore foam and caustics from the surroundings; 4: the traced
    # sky and the debug views; 5: whitecaps broken up by the foam tile, as the shore's foam; 6: the
    # caustics an optional part (`PARTS`: older groups have them built in, `retire_legacy_shades`);
    # 7: seen from below, Snell's window (it was clear); 8: its normal and weights from the one
    # `Water Underside` group; 9: `Water Fresnel` (water's own reflectance, from the same group);
    # 10: `Foam Streaks` (the lace drawn out along the wind: streaks in a gale, not cells); 11: from
    # below, the deep water reflected outside Snell's window is its Deep Color (was a glossy, which
    # EEVEE fills with the world); 12: `Unresolved Slope` (with Water Fresnel: water's mean
    # reflectance over the slopes EEVEE's mipmaps averaged away, `rough_fresnel.py`, and a mirror
    # as much rougher); past the sea's fade (`Fade Start`, `Fade End`), whitecaps where the mesh
    # marks no crests (the far sea was bare: at 25 m/s a band 40 m up); 13: the far whitecaps from
    # two reads of the tile (one alone repeated across the wind: stripes from high up); 14: the
    # lace read nearest-texel (a mipmapped read hung software EEVEE on folded crests); 15: whitecaps
    # are compact spots (Voronoi), whole, drawn out a^0.42 (were the foam tile's bubble middles:
    # dashes a pixel wide); 16: the shore foam's and caustics' reads capped where a pixel sees the
    # sea edge-on (`footprint_cap.py`: software EEVEE took 30 s over such a frame)
    version=16,
    description="Ocean colour: deep blue and the reflected sky by the ocean Fresnel, plus the glint; "
    "white lit foam on the crests; with the surroundings, the bed seen through shallow water, "
    "shore foam and caustics",
    inputs=SHADE_INPUTS,
    outputs=(Socket("Shader", "NodeSocketShader"),),
    nodes={
        "geometry": Node("ShaderNodeNewGeometry", 1),
        "cos": vmath("DOT_PRODUCT", 2, "dot(-eye, n)"),
        "F_seeds": math("MULTIPLY_ADD", 3, "the seeds' F = dot / 2 + 0.5", b=0.5, c=0.5),
        # Water's own (`Water Fresnel`): F = 1 - R, R Fresnel's reflectance at water's IOR, from the
        # one `Water Underside` group (on the top side its facing normal is n itself).
        "F_towards": math("SUBTRACT", 3, "water's 1 - R - the seeds'"),
        # Where the bump's slopes were averaged away, R over them: R(c, s) - R(c, 0) from the table
        # at (|cos|, s), s the lost rms slope (with Water Fresnel only: the seeds' stay the seeds').
        "unresolved": math("MULTIPLY", 1, "lost slope^2 x Water Fresnel"),
        "rough_slope": math("SQRT", 1, "s"),
        "rough_v": math(
            "MULTIPLY_ADD",
            2,
            "table row",
            b=(rough_fresnel.SIZE - 1) / (rough_fresnel.SIZE * rough_fresnel.SLOPE_MAX),
            c=0.5 / rough_fresnel.SIZE,
        ),
        "abs_cos": math("ABSOLUTE", 2, "|cos|"),
        "rough_u": math(
            "MULTIPLY_ADD",
            2,
            "table column",
            b=(rough_fresnel.SIZE - 1) / rough_fresnel.SIZE,
            c=0.5 / rough_fresnel.SIZE,
        ),
        "rough_uv": Node("ShaderNodeCombineXYZ", 2, label="(|cos|, s) in the table"),
        "rough_table": Node(
            "ShaderNodeTexImage",
            3,
            {"extension": "EXTEND", "interpolation": "Linear", "image": ROUGH_FRESNEL_IMAGE},
            label="R(c, s) - R(c, 0)",
        ),
        "rough_refracted": math("SUBTRACT", 3, "1 - R over the lost slopes"),
        # The mirror as much rougher: GGX alpha^2 = alpha_0^2 + 2 s^2 (roughness = sqrt(alpha)).
        "rough_alpha": Node(
            "ShaderNodeMath",
            4,
            {"operation": "MULTIPLY_ADD"},
            {1: 2.0, 2: TRACED_ROUGHNESS**4},
            label="alpha^2",
            part="traced_sky",
        ),
        "rough_mirror": Node(
            "ShaderNodeMath", 5, {"operation": "POWER"}, {1: 0.25}, label="roughness", part="traced_sky"
        ),
        "F": math("MULTIPLY_ADD", 3, "F: the seeds' or water's (Water Fresnel)"),
        "one_minus_F": math("SUBTRACT", 4, "1 - F", a=1.0),
        # Through the water: T = exp(-Absorption x path) where the surroundings are measured, else 0
        # (the seeds' ocean, all deep colour); the bed shows at T, the deep colour at 1 - T.
        **_T_NODES,
        "flag": attribute(surface_parts.FLAG_ATTRIBUTE, 14, "water_surroundings (1 = measured)"),
        "t_seen": vmath("SCALE", 24, "T, 0 without surroundings"),
        "hidden": vmath("SUBTRACT", 25, "1 - T", a=(1.0, 1.0, 1.0)),
        "deep_hides": vmath("MULTIPLY", 26, "deep x (1 - T)"),
        "deep": vmath("SCALE", 27, "deep (1 - T) F"),
        "looked_up": math("SUBTRACT", 4, "1 - Traced Sky", a=1.0),
        "sky_share": math("MULTIPLY", 5, "(1 - F) x looked up"),
        "sky": vmath("SCALE", 5, "sky * (1 - F)"),
        "mean": vmath("DOT_PRODUCT", 5, "mean(sky)", b=(1 / 3, 1 / 3, 1 / 3)),
        "glint_raw": math("POWER", 6, "pow(mean, Glint Power)"),
        "glint": math("MULTIPLY", 6, "x looked up"),
        "glint_v": Node("ShaderNodeCombineXYZ", 7, label="glint (white)"),
        # The traced sky (part "traced_sky"): the world reflected by the renderer at (1 - F).
        "mirror_share": Node(
            "ShaderNodeMath", 5, {"operation": "MULTIPLY"}, label="(1 - F) x Traced Sky", part="traced_sky"
        ),
        # Multiscatter: rougher far off, a single-scatter lobe would lose light at grazing.
        "mirror": Node(
            "ShaderNodeBsdfAnisotropic",
            30,
            {"distribution": "MULTI_GGX"},
            {"Roughness": TRACED_ROUGHNESS},
            label="the world reflected",
            part="traced_sky",
        ),
        "with_mirror": Node("ShaderNodeAddShader", 32, label="+ reflection", part="traced_sky"),
        "water": vmath("ADD", 28),
        "color": vmath("ADD", 29, "colour"),
        "emit": Node("ShaderNodeEmission", 30, values={"Strength": 1.0}, label="unlit"),
        # The bed, refracted, at F T x the caustic factor (`caustics.py`).
        "bump_uv": group_node(bump_uv.NAME, 12, "scrolled bump UV (foam, caustics)"),
        "bump_tiles": math("DIVIDE", 12, "the bump UV's tiles a metre", a=1.0 / sea_fade.UV_METRES),
        **_CAP_NODES,
        "caustics": replace(group_node(caustics.NAME, 24, "caustic factor"), part="caustics"),
        "lit_bed": vmath("SCALE", 25, "T x caustics"),
        "seen": vmath("SCALE", 28, "F T x caustics"),
        "refraction": Node(
            "ShaderNodeBsdfRefraction",
            30,
            {"distribution": "GGX"},
            {"Roughness": 0.0, "IOR": surface_parts.IOR},
            label="the bed, refracted",
        ),
        "water_shader": Node("ShaderNodeAddShader", 31, label="unlit + refraction"),
        # Foam: whitecaps or shore foam (the lake's coverage), whichever covers more; white, lit.
        # Whitecaps break on the crests the sea's fade marks (`water_whitecaps`, the Foam input):
        # there spots B (`_spots`: B < s covers s of the sea) of the share the wind asks for, and
        # inside them the foam tile, read fine, laces the foam as on the shore,
        # clamp((b + f - 1) / SOFTNESS) with f = WHITECAP_FOAM. Both follow where the water came
        # from (`water_rest`: the foam rides with the chop), drawn out along the wind.
        "rest": attribute(sea_fade.REST_ATTRIBUTE, 24, "water_rest (where the water came from)"),
        "wind_w": vmath("NORMALIZE", 24, "w"),
        "wind_across": vmath("CROSS_PRODUCT", 25, "z x w: across the wind", a=(0.0, 0.0, 1.0)),
        "cap_along": vmath("DOT_PRODUCT", 26, "along the wind (m)"),
        "cap_across": vmath("DOT_PRODUCT", 26, "across the wind (m)"),
        **spots("blob", WHITECAP_BLOB_TILE, 27, "spots B (which whitecaps)"),
        # Closest: a mipmapped read of the lace, on a crest folded over in front of the camera,
        # took software EEVEE minutes a frame (issue 57 point 1); the lace is cut sharp by the
        # breakup's threshold anyway.
        **tile_read("lace", WHITECAP_TILE, 27, "foam tile b (their lace)", "Closest"),
        "lace_length": math("MULTIPLY", 26, "12 a: drawn out along the wind", b=WHITECAP_TILE[0]),
        "lace_width": math("DIVIDE", 26, "6 / a: narrowed across it", a=WHITECAP_TILE[1]),
        # Which whitecaps, by a^0.42 only: drawn out as far as their lace, one would run for
        # hundreds of metres (over 500 m^2 at 15 m/s).
        "blob_stretch": math("POWER", 25, "a^0.42", b=BLOB_STRETCH_POWER),
        "blob_length": math("MULTIPLY", 26, "12 a^0.42: drawn out along the wind", b=WHITECAP_BLOB_TILE[0]),
        "blob_width": math("DIVIDE", 26, "10 / a^0.42: narrowed across it", a=WHITECAP_BLOB_TILE[1]),
        "cap_share": math("MULTIPLY", 27, "Whitecaps x Whitecap Coverage"),
        "blob_share": math("MULTIPLY", 28, "s: bubbles' share", b=WHITECAP_BLOB_GAIN),
        # Each spot's edge ragged by the tile R, metres-wide wobbles: B (1 + e (R - 1/2)).
        "blob_rag": math("MULTIPLY_ADD", 28, "1 + e (R - 1/2)", b=SPOT_RAG, c=1.0 - SPOT_RAG / 2),
        "blob_ragged": math("MULTIPLY", 28, "B ragged"),
        "blob_gap": math("SUBTRACT", 29, "s - B"),
        "blob": bubble("a whitecap's bubble"),
        "mark_lift": math("POWER", 30, f"mark^{MARK_POWER:g}: whole where marked", b=MARK_POWER),
        "mark_share": math("MULTIPLY", 29, "s x mark^g: aged whitecaps shrink"),
        "fade_distance": vmath("LENGTH", 25, "distance from the sea's centre"),
        "fade_near": Node(
            "ShaderNodeMapRange",
            26,
            {"interpolation_type": "SMOOTHSTEP", "clamp": True},
            {3: 1.0, 4: 0.0},
            label="near: 1 where the crests are marked, 0 past the fade",
        ),
        # The mesh's mark faded by `near` (as the waves): whole again, and then either the crests'
        # whitecaps or the far ones, by a third read of the tile R (near > R: the crests'), so
        # both stay whole whitecaps where the sea fades, in those shares.
        "near_floor": math("MAXIMUM", 27, "near (>= 0.001)", b=0.001),
        "crest_whole": math("DIVIDE", 28, "the crest's mark, unfaded", clamp=True),
        "pick_u": math("DIVIDE", 27, "across / 37 m", b=PICK_TILE[0]),
        "pick_v": math("DIVIDE", 27, "along / 53 m", b=PICK_TILE[1]),
        "pick_uv": Node("ShaderNodeCombineXYZ", 28),
        "pick_tile": foam_coverage.foam_tile(29, "foam tile R (crests' or far whitecaps)", "Closest"),
        "crests_here": math("GREATER_THAN", 30, "near > R: the crests' whitecaps"),
        "caps_change": math("SUBTRACT", 31, "crests' - far"),
        "far_share": math("MULTIPLY", 28, "far bubbles' share", b=FAR_CAP_GAIN, clamp=True),
        "far_keep": math("SUBTRACT", 28, "1 - share", a=1.0),
        "far_root": math("SQRT", 28, "sqrt(1 - share)"),
        "far_cut": math("SUBTRACT", 29, "t = 1 - sqrt(1 - share)", a=1.0),
        "far_length": math("MULTIPLY", 26, "B2's length", b=FAR_SECOND_READ[0]),
        "far_width": math("MULTIPLY", 26, "B2's width", b=FAR_SECOND_READ[1]),
        **spots("far2", WHITECAP_BLOB_TILE, 27, "spots B2 (far whitecaps, second read)"),
        "far_either": math("MINIMUM", 29, "min(B, B2)"),
        "far_gap": math("SUBTRACT", 29, "t - min(B, B2)"),
        "far_blob": bubble("a far whitecap's bubble"),
        "caps": math("MULTIPLY_ADD", 31, "the crests' or the far whitecaps"),
        # No share, no whitecap: the bubble's soft edge would otherwise keep a few.
        "some": math("MULTIPLY", 30, "any share?", clamp=True, b=1.0 / WHITECAP_BLOB_SOFTNESS),
        "on_some": math("MULTIPLY", 31, "x any share"),
        "crest": math("MULTIPLY", 32, "f", b=WHITECAP_FOAM),
        "cap_sum": math("ADD", 32, "b + f"),
        "cover": foam_coverage.foam_breakup(32, "whitecaps: "),
        "shore_foam": group_node(foam_coverage.NAME, 28, "shore foam coverage"),
        "foam_cover": math("MAXIMUM", 30, "foam cover"),
        # Lit from 4.5; EEVEE in 4.2 drops the traced refraction beside a diffuse closure, so there
        # the foam is unlit white, as on the lake.
        "foam_bsdf": Node(
            "ShaderNodeBsdfDiffuse",
            31,
            values={"Color": (*FOAM_WHITE, 1.0)},
            label="white foam, lit",
            since=surface_parts.LIT_FOAM_SINCE,
        ),
        "foam_glow": Node(
            "ShaderNodeEmission",
            31,
            values={"Color": (*FOAM_WHITE, 1.0), "Strength": 1.0},
            label="white foam, unlit (before 4.5)",
            before=surface_parts.LIT_FOAM_SINCE,
        ),
        "mix": Node("ShaderNodeMixShader", 32, label="water or foam"),
        # Seen from below by the camera, physics alone (its unlit colour is what the eye sees from
        # above, not a lamp over the bed), the one rule of `Water Underside`: the sky refracted
        # inside Snell's window at 1 - F, the water below reflected outside it at F, on the normal
        # turned to face the eye (the waves' worked-out normal is not turned on a backface). The
        # water below is deep (the ocean shading's): what it sends up is its far colour, the Deep
        # Color the underwater fog fades to, so the reflection is that colour at F, unlit, the
        # same in EEVEE (whose glossy would show the world's sky there) and Cycles. To every
        # other ray (the bed's light bounces in Cycles) it stays clear, as EEVEE lights the bed:
        # the two engines show the same shallows.
        "underside": group_node(underside.NAME, 30, "from below: n facing the eye, F, 1 - F"),
        "under_deep": vmath("SCALE", 30, "the deep water's colour at F"),
        "under_mirror": Node("ShaderNodeEmission", 31, label="from below: the deep water reflected"),
        "under_sky": Node(
            "ShaderNodeBsdfRefraction",
            31,
            {"distribution": "GGX"},
            {"Roughness": 0.0, "IOR": surface_parts.IOR},
            label="from below: the sky refracted",
        ),
        "see_through": Node("ShaderNodeAddShader", 32, label="from below"),
        "light_path": Node("ShaderNodeLightPath", 31),
        "clear": Node("ShaderNodeBsdfTransparent", 32, label="from below, to other rays: clear"),
        "under_camera": Node("ShaderNodeMixShader", 33, label="the camera's view, or clear"),
        "sides": Node("ShaderNodeMixShader", 33, label="above or below"),
        **_DEBUG_NODES,
    },
    includes=(foam_coverage.SPEC,),
    parts=PARTS,
    links=(
        ("geometry:Incoming", "cos:#0"),
        ("input:Normal", "cos:#1"),
        ("cos:Value", "F_seeds:#0"),
        (f"input:{UNRESOLVED_SLOPE}", "unresolved:#0"),
        ("input:Water Fresnel", "unresolved:#1"),
        ("unresolved:Value", "rough_slope:#0"),
        ("rough_slope:Value", "rough_v:#0"),
        ("cos:Value", "abs_cos:#0"),
        ("abs_cos:Value", "rough_u:#0"),
        ("rough_u:Value", "rough_uv:X"),
        ("rough_v:Value", "rough_uv:Y"),
        ("rough_uv:Vector", "rough_table:Vector"),
        ("underside:Refracted", "rough_refracted:#0"),
        ("rough_table:Color", "rough_refracted:#1"),
        ("rough_refracted:Value", "F_towards:#0"),
        ("unresolved:Value", "rough_alpha:#0"),
        ("rough_alpha:Value", "rough_mirror:#0"),
        ("rough_mirror:Value", "mirror:Roughness"),
        ("F_seeds:Value", "F_towards:#1"),
        ("F_towards:Value", "F:#0"),
        ("input:Water Fresnel", "F:#1"),
        ("F_seeds:Value", "F:#2"),
        ("F:Value", "one_minus_F:#1"),
        *_T_LINKS,
        ("transmit:Vector", "t_seen:#0"),
        ("flag:Fac", "t_seen:Scale"),
        ("t_seen:Vector", "hidden:#1"),
        ("input:Deep Color", "deep_hides:#0"),
        ("hidden:Vector", "deep_hides:#1"),
        ("deep_hides:Vector", "deep:#0"),
        ("F:Value", "deep:Scale"),
        ("input:Traced Sky", "looked_up:#1"),
        ("one_minus_F:Value", "sky_share:#0"),
        ("looked_up:Value", "sky_share:#1"),
        ("input:Sky", "sky:#0"),
        ("sky_share:Value", "sky:Scale"),
        ("input:Sky", "mean:#0"),
        ("mean:Value", "glint_raw:#0"),
        ("input:Glint Power", "glint_raw:#1"),
        ("glint_raw:Value", "glint:#0"),
        ("looked_up:Value", "glint:#1"),
        ("one_minus_F:Value", "mirror_share:#0"),
        ("input:Traced Sky", "mirror_share:#1"),
        ("mirror_share:Value", "mirror:Color"),
        ("input:Normal", "mirror:Normal"),
        ("water_shader:Shader", "with_mirror:#0"),
        ("mirror:BSDF", "with_mirror:#1"),
        ("glint:Value", "glint_v:X"),
        ("glint:Value", "glint_v:Y"),
        ("glint:Value", "glint_v:Z"),
        ("deep:Vector", "water:#0"),
        ("sky:Vector", "water:#1"),
        ("water:Vector", "color:#0"),
        ("glint_v:Vector", "color:#1"),
        ("color:Vector", "emit:Color"),
        *pass_inputs("bump_uv", surface_parts.BUMP_UV_INPUTS),
        ("input:Wave Length", "bump_tiles:#1"),
        *_CAP_LINKS,
        *caustics.feed("caustics", "tile_uv:Vector"),
        ("t_seen:Vector", "lit_bed:#0"),
        ("caustics:Factor", "lit_bed:Scale"),
        ("lit_bed:Vector", "seen:#0"),
        ("F:Value", "seen:Scale"),
        ("seen:Vector", "refraction:Color"),
        ("input:Normal", "refraction:Normal"),
        ("emit:Emission", "water_shader:#0"),
        ("refraction:BSDF", "water_shader:#1"),
        ("input:Wind Direction", "wind_w:#0"),
        ("wind_w:Vector", "wind_across:#1"),
        ("rest:Vector", "cap_along:#0"),
        ("wind_w:Vector", "cap_along:#1"),
        ("rest:Vector", "cap_across:#0"),
        ("wind_across:Vector", "cap_across:#1"),
        *spot_links("blob"),
        *tile_links("lace"),
        (f"input:{STREAKS_INPUT}", "lace_length:#0"),
        (f"input:{STREAKS_INPUT}", "lace_width:#1"),
        ("lace_length:Value", "lace_u:#1"),
        ("lace_width:Value", "lace_v:#1"),
        (f"input:{STREAKS_INPUT}", "blob_stretch:#0"),
        ("blob_stretch:Value", "blob_length:#0"),
        ("blob_stretch:Value", "blob_width:#1"),
        ("blob_length:Value", "blob_u:#1"),
        ("blob_width:Value", "blob_v:#1"),
        ("input:Whitecaps", "cap_share:#0"),
        ("input:Whitecap Coverage", "cap_share:#1"),
        ("cap_share:Value", "blob_share:#0"),
        ("mark_share:Value", "blob_gap:#0"),
        ("pick_tile:Color", "blob_rag:#0"),
        ("blob_even:Value", "blob_ragged:#1"),
        ("blob_rag:Value", "blob_ragged:#0"),
        ("blob_ragged:Value", "blob_gap:#1"),
        ("blob_gap:Value", "blob:Value"),
        ("crest_whole:Value", "mark_lift:#0"),
        ("blob_share:Value", "mark_share:#0"),
        ("mark_lift:Value", "mark_share:#1"),
        ("blob_share:Value", "some:#0"),
        ("rest:Vector", "fade_distance:#0"),
        ("fade_distance:Value", "fade_near:Value"),
        (f"input:{FADE_START_INPUT}", "fade_near:From Min"),
        (f"input:{FADE_END_INPUT}", "fade_near:From Max"),
        ("fade_near:Result", "near_floor:#0"),
        ("input:Foam", "crest_whole:#0"),
        ("near_floor:Value", "crest_whole:#1"),
        ("cap_across:Value", "pick_u:#0"),
        ("cap_along:Value", "pick_v:#0"),
        ("pick_u:Value", "pick_uv:X"),
        ("pick_v:Value", "pick_uv:Y"),
        ("pick_uv:Vector", "pick_tile:Vector"),
        ("fade_near:Result", "crests_here:#0"),
        ("pick_tile:Color", "crests_here:#1"),
        ("cap_share:Value", "far_share:#0"),
        ("far_share:Value", "far_keep:#1"),
        ("far_keep:Value", "far_root:#0"),
        ("far_root:Value", "far_cut:#1"),
        ("blob_length:Value", "far_length:#0"),
        ("blob_width:Value", "far_width:#0"),
        *spot_links("far2"),
        ("far_length:Value", "far2_u:#1"),
        ("far_width:Value", "far2_v:#1"),
        ("blob_even:Value", "far_either:#0"),
        ("far2_even:Value", "far_either:#1"),
        ("far_cut:Value", "far_gap:#0"),
        ("far_either:Value", "far_gap:#1"),
        ("far_gap:Value", "far_blob:Value"),
        ("blob:Result", "caps_change:#0"),
        ("far_blob:Result", "caps_change:#1"),
        ("caps_change:Value", "caps:#0"),
        ("crests_here:Value", "caps:#1"),
        ("far_blob:Result", "caps:#2"),
        ("caps:Value", "on_some:#0"),
        ("some:Value", "on_some:#1"),
        ("on_some:Value", "crest:#0"),
        ("lace_tile:Color", "cap_sum:#0"),
        ("crest:Value", "cap_sum:#1"),
        ("cap_sum:Value", "cover:Value"),
        *foam_coverage.foam_feed("shore_foam", "tile_uv:Vector"),
        ("cover:Result", "foam_cover:#0"),
        ("shore_foam:Coverage", "foam_cover:#1"),
        ("foam_cover:Value", "mix:Fac"),
        ("with_mirror:Shader", "mix:#1"),
        ("foam_bsdf:BSDF", "mix:#2"),
        ("foam_glow:Emission", "mix:#2"),
        ("geometry:Backfacing", "sides:Fac"),
        ("mix:Shader", "sides:#1"),
        ("input:Normal", "underside:Normal"),
        ("input:Deep Color", "under_deep:#0"),
        ("underside:Reflected", "under_deep:Scale"),
        ("under_deep:Vector", "under_mirror:Color"),
        ("underside:Refracted", "under_sky:Color"),
        ("underside:Normal", "under_sky:Normal"),
        ("under_mirror:Emission", "see_through:#0"),
        ("under_sky:BSDF", "see_through:#1"),
        ("light_path:Is Camera Ray", "under_camera:Fac"),
        ("clear:BSDF", "under_camera:#1"),
        ("see_through:Shader", "under_camera:#2"),
        ("under_camera:Shader", "sides:#2"),
        *_DEBUG_LINKS,
    ),
)

# The shade that looks the Sky input up (the seeds' ocean, and what version 3 and older built):
# the one in `SPECS`, so older groups upgrade in place to it.
SHADE_SPEC = FULL_SHADE_SPEC.variant(())
