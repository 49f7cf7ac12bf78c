"""The sea shading's helpers and inputs (`ocean_shade.py`): the whitecaps' constants and the
nodes that read and spot the foam tile, the far sea's fade, its inputs and debug views, apart so
the group's own module stays short enough to read."""

from .. import bump_uv, caustics, foam_coverage, foam_map, surface_parts
from ..spec import Node, Socket, math, vmath
from . import sea_fade

DEEP_BLUE = (0.0, 0.2, 0.4, 1.0)
WHITECAPS_MAX = 4.0
# Which water a whitecap covers: round spots, one a cell of WHITECAP_BLOB_TILE metres along and
# across the wind, at random in it (Voronoi), each of its own size and its edge ragged by the
# foam tile (`_spots`): compact patches metres across, whole, as a breaking crest's foam is. (A
# read of the foam tile itself picked its three octaves' bubble middles: rows of dashes a pixel
# wide, 0.1 m^2 at the median, issue 58.) The foam tile, read at WHITECAP_TILE, laces them.
WHITECAP_BLOB_TILE = (12.0, 10.0)
WHITECAP_TILE = (12.0, 6.0)
# The foam drawn out along the wind by `Foam Streaks` a: the lace's tile (12 a, 6 / a) metres and
# the spots' cells a^0.42 longer and narrower, so from Beaufort 7 the whitecaps' foam lies in broad
# streaks along the wind (a typical piece 5 times as long as wide, 0.5 m or more across). The open
# sea drives a from its wind (`whitecap_math.streaks`).
STREAKS_INPUT = "Foam Streaks"
STREAKS_MAX = 8.0
BLOB_STRETCH_POWER = 0.42
WHITECAP_BLOB_SOFTNESS = 0.01
# f inside a whitecap: over 1 + SOFTNESS / 2 the lace leaves only its darkest few per cent open,
# so a whitecap stays one patch (a thinner lace split it into specks a pixel wide).
WHITECAP_FOAM = 1.2
LACE_COVER = min(1.0, WHITECAP_FOAM - foam_map.SOFTNESS / 2)
SPOT_RAG = 0.4  # a spot's edge: B (1 + e (R - 1/2)), R the foam tile read 37 by 53 m
# The crest's mark (1 on the crest, TRAIL_FADE^k k trail steps behind it) raised to MARK_POWER:
# the foam a crest leaves stays whole, shrinking a little as it ages (`sea_fade.py`).
MARK_POWER = 0.1
# The spots' share per share of the sea asked: 1 / (crest share x lace cover x how much more
# of the sea the crests and the foam they leave behind mark, seen from above), the last measured
# (tests/test_whitecaps.py).
WHITECAP_SEEN = 1.59
WHITECAP_BLOB_GAIN = 1.0 / (sea_fade.CREST_SHARE * LACE_COVER * WHITECAP_SEEN)


def tile_read(key, tile, column, label, interpolation="Linear"):
    """Nodes reading the foam tile at (along, across) / `tile` metres: `{key}_tile:Color`."""
    return {
        f"{key}_u": math("DIVIDE", column, "along / length", b=tile[0]),
        f"{key}_v": math("DIVIDE", column, "across / width", b=tile[1]),
        f"{key}_uv": Node("ShaderNodeCombineXYZ", column + 1),
        f"{key}_tile": foam_coverage.foam_tile(column + 2, label, interpolation),
    }


def spots(key, tile, column, label):
    """Nodes making an evenly spread value from round spots, one a (along, across) / `tile` cell:
    Voronoi's nearest-point distance d, as 1 - exp(-pi d^2) (even for points one a cell at
    random), so `{key}_even < s` covers s of the sea in compact spots. `{key}_even:Value`."""
    return {
        f"{key}_u": math("DIVIDE", column, "along / length", b=tile[0]),
        f"{key}_v": math("DIVIDE", column, "across / width", b=tile[1]),
        f"{key}_uv": Node("ShaderNodeCombineXYZ", column + 1),
        f"{key}_tile": Node(
            "ShaderNodeTexVoronoi",
            column + 2,
            {"voronoi_dimensions": "2D", "feature": "F1", "distance": "EUCLIDEAN"},
            {"Scale": 1.0, "Randomness": 1.0},
            label=label,
        ),
        f"{key}_size": math("MULTIPLY_ADD", column + 3, "its size: 1/2 + the cell's grey", b=1.0, c=0.5),
        f"{key}_rel": math("DIVIDE", column + 3, "d / size"),
        f"{key}_sq": math("POWER", column + 3, "d^2", b=2.0),
        f"{key}_neg": math("MULTIPLY", column + 3, "-pi d^2", b=-3.141592653589793),
        f"{key}_exp": math("EXPONENT", column + 3, "exp(-pi d^2)"),
        f"{key}_even": math("SUBTRACT", column + 3, "1 - exp(-pi d^2): even", a=1.0),
    }


