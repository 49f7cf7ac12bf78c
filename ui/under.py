"""The view from below in the panel: the `Underwater` switch and its light shafts."""

from ..water import underwater


def draw_underwater(layout, obj):
    """The `Underwater` switch: what a camera under the surface sees through."""
    on = underwater.find(obj) is not None
    text = "Underwater: on (fog by distance)" if on else "Underwater: off (clear as air)"
    button = layout.operator("object.water_underwater", text=text, icon="MOD_FLUIDSIM", depress=on)
    button.enable = not on
    node = underwater.fog_node(obj) if on else None
    if node is not None and "Light Shafts" in node.inputs:
        layout.prop(node.inputs["Light Shafts"], "default_value", text="Light Shafts")
