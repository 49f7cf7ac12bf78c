"""The repository is a valid extension, installs from its zip, and cleans up after itself."""

import addon_utils
import bpy

import harness

# Paths a built zip may hold: the add-on and nothing else.
ADDON_PARTS = ("__init__.py", "blender_manifest.toml", "operators/", "nodes/", "presets/", "ui/", "water/")
TOOLING = ("tests/", "tools/", ".ci/", "bench/", "docs/", "out/", "README", "pyproject", "venv")


def test_manifest_validates():
    proc = harness.run_blender_ext("validate", str(harness.ROOT))
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_built_zip_validates_and_holds_only_the_addon(addon_zip):
    import zipfile

    proc = harness.run_blender_ext("validate", str(addon_zip))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    names = zipfile.ZipFile(addon_zip).namelist()
    assert "__init__.py" in names and "blender_manifest.toml" in names
    leaked = [n for n in names if n.startswith(TOOLING) or "/." in f"/{n}" or n.endswith(".pyc")]
    assert leaked == []
    strays = [n for n in names if not (n.startswith(ADDON_PARTS) or "/" not in n)]
    assert strays == []


def test_installed_from_zip_and_enabled(addon):
    assert addon.__name__ == harness.ADDON_MODULE
    assert "extensions/user_default/water_surface" in addon.__file__.replace("\\", "/")
    loaded_default, loaded_state = addon_utils.check(harness.ADDON_MODULE)
    assert loaded_state
    assert harness.ADDON_MODULE in bpy.context.preferences.addons


def _registry():
    """What an add-on can leave registered: types, menu entries, properties, handlers."""
    menus = {}
    for name in dir(bpy.types):
        cls = getattr(bpy.types, name)
        if hasattr(cls, "_dyn_ui_initialize") and hasattr(cls, "draw"):
            menus[name] = tuple(f"{f.__module__}.{f.__qualname__}" for f in cls._dyn_ui_initialize())
    props = {}
    for id_type in ("Object", "Scene", "Material", "WindowManager", "World", "Light", "ShaderNodeTree"):
        props[id_type] = frozenset(p.identifier for p in getattr(bpy.types, id_type).bl_rna.properties)
    handlers = {
        name: len(getattr(bpy.app.handlers, name))
        for name in dir(bpy.app.handlers)
        if isinstance(getattr(bpy.app.handlers, name), list)
    }
    keymap_items = sum(len(km.keymap_items) for km in bpy.context.window_manager.keyconfigs.addon.keymaps)
    return {
        "types": frozenset(dir(bpy.types)),
        "menus": menus,
        "props": props,
        "handlers": handlers,
        "keymap_items": keymap_items,
    }


def _assert_same(before, after):
    assert after["types"] - before["types"] == set(), "classes left registered"
    assert before["types"] - after["types"] == set(), "classes missing"
    for key in ("menus", "props", "handlers", "keymap_items"):
        assert after[key] == before[key], f"{key} differ"


def test_disable_enable_cycles_leave_nothing_behind(addon):
    module = harness.ADDON_MODULE
    enabled = _registry()
    ours = {name for name in enabled["types"] if "water" in name.lower()}
    assert ours, "the add-on registers no class"
    addon_utils.disable(module, default_set=True)
    disabled = _registry()
    assert not {name for name in disabled["types"] if "water" in name.lower()}
    for _cycle in range(3):
        addon_utils.enable(module, default_set=True)
        _assert_same(enabled, _registry())
        addon_utils.disable(module, default_set=True)
        _assert_same(disabled, _registry())
    addon_utils.enable(module, default_set=True)
    _assert_same(enabled, _registry())
    # Still works: the panel is back and the operator adds water with its mirror set-up.
    assert hasattr(bpy.types, "VIEW3D_PT_water_surface")
    harness.clean_scene()
    assert bpy.ops.object.water_surface_add() == {"FINISHED"}
    assert harness.addon("water.values").is_water(bpy.context.active_object)
    assert harness.addon("water.mirror").find_probe(bpy.context.active_object) is not None
