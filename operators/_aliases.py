"""The ids operators had before, kept working, since saved keymaps and scripts call operators by
id. Each is a copy of its operator's class, made before registering: the same properties and
methods, so the same code runs; `INTERNAL` keeps it out of search. Not a subclass: Blender
registers no property an operator inherits from another operator class.

Two kinds: `RENAMED`, the ids before issue 59 (`object.water_surface_*`), the same operator under
another name; and `FIXED`, the old ids of one way of a switch (`object.water_float_stop`, before
each switch was one operator with `enable`, `_switch`), the switch with that way fixed.
"""

from types import SimpleNamespace

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

# Old id -> (new id, the properties it fixes, its label as before: the keymap editor's). A literal too.
FIXED = {
    "object.water_float_stop": ("object.water_float", {"enable": False}, "Stop Floating"),
    "object.water_let_in": ("object.water_keep_out", {"enable": False}, "Let Water In"),
    "object.water_wake_add": ("object.water_wake", {"enable": True}, "Add Wake"),
    "object.water_wake_remove": ("object.water_wake", {"enable": False}, "Remove Wake"),
}

# Python makes `__dict__` and `__weakref__` for each class; the id and options are the alias's own.
_NOT_COPIED = {"__dict__", "__weakref__", "__qualname__", "bl_idname", "bl_options"}


def _class_name(idname):
    """Blender's class name for an id: "object.water_add" -> "OBJECT_OT_water_add"."""
    prefix, name = idname.split(".")
    return f"{prefix.upper()}_OT_{name}"


def _namespace(cls, old_idname):
    """The class body of an alias of `cls` answering to `old_idname`, hidden from search."""
    namespace = {key: value for key, value in vars(cls).items() if key not in _NOT_COPIED}
    namespace["__annotations__"] = dict(vars(cls).get("__annotations__", {}))
    namespace["bl_idname"] = old_idname
    namespace["bl_options"] = set(getattr(cls, "bl_options", ())) | {"INTERNAL"}  # a mix-in's too
    return namespace


def alias(cls, old_idname):
    """A copy of the unregistered operator class `cls` answering to `old_idname`, hidden from search."""
    return type(cls)(_class_name(old_idname), cls.__bases__, _namespace(cls, old_idname))


def fixed_alias(cls, old_idname, values, label):
    """An alias of `cls` whose properties `values` are fixed: each a hidden property with that
    default, set again before `execute` and `invoke` run (a script or a keymap item that sets it
    changes nothing), and, for `enable` of a switch with `enable_polls`, the poll of that way
    alone (`_switch`), as the old operator's was. Labelled `label`, described as its `description`
    callback describes that way."""
    namespace = _namespace(cls, old_idname)
    annotations = namespace["__annotations__"]
    for key, value in values.items():
        deferred = annotations[key]  # bpy.props' deferred property: its function and keywords
        annotations[key] = deferred.function(**{**deferred.keywords, "default": value, "options": {"HIDDEN"}})
    namespace["bl_label"] = label
    if "description" in vars(cls):  # its tooltip for that way, as its static description too
        namespace["__doc__"] = cls.description(None, SimpleNamespace(**values)) or cls.__doc__
    if "enable" in values and hasattr(cls, "enable_polls"):
        namespace["poll"] = _one_way_poll(cls.enable_polls[values["enable"]])
    namespace["execute"] = _fixed_execute(cls.execute, values)
    if "invoke" in vars(cls):
        namespace["invoke"] = _fixed_invoke(cls.invoke, values)
    return type(cls)(_class_name(old_idname), cls.__bases__, namespace)


def _one_way_poll(check):
    def poll(cls, context):
        return check(cls, context)

    return classmethod(poll)


def _set(operator, values):
    for key, value in values.items():
        setattr(operator, key, value)


# Blender counts a callback's arguments: one wrapper for each.
def _fixed_execute(execute, values):
    def fixed(self, context):
        _set(self, values)
        return execute(self, context)

    return fixed


def _fixed_invoke(invoke, values):
    def fixed(self, context, event):
        _set(self, values)
        return invoke(self, context, event)

    return fixed


def aliases(classes):
    """The aliases of the renamed and fixed operators among `classes` (checked: each new id is one
    of them)."""
    by_id = {cls.bl_idname: cls for cls in classes}
    missing = sorted({*RENAMED.values(), *(new for new, _values, _label in FIXED.values())} - set(by_id))
    if missing:
        raise LookupError(f"renamed operators not registered: {missing}")
    renamed = tuple(alias(by_id[new], old) for old, new in RENAMED.items())
    fixed = tuple(fixed_alias(by_id[new], old, values, label) for old, (new, values, label) in FIXED.items())
    return renamed + fixed
