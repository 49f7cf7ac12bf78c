"""The open sea's whitecaps follow its wind: the ocean shading's `Whitecap Coverage` is driven by
the Ocean modifier's wind speed (a simple expression, `whitecap_math.py`), so changing the wind
in the panel, by script or on the modifier itself changes them too, with no Python at render;
and so is `Foam Streaks` (the foam drawn out along a strong wind); the sea's fade gets the crests'
run in half a second (`Trail Step`), for the foam they leave; and the shading's `Fade Start` and
`Fade End` follow the fade's own, so past it whitecaps cover the flat far sea as the crests would."""

import math

import bpy

from ...nodes.material import drive_socket
from ...nodes.sea import sea_fade
from ...nodes.sea.ocean_material import ocean_nodes
from ...nodes.sea.ocean_parts import FADE_END_INPUT, FADE_START_INPUT, STREAKS_INPUT
from ..waves import input_ids, input_path, set_wave_input
from .whitecap_math import coverage_expression, crest_speed, streaks_expression

COVERAGE_INPUT = "Whitecap Coverage"


def drive_whitecaps(obj, ocean, fade):
    """Drives the coverage input of every ocean shading on `obj` from `ocean`'s wind speed, and
    sets the trail on `fade`, the sea's fade modifier.
    Groups from before these inputs existed are left as they are."""
    path = f'modifiers["{bpy.utils.escape_identifier(ocean.name)}"].wind_velocity'
    for slot in obj.material_slots:
        nodes = ocean_nodes(slot.material)
        if not nodes or COVERAGE_INPUT not in nodes[1].inputs:
            continue
        socket = nodes[1].inputs[COVERAGE_INPUT]
        drive_socket(socket, None, coverage_expression("u"), [("u", "OBJECT", obj, path)])
        if STREAKS_INPUT in nodes[1].inputs:  # version 10 on
            streaks = nodes[1].inputs[STREAKS_INPUT]
            drive_socket(streaks, None, streaks_expression("u"), [("u", "OBJECT", obj, path)])
        for name in (FADE_START_INPUT, FADE_END_INPUT):  # version 12 on
            if name in nodes[1].inputs and name in input_ids(fade):
                drive_socket(nodes[1].inputs[name], None, "d", [("d", "OBJECT", obj, input_path(fade, name))])
    if "Trail Step" in [item.name for item in fade.node_group.interface.items_tree]:
        # The modifier's waves at angle a travel along (-cos a, sin a) (`sea_math.wave_angle`).
        run = crest_speed(ocean.wind_velocity) * sea_fade.TRAIL_SECONDS
        angle = ocean.wave_direction
        set_wave_input(fade, "Trail Step", (-math.cos(angle) * run, math.sin(angle) * run, 0.0))
