"""The ids before issue 59 (`object.water_surface_*`) kept working, since saved keymaps and scripts
call operators by id. Each is a copy of its operator's class, made before registering: the same
properties and methods, so the same code runs; `INTERNAL` keeps it out of search. Not a subclass:
Blender registers no property an operator inherits from another operator class.
"""

# Old id -> new id. Read by `tests/plain/test_operator_ids.py` without Blender: keep it a literal.
RENAMED = {
    "object.water_surface_add": "object.water_add",
    "object.water_surface_preset_apply": "object.water_preset_apply",
    "object.water_surface_preset_add": "object.water_preset_add",
    "object.water_surface_preset_remove": "object.water_preset_remove",
    "object.water_surface_sun_set": "object.water_sun_set",
    "object.water_surface_bump_set": "object.water_bump_set",
    "object.water_surface_repair": "object.water_repair",
}

# Python makes `__dict__` and `__weakref__` for each class; the id and options are the alias's own.
_NOT_COPIED = {"__dict__", "__weakref__", "__qualname__", "bl_idname", "bl_options"}


def _class_name(idname):
    """Blender's class name for an id: "object.water_add" -> "OBJECT_OT_water_add"."""
    prefix, name = idname.split(".")
    return f"{prefix.upper()}_OT_{name}"


def alias(cls, old_idname):
    """A copy of the unregistered operator class `cls` answering to `old_idname`, hidden from search."""
    namespace = {key: value for key, value in vars(cls).items() if key not in _NOT_COPIED}
    namespace["__annotations__"] = dict(vars(cls).get("__annotations__", {}))
    namespace["bl_idname"] = old_idname
    namespace["bl_options"] = set(getattr(cls, "bl_options", ())) | {"INTERNAL"}  # a mix-in's too
    return type(cls)(_class_name(old_idname), cls.__bases__, namespace)


def aliases(classes):
    """The aliases of the renamed operators among `classes` (checked: each new id is one of them)."""
    by_id = {cls.bl_idname: cls for cls in classes}
    missing = sorted(set(RENAMED.values()) - set(by_id))
    if missing:
        raise LookupError(f"renamed operators not registered: {missing}")
    return tuple(alias(by_id[new], old) for old, new in RENAMED.items())
