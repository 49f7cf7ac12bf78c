"""Render engine identifiers, looked up in the running Blender.

EEVEE is `BLENDER_EEVEE_NEXT` in 4.2-4.5 and `BLENDER_EEVEE` from 5.0; the
add-on asks Blender instead of assuming either.
"""

import bpy

_EEVEE_IDS = ("BLENDER_EEVEE_NEXT", "BLENDER_EEVEE")


def eevee_engine_id():
    """The identifier of EEVEE in this Blender."""
    engines = {item.identifier for item in bpy.types.RenderSettings.bl_rna.properties["engine"].enum_items}
    for ident in _EEVEE_IDS:
        if ident in engines:
            return ident
    raise RuntimeError(f"no EEVEE render engine among {sorted(engines)}")


def enable_ray_tracing(scene):
    """EEVEE settings under which the water shows traced reflection and refraction.

    Screen-trace ray tracing is the seeds' screen-space reflection and refraction
    maps; a full-resolution trace keeps the mirror sharp (the default traces at half).
    Returns the names of the settings it changed.
    """
    eevee = scene.eevee
    options = eevee.ray_tracing_options
    wanted = (
        (eevee, "use_raytracing", True),
        (eevee, "ray_tracing_method", "SCREEN"),
        (options, "resolution_scale", "1"),
    )
    changed = []
    for owner, prop, value in wanted:
        if getattr(owner, prop) != value:
            setattr(owner, prop, value)
            changed.append(prop)
    return changed
