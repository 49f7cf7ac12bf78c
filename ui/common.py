"""What the panel draws for every kind of water: a shader part's switch, the surroundings button
and the four-sine waves' inputs."""

from ..nodes.material import parts_built
from ..nodes.water_waves import WAVE_COUNT
from ..operators.parts import PART_ITEMS
from ..water.surroundings import surroundings_collection, surroundings_modifier
from ..water.waves import input_ids, input_property, wave_modifier

# The optional parts of the shading (`water_surface.PARTS`; the ocean's has the caustics): a
# switch, then their inputs while they are in the shader.
PARTS = {
    "depth": ("Absorption", "Scatter Color"),
    "foam": ("Foam Width", "Foam Amount"),
    "caustics": ("Caustics", "Caustics Scale"),
}
_PART_LABELS = {name: label for name, label, _tip in PART_ITEMS}


def draw_part(box, node, name, spec=None):
    """A part's switch, and its inputs while it is in the shader (out, it costs nothing);
    `spec`: the shading's description with every part (default: the lake's)."""
    label, inputs = _PART_LABELS[name], PARTS[name]
    on = name in (parts_built(node.node_tree, spec) if spec else parts_built(node.node_tree))
    op = box.operator(
        "object.water_part_switch",
        text=f"{label}: {'On' if on else 'Off'}",
        icon="CHECKBOX_HLT" if on else "CHECKBOX_DEHLT",
    )
    if op is not None:  # None while the operator's poll refuses (linked water)
        op.part, op.enable = name, not on
    if on:
        for input_name in inputs:
            box.prop(node.inputs[input_name], "default_value", text=input_name)


def draw_surroundings(box, obj):
    """Which collection the water measures its depth and shore against."""
    if surroundings_modifier(obj) is None:
        text = "Surroundings: none (add them)"
    else:
        collection = surroundings_collection(obj)
        text = f"Surroundings: {collection.name if collection else 'nothing'}"
    box.operator("object.water_surroundings_set", text=text, icon="OUTLINER_COLLECTION")


def draw_waves(layout, obj):
    """The wave modifier's inputs, wave by wave, or a button to add it."""
    modifier = wave_modifier(obj)
    box = layout.box()
    if modifier is None:
        box.operator("object.water_waves_add", icon="MOD_WAVE")
        return
    box.label(text="Waves", icon="MOD_WAVE")
    names = input_ids(modifier)
    missing = [
        f"{name} {number}"
        for number in range(1, WAVE_COUNT + 1)
        for name in ("Amplitude", "Wavelength", "Speed", "Direction")
        if f"{name} {number}" not in names
    ]
    if missing:
        box.label(text=f"Group '{modifier.node_group.name}' lacks '{missing[0]}'", icon="ERROR")
        return
    box.use_property_split = True
    for number in range(1, WAVE_COUNT + 1):
        col = box.column(align=True)
        for name in ("Amplitude", "Wavelength", "Speed"):
            col.prop(*input_property(modifier, f"{name} {number}"), text=f"{name} {number}")
        owner, path = input_property(modifier, f"Direction {number}")
        row = col.row(align=True)
        row.prop(owner, path, index=0, text=f"Direction {number} X")
        row.prop(owner, path, index=1, text="Y")