def spot_links(key):
    return (
        *tile_links(key),
        (f"{key}_tile:Color", f"{key}_size:#0"),
        (f"{key}_tile:Distance", f"{key}_rel:#0"),
        (f"{key}_size:Value", f"{key}_rel:#1"),
        (f"{key}_rel:Value", f"{key}_sq:#0"),
        (f"{key}_sq:Value", f"{key}_neg:#0"),
        (f"{key}_neg:Value", f"{key}_exp:#0"),
        (f"{key}_exp:Value", f"{key}_even:#1"),
    )


def bubble(label):
    """A whitecap's bubble from `share - B`: 0 outside, 1 inside, over WHITECAP_BLOB_SOFTNESS."""
    return Node(
        "ShaderNodeMapRange",
        30,
        {"interpolation_type": "LINEAR", "clamp": True},
        {1: -WHITECAP_BLOB_SOFTNESS / 2, 2: WHITECAP_BLOB_SOFTNESS / 2, 3: 0.0, 4: 1.0},
        label=label,
    )


def tile_links(key):
    return (
        ("cap_along:Value", f"{key}_u:#0"),
        ("cap_across:Value", f"{key}_v:#0"),
        (f"{key}_u:Value", f"{key}_uv:X"),
        (f"{key}_v:Value", f"{key}_uv:Y"),
        (f"{key}_uv:Vector", f"{key}_tile:Vector"),
    )


FOAM_WHITE = (0.85, 0.87, 0.88)


# The far sea's whitecaps: past the sea's fade the mesh marks no crests, so there the shade picks
# bubbles of the share the crests and the foam they leave would cover, s x crest share x seen,
# that is the share asked over the lace's cover, everywhere: the same foam on average, to the
# horizon. A group left undriven (the seeds' ocean) fades only past FADE_NEVER metres.
FADE_START_INPUT = "Fade Start"
FADE_END_INPUT = "Fade End"
FADE_NEVER = 1.0e6
FAR_CAP_GAIN = 1.0 / LACE_COVER
# The far whitecaps are where either of two spot reads, B and B2 (`spots`), is low
# (min(B, B2) < t, t = 1 - sqrt(1 - share)): B2's cells are drawn other ways (along and across
# the wind, no simple ratio to B's), so far foam has no lattice of its own. (When B was a read of
# the foam tile, one read alone repeated every tile width: parallel stripes from high up.)
FAR_SECOND_READ = (1.27, 0.79)
PICK_TILE = (37.0, 53.0)  # metres across and along the wind: no multiple of the other reads

UNRESOLVED_SLOPE = "Unresolved Slope"

SEA_ABSORPTION = (0.4, 0.08, 0.04, 1.0)  # per metre: clear sea water, red gone first


