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


# The EEVEE settings under which the water shows traced reflection and refraction:
# (RNA path from the scene, value, what it means in words).
RAY_TRACING = (
    ("eevee.use_raytracing", True, "EEVEE ray tracing"),
    ("eevee.ray_tracing_method", "SCREEN", "ray tracing method"),
    ("eevee.ray_tracing_options.resolution_scale", "1", "ray tracing resolution"),
)


def enable_ray_tracing(scene):
    """EEVEE settings under which the water shows traced reflection and refraction.

    Screen-trace ray tracing is the seeds' screen-space reflection and refraction
    maps; a full-resolution trace keeps the mirror sharp (the default traces at half).
    Returns the names of the settings it changed.
    """
    changed = []
    for path, value, _label in RAY_TRACING:
        owner_path, _, prop = path.rpartition(".")
        owner = scene.path_resolve(owner_path)
        if getattr(owner, prop) != value:
            setattr(owner, prop, value)
            changed.append(prop)
    return changed
