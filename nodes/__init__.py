"""Node groups and the water material, each group described as data and built by one builder.

This package's descriptions (`SPECS`) are plain data and import without Blender; the builder
(`builder.py`) and the material modules are the parts that need `bpy`.
"""

from . import bump_uv, caustics, underside, water_waves, wind_frame
from .boats import float_fit, keep_out, wake, wake_foam_cover
from .lake import water_surface
from .sea import ocean_normal, ocean_shade, sea_fade
from .surroundings import surroundings, surroundings_sample
from .under import caustic_light, caustic_sheet, meniscus, underwater_fog, underwater_shell

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
        ocean_normal.NORMAL_SPEC,
        ocean_shade.SHADE_SPEC,
        surroundings.SPEC,
        surroundings_sample.SPEC,
        keep_out.SPEC,
        wake.SPEC,
        wake_foam_cover.SPEC,
        float_fit.SPEC,
        underwater_fog.SPEC,
        meniscus.SPEC,
        underwater_shell.SPEC,
        caustic_sheet.SPEC,
        caustic_light.SPEC,
    )
}

__all__ = ("SPECS",)


def register():
    pass


def unregister():
    pass