SHADE_INPUTS = (
    Socket("Normal", "NodeSocketVector", (0.0, 0.0, 1.0), hide_value=True, tooltip="Shading normal n"),
    Socket("Sky", "NodeSocketColor", (0.5, 0.7, 1.0, 1.0), tooltip="The sky seen in the reflected direction"),
    Socket(
        "Deep Color",
        "NodeSocketColor",
        DEEP_BLUE,
        tooltip="Colour of the deep water (the seeds' deep blue); with the surroundings, what the "
        "water scatters back where it hides the bed",
    ),
    Socket(
        "Glint Power",
        "NodeSocketFloat",
        30.0,
        min=1.0,
        max=1000.0,
        tooltip="The glint is mean(sky) to this power: only the brightest sky glints",
    ),
    Socket(
        "Foam",
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        hide_value=True,
        tooltip="The crest's foam here, 0 to 1 (the open sea's `water_whitecaps`; 0 where the mesh has none)",
    ),
    Socket(
        "Whitecap Coverage",
        "NodeSocketFloat",
        0.02,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
        tooltip="Share of the sea whitecaps cover at Whitecaps 1 (the open sea drives it from its wind, as "
        "Monahan and O'Muircheartaigh measured the sea's whitecaps)",
    ),
    Socket(
        "Whitecaps",
        "NodeSocketFloat",
        1.0,
        min=0.0,
        max=WHITECAPS_MAX,
        tooltip="Whitecaps on the crests, white foam lit by the scene: 1 as many as nature has for the "
        "wind (Monahan), 0 none, 2 more",
    ),
    Socket(
        STREAKS_INPUT,
        "NodeSocketFloat",
        1.0,
        min=1.0,
        max=STREAKS_MAX,
        tooltip="How far the wind draws the foam's lace out along itself: 1 bubbles, more long streaks "
        "(the open sea drives it from its wind: streaks from 12 m/s, Beaufort 6 and up)",
    ),
    # The surroundings (depth colour, shore foam, caustics), as on the lake: nothing without them.
    *bump_uv.SCROLL_INPUTS,  # Wave Length, Wind Direction, Wind Force, Time
    Socket(
        "Absorption",
        "NodeSocketColor",
        SEA_ABSORPTION,
        tooltip="How much of each colour the water absorbs per metre seen through it (needs the "
        "surroundings' depth): where it lets the bed through, the bed shows instead of Deep Color",
    ),
    foam_coverage.FOAM_WIDTH_INPUT,
    foam_coverage.FOAM_AMOUNT_INPUT,
    surface_parts.SUN_DIRECTION_INPUT,
    caustics.CAUSTICS_INPUT,
    caustics.CAUSTICS_SCALE_INPUT,
    caustics.SUN_LIT_INPUT,
    Socket(
        "Debug View",
        "NodeSocketInt",
        0,
        min=0,
        max=8,
        tooltip="0 final, 3 Fresnel F, 4 shading normal (world), 5 sun glint, 6 transmittance, "
        "7 foam and whitecaps, 8 caustics, each unlit (1 and 2: the final picture)",
    ),
    Socket(
        "Water Fresnel",
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
        tooltip="1: water's own reflectance from its refractive index (2% looking straight down, a mirror "
        "at grazing: the open sea); 0: the seeds' ocean Fresnel (never under half a mirror)",
    ),
    Socket(
        "Traced Sky",
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        subtype="FACTOR",
        tooltip="1: the renderer reflects the world the scene has now, whatever it is (an image, Sky "
        "Texture, a gradient), and the sun's own glint, as on the lake; 0: the Sky input (the world's "
        "image or colour looked up as the seeds do, as it was when the water was added)",
    ),
    Socket(
        UNRESOLVED_SLOPE,
        "NodeSocketFloat",
        0.0,
        min=0.0,
        max=1.0,
        hide_value=True,
        tooltip="Mean square slope each way the bump's reads lost (Water Ocean Normal's): with Water "
        "Fresnel, the far sea reflects what those slopes would (water's mean reflectance over them, a "
        "rougher mirror), not a flat mirror",
    ),
    Socket(
        FADE_START_INPUT,
        "NodeSocketFloat",
        FADE_NEVER,
        min=0.0,
        hide_value=True,
        tooltip="Metres from the sea's centre where its waves, and the crests marked on them, start to "
        "fade (the sea's Water Sea Fade, driven): past it whitecaps are spread over the flat far sea, "
        "as many as the crests would carry",
    ),
    Socket(
        FADE_END_INPUT,
        "NodeSocketFloat",
        FADE_NEVER + 1.0,
        min=0.0,
        hide_value=True,
        tooltip="Metres from the sea's centre where its waves are gone (Water Sea Fade's, driven)",
    ),
)
# The ocean's debug views: the lake's numbers for what the ocean shading has (1 and 2, the lake's
# closures alone, show the final picture here).
DEBUG_VIEWS = (
    (3, "F, grey"),
    (4, "shading normal n * 0.5 + 0.5 (world space)"),
    (5, "sun glint: pow(max(reflect(L, n) . eye, 0), Glint Power)"),
    (6, "transmittance T (0 without surroundings)"),
    (7, "foam: whitecaps and shore foam"),
    (8, "caustic factor"),
)


def debug_nodes():
    """Each debug view's value as an unlit emission, mixed over the final picture while a view
    from 3 to 8 is asked; any other number shows the final picture."""
    values = {
        3: "F:Value",
        4: "normal_colour:Vector",
        5: "glint_pow:Value",
        6: "t_seen:Vector",
        7: "foam_cover:Value",
        8: "caustics:Factor",
    }
    nodes = {
        "normal_colour": vmath("MULTIPLY_ADD", 30, "n * 0.5 + 0.5", b=(0.5, 0.5, 0.5), c=(0.5, 0.5, 0.5)),
        "debug_emit": Node("ShaderNodeEmission", 35, values={"Strength": 1.0}, label="debug view, unlit"),
        "debug_or_final": Node("ShaderNodeMixShader", 36, label="final, or a debug view"),
    }
    links = [
        ("input:Normal", "normal_colour:#0"),
    ]
    glint, glint_links = surface_parts.glint_nodes("input:Normal", "input:Glint Power", column=30)
    nodes |= glint
    links += glint_links
    colour, any_view = None, None
    for number, source in values.items():
        nodes[f"is_{number}"] = math("COMPARE", 33, f"view == {number}", b=float(number), c=0.5)
        nodes[f"view_{number}"] = vmath("MULTIPLY_ADD", 34, f"+ view {number}")
        links += [
            ("input:Debug View", f"is_{number}:#0"),
            (source, f"view_{number}:#0"),
            (f"is_{number}:Value", f"view_{number}:#1"),
        ]
        if colour is not None:
            links.append((colour, f"view_{number}:#2"))
            nodes[f"any_{number}"] = math("ADD", 34, "a debug view")
            links += [(any_view, f"any_{number}:#0"), (f"is_{number}:Value", f"any_{number}:#1")]
            any_view = f"any_{number}:Value"
        else:
            any_view = f"is_{number}:Value"
        colour = f"view_{number}:Vector"
    links += [
        (colour, "debug_emit:Color"),
        (any_view, "debug_or_final:Fac"),
        ("sides:Shader", "debug_or_final:#1"),
        ("debug_emit:Emission", "debug_or_final:#2"),
        ("debug_or_final:Shader", "output:Shader"),
    ]
    return nodes, tuple(links)
