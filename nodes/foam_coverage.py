"""`Water Surface Foam Coverage`: the shore foam's share of the water, nested in the lake's and the
sea's shading so both draw their foam by one rule, with the foam tile's reads they share."""

from . import foam_map
from .spec import FOAM_IMAGE, GroupSpec, Node, Socket, attribute, math, pass_inputs
from .surface_parts import FLAG_ATTRIBUTE, SHORE_ATTRIBUTE

NAME = "Water Surface Foam Coverage"
FOAM_WIDTH_INPUT = Socket(
    "Foam Width",
    "NodeSocketFloat",
    1.0,
    min=0.01,
    max=100.0,
    subtype="DISTANCE",
    tooltip="How far from the waterline the shore foam reaches, in metres",
)
FOAM_AMOUNT_INPUT = Socket(
    "Foam Amount",
    "NodeSocketFloat",
    0.0,
    min=0.0,
    max=1.0,
    subtype="FACTOR",
    tooltip="Shore and contact foam, lit by the scene (0 = none; needs the surroundings)",
)
INPUTS = (
    Socket("Vector", "NodeSocketVector", tooltip="Where the foam tile is read", hide_value=True),
    FOAM_WIDTH_INPUT,
    FOAM_AMOUNT_INPUT,
)


def foam_feed(node, vector):
    """The links into a nested foam coverage node `node`: `vector` (where the tile is read) and
    the enclosing group's Foam Width and Foam Amount."""
    return ((vector, f"{node}:Vector"), *pass_inputs(node, [socket.name for socket in INPUTS[1:]]))


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


SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="Shore foam coverage: falloff from the waterline, thresholded against the foam tile",
    inputs=INPUTS,
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
