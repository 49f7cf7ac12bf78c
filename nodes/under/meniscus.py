"""`Water Meniscus` (a shader): the dark line of the waterline across the lens (the ribbon
`Water Underwater Shell` makes), a little of what is behind showing."""

from ..spec import GroupSpec, Node, Socket

NAME = "Water Meniscus"

SPEC = GroupSpec(
    name=NAME,
    version=1,
    description="The thin line of water across the lens where it crosses the surface: dark, a "
    "little of what is behind showing through",
    inputs=(
        Socket("Color", "NodeSocketColor", (0.01, 0.015, 0.02, 1.0), tooltip="The line's own colour"),
        Socket(
            "Opacity",
            "NodeSocketFloat",
            0.85,
            min=0.0,
            max=1.0,
            subtype="FACTOR",
            tooltip="How much of what is behind the line it hides",
        ),
    ),
    outputs=(Socket("Shader", "NodeSocketShader"),),
    nodes={
        "clear": Node("ShaderNodeBsdfTransparent", 1),
        "line": Node("ShaderNodeEmission", 1, label="the line"),
        "mix": Node("ShaderNodeMixShader", 2),
    },
    links=(
        ("input:Color", "line:Color"),
        ("input:Opacity", "mix:Fac"),
        ("clear:BSDF", "mix:#1"),
        ("line:Emission", "mix:#2"),
        ("mix:Shader", "output:Shader"),
    ),
)
