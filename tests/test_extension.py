"""The repository is a valid extension, installs from its zip, and cleans up after itself."""

import addon_utils
import bpy

import harness

# The add-on, the whole of what a built zip may hold at its top level (an allow-list: a file added
# at the repository's top level, CONTRIBUTING.md, a README, pyproject.toml, tests/, tools/, bench/,
# docs/, .ci/, is not the add-on and must be excluded in the manifest's [build] section).
ADDON_MODULES = ("__init__.py", "api.py", "cli.py", "engine.py", "handlers.py")
ADDON_PACKAGES = ("nodes", "operators", "presets", "ui", "water")
MANIFEST = "blender_manifest.toml"
ADDON_TOP = {*ADDON_MODULES, MANIFEST, *ADDON_PACKAGES}


def _addon_files():
    """The add-on's files in the repository, as the zip names them: the top-level modules, the
    manifest and every file of its packages but Python's caches and hidden files."""
    files = {*ADDON_MODULES, MANIFEST}
    for package in ADDON_PACKAGES:
        for path in (harness.ROOT / package).rglob("*"):
            relative = path.relative_to(harness.ROOT)
            hidden = any(part.startswith(".") or part == "__pycache__" for part in relative.parts)
            if path.is_file() and not hidden and path.suffix != ".pyc":
                files.add(relative.as_posix())
    return files


def test_manifest_validates():
    proc = harness.run_blender_ext("validate", str(harness.ROOT))
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_built_zip_validates_and_holds_only_the_addon(addon_zip):
    import zipfile

    proc = harness.run_blender_ext("validate", str(addon_zip))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    names = [name for name in zipfile.ZipFile(addon_zip).namelist() if not name.endswith("/")]
    assert len(names) == len(set(names)), "no file twice"
    top = {name.split("/", 1)[0] for name in names}
    assert sorted(top - ADDON_TOP) == [], "at the zip's top level, not the add-on"
    assert sorted(ADDON_TOP - top) == [], "the add-on's, not in the zip"
    expected = _addon_files()
    assert sorted(set(names) - expected) == [], "shipped, not the add-on's"
    assert sorted(expected - set(names)) == [], "the add-on's, not shipped"


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
    assert bpy.ops.object.water_add() == {"FINISHED"}
    assert harness.addon("water.values").is_water(bpy.context.active_object)
    assert harness.addon("water.mirror").find_probe(bpy.context.active_object) is not None
