"""Test set-up: the add-on is built and installed once per run, as users get it.

bpy must see `BLENDER_USER_RESOURCES` before it starts, so the harness starts
it here, before any test module imports bpy.
"""

import re
import shutil

import pytest

import harness

bpy = harness.start()

FAILURES = harness.ROOT / "out" / "test-failures"

# The `lts` subset (CI runs it on 4.2.23 and 4.5.15; 5.2.3 runs every test): tests of files kept by
# others, marked here by name (every case of a parametrized one); the other files mark their own.
LTS_ELSEWHERE = {
    "test_install.py": ("test_tools_build_zip_installs_from_disk_into_a_clean_user_folder_and_adds_water",),
    "test_extension.py": (
        "test_built_zip_validates_and_holds_only_the_addon",
        "test_installed_from_zip_and_enabled",
        "test_disable_enable_cycles_leave_nothing_behind",
    ),
    "test_add_water.py": (  # materials and worlds need `use_nodes` before 5.0; the ray tracing settings
        "test_adds_a_uv_mapped_plane_with_the_water_material_at_the_cursor",
        "test_undo_removes_the_water_and_its_set_up",
        "test_mirror_set_up_turns_tracing_on_adds_a_world_and_one_probe_that_follows_the_water",
    ),
    # the node-group interface API (sockets added, moved and removed in place)
    "test_node_groups.py": ("test_older_group_is_upgraded_in_place_keeping_material_values",),
    "test_surroundings.py": ("test_the_modifier_survives_save_and_reload_without_the_add_on",),
}

# The quick loop (`tools/test --quick`, `-m quick`): one test of each feature, the cheap ones, so
# the one writing code hears in a few minutes whether anything is broken; CI runs every test.
QUICK = {
    "test_extension.py": ("test_built_zip_validates_and_holds_only_the_addon",),
    "test_add_water.py": ("test_adds_a_uv_mapped_plane_with_the_water_material_at_the_cursor",),
    "test_kinds.py": ("test_the_operators_and_the_api_refuse_the_same_things",),
    "test_presets.py": ("test_written_presets_read_back_equal",),
    "test_water_shader.py": ("test_final_view_is_the_composition_of_the_debug_views",),  # the lake, rendered
    "test_surroundings.py": ("test_depth_and_shore_distance_match_the_bed_and_the_post",),
    "test_caustics.py": ("test_caustics_show_where_the_presets_and_the_surroundings_say",),
    "test_open_sea.py": (
        "test_the_open_sea_moves_with_the_clock_and_its_waves_and_foam_grow_with_the_wind",
        "test_a_saved_sea_animates_and_renders_the_same_without_the_add_on",
    ),
    "test_float_footprint.py": (
        "test_waves_four_hulls_long_pitch_it_as_its_footprint_and_it_keeps_its_draft",
        "test_a_saved_floating_hull_rocks_the_same_without_the_add_on",
    ),
    "test_wake.py": (
        "test_floating_and_stopping_keep_the_wake_without_a_cycle_and_a_deleted_hull_leaves_none",
        "test_a_baked_wake_renders_any_frame_alone_without_the_add_on",
    ),
    "test_keep_water_out.py": ("test_operator_panel_again_after_a_change_of_shape_and_let_in",),
    "test_underwater_switch.py": ("test_the_switch_takes_the_body_away_and_brings_it_back_with_the_samples",),
    "test_underwater_farm.py": ("test_a_half_under_shot_renders_the_same_without_the_add_on",),
    "test_caustic_light.py": ("test_the_light_comes_and_goes_with_the_caustics",),
    "test_cli.py": (
        "test_add_writes_a_new_file_with_water_and_prints_what_it_did",
        "test_render_writes_the_image_of_one_frame",
    ),
    "test_saved_file.py": ("test_saved_water_renders_the_same_without_the_add_on_and_with_auto_run_off",),
}


