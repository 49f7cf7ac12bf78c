"""Node groups and the water material, each group described as data and built by one builder.

This package's descriptions (`SPECS`) are plain data and import without Blender; the builder
(`builder.py`) and the material modules are the parts that need `bpy`.
"""

from . import (
    bump_uv,
    caustic_light,
    caustics,
    float_fit,
    keep_out,
    ocean,
    sea_fade,
    surroundings,
    underside,
    underwater,
    water_surface,
    water_waves,
    wind_frame,
)
from .boats import wake

SPECS = {
    spec.name: spec
    for spec in (
        wind_frame.SPEC,
        bump_uv.SPEC,
        caustics.SPEC,
        underside.SPEC,
        water_surface.SPEC,
        water_waves.SPEC,
        sea_fade.SPEC,
        ocean.NORMAL_SPEC,
        ocean.SHADE_SPEC,
        surroundings.SPEC,
        surroundings.SAMPLE_SPEC,
        keep_out.SPEC,
        wake.SPEC,
        float_fit.SPEC,
        underwater.FOG_SPEC,
        underwater.MENISCUS_SPEC,
        underwater.SHELL_SPEC,
        underwater.SHEET_SPEC,
        caustic_light.SPEC,
    )
}

__all__ = ("SPECS",)


def register():
    pass


def unregister():
    pass
