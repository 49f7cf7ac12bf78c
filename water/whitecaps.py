"""The open sea's whitecaps follow its wind: the ocean shading's `Whitecap Coverage` is driven by
the Ocean modifier's wind speed (a simple expression, `whitecap_math.py`), so changing the wind
in the panel, by script or on the modifier itself changes them too, with no Python at render."""

import bpy

from ..nodes.material import drive_socket
from ..nodes.ocean_material import ocean_nodes
from .whitecap_math import coverage_expression

COVERAGE_INPUT = "Whitecap Coverage"


def drive_whitecaps(obj, ocean, per_wind=1.0):
    """Drives the coverage input of every ocean shading on `obj` from `ocean`'s wind (which is
    `per_wind` times the wind speed). Groups from before the input existed are left as they are."""
    path = f'modifiers["{bpy.utils.escape_identifier(ocean.name)}"].wind_velocity'
    for slot in obj.material_slots:
        nodes = ocean_nodes(slot.material)
        if not nodes or COVERAGE_INPUT not in nodes[1].inputs:
            continue
        socket = nodes[1].inputs[COVERAGE_INPUT]
        drive_socket(socket, None, coverage_expression("u", per_wind), [("u", "OBJECT", obj, path)])