def _mark_by_name(items, table, mark, name):
    marked = set()
    for item in items:
        if item.originalname in table.get(item.path.name, ()):
            item.add_marker(mark)
            marked.add((item.path.name, item.originalname))
    collected = {item.path.name for item in items}
    missing = [
        f"{file}::{test}"
        for file, tests in table.items()
        if file in collected
        for test in tests
        if (file, test) not in marked
    ]
    if missing:  # a renamed test would silently leave the subset
        raise pytest.UsageError(f"tests/conftest.py {name} names tests that do not exist: {missing}")


@pytest.hookimpl(tryfirst=True)  # before `-m` deselects by marks
def pytest_collection_modifyitems(config, items):
    _mark_by_name(items, LTS_ELSEWHERE, pytest.mark.lts, "LTS_ELSEWHERE")
    _mark_by_name(items, QUICK, pytest.mark.quick, "QUICK")


@pytest.fixture(scope="session")
def addon_zip(tmp_path_factory):
    """The extension zip built by Blender's own `blender_ext.py build`."""
    return harness.build_zip(tmp_path_factory.mktemp("dist"))


@pytest.fixture(scope="session")
def addon(addon_zip):
    """The installed and enabled add-on package (`bl_ext.user_default.water_surface`)."""
    return harness.install(addon_zip)


@pytest.fixture(scope="session")
def eevee(addon):
    """EEVEE's engine id in the running Blender."""
    return harness.addon("engine").eevee_engine_id()


@pytest.fixture
def scene(addon, eevee):
    """A clean, small EEVEE scene; the add-on stays enabled."""
    return harness.clean_scene(engine=eevee)


# Renders seen since the test's setup began (a persistent handler: loading a file keeps it), so a
# test that renders without the `render` mark fails: the mark is how a quick run leaves them out.
_RENDERS = []


@bpy.app.handlers.persistent
def _note_render(*_):
    _RENDERS.append(True)


bpy.app.handlers.render_init.append(_note_render)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if report.when == "call" and _RENDERS and report.passed and item.get_closest_marker("render") is None:
        report.outcome = "failed"
        report.longrepr = f"{item.nodeid} renders but is not marked `render` (pytest.mark.render)"
    setattr(item, f"report_{report.when}", report)


@pytest.hookimpl(tryfirst=True)
def pytest_runtest_setup(item):
    _RENDERS.clear()


@pytest.fixture
def render(request, tmp_path):
    """Renders a scene to a float (H, W, 4) array, row 0 at the top.

    `render(scene, name="x", exr=False)`. When the test fails, its renders and
    the scene's `.blend` are kept under `out/test-failures/` and their paths printed.
    """
    made = []

    def _render(scene, name="render", exr=False):
        path = tmp_path / f"{name}.{'exr' if exr else 'png'}"
        made.append(path)
        return harness.render(scene, path, exr=exr)

    yield _render
    report = getattr(request.node, "report_call", None)
    if made and report is not None and report.failed:
        keep = FAILURES / re.sub(r"[^\w.-]+", "_", request.node.nodeid)
        keep.mkdir(parents=True, exist_ok=True)
        for path in made:
            if path.exists():
                shutil.copy(path, keep / path.name)
        bpy.ops.wm.save_as_mainfile(filepath=str(keep / "scene.blend"), copy=True)
        print(f"\nkept renders and .blend of the failed test in {keep}")


@pytest.fixture
def project():
    """The helper that projects world points to pixels of the scene's camera."""
    return harness.world_to_pixel


@pytest.fixture
def addon_disabled_afterwards(addon):
    """For tests that disable the add-on and turn auto-run off: both come back afterwards."""
    import addon_utils  # after `harness.start()`, like every bpy import

    yield
    bpy.context.preferences.filepaths.use_scripts_auto_execute = True
    addon_utils.enable(harness.ADDON_MODULE, default_set=True)
    assert hasattr(bpy.types, "OBJECT_OT_water_add")
