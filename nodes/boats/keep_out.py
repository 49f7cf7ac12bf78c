"""`Water Keep Out`: how dry the water is at a point, from one hull's dry mask.

The material gives it the point's position in the hull's own space (a Texture Coordinate node
whose Object is the hull: it follows the hull's final transform, constraints and all, in EEVEE and
Cycles, with no driver). The hull's dry mask (`water/boats/dry_mask_math.py`, a packed image: one
group per hull, found by its image) says whether that point lies within the hull's outline, and
the hull's height range whether it lies between its keel and its top. Hulls chain: each takes
the `Dry` of the one before and passes on the larger.
"""

from ..spec import BUMP_IMAGE, GroupSpec, Node, Socket, math, vmath

NAME = "Water Keep Out"

SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="1 where the point lies inside the hull's dry mask (between its keel and top), else "
    "the Dry of the hulls before",
    inputs=(
        Socket(
            "Dry",
            "NodeSocketFloat",
            0.0,
            0.0,
            1.0,
            subtype="FACTOR",
            tooltip="How dry the water is here by the hulls before this one (0 for the first)",
        ),
        Socket(
            "Position",
            "NodeSocketVector",
            (0.0, 0.0, 0.0),
            tooltip="The point in the hull's own space: Texture Coordinate's Object, with the hull",
            hide_value=True,
        ),
        Socket(
            "Low Corner",
            "NodeSocketVector",
            (0.0, 0.0, 0.0),
            subtype="TRANSLATION",
            tooltip="Where the mask begins (x, y) and the hull's keel (z), in its own space",
        ),
        Socket(
            "Size",
            "NodeSocketVector",
            (1.0, 1.0, 1.0),
            subtype="TRANSLATION",
            tooltip="The mask's length and width (x, y) and the hull's height (z), in its own space",
        ),
    ),
    outputs=(Socket("Dry", "NodeSocketFloat", tooltip="1 where no water shows, 0 where it does"),),
    nodes={
        "offset": vmath("SUBTRACT", 1, "position - low corner"),
        "unit": vmath("DIVIDE", 2, "0..1 over the mask and the height"),
        "mask": Node(
            "ShaderNodeTexImage",
            3,
            {"extension": "CLIP", "interpolation": "Linear", "image": BUMP_IMAGE},
            label="dry mask (seen from above)",
        ),
        "height": Node("ShaderNodeSeparateXYZ", 3, label="height in the hull, 0..1"),
        "inside": math("GREATER_THAN", 4, "within the outline", b=0.5),
        "above_keel": math("GREATER_THAN", 4, "above the keel", b=0.0),
        "below_top": math("LESS_THAN", 4, "below the top", b=1.0),
        "in_height": math("MULTIPLY", 5, "keel to top"),
        "dry_here": math("MULTIPLY", 6, "dry by this hull"),
        "dry": math("MAXIMUM", 7, "dry by any hull so far"),
    },
    links=(
        ("input:Position", "offset:#0"),
        ("input:Low Corner", "offset:#1"),
        ("offset:Vector", "unit:#0"),
        ("input:Size", "unit:#1"),
        ("unit:Vector", "mask:Vector"),
        ("unit:Vector", "height:Vector"),
        ("mask:Color", "inside:#0"),
        ("height:Z", "above_keel:#0"),
        ("height:Z", "below_top:#0"),
        ("above_keel:Value", "in_height:#0"),
        ("below_top:Value", "in_height:#1"),
        ("inside:Value", "dry_here:#0"),
        ("in_height:Value", "dry_here:#1"),
        ("input:Dry", "dry:#0"),
        ("dry_here:Value", "dry:#1"),
        ("dry:Value", "output:Dry"),
    ),
)
