"""Node groups and the water material, each group described as data and built by one builder."""

from . import bump_uv, caustics, ocean, sea_fade, surroundings, water_surface, water_waves, wind_frame
from .builder import NodeGroupError, ensure_group

SPECS = {
    spec.name: spec
    for spec in (
        wind_frame.SPEC,
        bump_uv.SPEC,
        caustics.SPEC,
        water_surface.SPEC,
        water_waves.SPEC,
        sea_fade.SPEC,
        ocean.NORMAL_SPEC,
        ocean.SHADE_SPEC,
        surroundings.SPEC,
        surroundings.SAMPLE_SPEC,
    )
}

__all__ = ("SPECS", "NodeGroupError", "ensure_group")


def register():
    pass


def unregister():
    pass
